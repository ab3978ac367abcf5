"""Type stubs of the Rust extension ``sigdt._core`` (conversion layer only)."""

import os
from collections.abc import Sequence
from typing import TypedDict

import numpy as np
import numpy.typing as npt

# One finding of the sampling check (``sigdt.Finding``).
_Finding = TypedDict(
    "_Finding",
    {
        "kind": str,
        "count": int,
        "worst": float,
        "at": int,
        "point": list[float],
        "message": str,
    },
)

# What ``reconstruct`` hands over, by name (``python/sigdt/_result.py`` keeps it as is).
# Loops and paths are flat: chain ``k`` is ``vertices[offsets[k]:offsets[k + 1]]``.
_Reconstruction = TypedDict(
    "_Reconstruction",
    {
        "edges": npt.NDArray[np.int64],  # (m, 2)
        "loop_vertices": npt.NDArray[np.int64],
        "loop_offsets": npt.NDArray[np.int64],
        "path_vertices": npt.NDArray[np.int64],
        "path_offsets": npt.NDArray[np.int64],
        "status": str,
        "status_message": str,
        "method": str,  # absent from results pickled before it was recorded
        "status_warns": bool,
        "status_is_warning": bool,
        "diagnosis": list[_Finding],
        "left_out": npt.NDArray[np.int64],
        "left_out_reasons": list[str],
        "vertices": str,  # "input", "moved" or "new"
        "positions": npt.NDArray[np.float64] | None,  # (k, 2), None for "input"
        "duplicates": npt.NDArray[np.int64],  # (d, 2)
        "stats": dict[str, int],
    },
)

METHODS: list[str]
GRAPH_KINDS: list[str]
PHASES: list[str]
PALETTE: dict[str, str]
__version__: str

class Trace(object):  # noqa: UP004  # the bases mirror the runtime's, as test_docs.py checks
    @property
    def triangles(self) -> npt.NDArray[np.int64]: ...  # (T, 3)
    @property
    def graph(self) -> npt.NDArray[np.int64]: ...  # (m, 2)
    @property
    def initial_inside(self) -> npt.NDArray[np.bool_]: ...  # (T,)
    @property
    def dangling(self) -> npt.NDArray[np.int64]: ...  # (d, 2)
    @property
    def step_triangle(self) -> npt.NDArray[np.int64]: ...  # (S,)
    @property
    def step_inside(self) -> npt.NDArray[np.bool_]: ...  # (S,)
    @property
    def step_phase(self) -> npt.NDArray[np.uint8]: ...  # (S,): indices into PHASES
    @property
    def inflated_at(self) -> int: ...
    def boundary_at(self, step: int) -> npt.NDArray[np.int64]: ...  # (m, 2)
    def inside_at(self, step: int) -> npt.NDArray[np.bool_]: ...  # (T,)

def reconstruct(
    points: npt.NDArray[np.float64],
    method: str,
    leaf_elimination: bool,
    lon_lat: bool = False,
    expect: str = "curves",
) -> _Reconstruction: ...
def reconstruct_many(
    point_sets: Sequence[npt.NDArray[np.float64]],
    method: str,
    leaf_elimination: bool,
    n_jobs: int | None = None,
    lon_lat: bool = False,
    _panic_in_set: int | None = None,  # test hook: that set panics in its worker
    expect: str = "curves",
) -> list[_Reconstruction]: ...
def trace(points: npt.NDArray[np.float64], method: str, leaf_elimination: bool) -> Trace | None: ...
def polygons(
    points: npt.NDArray[np.float64],
    loop_vertices: npt.NDArray[np.int64],
    loop_offsets: npt.NDArray[np.int64],
) -> list[tuple[int, list[int]]]: ...  # (shell, holes): indices into the loops
def write_reconstruction(
    points: npt.NDArray[np.float64], fields: _Reconstruction, format: str
) -> str: ...  # the text of `sigdt reconstruct --format FORMAT`
def proximity_graph(
    points: npt.NDArray[np.float64], kind: str, k: int | None = None
) -> npt.NDArray[np.int64]: ...
def read_points(
    path: str | os.PathLike[str],
    columns: str | None = None,
    max_points: int | None = None,
    layer: str | None = None,
) -> npt.NDArray[np.float64]: ...
def place(
    points: npt.NDArray[np.float64], width: float
) -> tuple[float, npt.NDArray[np.float64]]: ...  # (height, (n, 2) pixels, y down)
def split_polygon_at_antimeridian(
    rings: list[npt.NDArray[np.float64]],
) -> list[list[npt.NDArray[np.float64]]]: ...
def split_line_at_antimeridian(line: npt.NDArray[np.float64]) -> list[npt.NDArray[np.float64]]: ...
def evaluate(
    points: npt.NDArray[np.float64], edges: npt.NDArray[np.int64], gt: npt.NDArray[np.int64]
) -> dict[str, bool | int | float | None]: ...
def graph_epsilon(points: npt.NDArray[np.float64], gt: npt.NDArray[np.int64]) -> float: ...
def graph_overlap(
    points: npt.NDArray[np.float64], gt: npt.NDArray[np.int64]
) -> dict[str, float | bool]: ...
