"""The HTML viewer in a real browser: Debian's chromium driven by Python playwright.

The page for ``data/inputs/glyph_e_reversed.xy`` (with its ``.gt``) is opened from ``file://``;
the test toggles a layer, moves the step slider the way a user does (value + ``input``
event), and checks that the canvas is drawn, that the replay changes it, that the status
text follows, and that the page logs nothing, raises nothing and requests nothing but
itself. It also checks the page's data: the trace is replayed in Rust (the initial
boundary, and per step the triangle, the phase code and the boundary edges it toggles), so
the page's boundary after inflating and at the end must be the kernel's. Nothing is
downloaded at run time: a missing chromium or playwright fails the test with the command
that installs it.
"""

from __future__ import annotations

import io
import json
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

#: Debian's chromium (``apt-get install chromium``); $CHROMIUM overrides it.
CHROMIUM = Path(os.environ.get("CHROMIUM", "/usr/bin/chromium"))
CASE = "glyph_e_reversed"  # inflating (46 triangles) and sculpting (4) both have steps
NO_TRACE = "no trace (method has no inflating/sculpting)"
#: The page's boundary after s steps as sorted [i, j] pairs; the page is left at step 0.
BOUNDARY_AT = """(s) => {
  const trace = window.sigdtView.model.trace;
  trace.seek(s);
  const flat = trace.boundary();
  trace.seek(0);
  const edges = [];
  for (let k = 0; k < flat.length; k += 2) edges.push([flat[k], flat[k + 1]]);
  return edges.sort((p, q) => p[0] - q[0] || p[1] - q[1]);
}"""


def viewer_page(cli: Path, repo_root: Path, out: Path, *, trace: bool = True) -> Path:
    """Writes the viewer page of the bundled example to ``out`` with ``sigdt view``; without
    a trace, with a method that has no inflating or sculpting (CRUST)."""
    inputs = repo_root / "data" / "inputs"
    method = "sig-connect2d" if trace else "crust"
    run = subprocess.run(
        [cli, "view", inputs / f"{CASE}.xy", "--gt", inputs / f"{CASE}.gt"]
        + ["--method", method, "-o", out],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0 and out.is_file(), f"writing {out} failed:\n{run.stderr}"
    return out


@pytest.fixture(scope="module")
def pages(cli, repo_root, tmp_path_factory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("viewer")
    return {
        "trace": viewer_page(cli, repo_root, folder / "trace.html"),
        "no-trace": viewer_page(cli, repo_root, folder / "no-trace.html", trace=False),
    }


@pytest.fixture(scope="module")
def browser():
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.fail(
            "Python playwright is missing: install it with "
            "`.venv/bin/pip install playwright==1.65.2` (no browser download needed)",
            pytrace=False,
        )
    if not CHROMIUM.is_file():
        pytest.fail(
            f"chromium is missing at {CHROMIUM}: install it with `sudo apt-get install chromium` "
            "(or set CHROMIUM to a Chromium binary)",
            pytrace=False,
        )
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=str(CHROMIUM), args=["--no-sandbox"])
        yield browser
        browser.close()


class Page:
    """One page of the viewer, recording console messages, errors and requests."""

    def __init__(self, browser, path: Path):
        self.page = browser.new_page(viewport={"width": 1200, "height": 800})
        self.messages: list[str] = []
        self.requests: list[str] = []
        self.page.on("console", lambda m: self.messages.append(f"console.{m.type}: {m.text}"))
        self.page.on("pageerror", lambda e: self.messages.append(f"page error: {e}"))
        self.page.on("request", lambda r: self.requests.append(r.url))
        self.url = path.as_uri()
        self.page.goto(self.url)
        self.settle()

    def settle(self) -> None:
        """Waits until the frames requested so far are drawn."""
        self.page.evaluate("() => new Promise(r => requestAnimationFrame(() => setTimeout(r)))")

    def set_step(self, value: str) -> None:
        """Moves the slider as a user does: a new value, then an ``input`` event."""
        self.page.eval_on_selector(
            "#step",
            "(el, v) => { el.value = v === 'end' ? el.max : v;"
            " el.dispatchEvent(new Event('input', { bubbles: true })); }",
            value,
        )
        self.settle()

    def canvas(self) -> np.ndarray:
        from PIL import Image

        png = self.page.locator("#canvas").screenshot()
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))

    def text(self, selector: str) -> str:
        return self.page.inner_text(selector).strip()

    def check_quiet(self) -> None:
        assert self.messages == [], "the page logged or raised:\n" + "\n".join(self.messages)
        assert self.requests == [self.url], f"the page requested more than itself: {self.requests}"


