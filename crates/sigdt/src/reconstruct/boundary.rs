//! The state inflating and sculpting work on: triangle labels, the boundary edge set `B`,
//! vertex classes (ALGORITHMS.md §2.1–2.3).
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
//! # References
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use crate::delaunay::{Triangulation, EMPTY};
use crate::graph::{EdgeMask, UnionFind};

/// How a vertex sits on the boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VertexClass {
    /// Exactly one exterior and one interior wedge, no dangling edge.
    Manifold,
    /// Pinched, dangling, or otherwise not (yet) a polygon vertex.
    NonManifold,
    /// Surrounded by interior triangles: not on the boundary.
    Interior,
}

/// Labels, boundary and classes of one run.
pub struct Boundary<'a> {
    /// The triangulation.
    pub dt: &'a Triangulation,
    /// `inside[t]`: triangle `t` is interior (IN).
    pub inside: Vec<bool>,
    /// The boundary edge set `B`.
    pub edges: EdgeMask,
    /// Class of every vertex.
    pub class: Vec<VertexClass>,
    /// Connectivity of `B` (an over-approximation; see [`crate::reconstruct::pocket`]).
    pub components: UnionFind,
    /// Number of non-manifold vertices.
    pub non_manifold: usize,
    /// Number of interior vertices.
    pub interior: usize,
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
        let mut bd = Boundary {
            dt,
            inside,
            edges: EdgeMask::new(dt),
            class: vec![VertexClass::Manifold; dt.num_vertices()],
            components: UnionFind::new(dt.num_vertices()),
            non_manifold: 0,
            interior: 0,
            stamp: vec![0; nt],
            epoch: 0,
        };
        for h in dt.edge_halfedges() {
            if g.contains(h) {
                bd.components.union(dt.origin(h), dt.dest(h));
                if !bd.left_is_in(h) || !bd.right_is_in(h) {
                    bd.edges.set(dt, h, true);
                }
            }
        }
        for v in 0..dt.num_vertices() as u32 {
            let c = bd.classify(v);
            bd.class[v as usize] = c;
            bd.count(c, 1);
        }
        bd
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

    /// The class of `v` from its star (O(deg v)).
    pub fn classify(&self, v: u32) -> VertexClass {
        let (mut transitions, mut dangling, mut touches_out) = (0, 0, false);
        for h in self.dt.incident(v) {
            let (left, right) = (self.left_is_in(h), self.right_is_in(h));
            transitions += usize::from(left != right);
            dangling += usize::from(!left && !right && self.edges.contains(h));
            touches_out |= !left || !right;
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
