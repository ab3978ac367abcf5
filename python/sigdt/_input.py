"""Reading what users pass in: point arrays and method names, checked once at the entry."""

from __future__ import annotations

from typing import Any

import numpy as np

from . import _core
from .errors import InvalidInputError

__all__ = ["LEAF_ELIMINATION"]

#: Default of ``leaf_elimination``: on (measured better on every category of the labelled
#: curves; see docs/algorithms.md).
LEAF_ELIMINATION = True


def _geometry_points(points: Any) -> tuple[np.ndarray, Any] | None:
    """The coordinates of a shapely or GeoPandas input and the GeoPandas index (``None`` for
    shapely), or ``None`` when ``points`` is neither. Neither library is imported here: the
    input's type says what it is."""
    module = type(points).__module__ or ""
    if module.startswith("geopandas"):
        series = points.geometry if type(points).__name__ == "GeoDataFrame" else points
        kinds = set(series.geom_type.dropna().unique())
        if kinds - {"Point"}:
            raise InvalidInputError(
                f"a {type(points).__name__} of {sorted(kinds)} geometries: sigdt reads one "
                "point per row; for the vertices of other geometries pass "
                "series.get_coordinates() (its index repeats each row's)"
            )
        _refuse_empty_points(np.asarray(series.values), series.index)
        coords = np.c_[series.x.to_numpy(dtype=np.float64), series.y.to_numpy(dtype=np.float64)]
        return coords, series.index
    if module.startswith("shapely"):
        kind = getattr(points, "geom_type", type(points).__name__)
        if kind not in ("MultiPoint", "Point"):
            raise InvalidInputError(
                f"a shapely {kind}: pass a MultiPoint, a sequence of Points, or the vertices "
                "of a geometry with sigdt.from_shapely(geometry)"
            )
        return _shapely_points(points), None
    if isinstance(points, (list, tuple)) and points:
        first = type(points[0]).__module__ or ""
        if first.startswith("shapely"):
            kinds = {getattr(p, "geom_type", type(p).__name__) for p in points}
            if kinds != {"Point"}:
                raise InvalidInputError(
                    f"a sequence of shapely {sorted(kinds)}: sigdt reads a sequence of Points"
                )
            return _shapely_points(points), None
    return None


def _shapely_points(points: Any) -> np.ndarray:
    """The coordinates of a shapely ``Point``, ``MultiPoint`` or sequence of points, one row
    per point."""
    import shapely

    parts = shapely.get_parts(points)
    _refuse_empty_points(parts)
    return np.ascontiguousarray(shapely.get_coordinates(parts), dtype=np.float64).reshape(-1, 2)


def _refuse_empty_points(geometries: np.ndarray, index: Any = None) -> None:
    """Refuses missing (``None``) and empty points, naming the first by its position (and
    its ``index`` label, for GeoPandas rows). Shapely reads no coordinates from them, so
    every later point would move up one position and the result's indices would name the
    wrong points (GeoPandas gives them NaN coordinates)."""
    import shapely

    missing = shapely.is_missing(geometries)
    bad = missing | shapely.is_empty(geometries)
    if bad.any():
        k = int(np.argmax(bad))
        if index is None:
            where, drop = f"point {k}", ""
        else:
            # The label as a Python value (20, not numpy's np.int64(20)).
            where = f"row {index[k : k + 1].tolist()[0]!r} (position {k})"
            drop = " (rows[~(rows.is_empty | rows.geometry.isna())])"
        what = "missing (None)" if missing[k] else "an empty point, without coordinates"
        raise InvalidInputError(
            f"{where} is {what} ({int(bad.sum())} of {len(bad)} missing or empty): every "
            "point needs coordinates, so that the result's indices name the input's points; "
            f"drop them first{drop}"
        )


def _as_points_and_index(points: Any) -> tuple[np.ndarray, Any, Any]:
    """:func:`_as_points`, and the index and coordinate reference system of a GeoPandas
    input (``None`` otherwise)."""
    geometric = _geometry_points(points)
    if geometric is not None:
        coords, index = geometric
        return _as_points(coords), index, getattr(points, "crs", None)
    return _as_points(points), None, None


def _is_geographic(crs: Any) -> bool:
    """Whether a GeoPandas (pyproj) coordinate reference system is longitude/latitude."""
    return bool(getattr(crs, "is_geographic", False))


def _unwrapped(lon_lat: np.ndarray) -> np.ndarray:
    """Longitude/latitude with each longitude shifted by whole turns to within 180° of the
    points' circular mean longitude (the centre of their local plane): a chart without a cut
    where the points are, so that rings across ±180° nest and overlap as on the ground."""
    lon = np.radians(lon_lat[:, 0])
    centre = np.degrees(np.arctan2(np.sin(lon).sum(), np.cos(lon).sum())) if len(lon) else 0.0
    out = np.array(lon_lat, dtype=np.float64, copy=True)
    out[:, 0] = centre + (out[:, 0] - centre + 180.0) % 360.0 - 180.0
    return out


def _as_points(points: Any) -> np.ndarray:
    geometric = _geometry_points(points)
    if geometric is not None:
        points = geometric[0]
    if np.ma.isMaskedArray(points) and np.ma.getmaskarray(points).any():
        raise InvalidInputError(
            "points is a masked array with masked values: drop them first "
            "(points[~points.mask.any(axis=1)].data) or fill them (points.filled(...))"
        )
    try:
        given = np.asarray(np.ma.getdata(points))
        if np.iscomplexobj(given):
            raise InvalidInputError(
                "points are complex numbers: pass an (n, 2) real array, for example "
                "np.c_[z.real, z.imag]"
            )
        # C-contiguous and aligned (arrays deserialised from message frames, as Dask workers
        # receive them, may be unaligned); copies only when one of these does not hold.
        array = np.require(given, dtype=np.float64, requirements=["C", "A"])
    except (TypeError, ValueError, OverflowError) as e:
        if isinstance(e, InvalidInputError):
            raise
        raise InvalidInputError(f"points cannot be read as an (n, 2) float array: {e}") from e
    if array.ndim <= 2 and array.size == 0 and array.shape[0] == 0:
        return array.reshape(0, 2)  # no rows: no points, whatever the width
    if array.ndim == 2 and array.shape[1] > 2:
        raise InvalidInputError(
            f"points must have shape (n, 2), got {array.shape}: select the x and y columns, "
            "for example points[:, :2]"
        )
    if array.ndim != 2 or array.shape[1] != 2:
        raise InvalidInputError(f"points must have shape (n, 2), got {array.shape}")
    return array


def _check_method(method: str, leaf_elimination: bool = LEAF_ELIMINATION) -> None:
    if not isinstance(method, str):
        raise TypeError(f"method must be a str, got {type(method).__name__}")
    if method not in _core.METHODS:
        raise ValueError(f"unknown method {method!r} (expected one of: {', '.join(_core.METHODS)})")
    if not leaf_elimination and method != "sig-connect2d":
        # An option without effect would hide that another method ran than the one meant.
        raise ValueError(
            f"leaf_elimination=False applies to method='sig-connect2d' only; {method!r} does "
            "not use it"
        )
