"""``sigdt.outlines`` beside ``concave_hull`` on Natural Earth's 177 countries, given as the
points of their outlines densified every SPACING degrees: how many each gets right, and a
picture of a few countries.

Run: ``.venv/bin/python python/bench/outlines_vs_concave_hull.py [SPACING] [PICTURE]``
(``make pictures`` runs it with 0.1 and docs/images/gis/outlines_vs_concave_hull.png).

"Right" is the report's measure for areas (docs/evaluation.md): IoU ≥ 0.95 against the
true polygons and as many parts. ``concave_hull`` runs as GIS users call it,
``gdf.dissolve(by).concave_hull()`` with its default ``ratio`` (0.0) and with 0.1; it has no
notion of longitude/latitude, so both run on the degrees as given. The Natural Earth file is
pyogrio's test fixture (pinned in requirements-dev.txt).
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import geopandas as gpd
import numpy as np
import pyogrio
import shapely
import sigdt

NATURAL_EARTH = (
    Path(pyogrio.__file__).parent / "tests/fixtures/naturalearth_lowres/naturalearth_lowres.shp"
)
SHOWN = ["Indonesia", "Norway", "Chile", "Fiji"]


def _right(got: gpd.GeoSeries, truth: gpd.GeoSeries) -> np.ndarray:
    # make_valid: an invalid result is scored, not a GEOS exception.
    got = shapely.make_valid(got.loc[truth.index])
    union = shapely.union(got.values, truth.values)
    iou = shapely.area(shapely.intersection(got.values, truth.values)) / shapely.area(union)
    parts = shapely.get_num_geometries(got.values) == shapely.get_num_geometries(truth.values)
    return (iou >= 0.95) & parts


def main(spacing: float, picture: Path | None) -> list[str]:
    world = gpd.read_file(NATURAL_EARTH)
    truth = world.set_index("name").geometry.apply(
        lambda g: g if g.geom_type == "MultiPolygon" else shapely.MultiPolygon([g])
    )
    dense = world.geometry.segmentize(spacing).get_coordinates(index_parts=False)
    points = gpd.GeoDataFrame(
        {"name": world.loc[dense.index, "name"].to_numpy()},
        geometry=gpd.points_from_xy(dense.x, dense.y),
        crs=world.crs,
    )
    multi = shapely.get_num_geometries(truth.values) > 1
    print(f"{len(truth)} countries ({multi.sum()} of several parts), {len(points)} points")
    rows = []
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sigdt.SigdtWarning)
        ours = sigdt.outlines(points, by="name")
    rows.append(("sigdt.outlines(points, by='name')", ours, time.perf_counter() - start))
    dissolved = points.dissolve("name")
    for ratio in (0.0, 0.1):
        start = time.perf_counter()
        hull = dissolved.concave_hull(ratio=ratio)
        rows.append(
            (f"dissolve('name').concave_hull(ratio={ratio})", hull, time.perf_counter() - start)
        )
    for line in table(rows, truth, multi):
        print(line)
    print("seconds: " + ", ".join(f"{seconds:.2f}" for _, _, seconds in rows))
    if picture is not None:
        _draw(picture, truth, rows[0][1], rows[1][1])
    return table(rows, truth, multi)


def _east(geometry: shapely.Geometry) -> shapely.Geometry:
    """For the picture only: longitudes west of -90° moved by a turn, so that a country
    across ±180° (Fiji) is drawn in one piece."""
    return shapely.transform(
        geometry, lambda xy: np.c_[np.where(xy[:, 0] < -90, xy[:, 0] + 360, xy[:, 0]), xy[:, 1]]
    )


def table(rows: list, truth: gpd.GeoSeries, multi: np.ndarray) -> list[str]:
    """The Markdown table of docs/gis.md: each call's share of countries right."""
    lines = ["| call | right | right, of several parts |", "|---|---|---|"]
    for name, got, _ in rows:
        right = _right(got, truth)
        lines.append(
            f"| `{name}` | {right.mean():.1%} ({right.sum()}) | "
            f"{right[multi].mean():.1%} ({right[multi].sum()} of {multi.sum()}) |"
        )
    return lines


def _draw(path: Path, truth: gpd.GeoSeries, ours: gpd.GeoSeries, hull: gpd.GeoSeries) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, len(SHOWN), figsize=(3.2 * len(SHOWN), 6.4))
    for column, name in enumerate(SHOWN):
        for row, (label, got) in enumerate([("sigdt.outlines", ours), ("concave_hull", hull)]):
            ax = axes[row, column]
            shown = [_east(truth[name]), _east(got[name])]
            gpd.GeoSeries(shown[:1]).plot(ax=ax, color="#dddddd")
            gpd.GeoSeries(shown[1:]).boundary.plot(ax=ax, color="#c0392b", linewidth=0.8)
            ax.set_title(f"{name}: {label}", fontsize=9)
            ax.set_axis_off()
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


if __name__ == "__main__":
    main(
        float(sys.argv[1]) if len(sys.argv) > 1 else 0.1,
        Path(sys.argv[2]) if len(sys.argv) > 2 else None,
    )
