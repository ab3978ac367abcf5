"""The result type of :func:`sigdt.reconstruct`."""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["Reconstruction"]

#: Names of :attr:`Reconstruction.status`, in the order the core defines them.
STATUSES = (
    "polygon",
    "polygons",
    "sculpting-stuck",
    "curves",
    "network",
    "collinear",
    "too-few-points",
)


def _split(flat: np.ndarray, offsets: np.ndarray) -> list[np.ndarray]:
    return [flat[offsets[k] : offsets[k + 1]] for k in range(len(offsets) - 1)]


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
        ``"network"`` paths end at junctions (a path may start and end at the same
        junction).
    status : str
        ``"polygon"``, ``"polygons"``, ``"sculpting-stuck"``, ``"curves"`` (loops and open
        paths, not every point on a loop), ``"network"`` (some point has 3 or more edges),
        ``"collinear"`` or ``"too-few-points"``.
    left_out : numpy.ndarray
        int64 indices of the points no loop reaches (only with ``"sculpting-stuck"``).
    duplicates : numpy.ndarray
        ``(d, 2)`` int64 rows ``[duplicate, representative]``; duplicates get no edges.
    stats : dict
        Per-stage counts of the run.
    """

    __slots__ = (
        "_loop_offsets",
        "_loop_vertices",
        "_path_offsets",
        "_path_vertices",
        "duplicates",
        "edges",
        "left_out",
        "points",
        "stats",
        "status",
    )

    def __init__(self, points: np.ndarray, raw: tuple[Any, ...]) -> None:
        (
            self.edges,
            self._loop_vertices,
            self._loop_offsets,
            self._path_vertices,
            self._path_offsets,
            self.status,
            self.left_out,
            self.duplicates,
            self.stats,
        ) = raw
        self.points = points

    @property
    def loops(self) -> list[np.ndarray]:
        return _split(self._loop_vertices, self._loop_offsets)

    @property
    def paths(self) -> list[np.ndarray]:
        return _split(self._path_vertices, self._path_offsets)

    @property
    def is_manifold(self) -> bool:
        """True when the loops pass through every distinct point."""
        return self.status in ("polygon", "polygons")

    def to_shapely(self) -> Any:
        """The result as a shapely geometry: ``Polygon`` (one loop), ``MultiPolygon``
        (several), ``LineString`` (one path, or empty), ``MultiLineString`` (several).

        Needs the optional dependency ``shapely`` (``pip install sigdt[shapely]``).
        """
        from .shapely import to_shapely

        return to_shapely(self)

    def to_geojson(self) -> dict[str, Any]:
        """The result as a GeoJSON ``Feature`` (a JSON-serialisable dict) with the status
        and counts as properties."""
        from .shapely import to_geojson

        return to_geojson(self)

    def plot(self, ax: Any = None, **style: Any) -> Any:
        """Draw points, edges and filled loops with matplotlib; returns the axes.

        Needs the optional dependency ``matplotlib`` (``pip install sigdt[plot]``).
        """
        from .plot import plot

        return plot(self, ax=ax, **style)

    def __repr__(self) -> str:
        return (
            f"Reconstruction(n_points={len(self.points)}, n_edges={len(self.edges)}, "
            f"n_loops={len(self._loop_offsets) - 1}, status={self.status!r})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Reconstruction):
            return NotImplemented
        return all(
            a == b if isinstance(a, (str, dict)) else np.array_equal(a, b)
            for a, b in zip((self.points, *self._raw()), (other.points, *other._raw()))
        )

    __hash__ = None  # type: ignore[assignment]  # mutable arrays inside

    def __reduce__(self) -> tuple[Any, ...]:
        return (Reconstruction, (self.points, self._raw()))

    def _raw(self) -> tuple[Any, ...]:
        """The fields in the order the extension returns them (see ``__init__``)."""
        return (
            self.edges,
            self._loop_vertices,
            self._loop_offsets,
            self._path_vertices,
            self._path_offsets,
            self.status,
            self.left_out,
            self.duplicates,
            self.stats,
        )
