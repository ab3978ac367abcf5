"""Scores every method on labelled networks: exact rate, edge precision / recall / F1, and
junctions found right (issue 33). Writes a Markdown table.

Run from the repository root after ``make build`` (``make report`` runs it)::

    .venv/bin/python python/bench/network_scores.py data/non-manifold data/networks \\
        --out docs/report/networks/scores.md

Each case is reconstructed by ``target/release/sigdt reconstruct CASE.xy --method M``.
Edge precision and recall are summed over the cases of a folder (edges right over output
edges, and over ground-truth edges). A junction is a ground-truth vertex of degree 3 or more;
the output finds it right when the same vertex has the same degree there. Junction precision
is junctions found right over the output's vertices of degree 3 or more, recall over the
ground truth's. A folder whose ``index.csv`` has a ``half`` column (``design`` /
``held-out``, split by source item: ``data/networks``) is scored on all its cases and on
each half, in rows side by side.

Beside the table it writes ``scores.json`` (the counts and the scores of every row, for the
figures the README quotes: ``python/tests/test_published_numbers.py``)::

    {"folders": ["data/non-manifold", "data/networks"], "rows": [
      {"method": "emst", "category": "data/networks", "half": "all", "cases": 120,
       "exact": 27, "edges_right": ..., "edge_p": 0.9, "edge_r": 0.9, "edge_f1": 0.9,
       "junctions": ..., "junctions_found": ..., "junctions_right": ...,
       "junction_p": null, "junction_r": 0.7}, ...]}
"""

from __future__ import annotations

import argparse
import csv
import json
import subprocess
import sys
from collections import Counter
from pathlib import Path

import sigdt
from release_binary import cli_binary

# The methods that move the points or place their own vertices have no edges to score.
METHODS = [m for m in sigdt.METHODS if m not in ("stretch-denoise", "optimal-transport")]


def labelled_cases(folder: Path, script: str) -> list[Path]:
    """The cases NAME.xy of `folder`, each with its NAME.gt; exits naming what is wrong."""
    cases = sorted(folder.glob("*.xy"))
    unlabelled = [xy for xy in cases if not xy.with_suffix(".gt").is_file()]
    if not cases or unlabelled:
        what = f"{unlabelled[0].name} has no .gt" if unlabelled else "no NAME.xy files"
        sys.exit(f"{script}: {folder}: {what} (each case is NAME.xy with NAME.gt)")
    return cases


def edges_of(text: str) -> set[tuple[int, int]]:
    pairs = (line.split() for line in text.splitlines() if line.strip() and line[0] != "#")
    return {(min(int(a), int(b)), max(int(a), int(b))) for a, b in pairs}


def degrees(edges: set[tuple[int, int]]) -> Counter:
    count: Counter = Counter()
    for a, b in edges:
        count[a] += 1
        count[b] += 1
    return count


def halves_of(folder: Path) -> dict[str, str]:
    """The `half` column of `folder`'s `index.csv` by case name; empty when it has none."""
    index = folder / "index.csv"
    if not index.is_file():
        return {}
    with open(index, newline="", encoding="utf-8-sig") as f:
        rows = list(csv.DictReader(f))
    return {row["name"]: row["half"].strip() for row in rows if (row.get("half") or "").strip()}


def score(cli: Path, folder: Path, method: str) -> dict[str, Counter]:
    """The counts of `method` on `folder`, by case name."""
    per_case: dict[str, Counter] = {}
    for xy in sorted(folder.glob("*.xy")):
        total: Counter = Counter()
        per_case[xy.stem] = total
        truth = edges_of(xy.with_suffix(".gt").read_text())
        run = subprocess.run(
            [str(cli), "reconstruct", str(xy), "--format", "edges", "--method", method],
            capture_output=True,
            text=True,
            check=True,
        )
        found = edges_of(run.stdout)
        true_degree, found_degree = degrees(truth), degrees(found)
        true_junctions = {v for v, d in true_degree.items() if d >= 3}
        found_junctions = {v for v, d in found_degree.items() if d >= 3}
        total["cases"] += 1
        total["exact"] += found == truth
        total["right"] += len(found & truth)
        total["output"] += len(found)
        total["truth"] += len(truth)
        total["junctions"] += len(true_junctions)
        total["found"] += len(found_junctions)
        total["found_right"] += sum(found_degree[v] == true_degree[v] for v in true_junctions)
    return per_case


