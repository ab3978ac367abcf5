//! DISCUR: grow curves along the Delaunay edges, shortest first, and let each curve's own
//! spacing statistics decide whether it takes a longer edge.
//!
//! \[ZNYL08\] Y. Zeng, T. A. Nguyen, B. Yan, S. Li, *A distance-based parameter free algorithm
//! for curve reconstruction* (DISCUR), Computer-Aided Design 40(2), 2008. The paper's text was
//! not at hand. What is known of it from its abstract (as `docs/algorithms.md` §3.9 reports
//! it) is that it has no parameter and rests on two principles of human visual perception,
//! read here as *proximity* (a point is connected to its nearest neighbour first) and a
//! *statistical* criterion (a curve takes a new link only if its length fits the lengths the
//! curve already has). Everything else is **reconstructed**:
//! - the decision order (two passes over the Delaunay edges, shortest first; free–free edges
//!   connect; edges at inner points are removed; deferred edges are tried again) is common to
//!   four versions of a third-party Java class `Discur` (a student project, seen once, not the
//!   authors' code), restated in our own words;
//! - the formula of the criterion, `ρ` below, is that of one of those versions (one leaves it
//!   unfinished, two replace it by an angle-and-distance score that is not DISCUR's);
//! - where the versions disagree (either end or both; removing a point's edges after two
//!   processed edges or after two curve edges) and where none says anything (closing a
//!   curve, the order of pass 2), the choice is ours, made from the principles above and not
//!   from the scores; [`Variant`] holds the alternatives so that they can be measured.
//!
//! # Steps
//! 1. Order the Delaunay edges by length (ties: the lower, then the higher input index). Each
//!    point has a *curve degree* `c`: 0 free, 1 the end of a curve, 2 inside one. Each curve
//!    keeps its two ends and the count, mean `h̄` and standard deviation `s̄` (with `k − 1`
//!    in the denominator, as three of the Java versions; 0 for one edge) of its edge lengths.
//! 2. *Pass 1*, every edge `pq` not yet removed, in order:
//!    - `c(p) = c(q) = 0`: connect; `pq` is a new two-point curve (proximity: the first
//!      edge a free point meets in length order is the edge to its nearest neighbour);
//!    - `c(p) = 2` or `c(q) = 2`: remove `pq`;
//!    - otherwise test the *criterion* at each end among `p, q`. At an end `e` of curve `C`
//!      whose edge at `e` has length `a`, for `d = |pq|`: `h = (d + a)/2` and
//!      `s = |d − a|/√2` (the mean and standard deviation of `{d, a}`), and
//!      `ρ = h̄ · (h/s) · (1 + h̄/s̄)^(s̄/h̄)`, with `ρ = ∞` when `s = 0` and the last factor 1
//!      when `s̄ = 0`. The end accepts `pq` iff `d < ρ`. Connect iff *either* end accepts:
//!      two ends of one curve close it, ends of two curves merge them. Otherwise *defer* `pq`.
//!    - A point that reaches `c = 2` has its unprocessed edges removed.
//! 3. *Pass 2*, every deferred edge in order, tested again with the statistics as they are
//!    now. After each connection, the deferred edges at the two ends of the enlarged curve
//!    are tested, shortest first, and the first that passes is connected, until none passes.
//! 4. The connected edges are the result: paths and cycles. A point whose every edge was
//!    refused or removed stays *free*, without an edge.
//!
//! `curve.rs` holds a curve's statistics and the criterion, `growth.rs` the two passes.
//!
//! The factor `(1 + h̄/s̄)^(s̄/h̄)` grows from 1 to `e` with the curve's irregularity
//! `s̄/h̄`: an irregular curve tolerates more. On a uniform curve an end takes an edge up to
//! about twice the spacing.
//!
//! # Guarantee
//! None is proven. Every point has at most two edges, so the result is paths and cycles; no
//! two edges cross (they are Delaunay edges). Curves may stay open where a closing edge is too
//! long for both ends; samples at sharp corners and outliers may stay free.
//!
//! # Free points
//! Free points get no entry in [`left_out`](crate::Reconstruction::left_out). DISCUR has no
//! outlier test: a point stays free when every curve it met refused it or filled up first,
//! which happens as much to curve samples (at a sharp corner, next to a denser curve) as to
//! outliers, so calling them [`Outlier`](crate::LeftOutReason::Outlier) would claim a
//! decision the method does not make. As for the other graph filters, the status
//! ([`Curves`](crate::Status::Curves)) says that some points have no edge.
//!
//! # Complexity
//! O(n log n) for the sort; every edge is decided once in pass 1 and a point's edges are
//! removed once. In pass 2 each connection re-tests the deferred edges at the two ends of
//! its curve, O(the ends' Delaunay degrees) each, so O(n) when degrees are bounded and
//! O(n · Δ) for a maximum degree Δ in the worst case.
//!
//! # Departures and decisions
//! - The alternatives kept in [`Variant`], measured against [MOW22] Table 2
//!   (`docs/evaluation.md`): the criterion at *both* ends instead of either; the earliest
//!   Java version's rule that removes a point's unprocessed edges once *two* of its edges
//!   have been processed (accepted or deferred), a two-nearest-neighbours reading of
//!   proximity; closing a curve only when *both* its ends accept. None is the default: the
//!   abstract speaks of a point joining a curve when it fits that curve, which one end
//!   decides, and of proximity as the nearest neighbour, not the two nearest.
//! - Lengths are `f64`, ordered by squared length with ties by input index
//!   (`docs/algorithms.md` §0.3). The statistics are kept as pooled means and sums of
//!   squared deviations (never negative, unlike running sums of squares), and the factor is
//!   evaluated as `exp(t (ln(1 + t) − ln t))` with `t = s̄/h̄`, which cannot overflow.
//! - The order of pass 2 is not known; ascending length is our choice.
//!
//! # References
//! - \[ZNYL08\] Y. Zeng, T. A. Nguyen, B. Yan, S. Li. A distance-based parameter free
//!   algorithm for curve reconstruction. Computer-Aided Design 40(2), 2008 (cited from
//!   memory, not checked against the paper).
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
mod curve;
mod growth;

