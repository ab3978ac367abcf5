"""The step trace of inflating and sculpting: :func:`sigdt.trace` and :class:`Trace`."""

from __future__ import annotations

import operator
from typing import Any

import numpy as np

from . import _core
from ._core import PHASES  # the names of the codes in Trace.step_phase (Rust's Phase::ALL)
from ._input import LEAF_ELIMINATION, _as_points, _check_method
from ._types import Method

__all__ = ["PHASES", "Trace", "trace"]


def trace(
    points: Any,
    *,
    method: Method = "sig-connect2d",
    leaf_elimination: bool = LEAF_ELIMINATION,
) -> Trace | None:
    """Record every step of inflating and sculpting, to replay or draw the run.

    Runs the same reconstruction as :func:`reconstruct` and records the labels of the
    Delaunay triangles right after the initial graph's boundary is found, then every label
    change in order: inflating turns exterior triangles interior one at a time
    (``"inflate"``) and fills enclosed pockets several at once (``"pocket"``); sculpting
    turns interior triangles exterior one at a time (``"sculpt"``).

    Parameters
    ----------
    points : array_like, shape (n, 2)
        Anything numpy turns into an ``(n, 2)`` float64 array.
    method : str, default "sig-connect2d"
        ``"sig-connect2d"`` or ``"connect2d"``; the graph filters (``"crust"``, ...) neither
        inflate nor sculpt.
    leaf_elimination : bool, default True
        As in :func:`reconstruct`.

    Returns
    -------
    Trace or None
        The trace; ``None`` for the graph-filter methods and for degenerate input (fewer
        than three distinct points, or all collinear: no triangles). Its
        ``boundary_at(trace.n_steps)`` equals ``reconstruct(points, ...).edges``.

    Raises
    ------
    InvalidInputError
        Wrong shape or non-finite coordinates. (A subclass of ValueError.)
    ValueError
        Unknown method.
    TypeError
        ``method`` is not a string.

    Examples
    --------
    A regular 12-gon around its centre (the paper's Figure 7): SIGDT is the fan, so the
    centre is inside the boundary and sculpting removes one triangle to reach it.

    >>> import numpy as np, sigdt
    >>> t = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    >>> points = np.r_[np.c_[np.cos(t), np.sin(t)], [[0, 0]]]
    >>> tr = sigdt.trace(points)
    >>> tr
    Trace(n_triangles=12, n_steps=1, inflated_at=0)
    >>> tr.phases
    ['sculpt']
    >>> len(tr.boundary_at(0)), len(tr.boundary_at(tr.n_steps))
    (12, 13)
    >>> sigdt.trace(points, method="crust") is None
    True
    """
    _check_method(method, leaf_elimination)
    array = _as_points(points)
    recorded = _core.trace(array, method, bool(leaf_elimination))
    return None if recorded is None else Trace(array, recorded)


class Trace:
    """The steps of inflating and sculpting of one run; see :func:`sigdt.trace`.

    The replay (:meth:`boundary_at`, :meth:`inside_at`) runs in Rust, on the recorded run.

    Attributes
    ----------
    points : numpy.ndarray
        The input points, ``(n, 2)`` float64.
    triangles : numpy.ndarray
        ``(T, 3)`` int64: every Delaunay triangle as point indices, counter-clockwise
        (a duplicate point appears as its lowest-index equal).
    graph : numpy.ndarray
        ``(m, 2)`` int64: the initial graph (SIGDT, SIGDT2 or BC0), rows ``[i, j]`` with
        ``i < j``, sorted.
    initial_inside : numpy.ndarray
        ``(T,)`` bool: which triangles are interior before the first step.
    dangling : numpy.ndarray
        ``(d, 2)`` int64: edges of the initial boundary with exterior on both sides.
    step_triangle : numpy.ndarray
        ``(S,)`` int64: the triangle (a row of ``triangles``) each step relabels.
    step_inside : numpy.ndarray
        ``(S,)`` bool: its new label, True for interior.
    step_phase : numpy.ndarray
        ``(S,)`` uint8: what made the step, an index into ``sigdt.PHASES``
        (``"inflate"``, ``"pocket"``, ``"sculpt"``).
    inflated_at : int
        The number of steps when inflating ended and sculpting started.
    """

    __slots__ = (
        "_recorded",
        "dangling",
        "graph",
        "inflated_at",
        "initial_inside",
        "points",
        "step_inside",
        "step_phase",
        "step_triangle",
        "triangles",
    )

    def __init__(self, points: np.ndarray, recorded: _core.Trace) -> None:
        self.points = points
        self._recorded = recorded  # the Rust trace, which replays the steps
        self.triangles = recorded.triangles
        self.graph = recorded.graph
        self.initial_inside = recorded.initial_inside
        self.dangling = recorded.dangling
        self.step_triangle = recorded.step_triangle
        self.step_inside = recorded.step_inside
        self.step_phase = recorded.step_phase
        self.inflated_at = recorded.inflated_at

    @property
    def n_steps(self) -> int:
        """The number of steps (label changes)."""
        return len(self.step_triangle)

    @property
    def phases(self) -> list[str]:
        """The phase name of every step: ``"inflate"``, ``"pocket"`` or ``"sculpt"``."""
        return [PHASES[code] for code in self.step_phase.tolist()]

    def _check_step(self, step: int) -> int:
        try:
            step = operator.index(step)
        except TypeError:
            raise TypeError(f"step must be an int, got {type(step).__name__}") from None
        if not 0 <= step <= self.n_steps:
            raise IndexError(f"step must be in 0..={self.n_steps}, got {step}")
        return step

    def inside_at(self, step: int) -> np.ndarray:
        """The triangle labels after the first ``step`` steps.

        Parameters
        ----------
        step : int
            From 0 (the initial labels) to ``n_steps``.

        Returns
        -------
        numpy.ndarray
            ``(T,)`` bool, True for interior.

        Raises
        ------
        IndexError
            ``step`` is outside ``0..=n_steps``.
        TypeError
            ``step`` is not an int.
        """
        return self._recorded.inside_at(self._check_step(step))

    def boundary_at(self, step: int) -> np.ndarray:
        """The boundary after the first ``step`` steps.

        The edges whose two sides have different labels (the outside of the convex hull
        counts as exterior), plus the initially dangling edges whose sides have stayed
        exterior all along.

        Parameters
        ----------
        step : int
            From 0 (the boundary of the initial graph) to ``n_steps`` (the result).

        Returns
        -------
        numpy.ndarray
            ``(m, 2)`` int64, rows ``[i, j]`` with ``i < j``, sorted.

        Raises
        ------
        IndexError
            ``step`` is outside ``0..=n_steps``.
        TypeError
            ``step`` is not an int.
        """
        return self._recorded.boundary_at(self._check_step(step))

    def __repr__(self) -> str:
        return (
            f"Trace(n_triangles={len(self.triangles)}, n_steps={self.n_steps}, "
            f"inflated_at={self.inflated_at})"
        )
