"""Writes crates/sigdt-io/src/gis/geographic_codes.rs: the EPSG codes of geographic
coordinate systems (longitude/latitude, 2D and 3D, deprecated ones included), read from the
EPSG registry that PROJ ships (pyproj's proj.db). sigdt reads the table to tell degrees from
metres, the same answer as pyproj's ``CRS.is_geographic`` in the Python package.

Run from the repository root with the dev environment: ``.venv/bin/python tools/epsg-geographic.py``.
"""

import os
import sqlite3
import sys

import pyproj

OUT = os.path.join("crates", "sigdt-io", "src", "gis", "geographic_codes.rs")


def main() -> int:
    db = sqlite3.connect(os.path.join(pyproj.datadir.get_data_dir(), "proj.db"))
    version = db.execute("SELECT value FROM metadata WHERE key = 'EPSG.VERSION'").fetchone()[0]
    rows = db.execute(
        "SELECT code FROM geodetic_crs WHERE auth_name = 'EPSG' "
        "AND type IN ('geographic 2D', 'geographic 3D')"
    ).fetchall()
    codes = sorted({int(code) for (code,) in rows if str(code).isdigit()})
    lines = [
        "//! The EPSG codes of geographic coordinate systems (longitude/latitude, 2D and 3D,",
        f"//! deprecated ones included): {len(codes)} codes of the EPSG registry {version}, as PROJ",
        f"//! {pyproj.proj_version_str} ships it. Written by `tools/epsg-geographic.py`; do not edit.",
        "",
        "/// Sorted, for a binary search.",
        "#[rustfmt::skip]",
        f"pub(super) const GEOGRAPHIC: [u32; {len(codes)}] = [",
    ]
    for start in range(0, len(codes), 10):
        lines.append("    " + ", ".join(str(c) for c in codes[start : start + 10]) + ",")
    lines.append("];")
    with open(OUT, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{OUT}: {len(codes)} codes (EPSG {version})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
