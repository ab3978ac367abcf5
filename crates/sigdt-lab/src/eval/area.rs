//! Symmetric difference of area between a reconstruction and the ground truth.
//!
//! `docs/algorithms.md` §4.6, after \[MOW22\] (Figs. 10, 11, 19), who used Boost.Geometry's
//! `sym_difference`, whose rings are implicitly closed:
//!
//! 1. Each edge set is cut into maximal chains: cycles of degree-2 vertices and paths between
//!    vertices of degree ≠ 2.
//! 2. Every chain is a ring, an open one closed implicitly by the segment joining its ends.
//!    Rings with fewer than three distinct points (by coordinates) have no area and are
//!    dropped.
//! 3. The region of an edge set is the even-odd combination of its rings, so nested curves
//!    give holes and a self-overlapping ring counts its doubly covered parts as outside.
//! 4. `area = |region(R) XOR region(GT)|`, computed by the `i_overlay` crate on `f64`
//!    coordinates (it snaps to an integer grid of about 2^-30 of the input's extent, so
//!    results are exact up to that rounding), and `normalised = area / area of the ground
//!    truth's bounding box`.
//!
//! Degenerate input: an empty result (or ground truth) has the empty region; the
//! normalised value is `None` when the ground truth's box has zero area (no edges,
//! collinear or coincident points). Self loops are ignored.
//!
//! # Complexity
//! O((m + k) log m) for `m` edges whose rings cross in `k` points (chains in linear time,
//! the overlay by a sweep line that splits every crossing): O(m log m) on curves, whose rings
//! cross only where the result strays from the ground truth, and quadratic when the edges
//! themselves cross everywhere (a random polygon).
//!
//! # References
//! - \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use super::input::{check_all, edge_bbox, extent, proper_edges, UnitScale};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;
use sigdt::internals::chains;
use sigdt::{Edge, Point, Result};

/// The symmetric difference of area between two edge sets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AreaDifference {
    /// Area of `region(result) XOR region(gt)`, in squared input units.
    pub area: f64,
    /// `area` divided by the area of the ground truth's bounding box; `None` when that box
    /// has zero area.
    pub normalised: Option<f64>,
}

/// The symmetric difference of area between `result` and `gt`, edges over `points`. Fails on
/// non-finite points or edges out of range.
pub fn area_difference(points: &[Point], result: &[Edge], gt: &[Edge]) -> Result<AreaDifference> {
    check_all(points, result, gt)?;
    let (r, g, scale) = unit_rings(points, result, gt);
    let area = match (r.is_empty(), g.is_empty()) {
        (true, true) => 0.0,
        (false, true) => region_area(&r),
        (true, false) => region_area(&g),
        (false, false) => {
            let shapes = FloatOverlay::with_subj_and_clip(&r, &g)
                .overlay(OverlayRule::Xor, FillRule::EvenOdd);
            shapes_area(&shapes)
        }
    };
    let area = scale.unscale_area(area);
    let box_area =
        edge_bbox(points, &proper_edges(gt)).map_or(0.0, |b| extent(b)[0] * extent(b)[1]);
    let normalised = (box_area > 0.0).then(|| area / box_area);
    Ok(AreaDifference { area, normalised })
}

/// The rings of `a` and of `b` (steps 1–2), scaled together by the power of two that brings
/// their coordinates into [1, 2): i_overlay's integer grid overflowed on rings of subnormal
/// coordinates (fuzzing finding 5). Areas measured on them scale by its square.
pub(crate) fn unit_rings(
    points: &[Point],
    a: &[Edge],
    b: &[Edge],
) -> (Vec<Vec<Point>>, Vec<Vec<Point>>, UnitScale) {
    let (mut a, mut b) = (rings(points, a), rings(points, b));
    let scale = UnitScale::of(a.iter().chain(&b).flatten().flatten().copied());
    for p in a.iter_mut().chain(b.iter_mut()).flatten() {
        *p = scale.apply(*p);
    }
    (a, b, scale)
}

