"""Many groups of points in one call, a failing group a row of its own: what
:func:`sigdt.reconstruct_frame` and :func:`sigdt.outlines` share.

A GIS user runs hundreds of countries, parcels or islands at once; one group with a point
off the map, or two points only, must not cost the other rows. Groups run in Rust threads
(``reconstruct_many``) in batches, so that progress can be reported; a batch that fails is
run again group by group to tell which groups failed and why.
"""

from __future__ import annotations

import sys
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Callable, Literal

import numpy as np

from . import _core
from ._api import _no_cycle_collection, _warning_text
from ._input import _is_geographic
from ._result import Reconstruction
from ._types import Expect, Method
from .errors import InvalidInputError, SigdtWarning

#: What a failing group does: becomes a row (status ``"error"``) or raises.
Errors = Literal["row", "raise"]

#: The status of a group that could not be reconstructed.
ERROR = "error"


@dataclass(frozen=True)
class Failure:
    """A group that could not be reconstructed: its points and why."""

    n_points: int
    message: str


def _progress(total: int, show: bool | None) -> Callable[[int], None]:
    """A one-line progress report on standard error, ``done/total groups``, drawn in place;
    by default only when standard error is a terminal."""
    if show is None:
        show = sys.stderr.isatty()
    if not show:
        return lambda done: None

    def report(done: int) -> None:
        width = 30
        filled = width * done // max(total, 1)
        end = "\n" if done == total else ""
        bar = "#" * filled + "-" * (width - filled)
        print(f"\rsigdt: [{bar}] {done}/{total} groups", end=end, file=sys.stderr, flush=True)

    return report


def check_errors(errors: Any) -> None:
    if errors not in ("row", "raise"):
        raise ValueError(f"errors must be 'row' or 'raise', got {errors!r}")


def grouped_positions(grouped: Any) -> tuple[Any, np.ndarray, np.ndarray]:
    """A pandas ``GroupBy``'s groups in one vectorised pass: the index ``grouped.size()``
    has, the row positions of every group in turn (each group's in row order), and each
    group's size. Iterating the groups costs a sub-frame or sub-series each, which 10⁵
    buildings cannot pay."""
    index = grouped.size().index
    codes = grouped.ngroup().to_numpy()
    return index, np.argsort(codes, kind="stable"), np.bincount(codes, minlength=len(index))


def run_groups(
    arrays: Sequence[np.ndarray | Failure],
    names: Sequence[str],
    crs: Any,
    *,
    method: Method,
    leaf_elimination: bool,
    expect: Expect,
    threads: int | None,
    progress: bool | None,
    errors: Errors,
) -> list[Reconstruction | Failure]:
    """Reconstructs every group (``arrays[k]``, called ``names[k]`` in messages); a group given as a :class:`Failure` (its points could not be read) stays
    one. With ``errors="raise"`` the first failure raises :class:`InvalidInputError` naming
    its group.
    """
    lon_lat = _is_geographic(crs)
    report = _progress(len(arrays), progress)
    # Batches of about a hundredth of the groups: progress without losing the parallelism.
    batch = max(64, len(arrays) // 100)
    results: list[Reconstruction | Failure] = []

    def fail(k: int, failure: Failure) -> Failure:
        if errors == "raise":
            raise InvalidInputError(f"{names[k]}: {failure.message}")
        return failure

    def run(chunk: list[np.ndarray]) -> list[Any]:
        return _core.reconstruct_many(
            chunk, method, bool(leaf_elimination), threads, lon_lat, expect=expect
        )

    def run_batch(start: int) -> list[Reconstruction | Failure]:
        given = list(arrays[start : start + batch])
        chunk: list[Reconstruction | Failure | None] = [None] * len(given)
        todo: list[tuple[int, np.ndarray]] = []
        for k, a in enumerate(given):
            if isinstance(a, Failure):
                chunk[k] = fail(start + k, a)
            else:
                todo.append((k, a))
        try:
            raws: list[Any] = run([a for _, a in todo])
        except InvalidInputError:
            # One group spoils the batch: run its groups one by one to name each failure.
            raws = []
            for k, a in todo:
                try:
                    raws.append(run([a])[0])
                except InvalidInputError as e:
                    why = str(e).removeprefix("point set 0: ")
                    raws.append(fail(start + k, Failure(len(a), why)))
        for (k, a), raw in zip(todo, raws):
            chunk[k] = (
                raw if isinstance(raw, Failure) else Reconstruction(a, raw, None, crs, lon_lat)
            )
        return [r for r in chunk if r is not None]

    with _no_cycle_collection():
        for start in range(0, len(arrays), batch):
            results.extend(run_batch(start))
            report(len(results))
    return results


def warn_about_groups(
    results: Sequence[Reconstruction | Failure], names: list[str], depth: int = 1
) -> None:
    """One :class:`SigdtWarning` for a call over groups: the groups that failed, by name, and
    the first group whose result may not be its curves, pointing at the user's line, ``depth``
    calls above the caller."""
    failed = [(n, r) for n, r in zip(names, results) if isinstance(r, Failure)]
    done = [(n, r) for n, r in zip(names, results) if isinstance(r, Reconstruction)]
    parts = []
    if failed:
        shown = ", ".join(n for n, _ in failed[:5])
        more = f" and {len(failed) - 5} more" if len(failed) > 5 else ""
        name, first = failed[0]
        parts.append(
            f"{len(failed)} of {len(results)} groups failed and are rows with status "
            f"{ERROR!r} ({shown}{more}); {name}: {first.message}"
        )
    text = _warning_text([r for _, r in done], [n for n, _ in done])
    if text is not None:
        parts.append(text)
    if parts:
        warnings.warn("; ".join(parts), SigdtWarning, stacklevel=2 + depth)
