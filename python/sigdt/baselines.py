"""Reconstructions by tools outside sigdt, for side-by-side comparisons.

:func:`concave_hull` runs ``shapely.concave_hull`` (GEOS), the tool practitioners reach for
today, and reads its polygon back as edges between input indices, so that it can be scored
like any sigdt method. Run as a module, it writes a folder that ``sigdt bench --import``
scores::

    python -m sigdt.baselines DATA_DIR OUT_DIR [--ratio 0]

writes ``OUT_DIR/NAME.edges`` for every case of ``DATA_DIR/index.csv`` and
``OUT_DIR/times.csv`` (``name,time_ms``: the median of 3 calls of ``shapely.concave_hull``
on the already loaded points).
"""

from __future__ import annotations

import argparse
import csv
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["concave_hull"]


def concave_hull(points: Any, *, ratio: float = 0.0) -> np.ndarray:
    """The edges of ``shapely.concave_hull(MultiPoint(points), ratio)`` as input indices.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        The points.
    ratio : float, default 0.0
        shapely's ``ratio`` in [0, 1]: 0 is the most concave hull, 1 the convex hull.

    Returns
    -------
    numpy.ndarray
        ``(m, 2)`` int64 edges ``[i, j]``, ``i < j``, rows sorted: the boundary of the
        hull polygon (holes included), with each vertex mapped to the lowest input index
        with those exact coordinates. Points inside the hull get no edges; fewer than three
        distinct points, or a hull that is not a polygon, give the edges of the line or none.

    Raises
    ------
    ValueError
        Points not of shape (n, 2), non-finite coordinates, or ratio outside [0, 1].

    Examples
    --------
    >>> from sigdt.baselines import concave_hull
    >>> concave_hull([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]]).tolist()
    [[0, 1], [0, 4], [1, 2], [2, 3], [3, 4]]
    """
    import shapely

    array = np.asarray(points, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"points must have shape (n, 2), got {array.shape}")
    if not np.isfinite(array).all():
        raise ValueError("points have NaN or infinite coordinates")
    if not 0.0 <= ratio <= 1.0:
        raise ValueError(f"ratio must be in [0, 1], got {ratio}")
    index: dict[tuple[float, float], int] = {}
    for i, (x, y) in enumerate(array.tolist()):
        index.setdefault((x, y), i)
    hull = shapely.concave_hull(shapely.MultiPoint(array), ratio=ratio)
    rings = []
    for part in getattr(hull, "geoms", [hull]):
        if part.geom_type == "Polygon":
            rings += [part.exterior, *part.interiors]
        elif part.geom_type in ("LineString", "LinearRing"):
            rings.append(part)
    edges = set()
    for ring in rings:
        ids = [index[(x, y)] for x, y in shapely.get_coordinates(ring).tolist()]
        for a, b in zip(ids, ids[1:]):
            if a != b:
                edges.add((min(a, b), max(a, b)))
    return np.array(sorted(edges), dtype=np.int64).reshape(-1, 2)


def _write_folder(data: Path, out: Path, ratio: float) -> int:
    with open(data / "index.csv", newline="") as f:
        names = [row["name"] for row in csv.DictReader(f)]
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for name in names:
        points = np.loadtxt(data / f"{name}.xy", ndmin=2)
        times = []
        for _ in range(3):
            start = time.perf_counter()
            edges = concave_hull(points, ratio=ratio)
            times.append((time.perf_counter() - start) * 1e3)
            if times[-1] > 1000:
                break
        np.savetxt(out / f"{name}.edges", edges, fmt="%d")
        rows.append((name, statistics.median(times)))
    with open(out / "times.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["name", "time_ms"])
        writer.writerows((n, f"{t:.6g}") for n, t in rows)
    return len(rows)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m sigdt.baselines",
        description="Write shapely.concave_hull results for every case of a labelled folder.",
    )
    parser.add_argument("data", type=Path, help="folder with index.csv and NAME.xy files")
    parser.add_argument("out", type=Path, help="folder for NAME.edges and times.csv")
    parser.add_argument("--ratio", type=float, default=0.0, help="concave_hull ratio (0)")
    args = parser.parse_args(argv)
    try:
        count = _write_folder(args.data, args.out, args.ratio)
    except (OSError, ValueError, KeyError) as e:
        print(f"python -m sigdt.baselines: {e}", file=sys.stderr)
        return 1
    print(f"wrote {count} results to {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
