//! Reading the result off the boundary: ordered loops and sorted edges.
//!
//! Every boundary half-edge with interior on its left is followed from vertex to vertex; on a
//! manifold boundary each boundary vertex has exactly one, so the boundary splits into
//! loops running counter-clockwise around the interior. Each loop starts at its smallest
//! input index; loops are sorted by it.
//!
//! # Complexity
//! O(n).
use super::boundary::Boundary;
use crate::delaunay::EMPTY;
use crate::geometry::Edge;

/// The loops of the boundary, as input indices.
pub fn loops(bd: &Boundary<'_>) -> Vec<Vec<usize>> {
    let dt = bd.dt;
    let mut successor = vec![EMPTY; dt.num_vertices()];
    for h in 0..dt.num_halfedges() as u32 {
        if bd.edges.contains(h) && bd.left_is_in(h) {
            debug_assert_eq!(successor[dt.origin(h) as usize], EMPTY, "non-manifold boundary");
            successor[dt.origin(h) as usize] = dt.dest(h);
        }
    }
    let mut loops = Vec::new();
    let mut seen = vec![false; dt.num_vertices()];
    for start in 0..dt.num_vertices() as u32 {
        if seen[start as usize] || successor[start as usize] == EMPTY {
            continue;
        }
        let mut cycle = Vec::new();
        let mut v = start;
        // Bounded walk: a broken boundary can never make this loop forever.
        while v != EMPTY && !seen[v as usize] {
            seen[v as usize] = true;
            cycle.push(dt.input_index(v));
            v = successor[v as usize];
        }
        let smallest = (0..cycle.len()).min_by_key(|&i| cycle[i]).unwrap_or(0);
        cycle.rotate_left(smallest);
        loops.push(cycle);
    }
    loops.sort_unstable();
    loops
}

/// The edges of closed, vertex-disjoint loops over indices `0..n`, sorted, `[i, j]` with
/// `i < j`. Each vertex is the smaller end of at most two loop edges, so a counting pass
/// replaces a comparison sort.
pub fn loop_edges(loops: &[Vec<usize>], n: usize) -> Vec<Edge> {
    let mut larger = vec![[usize::MAX; 2]; n];
    let mut count = 0;
    for l in loops {
        for k in 0..l.len() {
            let (a, b) = (l[k], l[(k + 1) % l.len()]);
            let slot = &mut larger[a.min(b)];
            let j = a.max(b);
            if a != b && !slot.contains(&j) {
                let free = usize::from(slot[0] != usize::MAX);
                debug_assert!(slot[free] == usize::MAX, "vertex on more than two loop edges");
                slot[free] = j;
                count += 1;
            }
        }
    }
    let mut edges = Vec::with_capacity(count);
    for (i, mut js) in larger.into_iter().enumerate() {
        js.sort_unstable();
        edges.extend(js.into_iter().filter(|&j| j != usize::MAX).map(|j| [i, j]));
    }
    edges
}
