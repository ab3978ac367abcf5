"""Points from shapely and GeoPandas, results as WKT and SVG."""

from __future__ import annotations

import pickle
import sys
import warnings
import xml.etree.ElementTree as ET

import geopandas as gpd
import numpy as np
import pytest
import shapely
import sigdt

SQUARE = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])


def test_shapely_points_read_like_arrays() -> None:
    expected = sigdt.reconstruct(SQUARE)
    multipoint = shapely.MultiPoint(SQUARE)
    assert sigdt.reconstruct(multipoint) == expected
    assert sigdt.reconstruct([shapely.Point(p) for p in SQUARE]) == expected
    assert sigdt.reconstruct(multipoint).index is None
    with pytest.raises(sigdt.InvalidInputError, match="from_shapely"):
        sigdt.reconstruct(shapely.Polygon(SQUARE))
    with pytest.raises(sigdt.InvalidInputError, match="sequence of Points"):
        sigdt.reconstruct([shapely.Point(0, 0), shapely.LineString(SQUARE)])
    # The polygon's vertices, explicitly: the closing vertex is a duplicate, left without edges.
    rec = sigdt.reconstruct(sigdt.from_shapely(shapely.Polygon(SQUARE)))
    assert rec.status == "polygon" and rec.duplicates.tolist() == [[4, 0]]
    assert sigdt.to_shapely(expected).equals(shapely.Polygon(SQUARE))


def test_empty_shapely_points_are_refused_by_position() -> None:
    # Shapely reads no coordinates from an empty point: taking the others would shift the
    # position of every later point, so that the result's indices name the wrong points.
    points = [shapely.Point(p) for p in SQUARE]
    points.insert(1, shapely.Point())
    with pytest.raises(sigdt.InvalidInputError, match=r"^point 1 is an empty point"):
        sigdt.reconstruct(points)
    multipoint = shapely.from_wkt("MULTIPOINT ((0 0), (1 0), EMPTY, (1 1), (0 1))")
    with pytest.raises(sigdt.InvalidInputError, match=r"^point 2 is an empty point"):
        sigdt.reconstruct(multipoint)
    with pytest.raises(sigdt.InvalidInputError, match=r"^point 0 is an empty point"):
        sigdt.reconstruct(shapely.Point())


def test_geopandas_rows_map_back_through_the_index() -> None:
    # Rows in a scrambled order with labels: the loop's rows come back by label.
    order = [2, 0, 3, 1]
    series = gpd.GeoSeries(gpd.points_from_xy(*SQUARE[order].T), index=["c", "a", "d", "b"])
    rec = sigdt.reconstruct(series)
    assert list(rec.index) == ["c", "a", "d", "b"]
    assert sorted(rec.index[rec.loops[0]]) == ["a", "b", "c", "d"]
    frame = gpd.GeoDataFrame({"name": list("cadb")}, geometry=series, index=series.index)
    assert sigdt.reconstruct(frame) == rec
    again = pickle.loads(pickle.dumps(rec))
    assert list(again.index) == list(rec.index)
    polygons = gpd.GeoSeries([shapely.Polygon(SQUARE)])
    with pytest.raises(sigdt.InvalidInputError, match="get_coordinates"):
        sigdt.reconstruct(polygons)
    with pytest.raises(sigdt.InvalidInputError, match=r"^row 1 \(position 1\) is missing"):
        sigdt.reconstruct(gpd.GeoSeries([shapely.Point(0, 0), None]))


def test_empty_geopandas_points_are_refused_by_row() -> None:
    rows = [shapely.Point(p) for p in SQUARE] + [shapely.Point()]
    series = gpd.GeoSeries(rows, index=[10, 20, 30, 40, 50])
    message = r"^row 50 \(position 4\) is an empty point"
    with pytest.raises(sigdt.InvalidInputError, match=message):
        sigdt.reconstruct(series)
    frame = gpd.GeoDataFrame({"name": list("abcde")}, geometry=series, index=series.index)
    with pytest.raises(sigdt.InvalidInputError, match=message):
        sigdt.reconstruct(frame)


def test_wkt_reads_back_as_the_shapely_geometry() -> None:
    t = np.linspace(0, 2 * np.pi, 40, endpoint=False)
    ring = np.c_[np.cos(t), np.sin(t)]
    for points, method in [
        (np.r_[ring, 0.4 * ring], "sig-auto"),  # a polygon with a hole
        (np.r_[ring, ring + 3], "sig-connect2d"),  # two polygons
        (np.c_[np.linspace(0, 1, 9), np.linspace(0, 1, 9) ** 2], "sig-auto"),  # a path
    ]:
        rec = sigdt.reconstruct(points, method=method)
        back, direct = shapely.from_wkt(rec.to_wkt()), rec.to_shapely()
        assert shapely.normalize(back).equals_exact(shapely.normalize(direct), 0.0), method
    empty = sigdt.reconstruct(np.zeros((0, 2)))
    assert empty.to_wkt() == "GEOMETRYCOLLECTION EMPTY"


def test_svg_is_a_standalone_picture() -> None:
    rec = sigdt.reconstruct(SQUARE)
    svg = rec.to_svg(width=200)
    root = ET.fromstring(svg)
    assert root.tag.endswith("svg") and root.get("width") == "200"
    assert svg.count("<circle") == 4 and 'fill-rule="evenodd"' in svg
    assert "4 points, 4 edges, polygon" in svg
    with pytest.raises(ValueError, match="width"):
        rec.to_svg(width=3)
    ET.fromstring(sigdt.reconstruct(np.zeros((0, 2))).to_svg())


def test_svg_frames_any_finite_range_as_the_cli_does() -> None:
    # Corners at ±f64::MAX overflow the box's extent, a subnormal side the scale; the CLI
    # draws both (in quarter units; the tiny square as a point), and so must to_svg.
    big = sys.float_info.max
    huge = np.array([[-big, -big], [big, -big], [big, big], [-big, big]])
    for square in (huge, SQUARE * 5e-324):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # numpy's overflow warnings included
            svg = sigdt.reconstruct(square).to_svg(width=200)
        root = ET.fromstring(svg)
        size = [float(root.get(k)) for k in ("width", "height")]
        xy = [[float(e.get("cx")), float(e.get("cy"))] for e in root.iter() if e.get("cx")] + [
            [float(v) for v in token.split(",")]
            for e in root.iter()
            for token in (e.get("d") or "").split()
            if "," in token
        ]
        assert len(xy) == 4 + 4 + 2 * 4, svg  # dots, the loop's vertices, the edges' ends
        assert np.isfinite(xy).all() and ((0 <= np.array(xy)) & (np.array(xy) <= size)).all()
    # An exact power-of-two scaling: the picture of the unit square, stretched.
    assert sigdt.reconstruct(huge).to_svg() == sigdt.reconstruct(SQUARE * 2 - 1).to_svg()
