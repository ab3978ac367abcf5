"""What the views of a result (shapely, GeoDataFrame, text, matplotlib) read of it.

:class:`Outlines` is the part of :class:`sigdt.Reconstruction` that those views use, as a
protocol, so that the views need not import the class whose methods call them: the result
imports each view when one of its methods runs, and no view imports the result back.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol, Union

import numpy as np
import numpy.typing as npt

from ._types import Finding, Method, Status

if TYPE_CHECKING:  # pragma: no cover
    import shapely

    from ._core import _Reconstruction

    #: What :meth:`Reconstruction.to_shapely` returns.
    ShapelyResult = Union[
        shapely.Polygon,
        shapely.MultiPolygon,
        shapely.LineString,
        shapely.MultiLineString,
        shapely.GeometryCollection,
    ]
else:
    # Named at run time too, for documentation tools that evaluate annotations.
    _Reconstruction = dict
    ShapelyResult = Any

#: int64 index arrays and float64 coordinate arrays.
Indices = npt.NDArray[np.int64]
Coordinates = npt.NDArray[np.float64]


class Outlines(Protocol):
    """A reconstruction as the views read it (:class:`sigdt.Reconstruction` is one)."""

    @property
    def points(self) -> Coordinates: ...
    @property
    def vertices(self) -> Coordinates: ...
    @property
    def edges(self) -> Indices: ...
    @property
    def loops(self) -> list[Indices]: ...
    @property
    def paths(self) -> list[Indices]: ...
    @property
    def junctions(self) -> Indices: ...
    @property
    def polygons(self) -> list[tuple[int, list[int]]]: ...
    @property
    def status(self) -> Status: ...
    @property
    def method(self) -> Method | None: ...
    @property
    def warns(self) -> bool: ...
    @property
    def diagnosis(self) -> list[Finding]: ...
    @property
    def crs(self) -> Any: ...
    @property
    def lon_lat(self) -> bool: ...
    @property
    def _fields(self) -> _Reconstruction: ...
