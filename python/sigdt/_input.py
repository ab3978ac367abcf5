"""Reading what users pass in: point arrays and method names, checked once at the entry."""

from __future__ import annotations

from typing import Any

import numpy as np

from . import _core
from .errors import InvalidInputError

__all__ = ["LEAF_ELIMINATION"]

#: Default of ``leaf_elimination``: on (measured better on every category of the labelled
#: curves; see docs/algorithms.md).
LEAF_ELIMINATION = True


def _as_points(points: Any) -> np.ndarray:
    if np.ma.isMaskedArray(points) and np.ma.getmaskarray(points).any():
        raise InvalidInputError(
            "points is a masked array with masked values: drop them first "
            "(points[~points.mask.any(axis=1)].data) or fill them (points.filled(...))"
        )
    try:
        given = np.asarray(np.ma.getdata(points))
        if np.iscomplexobj(given):
            raise InvalidInputError(
                "points are complex numbers: pass an (n, 2) real array, for example "
                "np.c_[z.real, z.imag]"
            )
        # C-contiguous and aligned (arrays deserialised from message frames, as Dask workers
        # receive them, may be unaligned); copies only when one of these does not hold.
        array = np.require(given, dtype=np.float64, requirements=["C", "A"])
    except (TypeError, ValueError, OverflowError) as e:
        if isinstance(e, InvalidInputError):
            raise
        raise InvalidInputError(f"points cannot be read as an (n, 2) float array: {e}") from e
    if array.ndim <= 2 and array.size == 0 and array.shape[0] == 0:
        return array.reshape(0, 2)  # no rows: no points, whatever the width
    if array.ndim == 2 and array.shape[1] > 2:
        raise InvalidInputError(
            f"points must have shape (n, 2), got {array.shape}: select the x and y columns, "
            "for example points[:, :2]"
        )
    if array.ndim != 2 or array.shape[1] != 2:
        raise InvalidInputError(f"points must have shape (n, 2), got {array.shape}")
    return array


def _check_method(method: str) -> None:
    if not isinstance(method, str):
        raise TypeError(f"method must be a str, got {type(method).__name__}")
    if method not in _core.METHODS:
        raise ValueError(f"unknown method {method!r} (expected one of: {', '.join(_core.METHODS)})")
