"""Metrics from Python, the concave-hull comparison, and their agreement with the CLI."""

from __future__ import annotations

import csv
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sigdt
from sigdt.baselines import concave_hull

SQUARE = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
SQUARE_GT = np.array([[0, 1], [0, 3], [1, 2], [2, 3]])


def test_evaluate_an_exact_and_a_wrong_result():
    m = sigdt.evaluate(SQUARE, SQUARE_GT, SQUARE_GT)
    assert m["exact"] and m["missing"] == m["extra"] == 0
    assert m["rmse"] == m["hausdorff"] == m["area_difference"] == 0.0
    # The diagonal instead of a side: one missing, one extra, area halved.
    wrong = sigdt.evaluate(SQUARE, [[0, 1], [1, 2], [2, 3], [1, 3]], SQUARE_GT)
    assert (wrong["exact"], wrong["missing"], wrong["extra"]) == (False, 1, 1)
    assert wrong["area_difference"] == pytest.approx(0.5)
    assert wrong["area_difference_normalised"] == pytest.approx(0.5)
    assert wrong["hausdorff"] > 0


def test_evaluate_without_a_result_has_no_distances():
    m = sigdt.evaluate(SQUARE, np.zeros((0, 2), dtype=np.int64), SQUARE_GT)
    assert not m["exact"] and m["missing"] == 4 and m["rmse"] is None


def test_bad_edges_raise_naming_the_problem():
    with pytest.raises(ValueError, match="999"):
        sigdt.evaluate(SQUARE, [[0, 999]], SQUARE_GT)
    with pytest.raises(ValueError, match="negative"):
        sigdt.evaluate(SQUARE, [[0, -1]], SQUARE_GT)
    with pytest.raises(ValueError, match=r"shape \(m, 2\)"):
        sigdt.graph_epsilon(SQUARE, [0, 1, 2])
    with pytest.raises(ValueError, match="integer"):
        sigdt.graph_overlap(SQUARE, [[0.5, 1.0]])
    with pytest.raises(sigdt.InvalidInputError):
        sigdt.graph_epsilon([[0, np.nan], [1, 1], [2, 0]], [[0, 1]])


def test_metrics_on_labelled_cases_match_the_cli(curves_dir: Path, cli: Path):
    for name in ["real_mushroom", "svg_manif_f5_path1_0_209"]:
        points = sigdt.read_points(curves_dir / f"{name}.xy")
        gt = np.loadtxt(curves_dir / f"{name}.gt", dtype=np.int64, ndmin=2)
        rec = sigdt.reconstruct(points)
        m = sigdt.evaluate(points, rec.edges, gt)
        eps = sigdt.graph_epsilon(points, gt)
        out = subprocess.run(
            [cli, "eval", curves_dir / f"{name}.xy", "--gt", curves_dir / f"{name}.gt"],
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        fields = dict(line.split(":", 1) for line in out.splitlines() if ":" in line)
        assert fields["exact"].strip() == ("yes" if m["exact"] else "no")
        assert float(fields["rmse"]) == pytest.approx(m["rmse"], rel=1e-5, abs=1e-12)
        assert float(fields["epsilon"].split()[0]) == pytest.approx(eps, abs=1e-4)
        overlap = sigdt.graph_overlap(points, gt)
        assert 0 <= overlap["sigdt_in_gt"] <= 1 and overlap["sig_in_dt"] > 0.5


def test_concave_hull_maps_the_hull_to_input_indices():
    inner = np.vstack([SQUARE, [[0.5, 0.5]]])
    edges = concave_hull(inner)
    assert edges.dtype == np.int64 and edges.shape[1] == 2
    assert set(map(tuple, edges.tolist())) >= {(0, 1), (1, 2), (2, 3)}
    assert set(map(tuple, concave_hull(inner, ratio=1.0).tolist())) == set(
        map(tuple, SQUARE_GT.tolist())
    )
    with pytest.raises(ValueError, match="ratio"):
        concave_hull(SQUARE, ratio=2)
    with pytest.raises(ValueError, match="non-finite|NaN"):
        concave_hull([[0, 0], [np.inf, 1], [1, 0]])


def test_concave_hull_results_are_scored_by_sigdt_bench(curves_dir: Path, cli: Path, tmp_path):
    data = tmp_path / "data"
    data.mkdir()
    names = ["real_mushroom", "svg_manif_f5_path1_0_209"]
    with open(curves_dir / "index.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["name"] in names]
    with open(data / "index.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    for name in names:
        for ext in ("xy", "gt"):
            shutil.copy(curves_dir / f"{name}.{ext}", data / f"{name}.{ext}")
    hull = tmp_path / "hull"
    subprocess.run([sys.executable, "-m", "sigdt.baselines", data, hull], check=True)
    assert (hull / "times.csv").is_file() and len(list(hull.glob("*.edges"))) == 2
    out = tmp_path / "report"
    subprocess.run(
        [cli, "bench", data, "--method", "sig-connect2d", "--out", out,
         "--import", f"concave-hull={hull}"],
        check=True,
        capture_output=True,
    )  # fmt: skip
    with open(out / "results.csv", newline="") as f:
        results = list(csv.DictReader(f))
    hull_rows = [r for r in results if r["method"] == "concave-hull"]
    assert len(hull_rows) == 2 and all(r["outcome"] == "ok" for r in hull_rows)
