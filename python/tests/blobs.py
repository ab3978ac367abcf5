"""Test inputs and output checkers shared by the Python tests.

``blob`` samples a smooth closed curve densely and uniformly in arc length, so the correct
reconstruction is known: the cycle through the samples in order. ``check_result`` states
the output invariants every :class:`sigdt.Reconstruction` must satisfy, whatever the input.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import sigdt

#: Statuses a Reconstruction may report.
STATUSES = set(sigdt._result.STATUSES)  # every status the core defines


def blob(
    n: int,
    amplitudes: Sequence[float] = (),
    phases: Sequence[float] = (),
    offset: float = 0.0,
    center: tuple[float, float] = (0.0, 0.0),
) -> np.ndarray:
    """``n`` points, in curve order, uniformly spaced in arc length on the radial Fourier
    blob ``r(θ) = 1 + Σ_k a_k cos(kθ + φ_k)`` (k = 2, 3, ...). ``offset`` in [0, 1) shifts
    the samples along the curve by that fraction of the spacing."""
    theta = np.linspace(0.0, 2.0 * np.pi, 8192 + 1)
    r = np.ones_like(theta)
    for k, (a, phi) in enumerate(zip(amplitudes, phases), start=2):
        r += a * np.cos(k * theta + phi)
    curve = np.c_[r * np.cos(theta), r * np.sin(theta)]
    arc = np.r_[0.0, np.cumsum(np.hypot(*np.diff(curve, axis=0).T))]
    s = (np.arange(n) + offset) * (arc[-1] / n)
    t = np.interp(s, arc, theta)
    r = np.ones_like(t)
    for k, (a, phi) in enumerate(zip(amplitudes, phases), start=2):
        r += a * np.cos(k * t + phi)
    return np.c_[r * np.cos(t) + center[0], r * np.sin(t) + center[1]]


def cycle_edges(n: int) -> np.ndarray:
    """The edges of the cycle 0-1-...-(n-1)-0 as sorted ``(n, 2)`` int64 rows ``i < j``."""
    k = np.arange(n, dtype=np.int64)
    return sort_edges(np.c_[k, (k + 1) % n])


def sort_edges(edges: np.ndarray) -> np.ndarray:
    """Rows ``[min, max]``, sorted lexicographically."""
    edges = np.sort(np.asarray(edges, dtype=np.int64).reshape(-1, 2), axis=1)
    return edges[np.lexsort((edges[:, 1], edges[:, 0]))]


def relabel(edges: np.ndarray, order: np.ndarray) -> np.ndarray:
    """Edges of a permuted input mapped back: point ``k`` of it is point ``order[k]``."""
    return sort_edges(np.asarray(order)[edges])


def normalise_loop(loop: np.ndarray) -> tuple[int, ...]:
    """A loop rotated to start at its smallest index (orientation kept)."""
    start = int(np.argmin(loop))
    return tuple(int(v) for v in np.roll(loop, -start))


def random_sets(count: int, seed: int) -> list[np.ndarray]:
    """``count`` varied point sets: blobs, random clouds, and every degenerate kind
    (empty, one or two points, collinear, duplicates, two separate curves)."""
    rng = np.random.default_rng(seed)
    sets: list[np.ndarray] = []
    for k in range(count):
        kind = k % 8
        if kind == 0:
            sets.append(np.empty((0, 2)))
        elif kind == 1:
            sets.append(rng.normal(size=(int(rng.integers(1, 3)), 2)))
        elif kind == 2:
            t = rng.permutation(int(rng.integers(3, 20))).astype(float)
            sets.append(np.c_[t, 2.0 * t + 1.0])
        elif kind == 3:
            base = rng.normal(size=(int(rng.integers(3, 40)), 2))
            sets.append(np.r_[base, base[rng.integers(0, len(base), size=5)]])
        elif kind == 4:
            sets.append(rng.integers(-3, 4, size=(int(rng.integers(3, 30)), 2)).astype(float))
        elif kind == 5:
            sets.append(np.r_[blob(40), blob(50, center=(5.0, 0.0))])
        else:
            n = int(rng.integers(30, 200))
            a = 0.25 * rng.uniform(size=3) / np.arange(2, 5) ** 2
            pts = blob(n, a, rng.uniform(0, 2 * np.pi, size=3), rng.uniform())
            sets.append(pts[rng.permutation(n)])
    return sets


def check_result(points: np.ndarray, rec: sigdt.Reconstruction) -> None:
    """Assert the output invariants of a reconstruction of ``points``."""
    n = len(points)
    edges = rec.edges
    assert rec.status in STATUSES
    assert edges.dtype == np.int64 and edges.ndim == 2 and edges.shape[1] == 2
    assert edges.flags.c_contiguous
    assert np.all(edges[:, 0] < edges[:, 1]), "an edge is not i < j"
    assert np.all((edges >= 0) & (edges < n)), "an edge index is out of range"
    if len(edges) > 1:
        diffs = np.diff(edges, axis=0)
        increasing = (diffs[:, 0] > 0) | ((diffs[:, 0] == 0) & (diffs[:, 1] > 0))
        assert np.all(increasing), "edges are not sorted and unique"

    # Duplicates: rows [duplicate, representative], the lowest-index copy represents.
    dup = rec.duplicates
    assert dup.dtype == np.int64 and dup.shape == (len(dup), 2)
    assert np.all(dup[:, 1] < dup[:, 0])
    assert np.array_equal(points[dup[:, 0]], points[dup[:, 1]])
    assert not np.isin(dup[:, 0], edges).any(), "a duplicate has an edge"
    distinct = np.setdiff1d(np.arange(n), dup[:, 0])
    assert len(np.unique(points[distinct], axis=0)) == len(distinct)

    # Loops and paths make up exactly the edges.
    chain_edges = []
    seen: set[int] = set()
    for loop in rec.loops:
        assert loop.dtype == np.int64 and len(loop) >= 3
        assert loop[0] == loop.min(), "a loop does not start at its smallest index"
        assert seen.isdisjoint(loop.tolist()) and len(set(loop.tolist())) == len(loop)
        seen.update(loop.tolist())
        chain_edges.append(np.c_[loop, np.roll(loop, -1)])
    for path in rec.paths:
        assert path.dtype == np.int64 and len(path) >= 2
        chain_edges.append(np.c_[path[:-1], path[1:]])
    from_chains = sort_edges(np.concatenate(chain_edges)) if chain_edges else edges[:0]
    assert np.array_equal(from_chains, edges), "loops/paths disagree with edges"

    degree = np.bincount(edges.ravel(), minlength=n)
    assert np.all(degree[rec.left_out] == 0), "a point left out has an edge"
    reasons = set(rec.left_out_reasons)
    if rec.is_manifold:
        # Loops through every distinct point but the outliers left out (SIG-AUTO).
        assert reasons <= {"outlier"} and not rec.paths
        on_loops = np.setdiff1d(distinct, rec.left_out)
        assert np.all(degree[on_loops] == 2), "a distinct point is not on exactly one loop"
        assert (len(rec.loops) == 1) == (rec.status == "polygon")
    if rec.status == "sculpting-stuck":
        assert "inside" in reasons
    else:
        assert "inside" not in reasons
    if rec.status == "too-few-points":
        assert len(distinct) < 3 and len(edges) == max(len(distinct) - 1, 0)
    if rec.status == "collinear":
        assert len(rec.paths) == 1 and len(rec.paths[0]) == len(distinct)
