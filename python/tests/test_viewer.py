"""The HTML viewer in a real browser: Debian's chromium driven by Python playwright.

The page for ``data/inputs/glyph_e_reversed.xy`` (with its ``.gt``) is opened from ``file://``;
the tests toggle layers, move the step slider the way a user does (value + ``input``
event), and check that the page opens on the result in the colours of ``sigdt render`` and
``sigdt.plot``, that the replay changes the canvas, that the status text follows, that the
triangle of a step stays visible when it is a sliver, that the page is usable 420 pixels
wide, that the PNG and SVG exports are the current view, and that the page logs nothing,
raises nothing and requests nothing but itself. They also decode the page's data here, on
their own (base64 arrays, one bit per edge of the edge list): the coordinates must be the
input's exactly, and since the trace is replayed in Rust (the initial boundary, and per
step the triangle, the phase and the sides it toggles), the page's boundary after
inflating and at the end must be the kernel's. Nothing is downloaded at run time: a
missing chromium or playwright fails the test with the command that installs it.
"""

from __future__ import annotations

import base64
import io
import json
import os
import re
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import sigdt

#: Debian's chromium (``apt-get install chromium``); $CHROMIUM overrides it.
CHROMIUM = Path(os.environ.get("CHROMIUM", "/usr/bin/chromium"))
CASE = "glyph_e_reversed"  # inflating (46 triangles) and sculpting (4) both have steps
PALETTE = sigdt._core.PALETTE
NO_TRACE = "no trace (method has no inflating/sculpting)"
#: The page's boundary after s steps as sorted [i, j] pairs; the page is left where it was.
BOUNDARY_AT = """(s) => {
  const trace = window.sigdtView.model.trace;
  const was = trace.current;
  trace.seek(s);
  const flat = trace.boundary();
  trace.seek(was);
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
    """The JSON data embedded in a viewer page, decoded: arrays as numpy, edge layers and
    the boundary as sorted ``[i, j]`` lists, steps as ``(triangle, phase, toggled edges)``."""
    element = r'<script type="application/json" id="data">(.*?)</script>'
    found = re.search(element, path.read_text(encoding="utf-8"), re.DOTALL)
    assert found, f"{path.name}: no data element"
    data = json.loads(found.group(1))
    assert data["format"] == 2

    def array(text: str, dtype: str) -> np.ndarray:
        return np.frombuffer(base64.b64decode(text), dtype=np.dtype(dtype).newbyteorder("<"))

    def bits(text: str, count: int) -> np.ndarray:
        raw = np.frombuffer(base64.b64decode(text), dtype=np.uint8)
        assert len(raw) == (count + 7) // 8
        return np.unpackbits(raw, bitorder="little")[:count].astype(bool)

    n = data["n"]
    triangles = array(data["triangles"], "u4").reshape(-1, 3)
    sides = np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    extra = array(data["extra_edges"], "u4").reshape(-1, 2)
    edges = np.unique(np.r_[sides, extra].reshape(-1, 2), axis=0)  # the edge list, sorted

    def layer(text: str) -> list[list[int]]:
        return edges[bits(text, len(edges))].tolist()

    decoded = {
        "n": n,
        "points": array(data["points"], "f8").reshape(n, 2),
        "nn": array(data["nn"], "f4"),
        "triangles": triangles,
        "layers": {k: None if v is None else layer(v) for k, v in data["layers"].items()},
        "trace": None,
    }
    trace = data["trace"]
    if trace is not None:
        changes = array(trace["step_changes"], "u1")
        steps = []
        for t, change in zip(array(trace["step_triangles"], "u4"), changes):
            corners = triangles[t]
            toggled = [sorted((int(corners[k]), int(corners[(k + 1) % 3]))) for k in range(3)]
            steps.append(
                (int(t), int(change >> 3), sorted(toggled[k] for k in range(3) if change >> k & 1))
            )
        decoded["trace"] = {
            "phases": trace["phases"],
            "initial_inside": bits(trace["initial_inside"], len(triangles)),
            "initial_boundary": layer(trace["initial_boundary"]),
            "steps": steps,
            "inflated_at": trace["inflated_at"],
        }
    return decoded


def test_coordinates_round_trip_exactly(pages, repo_root):
    data = page_data(pages["trace"])
    lines = (repo_root / "data" / "inputs" / f"{CASE}.xy").read_text().split("\n")
    expected = np.array([[float(v) for v in line.split()] for line in lines if line.strip()])
    assert data["points"].tobytes() == expected.tobytes()
    assert np.all(data["nn"] > 0)


def test_page_data_carries_the_replay(pages, repo_root):
    data = page_data(pages["trace"])
    trace = data["trace"]
    assert trace["phases"] == ["inflate", "pocket", "sculpt"]
    n, triangles = data["n"], len(data["triangles"])
    assert len(trace["initial_inside"]) == triangles
    codes = [phase for _, phase, _ in trace["steps"]]
    inflate, pocket, sculpt = range(3)
    inflating, sculpting = codes[: trace["inflated_at"]], codes[trace["inflated_at"] :]
    assert inflate in inflating and set(inflating) <= {inflate, pocket}
    assert sculpting and set(sculpting) == {sculpt}
    for t, _, toggled in trace["steps"]:
        assert 0 <= t < triangles
        assert toggled, "every step changes the boundary"
        assert all(0 <= i < j < n for i, j in toggled)
    assert set(data["layers"]) == {"dt", "sigdt", "sigdt2", "boundary", "result", "gt"}
    # The kernel's replay, step by step, from the initial boundary: the boundary after
    # inflating and at the end are the layers the page shows.
    boundary = {tuple(e) for e in trace["initial_boundary"]}
    for s, (_, _, toggled) in enumerate(trace["steps"], start=1):
        boundary ^= {tuple(e) for e in toggled}
        if s == trace["inflated_at"]:
            assert sorted(boundary) == [tuple(e) for e in data["layers"]["boundary"]]
    assert sorted(boundary) == [tuple(e) for e in data["layers"]["result"]]
    gt = np.loadtxt(repo_root / "data" / "inputs" / f"{CASE}.gt", dtype=int)
    assert data["layers"]["gt"] == np.unique(np.sort(gt, axis=1), axis=0).tolist()
    assert page_data(pages["no-trace"])["trace"] is None


def colour(hex_colour: str) -> np.ndarray:
    return np.array([int(hex_colour[k : k + 2], 16) for k in (1, 3, 5)], dtype=np.uint8)


def pixels_of(image: np.ndarray, hex_colour: str) -> int:
    """How many pixels of ``image`` are exactly ``hex_colour``."""
    return int((image == colour(hex_colour)).all(axis=2).sum())


def test_replay_in_the_browser(browser, pages):
    view = Page(browser, pages["trace"])
    page = view.page
    assert CASE in page.title()
    # The page opens on the result; the slider is at its end.
    assert view.text("#status") == "final"
    assert page.eval_on_selector("#step", "el => el.value === el.max && el.max > 0")
    final = view.canvas()
    assert (final != final[0, 0]).any(), "the canvas is blank"

    page.click("#dt")
    view.settle()
    assert page.is_checked("#dt")
    final_with_dt = view.canvas()
    assert (final_with_dt != final).any(), "showing the DT changed nothing"

    view.set_step("0")
    assert view.text("#status") == "initial"
    start = view.canvas()
    assert (start != start[0, 0]).any(), "the canvas is blank at step 0"
    assert (start != final_with_dt).any(), "the first and last steps look the same"

    view.set_step("end")
    assert view.text("#status") == "final"
    # One step back with the arrow key, then forward with the button.
    page.locator("#canvas").click()
    page.keyboard.press("ArrowLeft")
    view.settle()
    assert re.fullmatch(r"(sculpt|inflate) \d+/\d+|pocket", view.text("#status"))
    page.click("#forward")
    view.settle()
    assert view.text("#status") == "final"
    # The page only applies the kernel's steps: its boundary after inflating is the
    # "boundary" layer, and at the end it is the result (a polygon).
    data = page_data(pages["trace"])
    trace = data["trace"]
    assert page.evaluate(BOUNDARY_AT, 0) == trace["initial_boundary"]
    assert page.evaluate(BOUNDARY_AT, trace["inflated_at"]) == data["layers"]["boundary"]
    assert page.evaluate(BOUNDARY_AT, len(trace["steps"])) == data["layers"]["result"]
    page.mouse.move(5, 5)  # off the canvas: no point is highlighted
    view.settle()
    assert (view.canvas() == final_with_dt).all(), "the end looks different after the replay"
    view.set_step("0")
    assert (view.canvas() == start).all(), "step 0 looks different after the replay"
    view.check_quiet()
    page.close()


def test_colours_match_render_and_plot(browser, pages, cli, repo_root, tmp_path):
    """The page draws each layer in the palette's colour, as ``sigdt render`` and
    ``sigdt.plot`` do: at the end, the interior is the render's fill and the result its ink."""
    view = Page(browser, pages["trace"])
    styles = view.page.evaluate(
        "() => Object.fromEntries(Object.entries(window.sigdtView.view.styles).map(([k, v]) => [k, v.color]))"
    )
    assert styles["points"] == styles["result"] == PALETTE["ink"]
    assert styles["interior"] == PALETTE["fill"]
    for layer in ["dt", "sig", "sigdt", "sigdt2", "boundary"]:
        assert styles[layer] == PALETTE[layer], layer
    assert styles["gt"] == PALETTE["truth"]
    final = view.canvas()
    assert pixels_of(final, PALETTE["fill"]) > 20000, "the interior is not in the fill colour"
    assert pixels_of(final, PALETTE["ink"]) > 200, "the result is not in ink"
    assert pixels_of(final, PALETTE["background"]) > 100000
    view.check_quiet()
    view.page.close()

    # sigdt render: the result's loops filled and outlined in the same colours.
    svg = tmp_path / "render.svg"
    inputs = repo_root / "data" / "inputs"
    subprocess.run([cli, "render", inputs / f"{CASE}.xy", "-o", svg], check=True)
    paths = ET.parse(svg).getroot().iter("{http://www.w3.org/2000/svg}path")
    fills = {(p.get("fill"), p.get("stroke")) for p in paths}
    assert (PALETTE["fill"], PALETTE["ink"]) in fills, fills

    # sigdt.plot: the same fill and ink.
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.colors import to_hex

    rec = sigdt.reconstruct(np.loadtxt(inputs / f"{CASE}.xy"))
    ax = rec.plot()
    patch_colours = {to_hex(p.get_facecolor()) for p in ax.patches}
    edge_colours = {to_hex(c) for coll in ax.collections for c in coll.get_colors()}
    assert PALETTE["fill"] in patch_colours and PALETTE["ink"] in edge_colours


