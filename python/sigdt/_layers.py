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
    ``MultiPolygon``), built by shapely's array functions (:class:`ManyAreas`)."""
    builder = ManyAreas(len(results))
    for g, rec in enumerate(results):
        if rec is not None:
            builder.add(g, rec)
    return list(builder.build())


class ManyAreas:
    """:func:`areas` of many results at once: one ``Polygon`` at a time costs more than a
    small group's reconstruction, so the rings of every group are gathered and built by
    shapely's array functions in :meth:`build`. Longitude/latitude results go one by one,
    since their polygons may be split."""

    def __init__(self, groups: int) -> None:
        self._out = np.full(groups, _empty("areas"), dtype=object)
        # One-loop groups (the common case of small groups): their points and loop, joined
        # into one array in build().
        self._points: list[np.ndarray] = []
        self._loops: list[np.ndarray] = []
        self._shell_of: list[int] = []  # each one-loop group
        # Groups of several loops: their rings' coordinates.
        self._coords: list[np.ndarray] = []
        self._ring_sizes: list[int] = []  # each ring's vertices
        self._polygon_of: list[int] = []  # each ring's polygon
        self._group_of: list[int] = []  # each polygon's group

    def add(self, g: int, rec: Any) -> None:
        """Adds group ``g``'s result ``rec`` (a group not added has an empty area)."""
        fields = rec._fields
        offsets = fields["loop_offsets"]
        if offsets is None or len(offsets) < 2:
            return
        if _split(rec):
            self._out[g] = areas(rec)
        elif len(offsets) == 2:
            positions = fields["positions"]
            self._points.append(rec.points if positions is None else positions)
            self._loops.append(fields["loop_vertices"])
            self._shell_of.append(g)
        else:
            v, flat = rec.vertices, fields["loop_vertices"]
            for shell, holes in rec.polygons:
                for k in [shell, *holes]:
                    loop = flat[offsets[k] : offsets[k + 1]]
                    self._coords.append(v[loop])  # linearrings closes each ring
                    self._ring_sizes.append(len(loop))
                    self._polygon_of.append(len(self._group_of))
                self._group_of.append(g)

    def build(self) -> np.ndarray:
        """Every group's ``MultiPolygon``, in group order (an object array)."""
        import shapely

        if self._shell_of:
            # The one-loop groups' rings as the multi-loop groups' are: one vertex array,
            # each loop's indices moved to its group's place in it.
            sizes = np.fromiter(map(len, self._points), np.int64, len(self._points))
            lengths = np.fromiter(map(len, self._loops), np.int64, len(self._loops))
            bases = np.cumsum(sizes) - sizes
            flat = np.concatenate(self._loops) + np.repeat(bases, lengths)
            self._coords.insert(0, np.concatenate(self._points)[flat])
            shells = len(self._shell_of)
            self._ring_sizes[:0] = lengths.tolist()
            self._polygon_of = list(range(shells)) + [p + shells for p in self._polygon_of]
            self._group_of[:0] = self._shell_of
        if self._group_of:
            ring_of = np.repeat(np.arange(len(self._ring_sizes)), self._ring_sizes)
            rings = shapely.linearrings(np.concatenate(self._coords), indices=ring_of)
            polygons = shapely.polygons(rings, indices=np.asarray(self._polygon_of))
            # multipolygons wants its indices in increasing order, every one from 0 to the
            # largest: sort the polygons by group (each group's stay in order), number the
            # groups that have polygons consecutively, then place them.
            group_of = np.asarray(self._group_of)
            by_group = np.argsort(group_of, kind="stable")
            present, consecutive = np.unique(group_of[by_group], return_inverse=True)
            self._out[present] = shapely.multipolygons(polygons[by_group], indices=consecutive)
        return self._out
