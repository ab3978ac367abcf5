"""Matplotlib drawing with the Agg backend: one LineCollection, one fill patch per loop."""

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
from matplotlib.patches import Polygon


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _line_collections(ax):
    return [c for c in ax.collections if isinstance(c, LineCollection)]


def test_plot_draws_edges_fills_and_points():
    points = np.r_[blob(60), blob(40, center=(4.0, 0.0))]
    rec = sigdt.reconstruct(points)
    ax = rec.plot()
    assert isinstance(ax, Axes)
    (edges,) = _line_collections(ax)
    assert len(edges.get_segments()) == len(rec.edges) == 100
    fills = [p for p in ax.patches if isinstance(p, Polygon)]
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


@pytest.mark.parametrize(
    ("points", "n_segments"),
    [([], 0), ([[0, 0]], 0), ([[0, 0], [1, 1], [2, 2]], 2)],
    ids=["0-points", "1-point", "collinear"],
)
def test_plot_of_degenerate_results(points, n_segments):
    ax = sigdt.reconstruct(points).plot()
    assert sum(len(c.get_segments()) for c in _line_collections(ax)) == n_segments
    assert len(ax.patches) == 0
    ax.figure.canvas.draw()
