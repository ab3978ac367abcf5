"""The exception hierarchy, SigdtWarning for results that are not faithful curves, and the
points a method leaves out with their reasons."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
import sigdt

# A 40 x 40 grid: every cost ties and sculpting gets stuck with one point inside
# (crates/sigdt/tests/degenerate.rs pins the count).
GRID = np.array([[x, y] for x in range(40) for y in range(40)], dtype=float)


def circle(n: int = 60) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.c_[np.cos(t), np.sin(t)]


@pytest.mark.parametrize(
    ("name", "builtin"),
    [
        ("InvalidInputError", ValueError),
        ("ParseError", ValueError),
        ("InternalError", RuntimeError),
    ],
)
def test_every_exception_is_a_sigdt_error_and_its_builtin(name, builtin):
    cls = getattr(sigdt, name)
    assert issubclass(cls, sigdt.SigdtError) and issubclass(cls, builtin)
    assert cls.__module__ == "sigdt.errors"


def test_errors_raised_by_the_extension_are_the_exported_classes(tmp_path):
    with pytest.raises(sigdt.InvalidInputError) as info:
        sigdt.reconstruct([[0.0, 0.0], [1.0, np.nan], [2.0, 0.0]])
    assert isinstance(info.value, sigdt.SigdtError)
    bad = tmp_path / "bad.xy"
    bad.write_text("0 0\n1 zero\n")
    with pytest.raises(sigdt.ParseError, match="bad.xy"):
        sigdt.read_points(bad)
    with pytest.raises(sigdt.SigdtError, match="point set 1"):
        sigdt.reconstruct_many([circle(), [[0.0, np.inf], [1.0, 1.0], [2.0, 0.0]]])


def test_a_faithful_result_warns_nothing():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert sigdt.reconstruct(circle()).status == "polygon"
        sigdt.reconstruct_many([circle(), circle(30)])


def test_a_stuck_sculpting_warns_and_still_returns_the_result():
    with pytest.warns(sigdt.SigdtWarning, match=r"^sculpting-stuck: sculpting got stuck") as rec:
        result = sigdt.reconstruct(GRID)
    assert result.status == "sculpting-stuck" and len(result.left_out)
    assert set(result.left_out_reasons) == {"inside"}
    assert rec[0].filename == __file__  # points at the caller, not into sigdt


def test_reconstruct_many_warns_once_naming_the_first_set():
    with pytest.warns(sigdt.SigdtWarning) as caught:
        sigdt.reconstruct_many([circle(), GRID, GRID])
    assert len(caught) == 1
    assert str(caught[0].message).startswith("point set 1 (and 1 more): sculpting-stuck")


def test_sig_auto_leaves_a_far_outlier_out_with_its_reason():
    points = np.r_[circle(80), [[0.0, 0.0]]]  # the centre: far from the curve
    rec = sigdt.reconstruct(points, method="sig-auto")
    assert rec.status == "polygon", rec.status
    assert rec.left_out.tolist() == [80] and rec.left_out_reasons == ["outlier"]
    assert 80 not in rec.edges
    feature = rec.to_geojson()
    assert feature["properties"]["left_out"] == [80]
    assert feature["properties"]["left_out_reasons"] == ["outlier"]
    # The polygon leaves the outlier out: it is the circle alone.
    assert len(rec.loops) == 1 and len(rec.loops[0]) == 80


@pytest.mark.parametrize(
    ("points", "message"),
    [
        (np.array([1 + 2j, 3 + 4j, 5 + 0j]), "complex"),
        (np.zeros((5, 0)), r"shape \(n, 2\), got \(5, 0\)"),
        (np.zeros((1, 0)), r"got \(1, 0\)"),
        (np.zeros((4, 3)), r"points\[:, :2\]"),
        ([[10**400, 0], [1, 1], [2, 0]], "cannot be read"),
        ([[0, 0], [1, 1, 1]], "cannot be read"),
        (
            np.ma.masked_array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], mask=[[0, 0], [0, 1], [0, 0]]),
            "masked",
        ),
    ],
)
def test_input_that_would_lose_information_is_refused(points, message):
    with pytest.raises(sigdt.InvalidInputError, match=message):
        sigdt.reconstruct(points)


def test_input_that_loses_nothing_is_read():
    square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    unmasked = np.ma.masked_array(square, mask=False)
    assert sigdt.reconstruct(unmasked) == sigdt.reconstruct(square)
    assert sigdt.reconstruct([]).status == "too-few-points"
    assert sigdt.reconstruct(np.zeros((0, 2))).status == "too-few-points"


def test_a_result_that_breaks_the_sampling_condition_warns_with_its_findings():
    # A circle of 60 samples and, beside it, a knot of five points: no closed curve
    # sampled within the condition gives a loop of five.
    knot = 3.0 + 0.05 * circle(5)
    with pytest.warns(sigdt.SigdtWarning, match=r"fewer than 7 points") as caught:
        rec = sigdt.reconstruct(np.r_[circle(), knot])
    assert caught[0].filename == __file__
    assert rec.status == "polygons" and rec.warns
    [finding] = rec.diagnosis
    assert (finding["kind"], finding["count"], finding["worst"], finding["at"]) == (
        "small-loops",
        1,
        5.0,
        60,
    )
    assert "the result may not be the points' curves" in str(caught[0].message)
    properties = rec.to_geojson()["properties"]
    assert properties["warning"] is True and properties["diagnosis"] == rec.diagnosis


def test_noise_that_moves_the_area_warns_with_how_much():
    # 40 samples of the unit circle moved across it by half their spacing: the loop keeps
    # its order, but the strip of noise along it is a tenth of the area.
    rng = np.random.default_rng(7)
    angle = 2 * np.pi * np.arange(40) / 40
    radius = 1 + 0.5 * (2 * np.pi / 40) * rng.standard_normal(40)
    points = np.c_[radius * np.cos(angle), radius * np.sin(angle)]
    with pytest.warns(sigdt.SigdtWarning, match=r"scatter like noise.* uncertain by about"):
        rec = sigdt.reconstruct(points, method="sig-auto")
    [finding] = [f for f in rec.diagnosis if f["kind"] == "noisy-area"]
    assert finding["count"] == 1 and 0.05 < finding["worst"] < 0.3


def test_a_faithful_result_has_an_empty_diagnosis():
    rec = sigdt.reconstruct(circle())
    assert rec.diagnosis == [] and not rec.warns
    assert rec.to_geojson()["properties"]["warning"] is False


def test_expect_areas_closes_outlines_or_warns():
    # Togo and Georgia by their vertices (data/vertices): read as open lines by default.
    # Told that the points outline areas, Togo closes; Georgia stays open and warns.
    folder = Path(__file__).resolve().parents[2] / "data" / "vertices"
    togo = np.loadtxt(folder / "ne_togo_raw.xy")
    assert len(sigdt.reconstruct(togo).paths) == 1
    rec = sigdt.reconstruct(togo, expect="areas")
    assert rec.status == "polygon" and not rec.paths
    georgia = np.loadtxt(folder / "ne_georgia_raw.xy")
    with pytest.warns(sigdt.SigdtWarning, match="come back open although the points outline"):
        rec = sigdt.reconstruct(georgia, expect="areas")
    [finding] = [f for f in rec.diagnosis if f["kind"] == "open-outlines"]
    assert finding["count"] == 1 and finding["point"] == list(georgia[finding["at"]])
    [many] = sigdt.reconstruct_many([togo], expect="areas")
    assert many == sigdt.reconstruct(togo, expect="areas")
    with pytest.raises(ValueError, match="areas"):
        sigdt.reconstruct(togo, expect="polygons")
