"""A result as three layers of one geometry type each: ``areas`` (``MultiPolygon``), ``paths``
(``MultiLineString``: open curves) and ``networks`` (``MultiLineString``: the curves that meet
at junctions), as GIS files want them; in longitude/latitude split at the antimeridian.

A GIS layer, a Shapefile above all, holds one geometry type: a column of polygons, lines and
collections cannot be written. The CLI writes the same three layers
(``sigdt_io::gis::layers``) and splits with the same code (``sigdt_io::gis::antimeridian``,
RFC 7946 §3.1.9), so that a ring through points at +179.9° and -179.9° is two valid polygons
that meet at ±180°, not one that spans the world.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    import shapely

    from ._outlines import Outlines

#: The layers, in the order GIS files list them.
LAYERS = ("areas", "paths", "networks")


def _split(rec: Outlines) -> bool:
    """Whether ``rec``'s coordinates are longitude/latitude, to be split at ±180°."""
    return rec.lon_lat


def polygon_rings(rec: Outlines) -> list[list[np.ndarray]]:
    """``rec``'s polygons (:attr:`~sigdt.Reconstruction.polygons`: loops with the loops
    directly inside them as holes) as lists of rings (not closed); in longitude/latitude
    split at the antimeridian, so possibly more than there are shells."""
    from . import _core

    v = rec.vertices
    out: list[list[np.ndarray]] = []
    for shell, holes in rec.polygons:
        rings = [np.ascontiguousarray(v[rec.loops[k]]) for k in [shell, *holes]]
        out.extend(_core.split_polygon_at_antimeridian(rings) if _split(rec) else [rings])
    return out


def line_coordinates(rec: Outlines, chains: list[Any]) -> list[np.ndarray]:
    """The vertex chains ``chains`` of ``rec`` as coordinate arrays, split as
    :func:`polygon_rings` are."""
    from . import _core

    v = rec.vertices
    out: list[np.ndarray] = []
    for chain in chains:
        line = np.ascontiguousarray(v[chain])
        out.extend(_core.split_line_at_antimeridian(line) if _split(rec) else [line])
    return out


def coordinates(rec: Outlines) -> dict[str, list[Any]]:
    """:meth:`sigdt.Reconstruction.layers`: the three layers as coordinate arrays."""
    free, meeting = _paths_by_junction(rec)
    return {
        "areas": polygon_rings(rec),
        "paths": line_coordinates(rec, free),
        "networks": line_coordinates(rec, meeting),
    }


def polygons(rec: Outlines) -> list[shapely.Polygon]:
    """:func:`polygon_rings` as shapely polygons."""
    import shapely

    return [shapely.Polygon(rings[0], rings[1:]) for rings in polygon_rings(rec)]


def lines(rec: Outlines, chains: list[Any]) -> list[shapely.LineString]:
    """:func:`line_coordinates` as shapely lines."""
    import shapely

    return [shapely.LineString(line) for line in line_coordinates(rec, chains)]


def areas(rec: Outlines) -> shapely.MultiPolygon:
    """:func:`polygons` as one ``MultiPolygon``, empty when there are none."""
    import shapely

    if not rec.loops:
        return _empty("areas")
    return shapely.MultiPolygon(polygons(rec))


def _paths_by_junction(rec: Outlines) -> tuple[list[Any], list[Any]]:
    """``rec``'s paths that end at no junction, and those with an end at one."""
    chains = rec.paths
    if not chains:
        return [], []
    junctions = set(np.asarray(rec.junctions).tolist())
    free, meeting = [], []
    for p in chains:
        (meeting if int(p[0]) in junctions or int(p[-1]) in junctions else free).append(p)
    return free, meeting


def _multi_lines(rec: Outlines, chains: list[Any]) -> shapely.MultiLineString:
    import shapely

    if not chains:
        return _empty("lines")
    return shapely.MultiLineString(lines(rec, chains))


