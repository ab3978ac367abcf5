"""Scores every method, and ``shapely.concave_hull``, on a folder of outlines with true
polygons (``data/outlines``) as a user would judge them (issue 29), and writes
``report.md`` and ``results.csv`` to OUT_DIR.

Run from the repository root after ``make py-build`` (``make report`` does both)::

    .venv/bin/python python/bench/outline_scores.py data/outlines docs/report/outlines

Per result:

- **IoU**: area of (result region AND true region) over area of (result OR true), regions
  read even-odd (nested loops are holes; an open path is closed by its chord);
- **topology right**: as many polygons and as many holes as the truth;
- **Hausdorff / s**: the symmetric Hausdorff distance between the result's edges and the
  true outline, over the sample spacing ``s`` of the case;
- **warned**: the result said it may be wrong (``rec.warns``: a warning status or a finding
  of the sampling check); ``concave-hull`` never warns;
- **good**: topology right and IoU >= 0.95; **silent wrong**: not good and not warned.
"""

from __future__ import annotations

import csv
import statistics
import sys
import time
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import shapely
import sigdt
from outline_data import region, rings_of
from shapely.geometry import MultiLineString

CONCAVE_HULL_RATIO = 0.05
GOOD_IOU = 0.95
LISTED = 20


def read_folder(folder: Path) -> list[dict[str, Any]]:
    with open(folder / "index.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        name = row["name"]
        row["points"] = np.loadtxt(folder / f"{name}.xy", ndmin=2)
        truth = np.loadtxt(folder / f"{name}.curve.xy", ndmin=2)
        edges = np.loadtxt(folder / f"{name}.curve.gt", dtype=np.int64, ndmin=2)
        row["truth_rings"] = rings_of(truth, edges)
        row["spacing"] = float(row["spacing"])
        gt = np.loadtxt(folder / f"{name}.gt", dtype=np.int64, ndmin=2)
        row["gt"] = {(int(a), int(b)) for a, b in gt}
        row["outliers"] = set(range(len(row["points"]))) - {int(v) for v in gt.ravel()}
    return rows


def topology(geometry: Any) -> tuple[int, int]:
    """(polygons, holes) of a region."""
    if geometry is None or geometry.is_empty:
        return (0, 0)
    parts = [g for g in getattr(geometry, "geoms", [geometry]) if g.geom_type == "Polygon"]
    return (len(parts), sum(len(p.interiors) for p in parts))


def score(rings: list[np.ndarray], edges: list[np.ndarray], case: dict[str, Any]) -> dict[str, Any]:
    truth = region(case["truth_rings"])
    result = region(rings)
    iou = 0.0
    if result is not None and not result.is_empty:
        union = result.union(truth).area
        iou = result.intersection(truth).area / union if union > 0 else 0.0
    lines = MultiLineString([e for e in edges if len(e) >= 2])
    truth_lines = MultiLineString([np.vstack([r, r[:1]]) for r in case["truth_rings"]])
    hausdorff = shapely.hausdorff_distance(lines, truth_lines) if not lines.is_empty else np.inf
    right = topology(result) == topology(truth)
    return {"iou": iou, "topology": right, "hausdorff": hausdorff / case["spacing"]}


def run_sigdt(method: str, cases: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for case in cases:
        points = case["points"]
        start = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", sigdt.SigdtWarning)
            rec = sigdt.reconstruct(points, method=method)
        seconds = time.perf_counter() - start
        vertices = rec.vertices
        rings = [vertices[loop] for loop in rec.loops] + [vertices[p] for p in rec.paths]
        edges = [vertices[np.r_[loop, loop[:1]]] for loop in rec.loops]
        edges += [vertices[p] for p in rec.paths]
        row = score(rings, edges, case)
        found = {(int(a), int(b)) for a, b in rec.edges}
        listed = {int(i) for i, why in zip(rec.left_out, rec.left_out_reasons) if why == "outlier"}
        row.update(
            warned=bool(rec.warns),
            status=rec.status,
            seconds=seconds,
            exact=found == case["gt"],
            listed=len(listed & case["outliers"]),
            curve_listed=len(listed - case["outliers"]),
        )
        out.append(row)
    return out


def run_concave_hull(cases: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for case in cases:
        start = time.perf_counter()
        hull = shapely.concave_hull(shapely.MultiPoint(case["points"]), CONCAVE_HULL_RATIO)
        seconds = time.perf_counter() - start
        parts = [g for g in getattr(hull, "geoms", [hull]) if g.geom_type == "Polygon"]
        rings = [np.asarray(r.coords)[:-1] for p in parts for r in [p.exterior, *p.interiors]]
        edges = [np.asarray(r.coords) for p in parts for r in [p.exterior, *p.interiors]]
        row = score(rings, edges, case)
        row.update(
            warned=False, status="hull", seconds=seconds, exact=False, listed=0, curve_listed=0
        )
        out.append(row)
    return out


def percent(part: int, whole: int) -> str:
    return f"{100 * part / whole:.1f}" if whole else "-"


def report(results: dict[str, list[dict[str, Any]]], cases: list[dict[str, Any]]) -> str:
    categories = sorted({c["category"] for c in cases})
    lines = [
        "# Outlines as a user would judge them",
        "",
        (
            "`python/bench/outline_scores.py` on `data/outlines` (real outlines of `data/real`, "
            "resampled at spacing s with +-0.3 s jitter along them: clean, Gaussian noise of "
            "0.1 s and 0.25 s, and 1-3 % outliers farther than 2 s from the outline; "
            f"{len(cases)} cases). Per method and category:"
        ),
        "",
        "- **good**: topology right (as many polygons and holes as the truth) and IoU >= 0.95;",
        (
            "- **silent wrong**: not good, and the result did not warn (`rec.warns`: a warning "
            "status or a finding of the sampling check, `docs/sampling-check.md`); "
            "`concave-hull` never warns;"
        ),
        "- **warned, good**: warnings on good results (false alarms on clean cases);",
        (
            "- **IoU**, **H/s**: medians of IoU and of the Hausdorff distance to the true outline "
            "over the spacing."
        ),
        "",
    ]
    for metric in ("good", "silent wrong", "warned, good", "IoU", "H/s"):
        lines += [f"## {metric}", "", "| method | " + " | ".join(categories) + " |"]
        lines.append("|---|" + "--:|" * len(categories))
        for method, rows in results.items():
            cells = []
            for category in categories:
                sel = [r for r, c in zip(rows, cases) if c["category"] == category]
                good = [r["topology"] and r["iou"] >= GOOD_IOU for r in sel]
                if metric == "good":
                    cells.append(percent(sum(good), len(sel)))
                elif metric == "silent wrong":
                    silent = sum(1 for r, g in zip(sel, good) if not g and not r["warned"])
                    cells.append(percent(silent, len(sel)))
                elif metric == "warned, good":
                    cells.append(
                        percent(sum(1 for r, g in zip(sel, good) if g and r["warned"]), sum(good))
                    )
                elif metric == "IoU":
                    cells.append(f"{statistics.median(r['iou'] for r in sel):.3f}")
                else:
                    cells.append(f"{statistics.median(r['hausdorff'] for r in sel):.2f}")
            lines.append(f"| {method} | " + " | ".join(cells) + " |")
        lines.append("")
    lines += [
        "## Warned while good: exact?",
        "",
        (
            "A result can be good by IoU and topology and still have wrong edges; the sampling "
            "check warns about those. Warned good results, and how many of them are exact:"
        ),
        "",
    ]
    for method, rows in results.items():
        warned_good = [r for r in rows if r["topology"] and r["iou"] >= GOOD_IOU and r["warned"]]
        if warned_good:
            exact = sum(r["exact"] for r in warned_good)
            lines.append(f"- {method}: {len(warned_good)} warned good results, {exact} exact")
    outlier_cases = [c for c in cases if c["outliers"]]
    total = sum(len(c["outliers"]) for c in outlier_cases)
    lines += [
        "",
        "## Outliers listed",
        "",
        (
            f"Of the {total} outliers of the {len(outlier_cases)} outlier cases: how many each "
            "method lists as `outlier`, and how many curve samples it lists as outliers."
        ),
        "",
        "| method | outliers listed | % | curve samples listed |",
        "|---|--:|--:|--:|",
    ]
    for method, rows in results.items():
        listed = sum(r["listed"] for r, c in zip(rows, cases) if c["outliers"])
        wrong = sum(r["curve_listed"] for r in rows)
        if listed or wrong:
            lines.append(f"| {method} | {listed} | {percent(listed, total)} | {wrong} |")
    lines += ["", "## Silent wrong results", ""]
    for method, rows in results.items():
        silent = [
            f"{c['name']} (IoU {r['iou']:.3f}, {r['status']})"
            for r, c in zip(rows, cases)
            if not (r["topology"] and r["iou"] >= GOOD_IOU) and not r["warned"]
        ]
        if silent:
            shown = ", ".join(silent[:LISTED]) + (
                f", and {len(silent) - LISTED} more" if len(silent) > LISTED else ""
            )
            lines.append(f"- **{method}** ({len(silent)}): {shown}")
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    if len(argv) < 2:
        print(__doc__)
        return 2
    folder, out = Path(argv[0]), Path(argv[1])
    methods = argv[2].split(",") if len(argv) > 2 else list(sigdt.METHODS)
    cases = read_folder(folder)
    results: dict[str, list[dict[str, Any]]] = {}
    for method in methods:
        start = time.perf_counter()
        results[method] = run_sigdt(method, cases)
        print(f"{method}: {time.perf_counter() - start:.1f} s", file=sys.stderr)
    results["concave-hull"] = run_concave_hull(cases)
    out.mkdir(parents=True, exist_ok=True)
    (out / "report.md").write_text(report(results, cases))
    with open(out / "results.csv", "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(
            [
                "method",
                "name",
                "category",
                "iou",
                "topology_right",
                "hausdorff_over_s",
                "warned",
                "status",
                "seconds",
            ]
        )
        for method, rows in results.items():
            for r, c in zip(rows, cases):
                writer.writerow(
                    [
                        method,
                        c["name"],
                        c["category"],
                        f"{r['iou']:.4f}",
                        int(r["topology"]),
                        f"{r['hausdorff']:.3f}",
                        int(r["warned"]),
                        r["status"],
                        f"{r['seconds']:.4f}",
                    ]
                )
    print(f"wrote {out / 'report.md'} and {out / 'results.csv'}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
