//! Incremental Delaunay insertion on the flat arrays: spade's algorithm, step for step.
//!
//! This is a port of what `spade` 2.15 does in `DelaunayTriangulation::insert_with_hint`
//! (`delaunay_core/triangulation_ext.rs` and `dcel_operations.rs`): the same greedy walk to
//! the nearest vertex and the same exact location, the same splits of a face or an edge, the
//! same growth of the convex hull and the same flips in the same order, with the exact
//! orient2d of the `robust` crate. It numbers faces as spade does, while holding about a
//! third of spade's memory (no vertex, edge and face records, no export). One departure
//! changes results: the flip test is the perturbed incircle ([`super::perturbation`]), so on
//! cocircular points the triangulation is the canonical one, not spade's
//! (`docs/algorithms.md` §0.2).
//!
//! # Representation
//! Face `f` (spade's inner face `f + 1`) owns slots `3f..3f+3`: `tri[s]` is the origin of the
//! half-edge in slot `s`, ordered `[prev(a), a, next(a)]` where `a` is the face's adjacent
//! edge in spade. `twin[s]` is the slot of the twin, or `EMPTY` when the twin lies on spade's
//! outer face. A *handle* names a spade half-edge: a slot, or [`OUTER`] plus the slot of the
//! inner twin. Which half of each edge is spade's "normalized" one (it decides which face a
//! flip keeps on which side) is one bit per slot. A vertex's out-edge is stored as a slot: the
//! half-edge itself if the vertex is its origin, otherwise its outer twin.
//!
//! Two departures that cannot change the result: a point strictly inside a face is located
//! by a visibility walk from the previous vertex (spade's walk can only find that face too),
//! and the most frequent operations (flips, face splits, hull growth) are written out by hand
//! instead of through the general [`Dt::rewrite`].
//!
//! # Complexity
//! As spade's: O(n log n) expected in BRIO order with the previous vertex as hint.
mod operations;

use super::{perturbation, EMPTY};
use crate::geometry::Point;
use robust::Coord;

/// A spade half-edge: a slot, or `OUTER | slot` for the outer twin of that slot.
type Handle = u64;
/// Marks the outer half of a convex-hull edge in a [`Handle`].
const OUTER: Handle = 1 << 32;

/// Where a point lies in the triangulation (spade's `PositionInTriangulation`).
enum Location {
    OnVertex(u32),
    OnEdge(Handle),
    OnFace(u32),
    Outside(Handle),
}

/// One half-edge of a face being (re)written by [`Dt::rewrite`].
#[derive(Clone, Copy)]
struct Half {
    origin: u32,
    normalized: bool,
    /// The spade half-edge that keeps living here, or `NEW`.
    old: Handle,
    twin: Twin,
}

/// Marks a [`Half`] that spade creates in this operation.
const NEW: Handle = u64::MAX;

#[derive(Clone, Copy)]
enum Twin {
    /// Index of the twin among the halves of the same rewrite.
    Internal(usize),
    /// The twin the old half-edge had (a slot outside the rewrite, or its inner twin).
    Kept,
    /// The outer face.
    Hull,
}

/// The triangulation under construction.
pub(super) struct Dt {
    /// Positions in insertion order; the first `num_vertices` are the vertices.
    pub points: Vec<Point>,
    pub num_vertices: usize,
    pub tri: Vec<u32>,
    pub twin: Vec<u32>,
    normalized: Vec<u64>,
    out: Vec<u32>,
    /// Edges still to legalize, the legalize-vertex list, and handles held by hull growth:
    /// every handle that must follow its half-edge when a rewrite moves it.
    stack: Vec<Handle>,
    pending: Vec<Handle>,
    held: Vec<Handle>,
    /// Whether the last point went outside the hull: the next one likely does too, and then
    /// the fast location path would only add a walk to spade's.
    last_outside: bool,
}

#[inline]
fn nxt(s: u32) -> u32 {
    if s % 3 == 2 {
        s - 2
    } else {
        s + 1
    }
}

#[inline]
fn prv(s: u32) -> u32 {
    if s % 3 == 0 {
        s + 2
    } else {
        s - 1
    }
}

#[inline]
fn slot(h: Handle) -> u32 {
    h as u32
}

#[inline]
fn is_outer(h: Handle) -> bool {
    h & OUTER != 0
}

#[inline]
fn coord(p: Point) -> Coord<f64> {
    Coord { x: p[0], y: p[1] }
}

/// spade's `side_query(from, to, q)`: positive on the left.
#[inline]
fn side(from: Point, to: Point, q: Point) -> f64 {
    robust::orient2d(coord(from), coord(to), coord(q))
}

#[inline]
fn distance_2(a: Point, b: Point) -> f64 {
    let (x, y) = (a[0] - b[0], a[1] - b[1]);
    x * x + y * y
}