def test_a_sliver_step_stays_visible(browser, pages):
    """The triangle of the thinnest step on screen is outlined and ringed in its phase's
    colour: hundreds of pixels of that exact colour, which go when its layer is off."""
    view = Page(browser, pages["trace"])
    page = view.page
    step, thickness, phase = page.evaluate(
        """() => {
      const { model, view } = window.sigdtView;
      const trace = model.trace;
      let best = [0, Infinity, ""];
      for (let k = 0; k < trace.steps; k++) {
        const t = trace.stepTriangle[k];
        const [a, b, c] = [0, 1, 2].map((i) => trace.tri[3 * t + i]);
        const [xa, ya, xb, yb, xc, yc] = [a, a, b, b, c, c].map((v, i) => (i % 2 ? view.sy[v] : view.sx[v]));
        const area2 = Math.abs((xb - xa) * (yc - ya) - (yb - ya) * (xc - xa));
        const side = Math.max(Math.hypot(xb - xa, yb - ya), Math.hypot(xc - xb, yc - yb), Math.hypot(xa - xc, ya - yc));
        if (area2 / side < best[1]) best = [k + 1, area2 / side, trace.phaseName(k)];
      }
      return best;
    }"""
    )
    assert thickness < 4, f"{CASE} has no sliver step to test (thinnest {thickness:.1f} px)"
    page.click("#result")  # off: the result's ink must not hide the highlight
    view.set_step(str(step))
    highlighted = pixels_of(view.canvas(), PALETTE[phase])
    assert highlighted > 150, (
        f"step {step} ({phase}, {thickness:.2f} px thick): {highlighted} pixels"
    )
    page.click("#changed")
    view.settle()
    assert pixels_of(view.canvas(), PALETTE[phase]) < highlighted / 10
    view.check_quiet()
    page.close()


