"""The binding contract: dtypes, shapes, degenerate input, zero-copy, accepted input types,
exceptions, pickling, equality, views and ``reconstruct_many`` (``read_points``: see
test_read_points.py)."""

from __future__ import annotations

import copy
import json
import pickle
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
import sigdt
from blobs import blob, check_result, cycle_edges, random_sets

SQUARE = [[0, 0], [1, 0], [1, 1], [0, 1]]
STATS_KEYS = {
    "points",
    "distinct_points",
    "graph_edges",
    "leaf_edges_added",
    "non_manifold_before",
    "inflated_triangles",
    "pockets",
    "interior_before_sculpting",
    "sculpted_triangles",
}


@pytest.fixture(scope="module")
def circle() -> np.ndarray:
    return blob(100)


@pytest.fixture(scope="module")
def two_circles() -> np.ndarray:
    return np.r_[blob(40), blob(60, center=(5.0, 1.0))]


# --- dtypes and shapes -------------------------------------------------------------------


def test_result_dtypes_and_shapes(circle):
    rec = sigdt.reconstruct(circle)
    assert rec.points.dtype == np.float64 and rec.points.shape == (100, 2)
    assert rec.edges.dtype == np.int64 and rec.edges.shape == (100, 2)
    assert np.array_equal(rec.edges, cycle_edges(100))
    assert isinstance(rec.loops, list) and len(rec.loops) == 1
    assert rec.loops[0].dtype == np.int64 and rec.loops[0].ndim == 1
    assert rec.paths == []
    assert rec.left_out.dtype == np.int64 and rec.left_out.shape == (0,)
    assert rec.duplicates.dtype == np.int64 and rec.duplicates.shape == (0, 2)
    assert rec.status == "polygon" and rec.is_manifold is True
    check_result(circle, rec)


def test_loops_are_counter_clockwise_from_their_smallest_index(two_circles):
    rec = sigdt.reconstruct(two_circles)
    assert rec.status == "polygons" and len(rec.loops) == 2
    for loop in rec.loops:
        x, y = two_circles[loop].T
        signed_area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
        assert signed_area > 0 and loop[0] == loop.min()
    assert [loop[0] for loop in rec.loops] == sorted(loop[0] for loop in rec.loops)


@pytest.mark.parametrize(
    ("points", "n_edges", "paths"),
    [([], 0, []), ([[3.0, 4.0]], 0, []), ([[0, 0], [1, 1]], 1, [[0, 1]])],
    ids=["0-points", "1-point", "2-points"],
)
def test_too_few_points_is_a_result(points, n_edges, paths):
    rec = sigdt.reconstruct(points)
    assert rec.status == "too-few-points" and not rec.is_manifold
    assert rec.points.shape == (len(points), 2) and rec.points.dtype == np.float64
    assert rec.edges.shape == (n_edges, 2) and rec.edges.dtype == np.int64
    assert rec.loops == [] and [p.tolist() for p in rec.paths] == paths


def test_empty_array_of_any_empty_shape_is_zero_points():
    for empty in (np.empty((0, 2)), np.empty(0), np.empty((0, 0)), []):
        assert sigdt.reconstruct(empty).points.shape == (0, 2)


def test_collinear_points_give_the_path_in_line_order():
    points = [[0, 0], [3, 3], [1, 1], [2, 2], [-1, -1]]
    rec = sigdt.reconstruct(points)
    assert rec.status == "collinear" and not rec.is_manifold and rec.loops == []
    assert [p.tolist() for p in rec.paths] in ([[4, 0, 2, 3, 1]], [[1, 3, 2, 0, 4]])
    assert rec.edges.tolist() == [[0, 2], [0, 4], [1, 3], [2, 3]]


def test_duplicates_get_no_edges_and_are_listed(circle):
    points = np.r_[circle, circle[[5, 0, 5]]]
    rec = sigdt.reconstruct(points)
    assert rec.duplicates.tolist() == [[100, 5], [101, 0], [102, 5]]
    assert np.array_equal(rec.edges, cycle_edges(100))
    assert rec.status == "polygon" and rec.stats["distinct_points"] == 100
    check_result(points, rec)