use crate::delaunay::Triangulation;
use crate::result::{degenerate_result, from_vertex_pairs, Reconstruction, Stats};
use growth::Growth;

/// The unknowns of the reconstruction as switches; [`Variant::DEFAULT`] is what
/// [`Method::Discur`](crate::Method::Discur) runs. Not a user option: it exists so that the
/// alternatives can be measured (`sigdt-lab/examples/discur_variants.rs`).
#[doc(hidden)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Variant {
    /// Connect two curve ends only if the criterion holds at both, not at either.
    pub both_ends: bool,
    /// Remove a point's unprocessed edges once two of its edges have been processed in
    /// pass 1 (connected or deferred), not once it has two curve edges.
    pub two_processed: bool,
    /// Close a curve only if the criterion holds at both its ends (implied by `both_ends`).
    pub close_both_ends: bool,
}

impl Variant {
    /// The reading of `docs/algorithms.md` §3.9: either end decides, a point's edges go when
    /// it is inside a curve, closing is a merge like any other.
    pub const DEFAULT: Variant =
        Variant { both_ends: false, two_processed: false, close_both_ends: false };
}

/// The DISCUR edges of `dt` as vertex pairs (see the module docs). Empty without triangles.
pub fn discur(dt: &Triangulation) -> Vec<[u32; 2]> {
    Growth::new(dt, Variant::DEFAULT).run()
}