impl Dt {
    /// Starts a triangulation of `points` (in insertion order) whose first three points span
    /// a triangle, in the state spade reaches after inserting them.
    pub fn new(points: Vec<Point>) -> Dt {
        let n = points.len();
        let mut dt = Dt {
            points,
            num_vertices: 3,
            tri: Vec::with_capacity(6 * n),
            twin: Vec::with_capacity(6 * n),
            normalized: Vec::with_capacity((6 * n).div_ceil(64)),
            out: Vec::with_capacity(n),
            stack: Vec::new(),
            pending: Vec::new(),
            held: Vec::new(),
            last_outside: false,
        };
        // spade: the first two vertices share edge 0 (normalized half from vertex 0); the
        // third, off their line, goes outside that edge on its side: one face whose adjacent
        // edge is the half with the third vertex on its left.
        let p = &dt.points;
        let left = side(p[0], p[1], p[2]) > 0.0;
        let (from, to) = if left { (0, 1) } else { (1, 0) };
        let halves = [
            Half { origin: from, normalized: left, old: NEW, twin: Twin::Hull },
            Half { origin: to, normalized: true, old: NEW, twin: Twin::Hull },
            Half { origin: 2, normalized: true, old: NEW, twin: Twin::Hull },
        ];
        dt.out.extend([0, 0, 0]);
        let s = dt.rewrite(&[0], &halves);
        // Out-edges: `from` has the face's edge, `to` its outer twin, the new vertex the
        // edge towards `from`.
        dt.out[from as usize] = s[0];
        dt.out[to as usize] = s[0];
        dt.out[2] = s[2];
        dt
    }

    /// Inserts `points[i]` (`i >= num_vertices`) with the vertex `hint` as the walk's start;
    /// returns the vertex, and whether it is new (else it equals an existing vertex).
    pub fn insert(&mut self, i: usize, hint: u32) -> (u32, bool) {
        let p = self.points[i];
        let start = if (hint as usize) < self.num_vertices { hint } else { 0 };
        let fast = if self.last_outside { None } else { self.face_strictly_containing(p, start) };
        let location = match fast {
            Some(f) => Location::OnFace(f),
            None => self.locate(p, start),
        };
        self.last_outside = matches!(location, Location::Outside(_));
        match location {
            Location::OnVertex(v) => (v, false),
            location => {
                let v = self.num_vertices as u32;
                self.points[v as usize] = p;
                self.num_vertices += 1;
                self.out.push(0);
                match location {
                    Location::Outside(edge) => self.insert_outside_of_convex_hull(edge, v),
                    Location::OnFace(f) => {
                        self.insert_into_triangle(v, f);
                        self.legalize_vertex(v);
                    }
                    Location::OnEdge(edge) => {
                        if is_outer(edge) {
                            self.split_half_edge(self.rev(edge), v);
                        } else if is_outer(self.rev(edge)) {
                            self.split_half_edge(edge, v);
                        } else {
                            self.split_edge(edge, v);
                        }
                        self.legalize_vertex(v);
                    }
                    Location::OnVertex(_) => unreachable!(),
                }
                (v, true)
            }
        }
    }

    /// The flat arrays: vertex positions, `triangles`, `halfedges`.
    pub fn finish(mut self) -> (Vec<Point>, Vec<u32>, Vec<u32>) {
        self.points.truncate(self.num_vertices);
        self.points.shrink_to_fit();
        (self.points, self.tri, self.twin)
    }

    // Navigation, as spade's handles.

    #[inline]
    fn from(&self, h: Handle) -> u32 {
        let s = slot(h);
        self.tri[(if is_outer(h) { nxt(s) } else { s }) as usize]
    }

    #[inline]
    fn to(&self, h: Handle) -> u32 {
        let s = slot(h);
        self.tri[(if is_outer(h) { s } else { nxt(s) }) as usize]
    }

    #[inline]
    fn pos(&self, v: u32) -> Point {
        self.points[v as usize]
    }

    #[inline]
    fn rev(&self, h: Handle) -> Handle {
        let s = slot(h);
        if is_outer(h) {
            return Handle::from(s);
        }
        match self.twin[s as usize] {
            EMPTY => OUTER | Handle::from(s),
            t => Handle::from(t),
        }
    }

    /// The next half-edge around the face; around the outer face, the hull edge that starts
    /// where `h` ends (found by rotating about that vertex).
    #[inline]
    fn next(&self, h: Handle) -> Handle {
        let s = slot(h);
        if !is_outer(h) {
            return Handle::from(nxt(s));
        }
        let mut x = prv(s);
        while self.twin[x as usize] != EMPTY {
            x = prv(self.twin[x as usize]);
        }
        OUTER | Handle::from(x)
    }

    #[inline]
    fn prev(&self, h: Handle) -> Handle {
        let s = slot(h);
        if !is_outer(h) {
            return Handle::from(prv(s));
        }
        let mut x = nxt(s);
        while self.twin[x as usize] != EMPTY {
            x = nxt(self.twin[x as usize]);
        }
        OUTER | Handle::from(x)
    }

