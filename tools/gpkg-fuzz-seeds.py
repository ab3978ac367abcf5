"""Writes fuzz/seeds/read_gpkg/: one small GeoPackage per finding of the GeoPackage reader
(issue 47 and before), as the seeds of the fuzz target `read_gpkg` and the cases of
crates/sigdt-io/tests/hostile_geopackages.rs, which reads each and checks the answer.

Run: python3 tools/gpkg-fuzz-seeds.py (the standard library's sqlite3 only). The files are
committed; rerunning rewrites them.
"""

from __future__ import annotations

import sqlite3
import struct
from pathlib import Path

OUT = Path(__file__).resolve().parents[1] / "fuzz" / "seeds" / "read_gpkg"

SRS = (
    "CREATE TABLE gpkg_spatial_ref_sys (srs_name TEXT, srs_id INTEGER PRIMARY KEY, "
    "organization TEXT, organization_coordsys_id INTEGER, definition TEXT);"
    "INSERT INTO gpkg_spatial_ref_sys VALUES ('undefined', 0, 'NONE', 0, 'undefined');"
    "INSERT INTO gpkg_spatial_ref_sys VALUES ('WGS 84', 4326, 'EPSG', 4326, '');"
)
COLUMNS = (
    "CREATE TABLE gpkg_geometry_columns (table_name TEXT, column_name TEXT, "
    "geometry_type_name TEXT, srs_id INTEGER, z INTEGER, m INTEGER);"
)
ENDLESS = "WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n)"


def point(x: float, y: float, srs: int = 4326) -> bytes:
    """A GeoPackage geometry blob of one point: header (no envelope), then WKB."""
    return b"GP" + bytes([0, 0b0000_0001]) + struct.pack("<i", srs) + struct.pack("<BIdd", 1, 1, x, y)


def square_layer(name: str = "points") -> str:
    return (
        f"CREATE TABLE {name} (fid INTEGER PRIMARY KEY, geom BLOB, island TEXT);"
        f"INSERT INTO gpkg_geometry_columns VALUES ('{name}', 'geom', 'POINT', 4326, 0, 0);"
    )


def write(name: str, sql: str, rows: list[tuple] | None = None, wal: bool = False) -> None:
    path = OUT / f"{name}.gpkg"
    path.unlink(missing_ok=True)
    db = sqlite3.connect(path)
    db.executescript(sql)
    for row in rows or []:
        db.execute("INSERT INTO points VALUES (?, ?, ?)", row)
    db.commit()
    if wal:
        db.execute("PRAGMA journal_mode = WAL")
    db.close()


SQUARE = [(k + 1, point(x, y), "a") for k, (x, y) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)])]

SEEDS = {
    # An ordinary layer: the fuzzer's starting point.
    "square": (SRS + COLUMNS + square_layer(), SQUARE, False),
    # M1: the layer list an endless view.
    "m1-endless-layer-list": (
        SRS
        + square_layer().split(";")[0]
        + ";"
        + "CREATE VIEW gpkg_geometry_columns AS "
        + ENDLESS
        + " SELECT 'points' AS table_name, 'geom' AS column_name, 'POINT' AS "
        "geometry_type_name, 4326 AS srs_id, 0 AS z, 0 AS m FROM n;",
        SQUARE,
        False,
    ),
    # M2: the layer an endless view of rows without geometry.
    "m2-endless-layer": (
        SRS
        + COLUMNS
        + "CREATE TABLE points (fid INTEGER PRIMARY KEY, geom BLOB, island TEXT);"
        + "INSERT INTO gpkg_geometry_columns VALUES ('endless', 'geom', 'POINT', 4326, 0, 0);"
        + "CREATE VIEW endless AS "
        + ENDLESS
        + " SELECT i AS fid, NULL AS geom FROM n;",
        [],
        False,
    ),
    # M2: the systems an endless view that never holds the layer's.
    "m2-endless-systems": (
        "CREATE VIEW gpkg_spatial_ref_sys AS "
        + ENDLESS
        + " SELECT 'x' AS srs_name, 2 * i AS srs_id, 'EPSG' AS organization, 2 * i AS "
        "organization_coordsys_id, '' AS definition FROM n;"
        + COLUMNS
        + "CREATE TABLE points (fid INTEGER PRIMARY KEY, geom BLOB, island TEXT);"
        + "INSERT INTO gpkg_geometry_columns VALUES ('points', 'geom', 'POINT', 4327, 0, 0);",
        SQUARE,
        False,
    ),
    # M1: an endless view that sorts before its first row.
    "m1-endless-sort": (
        SRS
        + COLUMNS
        + "CREATE TABLE points (fid INTEGER PRIMARY KEY, geom BLOB, island TEXT);"
        + "INSERT INTO gpkg_geometry_columns VALUES ('sorted', 'geom', 'POINT', 4326, 0, 0);"
        + "CREATE VIEW sorted AS "
        + ENDLESS
        + " SELECT i AS fid, NULL AS geom FROM n ORDER BY i DESC;",
        [],
        False,
    ),
    # M3: a feature view (GDAL writes them).
    "m3-feature-view": (
        SRS
        + COLUMNS
        + "CREATE TABLE base (fid INTEGER PRIMARY KEY, geom BLOB, island TEXT);"
        + "CREATE TABLE points (fid INTEGER PRIMARY KEY, geom BLOB, island TEXT);"
        + "INSERT INTO gpkg_geometry_columns VALUES ('view', 'geom', 'POINT', 4326, 0, 0);"
        + "CREATE VIEW view AS SELECT fid, geom FROM points;",
        SQUARE,
        False,
    ),
    # M4: write-ahead-log mode, as QGIS leaves them.
    "m4-wal": (SRS + COLUMNS + square_layer(), SQUARE, True),
    # K10: a layer whose srs_id has no row.
    "k10-missing-system": (
        SRS + COLUMNS + square_layer().replace("4326, 0, 0", "999, 0, 0"),
        SQUARE,
        False,
    ),
    # Triggers and a view that would write are never run by reading (read-only).
    "trigger": (
        SRS
        + COLUMNS
        + square_layer()
        + "CREATE TABLE log (x);"
        + "CREATE TRIGGER t AFTER INSERT ON points BEGIN INSERT INTO log VALUES (1); END;",
        SQUARE,
        False,
    ),
}


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for name, (sql, rows, wal) in SEEDS.items():
        write(name, sql, rows, wal)
        print(f"wrote {OUT / name}.gpkg")


if __name__ == "__main__":
    main()
