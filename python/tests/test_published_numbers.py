"""Figures quoted in README.md and docs/**/*.md cannot go stale (issue 49).

``make report`` runs ``sigdt bench`` on each labelled folder, which writes ``numbers.json``
next to its ``report.md``: ``docs/report/numbers.json`` (data/curves),
``docs/report/real/numbers.json``, ``docs/report/outlines/numbers.json``, ... Each holds
``{"folder": ..., "rows": [{"method", "category", "half", "cases", "exact", "good", ...}]}``,
one row per (method, category, half), with category ``all`` and half ``all`` rows too.

A figure quoted in the prose says where it comes from with a marker: an HTML comment
(invisible once rendered) right after the figure, on the same line::

    96.0 %<!-- outlines: sig-auto outline-clean all good/cases -->
    72/75<!-- outlines: sig-auto outline-clean all good/cases -->
    72<!-- outlines: sig-auto outline-clean all good -->
    **0.96**<!-- real: sig-auto all all good/cases -->
    41<!-- curves: sig-auto "manifold eps<1" all exact -->

The marker is ``<!-- REPORT: METHOD CATEGORY HALF EXPR -->``:

- ``REPORT`` names ``docs/report/REPORT/numbers.json``; ``curves`` or ``.`` names
  ``docs/report/numbers.json`` itself; ``FOLDER/NAME`` names ``docs/report/FOLDER/NAME.json``
  (``networks/scores``: the edge and junction scores of ``python/bench/network_scores.py``,
  whose rows have the same keys ``method``, ``category``, ``half``). Any HTML comment whose text starts with ``WORD:`` is
  a marker, so other comments must not start that way (but ``unchecked: WHY``: see below).
- ``METHOD CATEGORY HALF`` pick exactly one row (``HALF`` is ``all``, ``design`` or
  ``held-out``); a token with spaces is quoted (``"manifold eps<1"``).
- ``EXPR`` is ``FIELD`` or ``FIELD/FIELD``, fields of that row.

The figure is the number just before the comment (bold, italic or code marks and spaces
between them are allowed; thousands may be grouped with commas). It is compared, as text,
with the file's value formatted to as many decimals as the figure has:

- ``FIELD``: a number (``72``, ``0.996``); a ``%`` after it is kept as written, so the field
  must already be a percentage.
- ``FIELD/FIELD``: a percentage ``96.0 %`` (100 * A / B), a fraction ``72/75`` (both A and
  B), or a plain number ``0.96`` (A / B).

A table copied from a report carries one marker, alone on the line before it::

    <!-- table curves: all exact/cases% manifold,sharp,open -->
    | method | manifold | sharp | open | mean ms |
    |---|--:|--:|--:|--:|
    | sig-connect2d | 95.5 | 75.0 | 0.0 | 0.12 |

``table REPORT: HALF EXPR COLUMNS`` (the column names separated by commas) checks, in every row of the table, the cells of the
named columns (each a category; other columns, such as times, are not checked) against the
row of the method its first cell names (its first word, without code marks). ``EXPR`` is
as above; ``FIELD/FIELD%`` says the cells are percentages written without their sign.

Every percentage of README.md and docs/*.md (not the generated docs/report/) is checked:
a marker follows it, or it sits in a table with a table marker, or its paragraph says why
no report holds it with ``<!-- unchecked: WHY -->`` (the paper's own figures, a profile, a
parameter of the data, a figure measured once at a past commit). A new percentage without
either fails ``test_every_percentage_in_readme_and_docs_is_checked_or_says_why_not``.
Counts written as words or as "N of M" are not found by that test: mark them all the same.

Rounding is Python's ``format`` (round half to even on the exact binary value), which is
Rust's too, so a figure copied from ``report.md`` matches. Markers inside fenced code blocks
and inline code spans are not checked (they are examples). The test fails, naming
``file:line``, the marker, the quoted figure and the file's, on a drifted figure, on a
marker naming a missing file, row or field (or a null field: a folder without true curves
has no curve figures), and on a malformed marker.
"""