def row(method: str, half: str | None, t: Counter) -> str:
    """One table row: `method`'s scores summed into `t` (over the half `half`, if any)."""
    p, r = t["right"] / max(t["output"], 1), t["right"] / max(t["truth"], 1)
    f1 = 2 * p * r / (p + r) if p + r else 0.0
    cells = [f"`{method}`", *([half] if half is not None else [])]
    cells += [
        f"{100 * t['exact'] / max(t['cases'], 1):.1f} % ({t['exact']}/{t['cases']})",
        f"{p:.3f}",
        f"{r:.3f}",
        f"{f1:.3f}",
        ratio(t["found_right"], t["found"]),
        ratio(t["found_right"], t["junctions"]),
    ]
    return "| " + " | ".join(cells) + " |"


def half_summary(name: str, cases: list[Path], half_of: dict[str, str]) -> str:
    """`name`'s count of cases and of source networks (drawn and `_smooth` are one)."""
    stems = [xy.stem for xy in cases if half_of.get(xy.stem) == name]
    items = {stem.removesuffix("_smooth") for stem in stems}
    return f"`{name}`: {len(stems)} cases from {len(items)} networks"


def json_row(method: str, folder: Path, half: str, t: Counter) -> dict:
    """The counts and scores of `method` on `folder`'s cases of `half` (summed into `t`)."""
    p, r = t["right"] / max(t["output"], 1), t["right"] / max(t["truth"], 1)
    return {
        "method": method,
        "category": folder.as_posix(),
        "half": half,
        "cases": t["cases"],
        "exact": t["exact"],
        "edges_right": t["right"],
        "edges_output": t["output"],
        "edges_truth": t["truth"],
        "edge_p": p,
        "edge_r": r,
        "edge_f1": 2 * p * r / (p + r) if p + r else 0.0,
        "junctions": t["junctions"],
        "junctions_found": t["found"],
        "junctions_right": t["found_right"],
        "junction_p": t["found_right"] / t["found"] if t["found"] else None,
        "junction_r": t["found_right"] / t["junctions"] if t["junctions"] else None,
    }


def ratio(a: int, b: int) -> str:
    return f"{a / b:.3f}" if b else "–"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", type=Path)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    cli = cli_binary()
    lines = [
        "# Networks: edges and junctions",
        "",
        "Written by `python/bench/network_scores.py` (`make report`). Exact: output equals the",
        "ground truth. Edge P / R / F1: summed over the cases. Junctions: ground-truth vertices",
        "of degree 3 or more; found right when the output gives the same vertex the same",
        "degree. Junction P: found right over the output's vertices of degree 3 or more;",
        "R: over the ground truth's.",
        "",
    ]
    rows: list[dict] = []
    for folder in args.folders:
        cases = labelled_cases(folder, "network_scores")
        half_of = halves_of(folder)
        names = sorted({half_of.get(xy.stem, "") for xy in cases} - {""})
        lines += [f"## `{folder.as_posix()}`", ""]
        if names:
            lines += [
                "Halves: the `half` column of `index.csv`, split by source item (both cases of",
                "a network in one half); rules are designed on `design`, `held-out` checks them.",
                "Rows `all` score every case. "
                + "; ".join(half_summary(name, cases, half_of) for name in names)
                + ".",
                "",
                "| method | half | exact | edge P | edge R | edge F1 | junction P | junction R |",
                "| :-- | :-- | --: | --: | --: | --: | --: | --: |",
            ]
        else:
            lines += [
                "| method | exact | edge P | edge R | edge F1 | junction P | junction R |",
                "| :-- | --: | --: | --: | --: | --: | --: |",
            ]
        for method in METHODS:
            per_case = score(cli, folder, method)
            rows.append(json_row(method, folder, "all", sum(per_case.values(), Counter())))
            for name in names:
                part = [t for case, t in per_case.items() if half_of.get(case) == name]
                rows.append(json_row(method, folder, name, sum(part, Counter())))
            if not names:
                lines.append(row(method, None, sum(per_case.values(), Counter())))
                continue
            lines.append(row(method, "all", sum(per_case.values(), Counter())))
            for name in names:
                part = [t for case, t in per_case.items() if half_of.get(case) == name]
                lines.append(row(method, name, sum(part, Counter())))
        lines.append("")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(lines))
    folders = [folder.as_posix() for folder in args.folders]
    body = ",\n".join(f"    {json.dumps(r)}" for r in rows)
    args.out.with_suffix(".json").write_text(
        f'{{\n  "folders": {json.dumps(folders)},\n  "rows": [\n{body}\n  ]\n}}\n'
    )


if __name__ == "__main__":
    main()
