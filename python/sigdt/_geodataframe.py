"""A result as a ``GeoDataFrame`` (:func:`sigdt.geopandas.to_geopandas`).

Apart from :mod:`sigdt.geopandas` so that :class:`Reconstruction`'s method reaches it
without importing the grouping code, which builds results.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from geopandas import GeoDataFrame

    from ._outlines import Outlines
else:
    GeoDataFrame = Any

#: The columns of :func:`to_geopandas`, geometry aside.
CURVE_COLUMNS = ["kind", "method", "status", "warning", "diagnosis", "n_vertices"]


def _diagnosis(rec: Outlines) -> str:
    findings = rec.diagnosis
    return "; ".join(f["message"] for f in findings) if findings else ""


def to_geopandas(rec: Outlines) -> GeoDataFrame:
    """``rec`` as a ``GeoDataFrame`` in ``rec.crs``: one row per polygon (a loop with the
    loops directly inside it as holes, :attr:`Reconstruction.polygons`) and one per open
    path (a ``LineString``).

    Columns: ``kind`` (``"polygon"`` or ``"path"``), ``method``, ``status``, ``warning`` (whether the
    result may not be the points' curves), ``diagnosis`` (the sampling check's findings,
    ``"; "``-separated, empty when there are none), ``n_vertices`` and ``geometry``.

    Examples
    --------
    >>> import geopandas as gpd, shapely, sigdt
    >>> points = gpd.GeoSeries(shapely.points([[0, 0], [9, 0], [9, 9], [0, 9]]), crs=27700)
    >>> frame = sigdt.reconstruct(points).to_geopandas()
    >>> frame[["kind", "status", "n_vertices"]].to_dict("records"), frame.crs.to_epsg()
    ([{'kind': 'polygon', 'status': 'polygon', 'n_vertices': 4}], 27700)
    """
    import geopandas as gpd
    import shapely

    v = rec.vertices
    geometries: list[Any] = []
    kinds: list[str] = []
    counts: list[int] = []
    for shell, holes in rec.polygons:
        rings = [v[rec.loops[k]] for k in [shell, *holes]]
        geometries.append(shapely.Polygon(rings[0], rings[1:]))
        kinds.append("polygon")
        counts.append(sum(len(r) for r in rings))
    for path in rec.paths:
        geometries.append(shapely.LineString(v[path]))
        kinds.append("path")
        counts.append(len(path))
    n = len(geometries)
    columns = {
        "kind": kinds,
        "method": [rec.method] * n,
        "status": [rec.status] * n,
        "warning": [rec.warns] * n,
        "diagnosis": [_diagnosis(rec)] * n,
        "n_vertices": np.asarray(counts, dtype=np.int64),
    }
    return gpd.GeoDataFrame(columns, geometry=geometries, crs=rec.crs)
