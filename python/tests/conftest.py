"""Shared fixtures: the repository's labelled curves (data/curves) and the built CLI binary."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest
from hypothesis.configuration import set_hypothesis_home_dir

#: The repository root (python/tests/conftest.py -> parents[2]).
ROOT = Path(__file__).resolve().parents[2]

# Keep hypothesis's cache (.hypothesis/) out of the working tree.
if not os.environ.get("HYPOTHESIS_STORAGE_DIRECTORY"):
    set_hypothesis_home_dir(Path(tempfile.gettempdir()) / "sigdt-hypothesis")


@pytest.fixture(scope="session")
def repo_root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def curves_dir() -> Path:
    """``$SIGDT_DATA``, else the repository's ``data/curves``."""
    env = os.environ.get("SIGDT_DATA")
    path = Path(env) if env else ROOT / "data" / "curves"
    if not path.is_dir() or not any(path.glob("*.xy")):
        pytest.fail(
            f"the labelled curves are missing: no *.xy in {path} "
            "(set SIGDT_DATA to the folder holding NAME.xy / NAME.gt)",
            pytrace=False,
        )
    return path


@pytest.fixture(scope="session")
def cli() -> Path:
    """The release CLI binary (``make py-test`` builds it first), or the program in
    ``$SIGDT_CLI`` (``make wheel-test``: the wheel's ``sigdt`` script)."""
    if os.environ.get("SIGDT_CLI"):
        return Path(os.environ["SIGDT_CLI"])
    target = Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")
    if not target.is_absolute():
        target = ROOT / target
    binary = target / "release" / ("sigdt.exe" if os.name == "nt" else "sigdt")
    if not binary.is_file():
        pytest.fail(
            f"the CLI binary {binary} is missing; build it with `make build` "
            "(cargo build --release -p sigdt-cli)",
            pytrace=False,
        )
    return binary
