//! The canonical Delaunay triangulation, seen through flat index arrays.
//!
//! The points are copied once into BRIO order (module `brio`) and inserted one by one straight
//! into the representation every algorithm here uses (module `incremental`, a port of
//! spade's insertion). Its incircle test is symbolically perturbed (module `perturbation`),
//! so cocircular points get one triangulation, and the insertion order depends on the point
//! set alone: the same points give the same arrays in every input order and on every thread
//! count (`docs/algorithms.md` §0.2; module `check` is the invariant checker):
//!
//! - `triangles[3t..3t+3]`: the vertices of triangle `t`, counter-clockwise;
//! - half-edge `h` runs from `triangles[h]` to `triangles[next(h)]` and has triangle `h / 3`
//!   on its left; `halfedges[h]` is its twin, or [`EMPTY`] on the convex hull (the outside is
//!   a "ghost" that always counts as exterior);
//! - `vertex_halfedge[v]`: one outgoing half-edge of `v`, for hull vertices the one on the
//!   hull, so that rotating counter-clockwise from it visits every triangle at `v`.
//!
//! Vertices are the *distinct* input points, numbered in insertion order (canonical and
//! spatially coherent, which keeps the algorithms cache-friendly); [`Triangulation::input_index`] maps
//! them back. Exact duplicates are merged into their lowest-index representative and listed
//! in [`Triangulation::duplicates`]. All points collinear, or fewer than three distinct
//! points, give a triangulation without triangles ([`Shape`]).
//!
//! # Complexity
//! O(n log n) expected time, O(n) memory: the flat arrays are the only structure (memory per
//! point: `docs/algorithms.md` §7.3).

pub(crate) mod brio;
mod build;
pub(crate) mod check;
mod divide;
pub(crate) mod hygiene;
mod incremental;
mod merge;
pub(crate) mod perturbation;
mod relabel;

use crate::geometry::Edge;
use crate::geometry::{distance, Point};

/// Marks a missing twin (a hull half-edge) or a missing triangle.
pub const EMPTY: u32 = u32::MAX;

/// What kind of point set was triangulated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// At least three non-collinear distinct points: a proper triangulation.
    Proper,
    /// Three or more distinct points, all on one line. Vertices are numbered in their order
    /// along the line; there are no triangles.
    Collinear,
    /// Fewer than three distinct points; no triangles. Two points are numbered in
    /// lexicographic order.
    TooFewPoints,
}

/// A Delaunay triangulation of the distinct input points. See the module docs.
#[derive(Debug, Clone)]
pub struct Triangulation {
    points: Vec<Point>,
    input_index: Vec<u32>,
    triangles: Vec<u32>,
    halfedges: Vec<u32>,
    vertex_halfedge: Vec<u32>,
    duplicates: Vec<Edge>,
    input_len: usize,
    shape: Shape,
    scaling: hygiene::Scaling,
}

/// The half-edge after `h` in its triangle.
#[inline]
pub fn next(h: u32) -> u32 {
    if h % 3 == 2 {
        h - 2
    } else {
        h + 1
    }
}

/// The half-edge before `h` in its triangle.
#[inline]
pub fn prev(h: u32) -> u32 {
    if h % 3 == 0 {
        h + 2
    } else {
        h - 1
    }
}

impl Triangulation {
    /// What kind of point set this is.
    pub fn shape(&self) -> Shape {
        self.shape
    }

    /// Number of distinct points (vertices).
    pub fn num_vertices(&self) -> usize {
        self.points.len()
    }

    /// Number of points the caller gave, duplicates included.
    pub fn input_len(&self) -> usize {
        self.input_len
    }

    /// Number of triangles.
    pub fn num_triangles(&self) -> usize {
        self.triangles.len() / 3
    }

    /// Number of half-edges (three per triangle).
    pub fn num_halfedges(&self) -> usize {
        self.triangles.len()
    }

    /// Vertex position, scaled by the exact power of two chosen at construction; use it for
    /// comparisons only, never report it.
    #[inline]
    pub fn point(&self, v: u32) -> Point {
        self.points[v as usize]
    }

