"""``reconstruct_frame`` against ``reconstruct_many`` on many small groups (issue 47, P4):
building footprints, parcels. G groups of 10 points each, rings 5 m across scattered over
1000 km (EPSG:27700); both calls on the same points, in one process.

Run: ``.venv/bin/python python/bench/many_groups.py [GROUPS]`` (default 40,000); it prints
each call's seconds over 5 interleaved runs and the median of their ratios. Whole-process memory: ``/usr/bin/time -v`` around it.
"""

from __future__ import annotations

import sys
import time
import warnings

import geopandas as gpd
import numpy as np
import shapely
import sigdt


def main(groups: int, repeats: int) -> None:
    warnings.simplefilter("ignore", sigdt.SigdtWarning)
    rng = np.random.default_rng(0)
    n = 10
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    ring = 5 * np.c_[np.cos(t), np.sin(t)]
    points = (rng.uniform(0, 1e6, (groups, 2))[:, None, :] + ring[None]).reshape(-1, 2)
    frame = gpd.GeoDataFrame(
        {"building": np.repeat(np.arange(groups), n)},
        geometry=shapely.points(points),
        crs=27700,
    )
    arrays = list(points.reshape(groups, n, 2))
    many, grouped = [], []
    for _ in range(repeats):  # interleaved, so that both see the same machine
        start = time.perf_counter()
        results = sigdt.reconstruct_many(arrays)
        many.append(time.perf_counter() - start)
        del results
        start = time.perf_counter()
        sigdt.reconstruct_frame(frame, by="building", progress=False)
        grouped.append(time.perf_counter() - start)
    ratios = sorted(g / m for g, m in zip(grouped, many))
    print(
        f"{groups} groups of {n} points, {repeats} interleaved runs: reconstruct_many "
        f"{min(many):.2f}-{max(many):.2f} s, reconstruct_frame {min(grouped):.2f}-"
        f"{max(grouped):.2f} s, ratio median {ratios[len(ratios) // 2]:.2f} "
        f"(range {ratios[0]:.2f}-{ratios[-1]:.2f})"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 40_000, 5)
