//! CONNECT2D: inflating and sculpting started from the boundary graph BC₀.
//!
//! [OM13]: BC₀ approximates a minimum-length boundary that interpolates every point with
//! degree ≥ 2 in one connected component: "a superset of the EMST constraining vertex degree
//! to ≥ 2 instead of ≥ 1" ([MOW22] §4.1). We build it as the Euclidean minimum spanning
//! tree plus, for every leaf, its shortest missing Delaunay edge (`docs/algorithms.md` §2.8; the
//! original leaf rule is unverified, so the same rule as SIGDT2 is used). Inflating and
//! sculpting are exactly those of SIG-CONNECT2D.
//!
//! # Guarantee
//! [OM13]: reconstruction for ε < 0.5 with non-uniformity u < 1.609. BC₀ is connected, so
//! the result is always one polygon (0 % on open and multiple curves in [MOW22] Table 2).
//!
//! # Complexity
//! O(n log n).
//!
//! [OM13]: https://doi.org/10.1111/cgf.12227
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::connect::inflate_and_sculpt;
use crate::delaunay::Triangulation;
use crate::graph::EdgeMask;
use crate::proximity::{emst::emst_mask, leaf_elimination::eliminate_leaves};
use crate::result::{degenerate_result, Reconstruction};

/// CONNECT2D on a triangulation.
pub(crate) fn connect2d_on(dt: &Triangulation) -> Reconstruction {
    if let Some(result) = degenerate_result(dt) {
        return result;
    }
    let (graph, leaf_edges_added) = bc0(dt);
    inflate_and_sculpt(dt, &graph, leaf_edges_added)
}

/// BC₀ on a proper triangulation, and the number of leaf edges added to the EMST.
pub fn bc0(dt: &Triangulation) -> (EdgeMask, usize) {
    let mut graph = emst_mask(dt);
    let leaf_edges_added = eliminate_leaves(dt, &mut graph);
    (graph, leaf_edges_added)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Point;
    use crate::internals::check_reconstruction;

    fn connect2d(pts: &[Point]) -> Result<Reconstruction, crate::error::Error> {
        Ok(connect2d_on(&Triangulation::new(pts)?))
    }

    #[test]
    fn regular_polygon_is_reconstructed() {
        let pts: Vec<Point> = (0..16)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 16.0;
                [a.cos(), a.sin()]
            })
            .collect();
        let rec = connect2d(&pts).unwrap();
        check_reconstruction(&pts, &rec).unwrap();
        assert_eq!(rec.edges.len(), 16);
        assert!(rec.edges.iter().all(|&[i, j]| j - i == 1 || (i, j) == (0, 15)));
    }

    #[test]
    fn separate_curves_are_joined_into_one_polygon() {
        // BC₀ is connected, unlike SIGDT: two far circles become one polygon.
        let mut pts = Vec::new();
        for (cx, k) in [(0.0, 10), (5.0, 8)] {
            pts.extend((0..k).map(|i| {
                let a = i as f64 * std::f64::consts::TAU / k as f64;
                [cx + a.cos(), a.sin()]
            }));
        }
        let rec = connect2d(&pts).unwrap();
        check_reconstruction(&pts, &rec).unwrap();
        assert_eq!(rec.loops.len(), 1);
    }
}
