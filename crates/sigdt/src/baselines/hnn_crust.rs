//! HNN-CRUST: nearest and "half-plane" nearest neighbours, kept where the choice is mutual.
//!
//! [OMW16] as in the authors' reference code, `docs/algorithms.md` §3.3 (no Delaunay edges needed):
//! 1. for each point `p`, its `K = min(15, m)` nearest points including itself, nearest
//!    first (a 2-d tree; ties by input index);
//! 2. `nn1(p)`: the nearest other point;
//! 3. `nn2(p)`: the first `r` in that list after `nn1` with `|nn1 r| > |p nn1|` and
//!    `|nn1 r| > |p r|` (both strict: `nn1 r` is the longest side of the triangle
//!    `p nn1 r`, and `r` lies strictly on `p`'s side of the bisector of `p nn1`); none if no
//!    point of the list qualifies;
//! 4. the edge `{p, x}` for `x ∈ {nn1(p), nn2(p)}` iff also `p ∈ {nn1(x), nn2(x)}`.
//!
//! Every distance comparison is decided exactly (squared distances expanded into sums of
//! coordinate products, `sign_of_sum_of_products`): both in step 3 and in the ordering of
//! step 1, whose `f64` squared distances only pick the candidates from the 2-d tree. (An
//! `f64` ordering breaks near-ties by index instead of by distance; with far-apart clusters
//! that chose a farther point as `nn2` and made two HNN edges cross.)
//!
//! # Guarantee
//! If the points are an ε-sample of a smooth closed curve with ε < 0.47 (ρ < 0.9), the
//! result is exactly the polygon connecting curve neighbours; unlike NN-CRUST no uniformity
//! is needed ([OMW16], as quoted in [MOW22]). Mutual selection leaves the endpoints of open
//! curves with degree 1 more often than NN-CRUST does, but there is no guarantee for open
//! curves, corners or noise. The edges need not be Delaunay edges.
//!
//! # Complexity
//! O(n log n): the 2-d tree and `n` queries of `K ≤ 15` neighbours.
//!
//! # Departures
//! The reference test harness skips the second neighbour at the two ends of curves it knows
//! to be open; that uses the ground truth and is not reproduced.
//!
//! # References
//! - [OMW16] S. Ohrhallinger, S. A. Mitchell, M. Wimmer. Curve reconstruction with many
//!   fewer samples. Computer Graphics Forum 35(5) (SGP), 2016.
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [OMW16]: https://doi.org/10.1111/cgf.12973
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use super::nn_crust::sign_of_sum_of_products;
use crate::delaunay::Triangulation;
use crate::geometry::Point;
use crate::proximity::kdtree::KdTree;
use std::cmp::Ordering;

/// Neighbourhood size, including the point itself (hard-coded in the reference code).
const K: usize = 15;

/// The HNN-CRUST edges of the vertices of `dt` (a
/// [`Shape::Proper`](crate::delaunay::Shape::Proper) triangulation) as pairs of vertices,
/// each undirected edge once.
pub fn hnn_crust(dt: &Triangulation) -> Vec<[u32; 2]> {
    let points: Vec<Point> = (0..dt.num_vertices() as u32).map(|v| dt.point(v)).collect();
    let tree = KdTree::new(&points);
    let others = K.min(points.len()).saturating_sub(1);
    // Steps 1–3: nn1 and nn2 of every point, each on its own (in parallel on a pool).
    let chosen: Vec<[Option<u32>; 2]> = crate::parallel::map_range(points.len(), |p| {
        let p = p as u32;
        let near = nearest(dt, &tree, &points, p, others);
        let Some(&n1) = near.first() else {
            return [None, None];
        };
        let (pp, n) = (points[p as usize], points[n1 as usize]);
        let n2 = near[1..].iter().copied().find(|&r| {
            let r = points[r as usize];
            // |nn1 r| > |p nn1| and |nn1 r| > |p r|.
            farther(n, r, pp) && farther(r, n, pp)
        });
        [Some(n1), n2]
    });
    // Step 4: mutual choices, each edge once (from its lower vertex).
    let mut pairs = Vec::with_capacity(points.len());
    for (p, choice) in chosen.iter().enumerate() {
        let p = p as u32;
        for x in choice.iter().flatten().copied() {
            if p < x && chosen[x as usize].contains(&Some(p)) {
                pairs.push([p, x]);
            }
        }
    }
    pairs
}

/// Whether `|x a| > |x b|`, exactly.
fn farther(x: Point, a: Point, b: Point) -> bool {
    compare_distances(x, a, b) == Ordering::Greater
}

