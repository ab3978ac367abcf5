"""One outline per group of points in one call (:func:`sigdt.geopandas.reconstruct_frame`)."""

from __future__ import annotations

from collections.abc import Hashable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from . import _layers
from ._api import _no_cycle_collection, _threads
from ._groups import (
    ERROR,
    Errors,
    Failure,
    check_errors,
    grouped_positions,
    run_groups,
    warn_about_groups,
)
from ._input import LEAF_ELIMINATION, _as_points, _check_method
from ._types import Expect, Method
from .errors import InvalidInputError

if TYPE_CHECKING:  # pragma: no cover
    from geopandas import GeoDataFrame
else:
    GeoDataFrame = Any

#: The columns of :func:`reconstruct_frame`, geometry and group keys aside.
GROUP_COLUMNS = ["paths", "networks", "status", "warning", "diagnosis", "n_points", "n_left_out"]


def reconstruct_frame(
    frame: Any,
    by: Hashable | Sequence[Hashable] | None = None,
    *,
    method: Method = "sig-auto",
    leaf_elimination: bool = LEAF_ELIMINATION,
    expect: Expect = "curves",
    n_jobs: int | None = None,
    progress: bool | None = None,
    errors: Errors = "row",
) -> GeoDataFrame:
    """Reconstruct one outline per group of points of a GeoPandas frame, in parallel.

    Parameters
    ----------
    frame : GeoDataFrame or GeoSeries of points, or a dask_geopandas GeoDataFrame
        The points; empty or missing points are refused naming the row. A Dask frame is
        shuffled so that each group is in one partition, and the partitions are
        reconstructed on the workers: the result is a Dask frame with the same rows as the
        pandas path (``.compute()`` it); ``by`` must then name columns.
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
    errors : {"row", "raise"}, default "row"
        A group that cannot be reconstructed (too few points, a point off the map in
        longitude/latitude, a polygon among the points) is a row with status ``"error"``
        and the reason in ``diagnosis``, and the other groups come back; ``"raise"`` raises
        at the first instead.

    Returns
    -------
    GeoDataFrame
        One row per group, indexed by the group keys, in the frame's coordinate reference
        system, one geometry type per geometry column so that every layer can be written
        (:func:`sigdt.geopandas.layers` splits them, a Shapefile each): ``geometry``, the
        areas (``MultiPolygon``, empty when none); ``paths``, the open curves, and
        ``networks``, the curves that meet at junctions (``MultiLineString`` each); in
        longitude/latitude split at the antimeridian, valid in EPSG:4326. Then ``status``,
        ``warning``, ``diagnosis`` (``"; "``-separated findings), ``n_points`` and
        ``n_left_out``.

    Raises
    ------
    TypeError
        ``frame`` is not a GeoDataFrame or GeoSeries.
    InvalidInputError
        With ``errors="raise"``: a group holds something other than points, or a missing
        or empty point; the message starts with ``group KEY:``. In a geographic coordinate
        reference system, coordinates that are not longitude and latitude, or a group
        spread over more than 90° of arc.
    ValueError
        Unknown method or ``errors``, or ``n_jobs`` is 0 or not an int.

    Warns
    -----
    SigdtWarning
        Once: the groups that failed, by key, and the first group whose result may not be
        its curves.

    Examples
    --------
    >>> import geopandas as gpd, shapely, sigdt
    >>> square = [[0, 0], [9, 0], [9, 9], [0, 9]]
    >>> points = shapely.points(square + [[x + 20, y] for x, y in square])
    >>> frame = gpd.GeoDataFrame({"island": ["a"] * 4 + ["b"] * 4}, geometry=points)
    >>> out = sigdt.reconstruct_frame(frame, by="island")
    >>> out[["status", "n_points"]].to_dict("index")
    {'a': {'status': 'polygon', 'n_points': 4}, 'b': {'status': 'polygon', 'n_points': 4}}
    >>> out.geometry.geom_type.tolist(), out.paths.is_empty.all()
    (['MultiPolygon', 'MultiPolygon'], np.True_)
    """
    _check_method(method, leaf_elimination)
    check_errors(errors)
    threads = _threads(n_jobs)
    if type(frame).__module__.startswith("dask_geopandas"):
        from ._dask_frame import reconstruct_dask_frame

        options = {
            "method": method,
            "leaf_elimination": leaf_elimination,
            "expect": expect,
            "n_jobs": n_jobs,
            "errors": errors,
        }
        return reconstruct_dask_frame(frame, by, reconstruct_frame, options)
    if type(frame).__name__ not in ("GeoDataFrame", "GeoSeries"):
        raise TypeError(
            f"reconstruct_frame takes a GeoDataFrame or GeoSeries, not {type(frame).__name__}: "
            "for arrays use sigdt.reconstruct_many"
        )
    # pandas reads a tuple as one key (a column named by a tuple): a tuple of columns is a list.
    if isinstance(by, tuple):
        by = list(by)
    with _no_cycle_collection():
        return _reconstruct_groups(
            frame, by, method, leaf_elimination, expect, threads, progress, errors
        )


