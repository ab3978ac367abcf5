"""Shapely and GeoJSON views of a :class:`~sigdt.Reconstruction` (shapely imported lazily)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from ._result import Reconstruction

__all__ = ["from_shapely", "to_geojson", "to_shapely"]


def _rings(rec: Reconstruction) -> list[np.ndarray]:
    return [rec.vertices[loop] for loop in rec.loops]


def to_shapely(rec: Reconstruction) -> Any:
    """The loops as polygons and the open paths as lines. A loop inside another one (SIG-AUTO
    returns nested curves, such as the two outlines of an ``O``) is a hole of it, and a loop
    inside that hole is a new polygon again: :attr:`~sigdt.Reconstruction.polygons`, decided
    with exact predicates. ``Polygon`` for one polygon, ``MultiPolygon`` for several,
    ``LineString`` for one open path or an empty result, ``MultiLineString`` for several
    paths, ``GeometryCollection`` for polygons and paths together."""
    import shapely

    rings = _rings(rec)
    polygons = [
        shapely.Polygon(rings[shell], [rings[h] for h in holes]) for shell, holes in rec.polygons
    ]
    lines = [rec.vertices[p] for p in rec.paths]
    if len(polygons) == 1 and not lines:
        return polygons[0]
    if polygons and not lines:
        return shapely.MultiPolygon(polygons)
    if len(lines) == 1 and not polygons:
        return shapely.LineString(lines[0])
    if lines and not polygons:
        return shapely.MultiLineString(lines)
    if not polygons and not lines:
        return shapely.LineString()
    return shapely.GeometryCollection(polygons + [shapely.LineString(line) for line in lines])


def from_shapely(geometry: Any) -> np.ndarray:
    """The vertices of a shapely geometry as an ``(n, 2)`` float64 array (ring closing
    points included once per ring), e.g. to reconstruct a polygon's outline from them."""
    import shapely

    return np.ascontiguousarray(shapely.get_coordinates(geometry), dtype=np.float64)


def to_geojson(rec: Reconstruction) -> dict[str, Any]:
    """A GeoJSON ``Feature``: the geometry of :func:`to_shapely` (without needing shapely),
    with status and counts as properties."""

    def ring(idx: np.ndarray) -> list[list[float]]:
        coords = rec.vertices[idx].tolist()
        return coords + coords[:1]

    loops, paths = rec.loops, rec.paths
    polygons = [
        [ring(loops[shell])] + [ring(loops[h][::-1]) for h in holes]
        for shell, holes in rec.polygons
    ]
    lines = [rec.vertices[p].tolist() for p in paths]
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
        properties["left_out_reasons"] = list(rec.left_out_reasons)
    return {"type": "Feature", "geometry": geometry, "properties": properties}
