""":func:`sigdt.reconstruct_frame` over a ``dask_geopandas.GeoDataFrame``: points past one
machine's memory, groups spread over a cluster.

A group must be whole in one partition to be reconstructed there, so the frame is first
shuffled on the group columns (every row of a key goes to one partition); each partition is
then an ordinary GeoDataFrame, reconstructed on its worker with the pandas path. The rows are
those of the pandas path, in the partitions' order (``.compute().sort_index()`` orders them
as the pandas path does).
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import Any

import numpy as np


def reconstruct_dask_frame(
    frame: Any, by: Any, reconstruct: Callable[..., Any], options: dict[str, Any]
) -> Any:
    """``reconstruct(partition, by, **options)`` on every partition of ``frame`` shuffled on
    ``by``, lazily: a ``dask_geopandas.GeoDataFrame`` of one row per group."""
    import pandas as pd

    if by is None or isinstance(by, pd.Series):
        raise ValueError(
            "reconstruct_frame on a Dask frame needs by= naming the column(s) that group the "
            "points: the frame is shuffled on them so that each group is in one partition"
        )
    columns: list[Hashable] = list(by) if isinstance(by, (list, tuple)) else [by]
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(
            f"by: no column {missing[0]!r} in the Dask frame (its columns: "
            f"{', '.join(map(str, frame.columns))})"
        )
    by = columns if isinstance(by, (list, tuple)) else by
    meta = reconstruct(frame._meta, by, progress=False, **options)
    empty = [frame._meta[c].iloc[:0] for c in columns]
    if len(columns) > 1:
        meta.index = pd.MultiIndex.from_arrays(empty, names=columns)
    else:
        meta.index = pd.Index(empty[0], name=columns[0])
    # Ties are broken by point index, so each group's points must keep the frame's order
    # through the shuffle: number the rows (partition, then position) and sort on it after.
    numbered = frame.map_partitions(_number_rows, meta=_number_rows(frame._meta))
    # The task-based shuffle: the distributed scheduler's default (peer to peer) goes through
    # Arrow, which has no geometry type.
    shuffled = numbered.shuffle(on=columns, shuffle_method="tasks")
    return shuffled.map_partitions(
        _reconstruct_in_order, reconstruct, by, options, meta=meta, align_dataframes=False
    )


#: The column that carries each row's place in the frame through the shuffle.
_ORDER = "__sigdt_row_order__"


def _number_rows(part: Any, partition_info: dict[str, Any] | None = None) -> Any:
    number = 0 if partition_info is None else partition_info["number"]
    return part.assign(**{_ORDER: (number << 40) + np.arange(len(part), dtype=np.int64)})


def _reconstruct_in_order(
    part: Any, reconstruct: Callable[..., Any], by: Any, options: dict[str, Any]
) -> Any:
    ordered = part.sort_values(_ORDER, kind="stable").drop(columns=[_ORDER])
    return reconstruct(ordered, by, progress=False, **options)
