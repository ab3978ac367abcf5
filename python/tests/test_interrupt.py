"""Ctrl-C during a long call: KeyboardInterrupt comes promptly, and the module stays usable.

A timer thread sends SIGINT to the process while the call runs with the GIL released; the
call must raise KeyboardInterrupt well before the work would have ended.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time

import numpy as np
import pytest
import sigdt

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")


def spiral(n: int) -> np.ndarray:
    t = np.sqrt(np.linspace(0.0, 1.0, n)) * 60 * np.pi
    return np.c_[t * np.cos(t), t * np.sin(t)]


def interrupted_after(delay: float, call) -> float:
    """Seconds from the signal to KeyboardInterrupt (fails if the call ends first)."""
    sent: list[float] = []

    def fire() -> None:
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(delay, fire)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
        return time.perf_counter() - sent[0]
    finally:
        timer.cancel()


def test_reconstruct_many_is_interrupted_promptly():
    sets = [spiral(50_000)] * 200  # about 20 s of work on two cores
    start = time.perf_counter()
    latency = interrupted_after(0.3, lambda: sigdt.reconstruct_many(sets, n_jobs=2))
    assert latency < 2.0, f"KeyboardInterrupt {latency:.2f} s after the signal"
    assert time.perf_counter() - start < 5.0
    assert sigdt.reconstruct_many(sets[:2]) == [sigdt.reconstruct(sets[0])] * 2


def test_one_large_reconstruction_is_interrupted_promptly():
    points = spiral(1_500_000)  # seconds of work
    latency = interrupted_after(0.3, lambda: sigdt.reconstruct(points, method="sig-auto"))
    assert latency < 2.0, f"KeyboardInterrupt {latency:.2f} s after the signal"
    # The first thousand points are an open piece of the spiral.
    assert sigdt.reconstruct(points[:1000]).status == "curves"


def test_evaluate_is_interrupted_promptly():
    # A random polygon: its edges cross everywhere, and the area's overlay splits each
    # crossing (seconds of work).
    n = 2500
    points = np.random.default_rng(0).random((n, 2))
    polygon = np.c_[np.arange(n), (np.arange(n) + 1) % n]
    latency = interrupted_after(0.3, lambda: sigdt.evaluate(points, polygon[:0], polygon))
    assert latency < 1.0, f"KeyboardInterrupt {latency:.2f} s after the signal"
    assert sigdt.evaluate(points[:4], polygon[:0], [[0, 1], [1, 2], [2, 3], [3, 0]])["missing"] == 4


def test_reading_an_endless_geopackage_view_is_interrupted_and_stops(tmp_path):
    """Issue 47, P3: read_points on a GeoPackage whose layer is an endless view ignored
    Ctrl-C (the reader ran with the GIL released and never looked). The reader now runs on a
    thread of its own and stops at the flag Ctrl-C sets."""
    import sqlite3

    path = tmp_path / "endless.gpkg"
    db = sqlite3.connect(path)
    db.executescript(
        "CREATE TABLE gpkg_spatial_ref_sys (srs_name TEXT, srs_id INTEGER PRIMARY KEY, "
        "organization TEXT, organization_coordsys_id INTEGER, definition TEXT);"
        "CREATE TABLE gpkg_geometry_columns (table_name TEXT, column_name TEXT, "
        "geometry_type_name TEXT, srs_id INTEGER, z INTEGER, m INTEGER);"
        "INSERT INTO gpkg_geometry_columns VALUES ('endless', 'geom', 'POINT', 0, 0, 0);"
        "CREATE VIEW endless AS WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 "
        "FROM n) SELECT i AS fid, NULL AS geom FROM n WHERE i < 0;"
    )
    db.close()
    # Work an earlier test interrupted may still be finishing on its thread: wait for it.
    assert _idle_within(30.0), "the process never went idle before the test"
    latency = interrupted_after(0.5, lambda: sigdt.read_points(path))
    assert latency < 2.0, f"KeyboardInterrupt {latency:.2f} s after the signal"
    # The reading thread saw the flag and ended: the process is idle again (a reader left
    # running would burn a core: about 1 s of CPU a second).
    assert _idle_within(5.0), "the reader went on after KeyboardInterrupt"


def _idle_within(seconds: float) -> bool:
    """Whether, within ``seconds``, the process spends a second using under 0.3 s of CPU."""
    deadline = time.perf_counter() + seconds
    while time.perf_counter() < deadline:
        before = time.process_time()
        time.sleep(1.0)
        if time.process_time() - before < 0.3:
            return True
    return False
