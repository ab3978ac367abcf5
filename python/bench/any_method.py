"""Which cases of a labelled folder some method gets right, and how often SIG-AUTO is one
of them (issue 44's target: SIG-AUTO good on at least 95 % of the cases that any method
gets good, per category and half).

Run after ``sigdt bench DIR --out OUT`` (``make report`` does both)::

    .venv/bin/python python/bench/any_method.py OUT/results.csv --out OUT/any-method.md

Reads ``results.csv`` (columns ``name``, ``category``, ``method``, ``good``, ``half``) and
writes a Markdown table per category and half: the cases, how many some method gets good,
how many SIG-AUTO gets good of those, and the cases no method gets good (the hard cases,
kept in every denominator of the report).
"""

from __future__ import annotations

import argparse
import csv
import sys
from collections import defaultdict
from pathlib import Path


def summarise(rows: list[dict[str, str]], method: str) -> tuple[list[list[str]], list[str]]:
    """Table rows (category, half, cases, any good, method good of those, share) and the
    names no method gets good."""
    good: dict[str, set[str]] = defaultdict(set)
    key: dict[str, tuple[str, str]] = {}
    for row in rows:
        key[row["name"]] = (row["category"], row.get("half", ""))
        if row["good"] in ("1", "true"):
            good[row["name"]].add(row["method"])
    groups: dict[tuple[str, str], list[str]] = defaultdict(list)
    for name, group in key.items():
        groups[group].append(name)
        groups[(group[0], "all")].append(name)
    table, nobody = [], sorted(n for n in key if not good[n])
    for (category, half), names in sorted(groups.items()):
        if half == "":
            continue
        anyone = [n for n in names if good[n]]
        ours = sum(method in good[n] for n in anyone)
        share = f"{100 * ours / len(anyone):.1f} %" if anyone else "–"
        table.append([category, half, str(len(names)), str(len(anyone)), str(ours), share])
    return table, nobody


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", type=Path, help="results.csv of sigdt bench")
    parser.add_argument("--out", type=Path, required=True, help="the Markdown file to write")
    parser.add_argument("--method", default="sig-auto", help="the method to measure (sig-auto)")
    args = parser.parse_args(argv)
    try:
        with open(args.results, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as err:
        print(f"any_method.py: {args.results}: {err.strerror}", file=sys.stderr)
        return 2
    missing = {"name", "category", "method", "good"} - set(rows[0] if rows else {})
    if missing:
        print(f"any_method.py: {args.results}: no column {sorted(missing)}", file=sys.stderr)
        return 2
    table, nobody = summarise(rows, args.method)
    lines = [
        f"# Cases some method gets good, and {args.method}'s share of them",
        "",
        f"From `{args.results}`. Good: topology right, IoU ≥ 0.95 and Hausdorff within bound.",
        "",
        f"| category | half | cases | some method good | {args.method} good of those | share |",
        "| :-- | :-- | --: | --: | --: | --: |",
        *("| " + " | ".join(r) + " |" for r in table),
        "",
        f"## No method good ({len(nobody)} cases, kept in every count)",
        "",
        *(f"- `{n}`" for n in nobody),
        "",
    ]
    args.out.write_text("\n".join(lines))
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
