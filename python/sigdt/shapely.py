"""Shapely, GeoJSON, WKT and SVG views of a :class:`~sigdt.Reconstruction` (shapely imported
lazily; GeoJSON, WKT and SVG need only numpy)."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, cast

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from ._outlines import Coordinates, Outlines, ShapelyResult
    from ._types import GeoJsonFeature

__all__ = ["from_shapely", "to_geojson", "to_shapely", "to_svg", "to_wkt"]


def to_shapely(rec: Outlines, *, faces: bool = False) -> ShapelyResult:
    """The result as a shapely geometry: loops as polygons, open paths as lines.

    A loop inside another one (SIG-AUTO returns nested curves, such as the two outlines of
    an ``O``) is a hole of it, and a loop inside that hole is a new polygon again
    (:attr:`~sigdt.Reconstruction.polygons`, decided with exact predicates). The paths of
    a network (status ``"network"``) end at its junctions, so their lines are noded.

    Parameters
    ----------
    rec : Reconstruction
        A result of :func:`sigdt.reconstruct`.
    faces : bool, default False
        Return the regions the curves enclose instead: the polygons of the loops, and the
        faces the paths bound (``shapely.polygonize`` of the noded lines: the cells of a
        grid, the countries between borders); paths that bound nothing are dropped.

    Returns
    -------
    shapely.Geometry
        ``Polygon`` for one polygon, ``MultiPolygon`` for several, ``LineString`` for one
        open path or an empty result, ``MultiLineString`` for several paths,
        ``GeometryCollection`` for polygons and paths together. With ``faces``: a
        ``GeometryCollection`` of polygons (faces of a network share edges, which a
        ``MultiPolygon`` does not allow; empty when nothing is enclosed).

    Raises
    ------
    ImportError
        shapely is not installed (the ``shapely`` extra).

    Examples
    --------
    >>> import sigdt
    >>> sigdt.to_shapely(sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]])).area
    1.0

    A theta: a circle and a chord crossing it, read as a network of three paths between
    two junctions, enclosing two faces.

    >>> import numpy as np
    >>> t = np.linspace(0, 2 * np.pi, 48, endpoint=False)
    >>> chord = np.c_[np.linspace(-1, 1, 17)[1:-1], np.zeros(15)]
    >>> rec = sigdt.reconstruct(np.r_[np.c_[np.cos(t), np.sin(t)], chord])
    >>> rec.status, len(rec.junctions), len(rec.to_shapely().geoms)
    ('network', 2, 3)
    >>> len(rec.to_shapely(faces=True).geoms)
    2
    """
    import shapely

    from . import _layers

    # In longitude/latitude split at the antimeridian (valid in EPSG:4326).
    polygons = _layers.polygons(rec)
    lines = _layers.lines(rec, list(rec.paths))
    if faces:
        enclosed = shapely.polygonize(lines).geoms
        return shapely.GeometryCollection(polygons + list(enclosed))
    if len(polygons) == 1 and not lines:
        return polygons[0]
    if polygons and not lines:
        return shapely.MultiPolygon(polygons)
    if len(lines) == 1 and not polygons:
        return lines[0]
    if lines and not polygons:
        return shapely.MultiLineString(lines)
    if not polygons and not lines:
        return shapely.LineString()
    return shapely.GeometryCollection(polygons + lines)


def from_shapely(geometry: object) -> Coordinates:
    """The vertices of shapely geometries as an ``(n, 2)`` float64 array of points.

    Use it to reconstruct from the vertices of lines or polygons; a ring's closing vertex
    repeats its first, and sigdt treats it as a duplicate (no edges).

    Parameters
    ----------
    geometry : shapely.Geometry or array_like of them
        Any geometry or geometries; every vertex, in order.

    Returns
    -------
    numpy.ndarray
        ``(n, 2)`` float64 (z values dropped).

    Raises
    ------
    ImportError
        shapely is not installed (the ``shapely`` extra).

    Examples
    --------
    >>> import shapely, sigdt
    >>> sigdt.from_shapely(shapely.LineString([(0, 0), (1, 0), (1, 1)]))
    array([[0., 0.],
           [1., 0.],
           [1., 1.]])
    """
    import shapely

    return np.ascontiguousarray(shapely.get_coordinates(geometry), dtype=np.float64)


def _text(rec: Outlines, fmt: str) -> str:
    """The result in ``fmt`` by the CLI's writer (``sigdt_io::text::write_reconstruction``)."""
    from . import _core

    points = np.require(np.asarray(rec.points).reshape(-1, 2), np.float64, ["C", "A"])
    return _core.write_reconstruction(points, rec._fields, fmt)


