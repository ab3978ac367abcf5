"""Python benchmark of sigdt: call overhead at 1e5 points and batch throughput.

Run from the repository root after ``make py-build build``::

    .venv/bin/python python/bench/bench_python.py            # prints a Markdown report

(a) **Overhead of calling from Python at 1e5 points.** Input: ``large_100k.xy`` of the
labelled curves (``$SIGDT_DATA`` or the repository's ``data/curves``), read once per process.

- *Rust time*: the CLI's own timing of the library call, ``sigdt reconstruct FILE -v``
  (``time: X ms``, an ``Instant`` around ``sigdt::reconstruct`` only: no parsing, no output).
- *Python time*: ``time.perf_counter()`` around ``sigdt.reconstruct(points)`` with the
  points already loaded (``sigdt.read_points``), so it covers argument checks, the zero-copy
  borrow, the Rust call and the conversion of the result to numpy arrays.

The CLI's call is the first and only one in a fresh process, so it pays for first-touch page
faults that a warm process does not; comparing it with a warm Python call would flatter
Python. So the Python side is measured the same way: the first call in a fresh interpreter.
CLI and Python runs alternate, 7 of each, and the medians are compared. The overhead is
``python / rust - 1``. For information, the warm medians in this process (7 calls after
one warm-up) of ``sigdt._core.reconstruct`` (binding only) and ``sigdt.reconstruct``, both
with ``method="sig-connect2d"``, are printed too; their difference is the pure-Python
wrapper.

(b) **Batch throughput.** 10,000 seeded radial-Fourier blobs of 240 to 280 points (shuffled),
converted to float64 arrays beforehand. Sets per second (median of 3 runs) of the serial
loop ``[sigdt.reconstruct(p) for p in sets]``, ``reconstruct_many(sets, n_jobs=1)`` and
``reconstruct_many(sets, n_jobs=2)``; the speedup is ``n_jobs=2`` over ``n_jobs=1``.

Targets (issue 3): overhead < 5 % at 1e5 points; single-thread throughput >= 5,000 sets/s;
speedup >= 1.7 on 2 cores.
"""

from __future__ import annotations

import argparse
import os
import platform
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import sigdt
from release_binary import cli_binary

ROOT = Path(__file__).resolve().parents[2]
FIRST_CALL = """
import sys, time, sigdt
points = sigdt.read_points(sys.argv[1])
start = time.perf_counter()
sigdt.reconstruct(points)
print((time.perf_counter() - start) * 1e3)
"""


def default_input() -> Path:
    data = Path(os.environ.get("SIGDT_DATA") or ROOT / "data" / "curves")
    return data / "large_100k.xy"


def cli_ms(cli: Path, path: Path) -> float:
    run = subprocess.run(
        [str(cli), "reconstruct", str(path), "-v", "-o", os.devnull, "--format", "edges"],
        capture_output=True,
        text=True,
        check=True,
    )
    return float(re.search(r"^time:\s+([0-9.]+) ms", run.stderr, re.MULTILINE).group(1))


def python_first_call_ms(path: Path) -> float:
    run = subprocess.run(
        [sys.executable, "-c", FIRST_CALL, str(path)], capture_output=True, text=True, check=True
    )
    return float(run.stdout)


def warm_ms(f, reps: int = 7) -> float:
    f()
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        f()
        times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times)


def blob_sets(count: int, seed: int) -> list[np.ndarray]:
    """Radial Fourier blobs r = 1 + sum a_k cos(k t + phi_k), k = 2..4, a_k <= 0.25/k^2,
    sampled uniformly in arc length, shuffled."""
    rng = np.random.default_rng(seed)
    theta = np.linspace(0.0, 2.0 * np.pi, 2049)
    k = np.arange(2, 5)[:, None]
    sets = []
    for _ in range(count):
        n = int(rng.integers(240, 281))
        a = (0.25 * rng.uniform(size=3) / np.arange(2, 5) ** 2)[:, None]
        phi = rng.uniform(0, 2 * np.pi, size=3)[:, None]

        def radius(t, a=a, phi=phi):
            return 1.0 + (a * np.cos(k * t + phi)).sum(axis=0)

        r = radius(theta)
        arc = np.r_[
            0.0, np.cumsum(np.hypot(np.diff(r * np.cos(theta)), np.diff(r * np.sin(theta))))
        ]
        t = np.interp((np.arange(n) + rng.uniform()) * arc[-1] / n, arc, theta)
        r = radius(t)
        sets.append(np.ascontiguousarray(np.c_[r * np.cos(t), r * np.sin(t)][rng.permutation(n)]))
    return sets


