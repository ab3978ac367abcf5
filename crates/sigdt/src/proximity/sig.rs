//! The full spheres-of-influence graph (SIG), for statistics.
//!
//! Edge `pq` iff `|pq| <= r(p) + r(q)` with `r` the nearest-neighbour distance ([Tou88]; the
//! same closed test and tie slack as [`sigdt`](super::sigdt)). SIG is not planar, not a
//! subgraph of the Delaunay triangulation, and has O(n) edges.
//!
//! Every SIG edge satisfies `|pq| <= 2·max(r(p), r(q))`, so each point queries a 2-d tree
//! with radius `2·r(p)` and reports the edges for which it has the larger `(r, index)`.
//!
//! # Complexity
//! O(n log n + output) on typical inputs.
//!
//! # References
//! - [Tou88] G. T. Toussaint. A graph-theoretical primal sketch. 1988.
//!
//! [Tou88]: https://doi.org/10.1016/0167-8655(88)90029-4
use super::kdtree::KdTree;
use super::nearest::nearest_vertex_distances;
use super::sigdt::{is_sig_edge, TIE_SLACK};
use crate::delaunay::Triangulation;
use crate::geometry::Edge;
use crate::geometry::{distance, Point};

/// The SIG of the triangulation's distinct points as sorted input-index pairs.
pub(crate) fn sig(dt: &Triangulation) -> Vec<Edge> {
    let r = nearest_vertex_distances(dt);
    let points: Vec<Point> = (0..dt.num_vertices() as u32).map(|v| dt.point(v)).collect();
    let tree = KdTree::new(&points);
    // Each point's edges on their own (in parallel on a pool), listed in point order.
    let edges = crate::parallel::map_range(points.len(), |p| {
        let (p, rp) = (p as u32, r[p]);
        let mut found = Vec::new();
        if rp.is_finite() {
            tree.within(points[p as usize], 2.0 * rp * (1.0 + TIE_SLACK), &mut found);
        }
        found.retain(|&q| {
            let rq = r[q as usize];
            (rp, p) > (rq, q)
                && is_sig_edge(distance(points[p as usize], points[q as usize]), rp, rq)
        });
        found
    });
    let pairs = edges.iter().enumerate().flat_map(|(p, qs)| qs.iter().map(move |&q| [p as u32, q]));
    dt.to_input_edges(pairs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_brute_force() {
        let pts: Vec<Point> =
            (0..300).map(|i| [((i * 37) % 101) as f64 * 0.3, ((i * 91) % 103) as f64]).collect();
        let dt = Triangulation::new(&pts).unwrap();
        let r: Vec<f64> = (0..300)
            .map(|i| {
                (0..300)
                    .filter(|&j| j != i)
                    .map(|j| distance(pts[i], pts[j]))
                    .fold(f64::INFINITY, f64::min)
            })
            .collect();
        let mut want = Vec::new();
        for i in 0..300 {
            for j in i + 1..300 {
                if is_sig_edge(distance(pts[i], pts[j]), r[i], r[j]) {
                    want.push([i, j]);
                }
            }
        }
        assert_eq!(sig(&dt), want);
    }
}