from __future__ import annotations

import json
import re
import shlex
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

COMMENT = re.compile(r"<!--(.*?)-->")
MARKER = re.compile(r"^\s*(?P<report>[^\s:]+):(?P<rest>(?:\s.*)?)$", re.DOTALL)
REPORT = re.compile(r"^(?:\.|[A-Za-z0-9_-]+(?:/[A-Za-z0-9_-]+)?)$")
EXPR = re.compile(r"^(?P<a>[A-Za-z_]\w*)(?:/(?P<b>[A-Za-z_]\w*))?$")
NUMBER = r"[-\u2212]?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?"
FIGURE = re.compile(
    rf"(?<![\w.,/\u2212-])(?P<a>{NUMBER})(?:\s*/\s*(?P<b>{NUMBER}))?(?P<percent>\s*%)?"
    r"[*_`]*\s*$"
)
FENCE = re.compile(r"^ {0,3}(```|~~~)")
TABLE = re.compile(
    r"^\s*table\s+(?P<report>[^\s:]+):\s+(?P<half>\S+)\s+(?P<expr>\S+?)(?P<percent>%?)"
    r"\s+(?P<columns>\S.*?)\s*$"
)
CELL_MARKS = "*_` \t"


@dataclass(frozen=True)
class Marker:
    """A figure and the marker after it."""

    where: str  # file:line
    comment: str  # the comment as written
    figure: str  # the figure as written
    report: str
    row: tuple[str, str, str]  # method, category, half
    fields: tuple[str, ...]  # one field, or numerator and denominator


def scan(text: str, shown: str) -> tuple[list[Marker], list[str]]:
    """The markers of a Markdown text, and the problems of the malformed ones."""
    markers: list[Marker] = []
    problems: list[str] = []
    fenced = False
    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if fenced:
            continue
        table = TABLE.match(line.strip()[4:-3]) if line.strip().startswith("<!--") else None
        if table and line.strip().endswith("-->"):
            where = f"{shown}:{number}"
            try:
                markers += table_markers(table, text.splitlines()[number:], shown, number)
            except ValueError as e:
                problems.append(f"{where}: {line.strip()}: {e}")
            continue
        for comment in COMMENT.finditer(line):
            marker = MARKER.match(comment.group(1))
            if (
                not marker
                or line[: comment.start()].count("`") % 2
                or UNCHECKED.match(comment.group(0))
            ):
                continue
            where, written = f"{shown}:{number}", comment.group(0)
            try:
                markers.append(parse(line[: comment.start()], marker, where, written))
            except ValueError as e:
                problems.append(f"{where}: {written}: {e}")
    return markers, problems


def cells(line: str) -> list[str]:
    """The cells of a Markdown table row."""
    return [c.strip() for c in line.strip().strip("|").split("|")]


def table_markers(table: re.Match, after: list[str], shown: str, number: int) -> list[Marker]:
    """A marker for each checked cell of the table on the lines `after` a table marker (on
    line `number`); a ValueError says what is malformed."""
    report, half = table.group("report"), table.group("half")
    if not REPORT.match(report):
        raise ValueError(
            f"'{report}' is not a folder name under docs/report, FOLDER/NAME, 'curves' or '.'"
        )
    expr = EXPR.match(table.group("expr"))
    if not expr:
        raise ValueError(f"'{table.group('expr')}' is not FIELD or FIELD/FIELD")
    percent = " %" if table.group("percent") else ""
    if percent and not expr.group("b"):
        raise ValueError("a percentage needs FIELD/FIELD")
    rows = []
    for line in after:
        if not line.strip().startswith("|"):
            break
        rows.append(line)
    if len(rows) < 3:
        raise ValueError("no Markdown table on the lines right after it")
    header = cells(rows[0])
    columns = table.group("columns").split(",")
    missing = [c for c in columns if c not in header]
    if missing:
        raise ValueError(f"the table has no column {', '.join(map(repr, missing))}")
    markers = []
    for offset, line in enumerate(rows[2:], 3):
        row = cells(line)
        if len(row) != len(header):
            raise ValueError(
                f"line {number + offset} has {len(row)} cells, the header {len(header)}"
            )
        method = row[0].strip(CELL_MARKS).split()[0].strip(CELL_MARKS) if row[0].strip() else ""
        for column in columns:
            figure = row[header.index(column)].strip(CELL_MARKS)
            if not re.fullmatch(NUMBER, figure):
                raise ValueError(
                    f"line {number + offset}, column {column!r}: {figure!r} is no figure"
                )
            markers.append(
                Marker(
                    where=f"{shown}:{number + offset}",
                    comment=f"<!-- table {report}: {half} {table.group('expr')}{table.group('percent')} -->",
                    figure=figure + percent,
                    report=report,
                    row=(method, column, half),
                    fields=tuple(f for f in expr.group("a", "b") if f),
                )
            )
    return markers


