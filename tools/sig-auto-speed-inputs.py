"""Writes the inputs of SIG-AUTO's speed figures (README "Speed and memory",
docs/algorithms.md section 7.3): a smooth closed curve of 10^6 points sampled evenly by arc
length with +-0.1 spacing jitter along it, and a 10^5-point curve with +-0.3 jitter along
it and Gaussian noise of a quarter of the spacing across, both shuffled; and a network of
about 10^6 points (issue 33): the lines of a square grid, warped into smooth curves that
cross at about 53 000 shared samples, shuffled.

usage: .venv/bin/python tools/sig-auto-speed-inputs.py [--no-curve] OUT_DIR
then:  sigdt reconstruct OUT_DIR/even1e6.xy --threads 1 -o OUT.edges   (and --method
       sig-connect2d; tools/bench-process.sh interleaves whole processes)
"""

import sys
from pathlib import Path

import numpy as np


def blob(fine: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A smooth star-shaped closed curve as a fine polyline, and its arc length."""
    t = np.linspace(0.0, 2.0 * np.pi, fine + 1)
    r = 1.0 + 0.3 * np.sin(3.0 * t) + 0.1 * np.cos(7.0 * t)
    x, y = r * np.cos(t), r * np.sin(t)
    length = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    return x, y, length


def sample(n: int, jitter: float, noise: float, seed: int) -> np.ndarray:
    """`n` points along the curve, jittered along it by up to `jitter` spacings and across
    by Gaussian noise of `noise` spacings, shuffled."""
    rng = np.random.default_rng(seed)
    x, y, length = blob(2_000_000)
    spacing = length[-1] / n
    s = ((np.arange(n) + rng.uniform(-jitter, jitter, n)) * spacing) % length[-1]
    px = np.interp(s, length, x) + rng.normal(0.0, noise * spacing, n)
    py = np.interp(s, length, y) + rng.normal(0.0, noise * spacing, n)
    return np.column_stack([px, py])[rng.permutation(n)]


def warped_grid(cells: int, per_side: int, seed: int) -> np.ndarray:
    """The lines of a `cells` x `cells` grid sampled `per_side` times a cell side, every
    crossing a sample shared by its two lines, warped by a smooth map that bends each line
    by about a fifth of a cell; shuffled."""
    steps = np.arange(cells * per_side + 1) / per_side
    lines = np.arange(cells + 1, dtype=float)
    u_rows, v_rows = np.meshgrid(steps, lines)  # along the rows v = const
    off_crossing = (np.arange(steps.size) % per_side) != 0
    v_cols, u_cols = np.meshgrid(steps[off_crossing], lines)  # columns, crossings once
    u = np.concatenate([u_rows.ravel(), u_cols.ravel()])
    v = np.concatenate([v_rows.ravel(), v_cols.ravel()])
    x = u + 0.2 * np.sin(0.9 * v) + 0.1 * np.sin(0.37 * v + 1.0)
    y = v + 0.2 * np.sin(0.8 * u) + 0.1 * np.cos(0.41 * u + 2.0)
    return np.column_stack([x, y])[np.random.default_rng(seed).permutation(u.size)]


def no_curve(out: Path) -> None:
    """The S2 layouts (module docs), each shuffled."""
    rng = np.random.default_rng(1)

    def save(name: str, p: np.ndarray) -> None:
        np.savetxt(out / name, p[rng.permutation(len(p))], fmt="%.10f")

    grid = np.stack(np.meshgrid(np.arange(1000), np.arange(1000)), -1).reshape(-1, 2)
    save("grid1e6.xy", grid.astype(float))
    save("uniform1e6.xy", rng.uniform(0, 1, (10**6, 2)))
    centres, angles = rng.uniform(0, 1, (500_000, 2)), rng.uniform(0, 2 * np.pi, 500_000)
    twins = centres + np.column_stack([np.cos(angles), np.sin(angles)]) * 1e-4 / np.sqrt(10)
    save("pairs1e6.xy", np.concatenate([centres, twins]))
    along, lines = np.arange(1001.0), np.arange(0, 1001, 10.0)
    rows = np.stack(np.meshgrid(along, lines), -1).reshape(-1, 2)
    columns = np.stack(np.meshgrid(lines, along), -1).reshape(-1, 2)
    save("street1e6.xy", np.concatenate([rows, columns[columns[:, 1] % 10 != 0]]))


def main() -> None:
    args = sys.argv[1:]
    if len(args) not in (1, 2) or (len(args) == 2 and args[0] != "--no-curve"):
        sys.exit(__doc__)
    out = Path(args[-1])
    out.mkdir(parents=True, exist_ok=True)
    if len(args) == 2:
        no_curve(out)
        return
    np.savetxt(out / "even1e6.xy", sample(10**6, 0.1, 0.0, 5), fmt="%.10f")
    np.savetxt(out / "noisy1e5.xy", sample(10**5, 0.3, 0.25, 11), fmt="%.10f")
    np.savetxt(out / "network1e6.xy", warped_grid(229, 10, 13), fmt="%.10f")


if __name__ == "__main__":
    main()
