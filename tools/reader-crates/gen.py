"""Writes the hostile and big inputs of the harness into inputs/ (python3 gen.py [small|big])."""
import os
import shutil
import sqlite3
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "inputs")
os.makedirs(D, exist_ok=True)


def w(name, data):
    mode = "wb" if isinstance(data, (bytes, bytearray)) else "w"
    with open(os.path.join(D, name), mode) as f:
        f.write(data)


# ---------- Shapefile helpers ----------
def shp(records, shape_type=1, file_words=None):
    parts = []
    for i, content in enumerate(records, 1):
        if isinstance(content, tuple):  # (declared words, content)
            words, content = content
        else:
            words = len(content) // 2
        parts.append(struct.pack(">ii", i, words) + content)
    body = b"".join(parts)
    words = file_words if file_words is not None else (100 + len(body)) // 2
    head = struct.pack(">7i", 9994, 0, 0, 0, 0, 0, words) + struct.pack("<2i", 1000, shape_type)
    head += struct.pack("<8d", 0, 0, 1, 1, 0, 0, 0, 0)
    return head + body


def pt(x, y):
    return struct.pack("<i2d", 1, x, y)


def multipoint_content(n_declared, pts):
    c = struct.pack("<i4di", 8, 0, 0, 1, 1, n_declared)
    return c + b"".join(struct.pack("<2d", x, y) for x, y in pts)


# ---------- WKB helpers (little endian), wrapped as GeoPackage blobs ----------
def gp(wkb):
    return b"GP\x00\x01" + struct.pack("<i", 4326) + wkb


def wkb_point(x, y, code=1, extra=()):
    return struct.pack("<BI", 1, code) + struct.pack("<%dd" % (2 + len(extra)), x, y, *extra)


def gpkg(name, blob):
    """A copy of the project's sigma_4326.gpkg whose first feature's geometry is `blob`."""
    path = os.path.join(D, name)
    shutil.copy(os.path.join(HERE, "..", "..", "data", "gis", "sigma_4326.gpkg"), path)
    c = sqlite3.connect(path)
    for (t,) in c.execute("select name from sqlite_master where type='trigger'").fetchall():
        c.execute(f'drop trigger "{t}"')
    c.execute("delete from points where fid > 1")
    c.execute("update points set geom = ? where fid = 1", (blob,))
    c.commit()
    c.close()


