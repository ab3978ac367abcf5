//! FITCONNECT: connect noisy samples by growing a fitted neighbourhood around each point
//! until the point lies between its neighbours, and link points whose fitted
//! neighbourhoods overlap.
//!
//! \[OW18\] S. Ohrhallinger, M. Wimmer, *FitConnect: Connecting Noisy 2D Samples by Fitted
//! Neighborhoods*, Computer Graphics Forum 38(1), 2019 (Eurographics 2018 short-paper
//! track). The rules below are those of the authors' program (github stefango74/fitconnect
//! @0dde252, GPL-3), read to learn its behaviour and restated in our own words (here and
//! in `docs/algorithms.md` §3.11); no code was taken.
//!
//! # Steps
//! Every point has a state (initial, conforming, non-conforming, manifold, leaf, sharp,
//! eliminated), a growing list `K(p)` of its nearest neighbours, the circle fitted to
//! `p ∪ K(p)` (`fit.rs`) with the neighbours ordered on its two *sides*, and two link slots,
//! one per side. Passes run over the *unhandled* points (initial, conforming,
//! non-conforming) in input order until none is left (`visit.rs`):
//! 1. each visit adds the next nearest neighbour (two on the first visit) and refits; the
//!    point *conforms* when it lies between its outermost neighbours along the fit;
//! 2. a conforming point links to its *overlap* on each side: the outermost neighbour that
//!    can take the link and whose own neighbourhood holds the point; two links make it
//!    manifold;
//! 3. unhandled points between two linked points are eliminated (FITCONNECT's thinning of
//!    noise), curve points inconsistent with a link lose theirs, a point blocked by one
//!    point and a point inside an edge are eliminated;
//! 4. a non-conforming point where exactly two open chains end within 60° becomes a sharp
//!    corner (`sharp.rs`);
//! 5. every change is propagated to the points whose neighbourhoods hold the changed point;
//! 6. a point whose neighbourhood cannot grow any more ends a curve (leaf) or is eliminated.
//!
//! The edges are the links between curve points (manifold, leaf, sharp): loops and open
//! paths, every point with at most two edges.
//!
//! # Left out
//! Eliminated points are [`Eliminated`](crate::LeftOutReason::Eliminated): on clean,
//! sparse input FITCONNECT is often not exact for this reason, as it thins clean samples as
//! it thins noise. Points that never reached a link are
//! [`NonConforming`](crate::LeftOutReason::NonConforming); points
//! still undecided when a limit (passes or work, see "Complexity") stops the run are
//! [`Unresolved`](crate::LeftOutReason::Unresolved) and the status is
//! [`Unfinished`](crate::Status::Unfinished). Links can cross (the rules do not test for
//! it; the authors' program gives crossings on 4 of `data/curves`): the status is then
//! [`Crossing`](crate::Status::Crossing).
//!
//! # Guarantee
//! None for the connectivity; [OW18] argues for noisy samples of smooth curves. It needs no
//! parameter. Passes visit points in input order, as the authors' program does, so the
//! result depends on the input order; ties in distance and order are broken by input index.
//!
//! # Complexity
//! A visit costs O(k log k) for a neighbourhood of `k` points (the fit, the ordering, the
//! rules' scans of the sides); the next neighbour comes from a best-first walk of the
//! Delaunay triangulation (`nearest.rs`). A point that never conforms grows to every other
//! point, one per pass, so the worst case is O(n) passes and O(n² log n) per such point;
//! [`PASS_LIMIT`] bounds the passes and [`WORK_LIMIT_PER_POINT`] the neighbours fitted in
//! all, so a run takes O(n log n) time at worst; a run stopped by either limit ends
//! [`Unfinished`](crate::Status::Unfinished).
//!
//! # Departures from the reference program
//! - A (nearly) collinear neighbourhood is fitted by its least-squares line, not by a circle
//!   with a made-up centre far away.
//! - Neighbours come in order of distance with ties by input index (the program takes a
//!   k-d tree's order). On `data/curves` this is the one difference we traced between the
//!   program's edges and ours (`docs/algorithms.md` §3.11).
//! - The sharp rule's crossing test is exact and counts touching, but not parallel, edges
//!   as meeting (the program counts every parallel pair).
//! - The program's OUTLIER state is switched off there and absent here; its display-only
//!   blending of points onto the fits is not computed.
//!
//! [OW18]: https://doi.org/10.1111/cgf.13395
mod fit;
mod nearest;
mod sharp;
mod state;
mod visit;