def test_all_copies_of_one_point():
    rec = sigdt.reconstruct([[1, 2]] * 4)
    assert rec.status == "too-few-points" and len(rec.edges) == 0
    assert rec.duplicates.tolist() == [[1, 0], [2, 0], [3, 0]]


# --- zero-copy and accepted input types ----------------------------------------------------


def test_c_contiguous_float64_input_is_not_copied(circle):
    assert circle.flags.c_contiguous and circle.dtype == np.float64
    rec = sigdt.reconstruct(circle)
    assert np.shares_memory(rec.points, circle)


@pytest.mark.parametrize(
    "convert",
    [
        lambda a: a.astype(np.float32),
        np.asfortranarray,
        lambda a: np.repeat(a, 2, axis=0)[::2],
        lambda a: a.astype(">f8"),
    ],
    ids=["float32", "fortran", "strided", "big-endian"],
)
def test_other_arrays_are_converted(circle, convert):
    given = convert(circle)
    rec = sigdt.reconstruct(given)
    assert not np.shares_memory(rec.points, given)
    assert rec.points.dtype == np.float64 and rec.points.flags.c_contiguous
    assert np.array_equal(rec.points, given.astype(np.float64))
    assert np.array_equal(rec.edges, cycle_edges(100))


def test_unaligned_c_contiguous_input_works(circle):
    # Arrays deserialised from a byte buffer (e.g. by Dask's distributed) may be C-contiguous
    # float64 but not 8-byte aligned.
    buffer = bytearray(circle.nbytes + 1)
    unaligned = np.frombuffer(buffer, dtype=np.float64, offset=1).reshape(circle.shape)
    unaligned[:] = circle
    assert unaligned.flags.c_contiguous and not unaligned.flags.aligned
    assert sigdt.reconstruct(unaligned) == sigdt.reconstruct(circle)
    assert sigdt.reconstruct_many([unaligned]) == [sigdt.reconstruct(circle)]
    expected = sigdt.proximity_graph(circle)
    assert np.array_equal(sigdt.proximity_graph(unaligned), expected)


@pytest.mark.parametrize(
    "points",
    [
        SQUARE,
        tuple(tuple(p) for p in SQUARE),
        [tuple(p) for p in SQUARE],
        np.array(SQUARE, dtype=np.int64),
        np.array(SQUARE, dtype=np.int32),
        np.array(SQUARE, dtype=np.uint8),
        [[0.0, 0], [1, 0.0], [1.0, 1], [0, 1.0]],
    ],
    ids=["list", "tuple", "list-of-tuples", "int64", "int32", "uint8", "mixed"],
)
def test_accepted_input_types(points):
    rec = sigdt.reconstruct(points)
    assert rec.points.dtype == np.float64
    assert rec.edges.tolist() == [[0, 1], [0, 3], [1, 2], [2, 3]]
    assert rec == sigdt.reconstruct(np.array(SQUARE, dtype=np.float64))


# --- exceptions ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("points", "message"),
    [
        (np.zeros((4, 3)), r"shape \(n, 2\), got \(4, 3\)"),
        (np.zeros(4), r"shape \(n, 2\), got \(4,\)"),
        (np.zeros((2, 2, 2)), r"shape \(n, 2\), got \(2, 2, 2\)"),
        ([["a", "b"], ["c", "d"]], "cannot be read as an \\(n, 2\\) float array"),
        ([[0, 0], [1]], "cannot be read"),
    ],
    ids=["n-by-3", "1-D", "3-D", "strings", "ragged"],
)
def test_bad_shapes_and_values_raise_invalid_input(points, message):
    with pytest.raises(sigdt.InvalidInputError, match=message) as info:
        sigdt.reconstruct(points)
    assert isinstance(info.value, ValueError)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_coordinates_name_the_point(circle, bad):
    points = circle.copy()
    points[37, 1] = bad
    with pytest.raises(sigdt.InvalidInputError, match=r"^point 37 has a non-finite coordinate"):
        sigdt.reconstruct(points)
    with pytest.raises(sigdt.InvalidInputError, match=r"point 37"):
        sigdt.proximity_graph(points)


