//! The engine shared by CONNECT2D and SIG-CONNECT2D: from an initial graph, find its
//! boundary, inflate it to a manifold, sculpt it through every point and read the loops off
//! ([OM13]'s operations as [MOW22] §4.2 uses them; `docs/algorithms.md` §2.2–2.7).
//! SIG-CONNECT2D starts it from SIGDT or SIGDT2, CONNECT2D from BC₀, SIG-AUTO from each
//! component of SIGDT2.
//!
//! [OM13]: https://doi.org/10.1111/cgf.12227
//! [MOW22]: https://doi.org/10.1111/cgf.14654

pub(crate) mod boundary;
pub(crate) mod extract;
pub(crate) mod inflate;
mod pocket;
mod queue;
pub(crate) mod sculpt;
mod star_counts;
pub(crate) mod trace;

use crate::delaunay::Triangulation;
use crate::geometry::Edge;
use crate::graph::EdgeMask;
use crate::result::{inside_left_out, Reconstruction, Stats, Status, Vertices};
use boundary::Boundary;
use extract::{loop_edges, vertex_loops, VertexLoops};
use inflate::inflate;
use sculpt::sculpt;
use trace::Trace;

/// Reconstruction of a proper triangulation from initial graph `graph`, to which
/// `leaf_edges_added` leaf edges were added.
pub(crate) fn inflate_and_sculpt(
    dt: &Triangulation,
    graph: &EdgeMask,
    leaf_edges_added: usize,
) -> Reconstruction {
    inflate_and_sculpt_traced(dt, graph, leaf_edges_added, false).0
}

/// [`inflate_and_sculpt`], also returning every label change when `trace` is set
/// ([`trace`]); the reconstruction is the same either way.
pub(crate) fn inflate_and_sculpt_traced(
    dt: &Triangulation,
    graph: &EdgeMask,
    leaf_edges_added: usize,
    trace: bool,
) -> (Reconstruction, Option<Trace>) {
    let (outline, trace) = outline(dt, graph, leaf_edges_added, trace);
    let rec = outline.into_reconstruction(dt.input_indices(), dt.duplicates().to_vec());
    (rec, trace)
}

/// What inflating and sculpting leave, in vertices: the loops, the vertices still inside and
/// the counts. The boundary is freed once it is read, so the result (24 bytes a point as
/// input indices) is built without it, and without the triangulation when its owner frees
/// it first ([`reconstruct`](crate::reconstruct())).
pub(crate) struct Outline {
    loops: VertexLoops,
    inside: Vec<u32>,
    stats: Stats,
}

/// Inflates and sculpts the boundary of `graph` on a proper triangulation (see
/// [`inflate_and_sculpt_traced`]) and reads the outline off it.
pub(crate) fn outline(
    dt: &Triangulation,
    graph: &EdgeMask,
    leaf_edges_added: usize,
    trace: bool,
) -> (Outline, Option<Trace>) {
    let mut stats = Stats {
        points: dt.input_len(),
        distinct_points: dt.num_vertices(),
        graph_edges: graph.len(),
        leaf_edges_added,
        ..Stats::default()
    };
    let mut bd = Boundary::from_graph(dt, graph);
    let mut trace = trace.then(|| bd.start_trace(graph));
    inflate(&mut bd, graph, &mut stats);
    let inflated_at = bd.trace.as_ref().map_or(0, Vec::len);
    sculpt(&mut bd, &mut stats);
    if let Some(trace) = &mut trace {
        trace.steps = bd.trace.take().unwrap_or_default();
        trace.inflated_at = inflated_at;
    }
    let inside_vertices = bd.interior_vertices();
    let (inside, edges) = bd.into_labels_and_edges();
    let loops = vertex_loops(dt, &inside, &edges);
    (Outline { loops, inside: inside_vertices, stats }, trace.map(Trace::in_canonical_order))
}

impl Outline {
    /// The sampling check of the loops ([`check_curves`](crate::sampling_check::check_curves) and
    /// [`noisy_area`](crate::sampling_check::noisy_area)), as [`diagnose`](crate::sampling_check::diagnose)
    /// gives it for the same loops.
    pub(crate) fn check(&self, dt: &Triangulation) -> Vec<crate::result::Finding> {
        let mut found =
            crate::sampling_check::check_curves(dt, self.loops.iter().map(|l| (l, true)));
        let rings: Vec<&[u32]> = self.loops.iter().collect();
        found.extend(crate::sampling_check::noisy_area(dt, &rings));
        found
    }

