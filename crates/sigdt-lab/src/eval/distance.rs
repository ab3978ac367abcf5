//! Distance errors between a reconstruction and the ground-truth polygon.
//!
//! `docs/algorithms.md` §4.5, after the "RMS error between the reconstructed curve and the
//! original" of \[MOW22\] (Figs. 14, 16–18):
//!
//! 1. `diag` = diagonal of the ground truth's bounding box, `h = diag / 2000`.
//! 2. Both edge sets are sampled by arc length: every distinct vertex once, plus
//!    `ceil(len / h) - 1` evenly spaced interior points on each edge.
//! 3. `d_RC` = distance from each result sample to the nearest ground-truth edge, `d_CR` =
//!    from each ground-truth sample to the nearest result edge (uniform [`SegmentGrid`]s).
//! 4. `rmse = sqrt(mean(d_RC² ∪ d_CR²))` (two-sided: penalises missing parts and wrong edges
//!    alike), `rmse_to_gt = sqrt(mean(d_RC²))` (one-sided), `hausdorff = max(d_RC ∪ d_CR)`,
//!    all divided by `diag`.
//!
//! Degenerate input: an empty result or ground truth (after dropping duplicate edges) gives
//! `None` (§4.5 step 4: undefined, count it as a failure). Self loops count as single points.
//! If the ground truth's box has zero diagonal (all its points coincide), the box of both
//! sets is used instead, and if that is zero too all errors are 0.
//!
//! # Complexity
//! O(n + s) for `s = L / h` samples on curves of total length `L`, plus the grids' build
//! (O(m log m)); each sample's query is O(1) on evenly sampled curves.
//!
//! # References
//! - \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [`SegmentGrid`]: super::grid
use super::grid::{lerp, SegmentGrid};
use super::input::{check_all, edge_bbox, extent, normalise, UnitScale};
use sigdt::{Edge, Point, Reconstruction, Result};

/// Distance errors of a reconstruction, as fractions of the ground truth's bounding-box
/// diagonal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistanceErrors {
    /// Two-sided root mean square distance (result samples to the ground truth and back).
    pub rmse: f64,
    /// One-sided root mean square distance from result samples to the ground truth.
    pub rmse_to_gt: f64,
    /// Symmetric Hausdorff distance between the two edge sets (up to the sample spacing).
    pub hausdorff: f64,
}

/// Samples per bounding-box diagonal (`docs/algorithms.md` §4.5).
pub const SAMPLES_PER_DIAGONAL: f64 = 2000.0;

/// The most edge-interior samples taken of one edge set, about a million (see
/// `for_each_sample`): the labelled curves need far fewer, and 2^20 queries stay under a
/// second even in slow subnormal arithmetic.
pub const MAX_SAMPLES: usize = 1 << 20;

/// The distance errors of `result` against `gt`, edges over `points`; `None` when either edge
/// set is empty. Fails on non-finite points or edges out of range.
pub fn distance_errors(
    points: &[Point],
    result: &[Edge],
    gt: &[Edge],
) -> Result<Option<DistanceErrors>> {
    check_all(points, result, gt)?;
    let (result, gt) = (normalise(result), normalise(gt));
    // Scaled by the power of two that brings the largest coordinate of an edge end into
    // [1, 2): exact, and no squared length overflows (beyond 1e154) or spacing underflows
    // (subnormal edges: `h` became 0 and every edge got 2^24 samples, fuzzing finding 6).
    let scale = UnitScale::of(result.iter().chain(&gt).flatten().flat_map(|&i| points[i]));
    let scaled: Vec<Point> = points.iter().map(|&p| scale.apply(p)).collect();
    let points = &scaled[..];
    let (Some(gbox), Some(rbox)) = (edge_bbox(points, &gt), edge_bbox(points, &result)) else {
        return Ok(None);
    };
    let mut diag = extent(gbox)[0].hypot(extent(gbox)[1]);
    if diag == 0.0 {
        let both = [
            [gbox[0][0].min(rbox[0][0]), gbox[0][1].min(rbox[0][1])],
            [gbox[1][0].max(rbox[1][0]), gbox[1][1].max(rbox[1][1])],
        ];
        diag = extent(both)[0].hypot(extent(both)[1]);
    }
    if diag == 0.0 || !diag.is_finite() {
        return Ok(Some(DistanceErrors { rmse: 0.0, rmse_to_gt: 0.0, hausdorff: 0.0 }));
    }
    let h = diag / SAMPLES_PER_DIAGONAL;
    let segments = |edges: &[Edge]| edges.iter().map(|&[i, j]| [points[i], points[j]]).collect();
    let (rgrid, ggrid) = (SegmentGrid::new(segments(&result)), SegmentGrid::new(segments(&gt)));
    let (mut sum_rc, mut n_rc, mut max) = (0.0, 0usize, 0.0f64);
    for_each_sample(points, &result, h, |q| {
        let d = ggrid.nearest_distance(q);
        sum_rc += d * d;
        n_rc += 1;
        max = max.max(d);
    });
    let (mut sum_cr, mut n_cr) = (0.0, 0usize);
    for_each_sample(points, &gt, h, |q| {
        let d = rgrid.nearest_distance(q);
        sum_cr += d * d;
        n_cr += 1;
        max = max.max(d);
    });
    Ok(Some(DistanceErrors {
        rmse: ((sum_rc + sum_cr) / (n_rc + n_cr) as f64).sqrt() / diag,
        rmse_to_gt: (sum_rc / n_rc as f64).sqrt() / diag,
        hausdorff: max / diag,
    }))
}

