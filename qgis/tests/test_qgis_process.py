"""The plugin as users run it headless: ``qgis_process run sigdt:outlines_from_points`` on
GeoPackages of data/gis, its three layers read back with QGIS. Each test starts one QGIS
(about a second)."""

import json
import math
import subprocess
import sys
import unittest

from harness import (
    BARE_HOME,
    HOME,
    OUT,
    ROOT,
    layer,
    output,
    profile_python,
    run_algorithm,
)
from qgis.core import QgsWkbTypes

GIS = ROOT / "data" / "gis"
TYPES = {"AREAS": "MultiPolygon", "LINES": "MultiLineString", "LEFT_OUT": "Point"}
OWN_FIELDS = {"AREAS": [], "LINES": ["kind"], "LEFT_OUT": ["row", "reason"]}


class Outputs(unittest.TestCase):
    def run_ok(self, name, **parameters):
        """Runs the algorithm, expects success, and checks what every output shares: the
        geometry type, the input's CRS and the fields. Returns the layers by output name."""
        process, paths = run_algorithm(name, **parameters)
        self.assertEqual(sorted(paths), sorted(parameters.get("outputs", TYPES)))
        self.assertEqual(process.returncode, 0, output(process))
        self.assertNotIn("Traceback", process.stdout + process.stderr, output(process))
        source = layer(parameters["INPUT"])
        for skipped in set(TYPES) - set(paths):
            self.assertFalse(OUT.joinpath(name, f"{skipped.lower()}.gpkg").exists(), skipped)
        group = [parameters["GROUP_FIELD"]] if "GROUP_FIELD" in parameters else []
        layers = {}
        for key, path in paths.items():
            found = layers[key] = layer(path)
            self.assertEqual(QgsWkbTypes.displayString(found.wkbType()), TYPES[key], key)
            self.assertEqual(found.crs().authid(), source.crs().authid(), key)
            names = [f.name() for f in found.fields() if f.name() != "fid"]
            common = ["status", "warning", "diagnosis", "n_points"]
            self.assertEqual(names, group + common + OWN_FIELDS[key], key)
        return process, layers

    def test_islands_in_degrees_one_outline_per_archipelago(self):
        source = layer(GIS / "islands_4326.gpkg")
        self.assertEqual(source.crs().authid(), "EPSG:4326")
        process, out = self.run_ok(
            "islands", INPUT=GIS / "islands_4326.gpkg", GROUP_FIELD="archipelago"
        )
        self.assertIn("azimuthal equidistant plane", process.stdout + process.stderr)
        points = {}
        for feature in source.getFeatures():
            points.setdefault(feature["archipelago"], []).append(feature.geometry().asPoint())
        areas = {f["archipelago"]: f for f in out["AREAS"].getFeatures()}
        self.assertEqual(sorted(areas), ["aland", "dalmatia", "hebrides", "lofoten"])
        for name, feature in areas.items():
            self.assertEqual(feature["n_points"], len(points[name]), name)
            self.assertIn(feature["status"], ("polygon", "polygons"), name)
            geometry = feature.geometry()
            self.assertTrue(geometry.isGeosValid(), name)
            # Every point is on an outline (none left out, below), so the outlines span the
            # group's points exactly: in degrees, as they came, not in the local plane.
            x = [p.x() for p in points[name]]
            y = [p.y() for p in points[name]]
            box = geometry.boundingBox()
            self.assertEqual(
                (box.xMinimum(), box.yMinimum(), box.xMaximum(), box.yMaximum()),
                (min(x), min(y), max(x), max(y)),
                name,
            )
        self.assertEqual(out["LINES"].featureCount(), 0)
        self.assertEqual(out["LEFT_OUT"].featureCount(), 0)

    def test_metres_give_the_loop_the_command_line_gives(self):
        path = GIS / "sigma_27700.gpkg"
        _, out = self.run_ok("sigma", INPUT=path)
        [area] = out["AREAS"].getFeatures()
        self.assertEqual((area["status"], area["n_points"]), ("polygon", 245))
        self.assert_loops_as_the_command_line(path, out["AREAS"])

    def test_the_same_island_gives_the_same_loops_at_the_equator_and_at_60_north(self):
        # In degrees, a step east at 60° N is half as long as one at the equator: read as
        # plane coordinates the island gives other loops (python/tests/test_gis.py shows it
        # for sigdt; with the plugin's lon_lat off, this test fails).
        path = OUT / "aland.geojson"
        path.parent.mkdir(parents=True, exist_ok=True)
        rows = {"equator": island(0.0), "north": island(60.0)}
        path.write_text(geojson([(name, p) for name, points in rows.items() for p in points]))
        _, out = self.run_ok("aland", INPUT=path, GROUP_FIELD="name")
        loops = {}
        for feature in out["AREAS"].getFeatures():
            row = {p: k for k, p in enumerate(rows[feature["name"]])}
            loops[feature["name"]] = {tuple(row[p] for p in ring) for ring in rings(feature)}
        self.assertEqual(loops["equator"], loops["north"])
        self.assertTrue(loops["north"])
        # Rows count through the file: the north group's start after the equator's.
        first = {"equator": 0, "north": len(rows["equator"])}
        left = {"equator": set(), "north": set()}
        for feature in out["LEFT_OUT"].getFeatures():
            left[feature["name"]].add(feature["row"] - first[feature["name"]])
        self.assertEqual(left["equator"], left["north"])

    def assert_loops_as_the_command_line(self, path, areas):
        """The rings of ``areas`` are the loops the wheel's own command line finds in
        ``path``, point for point (both start at the smallest row, counter-clockwise)."""
        cli = subprocess.run(
            [sys.executable, "-m", "sigdt", "reconstruct", str(path), "--expect", "areas",
             "--format", "loops"],
            env={"PYTHONPATH": str(profile_python(HOME)), "PATH": "/usr/bin:/bin"},
            capture_output=True, text=True, check=True,
        )  # fmt: skip
        lines = cli.stdout.splitlines()
        self.assertFalse([s for s in lines if s.startswith("path")], "open paths: no areas")
        expected = {tuple(int(i) for i in line.split()) for line in lines}
        row = {}
        for k, feature in enumerate(layer(path).getFeatures()):
            point = feature.geometry().asPoint()
            row.setdefault((point.x(), point.y()), k)
        got = {tuple(row[p] for p in ring) for f in areas.getFeatures() for ring in rings(f)}
        self.assertEqual(len(got), len(expected))
        self.assertEqual(got, expected)

    def test_a_polygon_layer_gives_its_vertices_each_closing_one_once(self):
        hull = f"{GIS / 'two_layers.gpkg'}|layername=hull"
        # Lines and left-out points are optional outputs.
        _, out = self.run_ok("hull", INPUT=hull, outputs=["AREAS"])
        [polygon] = layer(hull).getFeatures()
        ring = polygon.geometry().constGet().exteriorRing()
        [area] = out["AREAS"].getFeatures()
        self.assertEqual(area["n_points"], ring.numPoints() - 1)
        self.assertTrue(area.geometry().isGeosEqual(polygon.geometry()))

    def test_every_kind_of_group_and_the_failing_ones_reported(self):
        path = OUT / "groups.geojson"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(groups_geojson())
        process, out = self.run_ok("groups", INPUT=path, GROUP_FIELD="name", EXPECT=0)
        log = process.stdout + process.stderr
        # A group sigdt refuses (longitude 500) and one it cannot outline (one point) are
        # named in the log; the other groups are written.
        self.assertRegex(log, r"group 'off': .*longitude", output(process))
        self.assertRegex(log, r"group 'lone': no outline \(too-few-points\)", output(process))
        self.assertEqual([f["name"] for f in out["AREAS"].getFeatures()], ["ring"])
        # A NULL name (QGIS's NULL, which is falsy) as None.
        kinds = {(f["name"] or None, f["kind"], f["status"]) for f in out["LINES"].getFeatures()}
        self.assertEqual(kinds, {(None, "path", "curves"), ("cross", "network", "network")})
        [left] = out["LEFT_OUT"].getFeatures()
        self.assertEqual(
            (left["name"], left["row"], left["reason"]), ("ring", OUTLIER_ROW, "outlier")
        )
        point = left.geometry().asPoint()
        self.assertEqual((point.x(), point.y()), OUTLIER)

    def test_an_island_across_the_antimeridian_stays_an_island(self):
        # 24 points 0.5° around (180°, -16.5°), longitudes in [-180, 180].
        ring = [(180 + 0.5 * math.cos(t), -16.5 + 0.5 * math.sin(t)) for t in turns(24)]
        path = OUT / "antimeridian.geojson"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(geojson([(None, (x - 360 if x > 180 else x, y)) for x, y in ring]))
        _, out = self.run_ok("antimeridian", INPUT=path)
        [area] = out["AREAS"].getFeatures()
        self.assertTrue(area.geometry().isGeosValid())
        # The disc is about 0.8 square degrees; rings written as they run span the world.
        self.assertLess(area.geometry().area(), 1.0)
        # Split at ±180 (RFC 7946 §3.1.9): two parts, one on each side, meeting there.
        parts = [part.boundingBox() for part in area.geometry().asGeometryCollection()]
        spans = sorted((round(b.xMinimum(), 6), round(b.xMaximum(), 6)) for b in parts)
        self.assertEqual(spans, [(-180.0, -179.5), (179.5, 180.0)])

    def test_without_sigdt_the_error_says_how_to_install_it(self):
        process, _ = run_algorithm("bare", home=BARE_HOME, INPUT=GIS / "sigma_27700.gpkg")
        self.assertNotEqual(process.returncode, 0, output(process))
        log = process.stdout + process.stderr
        self.assertNotIn("Traceback", log, output(process))
        python = "/usr/bin/python{}.{}".format(*sys.version_info)  # Debian's: QGIS embeds it
        command = f'"{python}" -m pip install --no-deps --target "{profile_python(BARE_HOME)}"'
        self.assertIn(command, log, output(process))

    def test_an_unknown_group_field_is_named(self):
        process, _ = run_algorithm("no-field", INPUT=GIS / "sigma_4326.gpkg", GROUP_FIELD="isle")
        self.assertNotEqual(process.returncode, 0, output(process))
        self.assertIn("The input has no field 'isle' to group by", process.stdout + process.stderr)
        self.assertNotIn("Traceback", process.stdout + process.stderr, output(process))

    def test_no_points_is_a_one_line_error(self):
        path = OUT / "no-points.geojson"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(
            '{"type": "FeatureCollection", "features": [{"type": "Feature", '
            '"properties": {"name": "a"}, "geometry": null}]}'
        )
        process, _ = run_algorithm("no-points", INPUT=path)
        self.assertNotEqual(process.returncode, 0, output(process))
        self.assertIn("The input has no points", process.stdout + process.stderr)
        self.assertNotIn("Traceback", process.stdout + process.stderr, output(process))