    /// The result: the loops and the points left inside as input indices (`input_index`
    /// of every vertex), the edges of the loops, and the input's `duplicates`.
    pub(crate) fn into_reconstruction(
        self,
        input_index: &[u32],
        duplicates: Vec<Edge>,
    ) -> Reconstruction {
        let loops = self.loops.input_loops(input_index);
        drop(self.loops);
        let mut inside: Vec<usize> =
            self.inside.iter().map(|&v| input_index[v as usize] as usize).collect();
        inside.sort_unstable();
        let left_out = inside_left_out(&inside);
        let status = if !inside.is_empty() {
            Status::SculptingStuck { left_out: inside }
        } else if loops.len() == 1 {
            Status::Polygon
        } else {
            Status::Polygons
        };
        Reconstruction {
            edges: loop_edges(&loops, self.stats.points),
            loops,
            paths: Vec::new(),
            status,
            duplicates,
            left_out,
            vertices: Vertices::Input,
            stats: self.stats,
            diagnosis: Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Edge;
    use trace::Phase;

    fn circle(k: usize) -> Vec<crate::geometry::Point> {
        (0..k)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / k as f64;
                [a.cos(), a.sin()]
            })
            .collect()
    }

    /// The mask of a path through the first `k` circle points.
    fn path(dt: &Triangulation, k: usize) -> EdgeMask {
        let mut g = EdgeMask::new(dt);
        for h in dt.edge_halfedges() {
            let (a, b) = (dt.input_index(dt.origin(h)), dt.input_index(dt.dest(h)));
            if a.abs_diff(b) == 1 && a.max(b) < k {
                g.set(dt, h, true);
            }
        }
        g
    }

    #[test]
    fn replay_matches_the_boundary_before_after_inflating_and_at_the_end() {
        let pts = circle(9);
        let dt = Triangulation::new(&pts).unwrap();
        let g = path(&dt, 9);
        let mut bd = Boundary::from_graph(&dt, &g);
        let mut trace = bd.start_trace(&g);
        assert_eq!(trace.dangling, (0..8).map(|i| [i, i + 1]).collect::<Vec<_>>());
        assert_eq!(trace.graph, trace.dangling);
        assert_eq!(trace.boundary_at(0), bd.edges.edges(&dt));
        let mut stats = Stats::default();
        inflate(&mut bd, &g, &mut stats);
        trace.inflated_at = bd.trace.as_ref().unwrap().len();
        trace.steps = bd.trace.clone().unwrap();
        assert_eq!(trace.boundary_at(trace.inflated_at), bd.edges.edges(&dt));
        sculpt(&mut bd, &mut stats);
        trace.steps = bd.trace.take().unwrap();
        assert_eq!(trace.boundary_at(usize::MAX), bd.edges.edges(&dt));
        assert_eq!(trace.inside_at(trace.steps.len()), bd.inside);
        let pockets = trace.steps.iter().filter(|s| s.phase == Phase::Pocket).count();
        assert!(pockets >= 1, "the path closes pockets: {trace:?}");
        assert_eq!(
            trace.steps.len(),
            stats.inflated_triangles + pockets + stats.sculpted_triangles,
        );
    }

    #[test]
    fn triangles_are_counter_clockwise_input_indices() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
        let dt = Triangulation::new(&pts).unwrap();
        let g = EdgeMask::new(&dt);
        let trace = Boundary::from_graph(&dt, &g).start_trace(&g);
        assert_eq!(trace.triangles.len(), 2);
        for &[a, b, c] in &trace.triangles {
            assert!(a < 4 && b < 4 && c < 4, "duplicates by their representative");
            assert!(crate::geometry::orient2d(pts[a], pts[b], pts[c]) > 0.0);
        }
        assert_eq!(trace.initial_inside, vec![false, false]);
        assert!(trace.dangling.is_empty() && trace.graph.is_empty());
        assert_eq!(trace.boundary_at(0), Vec::<Edge>::new());
    }
}
