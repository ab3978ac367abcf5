"""``data/outlines`` is what ``python/bench/outline_data.py`` writes (``make data-outlines``),
file for file, and the scorer reads it."""

from __future__ import annotations

import filecmp
import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def load(name: str):
    # The scorer imports the generator as a sibling module, as it does when run as a script.
    if str(ROOT / "python" / "bench") not in sys.path:
        sys.path.insert(0, str(ROOT / "python" / "bench"))
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


def test_the_scorer_judges_a_clean_outline_good(tmp_path):
    scores = load("outline_scores")
    cases = [
        c for c in scores.read_folder(ROOT / "data" / "outlines") if c["name"].endswith("_clean")
    ]
    circle = next(c for c in cases if c["name"].startswith("mp7_HCircle"))
    [row] = scores.run_sigdt("sig-auto", [circle])
    assert row["topology"] and row["iou"] > 0.99 and not row["warned"]
    # A result that is nothing: no region, IoU 0, topology wrong.
    empty = scores.score([], [], circle)
    assert empty["iou"] == 0.0 and not empty["topology"]
