//! How far a case's labelled samples stray from its true curve: `d_max`, the largest distance
//! from a point on some ground-truth edge to the curve's segments. It is 0 (up to rounding) on
//! clean data and the noise's reach on noisy data, so that a judge of results (`sigdt bench`'s
//! Hausdorff bound of a good result) can forgive what the input points themselves stray, and
//! no more.
//!
//! # Complexity
//! The segments in a [`SegmentGrid`](super::grid): O(m log m) to build for `m` segments, O(1)
//! a sample near an evenly sampled curve, O(m) at worst; so O(n + m log m) for `n` samples
//! near a dense curve, against O(n m) by brute force.
use super::grid::SegmentGrid;
use sigdt::{Edge, Point};

/// The largest distance from a point of `points` on some edge of `gt` (a self loop is no
/// edge) to the polyline `curve` (its points and edges); 0 without such a point, infinite
/// when the curve has no edge.
pub fn stray(points: &[Point], gt: &[Edge], curve: (&[Point], &[Edge])) -> f64 {
    let (curve_points, curve_edges) = curve;
    if curve_edges.is_empty() {
        return if gt.iter().any(|[i, j]| i != j) { f64::INFINITY } else { 0.0 };
    }
    let segments = curve_edges.iter().map(|&[i, j]| [curve_points[i], curve_points[j]]);
    let grid = SegmentGrid::new(segments.collect());
    let mut labelled = vec![false; points.len()];
    for &[i, j] in gt.iter().filter(|[i, j]| i != j) {
        (labelled[i], labelled[j]) = (true, true);
    }
    let samples = points.iter().zip(labelled).filter_map(|(&p, on)| on.then_some(p));
    samples.fold(0.0, |worst: f64, q| worst.max(grid.nearest_distance(q)))
}

#[cfg(test)]
mod tests {
    use super::super::grid::point_segment_distance;
    use super::*;

    /// A regular `n`-gon of radius `r` as points and a closed ring of edges.
    fn ring(n: usize, r: f64) -> (Vec<Point>, Vec<Edge>) {
        let points = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        let mut edges: Vec<Edge> = (1..n).map(|k| [k - 1, k]).collect();
        edges.push([0, n - 1]);
        (points, edges)
    }

    #[test]
    fn samples_on_the_curve_stray_nothing_and_outliers_do_not_count() {
        // The unit square as curve; its corners and mid-sides as samples, one of them moved
        // 0.25 out; an outlier far away without edges, a self loop that is no edge.
        let square = (
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            vec![[0, 1], [1, 2], [2, 3], [0, 3]],
        );
        let curve = (&square.0[..], &square.1[..]);
        let mut points =
            vec![[0.0, 0.0], [0.5, 0.0], [1.0, 0.0], [1.0, 0.5], [1.0, 1.0], [9.0, 9.0]];
        let gt = [[0, 1], [1, 2], [2, 3], [3, 4], [5, 5]];
        assert_eq!(stray(&points, &gt, curve), 0.0);
        points[3] = [1.25, 0.5];
        assert_eq!(stray(&points, &gt, curve), 0.25);
        assert_eq!(stray(&points, &[], curve), 0.0, "no labelled sample");
        assert_eq!(stray(&points, &gt, (&square.0, &[])), f64::INFINITY, "no curve");
    }

    #[test]
    fn the_grid_matches_brute_force() {
        // Noisy samples of a circle against the dense circle and a long chord.
        let (mut curve, mut edges) = ring(700, 10.0);
        curve.extend([[-30.0, -2.0], [40.0, 3.0]]);
        edges.push([700, 701]);
        let mut seed = 11u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let (mut points, gt) = ring(300, 10.0);
        for p in &mut points {
            (p[0], p[1]) = (p[0] + next(), p[1] + next());
        }
        points[17] = [25.0, -14.0];
        let brute = points
            .iter()
            .map(|&q| {
                let d = |&[i, j]: &Edge| point_segment_distance(q, curve[i], curve[j]);
                edges.iter().map(d).fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max);
        assert_eq!(stray(&points, &gt, (&curve, &edges)), brute);
    }
}