def to_geojson(rec: Outlines) -> GeoJsonFeature:
    """A GeoJSON ``Feature``: the geometry of :func:`to_shapely` (without needing shapely),
    with status and counts as properties, the points left out with their reasons, whether
    the result warns, and the sampling check's findings.

    It is what ``sigdt reconstruct --format geojson`` writes for the same result, read with
    :func:`json.loads`: one writer makes both (``sigdt_io::text::write_reconstruction``). The
    properties are ``status``, ``points`` (the input's count), ``vertices`` (only when the
    method moved the points or placed its own: the count of the positions the geometry
    uses), ``edges``, ``loops``, ``paths``, ``duplicates``, ``left_out`` and
    ``left_out_reasons`` (when points were left out), ``junctions`` (the points with three
    edges or more, when there are), ``warning`` and ``diagnosis`` (when the sampling check
    found something). A coordinate that is not finite is ``null``.
    """
    return cast("GeoJsonFeature", json.loads(_text(rec, "geojson")))


def to_wkt(rec: Outlines) -> str:
    """The geometry of :func:`to_shapely` as WKT, without needing shapely: the text of
    ``sigdt reconstruct --format wkt`` for the same result (one writer makes both), without
    its final newline. Coordinates are written so that they read back exactly (``1.0``,
    ``1e-7``, ``3e20``). An empty result is ``GEOMETRYCOLLECTION EMPTY``."""
    return _text(rec, "wkt").rstrip("\n")


def to_svg(rec: Outlines, width: int = 400) -> str:
    """A standalone SVG picture ``width`` pixels wide: the loops filled (holes even-odd), the
    edges and the points, y pointing up, framed and coloured as ``sigdt render`` draws them
    (any finite coordinates, up to ``±sys.float_info.max``, give a picture).

    >>> import sigdt
    >>> svg = sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]]).to_svg(width=100)
    >>> svg.splitlines()[0]
    '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 100">'
    """
    from . import _core

    if width < 16:
        raise ValueError(f"width must be at least 16 pixels, got {width}")
    pts, verts = np.asarray(rec.points).reshape(-1, 2), np.asarray(rec.vertices).reshape(-1, 2)
    # The CLI's frame (crates/sigdt-lab/src/render/frame.rs): it measures extents beyond
    # f64's range in exact quarter units and draws a box too small to scale as a point.
    every = np.ascontiguousarray(np.concatenate([pts, verts]), dtype=np.float64)
    height, at = _core.place(every, float(width))
    height = int(height)
    dots, at = at[: len(pts)], at[len(pts) :]

    def xy(k: int) -> str:
        return f"{at[k][0]:.2f},{at[k][1]:.2f}"

    out = [
        (
            f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}">'
        ),
        f"<title>{len(pts)} points, {len(rec.edges)} edges, {rec.status}</title>",
        '<rect width="100%" height="100%" fill="#ffffff"/>',
    ]
    for shell, holes in rec.polygons:
        d = " ".join("M " + " L ".join(xy(i) for i in rec.loops[k]) + " Z" for k in [shell, *holes])
        out.append(f'<path fill="#dce8f4" fill-rule="evenodd" d="{d}"/>')
    if len(rec.edges):
        d = " ".join(f"M {xy(i)} L {xy(j)}" for i, j in rec.edges)
        out.append(f'<path fill="none" stroke="#1a1a1a" stroke-width="1.2" d="{d}"/>')
    for cx, cy in dots:
        out.append(f'<circle cx="{cx:.2f}" cy="{cy:.2f}" r="1.6" fill="#1a1a1a"/>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