def boxes(page, selectors: list[str]) -> dict[str, dict]:
    return {s: page.locator(s).bounding_box() for s in selectors}


def test_layout_at_420_pixels(browser, pages):
    page = browser.new_page(viewport={"width": 420, "height": 800})
    page.goto(pages["trace"].as_uri())
    assert page.evaluate("() => document.documentElement.scrollWidth") <= 420, (
        "the page scrolls sideways"
    )
    canvas = page.locator("#canvas").bounding_box()
    assert canvas["width"] >= 400 and canvas["height"] >= 300, canvas
    controls = [
        "#back",
        "#play",
        "#forward",
        "#step",
        "#fit",
        "#export-png",
        "#export-svg",
        "#status",
    ]
    found = boxes(page, controls)
    for name, box in found.items():
        assert page.locator(name).is_visible(), name
        assert box["x"] >= 0 and box["x"] + box["width"] <= 420, (name, box)
        assert box["y"] >= 0 and box["y"] + box["height"] <= 800, (name, box)
    for a in controls:
        for b in controls:
            p, q = found[a], found[b]
            overlap = (
                a < b
                and p["x"] < q["x"] + q["width"]
                and q["x"] < p["x"] + p["width"]
                and p["y"] < q["y"] + q["height"]
                and q["y"] < p["y"] + p["height"]
            )
            assert not overlap, f"{a} and {b} overlap"
    # Every layer can be reached (the panel scrolls) and toggled.
    page.click("#changed")
    assert not page.is_checked("#changed")
    page.close()


