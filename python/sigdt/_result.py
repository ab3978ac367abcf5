"""The result type of :func:`sigdt.reconstruct`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, cast, get_args

import numpy as np

from . import _core
from ._input import _is_geographic, _unwrapped
from ._outlines import Coordinates, Indices, ShapelyResult
from ._types import Finding, GeoJsonFeature, LeftOutReason, Method, Status, VerticesKind

if TYPE_CHECKING:  # pragma: no cover
    from geopandas import GeoDataFrame
    from matplotlib.axes import Axes

    from ._core import _Reconstruction

else:
    # Named at run time too, for documentation tools that evaluate annotations (the
    # extension's result dict; shapely and matplotlib are optional, imported when used).
    _Reconstruction = dict
    Axes = GeoDataFrame = Any

__all__ = ["Reconstruction"]

#: Names of :attr:`Reconstruction.status`, in the order the core defines them.
STATUSES: tuple[str, ...] = get_args(Status)


def _split(flat: Indices, offsets: Indices) -> list[Indices]:
    return [flat[offsets[k] : offsets[k + 1]] for k in range(len(offsets) - 1)]


def _same(a: Any, b: Any) -> bool:
    return a == b if isinstance(a, (str, dict)) else np.array_equal(a, b)


class Reconstruction:
    """The curve(s) reconstructed from a point set.

    Attributes
    ----------
    points : numpy.ndarray
        The input points, ``(n, 2)`` float64 (the array given, when it was already
        C-contiguous float64).
    edges : numpy.ndarray
        ``(m, 2)`` int64, each row ``[i, j]`` with ``i < j``, rows sorted.
    loops : list of numpy.ndarray
        Closed loops, each an int64 array of point indices in order (the closing edge is
        implied), counter-clockwise, starting at its smallest index; sorted.
    paths : list of numpy.ndarray
        Open paths, each an int64 array of point indices in order: for collinear input or
        two distinct points, the open curves found by ``"sig-auto"``, and from the
        graph-filter methods (``"crawl"``, ``"peel"``, ...) for open curves; with status
        ``"network"`` or ``"branching"`` paths end at junctions (a path may start and end
        at the same junction).
    junctions : numpy.ndarray
        The points with three edges or more, where curves cross, end on one another or
        share an end (status ``"network"``, or ``"branching"`` from methods that do not
        read junctions), sorted int64 indices; empty otherwise.
    polygons : list of tuple
        The loops grouped into polygons with holes, ``(shell, holes)`` indices into
        ``loops``; see the property.
    status : str
        ``"polygon"``, ``"polygons"``, ``"sculpting-stuck"``, ``"curves"`` (loops and open
        paths, not every point on a loop), ``"network"`` (``"sig-auto"``: curves meeting
        at junctions, read as such), ``"branching"`` (graph filters: some point has 3 or
        more edges, not read as a junction),
        ``"noisy"`` (``"sig-auto"``: the edges zigzag, the points are too noisy or sparse
        for a curve through them), ``"crossing"`` (``"fit-connect"``,
        ``"stretch-denoise"``: some edges cross), ``"unfinished"`` (``"fit-connect"``,
        ``"stretch-denoise"``: stopped at a pass or work limit, undecided points left out),
        ``"collinear"`` or ``"too-few-points"``.
    vertices : numpy.ndarray
        The coordinates that ``edges``, ``loops`` and ``paths`` index, ``(k, 2)`` float64:
        ``points`` itself, unless the method moved the points (``"stretch-denoise"``) or
        placed vertices of its own (``"optimal-transport"``); see ``vertices_kind``.
    vertices_kind : str
        ``"input"``, ``"moved"`` or ``"new"``.
    left_out : numpy.ndarray
        int64 indices (sorted) of the distinct points the method left out on purpose: inside
        the boundary when sculpting got stuck, outliers (``"sig-auto"``), or points
        ``"fit-connect"`` and ``"stretch-denoise"`` eliminated or could not fit; they get no
        edges.
    left_out_reasons : list of str
        Why each point of ``left_out`` was left out, in the same order: ``"inside"``,
        ``"outlier"``, ``"eliminated"``, ``"non-conforming"``, ``"unresolved"`` or ``"seam"``
        (a vertex between the ends of a cut at the antimeridian, in longitude/latitude).
    diagnosis : list of dict
        What the sampling check found, as dicts with ``kind``, ``count``, ``worst``, ``at``,
        ``point`` (its coordinates) and ``message``: where the loops and paths break the sampling condition they
        assume, with how much and at which point. Empty when the result reads as a sampled curve. A non-empty list, like a warning
        status, comes with a :class:`sigdt.SigdtWarning`; see ``warns``.
    warns : bool
        Whether the result may not be the curves the points came from (a warning status or
        a finding); ``reconstruct`` then raises a :class:`sigdt.SigdtWarning`.
    duplicates : numpy.ndarray
        ``(d, 2)`` int64 rows ``[duplicate, representative]``; duplicates get no edges.
    stats : dict
        Per-stage counts of the run.
    method : str
        The method that made the result.
    index : pandas.Index or None
        For a GeoSeries or GeoDataFrame input, its index: point ``i`` is row
        ``index[i]``, so ``index[rec.loops[0]]`` are the rows of the first loop in order.
        ``None`` for any other input.
    crs : pyproj.CRS or None
        For a GeoSeries or GeoDataFrame input, its coordinate reference system, which
        :meth:`to_geopandas` keeps. ``None`` for any other input.
    """

    __slots__ = ("_fields", "_lon_lat", "_polygons", "crs", "index", "points")

    def __init__(
        self,
        points: Coordinates,
        fields: _Reconstruction,
        index: Any = None,
        crs: Any = None,
        lon_lat: bool | None = None,
    ) -> None:
        self.points = points
        self.index = index
        self.crs = crs
        self._lon_lat = _is_geographic(crs) if lon_lat is None else bool(lon_lat)
        # The extension's dict as it is: what __eq__ compares and pickling stores.
        self._fields = fields
        self._polygons: list[tuple[int, list[int]]] | None = None

    @property
    def lon_lat(self) -> bool:
        """Whether the points are longitude/latitude in degrees (``lon_lat=True`` given, or a
        geographic coordinate reference system): then they were reconstructed in a local
        plane, and :meth:`layers` and the shapely and GeoPandas views split what crosses
        ±180° so that it is valid in EPSG:4326."""
        return self._lon_lat

    def layers(self) -> dict[str, list[Any]]:
        """The result as GIS layers of one geometry type each, as coordinate arrays (no
        shapely needed): ``"areas"``, a list of polygons, each a list of rings (shell, then
        holes; ``(k, 2)`` arrays, not closed); ``"paths"``, the open paths that end at no
        junction, and ``"networks"``, the paths with an end at a junction, lists of
        ``(k, 2)`` arrays. With :attr:`lon_lat`, split at the antimeridian (RFC 7946
        §3.1.9), each piece within longitude [-180, 180], as the command line writes GIS
        files.

        Examples
        --------
        >>> import sigdt
        >>> rec = sigdt.reconstruct([[179.9, 0], [-179.9, 0], [-179.9, 0.2], [179.9, 0.2]],
        ...                         lon_lat=True)
        >>> sorted([float(ring[:, 0].min()), float(ring[:, 0].max())]
        ...        for ring, *holes in rec.layers()["areas"])
        [[-180.0, -179.9], [179.9, 180.0]]
        """
        from . import _layers

        return _layers.coordinates(self)

    @property
    def edges(self) -> Indices:
        return self._fields["edges"]

    @property
    def loops(self) -> list[Indices]:
        return _split(self._fields["loop_vertices"], self._fields["loop_offsets"])

    @property
    def paths(self) -> list[Indices]:
        return _split(self._fields["path_vertices"], self._fields["path_offsets"])

    @property
    def junctions(self) -> Indices:
        edges = self.edges
        if len(edges) == 0:
            return np.empty(0, dtype=np.int64)
        return np.flatnonzero(np.bincount(edges.ravel()) >= 3).astype(np.int64)

    @property
    def status(self) -> Status:
        return cast(Status, self._fields["status"])

    @property
    def vertices(self) -> Coordinates:
        positions = self._fields["positions"]
        return self.points if positions is None else positions

    @property
    def vertices_kind(self) -> VerticesKind:
        return cast(VerticesKind, self._fields["vertices"])

    @property
    def left_out(self) -> Indices:
        return self._fields["left_out"]

    @property
    def left_out_reasons(self) -> list[LeftOutReason]:
        return cast("list[LeftOutReason]", self._fields["left_out_reasons"])

    @property
    def diagnosis(self) -> list[Finding]:
        return cast("list[Finding]", self._fields["diagnosis"])

    @property
    def warns(self) -> bool:
        return self._fields["status_warns"]

    @property
    def duplicates(self) -> Indices:
        return self._fields["duplicates"]

    @property
    def stats(self) -> dict[str, int]:
        return self._fields["stats"]

    @property
    def method(self) -> Method | None:
        """The method that made the result (``None`` for a result pickled before sigdt
        recorded it)."""
        return cast("Method | None", self._fields.get("method"))

    @property
    def is_manifold(self) -> bool:
        """True when the loops pass through every distinct point."""
        return self.status in ("polygon", "polygons")

    @property
    def polygons(self) -> list[tuple[int, list[int]]]:
        """The loops grouped into polygons with holes: ``(shell, holes)`` pairs of indices
        into :attr:`loops`, shells in loop order.

        A loop inside an even number of other loops is a shell, and the loops directly
        inside it are its holes; a loop inside a hole is a shell again. Decided in Rust with
        exact predicates (``sigdt::Reconstruction::polygons``) on first use, then kept.
        :meth:`to_shapely`, :meth:`to_geojson` and :meth:`plot` draw these polygons.

        Examples
        --------
        Two concentric circles with ``"sig-auto"``: the inner loop is a hole of the outer.

        >>> import numpy as np, sigdt
        >>> t = np.linspace(0, 2 * np.pi, 40, endpoint=False)
        >>> circle = np.c_[np.cos(t), np.sin(t)]
        >>> rec = sigdt.reconstruct(np.r_[3 * circle, circle])
        >>> len(rec.loops), rec.polygons
        (2, [(0, [1])])
        """
        if self._polygons is None and len(self._fields["loop_offsets"]) == 2:
            self._polygons = [(0, [])]  # one loop is one shell: nothing to decide
        if self._polygons is None:
            # Longitude/latitude nest as in the local plane once unwrapped: a ring across
            # ±180° jumps by 360° in the stored degrees.
            at = _unwrapped(self.vertices) if self.lon_lat else self.vertices
            self._polygons = _core.polygons(
                np.require(at, dtype=np.float64, requirements=["C", "A"]),
                np.require(self._fields["loop_vertices"], dtype=np.int64, requirements=["A"]),
                np.require(self._fields["loop_offsets"], dtype=np.int64, requirements=["A"]),
            )
        return self._polygons

    def to_shapely(self, *, faces: bool = False) -> ShapelyResult:
        """The result as a shapely geometry: ``Polygon`` (one loop), ``MultiPolygon``
        (several), ``LineString`` (one path, or empty), ``MultiLineString`` (several); with
        ``faces``, the regions the curves enclose, the faces of a network too, as a
        ``GeometryCollection`` of polygons. See :func:`sigdt.to_shapely`.

        Needs the optional dependency ``shapely`` (the ``shapely`` extra, or
        ``pip install shapely``).
        """
        from .shapely import to_shapely

        return to_shapely(self, faces=faces)

    def to_geopandas(self) -> GeoDataFrame:
        """The result as a GeoPandas ``GeoDataFrame`` in :attr:`crs`: one row per polygon
        (a loop with the loops directly inside it as holes, see :attr:`polygons`) and per
        open path, with the columns ``kind`` (``"polygon"`` or ``"path"``), ``method``, ``status``,
        ``warning``, ``diagnosis`` (the findings' messages, ``"; "``-separated) and
        ``n_vertices``; see :func:`sigdt.geopandas.to_geopandas`.

        Needs the optional dependency ``geopandas``.
        """
        from ._geodataframe import to_geopandas

        return to_geopandas(self)

    def to_geojson(self) -> GeoJsonFeature:
        """The result as a GeoJSON ``Feature`` (a JSON-serialisable dict) with the status
        and counts as properties: what ``sigdt reconstruct --format geojson`` writes for
        it, by the same writer (see :func:`sigdt.shapely.to_geojson` for the members).

        >>> import sigdt
        >>> sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]]).to_geojson()["properties"]
        {'status': 'polygon', 'status_message': 'one closed polygon through every point not left out', 'method': 'sig-auto', 'points': 4, 'edges': 4, 'loops': 1, 'paths': 0, 'duplicates': 0, 'warning': False}
        """
        from .shapely import to_geojson

        return to_geojson(self)

    def to_wkt(self) -> str:
        """The result as WKT (the geometry of :meth:`to_shapely`), without needing shapely;
        coordinates read back exactly. It is the text ``sigdt reconstruct --format wkt``
        writes for the result, by the same writer, without the final newline.

        >>> import sigdt
        >>> sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]]).to_wkt()
        'POLYGON ((0.0 0.0, 1.0 0.0, 1.0 1.0, 0.0 1.0, 0.0 0.0))'
        """
        from .shapely import to_wkt

        return to_wkt(self)

    def to_svg(self, width: int = 400) -> str:
        """A standalone SVG picture of the result, ``width`` pixels wide: loops filled, edges
        and points, framed and coloured as ``sigdt render`` draws them."""
        from .shapely import to_svg

        return to_svg(self, width)

    def plot(self, ax: Axes | None = None, **style: Any) -> Axes:
        """Draw points, edges and filled loops with matplotlib; returns the axes.

        ``style``: ``fill``, ``edge_color``, ``point_color``, ``linewidth``, ``markersize``,
        ``max_points`` (markers drawn at most; denser sets are thinned), and any keyword of
        matplotlib's ``LineCollection`` for the edges (see :func:`sigdt.plot.plot`). An
        existing axes title is kept.

        Needs the optional dependency ``matplotlib`` (the ``plot`` extra, or
        ``pip install matplotlib``).
        """
        from .plot import plot

        return plot(self, ax=ax, **style)

    def __repr__(self) -> str:
        return (
            f"Reconstruction(n_points={len(self.points)}, n_edges={len(self.edges)}, "
            f"n_loops={len(self._fields['loop_offsets']) - 1}, status={self.status!r})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Reconstruction):
            return NotImplemented
        mine, theirs = self._fields, other._fields
        return (
            np.array_equal(self.points, other.points)
            and self.crs == other.crs
            and self.lon_lat == other.lon_lat
            and mine.keys() == theirs.keys()
            and all(_same(mine[k], theirs[k]) for k in mine)
        )

    __hash__ = None  # type: ignore[assignment]  # mutable arrays inside

    def __reduce__(self) -> tuple[Any, ...]:
        return (
            Reconstruction,
            (self.points, self._fields, self.index, self.crs, self._lon_lat),
        )
