//! Euclidean minimum spanning tree by Kruskal's algorithm over the Delaunay edges.
//!
//! The EMST is a subgraph of the Delaunay triangulation (Shamos and Hoey 1975), so sorting
//! the O(n) Delaunay edges by `(length, lower input index, higher input index)` and joining
//! components with union-find gives it deterministically.
//!
//! # Complexity
//! O(n log n).
use crate::delaunay::{Shape, Triangulation};
use crate::geometry::{squared_distance, Edge};
use crate::graph::{EdgeMask, UnionFind};

/// The EMST of a proper triangulation as an edge mask.
pub fn emst_mask(dt: &Triangulation) -> EdgeMask {
    minimum_spanning_forest(dt, |_| true)
}

/// The minimum spanning forest of the Delaunay edges for which `keep(h)` holds (`h` is the
/// representative half-edge of [`Triangulation::edge_halfedges`]): one minimum spanning
/// tree per connected component of that subgraph. Ties are broken by the edges' input
/// indices, so the forest does not depend on the vertex numbering.
pub fn minimum_spanning_forest(dt: &Triangulation, keep: impl Fn(u32) -> bool) -> EdgeMask {
    let sorted = sorted_by_length(dt, dt.edge_halfedges().filter(|&h| keep(h)));
    let mut mask = EdgeMask::new(dt);
    for h in kruskal(dt, sorted) {
        mask.set(dt, h, true);
    }
    mask
}

/// The half-edges `edges` sorted by `(length, lower input index, higher input index)`, the
/// order in which [`kruskal`] must see them.
pub(crate) fn sorted_by_length(dt: &Triangulation, edges: impl Iterator<Item = u32>) -> Vec<u32> {
    // One 128-bit key a half-edge sorts fastest; equal lengths, rare but for lattices, are
    // then put in input-index order run by run.
    // Both sorts on the pool when it has several threads: the keys are distinct (each holds
    // its half-edge), so the order is the same on every thread count.
    let mut keyed: Vec<u128> =
        edges.map(|h| u128::from(length_key(dt, h)) << 64 | u128::from(h)).collect();
    crate::parallel::sort_unstable(&mut keyed);
    let pair = |k: &u128| {
        let h = *k as u32;
        let (a, b) = (dt.input_index(dt.origin(h)), dt.input_index(dt.dest(h)));
        (a.min(b), a.max(b))
    };
    let same_length = |a: &u128, b: &u128| a >> 64 == b >> 64;
    crate::parallel::for_each_run(&mut keyed, same_length, |run| {
        if run.len() > 1 {
            run.sort_unstable_by_key(pair);
        }
    });
    keyed.into_iter().map(|k| k as u32).collect()
}

/// A key that sorts edges by length: the bits of the squared length (non-negative, so they
/// sort like the numbers; squaring is monotone and needs no square root).
fn length_key(dt: &Triangulation, h: u32) -> u64 {
    squared_distance(dt.point(dt.origin(h)), dt.point(dt.dest(h))).to_bits()
}

/// Kruskal's algorithm over half-edges given in [`sorted_by_length`] order: the forest's
/// half-edges, in that order.
pub(crate) fn kruskal(dt: &Triangulation, sorted: impl IntoIterator<Item = u32>) -> Vec<u32> {
    kruskal_with_sets(dt, sorted).0
}

/// [`kruskal`], and the disjoint sets it ends with: the forest's trees.
pub(crate) fn kruskal_with_sets(
    dt: &Triangulation,
    sorted: impl IntoIterator<Item = u32>,
) -> (Vec<u32>, UnionFind) {
    let mut uf = UnionFind::new(dt.num_vertices());
    let forest = sorted.into_iter().filter(|&h| uf.union(dt.origin(h), dt.dest(h))).collect();
    (forest, uf)
}

/// Merges two lists in [`sorted_by_length`] order into one.
pub(crate) fn merge_sorted(dt: &Triangulation, a: &[u32], b: &[u32]) -> Vec<u32> {
    let key = |h: u32| {
        let (x, y) = (dt.input_index(dt.origin(h)), dt.input_index(dt.dest(h)));
        (length_key(dt, h), x.min(y), x.max(y))
    };
    let (mut i, mut j) = (0, 0);
    let mut out = Vec::with_capacity(a.len() + b.len());
    while i < a.len() || j < b.len() {
        if j == b.len() || (i < a.len() && key(a[i]) <= key(b[j])) {
            out.push(a[i]);
            i += 1;
        } else {
            out.push(b[j]);
            j += 1;
        }
    }
    out
}

/// The EMST as sorted input-index pairs (the path along the line for collinear input).
pub(crate) fn emst(dt: &Triangulation) -> Vec<Edge> {
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
