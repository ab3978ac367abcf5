//! The split of an edge set into maximal chains: the one decomposition that results,
//! metrics and pictures share (`docs/algorithms.md` §4.6 step 1).
//!
//! A chain is a path between two *break* vertices (every vertex whose degree is not 2, plus
//! any the caller marks) whose interior vertices are unmarked and of degree 2, or a cycle of
//! unmarked degree-2 vertices. Every edge lies in exactly one chain.
//!
//! Steps: adjacency lists sorted by neighbour; walk from every break vertex along each unused
//! edge until the next break vertex; then walk the remaining edges, which form cycles, from
//! their lowest vertex. Deterministic for a given edge set.
//!
//! # Complexity
//! O(n + m log m) for `n` points and `m` edges.
use crate::geometry::Edge;

/// One maximal chain, as the sequence of its vertices.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Chain {
    /// Vertices in walking order. A path lists both ends (equal when it returns to its
    /// start vertex); a cycle lists each vertex once, its closing edge implied.
    pub vertices: Vec<usize>,
    /// True for a cycle without break vertex.
    pub cycle: bool,
}

/// The chains of `edges` over points `0..n` (each edge `[i, j]` with `i < j < n`, no
/// repeats); `mark[v]` (if given) makes `v` a break vertex even when it has degree 2.
/// Paths come first, from the break vertices in index order, then the cycles.
pub fn chains(n: usize, edges: &[Edge], mark: Option<&[bool]>) -> Vec<Chain> {
    let mut start = vec![0usize; n + 1];
    for &[i, j] in edges {
        start[i + 1] += 1;
        start[j + 1] += 1;
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    // Adjacency as (neighbour, edge index), sorted per vertex.
    let mut adj = vec![(0usize, 0usize); 2 * edges.len()];
    let mut fill = start.clone();
    for (k, &[i, j]) in edges.iter().enumerate() {
        adj[fill[i]] = (j, k);
        fill[i] += 1;
        adj[fill[j]] = (i, k);
        fill[j] += 1;
    }
    for v in 0..n {
        adj[start[v]..start[v + 1]].sort_unstable();
    }
    let degree = |v: usize| start[v + 1] - start[v];
    let is_break = |v: usize| degree(v) != 2 || mark.is_some_and(|m| m.get(v) == Some(&true));
    let mut used = vec![false; edges.len()];
    let mut out = Vec::new();
    let walk = |first: usize, mut edge: usize, mut v: usize, used: &mut Vec<bool>| {
        let mut vertices = vec![first];
        loop {
            used[edge] = true;
            vertices.push(v);
            if v == first || is_break(v) {
                return vertices;
            }
            match adj[start[v]..start[v + 1]].iter().find(|&&(_, k)| !used[k]) {
                Some(&(w, k)) => (v, edge) = (w, k),
                None => return vertices,
            }
        }
    };
    for v in (0..n).filter(|&v| is_break(v)) {
        for &(w, k) in &adj[start[v]..start[v + 1]] {
            if !used[k] {
                out.push(Chain { vertices: walk(v, k, w, &mut used), cycle: false });
            }
        }
    }
    for (k, &[i, j]) in edges.iter().enumerate() {
        if !used[k] {
            let mut vertices = walk(i, k, j, &mut used);
            vertices.pop(); // back at `i`
            out.push(Chain { vertices, cycle: true });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycles_paths_and_junctions() {
        // A square 0-1-2-3, a path 4-5-6, and a triangle 7-8-9 hanging off 6 via 6-7.
        let edges =
            [[0, 1], [1, 2], [2, 3], [0, 3], [4, 5], [5, 6], [6, 7], [7, 8], [8, 9], [7, 9]];
        let c = chains(10, &edges, None);
        assert_eq!(c.len(), 3);
        assert_eq!(c[0], Chain { vertices: vec![4, 5, 6, 7], cycle: false });
        assert_eq!(c[1], Chain { vertices: vec![7, 8, 9, 7], cycle: false });
        assert_eq!(c[2], Chain { vertices: vec![0, 1, 2, 3], cycle: true });
        let c = chains(4, &edges[..4], None);
        assert_eq!(c, vec![Chain { vertices: vec![0, 1, 2, 3], cycle: true }]);
        let marked = chains(4, &edges[..4], Some(&[false, true, false, true]));
        assert_eq!(marked.len(), 2);
        assert_eq!(marked[0].vertices, vec![1, 0, 3]);
        assert!(chains(3, &[], None).is_empty());
    }
}