def test_export_png_and_svg(browser, pages, tmp_path):
    """Both exports are the view on screen: the PNG pixel for pixel (within colour rounding),
    the SVG drawn by the
    browser nearly so (anti-aliasing differs at edges)."""
    view = Page(browser, pages["trace"])
    page = view.page
    page.mouse.move(5, 5)
    view.set_step("40")
    shown = view.canvas()
    with page.expect_download() as png_download:
        page.click("#export-png")
    assert png_download.value.suggested_filename == f"{CASE}-step-40.png"
    png_path = tmp_path / "view.png"
    png_download.value.save_as(png_path)
    from PIL import Image

    png = np.asarray(Image.open(png_path).convert("RGB"))
    assert png.shape == shown.shape
    # The buttons over the canvas's corner are in the screenshot, not in the picture.
    tools, canvas = page.locator("#tools").bounding_box(), page.locator("#canvas").bounding_box()
    over = np.zeros(shown.shape[:2], dtype=bool)
    over[
        : int(tools["y"] + tools["height"] - canvas["y"]) + 2, int(tools["x"] - canvas["x"]) - 2 :
    ] = True
    assert np.abs(png.astype(int) - shown)[~over].max() <= 8, "the PNG is not the view"

    with page.expect_download() as svg_download:
        page.click("#export-svg")
    assert svg_download.value.suggested_filename == f"{CASE}-step-40.svg"
    svg_path = tmp_path / "view.svg"
    svg_download.value.save_as(svg_path)
    root = ET.parse(svg_path).getroot()
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    size = float(root.get("width")), float(root.get("height"))
    assert abs(size[0] - shown.shape[1]) < 1 and abs(size[1] - shown.shape[0]) < 1, size
    fills = {p.get("fill") for p in root.iter("{http://www.w3.org/2000/svg}path")}
    assert PALETTE["fill"] in fills and PALETTE["ink"] in fills
    drawn = browser.new_page(viewport={"width": shown.shape[1], "height": shown.shape[0]})
    drawn.goto(svg_path.as_uri())
    picture = np.asarray(Image.open(io.BytesIO(drawn.screenshot())).convert("RGB"))
    drawn.close()
    differs = (np.abs(picture.astype(int) - shown).max(axis=2) > 48)[~over].mean()
    assert differs < 0.01, f"{differs:.2%} of the SVG's pixels differ from the view"
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


def test_junctions_are_ringed(browser, cli, repo_root, tmp_path):
    """A network's junctions get a layer of their own, on at start, that can be switched off;
    a polygon has none (the bundled example's layer is disabled)."""
    theta = repo_root / "data" / "non-manifold" / "nm_theta_00.xy"
    out = tmp_path / "theta.html"
    run = subprocess.run(
        [cli, "view", theta, "-o", out], capture_output=True, text=True, check=False
    )
    assert run.returncode == 0, run.stderr
    view = Page(browser, out)
    page = view.page
    assert page.is_checked("#junctions")
    row = page.locator("label.layer", has=page.locator("#junctions"))
    assert row.locator(".count").inner_text() == "2"
    shown = view.canvas()
    page.click("#junctions")
    view.settle()
    assert not page.is_checked("#junctions")
    assert (view.canvas() != shown).any()
    assert view.messages == []
    page.close()
    plain = Page(browser, viewer_page(cli, repo_root, tmp_path / "plain.html"))
    assert plain.page.is_disabled("#junctions")
    plain.page.close()