/// The distance errors of `rec`, a reconstruction of `points`, against the ground truth `gt`
/// over `truth` (the clean positions of noisy points, or `points` itself): the result's edges
/// are taken over its own vertices ([`Vertices`](sigdt::Vertices)), so methods that move the points or place
/// vertices of their own (OPTIMALTRANSPORT) are scored like the others. Fails as
/// [`distance_errors`].
pub fn reconstruction_distance_errors(
    points: &[Point],
    rec: &Reconstruction,
    truth: &[Point],
    gt: &[Edge],
) -> Result<Option<DistanceErrors>> {
    let vertices = rec.vertex_positions(points);
    let n = vertices.len();
    let shifted: Vec<Edge> = gt.iter().map(|&[i, j]| [i + n, j + n]).collect();
    distance_errors(&[vertices, truth].concat(), &rec.edges, &shifted)
}

/// Calls `f` on every distinct vertex of `edges` and on the interior samples of every edge,
/// spaced at most `h` apart.
///
/// The spacing grows beyond `h` when `h` would give more than [`MAX_SAMPLES`] interior
/// samples in all (a result edge far outside the ground truth's box, or an `h` that
/// underflowed to 0 on subnormal edges): the samples are then shared out by length, and the
/// errors stay exact at the vertices and within the coarser spacing elsewhere. The budget is
/// counted in samples, not derived from a spacing, so it holds whatever the magnitudes.
fn for_each_sample(points: &[Point], edges: &[Edge], h: f64, mut f: impl FnMut(Point)) {
    let length = |&[i, j]: &Edge| (points[i][0] - points[j][0]).hypot(points[i][1] - points[j][1]);
    let total: f64 = edges.iter().map(length).sum();
    let budget = MAX_SAMPLES as f64;
    // Interior samples of an edge of length `len`: len / h, or its share of the budget.
    let within_budget = h > 0.0 && total / h <= budget;
    let mut vertices: Vec<usize> = edges.iter().flatten().copied().collect();
    vertices.sort_unstable();
    vertices.dedup();
    for &v in &vertices {
        f(points[v]);
    }
    for edge in edges {
        let len = length(edge);
        let pieces = if within_budget {
            len / h
        } else if total > 0.0 {
            budget * (len / total)
        } else {
            1.0
        };
        let pieces = pieces.ceil().clamp(1.0, budget) as usize;
        let (p, q) = (points[edge[0]], points[edge[1]]);
        for k in 1..pieces {
            f(lerp(p, q, k as f64 / pieces as f64));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sigdt::Vertices;

    const SQUARE: [Point; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    const SQUARE_EDGES: [Edge; 4] = [[0, 1], [1, 2], [2, 3], [0, 3]];

    #[test]
    fn identical_sets_have_no_error() {
        let e = distance_errors(&SQUARE, &SQUARE_EDGES, &SQUARE_EDGES).unwrap().unwrap();
        assert_eq!(e, DistanceErrors { rmse: 0.0, rmse_to_gt: 0.0, hausdorff: 0.0 });
    }

    #[test]
    fn a_missing_edge_is_seen_from_the_ground_truth_only() {
        let e = distance_errors(&SQUARE, &SQUARE_EDGES[..3], &SQUARE_EDGES).unwrap().unwrap();
        assert_eq!(e.rmse_to_gt, 0.0);
        // The left side (x = 0) is at distance min(y, 1 - y, ...) from the three others: the
        // farthest point, its midpoint, is 0.5 away; the diagonal is sqrt 2.
        assert!((e.hausdorff - 0.5 / 2f64.sqrt()).abs() < 1e-3);
        assert!(e.rmse > 0.0 && e.rmse < e.hausdorff);
    }

    #[test]
    fn a_shifted_square_has_the_shift_as_error() {
        let mut pts = SQUARE.to_vec();
        pts.extend(SQUARE.iter().map(|p| [p[0], p[1] + 0.01]));
        let shifted = [[4, 5], [5, 6], [6, 7], [4, 7]];
        let e = distance_errors(&pts, &shifted, &SQUARE_EDGES).unwrap().unwrap();
        assert!((e.hausdorff - 0.01 / 2f64.sqrt()).abs() < 1e-12);
        assert!(e.rmse <= e.hausdorff && e.rmse > 0.5 * e.hausdorff);
    }

    #[test]
    fn huge_and_tiny_coordinates_give_the_same_errors() {
        let mut pts = SQUARE.to_vec();
        pts.extend(SQUARE.iter().map(|p| [p[0], p[1] + 0.01]));
        let shifted = [[4, 5], [5, 6], [6, 7], [4, 7]];
        let unit = distance_errors(&pts, &shifted, &SQUARE_EDGES).unwrap().unwrap();
        for scale in [2f64.powi(1000), 1e300, 1e-300, 2f64.powi(-1000)] {
            let big: Vec<Point> = pts.iter().map(|p| [p[0] * scale, p[1] * scale]).collect();
            let e = distance_errors(&big, &shifted, &SQUARE_EDGES).unwrap().unwrap();
            assert!((e.rmse - unit.rmse).abs() < 1e-12 * unit.rmse, "{scale}: {e:?}");
            assert!((e.hausdorff - unit.hausdorff).abs() < 1e-12 * unit.hausdorff, "{scale}");
        }
    }

    #[test]
    fn results_are_scored_on_their_own_vertices() {
        // A square shifted up by 0.01 as new vertices, against the square: the shift.
        let moved: Vec<Point> = SQUARE.iter().map(|p| [p[0], p[1] + 0.01]).collect();
        let rec = Reconstruction {
            edges: SQUARE_EDGES.iter().map(|&[i, j]| [i.min(j), i.max(j)]).collect(),
            vertices: Vertices::New(moved),
            ..Reconstruction::default()
        };
        let e = reconstruction_distance_errors(&[], &rec, &SQUARE, &SQUARE_EDGES).unwrap();
        assert!((e.unwrap().hausdorff - 0.01 / 2f64.sqrt()).abs() < 1e-12);
        // On the input points it is the plain metric.
        let rec = Reconstruction { edges: SQUARE_EDGES.to_vec(), ..Reconstruction::default() };
        let e = reconstruction_distance_errors(&SQUARE, &rec, &SQUARE, &SQUARE_EDGES).unwrap();
        assert_eq!(e.unwrap().rmse, 0.0);
    }

    #[test]
    fn degenerate_inputs() {
        assert_eq!(distance_errors(&SQUARE, &[], &SQUARE_EDGES).unwrap(), None);
        assert_eq!(distance_errors(&SQUARE, &SQUARE_EDGES, &[]).unwrap(), None);
        let same = [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]];
        let e = distance_errors(&same, &[[0, 2]], &[[0, 1]]).unwrap().unwrap();
        assert_eq!(e.hausdorff, 0.0);
        let e = distance_errors(&SQUARE, &[[2, 2]], &[[0, 1]]).unwrap().unwrap();
        assert!((e.rmse_to_gt - 1.0).abs() < 1e-12); // the loop at (1, 1) is 1 from the x axis
        assert!(distance_errors(&SQUARE, &[[0, 4]], &SQUARE_EDGES).is_err());
    }
}
