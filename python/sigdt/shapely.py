"""Shapely and GeoJSON views of a :class:`~sigdt.Reconstruction` (shapely imported lazily)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from ._result import Reconstruction

__all__ = ["from_shapely", "to_geojson", "to_shapely"]


def _rings(rec: Reconstruction) -> list[np.ndarray]:
    return [rec.points[loop] for loop in rec.loops]


def to_shapely(rec: Reconstruction) -> Any:
    """``Polygon`` for one loop, ``MultiPolygon`` for several (SIG-CONNECT2D loops are never
    nested), ``LineString`` for one open path or an empty result, ``MultiLineString`` for
    several paths."""
    import shapely

    rings = _rings(rec)
    lines = [rec.points[p] for p in rec.paths]
    if len(rings) == 1 and not lines:
        return shapely.Polygon(rings[0])
    if rings and not lines:
        return shapely.MultiPolygon([shapely.Polygon(r) for r in rings])
    if len(lines) == 1 and not rings:
        return shapely.LineString(lines[0])
    if lines and not rings:
        return shapely.MultiLineString(lines)
    if not rings and not lines:
        return shapely.LineString()
    return shapely.GeometryCollection(
        [shapely.Polygon(r) for r in rings] + [shapely.LineString(line) for line in lines]
    )


def from_shapely(geometry: Any) -> np.ndarray:
    """The vertices of a shapely geometry as an ``(n, 2)`` float64 array (ring closing
    points included once per ring), e.g. to reconstruct a polygon's outline from them."""
    import shapely

    return np.ascontiguousarray(shapely.get_coordinates(geometry), dtype=np.float64)


def to_geojson(rec: Reconstruction) -> dict[str, Any]:
    """A GeoJSON ``Feature``: the geometry of :func:`to_shapely` (without needing shapely),
    with status and counts as properties."""

    def ring(idx: np.ndarray) -> list[list[float]]:
        coords = rec.points[idx].tolist()
        return coords + coords[:1]

    loops, paths = rec.loops, rec.paths
    polygons = [[ring(loop)] for loop in loops]
    lines = [rec.points[p].tolist() for p in paths]
    geometries = [{"type": "Polygon", "coordinates": p} for p in polygons] + [
        {"type": "LineString", "coordinates": line} for line in lines
    ]
    if not geometries:
        geometry = None
    elif len(polygons) == 1 and not lines:
        geometry = geometries[0]
    elif polygons and not lines:
        geometry = {"type": "MultiPolygon", "coordinates": polygons}
    elif len(lines) == 1 and not polygons:
        geometry = geometries[0]
    elif lines and not polygons:
        geometry = {"type": "MultiLineString", "coordinates": lines}
    else:
        geometry = {"type": "GeometryCollection", "geometries": geometries}
    properties: dict[str, Any] = {
        "status": rec.status,
        "points": len(rec.points),
        "edges": len(rec.edges),
        "loops": len(loops),
        "paths": len(paths),
        "duplicates": len(rec.duplicates),
    }
    if len(rec.left_out):
        properties["left_out"] = rec.left_out.tolist()
    return {"type": "Feature", "geometry": geometry, "properties": properties}