def throughput(f, count: int, reps: int = 3) -> float:
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return count / statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--input", type=Path, default=default_input(), help="1e5-point file")
    parser.add_argument("--runs", type=int, default=7, help="processes per side in (a)")
    parser.add_argument("--sets", type=int, default=10_000, help="point sets in (b)")
    args = parser.parse_args()
    cli = cli_binary()
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    print(
        f"Machine: {platform.machine()} {platform.system()}, {cores} cores; Python "
        f"{platform.python_version()}, numpy {np.__version__}, sigdt {sigdt.__version__}.\n"
    )

    # (a) overhead
    points = sigdt.read_points(args.input)
    rust, python = [], []
    for _ in range(args.runs):
        rust.append(cli_ms(cli, args.input))
        python.append(python_first_call_ms(args.input))
    rust_ms, python_ms = statistics.median(rust), statistics.median(python)
    overhead = python_ms / rust_ms - 1.0
    core_warm = warm_ms(lambda: sigdt._core.reconstruct(points, "sig-connect2d", True))
    api_warm = warm_ms(lambda: sigdt.reconstruct(points, method="sig-connect2d"))

    # (b) throughput
    sets = blob_sets(args.sets, seed=7)
    mean_n = np.mean([len(p) for p in sets])
    serial = throughput(lambda: [sigdt.reconstruct(p) for p in sets], len(sets))
    one = throughput(lambda: sigdt.reconstruct_many(sets, n_jobs=1), len(sets))
    two = throughput(lambda: sigdt.reconstruct_many(sets, n_jobs=2), len(sets))
    speedup = two / one

    def verdict(ok: bool) -> str:
        return "yes" if ok else "**no**"

    print(f"(a) {len(points):,} points ({args.input.name}), medians of {args.runs} fresh processes")
    print()
    print("| measurement | median ms | min–max ms |")
    print("|---|--:|--:|")
    print(
        f"| Rust: CLI's timing of `sigdt::reconstruct` (first call) | {rust_ms:.1f} "
        f"| {min(rust):.1f}–{max(rust):.1f} |"
    )
    print(
        f"| Python: `sigdt.reconstruct(points)` (first call) | {python_ms:.1f} "
        f"| {min(python):.1f}–{max(python):.1f} |"
    )
    print(f"| warm, in this process: `sigdt._core.reconstruct` | {core_warm:.1f} | |")
    print(f"| warm, in this process: `sigdt.reconstruct` | {api_warm:.1f} | |")
    print()
    print(f"(b) {len(sets):,} sets of {mean_n:.0f} points on average, medians of 3 runs")
    print()
    print("| call | sets/s |")
    print("|---|--:|")
    print(f"| `[sigdt.reconstruct(p) for p in sets]` | {serial:,.0f} |")
    print(f"| `sigdt.reconstruct_many(sets, n_jobs=1)` | {one:,.0f} |")
    print(f"| `sigdt.reconstruct_many(sets, n_jobs=2)` | {two:,.0f} |")
    print()
    print("| target | measured | met |")
    print("|---|--:|:-:|")
    print(f"| Python overhead at 1e5 points < 5 % | {overhead:+.1%} | {verdict(overhead < 0.05)} |")
    print(f"| single-thread >= 5,000 sets/s | {one:,.0f} | {verdict(one >= 5000)} |")
    print(f"| serial loop >= 5,000 sets/s | {serial:,.0f} | {verdict(serial >= 5000)} |")
    met = speedup >= 1.7
    note = "" if cores >= 2 else f" (only {cores} core)"
    print(f"| n_jobs=2 speedup >= 1.7{note} | {speedup:.2f}x | {verdict(met)} |")


if __name__ == "__main__":
    main()