def parse(before: str, marker: re.Match, where: str, written: str) -> Marker:
    """The marker `written` with the text `before` it on its line; a ValueError says what is
    malformed."""
    report = marker.group("report")
    if not REPORT.match(report):
        raise ValueError(
            f"'{report}' is not a folder name under docs/report, FOLDER/NAME, 'curves' or '.'"
        )
    try:
        tokens = shlex.split(marker.group("rest"))
    except ValueError as e:
        raise ValueError(f"cannot split it into words ({e})") from None
    if len(tokens) != 4:
        raise ValueError(
            f"{len(tokens)} word(s) after '{report}:', expected 4: METHOD CATEGORY HALF EXPR"
        )
    expr = EXPR.match(tokens[3])
    if not expr:
        raise ValueError(f"'{tokens[3]}' is not FIELD or FIELD/FIELD")
    figure = FIGURE.search(before)
    if not figure:
        raise ValueError("no figure right before the marker")
    if figure.group("b") and not expr.group("b"):
        raise ValueError(f"the fraction {figure.group(0).strip()} needs FIELD/FIELD")
    return Marker(
        where=where,
        comment=written,
        figure=figure.group(0).rstrip("*_` \t"),
        report=report,
        row=(tokens[0], tokens[1], tokens[2]),
        fields=tuple(f for f in expr.group("a", "b") if f),
    )


def numbers_path(root: Path, report: str) -> Path:
    folder = root / "docs" / "report"
    if report in {"curves", "."}:
        return folder / "numbers.json"
    if "/" in report:
        return folder / f"{report}.json"
    return folder / report / "numbers.json"


def load_rows(path: Path) -> dict[tuple[str, str, str], list[dict]]:
    """The rows of a numbers.json by (method, category, half)."""
    rows: dict[tuple[str, str, str], list[dict]] = {}
    for row in json.loads(path.read_text(encoding="utf-8"))["rows"]:
        key = (str(row.get("method")), str(row.get("category")), str(row.get("half")))
        rows.setdefault(key, []).append(row)
    return rows


def decimals(figure: str) -> int:
    return len(figure.split(".")[1]) if "." in figure else 0


def plain(figure: str) -> str:
    return figure.replace(",", "").replace("\u2212", "-")


def check(marker: Marker, root: Path, cache: dict[Path, dict | str]) -> str | None:
    """The problem of a marker, or None when the figure is the file's."""
    path = numbers_path(root, marker.report)
    shown = path.relative_to(root).as_posix() if path.is_relative_to(root) else str(path)
    head = f"{marker.where}: {marker.comment}: quoted {marker.figure!r}"
    if path not in cache:
        try:
            cache[path] = load_rows(path)
        except FileNotFoundError:
            cache[path] = f"{shown} does not exist (make report writes it)"
        except (ValueError, KeyError, TypeError) as e:
            cache[path] = f"{shown} is not a numbers file ({e})"
    if isinstance(cache[path], str):
        return f"{head}, but {cache[path]}"
    rows = cache[path].get(marker.row, [])
    if len(rows) != 1:
        what = "no row" if not rows else f"{len(rows)} rows"
        return f"{head}, but {shown} has {what} for method, category, half = {marker.row}"
    values = []
    for field in marker.fields:
        value = rows[0].get(field)
        if field not in rows[0]:
            return f"{head}, but the row of {shown} has no field '{field}'"
        if value is None:
            return f"{head}, but the field '{field}' is null in {shown}"
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return f"{head}, but the field '{field}' of {shown} is not a number: {value!r}"
        values.append(value)
    expected = figure_of(marker.figure, values)
    if expected is None:
        return f"{head}, but {'/'.join(marker.fields)} divides by zero in {shown}"
    quoted = re.sub(r"\s+", "", plain(marker.figure))
    if quoted != re.sub(r"\s+", "", expected):
        fields = "/".join(marker.fields)
        return f"{head}, {shown} gives {expected!r} ({fields} = {'/'.join(map(str, values))})"
    return None