def rings(feature):
    """Every ring of a MultiPolygon feature as ``(x, y)`` tuples, without the closing one."""
    for polygon in feature.geometry().constGet():
        found = [polygon.exteriorRing()]
        found += [polygon.interiorRing(k) for k in range(polygon.numInteriorRings())]
        for ring in found:
            yield [(ring.xAt(k), ring.yAt(k)) for k in range(ring.numPoints() - 1)]


def turns(n):
    """``n`` angles evenly around the circle, from 0."""
    return [2 * math.pi * k / n for k in range(n)]


def island(lat0):
    """The island data/real/gshhs_arch_aland_k1.xy, 5 km wide, at latitude ``lat0`` as
    longitude/latitude (each point's own scale of longitude), as test_gis.py places it."""
    r = 6_371_008.8
    text = (ROOT / "data/real/gshhs_arch_aland_k1.xy").read_text()
    xy = [[float(v) for v in line.split()] for line in text.splitlines()]
    lo = [min(p[k] for p in xy) for k in (0, 1)]
    scale = 5000.0 / max(max(p[k] for p in xy) - lo[k] for k in (0, 1))
    out = []
    for x, y in xy:
        lat = lat0 + math.degrees((y - lo[1]) * scale / r)
        out.append(
            (10.0 + math.degrees((x - lo[0]) * scale / (r * math.cos(math.radians(lat)))), lat)
        )
    return out


