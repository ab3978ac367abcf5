//! The operations of incremental insertion: spade's `dcel_operations` (splitting a face or
//! an edge, growing the convex hull, flipping), each as the faces it leaves behind, and the
//! legalizing flips after each insertion (module `incremental` gives the representation).
use super::{is_outer, nxt, perturbation, prv, slot, Dt, Half, Handle, Twin, EMPTY, NEW, OUTER};
use crate::bits::word_bit;

impl Dt {
    /// `dcel_operations::insert_into_triangle`: `v` splits face `f0` into three. Spade keeps
    /// the adjacent edge `e0` in `f0` and moves `e1` and `e2` into the new faces `nf` and
    /// `nf + 1`, each with `v` opposite; written out by hand (the same as the [`Dt::rewrite`]
    /// of the three faces).
    pub(super) fn insert_into_triangle(&mut self, v: u32, f0: u32) {
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
    pub(super) fn split_edge(&mut self, e0: Handle, v0: u32) {
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
    pub(super) fn split_half_edge(&mut self, edge: Handle, nv: u32) {
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
    pub(super) fn create_new_face_adjacent_to_edge(&mut self, edge: Handle, v: u32) {
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
    pub(super) fn create_single_face_between_edge_and_next(&mut self, edge: Handle) -> [Handle; 3] {
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
    pub(super) fn flip_cw(&mut self, h: Handle) {
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
    pub(super) fn normalized_bit(&self, s: u32) -> bool {
        word_bit(&self.normalized, s)
    }

    #[inline]
    pub(super) fn set_normalized_bit(&mut self, s: u32, normalized: bool) {
        let (word, k) = (s as usize / 64, s % 64);
        self.normalized[word] = self.normalized[word] & !(1 << k) | u64::from(normalized) << k;
    }

    pub(super) fn num_faces(&self) -> u32 {
        (self.tri.len() / 3) as u32
    }

    /// Writes face `base / 3`: the origins of its three half-edges and their normalized bits.
    #[inline]
    pub(super) fn write_face(&mut self, base: u32, origins: [u32; 3], normalized: [bool; 3]) {
        self.tri[base as usize..base as usize + 3].copy_from_slice(&origins);
        for (k, bit) in (0..3).zip(normalized) {
            self.set_normalized_bit(base + k, bit);
        }
    }

    /// Makes slots `s` and `t` twins; `t = EMPTY` puts `s` on the hull.
    #[inline]
    pub(super) fn link(&mut self, s: u32, t: u32) {
        self.twin[s as usize] = t;
        if t != EMPTY {
            self.twin[t as usize] = s;
        }
    }

    /// Moves the out-edge of `x` from slot `old` to `new` if it was there (the half-edge
    /// itself, or its outer twin, moved).
    #[inline]
    pub(super) fn follow_out_edge(&mut self, x: u32, old: u32, new: u32) {
        if self.out[x as usize] == old {
            self.out[x as usize] = new;
        }
    }

    /// Appends `k` faces for the caller to fill.
    pub(super) fn add_faces(&mut self, k: usize) {
        let len = self.tri.len() + 3 * k;
        self.tri.resize(len, 0);
        self.twin.resize(len, EMPTY);
        self.normalized.resize(len.div_ceil(64), 0);
    }

    /// Writes `faces` (existing, or the next new ones in order) with `halves`, three per face
    /// starting at spade's adjacent edge, links the twins, and moves every stored handle of a
    /// half-edge that changed slot. Returns the slot of each half.
    pub(super) fn rewrite<const N: usize>(
        &mut self,
        faces: &[u32],
        halves: &[Half; N],
    ) -> [u32; N] {
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

    pub(super) fn insert_outside_of_convex_hull(&mut self, hull_edge: Handle, v: u32) {
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

    pub(super) fn legalize_vertex(&mut self, v: u32) {
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
    pub(super) fn legalize_edge(&mut self, edge: Handle) {
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
