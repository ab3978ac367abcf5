"""One outline per group of points in one call (:func:`sigdt.geopandas.reconstruct_frame`)."""

from __future__ import annotations

import sys
from collections.abc import Hashable, Sequence
from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from . import _core
from ._api import _threads, _warn_about
from ._geodataframe import _diagnosis
from ._input import LEAF_ELIMINATION, _as_points, _check_method, _is_geographic
from ._result import Reconstruction
from ._types import Expect, Method
from .errors import InvalidInputError

if TYPE_CHECKING:  # pragma: no cover
    from geopandas import GeoDataFrame
else:
    GeoDataFrame = Any

#: The columns of :func:`reconstruct_frame`, geometry and group keys aside.
GROUP_COLUMNS = ["status", "warning", "diagnosis", "n_points", "n_left_out"]


def _progress(total: int, show: bool | None) -> Callable[[int], None]:
    """A one-line progress report on standard error, ``done/total groups``, drawn in place;
    by default only when standard error is a terminal."""
    if show is None:
        show = sys.stderr.isatty()
    if not show:
        return lambda done: None

    def report(done: int) -> None:
        width = 30
        filled = width * done // max(total, 1)
        end = "\n" if done == total else ""
        bar = "#" * filled + "-" * (width - filled)
        print(f"\rsigdt: [{bar}] {done}/{total} groups", end=end, file=sys.stderr, flush=True)

    return report


def reconstruct_frame(
    frame: Any,
    by: Hashable | Sequence[Hashable] | None = None,
    *,
    method: Method = "sig-auto",
    leaf_elimination: bool = LEAF_ELIMINATION,
    expect: Expect = "curves",
    n_jobs: int | None = None,
    progress: bool | None = None,
) -> GeoDataFrame:
    """Reconstruct one outline per group of points of a GeoPandas frame, in parallel.

    Parameters
    ----------
    frame : GeoDataFrame or GeoSeries of points
        The points; empty or missing points are refused naming the row.
    by : column name, list or tuple of column names or Series, Series, or None
        The column(s) whose values group the rows (one building, island or survey line
        each), as ``frame.groupby(by)`` groups them (a tuple is a list of columns here);
        the result's index is that of ``frame.groupby(by).size()``. ``None``: all rows
        are one group.
    method, leaf_elimination, expect
        As in :func:`sigdt.reconstruct` (``expect="areas"`` for groups that outline areas).
    n_jobs : int, optional
        Threads, as in :func:`sigdt.reconstruct_many` (threads in Rust, the GIL released).
    progress : bool, optional
        Report ``done/total groups`` on standard error as batches finish; by default only
        when standard error is a terminal.

    Returns
    -------
    GeoDataFrame
        One row per group, indexed by the group keys, in the frame's coordinate reference
        system, with ``geometry`` (the group's result as :meth:`Reconstruction.to_shapely`
        gives it), ``status``, ``warning``, ``diagnosis`` (``"; "``-separated findings),
        ``n_points`` and ``n_left_out``.

    Raises
    ------
    TypeError
        ``frame`` is not a GeoDataFrame or GeoSeries.
    InvalidInputError
        A group holds something other than points, or a missing or empty point; the
        message starts with ``group KEY:``. In a geographic coordinate reference system,
        coordinates that are not longitude and latitude, or a group spread over more than
        90° of arc.
    ValueError
        Unknown method, or ``n_jobs`` is 0 or not an int.

    Warns
    -----
    SigdtWarning
        Once, when some groups' results may not be their curves, naming the first.

    Examples
    --------
    >>> import geopandas as gpd, shapely, sigdt
    >>> square = [[0, 0], [9, 0], [9, 9], [0, 9]]
    >>> points = shapely.points(square + [[x + 20, y] for x, y in square])
    >>> frame = gpd.GeoDataFrame({"island": ["a"] * 4 + ["b"] * 4}, geometry=points)
    >>> out = sigdt.reconstruct_frame(frame, by="island")
    >>> out[["status", "n_points"]].to_dict("index")
    {'a': {'status': 'polygon', 'n_points': 4}, 'b': {'status': 'polygon', 'n_points': 4}}
    """
    import geopandas as gpd
    import pandas as pd

    _check_method(method, leaf_elimination)
    threads = _threads(n_jobs)
    if type(frame).__name__ not in ("GeoDataFrame", "GeoSeries"):
        raise TypeError(
            f"reconstruct_frame takes a GeoDataFrame or GeoSeries, not {type(frame).__name__}: "
            "for arrays use sigdt.reconstruct_many"
        )
    crs = frame.crs
    # pandas reads a tuple as one key (a column named by a tuple): a tuple of columns is a list.
    if isinstance(by, tuple):
        by = list(by)
    keys: list[Any] = [None]
    groups = [frame]
    if by is not None:
        # One pass over the groups: their keys as pandas gives them (tuples for a list of
        # columns, a list of one included), which `get_group` does not take back everywhere.
        pairs = list(frame.groupby(by, sort=True, dropna=False))
        keys = [k[0] if isinstance(by, list) and len(by) == 1 else k for k, _ in pairs]
        groups = [group for _, group in pairs]
    arrays = []
    for key, group in zip(keys, groups):
        try:
            arrays.append(_as_points(group))
        except InvalidInputError as e:
            raise InvalidInputError(f"group {key!r}: {e}") from e
    lon_lat = _is_geographic(crs)
    report = _progress(len(arrays), progress)
    # Batches of about a hundredth of the groups: progress without losing the parallelism.
    batch = max(64, len(arrays) // 100)
    results: list[Reconstruction] = []
    for start in range(0, len(arrays), batch):
        chunk = arrays[start : start + batch]
        try:
            raws = _core.reconstruct_many(
                chunk, method, bool(leaf_elimination), threads, lon_lat, expect=expect
            )
        except InvalidInputError as e:
            # "point set K: ..." counts within the batch: name the group instead.
            k, _, why = str(e).removeprefix("point set ").partition(": ")
            raise InvalidInputError(f"group {keys[start + int(k)]!r}: {why}") from e
        for (array, raw), group in zip(zip(chunk, raws), groups[start : start + batch]):
            results.append(Reconstruction(array, raw, group.index, crs))
        report(len(results))
    _warn_about(results, many=True, names=[f"group {k!r}" for k in keys])
    rows = {
        "status": [r.status for r in results],
        "warning": [r.warns for r in results],
        "diagnosis": [_diagnosis(r) for r in results],
        "n_points": np.asarray([len(r.points) for r in results], dtype=np.int64),
        "n_left_out": np.asarray([len(r.left_out) for r in results], dtype=np.int64),
    }
    geometry = [r.to_shapely() for r in results]

    # The index `frame.groupby(by).size()` would have: a column's or a series' name.
    def name(b: Any) -> Any:
        return b.name if isinstance(b, pd.Series) else b

    if by is None:
        index = pd.RangeIndex(1)
    elif isinstance(by, list) and len(by) > 1:
        index = pd.MultiIndex.from_tuples(keys, names=[name(b) for b in by])
    elif isinstance(by, list):
        index = pd.Index(keys, name=name(by[0]))
    else:
        index = pd.Index(keys, name=name(by))
    return gpd.GeoDataFrame(rows, geometry=geometry, crs=crs, index=index)
