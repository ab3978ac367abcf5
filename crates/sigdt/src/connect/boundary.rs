//! The state inflating and sculpting work on: triangle labels, the boundary edge set `B`,
//! vertex classes (`docs/algorithms.md` §2.1–2.3).
//!
//! [MOW22] §4: "the boundary is the connected set of edges that includes all edges of the
//! graph G in its interior". Operationally (§2.2): the triangles reachable from outside the
//! convex hull without crossing an edge of `G` are exterior (OUT), all others interior (IN);
//! `B` is the set of edges of `G` with at least one exterior side (the outside of the hull
//! counts as exterior). Edges of `G` with both sides interior are dropped.
//!
//! Vertex classes are read off the star of the vertex, with no angular sorting: `T` = edges
//! at `v` whose sides differ, `D` = edges of `B` at `v` with both sides exterior (dangling).
//! A vertex is *interior* if it touches no exterior triangle and is not on the hull,
//! *manifold* if `T = 2` and `D = 0`, and *non-manifold* otherwise (pinched, or with
//! dangling edges: "the spaces defined by its incident edges are exterior" [MOW22]).
//!
//! The counts are kept per vertex and updated by every label or boundary change
//! ([`Boundary::set_inside`], [`Boundary::set_edge`], O(1) each), so classifying a vertex is
//! O(1) whatever its degree: walking the star instead made inflating a fan around a vertex
//! of degree `d` cost O(d) a step (a line of 10⁵ points and one point off it, without leaf
//! elimination: 43 s). [`Boundary::check_classes`] compares them with the star.
//!
//! # References
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
pub use super::star_counts::VertexClass;
use super::star_counts::{StarCounts, StarTable};
use super::trace::{Phase, Step, Trace};
use crate::delaunay::{prev, Triangulation, EMPTY};
use crate::graph::{EdgeMask, UnionFind};

/// Labels, boundary and classes of one run.
pub struct Boundary<'a> {
    /// The triangulation.
    pub dt: &'a Triangulation,
    /// `inside[t]`: triangle `t` is interior (IN).
    pub inside: Vec<bool>,
    /// The boundary edge set `B` (changed through [`Boundary::set_edge`] only).
    pub edges: EdgeMask,
    /// Class of every vertex.
    pub class: Vec<VertexClass>,
    /// What the class of every vertex is read from, kept current by [`Boundary::set_inside`]
    /// and [`Boundary::set_edge`].
    star: StarTable,
    /// Connectivity of `B` (an over-approximation; see `pocket`);
    /// built by [`Boundary::track_components`] when inflating has work to do.
    pub components: UnionFind,
    /// Number of non-manifold vertices.
    pub non_manifold: usize,
    /// Number of interior vertices.
    pub interior: usize,
    /// Every label change after [`Boundary::from_graph`], in order, when recording
    /// (`trace`); `None` (the default) records nothing.
    pub trace: Option<Vec<Step>>,
    /// Visit stamps per triangle for pocket searches.
    pub(crate) stamp: Vec<u32>,
    pub(crate) epoch: u32,
}

