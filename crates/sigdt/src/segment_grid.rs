//! Pairs of segments that may meet, found through a uniform grid: each segment goes into the
//! cells its bounding box covers, and every two segments that share a cell are visited, cells
//! in order. One search for the output checker ([`first_crossing`]), FIT-CONNECT's crossing
//! test and SIG-AUTO's untangling of coarse loops.
//!
//! # Complexity
//! O(k + Σ c²) for `k` segments and `c` segments a cell: O(k) on curve-like edge sets whose
//! cells are about as large as their edges, O(k²) when every segment shares one cell.
use crate::geometry::{segments_cross, Edge, Point};
use std::collections::HashMap;

/// Calls `visit(e, f)` for every two of the `count` segments (`ends(k)`: the ends of segment
/// `k`) that share a cell (`cell(p)`: the cell of point `p`), cells in increasing order and
/// `e` put in the cell before `f`; stops at the first `true` and returns whether there was
/// one. A pair sharing several cells is visited once for each.
pub(crate) fn visit_pairs_sharing_cells(
    count: usize,
    ends: impl Fn(usize) -> (Point, Point),
    cell: impl Fn(Point) -> (i64, i64),
    mut visit: impl FnMut(usize, usize) -> bool,
) -> bool {
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    for k in 0..count {
        let (p, q) = ends(k);
        let (cp, cq) = (cell(p), cell(q));
        for x in cp.0.min(cq.0)..=cp.0.max(cq.0) {
            for y in cp.1.min(cq.1)..=cp.1.max(cq.1) {
                grid.entry((x, y)).or_default().push(k);
            }
        }
    }
    let mut keys: Vec<_> = grid.keys().copied().collect();
    keys.sort_unstable();
    for key in keys {
        let bucket = &grid[&key];
        for (s, &e) in bucket.iter().enumerate() {
            for &f in &bucket[s + 1..] {
                if visit(e, f) {
                    return true;
                }
            }
        }
    }
    false
}

/// The first pair of `edges` (indices into `points`) that cross at a point interior to both,
/// if any, through a grid of about `√k × √k` cells over the edges' bounding box.
pub fn first_crossing(points: &[Point], edges: &[Edge]) -> Option<(Edge, Edge)> {
    if edges.len() < 2 {
        return None;
    }
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in edges.iter().flatten().map(|&i| points[i]) {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    let cells = (edges.len() as f64).sqrt().ceil().max(1.0);
    let size = [0, 1].map(|a| ((hi[a] - lo[a]) / cells).max(f64::MIN_POSITIVE));
    let axis = |p: Point, a: usize| (((p[a] - lo[a]) / size[a]) as i64).clamp(0, cells as i64 - 1);
    let ends = |k: usize| (points[edges[k][0]], points[edges[k][1]]);
    let mut found = None;
    visit_pairs_sharing_cells(
        edges.len(),
        ends,
        |p| (axis(p, 0), axis(p, 1)),
        |e, f| {
            let ([a, b], [c, d]) = (edges[e], edges[f]);
            if segments_cross(points[a], points[b], points[c], points[d]) {
                found = Some((edges[e].min(edges[f]), edges[e].max(edges[f])));
            }
            found.is_some()
        },
    );
    found
}
