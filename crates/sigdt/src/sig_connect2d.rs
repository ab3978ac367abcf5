//! SIG-CONNECT2D: SIGDT, optionally without leaves, then CONNECT2D's inflating and sculpting.
//!
//! [MOW22] Algorithm 1: build the Delaunay triangulation; keep the Delaunay edges that are
//! SIG edges (SIGDT, l. 3–10); inflate the boundary of that graph until every vertex is
//! manifold (l. 11–15); sculpt until every vertex is on the boundary (l. 16–20). With leaf
//! elimination (§4.2.3) every SIGDT leaf first gets its shortest missing Delaunay edge.
//!
//! # Guarantee
//! If the points sample a smooth closed curve with ρ < 1 and non-uniformity u < 2, SIGDT
//! contains the correct polygon (Theorem 1). The output is always a set of vertex-disjoint
//! simple closed polygons made of Delaunay edges around disjoint disks (never nested); when
//! sculpting succeeds they pass through every distinct point. Open curves, nested curves and
//! curves meeting at junctions are outside what the method can return.
//!
//! # Complexity
//! O(n log n) time, O(n) memory ([MOW22] §4.2).
//!
//! # References
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. PG 2022.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::connect::{inflate_and_sculpt, outline};
use crate::delaunay::Triangulation;
use crate::graph::EdgeMask;
use crate::proximity::{
    leaf_elimination::eliminate_leaves_with_degrees, sigdt::sigdt_with_degrees,
};
use crate::result::{degenerate_result, Reconstruction};

/// SIG-CONNECT2D on a triangulation.
pub(crate) fn sig_connect2d_on(dt: &Triangulation, leaf_elimination: bool) -> Reconstruction {
    if let Some(result) = degenerate_result(dt) {
        return result;
    }
    let (graph, leaf_edges_added) = initial_graph(dt, leaf_elimination);
    inflate_and_sculpt(dt, &graph, leaf_edges_added)
}

/// [`sig_connect2d_on`] on a triangulation it owns: the triangulation is freed, but for
/// its input indices, before the result is built, which lowers the peak memory of
/// [`reconstruct`](crate::reconstruct()) by about a fifth. The same result.
pub(crate) fn sig_connect2d_owning(dt: Triangulation, leaf_elimination: bool) -> Reconstruction {
    if let Some(result) = degenerate_result(&dt) {
        return result;
    }
    let (outline, _) = {
        let (graph, leaf_edges_added) = initial_graph(&dt, leaf_elimination);
        outline(&dt, &graph, leaf_edges_added, false)
    };
    let diagnosis = outline.check(&dt);
    let (input_index, duplicates) = dt.into_input_indices();
    let mut rec = outline.into_reconstruction(&input_index, duplicates);
    rec.diagnosis = diagnosis;
    rec
}

/// The graph inflating starts from, SIGDT or (with leaf elimination) SIGDT2, and the number
/// of leaf edges added, on a proper triangulation.
#[doc(hidden)]
pub fn initial_graph(dt: &Triangulation, leaf_elimination: bool) -> (EdgeMask, usize) {
    let (mut graph, degree) = sigdt_with_degrees(dt);
    let leaf_edges_added =
        if leaf_elimination { eliminate_leaves_with_degrees(dt, &mut graph, degree) } else { 0 };
    (graph, leaf_edges_added)
}