def test_impossible_coordinate_range_is_refused():
    with pytest.raises(sigdt.InvalidInputError, match="2\\^172"):
        sigdt.reconstruct([[0, 0], [1e-300, 0], [1e300, 1e300]])


def test_unknown_method_and_non_str_method():
    with pytest.raises(ValueError, match="unknown method 'gathan'.*sig-connect2d"):
        sigdt.reconstruct(SQUARE, method="gathan")
    with pytest.raises(TypeError, match="method must be a str, got int"):
        sigdt.reconstruct(SQUARE, method=3)
    with pytest.raises(TypeError):
        sigdt.reconstruct(SQUARE, "sig-connect2d")  # options are keyword-only


def test_the_default_method_is_sig_auto_and_leaf_elimination_needs_sig_connect2d():
    assert sigdt.reconstruct(SQUARE).method == "sig-auto"
    assert sigdt.reconstruct_many([SQUARE])[0].method == "sig-auto"
    rec = sigdt.reconstruct(SQUARE, method="sig-connect2d", leaf_elimination=False)
    assert rec.method == "sig-connect2d"
    # Without the method, the option would be dropped without a word.
    for call in (sigdt.reconstruct, lambda p, **kw: sigdt.reconstruct_many([p], **kw)):
        with pytest.raises(ValueError, match="applies to method='sig-connect2d' only"):
            call(SQUARE, leaf_elimination=False)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"kind": "delaunay"}, "unknown graph kind 'delaunay'"),
        ({"kind": "knn"}, "knn needs k"),
        ({"kind": "dt", "k": 2}, "k only applies to knn"),
        ({"kind": "knn", "k": 0}, "k must be a positive int"),
        ({"kind": "knn", "k": True}, "k must be a positive int"),
    ],
)
def test_proximity_graph_option_errors(kwargs, message):
    with pytest.raises(ValueError, match=message):
        sigdt.proximity_graph(SQUARE, **kwargs)


def test_internal_error_is_a_runtime_error():
    assert issubclass(sigdt.InternalError, RuntimeError)
    assert issubclass(sigdt.ParseError, ValueError)
    assert not issubclass(sigdt.ParseError, sigdt.InvalidInputError)


# --- proximity graphs ---------------------------------------------------------------------------


@pytest.mark.parametrize("kind", sigdt.GRAPH_KINDS)
def test_every_graph_kind_returns_sorted_int64_edges(circle, kind):
    k = 3 if kind == "knn" else None
    edges = sigdt.proximity_graph(circle, kind, k=k)
    assert edges.dtype == np.int64 and edges.ndim == 2 and edges.shape[1] == 2
    assert np.all(edges[:, 0] < edges[:, 1]) and len(edges) > 0
    assert np.array_equal(edges, np.unique(edges, axis=0))
    dt = {tuple(e) for e in sigdt.proximity_graph(circle, "dt").tolist()}
    if kind not in ("sig", "knn"):  # the others are subgraphs of the Delaunay triangulation
        assert {tuple(e) for e in edges.tolist()} <= dt


# --- pickling, equality, repr, views ---------------------------------------------------------------


def test_pickle_round_trip(two_circles):
    rec = sigdt.reconstruct(np.r_[two_circles, two_circles[:1]])
    for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1):
        back = pickle.loads(pickle.dumps(rec, protocol=protocol))
        assert back == rec and back is not rec
        assert back.status == rec.status and back.stats == rec.stats
        assert [loop.tolist() for loop in back.loops] == [loop.tolist() for loop in rec.loops]
    assert copy.deepcopy(rec) == rec