    #[inline]
    fn ccw(&self, h: Handle) -> Handle {
        self.rev(self.prev(h))
    }

    #[inline]
    fn cw(&self, h: Handle) -> Handle {
        self.next(self.rev(h))
    }

    #[inline]
    fn is_normalized(&self, h: Handle) -> bool {
        self.normalized_bit(slot(h)) != is_outer(h)
    }

    #[inline]
    fn side_of(&self, h: Handle, q: Point) -> f64 {
        side(self.pos(self.from(h)), self.pos(self.to(h)), q)
    }

    /// The out-edge of `v` as a handle.
    #[inline]
    fn out_edge(&self, v: u32) -> Handle {
        let s = self.out[v as usize];
        if self.tri[s as usize] == v {
            Handle::from(s)
        } else {
            OUTER | Handle::from(s)
        }
    }

    // Location: a fast path, then spade's `walk_to_nearest_neighbor` and
    // `locate_with_hint_fixed_core`.

    /// The face with `p` strictly inside, found by a visibility walk from a face of `start`;
    /// `None` when the walk meets `p` on an edge or a vertex, or leaves the hull.
    ///
    /// Where it answers, spade's location must answer the same: a point strictly inside a
    /// face lies in no other face, on no edge and no vertex. Every other case goes to the
    /// spade walk ([`Dt::locate`]), whose handle decides how an edge is split or the hull
    /// grows. A visibility walk cannot cycle in a Delaunay triangulation (Edelsbrunner,
    /// *An acyclicity theorem for cell complexes in d dimensions*, 1990); the step limit only
    /// hands pathological walks back to spade's.
    fn face_strictly_containing(&self, p: Point, start: u32) -> Option<u32> {
        let mut face = self.out[start as usize] / 3;
        // The slot we came in by: `p` is strictly left of it.
        let mut entry = EMPTY;
        for _ in 0..self.num_faces() {
            let base = 3 * face;
            let corners = [base, base + 1, base + 2].map(|s| self.pos(self.tri[s as usize]));
            let mut on_an_edge = false;
            let mut crossed = false;
            for k in 0..3 {
                let s = base + k;
                if s == entry {
                    continue;
                }
                let o = side(corners[k as usize], corners[((k + 1) % 3) as usize], p);
                if o < 0.0 {
                    let t = self.twin[s as usize];
                    if t == EMPTY {
                        return None;
                    }
                    (face, entry) = (t / 3, t);
                    crossed = true;
                    break;
                }
                on_an_edge |= o == 0.0;
            }
            if !crossed {
                return if on_an_edge { None } else { Some(face) };
            }
        }
        None
    }

    fn walk_to_nearest_neighbour(&self, start: u32, p: Point) -> u32 {
        let start_position = self.pos(start);
        if start_position == p {
            return start;
        }
        let mut best = distance_2(p, start_position);
        let mut current = start;
        'walk: loop {
            let first = self.out_edge(current);
            let mut e = first;
            loop {
                let candidate = self.to(e);
                let d = distance_2(self.pos(candidate), p);
                if d < best {
                    best = d;
                    current = candidate;
                    continue 'walk;
                }
                e = self.ccw(e);
                if e == first {
                    return current;
                }
            }
        }
    }

    fn locate(&self, p: Point, start: u32) -> Location {
        let closest = self.walk_to_nearest_neighbour(start, p);
        let mut e0 = self.out_edge(closest);
        let mut e0_side = self.side_of(e0, p);
        let mut rotate_ccw = e0_side >= 0.0;
        loop {
            let (from, to) = (self.from(e0), self.to(e0));
            if self.pos(from) == p {
                return Location::OnVertex(from);
            }
            if self.pos(to) == p {
                return Location::OnVertex(to);
            }
            if e0_side == 0.0 {
                if is_outer(e0) {
                    e0 = self.rev(e0);
                }
                e0 = self.prev(e0);
                e0_side = self.side_of(e0, p);
                rotate_ccw = e0_side >= 0.0;
                continue;
            }
            let e1 = if rotate_ccw { e0 } else { self.rev(e0) };
            if is_outer(e1) {
                return Location::Outside(e1);
            }
            let rotated = if rotate_ccw { self.ccw(e0) } else { self.cw(e0) };
            let rotated_side = self.side_of(rotated, p);
            if rotated_side == 0.0 || (rotated_side > 0.0) == rotate_ccw {
                e0 = rotated;
                e0_side = rotated_side;
                continue;
            }
            let e2 = if rotate_ccw { self.next(e1) } else { self.prev(e1) };
            let e2_side = self.side_of(e2, p);
            if e2_side == 0.0 {
                return Location::OnEdge(e2);
            }
            if e2_side > 0.0 {
                return Location::OnFace(slot(e1) / 3);
            }
            e0 = self.rev(e2);
            e0_side = -e2_side;
            if !is_outer(e0) {
                e0 = self.prev(e0);
                e0_side = self.side_of(e0, p);
            }
            rotate_ccw = e0_side >= 0.0;
        }
    }
}
