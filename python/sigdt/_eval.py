"""Metrics against ground truth: thin, documented wrappers of the Rust core's ``eval``."""

from __future__ import annotations

from typing import Any, cast

import numpy as np

from . import _core
from ._input import _as_points
from ._types import Evaluation, GraphOverlap

__all__ = ["evaluate", "graph_epsilon", "graph_overlap"]


def _as_edges(edges: Any, what: str) -> np.ndarray:
    array = np.asarray(edges)
    if array.size == 0:
        return np.zeros((0, 2), dtype=np.int64)
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"{what} must have shape (m, 2), got {array.shape}")
    if not np.issubdtype(array.dtype, np.integer):
        raise ValueError(f"{what} must be integer point indices, got dtype {array.dtype}")
    return np.ascontiguousarray(array, dtype=np.int64)


def evaluate(points: Any, edges: Any, gt: Any) -> Evaluation:
    """Score a reconstruction against ground truth.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The points both edge sets index.
    edges : array_like of int, shape (m, 2)
        The reconstruction, e.g. ``sigdt.reconstruct(points).edges``.
    gt : array_like of int, shape (k, 2)
        The ground-truth edges.

    Returns
    -------
    dict
        ``exact`` (the undirected edge sets are equal), ``missing`` and ``extra`` edge
        counts, ``rmse`` (two-sided), ``rmse_to_gt`` (result to ground truth) and
        ``hausdorff`` distances normalised by the ground truth's bounding-box diagonal
        (``None`` when either side has no edge), ``area_difference`` (symmetric difference
        of the enclosed areas, even-odd) and ``area_difference_normalised`` (over the
        ground truth's bounding-box area, ``None`` when that is zero).

    Raises
    ------
    InvalidInputError
        Points of the wrong shape or not finite.
    ValueError
        Edges of the wrong shape, or an index out of range (the message names the edge).

    Examples
    --------
    >>> import sigdt
    >>> square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    >>> m = sigdt.evaluate(square, [[0, 1], [1, 2], [2, 3]], [[0, 1], [1, 2], [2, 3], [0, 3]])
    >>> m["exact"], m["missing"], m["extra"]
    (False, 1, 0)
    """
    array = _as_points(points)
    return cast(Evaluation, _core.evaluate(array, _as_edges(edges, "edges"), _as_edges(gt, "gt")))


def graph_epsilon(points: Any, gt: Any) -> float:
    """The graph-based sampling density epsilon of a labelled sample (paper §3.1).

    The ground-truth polygon is split into arcs at corners (turns over 60 degrees) and
    junctions; the local feature size is the smaller of the planar-graph lfs between arcs
    and the distance to each arc's own medial axis. See ``docs/evaluation.md``.

    Parameters
    ----------
    points : array_like, shape (n, 2)
    gt : array_like of int, shape (k, 2)

    Returns
    -------
    float
        ``max dist(x, nearest sample) / lfs(x)`` over the ground-truth edges.

    Raises
    ------
    InvalidInputError
        Points of the wrong shape or not finite.
    ValueError
        Edges of the wrong shape or out of range.

    Examples
    --------
    >>> import numpy as np, sigdt
    >>> t = np.linspace(0, 2 * np.pi, 100, endpoint=False)
    >>> gt = [[i, (i + 1) % 100] for i in range(100)]
    >>> round(sigdt.graph_epsilon(np.c_[np.cos(t), np.sin(t)], gt), 3)  # tan(pi / 100)
    0.031
    """
    return _core.graph_epsilon(_as_points(points), _as_edges(gt, "gt"))


def graph_overlap(points: Any, gt: Any) -> GraphOverlap:
    """How well proximity graphs of the points contain the ground truth (paper §5).

    Parameters
    ----------
    points : array_like, shape (n, 2)
    gt : array_like of int, shape (k, 2)

    Returns
    -------
    dict
        ``sig_in_dt`` = |SIG ∩ DT| / |SIG|, ``dt_in_sig`` = |SIG ∩ DT| / |DT|,
        ``sigdt_in_gt`` = |GT ∩ SIGDT| / |SIGDT|, and for each graph ``G`` of ``sigdt``,
        ``sigdt2``, ``bc0``, ``knn2``, ``knn3``, ``knn4``: ``gt_in_G`` = |GT ∩ G| / |GT|
        and ``contains_gt_G`` (whether G contains all of GT).

    Raises
    ------
    InvalidInputError
        Points of the wrong shape or not finite.
    ValueError
        Edges of the wrong shape or out of range.

    Examples
    --------
    >>> import numpy as np, sigdt
    >>> t = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    >>> o = sigdt.graph_overlap(np.c_[np.cos(t), np.sin(t)], [[i, (i + 1) % 64] for i in range(64)])
    >>> o["contains_gt_sigdt"], o["gt_in_knn2"]
    (True, 1.0)
    """
    return cast(GraphOverlap, _core.graph_overlap(_as_points(points), _as_edges(gt, "gt")))