use crate::delaunay::Triangulation;
use crate::geometry::Point;
use crate::result::{
    degenerate_result, from_vertex_pairs, LeftOut, LeftOutReason, Reconstruction, Stats,
};
use crate::segment_grid::first_crossing;
use crate::Status;
pub(crate) use fit::{spread, Fit};
use state::{Points, State, NONE};

/// The most passes over the unhandled points. Every unhandled point gains a neighbour per
/// pass, so `n` passes exhaust every neighbourhood of `n` points unless links keep being
/// undone; the limit stops such oscillation (the authors' program stops at 99,999 passes).
pub const PASS_LIMIT: usize = 99_999;

/// The most work, in neighbours fitted (summed over every fit), per point. A point that
/// never conforms refits its ever larger neighbourhood until it holds every other point,
/// so the work of a run grows with n² per such point (and with n³ on a grid, where most
/// points never conform): the limit bounds a run by O(n) fits of at most n points, about a
/// quarter of a millisecond per point. On `data/curves` clean curves need 2.5 per point
/// (median) and the largest finished run 1,590 (a 1,367-point spiral with outliers).
pub const WORK_LIMIT_PER_POINT: usize = 2048;

/// FITCONNECT's decision for every vertex of a triangulation, for FITCONNECT itself and for
/// STRETCHDENOISE, which moves the points of the same connectivity.
pub(crate) struct Connectivity {
    /// The edges between curve points, as vertex pairs `[a, b]`, `a < b`, sorted.
    pub edges: Vec<[u32; 2]>,
    /// Per vertex, why it has no edge (`None` for curve points).
    pub left_out: Vec<Option<LeftOutReason>>,
    /// Per vertex, its last fit (noise extent and normal).
    pub fits: Vec<Fit>,
    /// Per vertex, whether it is a sharp corner.
    pub sharp: Vec<bool>,
    /// Per vertex, the neighbours it was fitted with, nearest first.
    pub neighbours: Vec<Vec<u32>>,
    /// Whether the passes ended with every point decided (not stopped by the limit).
    pub finished: bool,
}

/// FITCONNECT's connectivity of the vertices of `dt` (a proper triangulation: at least
/// three points, not all collinear).
pub(crate) fn connect(dt: &Triangulation, pass_limit: usize) -> Connectivity {
    let mut points = Points::new(dt);
    let mut passes = 0;
    let work_limit = WORK_LIMIT_PER_POINT.saturating_mul(points.xy.len());
    'passes: while !points.unhandled.is_empty() && passes < pass_limit {
        let mut cursor = points.unhandled.first().copied();
        while let Some(p) = cursor {
            if points.work > work_limit {
                break 'passes;
            }
            // Points that become unhandled behind the next one wait for the next pass.
            let next = points.unhandled.range(p + 1..).next().copied();
            points.visit(p);
            cursor = next.and_then(|next| points.unhandled.range(next..).next().copied());
        }
        passes += 1;
    }
    let finished = points.unhandled.is_empty();
    let curve = |r: u32| points.state[r as usize].is_curve();
    let vertex = |r: u32| points.vertex[r as usize];
    let mut edges: Vec<[u32; 2]> = (0..points.xy.len() as u32)
        .filter(|&r| curve(r))
        .flat_map(|r| points.links[r as usize].map(|s| [r, s]))
        .filter(|&[r, s]| s != NONE && curve(s) && points.links[s as usize].contains(&r))
        .map(|[r, s]| [vertex(r).min(vertex(s)), vertex(r).max(vertex(s))])
        .collect();
    edges.sort_unstable();
    edges.dedup();
    // Per-vertex copies of the per-rank results.
    let by_vertex = |r: &u32| *r as usize;
    let order = &points.rank;
    let left_out = order
        .iter()
        .map(|r| match points.state[by_vertex(r)] {
            State::Eliminated => Some(LeftOutReason::Eliminated),
            State::Initial | State::Conform | State::NonConform if !finished => {
                Some(LeftOutReason::Unresolved)
            }
            State::Initial | State::Conform | State::NonConform => {
                Some(LeftOutReason::NonConforming)
            }
            _ => None,
        })
        .collect();
    let sharp = order.iter().map(|r| points.state[by_vertex(r)] == State::Sharp).collect();
    let fits = order.iter().map(|r| points.fits[by_vertex(r)]).collect();
    let neighbours = order
        .iter()
        .map(|r| points.knn[by_vertex(r)].iter().map(|&s| vertex(s)).collect())
        .collect();
    Connectivity { edges, left_out, fits, sharp, neighbours, finished }
}

