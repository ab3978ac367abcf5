"""``data/outlines`` is what ``python/bench/outline_data.py`` writes (``make data-outlines``),
file for file. ``sigdt bench`` scores it (its Rust tests)."""

from __future__ import annotations

import filecmp
import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def load(name: str):
    spec = importlib.util.spec_from_file_location(name, ROOT / "python" / "bench" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def test_the_folder_is_what_the_generator_writes(tmp_path):
    load("outline_data").main([str(tmp_path)])
    folder = ROOT / "data" / "outlines"
    written = sorted(p.name for p in tmp_path.iterdir())
    assert written == sorted(p.name for p in folder.iterdir() if p.name != "README.md")
    _match, mismatch, errors = filecmp.cmpfiles(tmp_path, folder, written, shallow=False)
    assert not mismatch and not errors, f"differ: {mismatch[:5]} (run make data-outlines)"
