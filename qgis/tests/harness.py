"""What the plugin's tests share: a throwaway QGIS home under the build folder, QGIS's own
``qgis_process`` on it, and layers read back with QGIS.

``make qgis-test`` builds the plugin into ``$QGIS_BUILD/plugins`` (unpacked from the zip
users get) and installs the sigdt wheel into the throwaway profile's ``python`` folder,
where the plugin's install message tells users to put it. ``HOME`` and the XDG folders
point under ``$QGIS_BUILD`` before QGIS is imported, so neither QGIS here nor
``qgis_process`` reads or writes the user's own profile.
"""

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("QGIS_BUILD", ROOT / "target" / "qgis"))
PLUGINS = BUILD / "plugins"
OUT = BUILD / "out"
#: The home whose profile has sigdt, and one whose profile lacks it.
HOME = BUILD / "home"
BARE_HOME = BUILD / "bare-home"
PLUGIN = "sigdt_processing"
ALGORITHM = "sigdt:outlines_from_points"
# Debian 12's /usr/bin/qgis_process passes --noversioncheck, which its qgis_process.bin
# 3.22 refuses (qgis/QGIS#57683): the binary is called directly.
QGIS_PROCESS = os.environ.get("QGIS_PROCESS", "/usr/bin/qgis_process.bin")


def profile_python(home):
    """The profile's ``python`` folder, which QGIS puts on ``sys.path``."""
    return Path(home) / ".local/share/QGIS/QGIS3/profiles/default/python"


def environment(home):
    """The environment of a headless QGIS confined to ``home``."""
    env = dict(os.environ)
    env.update(
        HOME=str(home),
        XDG_CONFIG_HOME=f"{home}/.config",
        XDG_DATA_HOME=f"{home}/.local/share",
        XDG_CACHE_HOME=f"{home}/.cache",
        XDG_RUNTIME_DIR=f"{home}/run",
        QT_QPA_PLATFORM="offscreen",
        QGIS_PLUGINPATH=str(PLUGINS),
        # GDAL's warnings (GDAL 3.6 on data/gis's GeoPackage 1.4 files) go to a file.
        CPL_LOG=f"{home}/gdal.log",
    )
    # No sigdt but the profile's: the message test must not find one elsewhere.
    env.pop("PYTHONPATH", None)
    Path(home, "run").mkdir(mode=0o700, parents=True, exist_ok=True)
    return env


def qgis_process(*args, home=HOME):
    """``qgis_process ARGS`` on ``home``'s profile; the completed process, output as text."""
    return subprocess.run(
        [QGIS_PROCESS, *map(str, args)],
        env=environment(home),
        check=False,
        capture_output=True,
        text=True,
        timeout=300,
    )


_enabled = set()


def enable_plugin(home=HOME):
    """Enables the plugin in ``home``'s profile (``qgis_process`` loads only enabled Python
    plugins that declare a Processing provider); once per home."""
    if home in _enabled:
        return
    # Exits with 1 when the plugin is enabled already: the list says whether it worked.
    done = qgis_process("plugins", "enable", PLUGIN, home=home)
    listed = qgis_process("list", home=home)
    if ALGORITHM not in listed.stdout:
        raise AssertionError(
            f"qgis_process does not list {ALGORITHM} after `plugins enable {PLUGIN}`:\n"
            f"{done.stdout}{done.stderr}{listed.stderr}"
        )
    _enabled.add(home)


def run_algorithm(name, home=HOME, outputs=("AREAS", "LINES", "LEFT_OUT"), **parameters):
    """Runs the algorithm with ``parameters``; ``outputs`` go to ``OUT/name/``. Returns the
    completed process and the output paths by parameter name."""
    enable_plugin(home)
    folder = OUT / name
    folder.mkdir(parents=True, exist_ok=True)
    outputs = {key: folder / f"{key.lower()}.gpkg" for key in outputs}
    for path in outputs.values():
        path.unlink(missing_ok=True)
    args = [f"--{k}={v}" for k, v in {**parameters, **outputs}.items()]
    return qgis_process("run", ALGORITHM, *args, home=home), outputs


# QGIS in this process, for reading layers and running the algorithm directly: confined to
# HOME like qgis_process, before qgis.core is imported.
os.environ.update(environment(HOME))
sys.path[:0] = [str(profile_python(HOME)), str(PLUGINS)]

from qgis.core import QgsApplication, QgsVectorLayer

QgsApplication.setPrefixPath("/usr", True)
_app = QgsApplication([], False)
_app.initQgis()


def layer(path):
    """The vector layer at ``path`` (``path|layername=NAME`` for one of several), checked."""
    found = QgsVectorLayer(str(path), Path(str(path)).stem, "ogr")
    if not found.isValid():
        raise AssertionError(f"QGIS cannot open {path}")
    return found


def output(process):
    """What a ``qgis_process`` run printed, for assertion messages."""
    return f"exit {process.returncode}\n--- stdout\n{process.stdout}\n--- stderr\n{process.stderr}"
