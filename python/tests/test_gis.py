"""The GIS path (issue 31): GeoPandas in and out with the coordinate reference system
kept, longitude/latitude reconstructed in a local plane, one outline per group, and the
CLI's GeoPackage and FlatGeobuf layers read back by GeoPandas (pyogrio, GDAL).

The files of ``data/gis/`` were written by GeoPandas/pyogrio
(``python/tests/make_gis_fixtures.py``)."""

from __future__ import annotations

import subprocess
import warnings
from pathlib import Path

import geopandas as gpd
import numpy as np
import pandas as pd
import pyogrio
import pytest
import shapely
import sigdt

ROOT = Path(__file__).resolve().parents[2]
GIS = ROOT / "data" / "gis"
R = 6_371_008.8


def test_a_geodataframe_keeps_its_crs_through_to_geopandas() -> None:
    points = gpd.read_file(GIS / "sigma_27700.gpkg")
    rec = sigdt.reconstruct(points)
    assert rec.crs == points.crs and rec.status == "polygon"
    frame = rec.to_geopandas()
    assert frame.crs.to_epsg() == 27700
    assert frame[["kind", "status", "warning", "n_vertices"]].to_dict("records") == [
        {"kind": "polygon", "status": "polygon", "warning": False, "n_vertices": 245}
    ]
    assert frame.geometry.iloc[0].is_valid
    # The same polygon as the plain coordinates give.
    plain = sigdt.reconstruct(points.get_coordinates().to_numpy())
    assert np.array_equal(plain.edges, rec.edges)


def _island(lat0: float) -> np.ndarray:
    """The island data/real/gshhs_arch_aland_k1.xy, 5 km wide, at latitude ``lat0`` as
    longitude/latitude (each point's own scale of longitude)."""
    xy = np.loadtxt(ROOT / "data" / "real" / "gshhs_arch_aland_k1.xy")
    xy = (xy - xy.min(axis=0)) / np.ptp(xy, axis=0).max() * 5000.0
    lat = lat0 + np.degrees(xy[:, 1] / R)
    lon = 10.0 + np.degrees(xy[:, 0] / (R * np.cos(np.radians(lat))))
    return np.c_[lon, lat]


def test_longitude_latitude_give_the_same_edges_at_0_and_60_north() -> None:
    results = []
    for lat0 in (0.0, 60.0):
        points = gpd.GeoSeries(shapely.points(_island(lat0)), crs="EPSG:4326")
        results.append(sigdt.reconstruct(points))
    assert np.array_equal(results[0].edges, results[1].edges)
    # As plane coordinates, a degree of longitude at 60° N counts twice: other edges.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sigdt.SigdtWarning)
        planar = sigdt.reconstruct(_island(60.0))
    assert not np.array_equal(planar.edges, results[1].edges)


def test_degrees_that_are_not_degrees_are_refused() -> None:
    points = gpd.read_file(GIS / "sigma_27700.gpkg").set_crs("EPSG:4326", allow_override=True)
    with pytest.raises(sigdt.InvalidInputError, match="is not a longitude and a latitude"):
        sigdt.reconstruct(points)
    frame = points.assign(g=["x"] * len(points))
    with pytest.raises(sigdt.InvalidInputError, match="^group 'x': the coordinate system is"):
        sigdt.reconstruct_frame(frame, by="g", progress=False, errors="raise")
    # By default the group is a row saying so.
    with pytest.warns(sigdt.SigdtWarning, match="1 of 1 groups failed"):
        out = sigdt.reconstruct_frame(frame, by="g", progress=False)
    assert out.loc["x", "status"] == "error"
    assert "is not a longitude and a latitude" in out.loc["x", "diagnosis"]


def test_reconstruct_frame_gives_one_row_per_group() -> None:
    points = gpd.read_file(GIS / "sigma_4326.gpkg")
    shifted = points.assign(geometry=points.geometry.translate(0.2, 0.0))
    both = pd.concat([points.assign(island="b"), shifted.assign(island="a")], ignore_index=True)
    frame = sigdt.reconstruct_frame(both, by="island", progress=False)
    assert list(frame.index) == ["a", "b"] and frame.index.name == "island"
    assert frame.crs.to_epsg() == 4326
    assert list(frame.columns) == [
        "paths",
        "networks",
        "status",
        "warning",
        "diagnosis",
        "n_points",
        "n_left_out",
        "geometry",
    ]
    assert frame["status"].tolist() == ["polygon", "polygon"]
    assert frame["n_points"].tolist() == [245, 245]
    # Group b is the file's points: the same polygon as reconstructing them alone.
    alone = shapely.MultiPolygon([sigdt.reconstruct(points).to_shapely()])
    assert frame.geometry.loc["b"].equals(alone)
    whole = sigdt.reconstruct_frame(points, progress=False)
    assert len(whole) == 1 and whole.geometry.iloc[0].equals(alone)


