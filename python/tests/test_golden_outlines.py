"""Golden lists of the *good* results on the labelled outline folders (issue 49).

``sigdt bench FOLDER --method sig-auto,connect2d`` (the release binary) judges every case:
its ``results.csv`` has a ``good`` column (right topology, IoU and Hausdorff distance
against ``NAME.curve.xy`` / ``NAME.gt``; the rule is the CLI's, in
``crates/sigdt-cli/src/bench/``). For every folder of :data:`FOLDERS` and method of
:data:`METHODS` this test checks two things:

- **The good cases, case by case**, against ``data/golden/FOLDER/METHOD.good`` (a ``#``
  header line, then one case name a line: the format of the ``.exact`` lists of
  ``crates/sigdt-lab/tests/golden.rs``), with the same ratchet:

  - a case lost (in the list, not good in the run) fails, with or without
    ``UPDATE_GOLDEN=1``, unless ``data/golden/FOLDER/METHOD.lost`` gives its reason: lines
    ``CASE  reason text``, ``#`` comments and blank lines allowed; a line without a reason
    fails, as does a case listed twice;
  - a ``.lost`` line for a case that is good in the run fails too (a stale reason: delete
    the line);
  - without ``UPDATE_GOLDEN``, a gain or a reviewed loss fails (the list is out of date);
    with ``UPDATE_GOLDEN=1`` the list is rewritten as the run's good cases (gains added,
    reviewed losses removed) and ``.lost`` keeps the reasons. Nothing is written while
    anything fails. A missing list fails; ``UPDATE_GOLDEN=1`` writes it.

- **A floor per category**: the good count of each category must stay at or above the
  floor in ``data/golden/FOLDER/floors.json``, ``{"METHOD": {"CATEGORY": FLOOR, ...}, ...}``
  (keys starting with ``#`` are comments). The floors are set by hand: ``UPDATE_GOLDEN=1``
  adds a missing method or category at the count reached and never changes a floor that is
  there, so lowering one is an edit of its own, reviewed with its reason. A floor naming a
  category the run does not have fails (a renamed category). The floors bound the total
  loss that reviewed ``.lost`` entries can add up to.

A folder that does not exist is skipped, visibly (``pytest -rs`` names it); a folder that
exists but cannot be benchmarked fails. The bench runs once per folder (``--repeat 1``:
times do not matter here); on 2 cores it takes 8 to 15 s on ``data/outlines`` (300 cases,
two methods) and about 25 s on ``data/vertices`` (1374 cases).
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "data" / "golden"

#: The labelled folders under data/ with golden lists of good results.
FOLDERS = ("outlines", "vertices")
#: The methods whose good cases are kept.
METHODS = ("sig-auto", "connect2d")
CASES = [(folder, method) for folder in FOLDERS for method in METHODS]


def updating() -> bool:
    return bool(os.environ.get("UPDATE_GOLDEN"))


# --- the ratchet (the rules of crates/sigdt-lab/tests/golden.rs) ----------------------------


def read_names(text: str) -> set[str]:
    """The case names of a golden list: its lines but ``#`` comments and blank lines."""
    lines = (line.strip() for line in text.splitlines())
    return {line for line in lines if line and not line.startswith("#")}


def read_lost(text: str, shown: str) -> dict[str, str]:
    """The reasons of a ``.lost`` file by case; a ``ValueError`` names ``shown:LINE``."""
    reasons: dict[str, str] = {}
    for number, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        case, reason = (line.split(None, 1) + [""])[:2]
        reason = reason.strip()
        if not reason:
            raise ValueError(f"{shown}:{number}: '{case}' has no reason; write 'CASE  why'")
        if case in reasons:
            raise ValueError(f"{shown}:{number}: '{case}' is listed twice")
        reasons[case] = reason
    return reasons