impl<'a> Boundary<'a> {
    /// Labels and boundary of graph `g` (§2.2), and the class of every vertex.
    pub fn from_graph(dt: &'a Triangulation, g: &EdgeMask) -> Boundary<'a> {
        let nt = dt.num_triangles();
        let mut inside = vec![true; nt];
        let mut queue: Vec<u32> = Vec::new();
        for h in 0..dt.num_halfedges() as u32 {
            if dt.twin(h) == EMPTY && !g.contains(h) && inside[(h / 3) as usize] {
                inside[(h / 3) as usize] = false;
                queue.push(h / 3);
            }
        }
        while let Some(t) = queue.pop() {
            for h in 3 * t..3 * t + 3 {
                let twin = dt.twin(h);
                if twin != EMPTY && !g.contains(h) && inside[(twin / 3) as usize] {
                    inside[(twin / 3) as usize] = false;
                    queue.push(twin / 3);
                }
            }
        }
        let contribution = |h: u32| initial_contribution(dt, g, &inside, h);
        let (edges, star) = crate::parallel::join(
            || boundary_edges(dt, g, &inside),
            || StarTable::counted(dt, contribution),
        );
        let class = crate::parallel::map_range(dt.num_vertices(), |v| star.get(v as u32).class());
        let mut bd = Boundary {
            dt,
            inside,
            edges,
            class,
            star,
            components: UnionFind::new(0),
            non_manifold: 0,
            interior: 0,
            trace: None,
            stamp: Vec::new(),
            epoch: 0,
        };
        for v in 0..dt.num_vertices() {
            debug_assert_eq!(bd.class[v], bd.classify_by_star(v as u32));
            bd.count(bd.class[v], 1);
        }
        bd
    }

    /// Union-find over the endpoints of every edge of `g` and of the boundary, and the
    /// pocket-search stamps: what inflating needs, built only when it has work.
    pub fn track_components(&mut self, g: &EdgeMask) {
        let dt = self.dt;
        self.components = UnionFind::new(dt.num_vertices());
        for h in dt.edge_halfedges() {
            if g.contains(h) || self.edges.contains(h) {
                self.components.union(dt.origin(h), dt.dest(h));
            }
        }
        self.stamp = vec![0; dt.num_triangles()];
    }

    /// What edge `h` adds to the star counts of its two ends.
    fn contribution(&self, h: u32) -> StarCounts {
        StarCounts::of_edge(self.left_is_in(h), self.right_is_in(h), self.edges.contains(h))
    }

    /// Adds (or takes away) edge `h`'s contribution to the star counts of its ends.
    fn tally(&mut self, h: u32, add: bool) {
        let c = self.contribution(h);
        for v in [self.dt.origin(h), self.dt.dest(h)] {
            self.star.update(v, c, add);
        }
    }

    /// Starts recording every label change from now on, and returns the trace's fixed part
    /// (the triangles, graph `g`, the current labels and dangling edges; no steps yet).
    pub fn start_trace(&mut self, g: &EdgeMask) -> Trace {
        let dt = self.dt;
        let triangles = dt.input_triangles();
        let dangling = dt.to_input_edges(
            dt.edge_halfedges()
                .filter(|&h| self.edges.contains(h) && !self.left_is_in(h) && !self.right_is_in(h))
                .map(|h| [dt.origin(h), dt.dest(h)]),
        );
        self.trace = Some(Vec::new());
        Trace {
            triangles,
            graph: g.edges(dt),
            initial_inside: self.inside.clone(),
            dangling,
            steps: Vec::new(),
            inflated_at: 0,
        }
    }

    /// Sets the label of triangle `t`, recording the change when tracing.
    #[inline]
    pub fn set_inside(&mut self, t: u32, inside: bool, phase: Phase) {
        debug_assert_ne!(self.inside[t as usize], inside, "not a label change");
        for h in 3 * t..3 * t + 3 {
            self.tally(h, false);
        }
        self.inside[t as usize] = inside;
        for h in 3 * t..3 * t + 3 {
            self.tally(h, true);
        }
        if let Some(steps) = &mut self.trace {
            steps.push(Step { triangle: t as usize, inside, phase });
        }
    }

    /// Puts the edge of `h` on the boundary or takes it off.
    #[inline]
    pub fn set_edge(&mut self, h: u32, on: bool) {
        self.tally(h, false);
        self.edges.set(self.dt, h, on);
        self.tally(h, true);
    }

    /// The labels and the boundary edges, all the loops are read from; the rest (the counts,
    /// classes and stamps) is freed here, before the loops are.
    pub(crate) fn into_labels_and_edges(self) -> (Vec<bool>, EdgeMask) {
        (self.inside, self.edges)
    }

    /// Whether the triangle on the left of `h` is interior.
    #[inline]
    pub fn left_is_in(&self, h: u32) -> bool {
        self.inside[(h / 3) as usize]
    }

    /// Whether the triangle on the right of `h` (across it) is interior; the outside of the
    /// hull never is.
    #[inline]
    pub fn right_is_in(&self, h: u32) -> bool {
        let t = self.dt.twin(h);
        t != EMPTY && self.inside[(t / 3) as usize]
    }

    /// The class of `v` (O(1)).
    pub fn classify(&self, v: u32) -> VertexClass {
        self.star.get(v).class()
    }

    /// Panics unless every vertex's class and counts are those its star gives: the check of
    /// the incremental counts, run by debug builds after inflating and sculpting.
    pub fn check_classes(&self) {
        for v in 0..self.class.len() as u32 {
            assert_eq!(self.class[v as usize], self.classify_by_star(v), "class of vertex {v}");
        }
    }

    /// The class of `v` from its star (O(deg v)).
    fn classify_by_star(&self, v: u32) -> VertexClass {
        let (mut transitions, mut dangling, mut touches_out) = (0, 0, false);
        let mut edge = |h: u32| {
            let (left, right) = (self.left_is_in(h), self.right_is_in(h));
            transitions += usize::from(left != right);
            dangling += usize::from(!left && !right && self.edges.contains(h));
            touches_out |= !left || !right;
        };
        let mut last = EMPTY;
        for h in self.dt.outgoing(v) {
            edge(h);
            last = h;
        }
        // A hull vertex also has its incoming hull edge, `prev` of the last outgoing one.
        if last != EMPTY && self.dt.twin(prev(last)) == EMPTY {
            edge(prev(last));
        }
        if !touches_out {
            VertexClass::Interior
        } else if transitions == 2 && dangling == 0 {
            VertexClass::Manifold
        } else {
            VertexClass::NonManifold
        }
    }

    /// Recomputes the class of `v`, keeping the counters right.
    pub fn reclassify(&mut self, v: u32) {
        let new = self.classify(v);
        let old = std::mem::replace(&mut self.class[v as usize], new);
        if old != new {
            self.count(old, -1);
            self.count(new, 1);
        }
    }

    fn count(&mut self, class: VertexClass, delta: isize) {
        match class {
            VertexClass::NonManifold => {
                self.non_manifold = self.non_manifold.wrapping_add_signed(delta)
            }
            VertexClass::Interior => self.interior = self.interior.wrapping_add_signed(delta),
            VertexClass::Manifold => {}
        }
    }

    /// Interior vertices, by vertex number.
    pub fn interior_vertices(&self) -> Vec<u32> {
        (0..self.class.len() as u32)
            .filter(|&v| self.class[v as usize] == VertexClass::Interior)
            .collect()
    }
}

/// The boundary `B` of graph `g` under the labels `inside`: the edges of `g` with an
/// exterior side, 64 half-edges to a word of the mask, in parallel on several threads (the
/// test is the same for both halves of an edge, so each half is tested on its own).
fn boundary_edges(dt: &Triangulation, g: &EdgeMask, inside: &[bool]) -> EdgeMask {
    let halfedges = dt.num_halfedges();
    let words = crate::parallel::map_range(halfedges.div_ceil(64), |w| {
        let (mut word, mut edges) = (0u64, 0);
        for h in (64 * w..(64 * w + 64).min(halfedges)).map(|h| h as u32) {
            let twin = dt.twin(h);
            let exterior_side =
                || !inside[(h / 3) as usize] || twin == EMPTY || !inside[(twin / 3) as usize];
            if g.contains(h) && exterior_side() {
                word |= 1 << (h % 64);
                // Each edge once: its half with the smaller index, or its one hull half.
                edges += usize::from(h < twin);
            }
        }
        (word, edges)
    });
    let count = words.iter().map(|&(_, edges)| edges).sum();
    EdgeMask::from_words(words.into_iter().map(|(word, _)| word).collect(), count)
}

/// What edge `h` of graph `g` adds to the star counts of its ends under the labels `inside`,
/// before any change: [`Boundary::contribution`] with `B` read off `g` and the labels (an
/// edge of `g` with both sides exterior is on the boundary, so it dangles).
fn initial_contribution(dt: &Triangulation, g: &EdgeMask, inside: &[bool], h: u32) -> StarCounts {
    let twin = dt.twin(h);
    let left = inside[(h / 3) as usize];
    let right = twin != EMPTY && inside[(twin / 3) as usize];
    StarCounts::of_edge(left, right, g.contains(h))
}
