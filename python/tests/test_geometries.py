"""Issue 46: geometries in, geometries out (``sigdt.outlines``), one geometry type per layer,
a failing group a row, and the antimeridian; the Natural Earth countries end to end."""

from __future__ import annotations

import warnings
from pathlib import Path

import geopandas as gpd
import numpy as np
import pyogrio
import pytest
import shapely
import sigdt

NATURAL_EARTH = (
    Path(pyogrio.__file__).parent / "tests/fixtures/naturalearth_lowres/naturalearth_lowres.shp"
)


def _circle(cx: float, cy: float, r: float, n: int) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.c_[cx + r * np.cos(t), cy + r * np.sin(t)]


def _quiet(call, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sigdt.SigdtWarning)
        return call(*args, **kwargs)


def test_outlines_takes_what_concave_hull_takes() -> None:
    ring = _circle(0, 0, 10, 40)
    polygon = shapely.Polygon(ring)
    series = gpd.GeoSeries(
        [shapely.MultiPoint(ring), polygon, shapely.LinearRing(ring)],
        index=["points", "polygon", "ring"],
        crs=27700,
    )
    out = sigdt.outlines(series)
    assert list(out.index) == list(series.index) and out.crs == series.crs
    assert set(out.geom_type) == {"MultiPolygon"}
    for geometry in out:
        assert geometry.normalize().equals(shapely.MultiPolygon([polygon]).normalize())
    # The same points, as a numpy array of geometries and as one geometry.
    assert sigdt.outlines(series.values).geom_type.tolist() == ["MultiPolygon"] * 3
    assert sigdt.outlines(polygon).area == pytest.approx(polygon.area)
    # concave_hull, beside it: a polygon too, here the same.
    assert series.concave_hull().iloc[0].normalize().equals(polygon.normalize())


def test_outlines_by_groups_the_geometries_as_dissolve_does() -> None:
    a, b = _circle(0, 0, 10, 40), _circle(50, 0, 10, 40)
    frame = gpd.GeoDataFrame(
        {"island": ["a"] * 40 + ["b"] * 40}, geometry=shapely.points(np.r_[a, b]), crs=3857
    )
    out = sigdt.outlines(frame, by="island")
    assert list(out.index) == ["a", "b"] and out.index.name == "island"
    assert out.area.round(0).tolist() == [round(shapely.Polygon(a).area)] * 2
    curves = sigdt.outlines(frame, by="island", expect="curves")
    assert set(curves.geom_type) == {"MultiLineString"} and curves.iloc[0].is_closed
    # A list of one column groups as the column does (it raised inside pandas before).
    listed = sigdt.outlines(frame, by=["island"])
    assert list(listed.index) == ["a", "b"] and listed.index.names == ["island"]
    assert listed.geom_equals(out).all()


def test_a_failing_geometry_or_group_is_a_row_and_the_warning_names_it() -> None:
    good = shapely.MultiPoint(_circle(0, 0, 1, 20))
    series = gpd.GeoSeries([good, shapely.MultiPoint([(5, 5), (6, 6)]), None, good])
    with pytest.warns(sigdt.SigdtWarning, match=r"1 of 4 groups failed .*\(row 2\)") as caught:
        out = sigdt.outlines(series)
    assert len(caught) == 1 and "row 1" in str(caught[0].message)  # two points: warns
    assert out.is_empty.tolist() == [False, True, True, False]
    with pytest.raises(sigdt.InvalidInputError, match="^row 2: no points"):
        sigdt.outlines(series, errors="raise")


def test_reconstruct_frame_returns_every_other_group_when_one_fails() -> None:
    rng = np.random.default_rng(3)
    points = np.concatenate([_circle(rng.uniform(-100, 100), 10, 0.5, 30) for _ in range(177)])
    points[31] = [-180.0015, 10.0]  # group 1 has a point off the map
    frame = gpd.GeoDataFrame(
        {"country": np.repeat(np.arange(177), 30)},
        geometry=shapely.points(points),
        crs="EPSG:4326",
    )
    with pytest.warns(sigdt.SigdtWarning, match=r"1 of 177 groups failed .*\(group 1\)"):
        out = sigdt.reconstruct_frame(frame, by="country", progress=False)
    assert len(out) == 177 and (out.status == "error").tolist() == [k == 1 for k in range(177)]
    assert "-180.0015" in out.loc[1, "diagnosis"] and out.loc[1, "geometry"].is_empty
    assert (out.drop(index=1).status == "polygon").all()
    with pytest.raises(sigdt.InvalidInputError, match="^group 1: "):
        sigdt.reconstruct_frame(frame, by="country", progress=False, errors="raise")