def ratchet(
    stored: set[str], reasons: dict[str, str], run: set[str], shown: str, update: bool
) -> str | None:
    """The failure message of the list ``SHOWN.good`` against the run's good cases, or None
    when it passes (with ``update``: when the list may be rewritten)."""
    lost = sorted(stored - run)
    unexplained = [c for c in lost if c not in reasons]
    reviewed = [c for c in lost if c in reasons]
    stale = sorted(c for c in reasons if c in run)
    gained = sorted(run - stored)
    message = ""
    if unexplained:
        lines = "".join(f"    {c}  <reason>\n" for c in unexplained)
        message += (
            f"{shown}: {len(unexplained)} case(s) no longer good, with no reason given.\n"
            f"  If the loss is accepted, write why in {shown}.lost, one line per case:\n"
            f"{lines}  then rerun with UPDATE_GOLDEN=1 to remove them from {shown}.good.\n"
        )
    if stale:
        message += (
            f"{shown}.lost: {len(stale)} case(s) good again, so their reason is stale: "
            f"{', '.join(stale)}\n  Delete their lines from {shown}.lost.\n"
        )
    out_of_date = bool(reviewed or gained)
    if not message and (update or not out_of_date):
        return None
    if out_of_date:
        advice = (
            "UPDATE_GOLDEN=1 rewrites it once the failures above are fixed."
            if message
            else "If the change is intended, rerun with UPDATE_GOLDEN=1 and review the diff."
        )
        message += (
            f"{shown}.good is out of date:\n  gained ({len(gained)}): {gained}\n"
            f"  lost, with a reason in {shown}.lost ({len(reviewed)}): {reviewed}\n  {advice}\n"
        )
    return message


def list_text(folder: str, method: str, good: set[str]) -> str:
    header = (
        f"# Cases of data/{folder} that {method} reconstructs well (column good of sigdt "
        f"bench's results.csv; {len(good)} of them); checked by "
        "python/tests/test_golden_outlines.py, rewritten with UPDATE_GOLDEN=1.\n"
    )
    return header + "".join(f"{name}\n" for name in sorted(good))


# --- the bench run -------------------------------------------------------------------------


@pytest.fixture(scope="module")
def bench(cli, tmp_path_factory):
    """``folder -> {method -> {case: (category, good)}}``, one bench run per folder."""
    runs: dict[str, dict[str, dict[str, tuple[str, bool]]]] = {}

    def run(folder: str) -> dict[str, dict[str, tuple[str, bool]]]:
        data = ROOT / "data" / folder
        if not data.is_dir():
            pytest.skip(f"data/{folder} does not exist (yet): its golden lists are not checked")
        if folder not in runs:
            out = tmp_path_factory.mktemp(f"bench-{folder}")
            jobs = str(max(1, min(4, os.cpu_count() or 1)))
            command = [str(cli), "bench", str(data), "--method", ",".join(METHODS)]
            command += ["--out", str(out), "--repeat", "1", "--jobs", jobs]
            done = subprocess.run(command, capture_output=True, text=True, check=False)
            assert done.returncode == 0, f"{' '.join(command)} failed:\n{done.stderr}"
            runs[folder] = read_results(out / "results.csv")
        return runs[folder]

    return run


def read_results(path: Path) -> dict[str, dict[str, tuple[str, bool]]]:
    """``method -> {case: (category, good)}`` from the bench's ``results.csv``, read by
    column name."""
    with path.open(newline="", encoding="utf-8") as file:
        reader = csv.DictReader(file)
        missing = {"name", "category", "method", "good"} - set(reader.fieldnames or ())
        assert not missing, f"{path}: no column {sorted(missing)} in {reader.fieldnames}"
        results: dict[str, dict[str, tuple[str, bool]]] = {}
        for row in reader:
            good = row["good"].strip().lower() in {"1", "true", "yes"}
            results.setdefault(row["method"], {})[row["name"]] = (row["category"], good)
    return results


def method_run(bench, folder: str, method: str) -> dict[str, tuple[str, bool]]:
    results = bench(folder)
    assert method in results, f"sigdt bench data/{folder}: no rows for {method}"
    return results[method]


# --- the tests -------------------------------------------------------------------------------