def figure_of(figure: str, values: list) -> str | None:
    """The file's values written like `figure` (None on a division by zero)."""
    figure = plain(figure)
    if len(values) == 1:
        digits = decimals(figure.rstrip("% \t"))
        return f"{values[0]:.{digits}f}" + ("%" if figure.endswith("%") else "")
    a, b = values
    if "/" in figure:
        first, second = (part.strip() for part in figure.split("/"))
        return f"{a:.{decimals(first)}f}/{b:.{decimals(second)}f}"
    if b == 0:
        return None
    if figure.endswith("%"):
        return f"{100 * a / b:.{decimals(figure.rstrip('% '))}f}%"
    return f"{a / b:.{decimals(figure)}f}"


def documents(root: Path) -> list[Path]:
    """README.md and docs/**/*.md."""
    readme = [root / "README.md"] if (root / "README.md").is_file() else []
    return readme + sorted((root / "docs").rglob("*.md"))


def check_documents(root: Path) -> tuple[list[Marker], list[str]]:
    """Every marker of the documents under `root`, and every problem."""
    markers: list[Marker] = []
    problems: list[str] = []
    cache: dict[Path, dict | str] = {}
    for path in documents(root):
        found, malformed = scan(path.read_text(encoding="utf-8"), path.relative_to(root).as_posix())
        markers += found
        problems += malformed
        problems += [p for m in found if (p := check(m, root, cache))]
    return markers, problems


# --- figures without a marker -----------------------------------------------------------------

# A percentage (or a range of them) with no marker right after it.
PERCENTAGE = re.compile(
    rf"(?<![\w.]){NUMBER}(?:\s*[\u2013-]\s*{NUMBER})?\s*%(?![*_`\s]*<!--\s*[^\s:]+:)"
)
UNCHECKED = re.compile(r"<!--\s*unchecked:\s*\S[^>]*-->")


def hand_written(root: Path) -> list[Path]:
    """README.md and docs/*.md: the documents people write (docs/report/ is generated)."""
    readme = [root / "README.md"] if (root / "README.md").is_file() else []
    return readme + sorted((root / "docs").glob("*.md"))


def unmarked_percentages(text: str, shown: str) -> list[str]:
    """The percentages of a Markdown text that no marker checks, outside code, tables that
    carry a table marker and paragraphs that say why they are not checked
    (``<!-- unchecked: the paper's own figures -->``): one ``file:line: figure`` each."""
    found: list[str] = []
    paragraph: list[tuple[int, str]] = []
    fenced = False

    def close() -> None:
        lines = [line for _, line in paragraph]
        tabled = bool(lines) and TABLE.match(
            lines[0].strip()[4:-3] if lines[0].strip().startswith("<!--") else ""
        )
        if not any(UNCHECKED.search(line) for line in lines) and not tabled:
            for number, line in paragraph:
                prose = re.sub(r"`[^`]*`", "", line)
                found.extend(
                    [
                        f"{shown}:{number}: {m.group(0).strip()!r}"
                        for m in PERCENTAGE.finditer(prose)
                    ]
                )
        paragraph.clear()

    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            fenced = not fenced
            close()
            continue
        if fenced:
            continue
        if line.strip():
            paragraph.append((number, line))
        else:
            close()
    close()
    return found


