"""Typed results: a user script touching every public function and result attribute passes
``mypy --strict --disallow-any-expr`` (no ``Any`` reaches user code), and the ``Literal``
types list exactly the names the extension defines."""

from __future__ import annotations

import shutil
import subprocess
import sys
import typing
from pathlib import Path

import pytest
import sigdt
from sigdt import _types

SCRIPT = """
import numpy as np
import numpy.typing as npt

import sigdt

points: npt.NDArray[np.float64] = np.random.default_rng(0).random((50, 2))
rec = sigdt.reconstruct(points, method="sig-auto")
edges: npt.NDArray[np.int64] = rec.edges
loops: list[npt.NDArray[np.int64]] = rec.loops
paths: list[npt.NDArray[np.int64]] = rec.paths
xy: npt.NDArray[np.float64] = rec.points
verts: npt.NDArray[np.float64] = rec.vertices
status: str = rec.status
if rec.status == "sculpting-stuck":
    print(rec.left_out)
kind: str = rec.vertices_kind
left: npt.NDArray[np.int64] = rec.left_out
reasons = rec.left_out_reasons
first_reason: str = reasons[0] if reasons else ""
dups: npt.NDArray[np.int64] = rec.duplicates
stats: dict[str, int] = rec.stats
manifold: bool = rec.is_manifold
polys: list[tuple[int, list[int]]] = rec.polygons
warns: bool = rec.warns
findings = rec.diagnosis
if findings:
    worst: float = findings[0]["worst"]
    at: int = findings[0]["at"]
    finding_kind: str = findings[0]["kind"]
    message: str = findings[0]["message"]
geometry = rec.to_shapely()
area: float = geometry.area
feature = rec.to_geojson()
properties = feature["properties"]
wkt: str = rec.to_wkt()
svg: str = rec.to_svg(width=300)
ax = rec.plot()
ax.set_xlabel("x")
many = sigdt.reconstruct_many([points, points], n_jobs=-1)
first: sigdt.Reconstruction = many[0]
graph: npt.NDArray[np.int64] = sigdt.proximity_graph(points, kind="sigdt")
read: npt.NDArray[np.float64] = sigdt.read_points("points.xy")
m = sigdt.evaluate(points, edges, edges)
exact: bool = m["exact"]
rmse: float | None = m["rmse"]
eps: float = sigdt.graph_epsilon(points, edges)
overlap = sigdt.graph_overlap(points, edges)
contained: bool = overlap["contains_gt_sigdt"]
tr = sigdt.trace(points)
steps: int = tr.n_steps if tr is not None else 0
figure = sigdt.plot_steps(points)
figure.savefig("steps.png")
back: npt.NDArray[np.float64] = sigdt.from_shapely(geometry)
again = sigdt.to_shapely(rec)
methods: list[str] = sigdt.METHODS
"""


def test_the_literals_are_the_extensions_names() -> None:
    assert typing.get_args(_types.Method) == tuple(sigdt.METHODS)
    rec = sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]])
    assert set(_types.Evaluation.__annotations__) == set(
        sigdt.evaluate(rec.points, rec.edges, rec.edges)
    )
    overlap = sigdt.graph_overlap(rec.points, rec.edges)
    assert set(_types.GraphOverlap.__annotations__) == set(overlap)


def test_a_user_script_sees_no_any(tmp_path: Path) -> None:
    if shutil.which("mypy", path=str(Path(sys.executable).parent)) is None:
        pytest.fail("mypy is missing: it is pinned in requirements-dev.txt", pytrace=False)
    script = tmp_path / "user.py"
    script.write_text(SCRIPT)
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "mypy",
            "--strict",
            "--disallow-any-expr",
            "--no-incremental",
            "--cache-dir",
            str(tmp_path / "cache"),
            str(script),
        ],
        check=False,
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert run.returncode == 0, run.stdout + run.stderr