    /// The caller's coordinates of `p`, a point in the scaled coordinates of
    /// [`point`](Self::point): for methods that place vertices of their own.
    #[inline]
    pub fn unscale(&self, p: Point) -> Point {
        self.scaling.unapply(p)
    }

    /// The input index of every vertex ([`input_index`](Self::input_index)).
    pub(crate) fn input_indices(&self) -> &[u32] {
        &self.input_index
    }

    /// What a result needs of the triangulation once inflating and sculpting are done: the
    /// input index of every vertex and the duplicates; the rest is freed.
    pub(crate) fn into_input_indices(self) -> (Vec<u32>, Vec<Edge>) {
        (self.input_index, self.duplicates)
    }

    /// Index into the caller's points of vertex `v` (the lowest among exact duplicates).
    #[inline]
    pub fn input_index(&self, v: u32) -> usize {
        self.input_index[v as usize] as usize
    }

    /// The inverse of [`input_index`](Self::input_index): the vertex of every input index,
    /// `u32::MAX` for a duplicate that is not its copies' representative.
    pub(crate) fn vertex_of_inputs(&self) -> Vec<u32> {
        let mut vertex_of = vec![u32::MAX; self.input_len()];
        for v in 0..self.num_vertices() as u32 {
            vertex_of[self.input_index(v)] = v;
        }
        vertex_of
    }

    /// `[duplicate, representative]` for every input point equal to a lower-index point,
    /// sorted.
    pub fn duplicates(&self) -> &[Edge] {
        &self.duplicates
    }

    /// Every triangle as input indices (duplicates by their representative), counter-clockwise,
    /// in triangle order.
    pub fn input_triangles(&self) -> Vec<[usize; 3]> {
        (0..self.num_triangles() as u32)
            .map(|t| [0, 1, 2].map(|k| self.input_index(self.origin(3 * t + k))))
            .collect()
    }

    /// [`input_triangles`](Self::input_triangles) in an order that does not depend on how
    /// the arrays are laid out (which varies with the thread count): each triangle from its
    /// smallest index (counter-clockwise kept), sorted. `sigdt view` lists them so, as the
    /// trace does.
    #[doc(hidden)]
    pub fn input_triangles_in_canonical_order(&self) -> Vec<[usize; 3]> {
        let mut triangles: Vec<[usize; 3]> =
            self.input_triangles().into_iter().map(from_smallest).collect();
        triangles.sort_unstable();
        triangles
    }

    /// Vertex where half-edge `h` starts.
    #[inline]
    pub fn origin(&self, h: u32) -> u32 {
        self.triangles[h as usize]
    }

    /// Vertex where half-edge `h` ends.
    #[inline]
    pub fn dest(&self, h: u32) -> u32 {
        self.triangles[next(h) as usize]
    }

    /// The opposite half-edge of `h`, or [`EMPTY`] on the hull.
    #[inline]
    pub fn twin(&self, h: u32) -> u32 {
        self.halfedges[h as usize]
    }

    /// Length of the edge of half-edge `h` (in scaled coordinates).
    #[inline]
    pub fn length(&self, h: u32) -> f64 {
        distance(self.point(self.origin(h)), self.point(self.dest(h)))
    }

    /// Whether `v` lies on the convex hull.
    #[inline]
    pub fn is_hull_vertex(&self, v: u32) -> bool {
        self.twin(self.vertex_halfedge[v as usize]) == EMPTY
    }

