"""Geometries in, geometries out: :func:`sigdt.outlines`, where ``shapely.concave_hull`` and
``GeoSeries.concave_hull()`` are called today.

GIS users hold points as geometries: a MultiPoint per feature, or the vertices of polygons and
lines digitised long ago. They want one outline per feature (or per group of features) in a
column aligned with theirs and in their coordinate reference system, without arrays, indices
or a second library in between.
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from . import _layers
from ._api import _threads
from ._groups import (
    Errors,
    Failure,
    check_errors,
    grouped_positions,
    run_groups,
    warn_about_groups,
)
from ._input import LEAF_ELIMINATION, _check_method
from ._types import Expect, Method

if TYPE_CHECKING:  # pragma: no cover
    from geopandas import GeoSeries
else:
    GeoSeries = Any


def outlines(
    geometries: Any,
    by: Hashable | Sequence[Any] | None = None,
    *,
    expect: Expect = "areas",
    method: Method = "sig-auto",
    leaf_elimination: bool = LEAF_ELIMINATION,
    n_jobs: int | None = None,
    errors: Errors = "row",
) -> Any:
    """The outline through the vertices of each geometry, or of each group of them.

    A drop-in for ``GeoSeries.concave_hull()`` and ``shapely.concave_hull``, without a
    parameter to tune.

    Parameters
    ----------
    geometries : GeoSeries, GeoDataFrame, array_like of shapely geometries, or one geometry
        Each geometry's vertices are its points: a ``MultiPoint`` (or ``Point`` rows grouped
        with ``by``), or the vertices of polygons and lines (a ring's closing vertex is its
        first again and counts once). Missing or empty geometries have no points.
    by : column name, list of column names, or array_like of group labels, optional
        Group the geometries (as ``dissolve(by)`` does) and outline each group's vertices
        together; a name or names are columns of a GeoDataFrame, an array labels each
        geometry. ``None``: one outline per geometry.
    expect : {"areas", "curves"}, default "areas"
        ``"areas"``: the points outline regions (parcels, islands, countries); each outline
        is a ``MultiPolygon`` (SIG-AUTO closes open readings where the points allow; where
        they do not, the lines left are a warning, never a quiet line). ``"curves"``: every
        curve, closed loops and open paths alike, as a ``MultiLineString``.
    method, leaf_elimination, n_jobs
        As in :func:`sigdt.reconstruct_many`.
    errors : {"row", "raise"}, default "row"
        A geometry or group that cannot be outlined (too few points, a point off the map in
        longitude/latitude) gets an empty geometry and is named in the warning;
        ``"raise"`` raises at the first.

    Returns
    -------
    GeoSeries, or one geometry for one geometry in
        Aligned with the input (its index; with ``by``, one row per group indexed by the
        group keys, sorted), in its coordinate reference system. Longitude/latitude is
        reconstructed in a local plane and written split at the antimeridian, valid in
        EPSG:4326.

    Raises
    ------
    InvalidInputError
        With ``errors="raise"``: a geometry or group that cannot be outlined; the message
        starts with ``group KEY:`` (``row LABEL:`` without ``by``).
    ValueError
        Unknown ``method``, ``expect`` or ``errors``; ``by`` neither columns nor one label
        per geometry.

    Warns
    -----
    SigdtWarning
        Once: the rows or groups that failed and the first whose outline may not be its
        points' curves.

    Examples
    --------
    >>> import geopandas as gpd, shapely, sigdt
    >>> disc = shapely.Point(0, 0).buffer(5)                 # a polygon of 65 vertices
    >>> sigdt.outlines(disc).equals(shapely.MultiPolygon([disc]))
    True
    >>> parcels = gpd.GeoSeries([disc, shapely.affinity.translate(disc, 20)], crs=27700)
    >>> out = sigdt.outlines(parcels)
    >>> out.geom_type.tolist(), out.crs.to_epsg()
    (['MultiPolygon', 'MultiPolygon'], 27700)
    >>> [len(g.geoms) for g in sigdt.outlines(parcels, by=["farm", "farm"])]
    [2]
    """
    import geopandas as gpd
    import pandas as pd
    import shapely

    _check_method(method, leaf_elimination)
    check_errors(errors)
    if expect not in ("areas", "curves"):
        raise ValueError(f"expect must be 'areas' or 'curves', got {expect!r}")
    threads = _threads(n_jobs)
    one = isinstance(geometries, shapely.Geometry)
    frame = geometries if isinstance(geometries, gpd.GeoDataFrame) else None
    if one:
        series = gpd.GeoSeries([geometries])
    elif frame is not None:
        series = frame.geometry
    elif isinstance(geometries, gpd.GeoSeries):
        series = geometries
    else:
        series = gpd.GeoSeries(np.asarray(geometries, dtype=object).ravel())

    if by is None:
        keys: list[Any] = list(series.index)
        order, sizes = np.arange(len(series)), np.ones(len(series), np.int64)
        names = [f"row {k!r}" for k in keys]
        index = series.index
    else:
        labels, columns = _labels(by, frame, len(series))
        positions = pd.Series(np.arange(len(series)), index=series.index)
        groups, order, sizes = grouped_positions(positions.groupby(labels, sort=True, dropna=False))
        keys = list(groups)
        names = [f"group {k!r}" for k in keys]
        if len(columns) > 1:
            index = pd.MultiIndex.from_tuples(keys, names=columns)
        else:
            index = pd.Index(keys, name=columns[0] if columns else None)
    # Every geometry's vertices in group order at once, then each group's slice of them.
    ordered = np.asarray(series.values, dtype=object)[order]
    coords = np.ascontiguousarray(shapely.get_coordinates(ordered), dtype=np.float64)
    per_geometry = shapely.get_num_coordinates(ordered)
    ends = np.cumsum(per_geometry)[np.cumsum(sizes) - 1] if len(ordered) else sizes
    starts = np.r_[0, ends[:-1]] if len(ends) else ends
    arrays: list[np.ndarray | Failure] = [
        coords[a:b] if b > a else Failure(0, "no points: missing or empty")
        for a, b in zip(starts.tolist(), ends.tolist())
    ]
    results = run_groups(
        arrays,
        names,
        series.crs,
        method=method,
        leaf_elimination=leaf_elimination,
        expect=expect,
        threads=threads,
        progress=False,
        errors=errors,
    )
    warn_about_groups(results, names)
    done = [None if isinstance(r, Failure) else r for r in results]
    if expect == "areas":
        out = _layers.many_areas(done)
    else:
        out = [shapely.MultiLineString() if r is None else _layers.curves(r) for r in done]
    if one:
        return out[0]
    return gpd.GeoSeries(out, index=index, crs=series.crs, name=series.name)


def _labels(by: Any, frame: Any, n: int) -> tuple[Any, list[Any]]:
    """The group label of each geometry (columns of ``frame`` named by ``by``, or ``by`` as
    labels of its own) and the names of the columns (none for labels)."""
    names = by if isinstance(by, list) else [by]
    if frame is not None and all(isinstance(b, Hashable) and b in frame.columns for b in names):
        if isinstance(by, list):
            return [frame[b].to_numpy() for b in names], names
        return frame[by].to_numpy(), [by]
    labels = np.asarray(by, dtype=object)
    if labels.ndim != 1 or len(labels) != n:
        raise ValueError(
            f"by: {n} geometries need a column name or {n} group labels, got {by!r:.80}"
        )
    return labels, []
