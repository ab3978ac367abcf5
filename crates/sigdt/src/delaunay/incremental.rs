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
use super::{perturbation, EMPTY};
use crate::geometry::Point;
use crate::graph::word_bit;
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

    // Operations: spade's `dcel_operations`, each as the faces it leaves behind.

    /// `dcel_operations::insert_into_triangle`: `v` splits face `f0` into three. Spade keeps
    /// the adjacent edge `e0` in `f0` and moves `e1` and `e2` into the new faces `nf` and
    /// `nf + 1`, each with `v` opposite; written out by hand (the same as the [`Dt::rewrite`]
    /// of the three faces).
    fn insert_into_triangle(&mut self, v: u32, f0: u32) {
        debug_assert!(self.stack.is_empty() && self.pending.is_empty() && self.held.is_empty());
        let nf = self.num_faces();
        let (b0, b1, b2) = (3 * f0, 3 * nf, 3 * nf + 3);
        let (e0, e1, e2) = (b0 + 1, b0 + 2, b0);
        let [v0, v1, v2] = [e0, e1, e2].map(|s| self.tri[s as usize]);
        let [t1, t2] = [e1, e2].map(|s| self.twin[s as usize]);
        let [n1, n2] = [e1, e2].map(|s| self.normalized_bit(s));
        let n0 = self.normalized_bit(e0);
        self.add_faces(2);
        // Each face starts at the new vertex: [v, old edge's origin, its destination]. `e0`
        // stays at its slot with its twin.
        self.write_face(b0, [v, v0, v1], [false, n0, true]);
        self.write_face(b1, [v, v1, v2], [false, n1, true]);
        self.write_face(b2, [v, v2, v0], [false, n2, true]);
        for (s, t) in [(b0, b2 + 2), (b0 + 2, b1), (b1 + 2, b2), (b1 + 1, t1), (b2 + 1, t2)] {
            self.link(s, t);
        }
        for (x, old, new) in
            [(v1, e1, b1 + 1), (v2, e1, b1 + 1), (v2, e2, b2 + 1), (v0, e2, b2 + 1)]
        {
            self.follow_out_edge(x, old, new);
        }
        self.out[v as usize] = b1;
    }

    /// `dcel_operations::split_edge`: `v` splits the inner edge `e0` and both its faces.
    fn split_edge(&mut self, e0: Handle, v0: u32) {
        let t0 = self.rev(e0);
        let (ep, en, tn, tp) = (self.prev(e0), self.next(e0), self.next(t0), self.prev(t0));
        let (f0, f1) = (slot(e0) / 3, slot(t0) / 3);
        let nf = self.num_faces();
        let v1 = self.from(e0);
        let v2 = self.from(tp);
        let v3 = self.from(t0);
        let v4 = self.from(ep);
        let old = |e: Handle, origin, twin| Half {
            origin,
            normalized: self.is_normalized(e),
            old: e,
            twin,
        };
        let new = |origin, normalized, twin| Half {
            origin,
            normalized,
            old: NEW,
            twin: Twin::Internal(twin),
        };
        let kept = Twin::Kept;
        let halves = [
            // f0: e0, t3, ep
            old(e0, v1, Twin::Internal(4)),
            new(v0, false, 9),
            old(ep, v4, kept),
            // f1: e1, t0, tn
            new(v2, true, 7),
            old(t0, v0, Twin::Internal(0)),
            old(tn, v1, kept),
            // f2: e2, t1, tp
            new(v3, true, 10),
            new(v0, false, 3),
            old(tp, v2, kept),
            // f3: e3, t2, en
            new(v4, true, 1),
            new(v0, false, 6),
            old(en, v3, kept),
        ];
        let s = self.rewrite(&[f0, f1, nf, nf + 1], &halves);
        self.out[v0 as usize] = s[4]; // t0
        self.out[v3 as usize] = s[6]; // e2
    }

    /// `dcel_operations::split_half_edge`: `nv` splits the hull edge `edge` (inner half) and
    /// its face.
    fn split_half_edge(&mut self, edge: Handle, nv: u32) {
        let (en, ep) = (self.next(edge), self.prev(edge));
        let (from, to, v) = (self.from(edge), self.to(edge), self.from(ep));
        let f1 = slot(edge) / 3;
        let nf = self.num_faces();
        let old = |e: Handle, origin, twin| Half {
            origin,
            normalized: self.is_normalized(e),
            old: e,
            twin,
        };
        let halves = [
            // f1: edge, t1, ep
            old(edge, from, Twin::Hull),
            Half { origin: nv, normalized: false, old: NEW, twin: Twin::Internal(5) },
            old(ep, v, Twin::Kept),
            // nf: e2, en, e1
            Half { origin: nv, normalized: true, old: NEW, twin: Twin::Hull },
            old(en, to, Twin::Kept),
            Half { origin: v, normalized: true, old: NEW, twin: Twin::Internal(1) },
        ];
        let s = self.rewrite(&[f1, nf], &halves);
        self.out[nv as usize] = s[3]; // e2
        self.out[to as usize] = s[3]; // t2, the outer twin of e2
    }

    /// `dcel_operations::create_new_face_adjacent_to_edge`: a face on the outer half-edge
    /// `edge` with apex `v`; written out by hand (the same as the [`Dt::rewrite`] of the new
    /// face).
    fn create_new_face_adjacent_to_edge(&mut self, edge: Handle, v: u32) {
        debug_assert!(is_outer(edge) && self.stack.is_empty() && self.held.is_empty());
        let inner = slot(edge);
        let (from, to) = (self.from(edge), self.to(edge));
        let normalized = self.is_normalized(edge);
        let b = 3 * self.num_faces();
        self.add_faces(1);
        self.write_face(b, [v, from, to], [true, normalized, true]);
        self.link(b + 1, inner);
        self.follow_out_edge(from, inner, b + 1);
        self.out[v as usize] = b;
    }

    /// `dcel_operations::create_single_face_between_edge_and_next`: closes the outer
    /// half-edge `edge` and its successor with a face; returns the new outer half-edge and
    /// where `edge` and its successor now lie. Written out by hand (the same as the
    /// [`Dt::rewrite`] of the new face).
    fn create_single_face_between_edge_and_next(&mut self, edge: Handle) -> [Handle; 3] {
        debug_assert!(self.stack.is_empty() && self.pending.is_empty());
        let next = self.next(edge);
        let (a, b, c) = (self.from(edge), self.from(next), self.to(next));
        let (edge_normalized, next_normalized) =
            (self.is_normalized(edge), self.is_normalized(next));
        let (s_edge, s_next) = (slot(edge), slot(next));
        let base = 3 * self.num_faces();
        self.add_faces(1);
        // [next, the new hull edge c -> a, edge].
        self.write_face(base, [b, c, a], [next_normalized, true, edge_normalized]);
        self.link(base, s_next);
        self.link(base + 2, s_edge);
        self.follow_out_edge(a, s_edge, base + 2);
        self.follow_out_edge(b, s_next, base);
        for h in &mut self.held {
            if *h == edge {
                *h = Handle::from(base + 2);
            } else if *h == next {
                *h = Handle::from(base);
            }
        }
        [OUTER | Handle::from(base + 1), Handle::from(base + 2), Handle::from(base)]
    }

    /// `dcel_operations::flip_cw` of the undirected edge of `h` (both halves inner): the
    /// normalized half `e` keeps its face, now `[e, tp, en]`, and its twin `t` keeps its
    /// face, now `[t, ep, tn]`. Written out by hand (the most frequent operation); the same
    /// as the [`Dt::rewrite`] of those two faces.
    fn flip_cw(&mut self, h: Handle) {
        let e = if self.is_normalized(h) { slot(h) } else { slot(self.rev(h)) };
        let t = self.twin[e as usize];
        let (en, ep, tn, tp) = (nxt(e), prv(e), nxt(t), prv(t));
        let (be, bt) = (e - e % 3, t - t % 3);
        let (a, b) = (self.tri[e as usize], self.tri[t as usize]);
        let (c, d) = (self.tri[ep as usize], self.tri[tp as usize]);
        let bits = [tp, en, ep, tn].map(|s| self.normalized_bit(s));
        let twins = [tp, en, ep, tn].map(|s| self.twin[s as usize]);
        // Face of `e`: [en, e, tp] -> slots be, be + 1, be + 2; face of `t`: [tn, t, ep].
        self.write_face(be, [b, c, d], [bits[1], true, bits[0]]);
        self.write_face(bt, [a, d, c], [bits[3], false, bits[2]]);
        self.link(be + 1, bt + 1);
        for (s, outside) in [be + 2, be, bt + 2, bt].into_iter().zip(twins) {
            self.link(s, outside);
        }
        // Out-edges: spade resets those of `a` and `b`; `c` and `d` follow theirs (each old
        // slot lies in one face and its new one in the other, so the moves cannot chain).
        self.out[a as usize] = bt;
        self.out[b as usize] = be;
        for (x, old, new) in [(c, ep, bt + 2), (c, en, be), (d, tp, be + 2), (d, tn, bt)] {
            self.follow_out_edge(x, old, new);
        }
        // Handles into the two faces follow their half-edges. The link edges that
        // `legalize_vertex` has still to do never lie in them: a flip rewrites the face of
        // the link edge it flips and the face across, which does not contain the new vertex;
        // the other link edges lie in other faces of the new vertex's star.
        let (fe, ft) = (e / 3, t / 3);
        debug_assert!(self.pending.iter().all(|&h| slot(h) / 3 != fe && slot(h) / 3 != ft));
        for list in [&mut self.stack, &mut self.held] {
            for h in list.iter_mut() {
                let s = slot(*h);
                if s / 3 == fe || s / 3 == ft {
                    let new = if s == e {
                        be + 1
                    } else if s == tp {
                        be + 2
                    } else if s == en {
                        be
                    } else if s == t {
                        bt + 1
                    } else if s == ep {
                        bt + 2
                    } else {
                        bt
                    };
                    *h = (*h & OUTER) | Handle::from(new);
                }
            }
        }
    }

    #[inline]
    fn normalized_bit(&self, s: u32) -> bool {
        word_bit(&self.normalized, s)
    }

    #[inline]
    fn set_normalized_bit(&mut self, s: u32, normalized: bool) {
        let (word, k) = (s as usize / 64, s % 64);
        self.normalized[word] = self.normalized[word] & !(1 << k) | u64::from(normalized) << k;
    }

    fn num_faces(&self) -> u32 {
        (self.tri.len() / 3) as u32
    }

    /// Writes face `base / 3`: the origins of its three half-edges and their normalized bits.
    #[inline]
    fn write_face(&mut self, base: u32, origins: [u32; 3], normalized: [bool; 3]) {
        self.tri[base as usize..base as usize + 3].copy_from_slice(&origins);
        for (k, bit) in (0..3).zip(normalized) {
            self.set_normalized_bit(base + k, bit);
        }
    }

    /// Makes slots `s` and `t` twins; `t = EMPTY` puts `s` on the hull.
    #[inline]
    fn link(&mut self, s: u32, t: u32) {
        self.twin[s as usize] = t;
        if t != EMPTY {
            self.twin[t as usize] = s;
        }
    }

    /// Moves the out-edge of `x` from slot `old` to `new` if it was there (the half-edge
    /// itself, or its outer twin, moved).
    #[inline]
    fn follow_out_edge(&mut self, x: u32, old: u32, new: u32) {
        if self.out[x as usize] == old {
            self.out[x as usize] = new;
        }
    }

    /// Appends `k` faces for the caller to fill.
    fn add_faces(&mut self, k: usize) {
        let len = self.tri.len() + 3 * k;
        self.tri.resize(len, 0);
        self.twin.resize(len, EMPTY);
        self.normalized.resize(len.div_ceil(64), 0);
    }

    /// Writes `faces` (existing, or the next new ones in order) with `halves`, three per face
    /// starting at spade's adjacent edge, links the twins, and moves every stored handle of a
    /// half-edge that changed slot. Returns the slot of each half.
    fn rewrite<const N: usize>(&mut self, faces: &[u32], halves: &[Half; N]) -> [u32; N] {
        let slots: [u32; N] = std::array::from_fn(|j| 3 * faces[j / 3] + (j as u32 % 3 + 1) % 3);
        // Before writing: the twins kept, and which old half-edges are out-edges.
        let mut kept = [EMPTY; N];
        let mut out_of = [[u32::MAX; 2]; N];
        for (j, half) in halves.iter().enumerate() {
            if half.old == NEW {
                continue;
            }
            let s = slot(half.old);
            if is_outer(half.old) {
                kept[j] = s;
                let v = self.tri[nxt(s) as usize];
                if self.out_edge(v) == half.old {
                    out_of[j][0] = v;
                }
            } else {
                kept[j] = self.twin[s as usize];
                let v = self.tri[s as usize];
                if self.out_edge(v) == half.old {
                    out_of[j][0] = v;
                }
                if kept[j] == EMPTY {
                    let w = self.tri[nxt(s) as usize];
                    if self.out_edge(w) == OUTER | half.old {
                        out_of[j][1] = w;
                    }
                }
            }
        }
        // Write.
        let needed = 3 * (*faces.iter().max().unwrap() as usize + 1);
        if self.tri.len() < needed {
            self.tri.resize(needed, 0);
            self.twin.resize(needed, EMPTY);
            self.normalized.resize(needed.div_ceil(64), 0);
        }
        for (j, half) in halves.iter().enumerate() {
            let s = slots[j] as usize;
            self.tri[s] = half.origin;
            self.set_normalized_bit(s as u32, half.normalized);
        }
        for (j, half) in halves.iter().enumerate() {
            let s = slots[j];
            match half.twin {
                Twin::Internal(k) => self.twin[s as usize] = slots[k],
                Twin::Hull => self.twin[s as usize] = EMPTY,
                Twin::Kept => {
                    self.twin[s as usize] = kept[j];
                    if kept[j] != EMPTY {
                        self.twin[kept[j] as usize] = s;
                    }
                }
            }
        }
        // Move out-edges and held handles with their half-edges.
        for (j, half) in halves.iter().enumerate() {
            if half.old == NEW {
                continue;
            }
            let s = slots[j];
            for v in out_of[j] {
                if v != u32::MAX {
                    self.out[v as usize] = s;
                }
            }
        }
        let moved = |h: Handle| -> Handle {
            for (j, half) in halves.iter().enumerate() {
                if half.old == NEW {
                    continue;
                }
                let s = Handle::from(slots[j]);
                if h == half.old {
                    return s;
                }
                if !is_outer(half.old) && h == OUTER | half.old {
                    return OUTER | s;
                }
            }
            h
        };
        for list in [&mut self.stack, &mut self.pending, &mut self.held] {
            for h in list.iter_mut() {
                *h = moved(*h);
            }
        }
        slots
    }

    // Insertion: spade's `triangulation_ext`.

    fn insert_outside_of_convex_hull(&mut self, hull_edge: Handle, v: u32) {
        let p = self.pos(v);
        debug_assert!(self.side_of(hull_edge, p) > 0.0);
        self.create_new_face_adjacent_to_edge(hull_edge, v);
        // The hull edge now lies in the new face, at its adjacent slot.
        let edge = Handle::from(3 * (self.num_faces() - 1) + 1);
        let ccw_start = self.rev(self.prev(edge));
        let cw_start = self.rev(self.next(edge));
        self.held.clear();
        self.held.extend([ccw_start, cw_start]);
        self.legalize_edge(edge);
        // Counter-clockwise: close every hull edge before the new vertex that sees it.
        let mut current = self.held[0];
        loop {
            let prev = self.prev(current);
            current = prev;
            if self.side_of(prev, p) > 0.0 {
                let [new_edge, inner, _] = self.create_single_face_between_edge_and_next(current);
                self.held[0] = new_edge;
                self.legalize_edge(inner);
                current = self.held[0];
            } else {
                break;
            }
        }
        // Clockwise.
        let mut current = self.held[1];
        loop {
            let next = self.next(current);
            if self.side_of(next, p) > 0.0 {
                let [new_edge, _, inner] = self.create_single_face_between_edge_and_next(current);
                self.held[0] = new_edge;
                self.legalize_edge(inner);
                current = self.held[0];
            } else {
                break;
            }
        }
        self.held.clear();
    }

    fn legalize_vertex(&mut self, v: u32) {
        self.pending.clear();
        let first = self.out_edge(v);
        let mut e = first;
        loop {
            if !is_outer(e) {
                let next = self.next(e);
                self.pending.push(next);
            }
            e = self.ccw(e);
            if e == first {
                break;
            }
        }
        // In spade's order; the list holds only the edges still to do.
        self.pending.reverse();
        while let Some(edge) = self.pending.pop() {
            self.legalize_edge(edge);
        }
    }

    /// spade's `legalize_edge`: flips until the edges around the new vertex are Delaunay.
    fn legalize_edge(&mut self, edge: Handle) {
        self.stack.clear();
        self.stack.push(edge);
        while let Some(e) = self.stack.pop() {
            let r = self.rev(e);
            if is_outer(e) || is_outer(r) {
                continue;
            }
            let v2 = self.from(self.prev(r));
            let v3 = self.from(self.prev(e));
            let (v0, v1) = (self.from(e), self.to(e));
            // contained_in_circumference(v2, v1, v0, v3) = incircle(v0, v1, v2, v3) < 0.
            let [p0, p1, p2, p3] = [v0, v1, v2, v3].map(|v| self.pos(v));
            if perturbation::incircle(p0, p1, p2, p3) < 0.0 {
                let (rn, rp) = (self.next(r), self.prev(r));
                self.stack.push(rn);
                self.stack.push(rp);
                self.flip_cw(e);
            }
        }
    }
}