    /// The outgoing half-edges of `v` in counter-clockwise order; for a hull vertex the
    /// first is its outgoing hull edge. (The incoming hull edge of a hull vertex is then
    /// `prev` of the last one.)
    #[inline]
    pub fn outgoing(&self, v: u32) -> Outgoing<'_> {
        let start =
            if self.triangles.is_empty() { EMPTY } else { self.vertex_halfedge[v as usize] };
        Outgoing { dt: self, start, current: start }
    }

    /// Half-edges covering every edge at `v` once: the outgoing ones and, for a hull vertex,
    /// its incoming hull half-edge (which ends at `v`).
    #[inline]
    pub fn incident(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        let hull_in = if !self.triangles.is_empty() && self.is_hull_vertex(v) {
            // The incoming hull edge is `prev` of the last outgoing half-edge.
            self.outgoing(v).last().map(prev)
        } else {
            None
        };
        self.outgoing(v).chain(hull_in)
    }

    /// Whether `a` and `b` are joined by a Delaunay edge (O(degree of `a`)).
    #[inline]
    pub fn has_edge(&self, a: u32, b: u32) -> bool {
        self.incident(a).any(|h| self.other(h, a) == b)
    }

    /// The vertex at the other end of half-edge `h` from `v`.
    #[inline]
    pub fn other(&self, h: u32, v: u32) -> u32 {
        let a = self.origin(h);
        if a == v {
            self.dest(h)
        } else {
            a
        }
    }

    /// Every undirected edge once, as the half-edge that represents it: the one with the
    /// smaller index of a twin pair, or the hull half-edge.
    pub fn edge_halfedges(&self) -> impl Iterator<Item = u32> + '_ {
        // EMPTY is u32::MAX, so `h < twin` also holds for every hull half-edge.
        (0..self.triangles.len() as u32).filter(move |&h| h < self.halfedges[h as usize])
    }

    /// Hull vertices in counter-clockwise order, starting at the lowest vertex number.
    pub fn hull(&self) -> Vec<u32> {
        let Some(start) = (0..self.num_vertices() as u32)
            .find(|&v| !self.triangles.is_empty() && self.is_hull_vertex(v))
        else {
            return Vec::new();
        };
        let mut hull = vec![start];
        let mut v = self.dest(self.vertex_halfedge[start as usize]);
        while v != start {
            hull.push(v);
            v = self.dest(self.vertex_halfedge[v as usize]);
        }
        hull
    }

    /// The Delaunay edges as sorted input-index pairs. For collinear input these are the
    /// segments between consecutive points along the line; for two points, the one edge.
    pub fn edges(&self) -> Vec<Edge> {
        match self.shape {
            Shape::Proper => {
                self.to_input_edges(self.edge_halfedges().map(|h| [self.origin(h), self.dest(h)]))
            }
            _ => self.to_input_edges(self.line_edges()),
        }
    }

    /// Consecutive pairs along the line, for [`Shape::Collinear`] and [`Shape::TooFewPoints`].
    pub fn line_edges(&self) -> impl Iterator<Item = [u32; 2]> {
        (1..self.num_vertices() as u32).map(|v| [v - 1, v])
    }

    /// Maps vertex pairs to sorted, deduplicated input-index edges `[i, j]`, `i < j`.
    pub fn to_input_edges(&self, pairs: impl IntoIterator<Item = [u32; 2]>) -> Vec<Edge> {
        let mut edges: Vec<Edge> = pairs
            .into_iter()
            .map(|[a, b]| {
                let (i, j) = (self.input_index(a), self.input_index(b));
                [i.min(j), i.max(j)]
            })
            .collect();
        edges.sort_unstable();
        edges.dedup();
        edges
    }
}

/// Iterator over the outgoing half-edges of a vertex; see [`Triangulation::outgoing`].
pub struct Outgoing<'a> {
    dt: &'a Triangulation,
    start: u32,
    current: u32,
}

impl Iterator for Outgoing<'_> {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        let h = self.current;
        if h == EMPTY {
            return None;
        }
        let twin = self.dt.twin(prev(h));
        self.current = if twin == self.start { EMPTY } else { twin };
        Some(h)
    }
}

/// The triangle `t` rotated to start at its smallest index (its orientation kept).
pub(crate) fn from_smallest<T: Ord + Copy>(t: [T; 3]) -> [T; 3] {
    let k = (0..3).min_by_key(|&i| t[i]).unwrap_or(0);
    [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
}