def test_page_loads_nothing_from_elsewhere(pages):
    for path in pages.values():
        html = path.read_text(encoding="utf-8")
        for pattern, what in [
            (r"<script[^>]*\bsrc\s*=", "<script src=...>"),
            (r"<link[^>]*\bhref\s*=\s*[\"']?https?:", "<link href=http...>"),
            (r"url\(\s*[\"']?https?:", "url(http...)"),
        ]:
            assert re.search(pattern, html, re.IGNORECASE) is None, f"{path.name}: {what}"
        assert "@import" not in html


def page_data(path: Path) -> dict:
    """The JSON data embedded in a viewer page."""
    element = r'<script type="application/json" id="data">(.*?)</script>'
    found = re.search(element, path.read_text(encoding="utf-8"), re.DOTALL)
    assert found, f"{path.name}: no data element"
    return json.loads(found.group(1))


def test_page_data_carries_the_replay(pages):
    data = page_data(pages["trace"])
    trace = data["trace"]
    assert trace["phases"] == ["inflate", "pocket", "sculpt"]
    n, triangles = len(data["points"]), len(trace["triangles"])
    assert len(trace["initial_inside"]) == triangles
    assert trace["initial_boundary"] == sorted(trace["initial_boundary"])
    codes = [phase for _, phase, _ in trace["steps"]]
    inflate, pocket, sculpt = range(3)
    inflating, sculpting = codes[: trace["inflated_at"]], codes[trace["inflated_at"] :]
    assert inflate in inflating and set(inflating) <= {inflate, pocket}
    assert sculpting and set(sculpting) == {sculpt}
    for t, _, toggled in trace["steps"]:
        assert 0 <= t < triangles
        assert toggled and toggled == sorted(toggled), "a step toggles sorted edges"
        assert all(0 <= i < j < n for i, j in toggled)
    assert set(data["layers"]) == {"dt", "sigdt", "sigdt2", "boundary", "result", "gt"}
    assert page_data(pages["no-trace"])["trace"] is None


def test_replay_in_the_browser(browser, pages):
    view = Page(browser, pages["trace"])
    page = view.page
    assert CASE in page.title()
    assert view.text("#status") == "initial"
    start = view.canvas()
    assert (start != start[0, 0]).any(), "the canvas is blank"

    page.click("#dt")
    view.settle()
    assert page.is_checked("#dt")
    with_dt = view.canvas()
    assert (with_dt != start).any(), "showing the DT changed nothing"

    view.set_step("end")
    assert view.text("#status") == "final"
    end = view.canvas()
    assert (end != end[0, 0]).any(), "the canvas is blank at the end"
    assert (end != with_dt).any(), "the first and last steps look the same"

    # One step back with the arrow key, then forward with the button.
    page.locator("#canvas").click()
    page.keyboard.press("ArrowLeft")
    view.settle()
    assert re.fullmatch(r"(sculpt|inflate) \d+/\d+|pocket", view.text("#status"))
    page.click("#forward")
    view.settle()
    assert view.text("#status") == "final"
    view.set_step("0")
    assert view.text("#status") == "initial"
    # The page only applies the kernel's steps: its boundary after inflating is the
    # "boundary" layer, and at the end it is the result (a polygon).
    data = page_data(pages["trace"])
    trace = data["trace"]
    assert page.evaluate(BOUNDARY_AT, 0) == trace["initial_boundary"]
    assert page.evaluate(BOUNDARY_AT, trace["inflated_at"]) == data["layers"]["boundary"]
    assert page.evaluate(BOUNDARY_AT, len(trace["steps"])) == data["layers"]["result"]
    page.mouse.move(5, 5)  # off the canvas: no point is highlighted
    view.settle()
    assert (view.canvas() == with_dt).all(), "step 0 looks different after the replay"
    view.check_quiet()
    page.close()


def test_page_without_a_trace(browser, pages):
    view = Page(browser, pages["no-trace"])
    page = view.page
    assert view.text("#status") == NO_TRACE
    assert page.is_disabled("#step")
    assert page.is_disabled("#interior")
    canvas = view.canvas()
    assert (canvas != canvas[0, 0]).any(), "the canvas is blank"
    page.click("#sig")
    view.settle()
    assert (view.canvas() != canvas).any(), "showing the SIG circles changed nothing"
    view.check_quiet()
    page.close()
