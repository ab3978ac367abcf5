"""Many machines: map ``sigdt.reconstruct`` over point sets with Dask.

The recipe (a LocalCluster stands in for a real cluster; on one, connect with
``Client("scheduler-address:8786")`` and install sigdt on every worker)::

    import dask.bag as db
    from distributed import Client, LocalCluster
    import sigdt

    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True)
    client = Client(cluster)

    # Either a bag ...
    results = db.from_sequence(point_sets, npartitions=8).map(sigdt.reconstruct).compute()
    # ... or futures:
    results = client.gather(client.map(sigdt.reconstruct, point_sets))

    client.close()
    cluster.close()

``sigdt.reconstruct`` is a plain module-level function of a numpy array and
``Reconstruction`` pickles compactly (numpy arrays), so both travel between processes.
The results equal the serial ``[sigdt.reconstruct(p) for p in point_sets]``. A
``dask_geopandas.GeoDataFrame`` goes to ``sigdt.reconstruct_frame(frame, by=COLUMN)`` whole: it
is shuffled by the group column and reconstructed partition by partition on the workers.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
import sigdt
from blobs import blob
from dask import bag as db
from distributed import Client, LocalCluster

N_SETS = 1000


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    client = Client(cluster)
    try:
        yield client
    finally:
        client.close()
        cluster.close()


@pytest.fixture(scope="module")
def point_sets() -> list[np.ndarray]:
    """1,000 seeded random blobs of 30 to 120 points, shuffled, with a few degenerate sets."""
    rng = np.random.default_rng(2024)
    sets = []
    for k in range(N_SETS):
        n = int(rng.integers(30, 121))
        amplitudes = 0.25 * rng.uniform(size=3) / np.arange(2, 5) ** 2
        points = blob(n, amplitudes, rng.uniform(0, 2 * np.pi, size=3), rng.uniform())
        points = points[rng.permutation(n)] * rng.uniform(0.1, 10) + rng.normal(size=2)
        sets.append(points if k % 100 else points[: k % 3])
    return sets


@pytest.fixture(scope="module")
def serial(point_sets) -> list[sigdt.Reconstruction]:
    return [sigdt.reconstruct(p) for p in point_sets]


def test_workers_are_other_processes(client):
    pids = client.run(os.getpid)
    assert len(pids) == 2
    assert len(set(pids.values())) == 2 and os.getpid() not in pids.values()


def test_bag_map_equals_the_serial_path(client, point_sets, serial):
    bag = db.from_sequence(point_sets, npartitions=8)
    assert bag.npartitions == 8
    results = bag.map(sigdt.reconstruct).compute()  # the Client is the default scheduler
    assert len(results) == N_SETS
    assert all(isinstance(r, sigdt.Reconstruction) for r in results)
    assert results == serial
    assert {r.status for r in results} >= {"polygon", "too-few-points"}


def test_client_map_equals_the_serial_path(client, point_sets, serial):
    futures = client.map(sigdt.reconstruct, point_sets)
    results = client.gather(futures)
    assert results == serial
    where = client.who_has(futures)
    workers = {w for addresses in where.values() for w in addresses}
    assert len(workers) == 2, "both workers should have computed results"


def test_chunked_reconstruct_many_equals_the_serial_path(client, point_sets, serial):
    def chunk(part):
        return sigdt.reconstruct_many(list(part), n_jobs=1)

    results = db.from_sequence(point_sets, npartitions=8).map_partitions(chunk).compute()
    assert results == serial


def test_reconstruct_frame_on_a_dask_geodataframe_gives_the_pandas_rows(client):
    """Issue 46: 10⁴ groups (seeded blobs, a few of two points, one off the map) as a
    dask_geopandas frame over 7 partitions, shuffled by the group column on two workers."""
    import dask_geopandas
    import geopandas as gpd
    import pandas as pd
    import shapely

    rng = np.random.default_rng(46)
    parts, groups = [], []
    for g in range(10_000):
        n = 3 if g % 997 == 0 else int(rng.integers(8, 20))
        t = np.sort(rng.uniform(0, 2 * np.pi, n))
        centre = rng.uniform(-170, 170), rng.uniform(-60, 60)
        parts.append(np.c_[centre[0] + 0.01 * np.cos(t), centre[1] + 0.01 * np.sin(t)])
        groups += [f"g{g:05d}"] * n
    points = np.concatenate(parts)
    points[0] = [-180.0015, 0.0]  # group g00000 is off the map: a row with status "error"
    frame = gpd.GeoDataFrame(
        {"group": groups, "rank": np.arange(len(points)) % 5},
        geometry=shapely.points(points),
        crs="EPSG:4326",
    ).sample(frac=1.0, random_state=1)  # rows of a group scattered over the partitions
    points = dask_geopandas.from_geopandas(frame, npartitions=7)
    # The pandas path on the same frame: from_geopandas sorts the rows by their index.
    with pytest.warns(sigdt.SigdtWarning, match="1 of 10000 groups failed"):
        expected = sigdt.reconstruct_frame(points.compute(), by="group", progress=False)
    lazy = sigdt.reconstruct_frame(points, by="group")
    assert type(lazy).__module__.startswith("dask_geopandas")
    got = lazy.compute().sort_index()
    assert len(got) == 10_000 and got.crs == expected.crs
    assert got.loc["g00000", "status"] == "error"
    assert "-180.0015" in got.loc["g00000", "diagnosis"]
    pd.testing.assert_frame_equal(
        got.drop(columns=["geometry", "paths", "networks"]),
        expected.drop(columns=["geometry", "paths", "networks"]),
    )
    for column in ["geometry", "paths", "networks"]:
        assert shapely.equals_exact(got[column].values, expected[column].values, 0).all(), column


def test_a_dask_frame_needs_a_group_column():
    import dask_geopandas
    import geopandas as gpd
    import shapely

    frame = gpd.GeoDataFrame({"g": [1] * 4}, geometry=shapely.points(np.eye(4, 2)))
    lazy = dask_geopandas.from_geopandas(frame, npartitions=1)
    with pytest.raises(ValueError, match="needs by= naming the column"):
        sigdt.reconstruct_frame(lazy)
    with pytest.raises(ValueError, match="no column 'h' in the Dask frame"):
        sigdt.reconstruct_frame(lazy, by="h")
