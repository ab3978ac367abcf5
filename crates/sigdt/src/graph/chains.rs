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
//! O(n + m log m) for `n` points and `m` edges; 4 (n + 1) + 16 m bytes besides the chains
//! (vertices and edge numbers as `u32`: a million-point result is read in about 40 MB).
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
    // Vertices and edge numbers fit in `u32`: a triangulation numbers its vertices so.
    let small = |x: usize| u32::try_from(x).expect("fewer than 2^32 vertices and edges");
    small(n + 1);
    small(2 * edges.len());
    if mark.is_none() {
        let pairs = edges.iter().map(|&[i, j]| [i as u32, j as u32]);
        if let Some(slots) = two_slots(n, pairs) {
            return chains_of_slots(&slots);
        }
    }
    chains_by_adjacency(n, edges, mark)
}

/// [`chains`] through sorted adjacency lists, for any graph.
fn chains_by_adjacency(n: usize, edges: &[Edge], mark: Option<&[bool]>) -> Vec<Chain> {
    // `start[v]` becomes the end of `v`'s adjacency run, then (filled backwards) its start.
    let mut start = vec![0u32; n + 1];
    for &[i, j] in edges {
        start[i] += 1;
        start[j] += 1;
    }
    for v in 1..=n {
        start[v] += start[v - 1];
    }
    // Adjacency as (neighbour, edge index), sorted per vertex.
    let mut adj = vec![(0u32, 0u32); 2 * edges.len()];
    for (k, &[i, j]) in edges.iter().enumerate().rev() {
        start[i] -= 1;
        adj[start[i] as usize] = (j as u32, k as u32);
        start[j] -= 1;
        adj[start[j] as usize] = (i as u32, k as u32);
    }
    start[n] = adj.len() as u32;
    let run = |v: usize| start[v] as usize..start[v + 1] as usize;
    for v in 0..n {
        adj[run(v)].sort_unstable();
    }
    let degree = |v: usize| run(v).len();
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
            match adj[run(v)].iter().find(|&&(_, k)| !used[k as usize]) {
                Some(&(w, k)) => (v, edge) = (w as usize, k as usize),
                None => return vertices,
            }
        }
    };
    for v in (0..n).filter(|&v| is_break(v)) {
        for &(w, k) in &adj[run(v)] {
            if !used[k as usize] {
                let vertices = walk(v, k as usize, w as usize, &mut used);
                out.push(Chain { vertices, cycle: false });
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

/// No neighbour in a slot of [`two_slots`].
const NONE: u32 = u32::MAX;

/// Each vertex's neighbours in two slots, the smaller first, of the distinct edges `pairs`
/// over vertices `0..n`; `None` when some vertex has three or more. Paths and cycles only
/// (most results) need 8 bytes a vertex, not the adjacency lists.
pub(crate) fn two_slots(
    n: usize,
    pairs: impl IntoIterator<Item = [u32; 2]>,
) -> Option<Vec<[u32; 2]>> {
    let mut slots = vec![[NONE; 2]; n];
    for [i, j] in pairs {
        for (x, y) in [(i, j), (j, i)] {
            let s = &mut slots[x as usize];
            match (s[0], s[1]) {
                (NONE, _) => s[0] = y,
                (_, NONE) => s[1] = y,
                _ => return None,
            }
        }
    }
    for s in &mut slots {
        if s[1] < s[0] {
            s.swap(0, 1);
        }
    }
    Some(slots)
}

/// [`chains`] of a graph whose every vertex has at most two neighbours (`slots`, from
/// [`two_slots`]), in the same order: paths from their lower end in index order, then
/// cycles from their lowest vertex towards its smaller neighbour (the first unused edge in
/// sorted order). Each chain is walked twice, to allocate its vertices once at their size.
pub(crate) fn chains_of_slots(slots: &[[u32; 2]]) -> Vec<Chain> {
    let degree = |v: usize| slots[v].iter().filter(|&&w| w != NONE).count();
    let mut visited = vec![false; slots.len()];
    // Calls `visit` on the vertices from `first` until an end, or back at `first`.
    let along = |first: usize, visit: &mut dyn FnMut(usize)| {
        let (mut previous, mut v) = (first, slots[first][0] as usize);
        visit(first);
        loop {
            visit(v);
            let [a, b] = slots[v];
            let next = if a as usize == previous { b } else { a };
            if v == first || next == NONE {
                return;
            }
            (previous, v) = (v, next as usize);
        }
    };
    let walk = |first: usize, visited: &mut Vec<bool>| {
        let mut len = 0;
        along(first, &mut |_| len += 1);
        let mut vertices = Vec::with_capacity(len);
        along(first, &mut |v| {
            vertices.push(v);
            visited[v] = true;
        });
        vertices
    };
    let mut out = Vec::new();
    for v in 0..slots.len() {
        if degree(v) == 1 && !visited[v] {
            out.push(Chain { vertices: walk(v, &mut visited), cycle: false });
        }
    }
    for v in 0..slots.len() {
        if degree(v) == 2 && !visited[v] {
            let mut vertices = walk(v, &mut visited);
            vertices.pop(); // back at `v`
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

    #[test]
    fn paths_and_cycles_read_by_slots_as_by_adjacency() {
        // Random paths and cycles over shuffled vertex numbers, with isolated vertices.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = |below: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % below as u64) as usize
        };
        for _ in 0..200 {
            let n = 3 + next(60);
            let mut label: Vec<usize> = (0..n).collect();
            for k in (1..n).rev() {
                label.swap(k, next(k + 1));
            }
            let mut edges = Vec::new();
            let mut v = 0;
            while v < n {
                let len = (1 + next(12)).min(n - v);
                let closed = len >= 3 && next(2) == 0;
                for k in 1..len {
                    edges.push([label[v + k - 1], label[v + k]]);
                }
                if closed {
                    edges.push([label[v + len - 1], label[v]]);
                }
                v += len;
            }
            let mut edges: Vec<Edge> =
                edges.into_iter().map(|[a, b]| [a.min(b), a.max(b)]).collect();
            edges.sort_unstable();
            let pairs = edges.iter().map(|&[i, j]| [i as u32, j as u32]);
            let slots = two_slots(n, pairs).expect("degrees of two at most");
            assert_eq!(chains_of_slots(&slots), chains_by_adjacency(n, &edges, None), "{edges:?}");
        }
        // A vertex of degree three takes the general way.
        assert!(two_slots(4, [[0, 1], [0, 2], [0, 3]]).is_none());
    }
}
