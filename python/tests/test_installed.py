"""What ``make wheel-test`` checks about the installed wheel (skipped elsewhere): the package
comes from the virtualenv, not the source tree; no Rust toolchain is on PATH; the extension is
stripped; and the ``sigdt`` script is the command line."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import sigdt

pytestmark = pytest.mark.skipif(
    not os.environ.get("SIGDT_WHEEL_TEST"), reason="runs in make wheel-test only"
)


def test_the_package_is_the_installed_wheel_without_a_toolchain() -> None:
    assert Path(sigdt.__file__).resolve().is_relative_to(Path(sys.prefix).resolve())
    assert shutil.which("cargo") is None and shutil.which("rustc") is None
    (extension,) = Path(sigdt.__file__).parent.glob("_core*.so")
    if shutil.which("file"):  # optional; without it the size says enough
        out = subprocess.run(
            ["file", str(extension)], check=True, capture_output=True, text=True
        ).stdout
        assert "not stripped" not in out, out
    assert extension.stat().st_size < 20_000_000, extension.stat().st_size


def test_the_script_and_python_m_are_the_command_line(tmp_path: Path) -> None:
    (tmp_path / "square.xy").write_text("0 0\n1 0\n1 1\n0 1\n")
    script = Path(sys.prefix) / "bin" / "sigdt"
    for command in ([str(script)], [sys.executable, "-m", "sigdt"]):
        run = subprocess.run(
            [*command, "reconstruct", "square.xy"],
            check=False,
            cwd=tmp_path,
            capture_output=True,
            text=True,
        )
        assert (run.returncode, run.stdout, run.stderr) == (0, "0 1\n0 3\n1 2\n2 3\n", "")
        usage = subprocess.run(
            [*command, "reconstruct"], check=False, capture_output=True, text=True
        )
        assert usage.returncode == 2 and "Usage: sigdt reconstruct" in usage.stderr
