"""The CLI and Python give the same edges on every labelled case of data/curves.

The CLI runs once per case (``sigdt reconstruct NAME.xy --format edges``, four at a time);
Python reads the same file with ``sigdt.read_points`` and reconstructs it.
"""

from __future__ import annotations

import csv
import json
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest
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


def _circle(n: int, radius: float = 1.0, center: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    t = 2 * np.pi * np.arange(n) / n
    return np.c_[radius * np.cos(t) + center[0], radius * np.sin(t) + center[1]]


def _arc(n: int, center: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    t = np.linspace(0.0, 1.5 * np.pi, n)
    return np.c_[np.cos(t) + center[0], np.sin(t) + center[1]]


#: (points, method) of each case: every geometry type, points left out, vertices of the
#: method's own or moved, an empty input, duplicates and findings of the sampling check.
TEXT_CASES = {
    "square": ([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], "sig-connect2d"),
    "two-circles": (np.r_[_circle(40), _circle(30, center=(5.0, 0.0))], "sig-connect2d"),
    "nested-circles": (np.r_[_circle(60, 3.0), _circle(40, 2.0), _circle(20)], "sig-auto"),
    "open-arc": (_arc(40), "sig-auto"),
    "two-open-arcs": (np.r_[_arc(40), _arc(30, center=(5.0, 0.0))], "sig-auto"),
    "arc-and-circle": (np.r_[_arc(40), _circle(40, center=(5.0, 0.0))], "sig-auto"),
    "outliers": (np.r_[_circle(80), [[0.0, 0.0], [0.1, -0.2]]], "sig-auto"),
    "optimal-transport": (_circle(60, 3.0), "optimal-transport"),
    "stretch-denoise": (
        _circle(60) * (1 + 0.01 * np.random.default_rng(3).standard_normal((60, 1))),
        "stretch-denoise",
    ),
    "empty": (np.zeros((0, 2)), "sig-connect2d"),
    "one-point": ([[1.5, -2.0]], "sig-connect2d"),
    "collinear": ([[0.0, 0.0], [2.0, 1.0], [4.0, 2.0], [1.0, 0.5]], "sig-connect2d"),
    "duplicates": (np.r_[_circle(50), _circle(50)[::7]], "sig-connect2d"),
    "small-loop-finding": (np.r_[_circle(60), 3.0 + 0.05 * _circle(5)], "sig-connect2d"),
    "tiny-and-huge": ([[1e-7, 0.0], [3e20, 1e-7], [1e20, 2e20], [0.1, 1e20]], "crust"),
}


def _cli_text(cli: Path, xy: Path, method: str, fmt: str) -> str:
    run = subprocess.run(
        [str(cli), "reconstruct", str(xy), "--method", method, "--format", fmt],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, f"{fmt}: exit {run.returncode}: {run.stderr.strip()}"
    return run.stdout


@pytest.mark.parametrize("name", list(TEXT_CASES))
def test_wkt_and_geojson_are_the_clis(cli, tmp_path, name):
    """``to_wkt()`` is the CLI's ``--format wkt`` text (without its final newline) and
    ``to_geojson()`` the CLI's ``--format geojson`` feature, member for member."""
    points, method = TEXT_CASES[name]
    points = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    npy = tmp_path / "points.npy"
    np.save(npy, points)
    rec = sigdt.reconstruct(points, method=method)
    wkt, geojson = (_cli_text(cli, npy, method, f) for f in ("wkt", "geojson"))
    assert rec.to_wkt() + "\n" == wkt
    feature = json.loads(geojson)
    assert rec.to_geojson() == feature
    # The same types too (a float stays a float), and the dict is JSON as it is.
    assert json.dumps(rec.to_geojson()) == json.dumps(feature)
    properties = feature["properties"]
    assert properties["points"] == len(points) and properties["edges"] == len(rec.edges)
    if rec.vertices_kind != "input":
        assert properties["vertices"] == len(rec.vertices)
    else:
        assert "vertices" not in properties
