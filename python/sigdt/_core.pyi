"""Type stubs of the Rust extension ``sigdt._core`` (conversion layer only)."""

import os
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
from typing_extensions import TypeAlias

_Raw: TypeAlias = tuple[
    npt.NDArray[np.int64],  # edges (m, 2)
    npt.NDArray[np.int64],  # loop vertices, flat
    npt.NDArray[np.int64],  # loop offsets
    npt.NDArray[np.int64],  # path vertices, flat
    npt.NDArray[np.int64],  # path offsets
    str,  # status
    npt.NDArray[np.int64],  # left out
    npt.NDArray[np.int64],  # duplicates (d, 2)
    dict[str, int],  # stats
]
_Trace: TypeAlias = tuple[
    npt.NDArray[np.int64],  # triangles (T, 3)
    npt.NDArray[np.int64],  # graph (m, 2)
    npt.NDArray[np.bool_],  # initial inside (T,)
    npt.NDArray[np.int64],  # dangling (d, 2)
    npt.NDArray[np.int64],  # step triangle (S,)
    npt.NDArray[np.bool_],  # step inside (S,)
    npt.NDArray[np.uint8],  # step phase (S,): 0 inflate, 1 pocket, 2 sculpt
    int,  # inflated at
]

METHODS: list[str]
GRAPH_KINDS: list[str]
__version__: str

class InvalidInputError(ValueError): ...
class ParseError(ValueError): ...
class InternalError(RuntimeError): ...

def reconstruct(points: npt.NDArray[np.float64], method: str, leaf_elimination: bool) -> _Raw: ...
def reconstruct_many(
    point_sets: Sequence[npt.NDArray[np.float64]],
    method: str,
    leaf_elimination: bool,
    n_jobs: int | None = None,
    _panic_in_set: int | None = None,  # test hook: that set panics in its worker
) -> list[_Raw]: ...
def trace(
    points: npt.NDArray[np.float64], method: str, leaf_elimination: bool
) -> _Trace | None: ...
def proximity_graph(
    points: npt.NDArray[np.float64], kind: str, k: int | None = None
) -> npt.NDArray[np.int64]: ...
def read_points(path: str | os.PathLike[str]) -> npt.NDArray[np.float64]: ...
def evaluate(
    points: npt.NDArray[np.float64], edges: npt.NDArray[np.int64], gt: npt.NDArray[np.int64]
) -> dict[str, bool | int | float | None]: ...
def graph_epsilon(points: npt.NDArray[np.float64], gt: npt.NDArray[np.int64]) -> float: ...
def graph_overlap(
    points: npt.NDArray[np.float64], gt: npt.NDArray[np.int64]
) -> dict[str, float | bool]: ...