def test_pickle_is_compact_numpy_arrays():
    n = 10_000
    rec = sigdt.reconstruct(blob(n))
    assert rec.is_manifold
    size = len(pickle.dumps(rec))
    # points (16 B), edges (16 B) and the loop (8 B) per point, plus a few kB of framing:
    # about half the bound of twice that, and far below a pickle of Python lists.
    assert size < n * (16 + 16 + 8) + 4096, f"pickle of {n} points is {size} bytes"
    constructor, (points, fields, index, crs, lon_lat) = rec.__reduce__()
    assert constructor is sigdt.Reconstruction and isinstance(points, np.ndarray)
    assert index is None and crs is None and lon_lat is False
    arrays = [v for v in fields.values() if isinstance(v, np.ndarray)]
    assert len(arrays) == 7 and all(isinstance(a, np.ndarray) for a in arrays)
    assert all(a.dtype == np.int64 for a in arrays)


def test_equality_and_inequality(circle):
    rec = sigdt.reconstruct(circle)
    assert rec == sigdt.reconstruct(circle.copy())
    assert rec != sigdt.reconstruct(circle[:-1])
    moved = sigdt.reconstruct(circle + 1.0)  # same edges, other points
    assert np.array_equal(moved.edges, rec.edges) and moved != rec
    assert rec != "polygon"
    assert rec.__eq__(None) is NotImplemented
    with pytest.raises(TypeError):
        hash(rec)


@pytest.mark.parametrize(
    "points",
    [[], [[0, 0], [1, 1]], SQUARE, [[0, 0], [1, 1], [2, 2]]],
    ids=["empty", "two", "square", "collinear"],
)
def test_repr_is_one_line(points):
    text = repr(sigdt.reconstruct(points))
    assert "\n" not in text
    assert re.fullmatch(
        r"Reconstruction\(n_points=\d+, n_edges=\d+, n_loops=\d+, status='[a-z-]+'\)", text
    )


def test_is_manifold_follows_status(two_circles):
    assert sigdt.reconstruct(two_circles).is_manifold
    assert not sigdt.reconstruct([[0, 0], [1, 0], [2, 0]]).is_manifold
    assert not sigdt.reconstruct(SQUARE[:2]).is_manifold


def test_stats_keys_and_counts(circle):
    points = np.r_[circle, circle[:3]]
    stats = sigdt.reconstruct(points).stats
    assert set(stats) == STATS_KEYS
    assert all(type(v) is int and v >= 0 for v in stats.values())
    assert stats["points"] == 103 and stats["distinct_points"] == 100
    assert stats["graph_edges"] >= 100


@pytest.mark.parametrize(
    ("points", "geometry_type"),
    [
        (SQUARE, "Polygon"),
        ("two_circles", "MultiPolygon"),
        ([[0, 0], [1, 1], [3, 3]], "LineString"),
        ([[0, 0], [1, 1]], "LineString"),
        ([[0, 0]], None),
        ([], None),
    ],
)
def test_to_geojson(points, geometry_type, two_circles):
    if isinstance(points, str):
        points = two_circles
    rec = sigdt.reconstruct(points)
    feature = json.loads(json.dumps(rec.to_geojson()))
    assert feature["type"] == "Feature"
    geometry = feature["geometry"]
    assert (geometry and geometry["type"]) == geometry_type
    assert feature["properties"]["status"] == rec.status
    assert feature["properties"]["edges"] == len(rec.edges)
    if geometry_type == "Polygon":
        ring = geometry["coordinates"][0]
        assert ring[0] == ring[-1] and len(ring) == len(rec.loops[0]) + 1
    if geometry_type == "MultiPolygon":
        assert len(geometry["coordinates"]) == len(rec.loops) == 2


# --- reconstruct_many ---------------------------------------------------------------------------


@pytest.fixture(scope="module")
def varied_sets() -> list[np.ndarray]:
    return random_sets(200, seed=3)