/// DISCUR with the unknowns of the reconstruction set by `variant`, as a full result (the
/// degenerate results of `docs/algorithms.md` §0.1 included).
#[doc(hidden)]
pub fn discur_variant(dt: &Triangulation, variant: Variant) -> Reconstruction {
    degenerate_result(dt)
        .unwrap_or_else(|| from_vertex_pairs(dt, Growth::new(dt, variant).run(), Stats::default()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Edge, Point};
    use crate::internals::{check_reconstruction, filter_edges};
    use crate::samplers::cycle_edges as cycle;
    use crate::Status;

    fn run(pts: &[Point]) -> Vec<Edge> {
        filter_edges(pts, discur)
    }

    fn run_variant(pts: &[Point], variant: Variant) -> Reconstruction {
        let rec = discur_variant(&Triangulation::new(pts).unwrap(), variant);
        check_reconstruction(pts, &rec).unwrap();
        rec
    }

    /// `n` points on a circle arc of radius `r` from angle `from` to `to`, both ends included.
    fn arc(n: usize, r: f64, from: f64, to: f64) -> Vec<Point> {
        (0..n)
            .map(|i| {
                let a = from + (to - from) * i as f64 / (n - 1) as f64;
                [r * a.cos(), r * a.sin()]
            })
            .collect()
    }

    #[test]
    fn regular_16_gon_is_its_cycle() {
        let pts = crate::samplers::regular_polygon(16, 1.0).points;
        assert_eq!(run(&pts), cycle(16));
    }

    #[test]
    fn open_convex_arc_stays_open() {
        // A quarter circle of 12 points: the chord between its ends (a Delaunay edge, 10
        // spacings long) fails the criterion at both ends, so the arc stays a path (CRAWL
        // closes it).
        let pts = arc(12, 1.0, 0.0, std::f64::consts::FRAC_PI_2);
        let expected: Vec<Edge> = (0..11).map(|i| [i, i + 1]).collect();
        assert_eq!(run(&pts), expected);
    }

    #[test]
    fn an_outlier_stays_free_and_is_not_listed() {
        // A 20-gon of spacing 0.31 and its centre, 1 from every vertex: the polygon closes
        // first, then every edge to the centre is at an inner point and is removed.
        let mut pts = crate::samplers::regular_polygon(20, 1.0).points;
        pts.push([0.0, 0.0]);
        let rec = run_variant(&pts, Variant::DEFAULT);
        assert_eq!(rec.edges, cycle(20));
        assert_eq!(rec.status, Status::Curves);
        assert!(rec.left_out.is_empty());
    }

    #[test]
    fn two_circles_are_two_loops() {
        let mut pts = arc(30, 1.0, 0.0, std::f64::consts::TAU)[..29].to_vec();
        pts.extend(
            arc(30, 1.0, 0.0, std::f64::consts::TAU)[..29].iter().map(|p| [p[0] + 3.0, p[1]]),
        );
        let rec = run_variant(&pts, Variant::DEFAULT);
        assert_eq!(rec.status, Status::Polygons);
        assert_eq!(rec.loops.len(), 2);
    }

    /// A curve of spacing 1 (points 0..=5) and one of spacing 2 (points 6..=9), on a gentle
    /// zigzag, 2.2 apart: too long for the first curve's end, short enough for the second's.
    fn two_spacings() -> Vec<Point> {
        let mut pts: Vec<Point> = (0..6).map(|i| [f64::from(i), 0.05 * f64::from(i % 2)]).collect();
        pts.extend((0..4).map(|i| [7.2 + 2.0 * f64::from(i), 0.05 * f64::from(i % 2)]));
        pts
    }

    #[test]
    fn either_end_accepting_joins_two_curves_by_default() {
        let rec = run_variant(&two_spacings(), Variant::DEFAULT);
        assert_eq!(rec.paths, vec![(0..10).collect::<Vec<_>>()]);
    }

    #[test]
    fn with_both_ends_required_the_curves_stay_apart() {
        let both = Variant { both_ends: true, ..Variant::DEFAULT };
        let rec = run_variant(&two_spacings(), both);
        assert_eq!(rec.paths, vec![(0..6).collect::<Vec<_>>(), (6..10).collect()]);
    }

    #[test]
    fn two_refused_edges_retire_a_point_in_the_two_processed_variant() {
        // Two unit-spaced curves end 2.3 and 2.4 from a point f (too far for both ends); g is
        // 2.6 from f. By default f meets g as a free point and they connect; when two
        // processed edges retire a point, f has no edge left for g.
        let mut pts: Vec<Point> = (0..6).map(|i| [f64::from(i), 0.0]).collect();
        pts.extend((0..6).map(|i| [7.3, -2.4 - f64::from(i)]));
        pts.extend([[7.3, 0.0], [7.3, 2.6]]);
        let default = run_variant(&pts, Variant::DEFAULT);
        assert!(default.edges.contains(&[12, 13]));
        let two = run_variant(&pts, Variant { two_processed: true, ..Variant::DEFAULT });
        assert!(!two.edges.iter().flatten().any(|&i| i == 12), "{:?}", two.edges);
    }

    #[test]
    fn every_variant_keeps_the_invariants() {
        let mut pts = arc(40, 1.0, 0.0, 5.0);
        pts.extend(two_spacings().iter().map(|p| [p[0] * 0.1 + 3.0, p[1] * 0.1]));
        pts.push([0.1, 0.2]);
        for both_ends in [false, true] {
            for two_processed in [false, true] {
                for close_both_ends in [false, true] {
                    run_variant(&pts, Variant { both_ends, two_processed, close_both_ends });
                }
            }
        }
    }

    #[test]
    fn small_inputs_do_not_panic() {
        // The right triangle: both legs (equal lengths) and then the hypotenuse close it.
        let tri = run(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        assert_eq!(tri, vec![[0, 1], [0, 2], [1, 2]]);
        let square = run(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        assert_eq!(square, cycle(4));
        let collinear = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]).unwrap();
        assert!(discur(&collinear).is_empty());
    }
}
