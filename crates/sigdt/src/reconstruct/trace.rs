//! An optional record of inflating and sculpting, step by step, for figures and debugging.
//!
//! A [`Trace`] holds the triangulation (as input indices), the initial graph `G`, the labels
//! right after [`Boundary::from_graph`] and every later label change in order: inflating
//! turns exterior triangles interior one at a time ([`Phase::Inflate`]) and fills enclosed
//! pockets several at once ([`Phase::Pocket`]); sculpting turns interior triangles exterior
//! one at a time ([`Phase::Sculpt`]). [`Trace::boundary_at`] replays the labels to give the
//! boundary `B` after any number of steps.
//!
//! Recording costs one branch per changed label when it is off ([`Boundary::trace`] is
//! `None`), and one [`Step`] (24 bytes) per changed label when it is on.
//!
//! # Complexity
//! Building the trace: O(n) beyond the run. [`Trace::boundary_at`]: O(n log n).
use super::boundary::Boundary;
use crate::graph::EdgeMask;
use crate::Edge;

/// Which part of the run changed a label.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// Inflating took one exterior triangle ([`crate::reconstruct::inflate`]).
    Inflate,
    /// Inflating closed a cycle and filled the enclosed pocket
    /// ([`crate::reconstruct::pocket`]); a pocket is several steps in a row.
    Pocket,
    /// Sculpting took one interior triangle ([`crate::reconstruct::sculpt`]).
    Sculpt,
}

impl Phase {
    /// Every phase, in the order of its numeric code (`Phase::ALL[code]`).
    pub const ALL: [Phase; 3] = [Phase::Inflate, Phase::Pocket, Phase::Sculpt];

    /// The lower-case name: `inflate`, `pocket` or `sculpt`.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Inflate => "inflate",
            Phase::Pocket => "pocket",
            Phase::Sculpt => "sculpt",
        }
    }
}

/// One label change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Step {
    /// The triangle, an index into [`Trace::triangles`].
    pub triangle: usize,
    /// Its new label: `true` for interior.
    pub inside: bool,
    /// What changed it.
    pub phase: Phase,
}

/// Every label change of one inflate-and-sculpt run. See the module docs.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Trace {
    /// Every Delaunay triangle as input indices (duplicates by their representative),
    /// counter-clockwise.
    pub triangles: Vec<[usize; 3]>,
    /// The initial graph `G` (SIGDT, SIGDT2 or BC₀), sorted input-index edges `[i, j]`,
    /// `i < j`.
    pub graph: Vec<Edge>,
    /// The labels right after [`Boundary::from_graph`]: `true` for interior.
    pub initial_inside: Vec<bool>,
    /// Edges of the initial boundary with exterior on both sides (the outside of the hull
    /// counts as exterior), sorted.
    pub dangling: Vec<Edge>,
    /// Every label change, in order.
    pub steps: Vec<Step>,
    /// Number of steps when inflating ended and sculpting started.
    pub inflated_at: usize,
}

impl Trace {
    /// The trace's fixed part, from the boundary `bd` of graph `g` right after
    /// [`Boundary::from_graph`]; no steps yet.
    pub fn start(bd: &Boundary<'_>, g: &EdgeMask) -> Trace {
        let dt = bd.dt;
        let triangles = (0..dt.num_triangles() as u32)
            .map(|t| [0, 1, 2].map(|k| dt.input_index(dt.origin(3 * t + k))))
            .collect();
        let dangling = dt.to_input_edges(
            dt.edge_halfedges()
                .filter(|&h| bd.edges.contains(h) && !bd.left_is_in(h) && !bd.right_is_in(h))
                .map(|h| [dt.origin(h), dt.dest(h)]),
        );
        Trace {
            triangles,
            graph: g.edges(dt),
            initial_inside: bd.inside.clone(),
            dangling,
            steps: Vec::new(),
            inflated_at: 0,
        }
    }

    /// The labels after the first `step` steps (all of them if `step` is larger).
    pub fn inside_at(&self, step: usize) -> Vec<bool> {
        let mut inside = self.initial_inside.clone();
        for s in &self.steps[..step.min(self.steps.len())] {
            inside[s.triangle] = s.inside;
        }
        inside
    }

    /// The boundary after the first `step` steps (all of them if `step` is larger), sorted:
    /// the edges whose two sides differ (the outside of the hull counts as exterior), plus
    /// the initially dangling edges whose sides have stayed exterior all along. (A dangling
    /// edge leaves the boundary for good once a side turns interior: it then lies between
    /// two labels until both sides are interior, and sculpting never adds dangling edges.)
    pub fn boundary_at(&self, step: usize) -> Vec<Edge> {
        let mut inside = self.initial_inside.clone();
        let mut ever_inside = inside.clone();
        for s in &self.steps[..step.min(self.steps.len())] {
            inside[s.triangle] = s.inside;
            ever_inside[s.triangle] |= s.inside;
        }
        // Every side of every edge: (edge, triangle), grouped by edge.
        let mut sides: Vec<(Edge, usize)> = Vec::with_capacity(3 * self.triangles.len());
        for (t, tri) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (i, j) = (tri[k], tri[(k + 1) % 3]);
                sides.push(([i.min(j), i.max(j)], t));
            }
        }
        sides.sort_unstable();
        let mut edges = Vec::new();
        let mut k = 0;
        while k < sides.len() {
            let (e, left) = sides[k];
            // A hull edge has one side; its outside is exterior.
            let right = sides.get(k + 1).filter(|s| s.0 == e).map(|s| s.1);
            let right_inside = right.is_some_and(|t| inside[t]);
            let dangling = !ever_inside[left]
                && !right.is_some_and(|t| ever_inside[t])
                && self.dangling.binary_search(&e).is_ok();
            if inside[left] != right_inside || dangling {
                edges.push(e);
            }
            k += if right.is_some() { 2 } else { 1 };
        }
        edges
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::Triangulation;
    use crate::reconstruct::{inflate::inflate, result::Stats, sculpt::sculpt};

    fn circle(k: usize) -> Vec<crate::Point> {
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
        let mut trace = Trace::start(&bd, &g);
        bd.trace = Some(Vec::new());
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
        let trace = Trace::start(&Boundary::from_graph(&dt, &g), &g);
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