def small():
    n = 100_000
    # 1. deep nesting
    for depth in (1000, 10_000, n):
        w(f"deep_gc_{depth}.wkt", "GEOMETRYCOLLECTION(" * depth + "POINT(0 0)" + ")" * depth)
        w(f"deep_arrays_{depth}.geojson",
          '{"type":"MultiPoint","coordinates":' + "[" * depth + "]" * depth + "}")
        w(f"deep_gc_{depth}.geojson",
          '{"type":"GeometryCollection","geometries":[' * depth
          + '{"type":"Point","coordinates":[0,0]}' + "]}" * depth)
        blob = gp(struct.pack("<BII", 1, 7, 1) * depth + wkb_point(0, 0))
        w(f"deep_gc_{depth}.gpb", blob)
        gpkg(f"deep_gc_{depth}.gpkg", blob)
    # 3. lying sizes
    w("lie_header.shp", shp([pt(1, 2)], file_words=0x7FFFFFFF))
    # record announces ~2 GB and a multipoint of 2^27 - 8 points (fits that length); 3 points follow
    k = (2**31 - 2 - 44) // 16
    w("lie_record_2g.shp", shp([(0x3FFFFFFF, multipoint_content(k, [(0, 0), (1, 0), (1, 1)]))], 8))
    # 2^28 points: 40 + 16 n wraps to 40 in the crate's i32 size check; the record says 44 bytes
    w("lie_wrap_4g.shp", shp([(22, multipoint_content(2**28, [(0, 0), (1, 0), (1, 1)]))], 8))
    w("lie_wrap_32g.shp", shp([(22, multipoint_content(2**31 - 1, [(0, 0), (1, 0)]))], 8))
    # polyline announcing 2^26 parts in a 2 GB record, then the file ends
    c = struct.pack("<i4dii", 3, 0, 0, 1, 1, 2**26, 2**26) + struct.pack("<3i", 0, 1, 2)
    w("lie_parts.shp", shp([(0x3FFFFFFF, c)], 3))
    # WKB: a polygon whose ring count says 2^31, a linestring of 2^28 points, multipoint 2^31
    for name, wkb in [
        ("lie_rings", struct.pack("<BII", 1, 3, 2**31) + struct.pack("<I", 1) + struct.pack("<2d", 0, 0)),
        ("lie_line_2e28", struct.pack("<BII", 1, 2, 2**28) + struct.pack("<2d", 0, 0)),
        ("lie_mpoint_2e31", struct.pack("<BII", 1, 4, 2**31) + wkb_point(0, 0)),
    ]:
        w(name + ".gpb", gp(wkb))
        gpkg(name + ".gpkg", gp(wkb))
    # 4. error messages
    w("err_token.wkt", "POINT (1 x)")
    w("err_line3.wkt", "GEOMETRYCOLLECTION (\n  POINT (0 0),\n  LINESTRING (1 1, 2)\n)")
    w("err_trunc.wkt", "MULTIPOINT ((0 0), (1 1)")
    w("err_trunc.geojson", '{"type": "MultiPoint",\n "coordinates": [[0, 0], [1, 1]')
    w("err_string.geojson", '{"type": "Point", "coordinates": [1, "x"]}')
    w("err_line4.geojson",
      '{"type": "FeatureCollection", "features": [\n'
      '  {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [0, 0]}},\n'
      '  {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 1]}},\n'
      '  {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [2]}}\n]}')
    w("err_trunc.shp", shp([pt(0, 0), (10, pt(1, 1)[:8])]))
    w("err_type.shp", shp([pt(0, 0), struct.pack("<i2d", 99, 1, 1)]))
    c = struct.pack("<i4dii", 3, 0, 0, 1, 1, 2, 2) + struct.pack("<2i", 0, 5) + struct.pack("<4d", 0, 0, 1, 1)
    w("err_part.shp", shp([c], 3))
    w("err_trunc.gpb", gp(struct.pack("<BII", 1, 2, 3) + struct.pack("<3d", 0, 0, 1)))
    w("err_type.gpb", gp(struct.pack("<BI", 1, 99) + struct.pack("<2d", 0, 0)))
    w("err_order.gpb", gp(struct.pack("<BI", 7, 1) + struct.pack("<2d", 0, 0)))
    # 6. non-finite and 3D / M
    for name, text in [
        ("nan", "POINT (NaN 1)"), ("inf", "POINT (inf 1)"), ("e999", "POINT (1e999 1)"),
        ("z", "POINT Z (1 2 3)"), ("m", "POINT M (1 2 3)"), ("zm", "POINT ZM (1 2 3 4)"),
        ("z_implicit", "POINT (1 2 3)"), ("ls_z", "LINESTRING Z (0 0 0, 1 1 1)"),
    ]:
        w(f"v_{name}.wkt", text)
    for name, text in [
        ("e999", "[1e999, 1]"), ("nan", "[NaN, 1]"), ("z", "[1, 2, 3]"), ("zm", "[1, 2, 3, 4]"),
        ("short", "[1]"),
    ]:
        w(f"v_{name}.geojson", '{"type": "Point", "coordinates": %s}' % text)
    nan, inf = float("nan"), float("inf")
    w("v_nan.shp", shp([pt(nan, 1)]))
    w("v_inf.shp", shp([pt(inf, 1)]))
    w("v_z.shp", shp([struct.pack("<i4d", 11, 1, 2, 3, 4)], 11))
    w("v_m.shp", shp([struct.pack("<i3d", 21, 1, 2, 3)], 21))
    for name, wkb in [
        ("nan", wkb_point(nan, 1)), ("inf", wkb_point(inf, 1)), ("empty", wkb_point(nan, nan)),
        ("z", wkb_point(1, 2, 1001, (3,))), ("m", wkb_point(1, 2, 2001, (3,))),
        ("zm", wkb_point(1, 2, 3001, (3, 4))), ("ewkb_z", wkb_point(1, 2, 0x80000001, (3,))),
    ]:
        w(f"v_{name}.gpb", gp(wkb))


def big():
    import random
    rnd = random.Random(1)
    for n, tag in [(10**6, "1m"), (10**7, "10m")]:
        xs = [f"{rnd.random() * 1000:.6f} {rnd.random() * 1000:.6f}" for _ in range(n)]
        w(f"n{tag}.wkt", "MULTIPOINT (" + ", ".join("(" + p + ")" for p in xs) + ")")
        w(f"n{tag}.geojson", '{"type":"MultiPoint","coordinates":['
          + ",".join("[" + p.replace(" ", ",") + "]" for p in xs) + "]}")
        coords = [tuple(map(float, p.split())) for p in xs]
        del xs
        w(f"n{tag}_mp.shp", shp([multipoint_content(n, coords)], 8))
        w(f"n{tag}.gpb", gp(struct.pack("<BII", 1, 4, n) + b"".join(wkb_point(x, y) for x, y in coords)))
        if n == 10**6:
            w(f"n{tag}.shp", shp([pt(x, y) for x, y in coords], 1))
            w(f"n{tag}_fc.geojson", '{"type":"FeatureCollection","features":[\n' + ",\n".join(
                '{"type":"Feature","properties":{"id":%d},"geometry":{"type":"Point","coordinates":[%r,%r]}}'
                % (i, x, y) for i, (x, y) in enumerate(coords)) + "\n]}")
        del coords
    # a 200+ MB FeatureCollection: 2.5e6 point features
    m = 2_500_000
    with open(os.path.join(D, "n2500k_fc.geojson"), "w") as f:
        f.write('{"type":"FeatureCollection","features":[\n')
        for i in range(m):
            f.write(('' if i == 0 else ',\n') +
                    '{"type":"Feature","properties":{"id":%d,"name":"feature number %d"},'
                    '"geometry":{"type":"Point","coordinates":[%.6f,%.6f]}}'
                    % (i, i, rnd.random() * 1000, rnd.random() * 1000))
        f.write("\n]}")


if __name__ == "__main__":
    (big if sys.argv[1:] == ["big"] else small)()
