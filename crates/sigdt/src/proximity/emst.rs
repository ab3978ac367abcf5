//! Euclidean minimum spanning tree by Kruskal's algorithm over the Delaunay edges.
//!
//! The EMST is a subgraph of the Delaunay triangulation (Shamos and Hoey 1975), so sorting
//! the O(n) Delaunay edges by `(length, lower input index, higher input index)` and joining
//! components with union-find gives it deterministically.
//!
//! # Complexity
//! O(n log n).
use crate::delaunay::{Shape, Triangulation};
use crate::graph::{EdgeMask, UnionFind};
use crate::Edge;

/// The EMST of a proper triangulation as an edge mask.
pub fn emst_mask(dt: &Triangulation) -> EdgeMask {
    minimum_spanning_forest(dt, |_| true)
}

/// The minimum spanning forest of the Delaunay edges for which `keep(h)` holds (`h` is the
/// representative half-edge of [`Triangulation::edge_halfedges`]): one minimum spanning
/// tree per connected component of that subgraph. Ties are broken by the edges' input
/// indices, so the forest does not depend on the vertex numbering.
pub fn minimum_spanning_forest(dt: &Triangulation, keep: impl Fn(u32) -> bool) -> EdgeMask {
    let mut edges: Vec<(f64, usize, usize, u32)> = dt
        .edge_halfedges()
        .filter(|&h| keep(h))
        .map(|h| {
            let (a, b) = (dt.input_index(dt.origin(h)), dt.input_index(dt.dest(h)));
            (dt.length(h), a.min(b), a.max(b), h)
        })
        .collect();
    edges.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then((x.1, x.2).cmp(&(y.1, y.2))));
    let mut uf = UnionFind::new(dt.num_vertices());
    let mut mask = EdgeMask::new(dt);
    for (_, _, _, h) in edges {
        if uf.union(dt.origin(h), dt.dest(h)) {
            mask.set(dt, h, true);
        }
    }
    mask
}

/// The EMST as sorted input-index pairs (the path along the line for collinear input).
pub fn emst(dt: &Triangulation) -> Vec<Edge> {
    match dt.shape() {
        Shape::Proper => emst_mask(dt).edges(dt),
        _ => dt.edges(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tree_on_a_bent_line() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.5], [3.0, 0.0], [4.0, 0.2]];
        let dt = Triangulation::new(&pts).unwrap();
        assert_eq!(emst(&dt), vec![[0, 1], [1, 2], [2, 3], [3, 4]]);
    }
}
