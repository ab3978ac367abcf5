"""Shapely views: geometry types, validity, area, and the from_shapely round trip."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
import sigdt
from blobs import blob
from sigdt.shapely import from_shapely, to_shapely


def test_one_loop_is_a_polygon():
    rec = sigdt.reconstruct(blob(200, [0.05, 0.02], [0.3, 1.0]))
    geometry = rec.to_shapely()
    assert geometry.geom_type == "Polygon" and geometry.is_valid
    assert len(geometry.interiors) == 0
    assert len(geometry.exterior.coords) == 201  # closed ring
    assert to_shapely(rec).equals(geometry)


def test_two_separate_circles_are_a_multipolygon():
    points = np.r_[blob(80), blob(120, center=(4.0, -1.0))]
    rec = sigdt.reconstruct(points)
    geometry = rec.to_shapely()
    assert rec.status == "polygons"
    assert geometry.geom_type == "MultiPolygon" and geometry.is_valid
    assert len(geometry.geoms) == 2
    assert sorted(len(g.exterior.coords) - 1 for g in geometry.geoms) == [80, 120]


def test_collinear_points_are_a_linestring():
    geometry = sigdt.reconstruct([[0, 0], [2, 1], [4, 2], [1, 0.5]]).to_shapely()
    assert geometry.geom_type == "LineString" and geometry.is_valid
    assert geometry.length == pytest.approx(np.hypot(4, 2))
    assert shapely.get_coordinates(geometry).tolist() in (
        [[0, 0], [1, 0.5], [2, 1], [4, 2]],
        [[4, 2], [2, 1], [1, 0.5], [0, 0]],
    )


@pytest.mark.parametrize("points", [[], [[1.0, 2.0]]], ids=["0-points", "1-point"])
def test_no_edges_is_an_empty_linestring(points):
    geometry = sigdt.reconstruct(points).to_shapely()
    assert geometry.geom_type == "LineString" and geometry.is_empty


def test_two_points_are_a_segment():
    geometry = sigdt.reconstruct([[0, 0], [3, 4]]).to_shapely()
    assert geometry.geom_type == "LineString" and geometry.length == pytest.approx(5.0)


def test_dense_circle_area_is_pi():
    rec = sigdt.reconstruct(blob(1000, offset=0.5))
    polygon = rec.to_shapely()
    assert polygon.is_valid
    assert polygon.area == pytest.approx(np.pi, rel=0.01)
    assert polygon.length == pytest.approx(2 * np.pi, rel=0.01)


def test_duplicates_do_not_break_validity():
    points = blob(150)
    rec = sigdt.reconstruct(np.r_[points, points[::10]])
    assert rec.to_shapely().is_valid and rec.to_shapely().area > 3.0


def test_from_shapely_returns_the_vertices():
    polygon = shapely.Polygon([(0, 0), (2, 0), (2, 1), (0, 1)])
    coords = from_shapely(polygon)
    assert coords.dtype == np.float64 and coords.flags.c_contiguous and coords.shape == (5, 2)
    assert coords[0].tolist() == coords[-1].tolist() == [0.0, 0.0]


def _round_trip(polygon):
    """Reconstruct the polygon from its vertices (closing point dropped, order shuffled)."""
    coords = from_shapely(polygon)
    assert np.array_equal(coords[0], coords[-1])
    points = coords[:-1]
    shuffled = points[np.random.default_rng(5).permutation(len(points))]
    rec = sigdt.reconstruct(shuffled)
    assert rec.status == "polygon"
    return rec.to_shapely()


def test_round_trip_of_a_segmentized_circle():
    # A buffered point has 4 * quad_segs equal sides; segmentize splits every side into the
    # same number of pieces, so the samples stay uniform.
    circle = shapely.Point(1.0, -2.0).buffer(3.0, quad_segs=16)
    polygon = shapely.segmentize(circle, max_segment_length=0.1)
    sides = np.hypot(*np.diff(shapely.get_coordinates(polygon.exterior), axis=0).T)
    assert len(sides) == 192 and sides.max() < 1.001 * sides.min()
    result = _round_trip(polygon)
    assert result.is_valid
    assert result.symmetric_difference(polygon).area == pytest.approx(0.0, abs=1e-9)
    assert result.normalize().equals_exact(polygon.normalize(), tolerance=0.0)


def test_round_trip_of_a_smooth_non_convex_shape():
    # An L with rounded corners: outward buffer rounds the convex corners, the inward one
    # rounds the reflex corner. Resampled uniformly in arc length along the boundary.
    ell = shapely.union(shapely.box(0, 0, 4, 1), shapely.box(0, 0, 1, 4))
    shape = ell.buffer(0.6, quad_segs=32).buffer(-0.3, quad_segs=32)
    ring = shape.exterior
    distances = np.linspace(0.0, ring.length, 700, endpoint=False)
    samples = shapely.get_coordinates(shapely.line_interpolate_point(ring, distances))
    polygon = shapely.Polygon(samples)
    assert polygon.is_valid and polygon.area < shape.area * 1.001
    result = _round_trip(polygon)
    assert result.is_valid
    assert result.symmetric_difference(polygon).area == pytest.approx(0.0, abs=1e-9)
    assert result.normalize().equals_exact(polygon.normalize(), tolerance=0.0)


def _rings_in_rings() -> np.ndarray:
    """Three nested circles (radii 3, 2, 1) and a separate one."""
    return np.r_[
        blob(150, center=(0.0, 0.0)) * 3.0,
        blob(100, center=(0.0, 0.0)) * 2.0,
        blob(50),
        blob(60, center=(8.0, 0.0)),
    ]


def test_sig_auto_nested_loops_are_polygons_with_holes():
    rec = sigdt.reconstruct(_rings_in_rings(), method="sig-auto")
    assert rec.status == "polygons" and len(rec.loops) == 4
    geometry = rec.to_shapely()
    assert geometry.geom_type == "MultiPolygon" and geometry.is_valid
    # The ring between radii 3 and 2, the disk of radius 1 inside it, the separate disk.
    parts = sorted(geometry.geoms, key=lambda g: -g.area)
    assert [len(g.interiors) for g in parts] == [1, 0, 0]
    assert parts[0].area == pytest.approx(np.pi * (9 - 4), rel=0.01)
    feature = rec.to_geojson()
    assert feature["geometry"]["type"] == "MultiPolygon"
    assert shapely.geometry.shape(feature["geometry"]).equals(geometry)


def test_sig_auto_open_curve_is_a_linestring_and_mixed_is_a_collection():
    t = np.linspace(0.0, 1.5 * np.pi, 60)
    arc = np.c_[np.cos(t), np.sin(t)]
    rec = sigdt.reconstruct(arc, method="sig-auto")
    assert rec.status == "curves" and not rec.loops
    assert [p.tolist() for p in rec.paths] == [list(range(60))]
    assert rec.to_shapely().geom_type == "LineString"
    both = sigdt.reconstruct(np.r_[arc, blob(40, center=(5.0, 0.0))], method="sig-auto")
    geometry = both.to_shapely()
    assert geometry.geom_type == "GeometryCollection"
    assert sorted(g.geom_type for g in geometry.geoms) == ["LineString", "Polygon"]


def test_to_wkt_and_to_geojson_take_every_name_the_core_gives():
    """The writer rebuilds the core's result from the Python one: every status, reason and
    finding kind name is read back, and a pickled result writes the same text."""
    import pickle
    import typing

    from sigdt import _types

    square = sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]])
    for status in typing.get_args(_types.Status):
        fields = {**square._fields, "status": status}
        feature = sigdt.Reconstruction(square.points, fields).to_geojson()
        assert feature["properties"]["status"] == status
    reasons = list(typing.get_args(_types.LeftOutReason))
    kinds = typing.get_args(_types.FindingKind)
    findings = [
        {"kind": k, "count": 1, "worst": 0.5, "at": 0, "point": [0.0, 1.0], "message": ""}
        for k in kinds
    ]
    fields = {
        **square._fields,
        "left_out": np.arange(len(reasons), dtype=np.int64) % 4,
        "left_out_reasons": reasons,
        "diagnosis": findings,
    }
    properties = sigdt.Reconstruction(square.points, fields).to_geojson()["properties"]
    assert properties["left_out_reasons"] == reasons and properties["warning"] is True
    assert [f["kind"] for f in properties["diagnosis"]] == list(kinds)
    assert all(f["message"] for f in properties["diagnosis"])  # the core's own sentence
    back = pickle.loads(pickle.dumps(square))
    assert back.to_wkt() == square.to_wkt() and back.to_geojson() == square.to_geojson()


def test_a_result_whose_indices_are_out_of_range_is_refused():
    square = sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]])
    fields = {**square._fields, "loop_vertices": np.array([0, 1, 2, 9], dtype=np.int64)}
    with pytest.raises(ValueError, match="vertex 9 is not a point index"):
        sigdt.Reconstruction(square.points, fields).to_wkt()
    with pytest.raises(ValueError, match="unknown status"):
        sigdt.Reconstruction(square.points, {**square._fields, "status": "nope"}).to_wkt()


def warped_grid(cells: int, per_side: int = 8) -> np.ndarray:
    """The lines of a `cells` x `cells` grid, sampled `per_side` times a cell side with every
    crossing a sample of both lines, bent into smooth curves."""
    steps = np.arange(cells * per_side + 1) / per_side
    lines = np.arange(cells + 1, dtype=float)
    u_rows, v_rows = np.meshgrid(steps, lines)
    v_cols, u_cols = np.meshgrid(steps[np.arange(steps.size) % per_side != 0], lines)
    u, v = np.r_[u_rows.ravel(), u_cols.ravel()], np.r_[v_rows.ravel(), v_cols.ravel()]
    return np.c_[u + 0.2 * np.sin(0.9 * v), v + 0.2 * np.sin(0.8 * u)]


def test_a_network_is_noded_lines_and_its_faces_are_polygons():
    cells = 4
    rec = sigdt.reconstruct(warped_grid(cells))
    assert rec.status == "network" and not rec.warns
    lines = rec.to_shapely()
    assert lines.geom_type == "MultiLineString"
    # Paths end at junctions: the lines meet only at their ends (noded).
    assert shapely.union_all(lines).equals(lines) and len(lines.geoms) == len(rec.paths)
    faces = rec.to_shapely(faces=True)
    assert faces.geom_type == "GeometryCollection"
    assert len(faces.geoms) == cells * cells
    assert all(face.geom_type == "Polygon" and face.is_valid for face in faces.geoms)
    # The cells tile the grid's frame: the warp bends its sides, so the area is near cells².
    assert faces.area == pytest.approx(shapely.union_all(faces.geoms).area)
    assert faces.area == pytest.approx(cells * cells, rel=0.1)
    # Loops are faces too, and open curves bound nothing.
    circle = sigdt.reconstruct(blob(60))
    assert circle.to_shapely(faces=True).area == pytest.approx(circle.to_shapely().area)
    line = sigdt.reconstruct(np.c_[np.linspace(0, 1, 20), np.linspace(0, 1, 20) ** 2])
    assert line.to_shapely(faces=True).is_empty
