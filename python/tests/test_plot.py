"""Matplotlib drawing with the Agg backend: one LineCollection, one fill patch per polygon
(a loop nested in another is its hole)."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest
import sigdt
from blobs import blob

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.patches import PathPatch


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _line_collections(ax):
    return [c for c in ax.collections if isinstance(c, LineCollection)]


def _drawn_edges(collection) -> set[tuple[float, ...]]:
    """The segments of a LineCollection's polylines, each as its sorted end points."""
    out = set()
    for line in collection.get_segments():
        for a, b in zip(line[:-1], line[1:]):
            out.add(tuple(sorted([tuple(a), tuple(b)])))
    return out


def _edges_of(rec) -> set[tuple[float, ...]]:
    return {tuple(sorted([tuple(rec.vertices[i]), tuple(rec.vertices[j])])) for i, j in rec.edges}


def test_plot_draws_edges_fills_and_points():
    points = np.r_[blob(60), blob(40, center=(4.0, 0.0))]
    rec = sigdt.reconstruct(points)
    ax = rec.plot()
    assert isinstance(ax, Axes)
    (edges,) = _line_collections(ax)
    assert _drawn_edges(edges) == _edges_of(rec) and len(rec.edges) == 100
    fills = [p for p in ax.patches if isinstance(p, PathPatch)]
    assert len(fills) == len(rec.loops) == 2
    (dots,) = ax.lines
    assert len(dots.get_xdata()) == 100
    assert rec.status in ax.get_title()
    ax.figure.canvas.draw()  # renders without error


def test_plot_uses_the_given_axes_and_style():
    rec = sigdt.reconstruct(blob(50))
    fig, ax = plt.subplots()
    assert rec.plot(ax=ax, edge_color="black", fill="yellow") is ax
    assert len(fig.axes) == 1 and len(plt.get_fignums()) == 1
    (edges,) = _line_collections(ax)
    assert tuple(edges.get_colors()[0]) == matplotlib.colors.to_rgba("black")
    assert ax.patches[0].get_facecolor() == matplotlib.colors.to_rgba("yellow")


def test_plot_passes_matplotlib_styles_keeps_titles_and_thins_dense_points():
    rec = sigdt.reconstruct(blob(5000))
    _, ax = plt.subplots()
    ax.set_title("mine")
    rec.plot(ax=ax, alpha=0.5, linestyle="--", label="curve", fill=None, max_points=1000)
    (edges,) = _line_collections(ax)
    assert edges.get_alpha() == 0.5 and edges.get_label() == "curve"
    assert edges.get_linestyle()[0][1] is not None, "dashed"
    assert ax.get_title() == "mine" and not ax.patches, "title kept, no fill"
    (markers,) = ax.lines
    assert len(markers.get_xdata()) == 1000
    ax2 = rec.plot(max_points=0)
    assert not ax2.lines and "5000 points" in ax2.get_title()


@pytest.mark.parametrize(
    ("points", "n_segments"),
    [([], 0), ([[0, 0]], 0), ([[0, 0], [1, 1], [2, 2]], 2)],
    ids=["0-points", "1-point", "collinear"],
)
def test_plot_of_degenerate_results(points, n_segments):
    ax = sigdt.reconstruct(points).plot()
    drawn = sum(sum(len(s) - 1 for s in c.get_segments()) for c in _line_collections(ax))
    assert drawn == n_segments
    assert len(ax.patches) == 0
    ax.figure.canvas.draw()


def test_plot_fills_a_ring_with_its_hole_and_draws_open_paths():
    t = np.linspace(0.0, np.pi, 20)
    points = np.r_[blob(90) * 3.0, blob(40), np.c_[8.0 + np.cos(t), np.sin(t)]]
    rec = sigdt.reconstruct(points, method="sig-auto")
    assert len(rec.loops) == 2 and len(rec.paths) == 1
    ax = rec.plot()
    assert len(ax.patches) == 1  # one polygon: the outer loop with the inner one as its hole
    (edges,) = _line_collections(ax)
    assert _drawn_edges(edges) == _edges_of(rec) and len(rec.edges) == 90 + 40 + 19
    assert len(edges.get_segments()) == 3, "two loops and a path, one polyline each"
    ax.figure.canvas.draw()
    pixels = np.asarray(ax.figure.canvas.buffer_rgba())

    def colour_at(x, y):
        px, py = ax.transData.transform((x, y))
        return tuple(pixels[pixels.shape[0] - int(py), int(px), :3])

    fill = tuple(int(255 * c) for c in matplotlib.colors.to_rgb(sigdt.plot.FILL))
    assert colour_at(2.0, 0.0) == fill  # in the ring
    assert colour_at(0.0, 0.3) == (255, 255, 255)  # in the hole
