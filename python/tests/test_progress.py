"""``sigdt view`` and ``sigdt render`` name each stage of a long run on a terminal's stderr
(a spinner line, cleared at the end) and write nothing there when stderr is a pipe: the
cargo-built binary, and in ``make wheel-test`` also the wheel's ``sigdt`` script."""

from __future__ import annotations

import os
import pty
import re
import subprocess
import sys
from pathlib import Path

import pytest

CASE = "glyph_e_reversed"


def on_a_terminal(args: list) -> tuple[int, str]:
    """Runs ``args`` with stderr on a pseudo-terminal; returns the status and what it drew,
    without terminal escapes."""
    leader, follower = pty.openpty()
    try:
        run = subprocess.Popen(
            args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=follower
        )
        os.close(follower)
        drawn = bytearray()
        while True:
            try:
                chunk = os.read(leader, 65536)
            except OSError:  # the other side closed
                break
            if not chunk:
                break
            drawn += chunk
        status = run.wait(timeout=60)
    finally:
        os.close(leader)
    text = drawn.decode("utf-8", "replace")
    return status, re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", text)


@pytest.mark.parametrize(
    ("command", "output", "stages"),
    [
        (
            "view",
            "v.html",
            [
                "reading",
                "triangulating 70 points",
                "reconstructing (sig-auto)",
                "proximity graphs",
                "encoding the page",
                "writing",
            ],
        ),
        (
            "render",
            "r.png",
            [
                "reading",
                "triangulating 70 points",
                "reconstructing (sig-auto)",
                "drawing",
                "rasterising",
                "writing",
            ],
        ),
    ],
)
def test_stages_on_a_terminal_only(cli, repo_root, tmp_path, command, output, stages):
    xy = repo_root / "data" / "inputs" / f"{CASE}.xy"
    programs = [cli]
    if os.environ.get("SIGDT_WHEEL_TEST"):
        programs.append(Path(sys.prefix) / "bin" / "sigdt")
    for program in programs:
        run = [program, command, xy, "-o", tmp_path / output]
        status, drawn = on_a_terminal(run)
        assert status == 0
        for stage in stages:
            assert f"sigdt {command}: {stage}" in drawn, f"{program}: {stage!r} not shown:\n{drawn}"
        piped = subprocess.run(run, capture_output=True, check=True)
        assert piped.stderr == b"", piped.stderr
        assert Path(tmp_path / output).stat().st_size > 0