def _reconstruct_groups(
    frame: Any,
    by: Any,
    method: Method,
    leaf_elimination: bool,
    expect: Expect,
    threads: int | None,
    progress: bool | None,
    errors: Errors,
) -> GeoDataFrame:
    """:func:`reconstruct_frame` of a pandas frame, its arguments checked."""
    keys, order, sizes, index = _groups_of(frame, by)
    arrays = _points_of(frame, keys, order, sizes, errors)
    names = [f"group {k!r}" for k in keys]
    results = run_groups(
        arrays,
        names,
        frame.crs,
        method=method,
        leaf_elimination=leaf_elimination,
        expect=expect,
        threads=threads,
        progress=progress,
        errors=errors,
    )
    warn_about_groups(results, names, depth=2)  # the user called reconstruct_frame
    return _frame_of(results, index, frame.crs)


def _frame_of(results: list[Any], index: Any, crs: Any) -> GeoDataFrame:
    """The rows of ``results`` (reconstructions and failures), one geometry type a column."""
    import geopandas as gpd

    # One pass over the groups for every column, reading the extension's fields directly:
    # a property or a call a column costs more than a small group's reconstruction.
    n = len(results)
    status, warning, diagnosis, n_points, n_left_out = [], [], [], [], []
    empty = _layers.lines_of(None)[0]
    paths = np.full(n, empty, dtype=object)
    networks = np.full(n, empty, dtype=object)
    areas = _layers.ManyAreas(n)
    for g, r in enumerate(results):
        if isinstance(r, Failure):
            status.append(ERROR)
            warning.append(True)
            diagnosis.append(r.message)
            n_points.append(r.n_points)
            n_left_out.append(0)
            continue
        fields = r._fields
        status.append(fields["status"])
        warning.append(fields["status_warns"])
        findings = fields["diagnosis"]
        diagnosis.append("; ".join([f["message"] for f in findings]) if findings else "")
        n_points.append(len(r.points))
        n_left_out.append(len(fields["left_out"]))
        if len(fields["path_offsets"]) >= 2:
            paths[g], networks[g] = _layers.lines_of(r)
        areas.add(g, r)
    rows = {
        "paths": gpd.GeoSeries(paths, index=index, crs=crs),
        "networks": gpd.GeoSeries(networks, index=index, crs=crs),
        "status": status,
        "warning": warning,
        "diagnosis": diagnosis,
        "n_points": np.asarray(n_points, np.int64),
        "n_left_out": np.asarray(n_left_out, np.int64),
    }
    return gpd.GeoDataFrame(rows, geometry=areas.build(), crs=crs, index=index)


