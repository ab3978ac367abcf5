"""Writes the GIS fixtures of ``data/gis/`` with GeoPandas and pyogrio (GDAL), as GIS users'
files are written: ``.venv/bin/python python/tests/make_gis_fixtures.py``.

The points are the glyph sample ``data/inputs/glyph_sigma.xy`` (245 points, one closed
curve), placed in three coordinate systems:

- ``sigma_27700``: metres on the British National Grid (EPSG:27700), the glyph 2.5 km wide
  near (400 km, 300 km); GeoPackage, Shapefile (with ``.prj``) and FlatGeobuf.
- ``sigma_4326``: the same points in longitude/latitude (EPSG:4326) near 2°W 52°N, each
  degree of longitude scaled by cos 52° so that the glyph keeps its shape on the ground;
  GeoPackage, and CSV with the columns in ``lat,lon`` order.
- ``two_layers.gpkg``: the projected points beside a polygon layer, to choose with
  ``--layer``.
- ``islands_4326.gpkg``: four archipelagos of ``data/real`` (GSHHS shorelines, smoothed
  and sampled: ``gshhs_arch_*_smooth``), each point with its ``archipelago``, put back in
  longitude/latitude from the kilometres of ``data/real`` around the centre of the box
  each was taken from (``cases.jsonl``): approximately where they lie.
"""

import json
from pathlib import Path

import geopandas as gpd
import numpy as np
import shapely

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "data" / "gis"


def main() -> None:
    xy = np.loadtxt(ROOT / "data" / "inputs" / "glyph_sigma.xy")
    xy = (xy - xy.min(axis=0)) / np.ptp(xy, axis=0).max()
    metres = xy * 2500.0 + [400_000.0, 300_000.0]
    lat0 = 52.0
    lonlat = np.column_stack(
        [-2.0 + xy[:, 0] * 0.03 / np.cos(np.radians(lat0)), lat0 + xy[:, 1] * 0.03]
    )
    ids = np.arange(len(xy))
    projected = gpd.GeoDataFrame({"id": ids}, geometry=shapely.points(metres), crs="EPSG:27700")
    geographic = gpd.GeoDataFrame({"id": ids}, geometry=shapely.points(lonlat), crs="EPSG:4326")
    OUT.mkdir(parents=True, exist_ok=True)
    projected.to_file(OUT / "sigma_27700.gpkg", layer="points", engine="pyogrio")
    projected.to_file(OUT / "sigma_27700.shp", engine="pyogrio")
    projected.to_file(OUT / "sigma_27700.fgb", engine="pyogrio")
    geographic.to_file(OUT / "sigma_4326.gpkg", layer="points", engine="pyogrio")
    table = geographic.assign(lat=lonlat[:, 1], lon=lonlat[:, 0])
    table[["id", "lat", "lon"]].to_csv(OUT / "sigma_4326_latlon.csv", index=False)
    hull = gpd.GeoDataFrame(
        {"name": ["hull"]},
        geometry=[shapely.convex_hull(shapely.multipoints(metres))],
        crs="EPSG:27700",
    )
    two = OUT / "two_layers.gpkg"
    two.unlink(missing_ok=True)
    projected.to_file(two, layer="points", engine="pyogrio")
    hull.to_file(two, layer="hull", engine="pyogrio", mode="a")
    islands().to_file(OUT / "islands_4326.gpkg", layer="points", engine="pyogrio")


ARCHIPELAGOS = ["aland", "dalmatia", "hebrides", "lofoten"]


def islands() -> gpd.GeoDataFrame:
    real = ROOT / "data" / "real"
    boxes = {}
    for line in (real / "cases.jsonl").read_text().splitlines():
        case = json.loads(line)
        if "box" in case:
            boxes[case["name"]] = case["box"]
    names, coords = [], []
    for name in ARCHIPELAGOS:
        km = np.loadtxt(real / f"gshhs_arch_{name}_smooth.xy")
        lon0, lon1, lat0, lat1 = boxes[f"gshhs_arch_{name}_k1"]
        lonc, latc = (lon0 + lon1) / 2, (lat0 + lat1) / 2
        lat = latc + km[:, 1] / 111.32
        lon = lonc + km[:, 0] / (111.32 * np.cos(np.radians(latc)))
        names += [name] * len(km)
        coords.append(np.c_[lon, lat])
    return gpd.GeoDataFrame(
        {"archipelago": names}, geometry=shapely.points(np.concatenate(coords)), crs=4326
    )


if __name__ == "__main__":
    main()
