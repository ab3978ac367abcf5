"""The release build of the ``sigdt`` CLI that the bench scripts run."""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def cli_binary() -> Path:
    """``$CARGO_TARGET_DIR/release/sigdt`` (``target/`` by default, relative paths from the
    repository root); exits naming the script and the missing file when it is not built."""
    target = Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")
    binary = (target if target.is_absolute() else ROOT / target) / "release" / "sigdt"
    if not binary.is_file():
        sys.exit(f"{Path(sys.argv[0]).stem}: {binary} is missing; run `make build` first")
    return binary
