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
use crate::delaunay::{Shape, Triangulation};
use crate::geometry::squared_distance;

/// `r[v]`: distance from vertex `v` to its nearest other vertex (`∞` for a lone point), in
/// the triangulation's scaled coordinates.
pub fn nearest_neighbour_distances(dt: &Triangulation) -> Vec<f64> {
    // Minimum of squared lengths, then one square root per vertex: sqrt is monotone and
    // correctly rounded, so this equals the minimum of the lengths.
    let mut r = vec![f64::INFINITY; dt.num_vertices()];
    let mut visit = |a: u32, b: u32| {
        let len2 = squared_distance(dt.point(a), dt.point(b));
        r[a as usize] = r[a as usize].min(len2);
        r[b as usize] = r[b as usize].min(len2);
    };
    match dt.shape() {
        Shape::Proper => dt.edge_halfedges().for_each(|h| visit(dt.origin(h), dt.dest(h))),
        _ => dt.line_edges().for_each(|[a, b]| visit(a, b)),
    }
    r.iter_mut().for_each(|x| *x = x.sqrt());
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_on_a_rectangle() {
        let dt = Triangulation::new(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]).unwrap();
        // Distances are in scaled units: compare ratios only.
        let r = nearest_neighbour_distances(&dt);
        assert!(r.iter().all(|&x| x == r[0] && x > 0.0));
    }
}
