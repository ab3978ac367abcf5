"""The plugin's only door to the sigdt package: importing it, with the command that
installs it when it is missing, and reconstructing a batch of groups, where one group's
error does not sink the others.

The plugin does not bundle sigdt (a compiled extension per platform): the user installs the
wheel into the Python QGIS runs. The message therefore names that Python and the profile's
``python`` folder, which QGIS puts on its import path, so the command can be pasted as is.
"""

import os
import sys
import warnings

from qgis.core import QgsApplication

#: Passed on as sigdt's ``method``: the default of the package and the CLI.
METHOD = "sig-auto"


def load_sigdt():
    """``(sigdt, None)``, or ``(None, message)`` saying how to install it when the import
    fails (the message is what the user sees: the algorithm's error and ``canExecute``)."""
    try:
        import sigdt
    except ImportError as e:  # also a wheel for another platform or Python
        return None, install_message(e)
    return sigdt, None


def install_message(error):
    """What to run so that ``import sigdt`` works in this QGIS, given why it failed."""
    python = _python_executable()
    target = os.path.join(QgsApplication.qgisSettingsDirPath(), "python")
    version = ".".join(map(str, sys.version_info[:2]))
    numpy_missing = getattr(error, "name", None) == "numpy"
    # --no-deps: pip would otherwise put a second numpy before QGIS's own, which GDAL's and
    # QGIS's compiled modules were built against.
    deps = "" if numpy_missing else "--no-deps "
    why = f"{error}" + (" (so pip installs numpy too)" if numpy_missing else "")
    return (
        f"The sigdt Python package cannot be imported in the Python QGIS runs (Python {version}, "
        f"{python}): {why}. Install the sigdt wheel into it, into this profile's python "
        f'folder (on QGIS\'s import path), then restart QGIS:\n  "{python}" -m pip install '
        f'{deps}--target "{target}" sigdt-*.whl\n(the wheel is what `make wheel` writes to '
        "target/wheels/ in the sigdt repository; any pip install into this Python works too)."
    )


def _python_executable():
    """The Python interpreter of the library QGIS embeds. ``sys.executable`` is no guide
    there: embedded Python takes the first ``python3`` on ``PATH``, which may be another
    Python altogether (a pyenv or conda one)."""
    if sys.platform == "win32":  # OSGeo4W and the standalone installer: apps/PythonNN
        return os.path.join(sys.base_exec_prefix, "python.exe")
    return os.path.join(sys.base_exec_prefix, "bin", "python{}.{}".format(*sys.version_info))


class Failure(str):
    """A group's error message, in place of its result. Not the exception itself: its
    traceback holds the caller's frames, and with them the output sinks, in a reference
    cycle; sinks finish their files only when freed, so ``qgis_process``, which exits
    without collecting cycles, would leave GeoPackages without their layers."""


def reconstruct_batch(sigdt, arrays, *, expect, lon_lat):
    """One result per array, in order: a ``sigdt.Reconstruction``, or a :class:`Failure`
    saying why sigdt refused that array. The batch runs in sigdt's threads in one call; when
    it raises, each array is run alone to find which failed, since the error names only the
    first."""
    try:
        return _reconstruct(sigdt, arrays, expect, lon_lat)
    except sigdt.SigdtError as e:
        if len(arrays) == 1:
            return [_failure(e)]
    results = []
    for array in arrays:
        try:
            results.extend(_reconstruct(sigdt, [array], expect, lon_lat))
        except sigdt.SigdtError as e:
            results.append(_failure(e))
    return results


def _failure(error):
    # sigdt names the array by its place in the call ("point set 0: ..."), always 0 here.
    return Failure(str(error).removeprefix("point set 0: "))


def _reconstruct(sigdt, arrays, expect, lon_lat):
    with warnings.catch_warnings():
        # Each group's warning goes into its features (`warning`, `diagnosis`) and the log;
        # Python's warning would name "point set K" of a batch.
        warnings.simplefilter("ignore", sigdt.SigdtWarning)
        # lon_lat: degrees reconstructed in each group's local plane, as the CLI does.
        return sigdt.reconstruct_many(arrays, method=METHOD, expect=expect, lon_lat=lon_lat)
