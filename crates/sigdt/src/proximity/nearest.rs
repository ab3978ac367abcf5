//! Nearest-neighbour distances read off the Delaunay triangulation.
//!
//! The nearest neighbour `q` of a point `p` is always a Delaunay neighbour (the disk with
//! diameter `pq` lies in the empty disk of radius `|pq|` around `p`, so `pq` is a Gabriel
//! edge), so `r(v)` is the length of the shortest Delaunay edge at `v` ([MOW22] Algorithm 1,
//! l. 3–5).
//!
//! # Complexity
//! O(n) given the triangulation.
//!
//! # References
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::{Shape, Triangulation, EMPTY};
use crate::geometry::{distance, squared_distance, Point};

/// The distance from every input point to its nearest distinct point, in the caller's
/// coordinates (`points` are those `dt` was built from): the radius of its SIG circle. Exact
/// duplicates get 0, a lone point `∞`.
pub fn nearest_neighbour_distances(dt: &Triangulation, points: &[Point]) -> Vec<f64> {
    let mut r = vec![0.0; dt.input_len()];
    for (v, &(_, w)) in nearest(dt).iter().enumerate() {
        let i = dt.input_index(v as u32);
        r[i] =
            if w == EMPTY { f64::INFINITY } else { distance(points[i], points[dt.input_index(w)]) };
    }
    r
}

/// `r[v]`: distance from vertex `v` to its nearest other vertex (`∞` for a lone point), in
/// the triangulation's scaled coordinates.
pub(crate) fn nearest_vertex_distances(dt: &Triangulation) -> Vec<f64> {
    if dt.shape() != Shape::Proper {
        return nearest(dt).into_iter().map(|(len2, _)| len2.sqrt()).collect();
    }
    // Minimum of squared lengths, then one square root per vertex: sqrt is monotone and
    // correctly rounded, so this equals the minimum of the lengths. Every edge at `v` is an
    // outgoing half-edge of `v`, but for its incoming hull edge: one pass over the
    // half-edges with a branch-free minimum. Which neighbour is nearest is not needed,
    // and the half-edge filter and compare-and-keep of [`nearest`] mispredict about every
    // other edge, which made that pass three times slower.
    let min = |r: &mut f64, len2: f64| *r = if len2 < *r { len2 } else { *r };
    let add_range = |range: std::ops::Range<usize>, r2: &mut [f64]| {
        for h in range.start as u32..range.end as u32 {
            let (a, b) = (dt.origin(h), dt.dest(h));
            let len2 = squared_distance(dt.point(a), dt.point(b));
            min(&mut r2[a as usize], len2);
            if dt.twin(h) == EMPTY {
                min(&mut r2[b as usize], len2);
            }
        }
    };
    // Split among the threads (`parallel::tally`): a minimum does not depend on the split.
    let (halfedges, vertices) = (dt.num_halfedges(), dt.num_vertices());
    let mut r2 = crate::parallel::tally(halfedges, vertices, f64::INFINITY, add_range, min);
    crate::parallel::update_slice(&mut r2, |x| *x = x.sqrt());
    r2
}

/// Per vertex: the squared distance to its nearest other vertex and that vertex (ties to the
/// first edge in [`Triangulation::edge_halfedges`] order), `(∞, EMPTY)` for a lone point.
/// On several threads each vertex scans its own star, in parallel; on one, a single pass over
/// the edges is cheaper. Both keep, among the nearest, the edge first in that order.
fn nearest(dt: &Triangulation) -> Vec<(f64, u32)> {
    match dt.shape() {
        Shape::Proper if !crate::parallel::is_parallel() => {
            let mut r = vec![(f64::INFINITY, EMPTY); dt.num_vertices()];
            for h in dt.edge_halfedges() {
                let (a, b) = (dt.origin(h), dt.dest(h));
                let len2 = squared_distance(dt.point(a), dt.point(b));
                for (x, y) in [(a, b), (b, a)] {
                    if len2 < r[x as usize].0 {
                        r[x as usize] = (len2, y);
                    }
                }
            }
            r
        }
        Shape::Proper => crate::parallel::map_range(dt.num_vertices(), |v| {
            let v = v as u32;
            // (squared length, other end, the edge's representative half-edge)
            let mut best = (f64::INFINITY, EMPTY, EMPTY);
            for h in dt.incident(v) {
                let twin = dt.twin(h);
                let edge = if twin < h { twin } else { h };
                let w = dt.other(h, v);
                let len2 = squared_distance(dt.point(v), dt.point(w));
                if len2 < best.0 || (len2 == best.0 && edge < best.2) {
                    best = (len2, w, edge);
                }
            }
            (best.0, best.1)
        }),
        _ => {
            let mut r = vec![(f64::INFINITY, EMPTY); dt.num_vertices()];
            for [a, b] in dt.line_edges() {
                let len2 = squared_distance(dt.point(a), dt.point(b));
                for (x, y) in [(a, b), (b, a)] {
                    if len2 < r[x as usize].0 {
                        r[x as usize] = (len2, y);
                    }
                }
            }
            r
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_are_the_shortest_edge_at_every_vertex() {
        let mut rng = crate::samplers::Rng::new(5);
        let points: Vec<[f64; 2]> = (0..3000).map(|_| [rng.uniform(), rng.uniform()]).collect();
        let dt = Triangulation::new(&points).unwrap();
        let r = nearest_vertex_distances(&dt);
        for v in 0..dt.num_vertices() as u32 {
            let shortest = dt.incident(v).map(|h| dt.length(h)).fold(f64::INFINITY, f64::min);
            assert_eq!(r[v as usize], shortest, "vertex {v}");
        }
        assert_eq!(r, nearest(&dt).iter().map(|(len2, _)| len2.sqrt()).collect::<Vec<_>>());
    }

    #[test]
    fn nearest_on_a_rectangle() {
        let dt = Triangulation::new(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]).unwrap();
        // Distances are in scaled units: compare ratios only.
        let r = nearest_vertex_distances(&dt);
        assert!(r.iter().all(|&x| x == r[0] && x > 0.0));
        let points = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0], [2.0, 1.0]];
        let dt = Triangulation::new(&points).unwrap();
        assert_eq!(nearest_neighbour_distances(&dt, &points), vec![1.0, 1.0, 1.0, 1.0, 0.0]);
    }
}
