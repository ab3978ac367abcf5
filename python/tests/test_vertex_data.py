"""``data/vertices`` is what ``python/bench/vertex_data.py`` writes (``make data-vertices``),
file for file, and its halves share no source item."""

from __future__ import annotations

import csv
import filecmp
from pathlib import Path

from bench_scripts import load

ROOT = Path(__file__).resolve().parents[2]
FOLDER = ROOT / "data" / "vertices"


def test_the_folder_is_what_the_generator_writes(tmp_path):
    load("vertex_data").main([str(tmp_path)])
    written = sorted(p.name for p in tmp_path.iterdir())
    assert written == sorted(p.name for p in FOLDER.iterdir() if p.name != "README.md")
    _match, mismatch, errors = filecmp.cmpfiles(tmp_path, FOLDER, written, shallow=False)
    assert not mismatch and not errors, f"differ: {mismatch[:5]} (run make data-vertices)"


def test_the_halves_share_no_source_item_and_every_variant_is_in_both():
    with open(FOLDER / "index.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    half_of: dict[str, set[str]] = {}
    for row in rows:
        half_of.setdefault(row["source"], set()).add(row["half"])
    assert all(len(h) == 1 for h in half_of.values())
    design = {r["category"] for r in rows if r["half"] == "design"}
    held_out = {r["category"] for r in rows if r["half"] == "held-out"}
    assert design == held_out and len(design) == 6
    share = sum(r["half"] == "design" for r in rows) / len(rows)
    assert 0.4 < share < 0.6, share
