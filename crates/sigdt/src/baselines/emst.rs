//! EMST: the Euclidean minimum spanning tree as a reconstruction, the trivial baseline for
//! open curves (a tree never closes a loop).
//!
//! # Complexity
//! O(n log n) given the triangulation (Kruskal over its edges; the EMST is a subgraph of the
//! Delaunay triangulation).
use crate::delaunay::Triangulation;
use crate::proximity::emst::emst_mask;

/// The EMST edges of a proper triangulation, as vertex pairs.
pub(crate) fn emst(dt: &Triangulation) -> Vec<[u32; 2]> {
    let tree = emst_mask(dt);
    dt.edge_halfedges().filter(|&h| tree.contains(h)).map(|h| [dt.origin(h), dt.dest(h)]).collect()
}