/// FITCONNECT on `dt` as a full result: the degenerate results of `docs/algorithms.md`
/// §0.1, otherwise the links read as loops and paths, with the points left out listed.
pub(crate) fn fit_connect_on(dt: &Triangulation) -> Reconstruction {
    fit_connect_with_limit(dt, PASS_LIMIT)
}

/// [`fit_connect_on`] with another pass limit (tests reach the limit with a small one).
pub(crate) fn fit_connect_with_limit(dt: &Triangulation, pass_limit: usize) -> Reconstruction {
    if let Some(result) = degenerate_result(dt) {
        return result;
    }
    let connectivity = connect(dt, pass_limit);
    result_of(dt, &connectivity)
}

/// The result of FITCONNECT's connectivity: its edges read as loops and paths, the points
/// without an edge listed as left out, [`Status::Unfinished`] if the pass limit stopped it.
pub(crate) fn result_of(dt: &Triangulation, connectivity: &Connectivity) -> Reconstruction {
    let mut rec = from_vertex_pairs(dt, connectivity.edges.clone(), Stats::default());
    rec.left_out = connectivity
        .left_out
        .iter()
        .enumerate()
        .filter_map(|(v, reason)| {
            reason.map(|reason| LeftOut { index: dt.input_index(v as u32), reason })
        })
        .collect();
    rec.left_out.sort_unstable();
    let on_loops: usize = rec.loops.iter().map(Vec::len).sum();
    if !connectivity.finished {
        rec.status = Status::Unfinished;
    } else if crossing(dt, &rec, None) {
        rec.status = Status::Crossing;
    } else if !rec.loops.is_empty()
        && rec.paths.is_empty()
        && on_loops + rec.left_out.len() == dt.num_vertices()
    {
        // Closed loops through every point not left out, as SIG-AUTO reports it.
        rec.status = if rec.loops.len() == 1 { Status::Polygon } else { Status::Polygons };
    }
    rec
}

/// Whether two edges of `rec` cross, at the input points or at `moved` (input-indexed,
/// in the caller's coordinates).
pub(crate) fn crossing(dt: &Triangulation, rec: &Reconstruction, moved: Option<&[Point]>) -> bool {
    let at: Vec<Point>;
    let positions = match moved {
        Some(points) => points,
        None => {
            let vertex = dt.vertex_of_inputs();
            at = (0..dt.input_len())
                .map(|i| match vertex[i] {
                    u32::MAX => [0.0, 0.0], // a duplicate: never on an edge
                    v => dt.point(v),
                })
                .collect();
            &at
        }
    };
    first_crossing(positions, &rec.edges).is_some()
}

#[cfg(test)]
mod tests;