def _groups_of(frame: Any, by: Any) -> tuple[list[Any], np.ndarray, np.ndarray, Any]:
    """The groups of ``frame`` as ``frame.groupby(by)`` makes them: their keys, the row
    positions of every group in turn (each group's in frame order), each group's size, and
    the index ``frame.groupby(by).size()`` has (:func:`grouped_positions`)."""
    import pandas as pd

    n = len(frame)
    if by is None:
        return [None], np.arange(n), np.array([n]), pd.RangeIndex(1)
    index, order, sizes = grouped_positions(frame.groupby(by, sort=True, dropna=False))
    return list(index), order, sizes, index


def _points_of(
    frame: Any, keys: list[Any], order: np.ndarray, sizes: np.ndarray, errors: Errors
) -> list[np.ndarray | Failure]:
    """Each group's points (rows ``order``, ``sizes`` of them a group), as slices of one
    coordinate array; a group holding something other than points is a :class:`Failure`
    with the reason (``errors="raise"``: raised, naming the group)."""
    import shapely

    series = frame.geometry if type(frame).__name__ == "GeoDataFrame" else frame
    values = np.asarray(series.values)[order]
    bad = shapely.is_missing(values) | shapely.is_empty(values)
    bad |= shapely.get_type_id(values) != shapely.GeometryType.POINT
    coords = np.full((len(values), 2), np.nan)
    coords[~bad] = shapely.get_coordinates(values[~bad])
    starts = np.cumsum(sizes) - sizes
    bad_groups = np.zeros(len(sizes), bool)
    if len(values):  # groupby makes no empty group, and reduceat needs none
        bad_groups = np.add.reduceat(bad, starts) > 0
    arrays: list[np.ndarray | Failure] = []
    for k, (key, start, size) in enumerate(zip(keys, starts.tolist(), sizes.tolist())):
        if bad_groups[k]:
            try:
                # says what is wrong, naming the row
                _as_points(frame.iloc[order[start : start + size]])
            except InvalidInputError as e:
                if errors == "raise":
                    raise InvalidInputError(f"group {key!r}: {e}") from e
                arrays.append(Failure(size, str(e)))
                continue
        arrays.append(coords[start : start + size])
    return arrays


def layers(result: Any) -> dict[str, GeoDataFrame]:
    """The result of :func:`reconstruct_frame` (or one :class:`sigdt.Reconstruction`) as GIS
    layers of one geometry type each, every one writable to a Shapefile.

    Returns
    -------
    dict of str to GeoDataFrame
        ``"areas"`` (``MultiPolygon``; rows of groups that failed too, with an empty
        geometry, so that their status is written), ``"paths"`` and ``"networks"``
        (``MultiLineString``): the rows whose geometry there is not empty, with the other
        columns (status, warning, ...), the index and the coordinate reference system.

    Examples
    --------
    >>> import geopandas as gpd, shapely, sigdt
    >>> points = gpd.GeoSeries(shapely.points([[0, 0], [9, 0], [9, 9], [0, 9]]), crs=3857)
    >>> out = sigdt.geopandas.layers(sigdt.reconstruct_frame(points))
    >>> {name: len(layer) for name, layer in out.items()}
    {'areas': 1, 'paths': 0, 'networks': 0}
    >>> out["areas"].geom_type.tolist(), out["areas"].crs.to_epsg()
    (['MultiPolygon'], 3857)
    """
    import geopandas as gpd
    import pandas as pd

    if not isinstance(result, gpd.GeoDataFrame):
        result = _frame_of([result], pd.RangeIndex(1), result.crs)
    geometry = result.geometry.name
    others = [c for c in result.columns if c not in (geometry, "paths", "networks")]
    out = {}
    for name, column in (("areas", geometry), ("paths", "paths"), ("networks", "networks")):
        shapes = result[column]
        keep = ~shapes.is_empty
        if name == "areas":
            keep |= result["status"] == ERROR
        out[name] = gpd.GeoDataFrame(
            result.loc[keep, others], geometry=shapes[keep], crs=result.crs
        )
    return out