def _empty(kind: str) -> Any:
    """One empty ``MultiPolygon`` and ``MultiLineString``, shared (geometries are immutable;
    parsing a new one costs more than the rest of a small group's row)."""
    import shapely

    if not _EMPTY:
        _EMPTY["areas"] = shapely.MultiPolygon()
        _EMPTY["lines"] = shapely.MultiLineString()
    return _EMPTY[kind]


_EMPTY: dict[str, Any] = {}


def paths(rec: Outlines) -> shapely.MultiLineString:
    """``rec``'s open paths that end at no junction, as one ``MultiLineString`` (empty when
    there are none); in a geographic coordinate reference system split at the antimeridian."""
    return _multi_lines(rec, _paths_by_junction(rec)[0])


def networks(rec: Outlines) -> shapely.MultiLineString:
    """``rec``'s paths with an end at a junction (:attr:`~sigdt.Reconstruction.junctions`:
    where curves cross or end on one another), as one ``MultiLineString``; split as
    :func:`paths` is."""
    return _multi_lines(rec, _paths_by_junction(rec)[1])


def lines_of(rec: Outlines | None) -> tuple[Any, Any]:
    """:func:`paths` and :func:`networks` of ``rec`` at once (empty for ``None``)."""
    if rec is None or len(rec._fields["path_offsets"]) < 2:
        return _empty("lines"), _empty("lines")
    free, meeting = _paths_by_junction(rec)
    return _multi_lines(rec, free), _multi_lines(rec, meeting)


def curves(rec: Outlines) -> shapely.MultiLineString:
    """Every curve of ``rec`` as lines: each loop closed (its first vertex repeated), then
    the paths; split as :func:`paths` is."""
    import shapely

    closed = [np.r_[loop, loop[:1]] for loop in rec.loops]
    return shapely.MultiLineString(lines(rec, closed + list(rec.paths)))


def many_areas(results: list[Any]) -> list[Any]:
    """:func:`areas` of many results (``None`` for a group without one: an empty
    ``MultiPolygon``), built by shapely's array functions: one ``Polygon`` at a time costs
    more than a small group's reconstruction. Longitude/latitude results go one by one, since
    their polygons may be split."""
    import shapely

    coords: list[np.ndarray] = []
    ring_sizes: list[int] = []  # each ring's vertices
    polygon_of: list[int] = []  # each ring's polygon
    group_of: list[int] = []  # each polygon's group
    out = np.empty(len(results), dtype=object)
    empty = _empty("areas")
    for g, rec in enumerate(results):
        # The loops straight from the result's flat arrays (rec.loops splits them anew).
        fields = None if rec is None else rec._fields
        offsets = None if fields is None else fields["loop_offsets"]
        if offsets is None or len(offsets) < 2:
            out[g] = empty
        elif _split(rec):
            out[g] = areas(rec)
        elif len(offsets) == 2:  # one loop: one shell, the common case of small groups
            positions = fields["positions"]
            ring = (rec.points if positions is None else positions)[fields["loop_vertices"]]
            coords.append(ring)
            ring_sizes.append(len(ring))
            polygon_of.append(len(group_of))
            group_of.append(g)
        else:
            v, flat = rec.vertices, rec._fields["loop_vertices"]
            for shell, holes in rec.polygons:
                for k in [shell, *holes]:
                    loop = flat[offsets[k] : offsets[k + 1]]
                    coords.append(v[loop])  # linearrings closes each ring
                    ring_sizes.append(len(loop))
                    polygon_of.append(len(group_of))
                group_of.append(g)
    if group_of:
        ring_of = np.repeat(np.arange(len(ring_sizes)), ring_sizes)  # each vertex's ring
        rings = shapely.linearrings(np.concatenate(coords), indices=ring_of)
        polygons = shapely.polygons(rings, indices=np.asarray(polygon_of))
        # multipolygons wants every index from 0 to the largest: number the groups that
        # have polygons consecutively, then place them.
        present, consecutive = np.unique(np.asarray(group_of), return_inverse=True)
        out[present] = shapely.multipolygons(polygons, indices=consecutive)
    return list(out)
