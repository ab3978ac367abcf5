//! Inflating and sculpting one component of a graph on its own, for SIG-AUTO.
//!
//! The component's points get their own Delaunay triangulation; the component's graph edges
//! are Delaunay edges there too (removing points keeps an empty circle empty). Inflating
//! and sculpting then see no other component: a curve nested inside another one is not
//! swallowed as interior points, as it is when every component shares one triangulation.
//!
//! # Complexity
//! O(k log k) for a component of `k` points.
use crate::connect::inflate_and_sculpt;
use crate::delaunay::{Shape, Triangulation};
use crate::graph::EdgeMask;
use crate::proximity::sigdt::TIE_SLACK;
use crate::result::{Reconstruction, Stats, Status};
use std::collections::HashSet;

/// What inflating and sculpting one component gave, in the vertex numbers of the whole
/// triangulation.
pub(crate) struct ClosedComponent {
    /// The loop edges.
    pub edges: Vec<[u32; 2]>,
    /// Points left inside when sculpting got stuck.
    pub left_out: Vec<u32>,
    /// The run's counts.
    pub stats: Stats,
}

/// Inflates and sculpts the component with vertices `vertices` (of `dt`) and edges `graph`
/// restricted to it, cutting a loop open at its longest link when that is more than
/// `join_ratio` times the second longest. `None` when a loop edge is not an edge of `dt`
/// (it could cross another component) or the component's points are collinear.
pub(crate) fn closed_component(
    dt: &Triangulation,
    graph: &EdgeMask,
    vertices: &[u32],
    join_ratio: f64,
) -> Option<ClosedComponent> {
    if vertices.len() == dt.num_vertices() {
        // One component holding every point: its triangulation is `dt` itself, so its loop
        // edges are edges of `dt` and need no check.
        let rec = inflate_and_sculpt(dt, graph, 0);
        let vertex_of = dt.vertex_of_inputs();
        return from_loops(dt, &rec, |i| vertex_of[i], false, join_ratio);
    }
    let points: Vec<_> = vertices.iter().map(|&v| dt.point(v)).collect();
    let sub = Triangulation::new(&points).ok()?;
    if sub.shape() != Shape::Proper {
        return None;
    }
    let wanted: HashSet<[u32; 2]> = vertices
        .iter()
        .flat_map(|&v| {
            dt.incident(v).filter(|&h| graph.contains(h)).map(move |h| {
                let w = dt.other(h, v);
                [v.min(w), v.max(w)]
            })
        })
        .collect();
    // Sub-vertex -> vertex of `dt`.
    let whole = |s: u32| vertices[sub.input_index(s)];
    let mut mask = EdgeMask::new(&sub);
    for h in sub.edge_halfedges() {
        let (a, b) = (whole(sub.origin(h)), whole(sub.dest(h)));
        if wanted.contains(&[a.min(b), a.max(b)]) {
            mask.set(&sub, h, true);
        }
    }
    let rec = inflate_and_sculpt(&sub, &mask, 0);
    from_loops(dt, &rec, |i| vertices[i], true, join_ratio)
}

/// The loops of `rec` (indices mapped to vertices of `dt` by `vertex`), each cut open at
/// [`opening_edge`]; `None` if `check_edges` is set and a link is not an edge of `dt`.
fn from_loops(
    dt: &Triangulation,
    rec: &Reconstruction,
    vertex: impl Fn(usize) -> u32,
    check_edges: bool,
    join_ratio: f64,
) -> Option<ClosedComponent> {
    let mut edges = Vec::with_capacity(rec.edges.len());
    for cycle in &rec.loops {
        let k = cycle.len();
        let link = |a: usize| [vertex(cycle[a]), vertex(cycle[(a + 1) % k])];
        let length = |a: usize| {
            let [p, q] = link(a);
            crate::geometry::distance(dt.point(p), dt.point(q))
        };
        let open_at = opening_edge(k, length, join_ratio);
        for a in (0..k).filter(|&a| Some(a) != open_at) {
            let [p, q] = link(a);
            if check_edges && !dt.has_edge(p, q) {
                return None;
            }
            edges.push([p, q]);
        }
    }
    let left_out = match &rec.status {
        Status::SculptingStuck { left_out } => left_out.iter().map(|&i| vertex(i)).collect(),
        _ => Vec::new(),
    };
    Some(ClosedComponent { edges, left_out, stats: rec.stats })
}

/// The link of a loop of `k` links to cut open: the longest, when it is more than `ratio`
/// ([`JOIN_RATIO`](super::chain_join::JOIN_RATIO) in SIG-AUTO) times the second longest
/// (the chain rule of [`chain_join`](super::chain_join) read backwards: the rest of the loop
/// is a chain that this link would not be allowed to close).
fn opening_edge(k: usize, length: impl Fn(usize) -> f64, ratio: f64) -> Option<usize> {
    let (mut first, mut second) = ((0, f64::NEG_INFINITY), f64::NEG_INFINITY);
    for a in 0..k {
        let l = length(a);
        if l > first.1 {
            second = first.1;
            first = (a, l);
        } else if l > second {
            second = l;
        }
    }
    (first.1 > ratio * second * (1.0 + TIE_SLACK)).then_some(first.0)
}