def test_every_percentage_in_readme_and_docs_is_checked_or_says_why_not():
    found = [
        figure
        for path in hand_written(ROOT)
        for figure in unmarked_percentages(
            path.read_text(encoding="utf-8"), path.relative_to(ROOT).as_posix()
        )
    ]
    if found:
        pytest.fail(
            f"{len(found)} percentage(s) with no marker: give each a marker naming its "
            "numbers.json row, or put <!-- unchecked: WHY --> in its paragraph (the paper's "
            "figures, a profile, a parameter of the data):\n" + "\n".join(found),
            pytrace=False,
        )


@pytest.mark.parametrize(
    ("text", "unmarked"),
    [
        ("right on 96.0 %<!-- outlines: sig-auto outline-clean all good/cases -->.", []),
        ("right on **96.0 %**<!-- outlines: sig-auto outline-clean all good/cases -->.", []),
        ("right on 96.0 % of them.", ["doc.md:1: '96.0 %'"]),
        ("1\u20133 % outliers", ["doc.md:1: '1\u20133 %'"]),
        ("<!-- unchecked: the generator's parameters -->\n1\u20133 % outliers", []),
        ("the paper: 91.5 %\n<!-- unchecked: the paper's -->\n\nours: 95 %", ["doc.md:4: '95 %'"]),
        ("`95 %` in code", []),
        ("```\n95 %\n```", []),
        ("<!-- table outlines: all good/cases% a -->\n| m | a |\n|--|--|\n| x | 95 % |", []),
        ("| m | a |\n|--|--|\n| x | 95 % |", ["doc.md:3: '95 %'"]),
        ("95%<!-- a comment -->", ["doc.md:1: '95%'"]),
        ("95%<!-- unchecked: a parameter -->", []),
    ],
)
def test_unmarked_percentages_are_found(text, unmarked):
    assert unmarked_percentages(text, "doc.md") == unmarked


# --- the documents of the repository ---------------------------------------------------------


def test_published_figures_are_the_reports():
    markers, problems = check_documents(ROOT)
    if problems:
        pytest.fail(
            f"{len(problems)} of the published figures disagree with docs/report "
            f"({len(markers)} markers):\n" + "\n".join(problems),
            pytrace=False,
        )


# --- the marker syntax, on small texts --------------------------------------------------------

ROWS = {
    "folder": "data/outlines",
    "rows": [
        {
            "method": "sig-auto",
            "category": "outline-clean",
            "half": "all",
            "cases": 75,
            "exact": 71,
            "good": 72,
            "hausdorff": 0.12345,
        },
        {
            "method": "sig-auto",
            "category": "all",
            "half": "design",
            "cases": 150,
            "exact": 140,
            "good": 145,
            "hausdorff": None,
        },
        {
            "method": "sig-auto",
            "category": "manifold eps<1",
            "half": "all",
            "cases": 1000,
            "exact": 1,
            "good": 1187,
            "hausdorff": 0.5,
        },
        {"method": "crust", "category": "all", "half": "all", "cases": 0, "exact": 0, "good": 0},
    ],
}


@pytest.fixture
def root(tmp_path):
    """A repository with docs/report/outlines/numbers.json, docs/report/numbers.json and
    docs/report/networks/scores.json."""
    for folder in (tmp_path / "docs" / "report" / "outlines", tmp_path / "docs" / "report"):
        folder.mkdir(parents=True, exist_ok=True)
        (folder / "numbers.json").write_text(json.dumps(ROWS), encoding="utf-8")
    (tmp_path / "docs" / "report" / "networks").mkdir()
    scores = tmp_path / "docs" / "report" / "networks" / "scores.json"
    scores.write_text(json.dumps(ROWS), encoding="utf-8")
    return tmp_path


def problems_of(text: str, root: Path) -> list[str]:
    markers, problems = scan(text, "doc.md")
    cache: dict[Path, dict | str] = {}
    return problems + [p for m in markers if (p := check(m, root, cache))]


