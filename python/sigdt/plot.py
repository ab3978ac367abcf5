"""Matplotlib drawings of a :class:`~sigdt.Reconstruction` and of the steps of a run
(matplotlib imported lazily)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from . import _core
from ._trace import trace
from ._types import Method

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ._outlines import Outlines
    from ._trace import Trace

__all__ = ["plot", "plot_steps"]


#: The most points :func:`plot` draws as markers; denser sets are thinned evenly (the edges
#: and fills are always drawn whole).
MAX_POINT_MARKERS = 20_000

#: The colours of every sigdt picture by role, shared with ``sigdt render`` and ``sigdt
#: view`` (crates/sigdt-lab/src/render/palette.rs).
PALETTE: dict[str, str] = dict(_core.PALETTE)
FILL, INK = PALETTE["fill"], PALETTE["ink"]


def plot(
    rec: Outlines,
    ax: Any = None,
    *,
    fill: Any = FILL,
    edge_color: Any = INK,
    point_color: Any = INK,
    linewidth: float = 1.0,
    markersize: float = 2.5,
    max_points: int = MAX_POINT_MARKERS,
    **edge_kw: Any,
) -> Axes:
    """Draw the filled loops (a loop nested in another is a hole of it), the edges (open
    paths included) and the points; returns the axes.

    Colours are those of ``sigdt render``. Other keyword arguments go to the edges'
    ``LineCollection`` (``alpha``, ``linestyle``, ``label``, ...); ``fill=None`` leaves the
    loops unfilled, ``max_points=0`` leaves the points out. Above ``max_points`` points
    only every k-th point is drawn as a marker, so a million points plot in seconds. The
    axes' title is set only when it has none.
    """
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path

    if ax is None:
        _, ax = plt.subplots()
    pts = np.asarray(rec.points)
    rings = [rec.vertices[loop] for loop in rec.loops]
    if fill is not None:
        for shell, holes in rec.polygons:
            # Holes clockwise against the counter-clockwise shell: a hole under either rule.
            parts = [rings[shell]] + [rings[h][::-1] for h in holes]
            vertices = np.concatenate([np.r_[r, r[:1]] for r in parts])
            codes = np.concatenate(
                [[Path.MOVETO] + [Path.LINETO] * (len(r) - 1) + [Path.CLOSEPOLY] for r in parts]
            )
            # add_artist, not add_patch: add_patch walks the path segment by segment to
            # update the data limits (20 s at 10^6 vertices); the edges set them below.
            ax.add_artist(PathPatch(Path(vertices, codes), color=fill, linewidth=0, zorder=0))
    if len(rec.edges):
        style = {"colors": edge_color, "linewidths": linewidth, "zorder": 1, **edge_kw}
        ax.add_collection(LineCollection(_polylines(rec), **style))
        ax.update_datalim(rec.vertices[np.unique(rec.edges)])
    if len(pts) and max_points > 0:
        step = -(-len(pts) // max_points)  # ceil: at most max_points markers
        shown = pts[::step]
        ax.plot(*shown.T, "o", color=point_color, markersize=markersize, zorder=2)
    ax.set_aspect("equal")
    ax.autoscale_view()
    if not ax.get_title():
        ax.set_title(f"{len(pts)} points, {len(rec.edges)} edges, {rec.status}")
    return ax


def _polylines(rec: Outlines) -> list[np.ndarray]:
    """The edges as few polylines: each loop closed, each path, then every edge on neither
    as a segment of its own (matplotlib makes one path per polyline: a million separate
    segments took 10 s)."""
    verts = rec.vertices
    chains = [np.r_[loop, loop[:1]] for loop in rec.loops] + list(rec.paths)
    n = len(verts)
    keys = np.sort(rec.edges, axis=1) @ np.array([n, 1])
    drawn = [np.sort(np.c_[c[:-1], c[1:]], axis=1) @ np.array([n, 1]) for c in chains if len(c) > 1]
    rest = rec.edges[~np.isin(keys, np.concatenate(drawn))] if drawn else rec.edges
    return [verts[c] for c in chains if len(c) > 1] + list(verts[rest])


def plot_steps(
    points: Any,
    *,
    steps: Any = None,
    method: Method = "sig-connect2d",
    ncols: int = 4,
    axes: Any = None,
) -> Figure:
    """Draw inflating and sculpting step by step, one panel per chosen step.

    Each panel shows the Delaunay triangles (faint), the interior triangles (filled), the
    triangle the step just relabelled (in its phase's colour: orange when inflating,
    sky blue for a pocket, vermillion when sculpting), the boundary after that step and the
    points, titled ``"start"``, ``"inflate k/K"`` or ``"sculpt k/K"``. The colours are those
    of ``sigdt render`` and ``sigdt view``.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        Anything numpy turns into an ``(n, 2)`` float64 array.
    steps : sequence of int, optional
        Step counts to draw, each in ``0..=trace.n_steps`` (see :func:`sigdt.trace`).
        Default: the start, two inflate steps, the end of inflating, two sculpt steps and
        the final result (fewer when steps coincide).
    method : str, default "sig-connect2d"
        ``"sig-connect2d"`` or ``"connect2d"`` (the methods that inflate and sculpt).
    ncols : int, default 4
        Panels per row when ``axes`` is not given.
    axes : sequence of matplotlib.axes.Axes, optional
        Axes to draw in, at least one per step (any array shape; extra ones are left
        untouched). Default: a new figure with a grid of panels.

    Returns
    -------
    matplotlib.figure.Figure
        The figure of the panels.

    Raises
    ------
    ValueError
        The method neither inflates nor sculpts, the input is degenerate (no triangles),
        ``ncols`` < 1, or there are fewer ``axes`` than steps.
    IndexError
        A step is outside ``0..=n_steps``.
    InvalidInputError
        Wrong shape or non-finite coordinates. (A subclass of ValueError.)

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import numpy as np, sigdt
    >>> t = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    >>> points = np.r_[np.c_[np.cos(t), np.sin(t)], [[0, 0]]]
    >>> fig = sigdt.plot_steps(points)
    >>> [ax.get_title() for ax in fig.axes]
    ['start', 'sculpt 1/1']
    """
    import matplotlib.pyplot as plt

    tr = trace(points, method=method)
    if tr is None:
        raise ValueError(
            f"no steps to draw: method {method!r} does not inflate or sculpt, or the input "
            "has no triangles (fewer than three distinct points, or all collinear)"
        )
    if steps is None:
        steps = _default_steps(tr.n_steps, tr.inflated_at)
    steps = [tr._check_step(k) for k in steps]
    if isinstance(ncols, bool) or not isinstance(ncols, int) or ncols < 1:
        raise ValueError(f"ncols must be a positive int, got {ncols!r}")
    if axes is None:
        nrows = max(1, -(-len(steps) // ncols))
        cols = max(1, min(ncols, len(steps)))
        fig, grid = plt.subplots(
            nrows, cols, figsize=(3 * cols, 3 * nrows), squeeze=False, layout="constrained"
        )
        axes = list(grid.ravel())
        for ax in axes[len(steps) :]:
            ax.remove()
    else:
        axes = list(np.ravel(np.asarray(axes, dtype=object)))
        if len(axes) < len(steps):
            raise ValueError(f"{len(steps)} steps need as many axes, got {len(axes)}")
        fig = axes[0].figure if axes else plt.figure()
    triangle_edges = _triangle_edges(tr.triangles)
    for ax, k in zip(axes, steps):
        _draw_step(ax, tr, k, triangle_edges)
    return fig


def _default_steps(n_steps: int, inflated_at: int) -> list[int]:
    """Start, two inflate steps, end of inflating, two sculpt steps, final."""
    inflate = np.linspace(0, inflated_at, 4).round().astype(int)
    sculpt = np.linspace(inflated_at, n_steps, 4).round().astype(int)
    return sorted({int(k) for k in np.r_[inflate, sculpt]})


def _triangle_edges(triangles: np.ndarray) -> np.ndarray:
    """Every edge of the triangles once, ``(m, 2)`` with ``i < j``, sorted."""
    pairs = np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    return np.unique(pairs, axis=0)


def _step_title(tr: Trace, k: int) -> str:
    if k == 0:
        return "start"
    if k <= tr.inflated_at:
        return f"inflate {k}/{tr.inflated_at}"
    return f"sculpt {k - tr.inflated_at}/{tr.n_steps - tr.inflated_at}"


def _draw_step(ax: Any, tr: Trace, k: int, edges: np.ndarray) -> None:
    from matplotlib.collections import LineCollection, PolyCollection

    pts = np.asarray(tr.points)
    ax.add_collection(LineCollection(pts[edges], colors=PALETTE["dt"], linewidths=0.4, zorder=0))
    inside = tr.inside_at(k)
    ax.add_collection(PolyCollection(pts[tr.triangles[inside]], facecolors=FILL, zorder=1))
    if k > 0:
        last = pts[tr.triangles[tr.step_triangle[k - 1 : k]]]
        colour = PALETTE[_core.PHASES[tr.step_phase[k - 1]]]
        ax.add_collection(PolyCollection(last, facecolors=colour, edgecolors=colour, zorder=2))
    boundary = tr.boundary_at(k)
    ax.add_collection(
        LineCollection(pts[boundary], colors=PALETTE["step_boundary"], linewidths=1.2, zorder=3)
    )
    ax.plot(*pts.T, "o", color=INK, markersize=2, zorder=4)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(_step_title(tr, k))
