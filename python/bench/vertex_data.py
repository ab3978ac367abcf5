"""Writes ``data/vertices``: real polygons given the way GIS users hold them, by their
digitised vertices, densified, jittered and with outliers (issue 44), each with its true
polygon, split into a design half and a held-out half by source item (issue 49).

Run from the repository root (``make data-vertices`` does it)::

    .venv/bin/python python/bench/vertex_data.py [OUT_DIR]

Outlines, one per source item:

- the closed polygon-vertex cases of ``data/real`` (GSHHS islands, lakes and archipelagos,
  census polygons: the ``_kK`` cases; per source item the one with the smallest K, so the
  vertices as digitised where the record is small enough);
- every country of Natural Earth's 1:110m admin-0 layer, as pyogrio ships it for its own
  tests (``naturalearth_lowres``), projected to kilometres by a local equirectangular
  projection about its centre; longitudes of a country that spans the antimeridian are
  unwrapped first (Russia, Fiji), and parts that then touch are merged.

Variants (``category`` in ``index.csv``), with ``m`` the median edge of the outline's own
vertices:

- ``vertices-raw``: the vertices as they are: dense on detail, sparse on straight runs;
- ``vertices-seg100``, ``vertices-seg050``: the vertices plus evenly spaced samples on every
  edge longer than ``d`` = ``m`` or ``m/2`` (as ``shapely.segmentize`` does);
- ``vertices-noise010``, ``vertices-noise025``: ``vertices-seg100`` with each sample moved by
  an isotropic Gaussian of standard deviation 0.10 and 0.25 of its local spacing (the mean
  of its two edges) per coordinate;
- ``vertices-outliers``: ``vertices-seg100`` plus 1, 2 or 3 % outliers (seeded), uniform in
  the samples' box enlarged by ``2 d``, each farther than ``2 d`` from the true outline.

Every usable outline is kept, hard ones included. An outline is dropped only when its
ground truth cannot be written as vertex-disjoint simple rings (``counts.json`` says why).
``spacing`` in ``index.csv`` is ``m`` for raw vertices and ``d`` otherwise: the largest gap
a sampler at that setting leaves along a straight run. The halves are drawn once by a
seeded permutation of the sorted source items (``half``: ``design`` or ``held-out``); rules
are designed on ``design`` only. The output is the same bit for bit for the pinned numpy,
shapely and pyogrio (``python/tests/test_vertex_data.py`` checks it).
"""

from __future__ import annotations

import csv
import json
import sys
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import LinearRing

sys.path.insert(0, str(Path(__file__).resolve().parent))
from outline_data import INDEX_HEADER, halves, holes, region, rings_of, write_case, write_truth

ROOT = Path(__file__).resolve().parents[2]
SOURCE = ROOT / "data" / "real"
SEED = 44
KM_PER_DEGREE = 111.32
SEGMENTS = {"seg100": 1.0, "seg050": 0.5}
NOISE = {"noise010": 0.10, "noise025": 0.25}
MIN_RING_VERTICES = 4


def natural_earth_path() -> Path:
    """The shapefile of Natural Earth's countries that pyogrio ships as a test fixture."""
    import pyogrio

    path = Path(pyogrio.__file__).parent / "tests/fixtures/naturalearth_lowres"
    return path / "naturalearth_lowres.shp"


def without_repeats(ring: np.ndarray) -> np.ndarray:
    """A ring's vertices without the closing copy and without consecutive repeats."""
    if len(ring) > 1 and np.array_equal(ring[0], ring[-1]):
        ring = ring[:-1]
    keep = np.any(ring != np.roll(ring, 1, axis=0), axis=1)
    return ring[keep] if len(ring) > 1 else ring


def polygon_rings(geometry: shapely.Geometry) -> list[np.ndarray]:
    """Every exterior and interior ring of a (multi)polygon, as vertex arrays."""
    rings = []
    for polygon in shapely.get_parts(geometry):
        if polygon.geom_type != "Polygon":
            continue
        for ring in [polygon.exterior, *polygon.interiors]:
            rings.append(without_repeats(np.asarray(ring.coords)))
    return rings


