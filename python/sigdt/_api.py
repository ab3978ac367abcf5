"""The public functions of :mod:`sigdt`: thin, documented wrappers of the Rust core."""

from __future__ import annotations

import contextlib
import gc
import operator
import os
import warnings
from collections.abc import Iterable, Iterator
from typing import Any

from . import _core
from ._input import (
    LEAF_ELIMINATION,
    _as_points,
    _as_points_and_index,
    _check_method,
    _is_geographic,
)
from ._outlines import Coordinates, Indices
from ._result import Reconstruction
from ._types import Expect, Method
from .errors import InvalidInputError, SigdtWarning


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover  # not on Linux
        return os.cpu_count() or 1


def _threads(n_jobs: Any) -> int | None:
    """The thread count for ``n_jobs`` (``None``: the extension's pool of one per core)."""
    if n_jobs is None:
        return None
    try:
        valid = not isinstance(n_jobs, bool) and operator.index(n_jobs) != 0
    except TypeError:
        valid = False
    if not valid:
        raise ValueError(f"n_jobs must be a non-zero int or None, got {n_jobs!r}")
    n, cores = operator.index(n_jobs), _cores()
    return min(n, cores) if n > 0 else max(1, cores + 1 + n)


@contextlib.contextmanager
def _no_cycle_collection() -> Iterator[None]:
    """Python's cycle collector paused while results are built: 10⁵ results are 10⁶ dicts,
    lists and arrays, none in a cycle, and each full collection walks all of them, which made
    building them quadratic (3 s of 4 for 40,000 sets of 10 points)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def _warning_text(results: list[Reconstruction], names: list[str] | None = None) -> str | None:
    """What the one warning for ``results`` says (``None``: nothing warns): the first that
    warns, by name, with how many more do, and its findings."""
    # What warns is decided once, in Rust (Reconstruction::warns: the status or a finding of
    # the sampling check).
    bad = [(k, r) for k, r in enumerate(results) if r.warns]
    if not bad:
        return None
    k, first = bad[0]
    name = names[k] if names is not None else f"point set {k}"
    where = name + (f" (and {len(bad) - 1} more)" if len(bad) > 1 else "")
    found = [f["message"] for f in first.diagnosis]
    if first._fields["status_is_warning"]:
        found.insert(0, f"{first.status}: {first._fields['status_message']}")
    return f"{where}: " + "; ".join(found) + " (the result may not be the points' curves)"


def _warn_about(results: list[Reconstruction], many: bool, names: list[str] | None = None) -> None:
    text = _warning_text(results, names)
    if text is None:
        return
    if not many:
        text = text.split(": ", 1)[1]
    # stacklevel 3: the warning points at the caller of reconstruct / reconstruct_many.
    warnings.warn(text, SigdtWarning, stacklevel=3)


__all__ = ["proximity_graph", "read_points", "reconstruct", "reconstruct_many"]


def reconstruct(
    points: Any,
    *,
    method: Method = "sig-auto",
    leaf_elimination: bool = LEAF_ELIMINATION,
    expect: Expect = "curves",
    lon_lat: bool | None = None,
) -> Reconstruction:
    """Reconstruct the closed curve(s) through a set of 2D points.

    Parameters
    ----------
    points : array_like, shape (n, 2), or shapely / GeoPandas points
        Anything numpy turns into an ``(n, 2)`` real float64 array (kept as
        ``rec.points``; the extension works on its own copy, so the result depends only on
        the values at the call); a shapely ``MultiPoint`` or a sequence of shapely
        ``Point`` objects; or a GeoPandas ``GeoSeries`` / ``GeoDataFrame`` of points, whose
        index is kept as ``rec.index`` so that results map back to rows, and whose
        coordinate reference system is kept as ``rec.crs``. A geographic system
        (longitude/latitude) is reconstructed in a plane centred on the points
        (azimuthal equidistant), where distances are lengths on the ground; the result's
        coordinates stay in degrees.
    method : str, default "sig-auto"
        The reconstruction method (see ``sigdt.METHODS``). The default, ``"sig-auto"``,
        keeps open curves open and nested curves separate (closed loops in ``loops``, open
        curves in ``paths``), leaves outliers out and reads noise at a coarser scale
        (docs/sig-auto.md). ``"sig-connect2d"`` is the paper's method: closed polygons
        through every point.
    leaf_elimination : bool, default True
        Give every SIGDT leaf its shortest missing Delaunay edge before inflating
        (SIG-CONNECT2D only: ``False`` with another method is a ``ValueError``).
    expect : {"curves", "areas"}, default "curves"
        What the points outline, as far as you know. ``"areas"``: every curve is a closed
        outline (polygon vertices, parcels, islands); SIG-AUTO then closes an open reading
        where a polygon through the points fits as well, and any open path left is a
        finding, ``"open-outlines"``, with a warning.
    lon_lat : bool, optional
        Whether the points are longitude and latitude in degrees; by default the input's
        coordinate reference system says (GeoPandas), else they are plane coordinates.
        Degrees are reconstructed in a plane centred on the points; the result's
        :meth:`~Reconstruction.layers` and shapely views are split at the antimeridian.

    Returns
    -------
    Reconstruction
        Edges, ordered loops and a status. Fewer than three distinct points, collinear
        points and duplicates give documented results (statuses ``"too-few-points"``,
        ``"collinear"``; duplicates get no edges), not errors.

    Raises
    ------
    InvalidInputError
        Wrong shape, NaN or infinite coordinates, coordinates spanning more than about
        2**172, or a missing or empty shapely / GeoPandas point (the message names the
        first). (A subclass of SigdtError and ValueError.)
    ValueError
        Unknown method.
    TypeError
        ``method`` is not a string.

    Warns
    -----
    SigdtWarning
        The status says the result is not a faithful curve: ``"sculpting-stuck"`` (points
        left inside), ``"branching"`` (edges branch where the method does not read
        junctions), ``"noisy"`` (the edges
        zigzag), ``"crossing"`` (edges cross) or ``"unfinished"`` (a limit stopped the
        run). The result is returned all
        the same.

    Examples
    --------
    >>> import sigdt
    >>> rec = sigdt.reconstruct([[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> rec
    Reconstruction(n_points=4, n_edges=4, n_loops=1, status='polygon')
    >>> rec.edges
    array([[0, 1],
           [0, 3],
           [1, 2],
           [2, 3]])
    >>> rec.loops
    [array([0, 1, 2, 3])]
    """
    _check_method(method, leaf_elimination)
    array, index, crs = _as_points_and_index(points)
    degrees = _is_geographic(crs) if lon_lat is None else bool(lon_lat)
    fields = _core.reconstruct(array, method, bool(leaf_elimination), degrees, expect=expect)
    rec = Reconstruction(array, fields, index, crs, degrees)
    _warn_about([rec], many=False)
    return rec


def reconstruct_many(
    point_sets: Iterable[object],
    *,
    n_jobs: int | None = None,
    method: Method = "sig-auto",
    leaf_elimination: bool = LEAF_ELIMINATION,
    expect: Expect = "curves",
    lon_lat: bool = False,
) -> list[Reconstruction]:
    """Reconstruct many point sets in parallel (threads in Rust, the GIL released).

    The results equal ``[reconstruct(p, ...) for p in point_sets]``, in the same order.

    Parameters
    ----------
    point_sets : iterable of array_like, each shape (n, 2)
        The point sets.
    n_jobs : int, optional
        Number of threads; default (``None``) or ``-1``: one per core; ``-2`` all cores but
        one, and so on (scikit-learn's convention). At most the number of cores: more
        threads would only add overhead.
    method, leaf_elimination, expect
        As in :func:`reconstruct`.
    lon_lat : bool, default False
        Whether every set is longitude/latitude in degrees (each reconstructed in a plane
        centred on it; see :func:`reconstruct`).

    Returns
    -------
    list of Reconstruction

    Raises
    ------
    InvalidInputError
        A set is unusable; the message starts with ``point set K:``, its position.
    ValueError
        Unknown method, or ``n_jobs`` is 0 or not an int.

    Warns
    -----
    SigdtWarning
        Once per call when some results are not faithful curves (as in
        :func:`reconstruct`), naming the first such set and how many more there are.

    Examples
    --------
    >>> import sigdt
    >>> square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    >>> [r.status for r in sigdt.reconstruct_many([square, square[:2]])]
    ['polygon', 'too-few-points']
    """
    _check_method(method, leaf_elimination)
    n_jobs = _threads(n_jobs)
    arrays = []
    for k, p in enumerate(point_sets):
        try:
            arrays.append(_as_points(p))
        except InvalidInputError as e:
            raise InvalidInputError(f"point set {k}: {e}") from e
    with _no_cycle_collection():
        raws = _core.reconstruct_many(
            arrays, method, bool(leaf_elimination), n_jobs, bool(lon_lat), expect=expect
        )
        results = [Reconstruction(a, raw, None, None, lon_lat) for a, raw in zip(arrays, raws)]
    _warn_about(results, many=True)
    return results


def proximity_graph(points: Any, kind: str = "sigdt", k: int | None = None) -> Indices:
    """The edges of a proximity graph of the points.

    Parameters
    ----------
    points : array_like, shape (n, 2)
    kind : {"dt", "sig", "sigdt", "sigdt2", "emst", "knn"}, default "sigdt"
        Delaunay triangulation, spheres-of-influence graph, their intersection, SIGDT after
        leaf elimination, Euclidean minimum spanning tree, k-nearest-neighbour graph
        (undirected union).
    k : int, optional
        Neighbours per point; required for ``"knn"`` and refused for the others.

    Returns
    -------
    numpy.ndarray
        ``(m, 2)`` int64, rows ``[i, j]`` with ``i < j``, sorted.

    Raises
    ------
    InvalidInputError
        Wrong shape or non-finite coordinates.
    ValueError
        Unknown kind, or ``k`` missing / given where it does not apply.

    Examples
    --------
    >>> import sigdt
    >>> sigdt.proximity_graph([[0, 0], [1, 0], [1, 1], [0, 1]], "emst")
    array([[0, 1],
           [0, 3],
           [1, 2]])
    """
    if kind not in _core.GRAPH_KINDS:
        raise ValueError(
            f"unknown graph kind {kind!r} (expected one of: {', '.join(_core.GRAPH_KINDS)})"
        )
    if k is not None and (isinstance(k, bool) or not isinstance(k, int) or k < 1):
        raise ValueError(f"k must be a positive int, got {k!r}")
    return _core.proximity_graph(_as_points(points), kind, k)


def read_points(
    path: str | os.PathLike[str],
    *,
    columns: str | None = None,
    max_points: int | None = None,
    layer: str | None = None,
) -> Coordinates:
    """Read a point file in any format the command line reads, with its reader.

    Plain text with two numbers a line (``.xy``, ``.txt``, ``.csv``, ``.p2d``; ``#``
    comments, one header line), Dey's ``.gtn``, CSV tables (``,``, ``;`` or tab separated,
    quoted fields, a header), WKT, GeoJSON, NumPy ``.npy`` arrays, each of these
    gzip-compressed (``.gz``), and the vertices of GeoPackage, FlatGeobuf and Shapefile
    features (``geopandas.read_file`` keeps their coordinate system; this returns
    coordinates only).

    Parameters
    ----------
    path : str or os.PathLike
        The file; the format follows its content and extension, as ``sigdt reconstruct``
        decides it.
    columns : str, optional
        The x and y columns of a table, as ``--columns``: names from its header row or
        numbers from 1 (``"lon,lat"``, ``"3,4"``).
    max_points : int, optional
        Refuse a file with more points (reading stops at the first one over).
    layer : str, optional
        The layer of a GeoPackage, as ``--layer`` (by default the only layer, or the only
        point layer).

    Returns
    -------
    numpy.ndarray
        ``(n, 2)`` float64.

    Raises
    ------
    ParseError
        The content is not points; the message names the file (and line). (A ValueError.)
    ValueError
        ``columns`` is malformed, or given for a format without columns (WKT, GeoJSON,
        ``.gtn``, ``.npy``, GIS formats); ``layer`` is given for a format without layers.
    OSError
        The file cannot be read.

    Examples
    --------
    >>> import sigdt, tempfile, os, gzip
    >>> with tempfile.TemporaryDirectory() as d:
    ...     path = os.path.join(d, "pts.csv")
    ...     _ = open(path, "w").write("x,y\\n0,0\\n1,0.5\\n")
    ...     sigdt.read_points(path)
    array([[0. , 0. ],
           [1. , 0.5]])
    >>> with tempfile.TemporaryDirectory() as d:
    ...     path = os.path.join(d, "pts.wkt.gz")
    ...     _ = gzip.open(path, "wt").write("MULTIPOINT ((0 0), (2 1))")
    ...     sigdt.read_points(path)
    array([[0., 0.],
           [2., 1.]])
    """
    return _core.read_points(os.fspath(path), columns, max_points, layer)
