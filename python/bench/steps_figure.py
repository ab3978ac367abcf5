"""The figure of docs/steps.md: SIG-CONNECT2D step by step on one point set.

Run from the repository root after ``make py-build`` (``make pictures`` does both)::

    .venv/bin/python python/bench/steps_figure.py POINTS.xy OUT.png
"""

from __future__ import annotations

import sys

import matplotlib

matplotlib.use("Agg")

import sigdt


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    points = sigdt.read_points(argv[0])
    trace = sigdt.trace(points)
    if trace is None:
        print(f"{argv[0]}: no trace (degenerate input)", file=sys.stderr)
        return 1
    k, n = trace.inflated_at, trace.n_steps
    steps = sorted({0, k // 4, k // 2, (3 * k) // 4, k, (k + n) // 2, n})
    figure = sigdt.plot_steps(points, steps=steps, ncols=4)
    figure.set_size_inches(16, 4.2 * ((len(steps) + 3) // 4))
    figure.savefig(argv[1], dpi=80, bbox_inches="tight")
    print(f"wrote {argv[1]}: steps {steps} of {n} (inflating ends at {k})", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
