"""Matplotlib drawing of a :class:`~sigdt.Reconstruction` (matplotlib imported lazily)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from ._result import Reconstruction

__all__ = ["plot"]


def plot(rec: Reconstruction, ax: Any = None, **style: Any) -> Any:
    """Draw the filled loops, the edges and the points; returns the axes.

    ``style`` may override ``fill``, ``edge_color``, ``point_color``, ``linewidth`` and
    ``markersize``.
    """
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    if ax is None:
        _, ax = plt.subplots()
    pts = rec.points
    for loop in rec.loops:
        ax.fill(*pts[loop].T, color=style.get("fill", "#dbe9f6"), zorder=0)
    if len(rec.edges):
        segments = pts[rec.edges]
        ax.add_collection(
            LineCollection(
                segments,
                colors=style.get("edge_color", "#1f4e79"),
                linewidths=style.get("linewidth", 1.0),
                zorder=1,
            )
        )
    if len(pts):
        ax.plot(
            *np.asarray(pts).T,
            "o",
            color=style.get("point_color", "#c0392b"),
            markersize=style.get("markersize", 2.5),
            zorder=2,
        )
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(f"{len(pts)} points, {len(rec.edges)} edges, {rec.status}")
    return ax
