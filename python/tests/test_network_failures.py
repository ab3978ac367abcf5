"""The sampling conditions ``python/bench/network_failures.py`` checks on a ground truth
(issue 33's reasons per failure), and SIG-AUTO's own junction rules it reports apart from
them (issue 49): each is found where it is broken and only there, and no rule of SIG-AUTO's
counts as a sampling condition."""

from __future__ import annotations

import numpy as np
from bench_scripts import load

failures = load("network_failures")


def tee(stem_angle: float = 90.0, stem: int = 8, wiggle: float = 0.0):
    """A bar of 17 unit-spaced samples, a stem of `stem` samples ending on its middle (8)
    at `stem_angle` degrees from the bar; the ground truth joins consecutive samples."""
    points = [[float(i), wiggle * (i % 2)] for i in range(-8, 9)]
    a = np.radians(stem_angle)
    points += [[i * np.cos(a), i * np.sin(a)] for i in range(1, stem + 1)]
    truth = {(i, i + 1) for i in range(16)} | {(8, 17)} | {(k, k + 1) for k in range(17, 16 + stem)}
    return np.array(points), truth


def test_a_well_sampled_tee_breaks_nothing():
    assert failures.broken_conditions(*tee()) == []
    assert failures.broken_rules(*tee()) == []


def test_sig_auto_rules_are_not_sampling_conditions():
    assert set(failures.RULES).isdisjoint(failures.CONDITIONS)
    assert set(failures.RULES) == {"narrow-arms", "near-junctions", "short-branch"}


def test_a_stem_of_two_samples_fails_only_sig_auto_s_branch_rule():
    assert failures.broken_conditions(*tee(stem=2)) == []
    assert failures.broken_rules(*tee(stem=2)) == ["short-branch"]


def test_a_stem_close_to_the_bar_runs_near_it_and_hides_behind_it():
    points, truth = tee(stem_angle=20.0)
    assert "near-curves" in failures.broken_conditions(points, truth)
    assert "narrow-arms" not in failures.broken_conditions(points, truth)
    assert "narrow-arms" in failures.broken_rules(points, truth)


def test_a_zigzag_bar_turns_sharply():
    assert "sharp-turn" in failures.broken_conditions(*tee(wiggle=1.2))


def test_a_stem_spaced_unlike_the_bar_is_an_uneven_junction():
    points, truth = tee()
    points[17:] *= 2.5  # the stem's samples 2.5 apart, the bar's 1
    assert failures.broken_conditions(points, truth) == ["uneven-junction"]
    assert failures.broken_rules(points, truth) == []


def test_two_tees_two_edges_apart_fail_only_sig_auto_s_junction_rules():
    points, truth = tee()
    points = np.vstack([points, [[2.0, -float(i)] for i in range(1, 9)]])
    truth |= {(10, 25)} | {(k, k + 1) for k in range(25, 32)}
    assert failures.broken_conditions(points, truth) == []
    # the one sample between them is also a branch shorter than SIG-AUTO's MIN_BRANCH
    assert failures.broken_rules(points, truth) == ["near-junctions", "short-branch"]


def crossing(past: int):
    """A bar of 17 unit-spaced samples crossed at its middle (8) by a stroke from 8 samples
    below to `past` samples above it; the ground truth joins consecutive samples."""
    points = [[float(i), 0.0] for i in range(-8, 9)]
    points += [[0.0, float(i)] for i in range(-8, past + 1) if i != 0]
    truth = {(i, i + 1) for i in range(16)}
    stroke = [17 + k for k in range(8)] + [8] + [25 + k for k in range(past)]
    truth |= {(min(a, b), max(a, b)) for a, b in zip(stroke, stroke[1:])}
    return np.array(points), truth


def test_a_stroke_stopping_two_samples_past_a_crossing_still_crosses():
    assert failures.broken_rules(*crossing(past=2)) == []
    assert failures.broken_rules(*crossing(past=1)) == ["short-branch"]
    assert failures.broken_conditions(*crossing(past=1)) == []