/// `|x a|` compared with `|x b|`, exactly.
fn compare_distances(x: Point, a: Point, b: Point) -> Ordering {
    // |x - a|² - |x - b|² = a·a - b·b - 2x·a + 2x·b, coordinate by coordinate.
    let [ax, ay] = a;
    let [bx, by] = b;
    let (x2, y2) = (2.0 * x[0], 2.0 * x[1]);
    sign_of_sum_of_products(&[
        (ax, ax),
        (-bx, bx),
        (-x2, ax),
        (x2, bx),
        (ay, ay),
        (-by, by),
        (-y2, ay),
        (y2, by),
    ])
}

/// The `k` points nearest to `p` other than itself, nearest first, ties by input index.
fn nearest(dt: &Triangulation, tree: &KdTree, points: &[Point], p: u32, k: usize) -> Vec<u32> {
    if k == 0 {
        return Vec::new();
    }
    let x = points[p as usize];
    let mut extra = 4;
    loop {
        // The tree orders by `f64` squared distance, ties by vertex number. Asking for more
        // than `k` and re-sorting exactly (ties by input index) is exact once the list holds
        // every other point, or once the `f64` distances of the first `k` stay below the
        // farthest one retrieved by more than their rounding error (a few ulps).
        let want = k + extra;
        let mut near = tree.nearest(x, want, p);
        near.sort_by(|a, b| {
            let (pa, pb) = (points[a.1 as usize], points[b.1 as usize]);
            compare_distances(x, pa, pb).then(dt.input_index(a.1).cmp(&dt.input_index(b.1)))
        });
        let kth = near.iter().take(k).map(|a| a.0).fold(0.0, f64::max);
        let last = near.iter().map(|a| a.0).fold(0.0, f64::max);
        if near.len() < want || near.len() <= k || kth * (1.0 + 16.0 * f64::EPSILON) < last {
            return near.into_iter().take(k).map(|(_, v)| v).collect();
        }
        extra *= 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Edge;
    use crate::internals::filter_edges;
    use crate::samplers::cycle_edges as cycle;
    use crate::samplers::regular_polygon;

    fn hnn_crust_edges(points: &[Point]) -> Vec<Edge> {
        filter_edges(points, hnn_crust)
    }

    #[test]
    fn regular_16_gon_gives_its_sides() {
        let pts = regular_polygon(16, 1.0).points;
        assert_eq!(hnn_crust_edges(&pts), cycle(16));
    }

    #[test]
    fn square_gives_its_sides() {
        // Point 0: nn1 = 1 (tie with 3, by index), nn2 = 3; likewise around the square.
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(hnn_crust_edges(&pts), cycle(4));
    }

    #[test]
    fn strict_tests_and_mutual_selection() {
        // 2 is equidistant from 0 and 1, so `|nn1 r| > |p r|` fails exactly for r = 2 at
        // both 0 and 1. Choices: 0 → {1}, 1 → {0, 3}, 2 → {0, 3}, 3 → {1}; mutual: 01, 13.
        let pts = [[0.0, 0.0], [1.0, 0.0], [0.5, 0.9], [10.0, 0.0]];
        assert_eq!(hnn_crust_edges(&pts), vec![[0, 1], [1, 3]]);
    }

    #[test]
    fn dense_ellipse_is_reconstructed_exactly() {
        let n = 250;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * (i as f64 + 0.37) / n as f64;
                [2.5 * t.cos() + 7.0, t.sin() - 2.0]
            })
            .collect();
        assert_eq!(hnn_crust_edges(&pts), cycle(n));
    }

    #[test]
    fn open_arc_is_a_path() {
        // The endpoints find no second neighbour: every other point lies beyond nn1.
        let n = 30;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let t = 5f64.to_radians() * i as f64;
                [1.3 * t.cos(), t.sin()]
            })
            .collect();
        let path: Vec<Edge> = (0..n - 1).map(|i| [i, i + 1]).collect();
        assert_eq!(hnn_crust_edges(&pts), path);
    }

    #[test]
    fn permuting_the_input_relabels_the_output() {
        let n = 90;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * (i as f64 + 0.29) / n as f64;
                let r = 1.0 + 0.25 * (3.0 * t).sin();
                [r * t.cos(), 1.2 * r * t.sin()]
            })
            .collect();
        let perm: Vec<usize> = (0..n).map(|i| (i * 37 + 11) % n).collect();
        let permuted: Vec<Point> = perm.iter().map(|&i| pts[i]).collect();
        let mut back: Vec<Edge> = hnn_crust_edges(&permuted)
            .into_iter()
            .map(|[a, b]| [perm[a].min(perm[b]), perm[a].max(perm[b])])
            .collect();
        back.sort_unstable();
        assert_eq!(back, hnn_crust_edges(&pts));
    }

    #[test]
    fn exact_distance_comparison() {
        let big = 2f64.powi(30);
        // |x a| = |x b| exactly although the squares cancel catastrophically.
        assert!(!farther([big, big], [big + 3.0, big + 4.0], [big + 5.0, big]));
        assert!(farther([big, big], [big + 3.0, big + 4.0], [big + 5.0 - 1e-6, big]));
    }
}