@pytest.mark.parametrize("n_jobs", [None, 1, 2])
def test_reconstruct_many_equals_the_serial_loop(varied_sets, n_jobs):
    serial = [sigdt.reconstruct(p) for p in varied_sets]
    assert {r.status for r in serial} >= {"polygon", "polygons", "collinear", "too-few-points"}
    many = sigdt.reconstruct_many(varied_sets, n_jobs=n_jobs)
    assert len(many) == len(serial)
    for k, (a, b) in enumerate(zip(many, serial)):
        assert a == b, f"point set {k}"


def test_reconstruct_many_options_and_inputs(varied_sets):
    options = {"method": "sig-connect2d", "leaf_elimination": False}
    lists = [p.tolist() for p in varied_sets[:40]]
    many = sigdt.reconstruct_many(iter(lists), n_jobs=2, **options)
    assert many == [sigdt.reconstruct(p, **options) for p in lists]
    assert sigdt.reconstruct_many([]) == []


@pytest.mark.parametrize(
    "bad",
    [
        [[0, 0], [1, 0], [np.nan, 1]],
        np.zeros((3, 3)),
        [["x", "y"]],
    ],
    ids=["nan", "n-by-3", "strings"],
)
def test_reconstruct_many_names_the_bad_set(varied_sets, bad):
    sets = varied_sets[:57] + [bad] + varied_sets[57:]
    for n_jobs in (None, 1, 2):
        with pytest.raises(sigdt.InvalidInputError) as info:
            sigdt.reconstruct_many(sets, n_jobs=n_jobs)
        assert str(info.value).startswith("point set 57:"), str(info.value)


@pytest.mark.parametrize("n_jobs", [None, 1, 2])
def test_reconstruct_many_turns_a_panic_into_an_internal_error_naming_the_set(varied_sets, n_jobs):
    # The extension's test hook makes set 31 panic inside its rayon worker; the panic is
    # caught there, the other workers finish, and the error names the set.
    arrays = [np.ascontiguousarray(p, dtype=np.float64) for p in varied_sets[:64]]
    with pytest.raises(sigdt.InternalError) as info:
        sigdt._core.reconstruct_many(arrays, "sig-connect2d", True, n_jobs, _panic_in_set=31)
    message = str(info.value)
    assert message.startswith("point set 31: internal error in sigdt"), message
    assert "test hook" in message
    # The module is still usable afterwards.
    assert sigdt.reconstruct_many(varied_sets[:5]) == [
        sigdt.reconstruct(p) for p in varied_sets[:5]
    ]


@pytest.mark.parametrize("n_jobs", [0, True, 1.5, "2"])
def test_reconstruct_many_rejects_bad_n_jobs(n_jobs):
    with pytest.raises(ValueError, match="n_jobs"):
        sigdt.reconstruct_many([SQUARE], n_jobs=n_jobs)


def test_n_jobs_counts_like_scikit_learn_and_never_exceeds_the_cores():
    from sigdt._api import _cores, _threads

    cores = _cores()
    assert _threads(None) is None
    assert _threads(-1) == cores and _threads(1) == 1
    assert _threads(-2) == max(1, cores - 1) and _threads(-1000) == 1
    assert _threads(1000) == cores  # 1000 threads would take seconds to start
    assert sigdt.reconstruct_many([SQUARE] * 3, n_jobs=-1) == [sigdt.reconstruct(SQUARE)] * 3


def test_reconstruct_many_rejects_unknown_method():
    with pytest.raises(ValueError, match="unknown method"):
        sigdt.reconstruct_many([SQUARE], method="gathan")


# --- module constants ------------------------------------------------------------------------------


def test_version_matches_the_package_metadata(repo_root: Path):
    from importlib.metadata import version

    text = (repo_root / "pyproject.toml").read_text()
    declared = re.search(r'^version = "([^"]+)"', text, re.MULTILINE).group(1)
    assert sigdt.__version__ == declared == version("sigdt")