def test_reconstruct_frame_areas_are_each_groups_own_in_any_mix_of_groups() -> None:
    # The areas of all groups are built at once, one-loop groups apart from the others
    # (issue 47, P4): each row must still hold its own group's polygons, holes included.
    def circle(x: float, r: float, k: int) -> np.ndarray:
        t = np.linspace(0, 2 * np.pi, k, endpoint=False)
        return np.c_[x + r * np.cos(t), r * np.sin(t)]

    groups = {
        "a": np.r_[circle(0, 10, 40), circle(0, 4, 16)],  # a ring round a hole
        "b": circle(100, 5, 20),
        "c": np.r_[circle(200, 5, 20), circle(230, 5, 20)],  # two islands
        "d": np.array([[300.0, 0], [301, 0]]),  # too few points: no area
        "e": circle(400, 6, 24),
    }
    keys = [k for k, v in groups.items() for _ in v]
    frame = gpd.GeoDataFrame(
        {"g": keys[::-1]}, geometry=shapely.points(np.concatenate(list(groups.values()))[::-1])
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sigdt.SigdtWarning)
        out = sigdt.reconstruct_frame(frame, by="g", progress=False)
        alone = {k: sigdt.reconstruct(v[::-1]) for k, v in groups.items()}
    counts = {
        k: (len(g.geoms), sum(len(p.interiors) for p in g.geoms)) for k, g in out.geometry.items()
    }
    assert counts == {"a": (1, 1), "b": (1, 0), "c": (2, 0), "d": (0, 0), "e": (1, 0)}
    for k, rec in alone.items():
        shapes = [p.normalize() for p in out.geometry.loc[k].geoms]
        own = [shapely.Polygon(shell, holes) for shell, *holes in rec.layers()["areas"]]
        assert shapes == [p.normalize() for p in own], k


def test_reconstruct_frame_groups_as_pandas_does() -> None:
    # Issue 47, P1: by=["k"] raised KeyError, and by=("k",) and by=series failed too.
    square = [[0, 0], [9, 0], [9, 9], [0, 9]]
    points = shapely.points(np.r_[square, np.add(square, 50)])
    frame = gpd.GeoDataFrame({"k": ["a"] * 4 + ["b"] * 4, "j": [1] * 8}, geometry=points)
    for by in ["k", ["k"], ("k",), frame["k"]]:
        out = sigdt.reconstruct_frame(frame, by=by, progress=False)
        assert (list(out.index), out.index.name) == (["a", "b"], "k"), by
        assert out["status"].tolist() == ["polygon", "polygon"], by
    for by in [["k", "j"], ("k", "j"), [frame["k"], "j"]]:
        out = sigdt.reconstruct_frame(frame, by=by, progress=False)
        assert list(out.index) == [("a", 1), ("b", 1)] and list(out.index.names) == ["k", "j"]


def test_reconstruct_frame_refuses_what_is_not_a_frame_and_warns_once() -> None:
    with pytest.raises(TypeError, match="GeoDataFrame or GeoSeries"):
        sigdt.reconstruct_frame(np.zeros((4, 2)))
    # Groups of two points are too few for a curve: one warning names the first.
    few = gpd.GeoDataFrame(
        {"g": [1, 1, 2, 2, 2, 2, 3, 3]},
        geometry=shapely.points([[0, 0], [1, 0], [0, 0], [1, 0], [1, 1], [0, 1], [5, 5], [6, 5]]),
    )
    with pytest.warns(sigdt.SigdtWarning, match=r"group 1 \(and 1 more\)") as caught:
        frame = sigdt.reconstruct_frame(few, by="g", progress=False)
    assert frame["status"].tolist() == ["too-few-points", "polygon", "too-few-points"]
    assert frame["warning"].tolist() == [True, False, True]
    assert len(caught) == 1