@pytest.mark.parametrize(
    "text",
    [
        "SIG-AUTO: 96.0 %<!-- outlines: sig-auto outline-clean all good/cases -->.",
        "| 96.0%<!-- outlines: sig-auto outline-clean all good/cases --> |",
        "96 %<!-- outlines: sig-auto outline-clean all good/cases -->",
        "96.00 % <!-- outlines: sig-auto outline-clean all good/cases -->",
        "**96.0 %**<!-- outlines: sig-auto outline-clean all good/cases -->",
        "72/75<!-- outlines: sig-auto outline-clean all good/cases -->",
        "good on 72 / 75<!-- outlines: sig-auto outline-clean all good/cases -->",
        "0.96<!-- outlines: sig-auto outline-clean all good/cases -->",
        "72<!-- outlines: sig-auto outline-clean all good -->",
        "`72`<!-- outlines: sig-auto outline-clean all good -->",
        "0.123<!-- outlines: sig-auto outline-clean all hausdorff -->",
        "1,187<!-- .: sig-auto 'manifold eps<1' all good -->",
        '1,187<!-- curves: sig-auto "manifold eps<1" all good -->',
        "96.7 %<!-- outlines: sig-auto all design good/cases -->",
        "72<!-- networks/scores: sig-auto outline-clean all good -->",
    ],
)
def test_a_right_figure_passes(text, root):
    assert problems_of(text, root) == []


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("95.9 %<!-- outlines: sig-auto outline-clean all good/cases -->", "gives '96.0%'"),
        ("71/75<!-- outlines: sig-auto outline-clean all good/cases -->", "gives '72/75'"),
        ("71<!-- outlines: sig-auto outline-clean all good -->", "gives '72'"),
        ("0.124<!-- outlines: sig-auto outline-clean all hausdorff -->", "(hausdorff = 0.12345)"),
        ("96.0 %<!-- vertices: sig-auto outline-clean all good/cases -->", "does not exist"),
        ("96.0 %<!-- outlines: sig-auto outline-noisy all good/cases -->", "has no row"),
        ("96.0 %<!-- outlines: sig-auto outline-clean all best/cases -->", "no field 'best'"),
        ("0.1<!-- outlines: sig-auto all design hausdorff -->", "is null"),
        ("0 %<!-- outlines: crust all all good/cases -->", "divides by zero"),
        ("96.0 %<!-- outlines: sig-auto outline-clean good/cases -->", "3 word(s)"),
        ("96.0 %<!-- outlines: sig-auto outline-clean all 100*good -->", "is not FIELD"),
        ("96.0 %<!-- outlines: sig-auto 'outline-clean all good -->", "cannot split"),
        ("about<!-- outlines: sig-auto outline-clean all good -->", "no figure"),
        ("72/75<!-- outlines: sig-auto outline-clean all good -->", "needs FIELD/FIELD"),
        ("72<!-- ../x: sig-auto outline-clean all good -->", "not a folder name"),
        ("72<!-- outlines/a/b: sig-auto outline-clean all good -->", "not a folder name"),
        ("72<!-- outlines/scores: sig-auto outline-clean all good -->", "scores.json does not"),
    ],
)
def test_a_drifted_or_broken_marker_fails(text, says, root):
    problems = problems_of(text, root)
    assert len(problems) == 1 and problems[0].startswith("doc.md:1: <!--"), problems
    assert says in problems[0], problems[0]


def test_the_problem_names_the_marker_and_both_figures(root):
    marker = "<!-- outlines: sig-auto outline-clean all good/cases -->"
    text = f"intro\n\nSIG-AUTO is good on 95.9 %{marker}\n"
    [problem] = problems_of(text, root)
    assert problem == (
        "doc.md:3: <!-- outlines: sig-auto outline-clean all good/cases -->: quoted '95.9 %', "
        "docs/report/outlines/numbers.json gives '96.0%' (good/cases = 72/75)"
    )