/// The even-odd region of `edges` as rings of points (step 1–2).
pub(crate) fn rings(points: &[Point], edges: &[Edge]) -> Vec<Vec<Point>> {
    let edges = proper_edges(edges);
    let mut out = Vec::new();
    for chain in chains(points.len(), &edges, None) {
        let mut ring: Vec<Point> = chain.vertices.iter().map(|&v| points[v]).collect();
        if !chain.cycle && ring.len() > 1 && ring[0] == ring[ring.len() - 1] {
            ring.pop();
        }
        let mut distinct = ring.clone();
        distinct.sort_unstable_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        distinct.dedup();
        if distinct.len() >= 3 {
            out.push(ring);
        }
    }
    out
}

/// Area of the even-odd region of `rings`.
fn region_area(rings: &[Vec<Point>]) -> f64 {
    let shapes =
        FloatOverlay::with_subj(&rings.to_vec()).overlay(OverlayRule::Subject, FillRule::EvenOdd);
    shapes_area(&shapes)
}

/// Total area of overlay output: each shape is an outer contour followed by its holes.
pub(crate) fn shapes_area(shapes: &[Vec<Vec<Point>>]) -> f64 {
    let mut total = 0.0;
    for shape in shapes {
        for (k, contour) in shape.iter().enumerate() {
            let a = ring_area(contour).abs();
            total += if k == 0 { a } else { -a };
        }
    }
    total.max(0.0)
}

/// Signed area of a closed ring by the shoelace formula, relative to its first point.
fn ring_area(ring: &[Point]) -> f64 {
    let Some(&o) = ring.first() else { return 0.0 };
    let mut twice = 0.0;
    for k in 1..ring.len().saturating_sub(1) {
        let (a, b) = (ring[k], ring[k + 1]);
        twice += (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    }
    twice / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, s: f64) -> [Point; 4] {
        [[x, y], [x + s, y], [x + s, y + s], [x, y + s]]
    }
    const SQ: [Edge; 4] = [[0, 1], [1, 2], [2, 3], [0, 3]];

    fn shifted(edges: &[Edge], by: usize) -> Vec<Edge> {
        edges.iter().map(|&[i, j]| [i + by, j + by]).collect()
    }

    #[test]
    fn identical_squares() {
        let d = area_difference(&square(0.0, 0.0, 1.0), &SQ, &SQ).unwrap();
        assert_eq!(d, AreaDifference { area: 0.0, normalised: Some(0.0) });
    }

    #[test]
    fn offset_unit_squares() {
        let mut pts = square(0.0, 0.0, 1.0).to_vec();
        pts.extend(square(0.5, 0.0, 1.0));
        let d = area_difference(&pts, &shifted(&SQ, 4), &SQ).unwrap();
        assert!((d.area - 1.0).abs() < 1e-6, "{d:?}");
        assert!((d.normalised.unwrap() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn nested_rings_make_holes() {
        let mut pts = square(0.0, 0.0, 4.0).to_vec();
        pts.extend(square(1.0, 1.0, 2.0));
        let both: Vec<Edge> = SQ.iter().copied().chain(shifted(&SQ, 4)).collect();
        // The annulus (16 - 4 = 12) against the outer square alone differs by the hole.
        let d = area_difference(&pts, &both, &SQ).unwrap();
        assert!((d.area - 4.0).abs() < 1e-6, "{d:?}");
        let d = area_difference(&pts, &[], &both).unwrap();
        assert!((d.area - 12.0).abs() < 1e-6, "{d:?}");
    }

    #[test]
    fn open_chains_are_closed_and_degenerate_rings_ignored() {
        let pts = square(0.0, 0.0, 1.0);
        // The path 0-1-2 closes into the triangle 0-1-2 of area 1/2.
        let d = area_difference(&pts, &[[0, 1], [1, 2]], &SQ).unwrap();
        assert!((d.area - 0.5).abs() < 1e-6, "{d:?}");
        let d = area_difference(&pts, &[[0, 1], [3, 3]], &SQ).unwrap();
        assert!((d.area - 1.0).abs() < 1e-6, "{d:?}");
        let line = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
        let d = area_difference(&line, &[[0, 1], [1, 2], [0, 2]], &[[0, 1]]).unwrap();
        assert_eq!(d, AreaDifference { area: 0.0, normalised: Some(0.0) });
        let d = area_difference(&[[0.0, 0.0], [1.0, 0.0]], &[], &[[0, 1]]).unwrap();
        assert_eq!(d, AreaDifference { area: 0.0, normalised: None });
        assert!(area_difference(&pts, &[], &[[0, 9]]).is_err());
    }
}