def crosses_antimeridian(geometry: shapely.Geometry) -> bool:
    """Parts on both sides of 180 deg, none of them wider than 180 deg itself (a part that is,
    Antarctica's, goes round the pole and is a polygon in longitude and latitude as it is)."""

    def span(g: shapely.Geometry) -> float:
        lon = shapely.get_coordinates(g)[:, 0]
        return float(lon.max() - lon.min())

    return span(geometry) > 180.0 and all(span(p) <= 180.0 for p in shapely.get_parts(geometry))


def local_plane(centre: np.ndarray):
    """Longitude and latitude to kilometres east and north of ``centre`` (equirectangular)."""
    scale = np.array([np.cos(np.radians(centre[1])) * KM_PER_DEGREE, KM_PER_DEGREE])
    return lambda c: (c - centre) * scale


def country_outlines() -> list[tuple[str, str, list[np.ndarray]]]:
    """Natural Earth's countries: (case base name, source item, rings in km)."""
    import pyogrio

    frame = pyogrio.read_dataframe(natural_earth_path())
    outlines = []
    for k, (name, geometry) in enumerate(zip(frame["name"], frame.geometry)):
        if crosses_antimeridian(geometry):
            # Western longitudes continue east of 180, and parts that meet there merge.
            geometry = shapely.transform(geometry, lambda c: np.where(c < 0, c + [360, 0], c))
            geometry = shapely.unary_union(shapely.make_valid(geometry))
        centre = shapely.get_coordinates(shapely.centroid(geometry))[0]
        geometry = shapely.transform(geometry, local_plane(centre))
        slug = "".join(ch for ch in name.lower() if ch.isalnum())[:24] or f"country{k}"
        outlines.append((f"ne_{slug}", f"naturalearth:{name}", polygon_rings(geometry)))
    return outlines


def real_outlines() -> list[tuple[str, str, list[np.ndarray]]]:
    """The closed polygon-vertex cases of ``data/real``, one per source item (smallest K)."""
    with open(SOURCE / "index.csv", newline="") as f:
        closed = {
            r["name"]
            for r in csv.DictReader(f)
            if r["category"] in ("manifold", "sharp", "multiple")
        }
    best: dict[tuple[str, ...], tuple[int, str]] = {}
    with open(SOURCE / "cases.jsonl") as f:
        for line in f:
            case = json.loads(line)
            if case["name"] not in closed or "k" not in case:
                continue
            key = tuple(case.get("items", [case["name"]]))
            if key not in best or (case["k"], case["name"]) < best[key]:
                best[key] = (case["k"], case["name"])
    outlines = []
    for key, (_, name) in sorted(best.items(), key=lambda kv: kv[1][1]):
        points = np.loadtxt(SOURCE / f"{name}.xy", ndmin=2)
        edges = np.loadtxt(SOURCE / f"{name}.gt", dtype=np.int64, ndmin=2)
        outlines.append((name, "+".join(key), rings_of(points, edges)))
    return outlines


def why_unusable(rings: list[np.ndarray]) -> str | None:
    """Why these rings cannot be a ground truth of vertex-disjoint simple rings, or ``None``."""
    if not rings:
        return "no ring"
    if any(len(r) < MIN_RING_VERTICES - 1 for r in rings):
        return "a ring has fewer than 3 vertices"
    if not all(LinearRing(r).is_simple for r in rings):
        return "a ring crosses itself"
    points = np.vstack(rings)
    if len(np.unique(points, axis=0)) < len(points):
        return "two rings share a vertex"
    lines = [LinearRing(r) for r in rings]
    for i in range(len(lines)):
        for j in range(i):
            if lines[i].intersects(lines[j]):
                return "two rings touch or cross"
    return None


def median_edge(rings: list[np.ndarray]) -> float:
    lengths = [np.hypot(*(np.roll(r, -1, axis=0) - r).T) for r in rings]
    return float(np.median(np.concatenate(lengths)))