def test_methods_and_graph_kinds():
    assert sigdt.METHODS == [
        "sig-connect2d",
        "sig-auto",
        "connect2d",
        "crust",
        "nn-crust",
        "hnn-crust",
        "crawl",
        "discur",
        "fit-connect",
        "stretch-denoise",
        "peel",
        "emst",
        "optimal-transport",
    ]
    assert sigdt.GRAPH_KINDS == ["dt", "sig", "sigdt", "sigdt2", "emst", "knn"]
    for method in sigdt.METHODS:
        rec = sigdt.reconstruct(SQUARE, method=method)
        # CRAWL closes no cycle shorter than 6 points, and a spanning tree has no cycle:
        # for both the square stays an open path. OPTIMALTRANSPORT keeps a quarter of the
        # points: one vertex, no edge.
        open_ = ("crawl", "emst", "optimal-transport")
        assert rec.status == ("curves" if method in open_ else "polygon"), method
        kinds = {"optimal-transport": "new", "stretch-denoise": "moved"}
        kind = kinds.get(method, "input")
        assert rec.vertices_kind == kind, method
        assert (rec.vertices is rec.points) == (kind == "input"), method


def test_fit_connect_thins_noise_and_stretch_denoise_moves_points_within_it():
    # A noisy circle: FITCONNECT links most points and eliminates some between linked
    # ones; STRETCHDENOISE has the same edges and moves the curve points closer to the
    # circle, each at most its noise extent.
    rng = np.random.default_rng(7)
    t = np.linspace(0, 2 * np.pi, 120, endpoint=False)
    radius = 1 + rng.uniform(-0.01, 0.01, len(t))
    noisy = np.c_[radius * np.cos(t), radius * np.sin(t)]
    fit = sigdt.reconstruct(noisy, method="fit-connect")
    stretch = sigdt.reconstruct(noisy, method="stretch-denoise")
    assert fit.vertices_kind == "input" and stretch.vertices_kind == "moved"
    assert np.array_equal(fit.edges, stretch.edges) and len(fit.edges) > 60
    assert set(fit.left_out_reasons) <= {"eliminated", "non-conforming"}
    on_curve = np.unique(fit.edges)
    error = lambda p: np.abs(np.hypot(*p[on_curve].T) - 1).mean()
    assert error(stretch.vertices) < error(noisy)
    assert np.abs(stretch.vertices - noisy).max() < 0.05


def test_optimal_transport_draws_on_its_own_vertices():
    # Its edges index vertices it placed, not the input: every view must use those.
    t = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    circle = np.c_[np.cos(t), np.sin(t)]
    rec = sigdt.reconstruct(circle, method="optimal-transport")
    assert rec.vertices_kind == "new"
    assert rec.vertices.shape[1] == 2 and len(rec.vertices) < len(circle)
    assert len(rec.edges) and rec.edges.max() < len(rec.vertices)
    assert np.all(np.abs(np.hypot(*rec.vertices.T) - 1) < 0.05)
    import shapely

    drawn = shapely.get_coordinates(rec.to_shapely())
    assert len(drawn) and all((rec.vertices == xy).all(axis=1).any() for xy in drawn)
    feature = rec.to_geojson()
    lines = feature["geometry"]["coordinates"]
    assert all((rec.vertices == xy).all(axis=1).any() for line in lines for xy in line)


def test_curves_that_meet_read_as_a_network_with_its_junction() -> None:
    # A T: a bar of 17 samples with a stem of 8 ending on its middle (point 8).
    bar = [[float(i), 0.0] for i in range(-8, 9)]
    stem = [[0.1 * np.sin(i), float(i)] for i in range(1, 9)]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a reading of junctions is not a warning
        rec = sigdt.reconstruct(bar + stem)
    assert rec.status == "network"
    # A graph filter's branch is not read as a junction: it warns.
    with pytest.warns(sigdt.SigdtWarning, match="branch"):
        emst = sigdt.reconstruct(bar + stem, method="emst")
    assert emst.status == "branching"
    assert emst.junctions.tolist() == [8]
    assert rec.junctions.tolist() == [8]
    assert len(rec.edges) == 24
    assert all(path[0] == 8 or path[-1] == 8 for path in rec.paths)
    assert sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]]).junctions.tolist() == []
