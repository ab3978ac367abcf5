//! The CONNECT2D machinery from a given initial graph: boundary, inflating, sculpting,
//! extraction (ALGORITHMS.md §2.2–2.7). SIG-CONNECT2D starts it from SIGDT; CONNECT2D from
//! its own graph BC₀.
use super::boundary::Boundary;
use super::extract::{loop_edges, loops};
use super::inflate::inflate;
use super::result::{Reconstruction, Stats, Status};
use super::sculpt::sculpt;
use super::trace::Trace;
use crate::delaunay::Triangulation;
use crate::graph::EdgeMask;

/// Reconstruction of a proper triangulation from initial graph `graph`, to which
/// `leaf_edges_added` leaf edges were added.
pub fn inflate_and_sculpt(
    dt: &Triangulation,
    graph: &EdgeMask,
    leaf_edges_added: usize,
) -> Reconstruction {
    inflate_and_sculpt_traced(dt, graph, leaf_edges_added, false).0
}

/// [`inflate_and_sculpt`], also returning every label change when `trace` is set
/// ([`crate::reconstruct::trace`]); the reconstruction is the same either way.
pub fn inflate_and_sculpt_traced(
    dt: &Triangulation,
    graph: &EdgeMask,
    leaf_edges_added: usize,
    trace: bool,
) -> (Reconstruction, Option<Trace>) {
    let mut stats = Stats {
        points: dt.input_len(),
        distinct_points: dt.num_vertices(),
        graph_edges: graph.len(),
        leaf_edges_added,
        ..Stats::default()
    };
    let mut bd = Boundary::from_graph(dt, graph);
    let mut trace = trace.then(|| Trace::start(&bd, graph));
    if trace.is_some() {
        bd.trace = Some(Vec::new());
    }
    inflate(&mut bd, graph, &mut stats);
    let inflated_at = bd.trace.as_ref().map_or(0, Vec::len);
    sculpt(&mut bd, &mut stats);
    if let Some(trace) = &mut trace {
        trace.steps = bd.trace.take().unwrap_or_default();
        trace.inflated_at = inflated_at;
    }
    let loops = loops(&bd);
    let status = if bd.interior > 0 {
        let mut left_out: Vec<usize> =
            bd.interior_vertices().into_iter().map(|v| dt.input_index(v)).collect();
        left_out.sort_unstable();
        Status::SculptingStuck { left_out }
    } else if loops.len() == 1 {
        Status::Polygon
    } else {
        Status::Polygons
    };
    let rec = Reconstruction {
        edges: loop_edges(&loops, dt.input_len()),
        loops,
        paths: Vec::new(),
        status,
        duplicates: dt.duplicates().to_vec(),
        stats,
    };
    (rec, trace)
}