def segmentized(ring: np.ndarray, d: float) -> np.ndarray:
    """The ring's vertices and evenly spaced samples on every edge longer than ``d``."""
    closed = np.vstack([ring, ring[:1]])
    dense = shapely.get_coordinates(shapely.segmentize(shapely.LineString(closed), d))
    return dense[:-1]


def local_spacing(ring: np.ndarray) -> np.ndarray:
    """Per sample, the mean length of its two edges."""
    after = np.hypot(*(np.roll(ring, -1, axis=0) - ring).T)
    return 0.5 * (after + np.roll(after, 1))


def outliers(
    rng: np.random.Generator, clean: np.ndarray, boundary: shapely.Geometry, gap: float
) -> list[np.ndarray]:
    """1, 2 or 3 % of the samples as outliers farther than ``gap`` from the outline."""
    want = max(1, round(rng.choice([0.01, 0.02, 0.03]) * len(clean)))
    lo, hi = clean.min(0) - gap, clean.max(0) + gap
    extra: list[np.ndarray] = []
    for _ in range(1000 * want):
        q = rng.uniform(lo, hi)
        if boundary.distance(shapely.Point(q)) > gap:
            extra.append(q)
            if len(extra) == want:
                break
    return extra


def main(argv: list[str]) -> int:
    out = Path(argv[0]) if argv else ROOT / "data" / "vertices"
    out.mkdir(parents=True, exist_ok=True)
    dropped: dict[str, list[str]] = {}
    usable = []
    for base, item, rings in real_outlines() + country_outlines():
        why = why_unusable(rings)
        if why:
            dropped.setdefault(why, []).append(base)
        else:
            usable.append((base, item, rings))
    half_of = halves(sorted({item for _, item, _ in usable}), SEED)
    index = []
    for k, (base, item, rings) in enumerate(usable):
        m = median_edge(rings)
        write_truth(out, f"{base}_raw", rings)
        n_holes = holes(rings)
        boundary = region(rings).boundary
        variants: list[tuple[str, list[np.ndarray], float, float]] = [("raw", rings, m, 0.0)]
        for variant, ratio in SEGMENTS.items():
            variants.append((variant, [segmentized(r, ratio * m) for r in rings], ratio * m, 0.0))
        seg = variants[1][1]
        for variant, sigma in NOISE.items():
            variants.append((variant, seg, m, sigma))
        variants.append(("outliers", seg, m, 0.0))
        for variant, samples, spacing, sigma in variants:
            rng = np.random.default_rng([SEED, k, len(index)])
            clean = np.vstack(samples)
            points = clean
            if sigma:
                scale = np.concatenate([local_spacing(s) for s in samples])[:, None]
                points = clean + rng.normal(0.0, 1.0, clean.shape) * sigma * scale
            n_out = 0
            if variant == "outliers":
                extra = outliers(rng, clean, boundary, 2 * spacing)
                n_out = len(extra)
                points = np.vstack([clean, *extra]) if extra else clean
            if len(np.unique(points, axis=0)) < len(points):
                dropped.setdefault("two samples coincide", []).append(f"{base}_{variant}")
                continue
            name = f"{base}_{variant}"
            write_case(out, name, points, [len(s) for s in samples], rng.permutation(len(points)))
            if variant != "raw":
                for suffix in ("curve.xy", "curve.gt"):
                    text = (out / f"{base}_raw.{suffix}").read_text()
                    (out / f"{name}.{suffix}").write_text(text)
            noise = f"{sigma:g}" if sigma else "0"
            row = [name, f"vertices-{variant}", len(points), len(rings), 1, "", noise, n_out]
            index.append([*row, f"{spacing:.6g}", n_holes, half_of[item], item])
    with open(out / "index.csv", "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(INDEX_HEADER)
        writer.writerows(index)
    counts = {
        "outlines": len(usable),
        "cases": len(index),
        "design outlines": sum(half_of[item] == "design" for _, item, _ in usable),
        "dropped": {why: sorted(names) for why, names in sorted(dropped.items())},
    }
    (out / "counts.json").write_text(json.dumps(counts, indent=1, sort_keys=True) + "\n")
    print(f"wrote {len(index)} cases ({len(usable)} outlines) to {out}; dropped {dropped}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
