"""Hypothesis property tests mirroring crates/sigdt/tests/properties.rs, through the binding.

- A smooth closed curve sampled densely and uniformly in arc length is reconstructed exactly
  (the cycle through the samples), and SIGDT contains that cycle ([MOW22] Theorem 1).
- Results are invariant under permutation (relabelled), translation, uniform scaling and a
  90° rotation.
- On arbitrary point clouds (duplicates and collinear subsets included) every output
  invariant holds and nothing crashes.

The curves are radial Fourier blobs ``r(θ) = 1 + Σ_{k=2..4} a_k cos(kθ + φ_k)`` with
``a_k ≤ 0.25 U_k / k²``: the curvature radius stays above about 0.5 while the perimeter is
about 2π, so 80 uniform samples already give a spacing well under the local feature size.
Coordinates are drawn on grids (offsets and shifts in thousandths, free coordinates rounded
to 1e-6): a coordinate like 1e-300 next to 1.0 is refused by design (README: coordinates may
not span more than about 2**172). The runs are derandomized, so CI is reproducible.
"""

from __future__ import annotations

import numpy as np
import sigdt
from blobs import blob, check_result, cycle_edges, normalise_loop, relabel, sort_edges
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

SETTINGS = {
    "deadline": None,
    "derandomize": True,
    "database": None,
    "suppress_health_check": [HealthCheck.too_slow],
}


@st.composite
def dense_blobs(draw):
    """``(points, n)``: a random blob sampled uniformly, in curve order."""
    n = draw(st.integers(80, 300))
    u = np.array([draw(st.floats(0.0, 1.0)) for _ in range(3)])
    phases = [draw(st.floats(0.0, 2.0 * np.pi)) for _ in range(3)]
    offset = draw(st.integers(0, 999)) / 1000
    return blob(n, 0.25 * u / np.arange(2, 5) ** 2, phases, offset), n


def _permutation(n: int, seed: int) -> np.ndarray:
    return np.random.default_rng(seed).permutation(n)


@settings(max_examples=200, **SETTINGS)
@given(dense_blobs(), st.integers(0, 2**32 - 1))
def test_dense_blob_is_reconstructed_exactly(sample, seed):
    curve, n = sample
    order = _permutation(n, seed)
    points = curve[order]  # point k is curve sample order[k]
    expected = cycle_edges(n)
    sigdt_edges = sigdt.proximity_graph(points, kind="sigdt")
    sigdt_set = {tuple(e) for e in relabel(sigdt_edges, order).tolist()}
    assert {tuple(e) for e in expected.tolist()} <= sigdt_set, "a curve edge is not in SIGDT"
    for leaf_elimination in (True, False):
        rec = sigdt.reconstruct(points, method="sig-connect2d", leaf_elimination=leaf_elimination)
        check_result(points, rec)
        assert rec.status == "polygon"
        assert np.array_equal(relabel(rec.edges, order), expected), leaf_elimination
    rec = sigdt.reconstruct(points)  # SIG-AUTO
    assert rec.status == "polygon" and np.array_equal(relabel(rec.edges, order), expected)


@settings(max_examples=150, **SETTINGS)
@given(
    dense_blobs(),
    st.integers(0, 2**32 - 1),
    st.tuples(*[st.integers(-(10**6), 10**6).map(lambda i: i / 1000)] * 2),
    st.floats(-3.0, 3.0),
)
def test_invariant_under_order_translation_scale_and_rotation(sample, seed, shift, exponent):
    curve, n = sample
    base = sigdt.reconstruct(curve)
    loops = sorted(normalise_loop(loop) for loop in base.loops)

    order = _permutation(n, seed)
    permuted = sigdt.reconstruct(curve[order])
    assert np.array_equal(relabel(permuted.edges, order), base.edges), "permutation"
    assert sorted(normalise_loop(order[loop]) for loop in permuted.loops) == loops

    moved = sigdt.reconstruct(curve + np.array(shift))
    assert np.array_equal(moved.edges, base.edges), "translation"
    scaled = sigdt.reconstruct(curve * 10.0**exponent)
    assert np.array_equal(scaled.edges, base.edges), "scaling"
    rotated = sigdt.reconstruct(np.c_[-curve[:, 1], curve[:, 0]])
    assert np.array_equal(rotated.edges, base.edges), "90° rotation"
    assert [r.tolist() for r in rotated.loops] == [r.tolist() for r in base.loops]


def _clouds():
    """(n, 2) float64 arrays: coordinates on a coarse grid (many duplicates and collinear
    runs), or free floats over many magnitudes."""
    n = st.integers(0, 60)
    grid = st.integers(-4, 4).map(float)
    free = st.floats(-1e6, 1e6).map(lambda x: round(x, 6))
    coarse = hnp.arrays(np.float64, st.tuples(n, st.just(2)), elements=grid)
    fine = hnp.arrays(np.float64, st.tuples(n, st.just(2)), elements=free)
    slope = st.integers(-3000, 3000).map(lambda i: i / 1000)
    line = st.tuples(n, slope, slope).map(
        lambda t: np.c_[np.arange(t[0]) * t[1], np.arange(t[0]) * t[2] + 1.0]
    )
    return st.one_of(coarse, fine, line)


@settings(max_examples=500, **SETTINGS)
@given(
    _clouds(),
    st.sampled_from([("sig-auto", True), ("sig-connect2d", True), ("sig-connect2d", False)]),
)
def test_output_invariants_on_arbitrary_clouds(points, options):
    method, leaf_elimination = options
    rec = sigdt.reconstruct(points, method=method, leaf_elimination=leaf_elimination)
    check_result(points, rec)
    assert rec.stats["points"] == len(points)
    again = sigdt.reconstruct(points.copy(), method=method, leaf_elimination=leaf_elimination)
    assert rec.stats["distinct_points"] == len(points) - len(rec.duplicates)
    assert rec == again


@settings(max_examples=200, **SETTINGS)
@given(_clouds())
def test_proximity_graphs_on_arbitrary_clouds(points):
    dt = sigdt.proximity_graph(points, kind="dt")
    dt_set = {tuple(e) for e in dt.tolist()}
    for kind in ("dt", "sig", "sigdt", "sigdt2", "emst", "knn"):
        edges = sigdt.proximity_graph(points, kind=kind, k=2 if kind == "knn" else None)
        assert edges.dtype == np.int64 and edges.shape == (len(edges), 2)
        assert np.array_equal(edges, sort_edges(np.unique(edges, axis=0)))
        assert np.all(edges[:, 0] < edges[:, 1])
        if kind in ("sigdt", "sigdt2", "emst"):
            assert {tuple(e) for e in edges.tolist()} <= dt_set, kind
    sig = {tuple(e) for e in sigdt.proximity_graph(points, kind="sig").tolist()}
    sig_dt = {tuple(e) for e in sigdt.proximity_graph(points, kind="sigdt").tolist()}
    assert sig_dt == sig & dt_set, "SIGDT is the SIG restricted to Delaunay edges"
