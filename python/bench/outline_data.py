"""Writes ``data/outlines``: real outlines resampled as a user's data would be, in four
variants (clean, Gaussian noise of 0.1 and 0.25 spacings, 1-3 % outliers), each with its
true polygon (issue 29).

Run from the repository root after ``make py-build`` (``make data-outlines`` does both)::

    .venv/bin/python python/bench/outline_data.py [OUT_DIR]

The outlines are the closed ground-truth rings of ``data/real`` (categories manifold, sharp
and multiple; one case per source item, the one with most points). Each is resampled by
arc length at spacing ``s`` = the median ground-truth edge of its case, with one random start
per ring and every sample moved by up to 0.3 s along the ring. An outline is kept when every
ring has at least 12 samples, the resampled rings are simple and at least 2 s apart, the
resampled polygon covers the true one with IoU >= 0.97 (the outline can be drawn at this
spacing) and has at most 4000 samples. The output is the same bit for bit for the pinned
numpy and shapely (``python/tests/test_outline_data.py`` checks it).
"""

from __future__ import annotations

import csv
import json
import sys
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import LinearRing, Polygon

ROOT = Path(__file__).resolve().parents[2]
SOURCE = ROOT / "data" / "real"
SEED = 29
JITTER = 0.3
NOISE = {"clean": 0.0, "noise010": 0.10, "noise025": 0.25}
MIN_RING_SAMPLES = 12
MAX_SAMPLES = 4000
MIN_IOU = 0.97
MAX_OUTLINES = 120
#: The columns of ``index.csv`` (the vertex set's too).
INDEX_HEADER = [
    "name",
    "category",
    "n_points",
    "n_components",
    "closed",
    "epsilon",
    "noise",
    "outliers",
    "spacing",
    "holes",
    "half",
    "source",
]


def rings_of(points: np.ndarray, edges: np.ndarray) -> list[np.ndarray]:
    """The closed rings of an edge set in which every vertex has two edges, in order."""
    neighbours: dict[int, list[int]] = {}
    for a, b in edges:
        neighbours.setdefault(int(a), []).append(int(b))
        neighbours.setdefault(int(b), []).append(int(a))
    seen: set[int] = set()
    rings = []
    for start in sorted(neighbours):
        if start in seen:
            continue
        ring, previous, current = [start], -1, start
        seen.add(start)
        while True:
            following = [v for v in neighbours[current] if v != previous]
            if not following or following[0] in seen:
                break
            previous, current = current, following[0]
            ring.append(current)
            seen.add(current)
        rings.append(points[ring])
    return rings


def read_rings(name: str) -> tuple[list[np.ndarray], float]:
    """The closed rings of a case's ground truth, and its median edge length."""
    points = np.loadtxt(SOURCE / f"{name}.xy", ndmin=2)
    edges = np.loadtxt(SOURCE / f"{name}.gt", dtype=np.int64, ndmin=2)
    spacing = float(np.median(np.hypot(*(points[edges[:, 0]] - points[edges[:, 1]]).T)))
    return rings_of(points, edges), spacing


def region(rings: list[np.ndarray]) -> shapely.Geometry:
    """The even-odd region of closed rings (nested rings are holes); ``None`` for no ring of
    three or more points."""
    result = None
    for ring in rings:
        if len(ring) < 3:
            continue
        polygon = Polygon(ring).buffer(0)
        result = polygon if result is None else result.symmetric_difference(polygon)
    return result


def resample(ring: np.ndarray, spacing: float, rng: np.random.Generator) -> np.ndarray:
    """Samples at arc length ``(j + o + J_j) * L / k``, ``J_j`` uniform in +-0.3."""
    closed = np.vstack([ring, ring[:1]])
    cumulative = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
    length = cumulative[-1]
    k = max(round(length / spacing), 1)
    offset = rng.uniform()
    t = (np.arange(k) + offset + rng.uniform(-JITTER, JITTER, k)) * length / k
    t = np.sort(np.mod(t, length))
    return np.c_[np.interp(t, cumulative, closed[:, 0]), np.interp(t, cumulative, closed[:, 1])]


def usable(samples: list[np.ndarray], truth: shapely.Geometry, spacing: float) -> str | None:
    """Why an outline is dropped, or ``None``."""
    if any(len(s) < MIN_RING_SAMPLES for s in samples):
        return "a ring has fewer than 12 samples"
    if sum(map(len, samples)) > MAX_SAMPLES:
        return "more than 4000 samples"
    rings = [LinearRing(s) for s in samples]
    if not all(r.is_simple for r in rings):
        return "a resampled ring crosses itself"
    for i in range(len(rings)):
        for j in range(i):
            if rings[i].distance(rings[j]) < 2 * spacing:
                return "two rings closer than 2 s"
    resampled = region(samples)
    if resampled.intersection(truth).area / resampled.union(truth).area < MIN_IOU:
        return "the resampled polygon differs from the true one (IoU < 0.97)"
    points = np.vstack(samples)
    if len(np.unique(points, axis=0)) < len(points):
        return "two samples coincide"
    return None


def holes(samples: list[np.ndarray]) -> int:
    """How many rings lie inside an odd number of others."""
    polygons = [Polygon(s) for s in samples]
    depth = [
        sum(other.contains(shapely.Point(s[0])) for j, other in enumerate(polygons) if j != i)
        for i, s in enumerate(samples)
    ]
    return sum(d % 2 for d in depth)


