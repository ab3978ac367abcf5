"""The types of sigdt's values, for type checkers: method, status and reason names as
``Literal`` types, and the dicts that :func:`sigdt.evaluate`, :func:`sigdt.graph_overlap`
and :meth:`sigdt.Reconstruction.to_geojson` return as ``TypedDict`` types. A test checks
the literals against the names the extension defines."""

from __future__ import annotations

from typing import Literal, TypedDict

__all__ = [
    "Evaluation",
    "Expect",
    "Finding",
    "GeoJsonFeature",
    "GraphOverlap",
    "LeftOutReason",
    "Method",
    "Status",
    "VerticesKind",
]

#: A reconstruction method (``sigdt.METHODS``).
Method = Literal[
    "sig-connect2d",
    "sig-auto",
    "connect2d",
    "crust",
    "nn-crust",
    "hnn-crust",
    "crawl",
    "discur",
    "fit-connect",
    "stretch-denoise",
    "peel",
    "emst",
    "optimal-transport",
]

#: What a result is (:attr:`sigdt.Reconstruction.status`).
Status = Literal[
    "polygon",
    "polygons",
    "sculpting-stuck",
    "curves",
    "network",
    "branching",
    "noisy",
    "crossing",
    "unfinished",
    "collinear",
    "too-few-points",
]

#: What a result's vertices are (:attr:`sigdt.Reconstruction.vertices_kind`).
VerticesKind = Literal["input", "moved", "new"]

#: Why a point was left out (:attr:`sigdt.Reconstruction.left_out_reasons`).
LeftOutReason = Literal["inside", "outlier", "eliminated", "non-conforming", "unresolved", "seam"]


class Evaluation(TypedDict):
    """What :func:`sigdt.evaluate` returns."""

    exact: bool
    missing: int
    extra: int
    rmse: float | None
    rmse_to_gt: float | None
    hausdorff: float | None
    area_difference: float
    area_difference_normalised: float | None


class GraphOverlap(TypedDict):
    """What :func:`sigdt.graph_overlap` returns: shares of edges, and whether each graph
    contains the whole ground truth."""

    sig_in_dt: float
    dt_in_sig: float
    sigdt_in_gt: float
    gt_in_sigdt: float
    gt_in_sigdt2: float
    gt_in_bc0: float
    gt_in_knn2: float
    gt_in_knn3: float
    gt_in_knn4: float
    contains_gt_sigdt: bool
    contains_gt_sigdt2: bool
    contains_gt_bc0: bool
    contains_gt_knn2: bool
    contains_gt_knn3: bool
    contains_gt_knn4: bool


#: What the sampling check can find (the ``kind`` of a finding).
FindingKind = Literal[
    "passes-over-samples",
    "doubles-back",
    "small-loops",
    "open-ends",
    "ends-meet",
    "outliers-on-curve",
    "noisy-area",
    "open-outlines",
]

#: What the points outline, as far as the caller knows (``expect=`` of
#: :func:`sigdt.reconstruct`): ``"curves"`` (open or closed, as they read) or ``"areas"``
#: (every curve is a closed outline).
Expect = Literal["curves", "areas"]


class Finding(TypedDict):
    """One finding of the sampling check (:attr:`sigdt.Reconstruction.diagnosis`): where the
    result breaks the sampling condition it assumes.

    ``kind`` is ``"passes-over-samples"`` (edges whose diametral disk holds another point
    at least 1 point spacing deep, or 2 for the curve's next point beyond an end),
    ``"doubles-back"`` (the curve turns by more than 150 degrees between two edges each at
    least 4 times the spacing at its far end), ``"small-loops"`` (loops of fewer than
    seven points, which no closed curve sampled within the condition gives),
    ``"open-ends"`` (an open path ends next to points nearer than half its last edge: the
    curve may go on there), ``"ends-meet"`` (two ends of open paths lie less than four
    times their last edges apart: the curve may close there), ``"outliers-on-curve"``
    (points left out as outliers lie within half their spacing of an edge of the result,
    nearer to one of its vertices than half that vertex's longer edge, or nearer to an
    edge than its length) or
    ``"noisy-area"`` (the loops' turns reverse at most points, as noise makes them, by
    enough to make the area they enclose uncertain by more than 5 %) or ``"open-outlines"``
    (open paths where ``expect="areas"`` said the points outline areas; ``worst`` is the
    largest gap between a path's ends over its longest edge); ``count`` edges,
    points, pairs of ends or loops show it; ``worst`` is the deepest reach in point
    spacings, the sharpest turn in degrees, the size of the smallest loop, the last edge
    over the nearest distance, the smallest gap between ends over their last edge, the
    nearest outlier's distance over its spacing or the uncertain share of the area, at
    input index ``at``, whose coordinates are ``point``;
    ``message`` is the sentence front ends print: what is wrong, near which coordinates,
    and what to do."""

    kind: FindingKind
    count: int
    worst: float
    at: int
    point: list[float]
    message: str


class GeoJsonFeature(TypedDict):
    """What :meth:`sigdt.Reconstruction.to_geojson` returns: a GeoJSON ``Feature``."""

    type: Literal["Feature"]
    geometry: dict[str, object] | None
    properties: dict[str, str | int | bool | list[int] | list[str] | list[Finding]]