def test_every_layer_has_one_geometry_type_and_writes_to_a_shapefile(tmp_path: Path) -> None:
    theta = np.r_[_circle(0, 0, 1, 48), np.c_[np.linspace(-1, 1, 17)[1:-1], np.zeros(15)]]
    line = np.c_[np.linspace(10, 20, 30), np.sin(np.linspace(10, 20, 30))]
    frame = gpd.GeoDataFrame(
        {"g": ["ring"] * 48 + ["theta"] * 63 + ["line"] * 30 + ["two"] * 2},
        geometry=shapely.points(np.r_[_circle(5, 5, 1, 48), theta, line, [[0, 9], [1, 9]]]),
        crs=2154,
    )
    out = _quiet(sigdt.reconstruct_frame, frame, by="g", progress=False)
    assert out.geometry.geom_type.unique().tolist() == ["MultiPolygon"]
    for column in ["paths", "networks"]:
        assert out[column].geom_type.unique().tolist() == ["MultiLineString"], column
    assert not out.loc["theta", "networks"].is_empty and out.loc["theta", "paths"].is_empty
    assert not out.loc["line", "paths"].is_empty and out.loc["line", "networks"].is_empty
    layers = sigdt.geopandas.layers(out)
    assert {k: sorted(v.index) for k, v in layers.items()} == {
        "areas": ["ring"],
        "paths": ["line", "two"],
        "networks": ["theta"],
    }
    for name, layer in layers.items():
        layer.to_file(tmp_path / f"{name}.shp")
        back = gpd.read_file(tmp_path / f"{name}.shp")
        assert back.crs.to_epsg() == 2154 and len(back) == len(layer), name


def _country_points(spacing: float) -> tuple[gpd.GeoDataFrame, gpd.GeoSeries]:
    """Natural Earth's 177 countries, their outlines densified every ``spacing`` degrees, as
    points (one row per vertex, named), and the true polygons by name."""
    world = gpd.read_file(NATURAL_EARTH)
    dense = world.geometry.segmentize(spacing).get_coordinates(index_parts=False)
    names = world.loc[dense.index, "name"].to_numpy()
    points = gpd.GeoDataFrame(
        {"name": names}, geometry=gpd.points_from_xy(dense.x, dense.y), crs=world.crs
    )
    return points, world.set_index("name").geometry


def _iou(a: shapely.Geometry, b: shapely.Geometry) -> float:
    return shapely.intersection(a, b).area / shapely.union(a, b).area


def test_natural_earth_countries_across_the_antimeridian(tmp_path: Path) -> None:
    """The issue's target: every country at 0.1°, every layer one type and writable to a
    Shapefile; Russia and Fiji, which store each crossing point at +180 and at -180, valid
    in EPSG:4326, no part wider than 180°, IoU ≥ 0.99."""
    points, truth = _country_points(0.1)
    assert len(truth) == 177
    out = _quiet(sigdt.reconstruct_frame, points, by="name", expect="areas", progress=False)
    assert len(out) == 177 and out.crs.to_epsg() == 4326
    for name in ["Russia", "Fiji"]:
        area = out.loc[name, "geometry"]
        assert area.is_valid, name
        widths = [g.bounds[2] - g.bounds[0] for g in area.geoms]
        assert max(widths) <= 180.0, (name, widths)
        assert _iou(area, truth[name]) >= 0.99, name
    for name, layer in sigdt.geopandas.layers(out).items():
        assert len(set(layer.geom_type)) <= 1, name
        layer.to_file(tmp_path / f"{name}.shp")


def test_a_polygon_across_the_antimeridian_is_split_there() -> None:
    island = _circle(180.0, -17.0, 0.5, 60)
    island[:, 0] = np.where(island[:, 0] > 180.0, island[:, 0] - 360.0, island[:, 0])
    # Its two points on the meridian, stored once at +180 and once more at -180.
    on_meridian = island[np.isclose(np.abs(island[:, 0]), 180.0)]
    points = np.r_[island, on_meridian * [-1, 1]]
    rec = sigdt.reconstruct(gpd.GeoSeries(shapely.points(points), crs=4326))
    assert rec.status == "polygon" and len(rec.duplicates) == len(on_meridian)
    area = sigdt.outlines(gpd.GeoSeries([shapely.MultiPoint(points)], crs=4326)).iloc[0]
    assert area.is_valid and len(area.geoms) == 2
    spans = sorted((g.bounds[0], g.bounds[2]) for g in area.geoms)
    assert spans == [(-180.0, pytest.approx(-179.5)), (pytest.approx(179.5), 180.0)]
    whole = shapely.Polygon(_circle(0.0, -17.0, 0.5, 60))
    assert area.area == pytest.approx(whole.area, rel=1e-9)


def test_the_concave_hull_table_in_docs_is_current() -> None:
    """docs/gis.md's table of sigdt.outlines beside concave_hull is what the bench script
    prints (python/bench/outlines_vs_concave_hull.py)."""
    import importlib.util

    root = Path(__file__).resolve().parents[2]
    path = root / "python" / "bench" / "outlines_vs_concave_hull.py"
    spec = importlib.util.spec_from_file_location("outlines_vs_concave_hull", path)
    assert spec is not None and spec.loader is not None
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    docs = (root / "docs" / "gis.md").read_text()
    for line in bench.main(0.1, None):
        assert line in docs, line
