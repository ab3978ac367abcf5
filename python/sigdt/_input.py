"""Reading what users pass in: point arrays and method names, checked once at the entry."""

from __future__ import annotations

from typing import Any

import numpy as np

from . import _core
from ._core import InvalidInputError

__all__ = ["LEAF_ELIMINATION"]

#: Default of ``leaf_elimination``: on (measured better on every category of the labelled
#: curves; see docs/algorithms.md).
LEAF_ELIMINATION = True


def _as_points(points: Any) -> np.ndarray:
    try:
        # C-contiguous and aligned (arrays deserialised from message frames, as Dask workers
        # receive them, may be unaligned); copies only when one of these does not hold.
        array = np.require(points, dtype=np.float64, requirements=["C", "A"])
    except (TypeError, ValueError) as e:
        raise InvalidInputError(f"points cannot be read as an (n, 2) float array: {e}") from e
    if array.size == 0 and array.ndim <= 2:
        return array.reshape(0, 2)
    if array.ndim != 2 or array.shape[1] != 2:
        raise InvalidInputError(f"points must have shape (n, 2), got {array.shape}")
    return array


def _check_method(method: str) -> None:
    if not isinstance(method, str):
        raise TypeError(f"method must be a str, got {type(method).__name__}")
    if method not in _core.METHODS:
        raise ValueError(f"unknown method {method!r} (expected one of: {', '.join(_core.METHODS)})")