@pytest.mark.parametrize(("given", "epsg"), [("sigma_27700.shp", 27700), ("sigma_4326.gpkg", 4326)])
def test_cli_geopackage_layers_read_back_with_their_crs(
    cli: Path, tmp_path: Path, given: str, epsg: int
) -> None:
    out = tmp_path / "result.gpkg"
    subprocess.run([str(cli), "reconstruct", str(GIS / given), "-o", str(out)], check=True)
    areas = gpd.read_file(out, layer="areas")
    assert areas.crs.to_epsg() == epsg
    assert areas[["method", "status", "warning", "vertices"]].to_dict("records") == [
        {"method": "sig-auto", "status": "polygon", "warning": False, "vertices": 245}
    ]
    points = gpd.read_file(GIS / given)
    alone = shapely.MultiPolygon([sigdt.reconstruct(points).to_shapely()])
    assert areas.geometry.iloc[0].equals(alone)
    # Every layer is there, each with its one geometry type, the empty ones too.
    types = {"paths": "MultiLineString", "networks": "MultiLineString", "left_out": "Point"}
    for name, kind in types.items():
        assert pyogrio.read_info(out, layer=name)["geometry_type"] == kind, name
        layer = gpd.read_file(out, layer=name)
        assert len(layer) == 0 and layer.crs == areas.crs, name


def test_cli_flatgeobuf_with_outliers_carries_left_out_points(cli: Path, tmp_path: Path) -> None:
    # The glyph with three far outliers: sig-auto leaves them out, with their rows.
    points = gpd.read_file(GIS / "sigma_27700.gpkg").get_coordinates().to_numpy()
    outliers = np.array([[380_000.0, 280_000.0], [420_000.0, 320_000.0], [380_000.0, 320_000.0]])
    frame = gpd.GeoDataFrame(geometry=shapely.points(np.r_[points, outliers]), crs=27700)
    given = tmp_path / "with_outliers.fgb"
    frame.to_file(given, engine="pyogrio", SPATIAL_INDEX="NO")
    out = tmp_path / "result.fgb"
    subprocess.run(
        [str(cli), "reconstruct", str(given), "--method", "sig-auto", "-o", str(out)],
        check=True,
        capture_output=True,
    )
    # FlatGeobuf holds one layer a file: the areas in the file named, the others beside it.
    areas = gpd.read_file(out)
    assert areas.crs.to_epsg() == 27700 and areas.geom_type.tolist() == ["MultiPolygon"]
    assert areas["method"].tolist() == ["sig-auto"]
    left = gpd.read_file(tmp_path / "result.left_out.fgb")
    assert left.crs.to_epsg() == 27700 and set(left.geom_type) == {"Point"}
    assert sorted(left["row"].astype(int)) == [245, 246, 247]
    assert set(left["reason"]) == {"outlier"}
    for name in ["paths", "networks"]:
        path = tmp_path / f"result.{name}.fgb"
        assert pyogrio.read_info(path)["geometry_type"] == "MultiLineString", name
        assert len(gpd.read_file(path)) == 0, name


def test_read_points_reads_gis_files_and_layers() -> None:
    glyph = sigdt.read_points(ROOT / "data" / "inputs" / "glyph_sigma.xy")
    for name in ("sigma_27700.gpkg", "sigma_27700.shp"):
        points = sigdt.read_points(GIS / name)
        assert points.shape == (245, 2)
        assert np.allclose(
            points - points.min(axis=0),
            (glyph - glyph.min(axis=0))
            * np.ptp(points, axis=0).max()
            / np.ptp(glyph, axis=0).max(),
        )
    hull = sigdt.read_points(GIS / "two_layers.gpkg", layer="hull")
    assert 3 <= len(hull) < 245
    with pytest.raises(sigdt.ParseError, match="no feature layer 'roads'"):
        sigdt.read_points(GIS / "two_layers.gpkg", layer="roads")
    with pytest.raises(ValueError, match="which has no layers"):
        sigdt.read_points(GIS / "sigma_27700.fgb", layer="x")


def test_the_cli_and_python_agree_on_which_systems_are_degrees(cli: Path, tmp_path: Path) -> None:
    # Issue 47, K2: the CLI took EPSG 4000-4999 for degrees, Python asks pyproj: degrees in
    # EPSG:6318 and 7844 were a plane to the CLI, metres in 4087 and 4978 degrees.
    turn = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    ring = np.c_[10 + 0.01 * np.cos(turn), 50 + 0.01 * np.sin(turn)]
    for code in [6318, 7844, 4326, 4087, 4978, 27700]:
        points = gpd.GeoSeries(shapely.points(ring), crs=code)
        path = tmp_path / f"p{code}.gpkg"
        points.to_file(path)
        run = subprocess.run(
            [str(cli), "reconstruct", str(path), "-v", "-o", str(tmp_path / f"o{code}.edges")],
            capture_output=True,
            text=True,
            check=True,
        )
        in_plane = "is longitude/latitude: reconstructed in" in run.stderr
        assert in_plane == points.crs.is_geographic, (code, run.stderr)
