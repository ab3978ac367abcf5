"""``data/outlines`` is what ``python/bench/outline_data.py`` writes (``make data-outlines``),
file for file. ``sigdt bench`` scores it (its Rust tests)."""

from __future__ import annotations

import filecmp
from pathlib import Path

from bench_scripts import load

ROOT = Path(__file__).resolve().parents[2]


def test_the_folder_is_what_the_generator_writes(tmp_path):
    load("outline_data").main([str(tmp_path)])
    folder = ROOT / "data" / "outlines"
    written = sorted(p.name for p in tmp_path.iterdir())
    assert written == sorted(p.name for p in folder.iterdir() if p.name != "README.md")
    _match, mismatch, errors = filecmp.cmpfiles(tmp_path, folder, written, shallow=False)
    assert not mismatch and not errors, f"differ: {mismatch[:5]} (run make data-outlines)"
