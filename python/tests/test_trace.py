"""The step trace: its binding contract, its replay against the result on the labelled
curves, and the step-by-step drawing (Agg backend)."""

from __future__ import annotations

import csv

import matplotlib
import numpy as np
import pytest
import sigdt
from blobs import blob
from sigdt import _core

matplotlib.use("Agg")
import matplotlib.pyplot as plt

FIGURE_7 = np.r_[
    np.c_[np.cos(np.arange(12) * np.pi / 6), np.sin(np.arange(12) * np.pi / 6)], [[0.0, 0.0]]
]


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _degrees(edges: np.ndarray, n: int) -> np.ndarray:
    return np.bincount(edges.ravel(), minlength=n)


def test_core_trace_returns_the_documented_arrays():
    raw = _core.trace(np.asarray(blob(80)), "sig-connect2d", True)
    triangles, graph, inside, dangling = raw.triangles, raw.graph, raw.initial_inside, raw.dangling
    tri, ins, phase = raw.step_triangle, raw.step_inside, raw.step_phase
    inflated_at = raw.inflated_at
    assert triangles.dtype == np.int64 and triangles.shape[1] == 3
    assert graph.dtype == dangling.dtype == tri.dtype == np.int64
    assert graph.shape[1] == dangling.shape[1] == 2
    assert inside.dtype == ins.dtype == np.bool_ and inside.shape == (len(triangles),)
    assert phase.dtype == np.uint8 and len(tri) == len(ins) == len(phase)
    assert isinstance(inflated_at, int) and 0 <= inflated_at <= len(tri)


@pytest.mark.parametrize("method", ["sig-connect2d", "connect2d"])
def test_replay_ends_at_the_result_on_the_labelled_curves(curves_dir, method):
    with open(curves_dir / "index.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["category"] != "large"]
    assert len(rows) > 400
    phases_seen = set()
    for row in rows:
        points = sigdt.read_points(curves_dir / f"{row['name']}.xy")
        rec = sigdt.reconstruct(points, method=method)
        tr = sigdt.trace(points, method=method)
        if rec.status in ("collinear", "too-few-points"):
            assert tr is None, row["name"]
            continue
        assert np.array_equal(tr.boundary_at(tr.n_steps), rec.edges), row["name"]
        degree = _degrees(tr.boundary_at(tr.inflated_at), len(points))
        assert set(np.unique(degree)) <= {0, 2}, f"{row['name']}: not manifold after inflating"
        stats = rec.stats
        phases = np.asarray(tr.phases)
        assert (phases == "inflate").sum() == stats["inflated_triangles"], row["name"]
        assert (phases == "sculpt").sum() == stats["sculpted_triangles"], row["name"]
        assert np.array_equal(phases == "sculpt", np.arange(tr.n_steps) >= tr.inflated_at)
        phases_seen.update(tr.phases)
    assert phases_seen == set(sigdt.PHASES)


def test_boundary_at_start_is_the_boundary_of_the_graph():
    tr = sigdt.trace(FIGURE_7)
    assert repr(tr) == "Trace(n_triangles=12, n_steps=1, inflated_at=0)"
    start = tr.boundary_at(0)
    assert start.dtype == np.int64 and start.flags.c_contiguous
    assert {tuple(e) for e in start} <= {tuple(e) for e in tr.graph}
    assert len(start) == 12 and tr.initial_inside.all()
    end = tr.boundary_at(1)
    assert np.array_equal(end, sigdt.reconstruct(FIGURE_7, method="sig-connect2d").edges)
    assert not tr.inside_at(1)[tr.step_triangle[0]]


def test_dangling_edges_are_boundary_until_a_side_turns_interior():
    # A path graph: CONNECT2D's BC0 on points along an open arc is the arc, dangling.
    t = np.linspace(0, np.pi, 9)
    tr = sigdt.trace(np.c_[np.cos(t), np.sin(t)], method="connect2d")
    assert len(tr.dangling) > 0
    start = {tuple(e) for e in tr.boundary_at(0)}
    assert {tuple(e) for e in tr.dangling} <= start


def test_trace_is_none_without_inflating_or_triangles():
    assert sigdt.trace(blob(30), method="crust") is None
    assert sigdt.trace([[0, 0], [1, 1], [2, 2]]) is None
    assert sigdt.trace([]) is None


def test_trace_errors():
    tr = sigdt.trace(FIGURE_7)
    with pytest.raises(IndexError):
        tr.boundary_at(2)
    with pytest.raises(IndexError):
        tr.boundary_at(-1)
    with pytest.raises(TypeError):
        tr.boundary_at(0.5)
    with pytest.raises(sigdt.InvalidInputError):
        sigdt.trace([[0.0, np.nan], [1, 0], [0, 1]])
    with pytest.raises(ValueError, match="unknown method"):
        sigdt.trace(FIGURE_7, method="nope")


def test_plot_steps_draws_one_panel_per_step():
    rng = np.random.default_rng(1)
    points = np.r_[blob(60), blob(40, center=(4.0, 0.0))] + rng.normal(0, 0.03, (100, 2))
    tr = sigdt.trace(points)
    assert 0 < tr.inflated_at < tr.n_steps
    fig = sigdt.plot_steps(points)
    titles = [ax.get_title() for ax in fig.axes]
    assert titles[0] == "start" and 3 <= len(titles) <= 7
    assert titles[-1].endswith(f"/{tr.n_steps - tr.inflated_at}") or tr.n_steps == tr.inflated_at
    fig.canvas.draw()
    fig = sigdt.plot_steps(points, steps=[0, 1, tr.n_steps], ncols=2)
    assert len(fig.axes) == 3
    assert [ax.get_title() for ax in fig.axes][:2] == ["start", f"inflate 1/{tr.inflated_at}"]


def test_plot_steps_uses_the_given_axes():
    fig, grid = plt.subplots(2, 2)
    assert sigdt.plot_steps(FIGURE_7, steps=[0, 1], axes=grid) is fig
    assert [ax.get_title() for ax in grid.ravel()] == ["start", "sculpt 1/1", "", ""]
    with pytest.raises(ValueError, match="axes"):
        sigdt.plot_steps(FIGURE_7, steps=[0, 1], axes=grid[0, :1])


def test_plot_steps_errors():
    with pytest.raises(ValueError, match="does not inflate"):
        sigdt.plot_steps(FIGURE_7, method="crust")
    with pytest.raises(IndexError):
        sigdt.plot_steps(FIGURE_7, steps=[5])
    with pytest.raises(ValueError, match="ncols"):
        sigdt.plot_steps(FIGURE_7, ncols=0)