def test_other_comments_and_code_are_not_markers(root):
    text = (
        "<!-- a comment, not a marker -->\n"
        "`95.9 %<!-- outlines: sig-auto outline-clean all good/cases -->`\n"
        "```markdown\n"
        "95.9 %<!-- outlines: sig-auto outline-clean all good/cases -->\n"
        "```\n"
        "<!-- unchecked: the paper's figures -->\n"
        "<!--\n"
        "outlines: a comment over several lines\n"
        "-->\n"
    )
    assert scan(text, "doc.md") == ([], [])


def test_the_scan_finds_the_markers_of_readme_and_docs(root):
    (root / "README.md").write_text(
        "Good on 96.0 %<!-- outlines: sig-auto outline-clean all good/cases --> of the clean "
        "outlines, 72/75<!-- outlines: sig-auto outline-clean all good/cases -->.\n",
        encoding="utf-8",
    )
    (root / "docs" / "deep").mkdir()
    (root / "docs" / "deep" / "page.md").write_text(
        "# Page\n\n| 71<!-- outlines: sig-auto outline-clean all exact --> |\n"
        "| 70<!-- outlines: sig-auto outline-clean all good --> |\n",
        encoding="utf-8",
    )
    markers, problems = check_documents(root)
    assert [m.where for m in markers] == [
        "README.md:1",
        "README.md:1",
        "docs/deep/page.md:3",
        "docs/deep/page.md:4",
    ]
    assert [m.figure for m in markers] == ["96.0 %", "72/75", "71", "70"]
    assert len(problems) == 1 and problems[0].startswith("docs/deep/page.md:4: "), problems
    assert "quoted '70'" in problems[0] and "gives '72'" in problems[0]


def test_every_marker_on_a_missing_file_says_so(root):
    text = (
        "72<!-- vertices: sig-auto outline-clean all good -->\n"
        "75<!-- vertices: sig-auto outline-clean all cases -->\n"
    )
    problems = problems_of(text, root)
    assert len(problems) == 2, problems
    assert all("docs/report/vertices/numbers.json does not exist" in p for p in problems)


TABLE_TEXT = """intro

<!-- table outlines: all good/cases% outline-clean -->
| method | outline-clean | mean ms |
|---|--:|--:|
| `sig-auto` (the default) | **CELL** | 0.12 |
"""


def test_a_table_marker_checks_its_columns(root):
    assert problems_of(TABLE_TEXT.replace("CELL", "96.0"), root) == []
    assert problems_of(TABLE_TEXT.replace("CELL", "96"), root) == []
    [problem] = problems_of(TABLE_TEXT.replace("CELL", "95.9"), root)
    assert problem.startswith("doc.md:6: <!-- table outlines: all good/cases% -->: quoted '95.9 %'")
    assert "gives '96.0%'" in problem, problem


@pytest.mark.parametrize(
    ("marker", "says"),
    [
        ("<!-- table outlines: all good/cases% outline-noisy -->", "no column 'outline-noisy'"),
        ("<!-- table outlines: all good% outline-clean -->", "needs FIELD/FIELD"),
        ("<!-- table ../x: all good outline-clean -->", "not a folder name"),
        ("<!-- table outlines: all good/cases% mean -->", "no column 'mean'"),
        ("<!-- table outlines: all good/cases% mean s -->", "no column 'mean s'"),
        ("<!-- table outlines: all good/cases% outline-clean,mean s -->", "no column 'mean s'"),
    ],
)
def test_a_broken_table_marker_fails(marker, says, root):
    text = TABLE_TEXT.replace("CELL", "96.0").replace(
        "<!-- table outlines: all good/cases% outline-clean -->", marker
    )
    problems = problems_of(text, root)
    assert len(problems) == 1 and problems[0].startswith("doc.md:3: "), problems
    assert says in problems[0], problems[0]


def test_a_table_cell_that_is_no_figure_fails(root):
    [problem] = problems_of(TABLE_TEXT.replace("CELL", "–"), root)
    assert "column 'outline-clean': '–' is no figure" in problem, problem