def halves(items: list[str], seed: int) -> dict[str, str]:
    """A seeded half of the sorted source ``items`` for design, the rest held out (issue 49):
    every second item of one permutation."""
    order = np.random.default_rng(seed).permutation(len(items))
    return {items[i]: ("design" if k % 2 == 0 else "held-out") for k, i in enumerate(order)}


def number(x: float) -> str:
    return repr(float(x))


def write_case(
    out: Path, name: str, points: np.ndarray, rings: list[int], order: np.ndarray
) -> None:
    """``NAME.xy`` in the seeded ``order`` and ``NAME.gt``: each ring's consecutive samples."""
    position = np.empty(len(order), dtype=np.int64)
    position[order] = np.arange(len(order))
    edges = []
    start = 0
    for size in rings:
        for j in range(size):
            a, b = position[start + j], position[start + (j + 1) % size]
            edges.append((min(a, b), max(a, b)))
        start += size
    (out / f"{name}.xy").write_text("".join(f"{number(x)} {number(y)}\n" for x, y in points[order]))
    (out / f"{name}.gt").write_text("".join(f"{a} {b}\n" for a, b in sorted(edges)))


def write_truth(out: Path, name: str, rings: list[np.ndarray]) -> None:
    """``NAME.curve.xy`` and ``NAME.curve.gt``: the true rings as closed polylines."""
    lines, edges, start = [], [], 0
    for ring in rings:
        lines += [f"{number(x)} {number(y)}\n" for x, y in ring]
        edges += [(start + j, start + (j + 1) % len(ring)) for j in range(len(ring))]
        start += len(ring)
    (out / f"{name}.curve.xy").write_text("".join(lines))
    edges = sorted((min(a, b), max(a, b)) for a, b in edges)
    (out / f"{name}.curve.gt").write_text("".join(f"{a} {b}\n" for a, b in edges))


def sources() -> list[dict[str, str]]:
    """One closed case of ``data/real`` per source item: the one with most points."""
    with open(SOURCE / "index.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["category"] in ("manifold", "sharp", "multiple")]
    items = {}
    with open(SOURCE / "cases.jsonl") as f:
        for line in f:
            case = json.loads(line)
            items[case["name"]] = tuple(case.get("items", [case["name"]]))
    best: dict[tuple[str, ...], dict[str, str]] = {}
    for row in rows:
        key = items.get(row["name"], (row["name"],))
        if key not in best or int(row["n_points"]) > int(best[key]["n_points"]):
            best[key] = row
    return sorted(best.values(), key=lambda r: r["name"])


def main(argv: list[str]) -> int:
    out = Path(argv[0]) if argv else ROOT / "data" / "outlines"
    out.mkdir(parents=True, exist_ok=True)
    dropped: dict[str, int] = {}
    kept = []
    for k, row in enumerate(sources()):
        rng = np.random.default_rng([SEED, k])
        rings, spacing = read_rings(row["name"])
        truth = region(rings)
        samples = [resample(r, spacing, rng) for r in rings]
        why = usable(samples, truth, spacing)
        if why:
            dropped[why] = dropped.get(why, 0) + 1
            continue
        kept.append((row, rings, spacing, samples, k))
    # At most MAX_OUTLINES, spread over the sorted names (every n-th).
    step = max(1, -(-len(kept) // MAX_OUTLINES))
    chosen = kept[::step]
    index = []
    half_of = halves(sorted(f"real:{row['name']}" for row, *_ in chosen), SEED)
    for row, rings, spacing, samples, k in chosen:
        base = row["name"]
        clean = np.vstack(samples)
        sizes = [len(s) for s in samples]
        n_holes = holes(samples)
        write_truth(out, f"{base}_clean", rings)
        for variant, sigma in [*NOISE.items(), ("outliers", 0.0)]:
            rng = np.random.default_rng([SEED, k, len(index)])
            points = clean + rng.normal(0.0, sigma * spacing, clean.shape) if sigma else clean
            n_out = 0
            if variant == "outliers":
                share = rng.choice([0.01, 0.02, 0.03])
                n_out = max(1, round(share * len(clean)))
                boundary = region(rings).boundary
                lo, hi = clean.min(0) - 2 * spacing, clean.max(0) + 2 * spacing
                extra: list[np.ndarray] = []
                for _ in range(1000 * n_out):
                    q = rng.uniform(lo, hi)
                    if boundary.distance(shapely.Point(q)) > 2 * spacing:
                        extra.append(q)
                        if len(extra) == n_out:
                            break
                n_out = len(extra)
                points = np.vstack([clean, *extra]) if extra else clean
            name = f"{base}_{variant}"
            order = rng.permutation(len(points))
            write_case(out, name, points, sizes, order)
            if variant != "clean":
                for suffix in ("curve.xy", "curve.gt"):
                    text = (out / f"{base}_clean.{suffix}").read_text()
                    (out / f"{name}.{suffix}").write_text(text)
            noise = f"{sigma:g}" if sigma else "0"
            index.append(
                [
                    name,
                    f"outline-{variant}",
                    len(points),
                    len(rings),
                    1,
                    "",
                    noise,
                    n_out,
                    f"{spacing:.6g}",
                    n_holes,
                    half_of[f"real:{base}"],
                    f"real:{base}",
                ]
            )
    with open(out / "index.csv", "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(INDEX_HEADER)
        writer.writerows(index)
    counts = {"kept": len(chosen), "usable": len(kept), "dropped": dropped}
    (out / "counts.json").write_text(json.dumps(counts, indent=1, sort_keys=True) + "\n")
    print(f"wrote {len(index)} cases ({len(chosen)} outlines) to {out}; dropped {dropped}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
