"""The CLI and Python give the same edges on every labelled case of data/curves.

The CLI runs once per case (``sigdt reconstruct NAME.xy --format edges``, four at a time);
Python reads the same file with ``sigdt.read_points`` and reconstructs it.
"""

from __future__ import annotations

import csv
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import sigdt


def _cli_edges(cli: Path, xy: Path) -> np.ndarray:
    run = subprocess.run(
        [str(cli), "reconstruct", str(xy), "--format", "edges"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, f"{xy.name}: exit {run.returncode}: {run.stderr.strip()}"
    return np.array(run.stdout.split(), dtype=np.int64).reshape(-1, 2)


def test_every_case_is_present(curves_dir):
    with open(curves_dir / "index.csv", newline="") as f:
        names = {row["name"] for row in csv.DictReader(f)}
    assert names, "index.csv lists no case"
    assert {p.stem for p in curves_dir.glob("*.xy")} == names


def test_cli_and_python_give_the_same_edges(cli, curves_dir):
    cases = sorted(curves_dir.glob("*.xy"))
    assert len(cases) > 500, f"only {len(cases)} cases in {curves_dir}"
    with ThreadPoolExecutor(max_workers=4) as pool:
        from_cli = list(pool.map(lambda xy: _cli_edges(cli, xy), cases))
    assert sum(len(e) for e in from_cli) > 10 * len(cases), "the CLI printed almost no edges"
    mismatches = []
    for xy, cli_edges in zip(cases, from_cli):
        edges = sigdt.reconstruct(sigdt.read_points(xy)).edges
        if not np.array_equal(edges, cli_edges):
            only_cli = {tuple(e) for e in cli_edges.tolist()} - {tuple(e) for e in edges.tolist()}
            only_py = {tuple(e) for e in edges.tolist()} - {tuple(e) for e in cli_edges.tolist()}
            mismatches.append(
                f"{xy.name}: CLI {len(cli_edges)} edges, Python {len(edges)}; "
                f"only CLI {sorted(only_cli)[:5]}, only Python {sorted(only_py)[:5]}"
            )
    assert not mismatches, f"{len(mismatches)} of {len(cases)} cases differ:\n" + "\n".join(
        mismatches[:20]
    )