#: The left-out point of group "ring" and its row in the file (see groups_geojson).
OUTLIER = (10.0 + 0.05, 50.0)
OUTLIER_ROW = 48


def groups_geojson():
    """Points in longitude/latitude (GeoJSON's CRS) near 10° E 50° N: a ring of 48 points
    and an outlier (``ring``), an open arc with no name (NULL), two crossing lines
    (``cross``), one point (``lone``) and points at longitude 500 (``off``)."""

    def ring(k, n, r, start=0.0, stop=2 * math.pi, closed=True):
        t = start + (stop - start) * k / (n if closed else n - 1)
        # About 1 km on the ground in both directions at 50° N.
        return 10 + r * math.cos(t) / math.cos(math.radians(50)), 50 + r * math.sin(t)

    points = [("ring", ring(k, 48, 0.01)) for k in range(48)] + [("ring", OUTLIER)]
    points += [(None, ring(k, 30, 0.01, 0, math.pi, False)) for k in range(30)]
    points += [("cross", (10.1 + 0.0005 * k, 50.1)) for k in range(-20, 21)]
    points += [("cross", (10.1, 50.1 + 0.0005 * k)) for k in range(-20, 21) if k]
    points += [("lone", (10.2, 50.2)), ("off", (500.0, 50.0)), ("off", (500.1, 50.1))]
    points += [("off", (500.2, 50.0))]
    return geojson(points)


def geojson(points):
    """A GeoJSON FeatureCollection of ``(name, (x, y))`` points (``name`` None: null)."""
    features = [
        {
            "type": "Feature",
            "properties": {"name": name},
            "geometry": {"type": "Point", "coordinates": [x, y]},
        }
        for name, (x, y) in points
    ]
    return json.dumps({"type": "FeatureCollection", "features": features})


if __name__ == "__main__":
    unittest.main()
