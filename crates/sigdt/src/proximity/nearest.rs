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
    // Minimum of squared lengths, then one square root per vertex: sqrt is monotone and
    // correctly rounded, so this equals the minimum of the lengths.
    nearest(dt).into_iter().map(|(len2, _)| len2.sqrt()).collect()
}

/// Per vertex: the squared distance to its nearest other vertex and that vertex (ties to the
/// first edge met), `(∞, EMPTY)` for a lone point.
fn nearest(dt: &Triangulation) -> Vec<(f64, u32)> {
    let mut r = vec![(f64::INFINITY, EMPTY); dt.num_vertices()];
    let mut visit = |a: u32, b: u32| {
        let len2 = squared_distance(dt.point(a), dt.point(b));
        for (x, y) in [(a, b), (b, a)] {
            if len2 < r[x as usize].0 {
                r[x as usize] = (len2, y);
            }
        }
    };
    match dt.shape() {
        Shape::Proper => dt.edge_halfedges().for_each(|h| visit(dt.origin(h), dt.dest(h))),
        _ => dt.line_edges().for_each(|[a, b]| visit(a, b)),
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

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