@pytest.mark.parametrize(("folder", "method"), CASES)
def test_good_cases_match_the_golden_list(bench, folder, method):
    run = {name for name, (_, good) in method_run(bench, folder, method).items() if good}
    shown = f"data/golden/{folder}/{method}"
    path, lost = GOLDEN / folder / f"{method}.good", GOLDEN / folder / f"{method}.lost"
    if path.is_file():
        stored = read_names(path.read_text(encoding="utf-8"))
    elif updating():
        stored = set()
    else:
        pytest.fail(f"{shown}.good is missing (UPDATE_GOLDEN=1 writes it)", pytrace=False)
    try:
        reasons = read_lost(lost.read_text(encoding="utf-8"), f"{shown}.lost")
    except FileNotFoundError:
        reasons = {}
    except ValueError as e:
        pytest.fail(str(e), pytrace=False)
    failure = ratchet(stored, reasons, run, shown, updating())
    if failure:
        pytest.fail(failure, pytrace=False)
    text = list_text(folder, method, run)
    if updating() and (not path.is_file() or path.read_text(encoding="utf-8") != text):
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


@pytest.mark.parametrize(("folder", "method"), CASES)
def test_good_count_per_category_stays_above_its_floor(bench, folder, method):
    counts: Counter[str] = Counter()
    totals: Counter[str] = Counter()
    for category, good in method_run(bench, folder, method).values():
        counts[category] += good
        totals[category] += 1
    path = GOLDEN / folder / "floors.json"
    shown = f"data/golden/{folder}/floors.json"
    floors_file = json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
    floors = {c: f for c, f in floors_file.get(method, {}).items() if not c.startswith("#")}
    missing = sorted(set(totals) - set(floors))
    if missing and updating():
        floors_file.setdefault(
            "#",
            f"Good cases per category of data/{folder} that each method must keep "
            "(python/tests/test_golden_outlines.py); set by hand, never lowered silently.",
        )
        floors_file[method] = {**floors, **{c: counts[c] for c in missing}}
        floors_file[method] = dict(sorted(floors_file[method].items()))
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(floors_file, indent=2) + "\n", encoding="utf-8")
        floors = floors_file[method]
    table = "".join(
        f"  {c:<20} {counts[c]:>4} / {totals[c]:<4} floor {floors.get(c, '-')}\n"
        for c in sorted(totals)
    )
    problems = [f"{c}: no floor (UPDATE_GOLDEN=1 adds it)" for c in missing if c not in floors]
    problems += [f"{c}: a floor, but no case of this category" for c in floors if c not in totals]
    problems += [
        f"{c}: {counts[c]} good, below its floor {floor}"
        for c, floor in sorted(floors.items())
        if c in totals and counts[c] < floor
    ]
    if problems:
        pytest.fail(f"{shown}, {method}:\n  " + "\n  ".join(problems) + f"\n{table}", False)


# --- the ratchet's rules, on small sets -------------------------------------------------------


def test_the_ratchet_rules():
    stored = {"a", "b", "c"}

    def failure(reasons, run, update):
        return ratchet(stored, reasons, set(run), "data/golden/x/m", update)

    assert failure({}, "abc", False) is None
    assert failure({}, "abc", True) is None
    assert "gained (1)" in failure({}, "abcd", False)
    assert failure({}, "abcd", True) is None
    for update in (False, True):
        message = failure({}, "acd", update)
        assert "no reason given" in message and "    b  <reason>\n" in message
        assert "data/golden/x/m.lost" in message
    reasons = read_lost("# reviewed losses\n\nb   the new rule splits it\n", "m.lost")
    assert reasons == {"b": "the new rule splits it"}
    assert "out of date" in failure(reasons, "ac", False)
    assert failure(reasons, "ac", True) is None
    for update in (False, True):
        assert "stale: b" in failure(reasons, "abc", update)
    for text, error in [("b\n", "m.lost:1: 'b' has no reason"), ("# x\nb \t\n", "m.lost:2:")]:
        with pytest.raises(ValueError, match=error):
            read_lost(text, "m.lost")
    with pytest.raises(ValueError, match="listed twice"):
        read_lost("b why\nb\twhy not\n", "m.lost")
