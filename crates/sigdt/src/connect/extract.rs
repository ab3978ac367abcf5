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
use crate::delaunay::{Triangulation, EMPTY};
use crate::geometry::Edge;
use crate::graph::EdgeMask;

/// The loops of the boundary as vertices, one after another: loop `k` is
/// `vertices[starts[k]..starts[k + 1]]`, in boundary order. Four bytes a vertex, so that the
/// boundary (and the triangulation) can be freed before the result is built.
pub(crate) struct VertexLoops {
    vertices: Vec<u32>,
    starts: Vec<usize>,
}

/// The loops of the boundary `edges` of the interior triangles (`inside[t]`), as vertices.
pub(crate) fn vertex_loops(dt: &Triangulation, inside: &[bool], edges: &EdgeMask) -> VertexLoops {
    // One sequential pass: split among the threads (`parallel::tally`) it was no faster on
    // two, and its merge made it slower on one.
    let mut successor = vec![EMPTY; dt.num_vertices()];
    for h in 0..dt.num_halfedges() as u32 {
        if edges.contains(h) && inside[(h / 3) as usize] {
            debug_assert_eq!(successor[dt.origin(h) as usize], EMPTY, "non-manifold boundary");
            successor[dt.origin(h) as usize] = dt.dest(h);
        }
    }
    // A taken vertex's successor becomes VISITED (no vertex has that number: at most
    // EMPTY / 6 vertices), so the walk is bounded even on a broken boundary.
    const VISITED: u32 = EMPTY - 1;
    let mut vertices = Vec::with_capacity(dt.num_vertices());
    let mut starts = vec![0];
    for start in 0..dt.num_vertices() as u32 {
        if matches!(successor[start as usize], EMPTY | VISITED) {
            continue;
        }
        let mut v = start;
        while v != EMPTY && successor[v as usize] != VISITED {
            vertices.push(v);
            v = std::mem::replace(&mut successor[v as usize], VISITED);
        }
        starts.push(vertices.len());
    }
    VertexLoops { vertices, starts }
}

impl VertexLoops {
    /// Each loop's vertices, in boundary order.
    pub(crate) fn iter(&self) -> impl Iterator<Item = &[u32]> + '_ {
        self.starts.windows(2).map(|w| &self.vertices[w[0]..w[1]])
    }

    /// The loops as input indices (`input_index[v]` of vertex `v`), each starting at its
    /// smallest index, sorted.
    pub(crate) fn input_loops(&self, input_index: &[u32]) -> Vec<Vec<usize>> {
        let mut loops: Vec<Vec<usize>> = self
            .starts
            .windows(2)
            .map(|w| {
                let cycle = &self.vertices[w[0]..w[1]];
                let mut cycle =
                    crate::parallel::map_slice(cycle, |&v| input_index[v as usize] as usize);
                let smallest = (0..cycle.len()).min_by_key(|&i| cycle[i]).unwrap_or(0);
                cycle.rotate_left(smallest);
                cycle
            })
            .collect();
        loops.sort_unstable();
        loops
    }
}

/// The loops of the boundary, as input indices.
pub fn loops(bd: &Boundary<'_>) -> Vec<Vec<usize>> {
    vertex_loops(bd.dt, &bd.inside, &bd.edges).input_loops(bd.dt.input_indices())
}

/// The edges of closed, vertex-disjoint loops over indices `0..n`, sorted, `[i, j]` with
/// `i < j`. Each vertex is the smaller end of at most two loop edges, so a counting pass
/// replaces a comparison sort.
///
/// # Panics
/// If an index is `n` or more, or `n` is `u32::MAX` or more (a triangulation has fewer
/// points).
pub fn loop_edges(loops: &[Vec<usize>], n: usize) -> Vec<Edge> {
    const NONE: u32 = u32::MAX;
    assert!(n < NONE as usize, "loop_edges: {n} indices do not fit in u32");
    let mut larger = vec![[NONE; 2]; n];
    let mut count = 0;
    for l in loops {
        for k in 0..l.len() {
            let (a, b) = (l[k], l[(k + 1) % l.len()]);
            let slot = &mut larger[a.min(b)];
            let j = a.max(b) as u32;
            if a != b && !slot.contains(&j) {
                let free = usize::from(slot[0] != NONE);
                debug_assert!(slot[free] == NONE, "vertex on more than two loop edges");
                slot[free] = j;
                count += 1;
            }
        }
    }
    let mut edges = Vec::with_capacity(count);
    for (i, mut js) in larger.into_iter().enumerate() {
        js.sort_unstable();
        edges.extend(js.into_iter().filter(|&j| j != NONE).map(|j| [i, j as usize]));
    }
    edges
}
