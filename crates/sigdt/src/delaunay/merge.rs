//! The merge step of divide-and-conquer Delaunay triangulation, on the flat arrays.
//!
//! Guibas and Stolfi (*Primitives for the manipulation of general subdivisions and the
//! computation of Voronoi diagrams*, ACM TOG 4(2), 1985, §8.4): two Delaunay triangulations
//! of point sets separated in lexicographic order (`x`, then `y`: all of the left before all
//! of the right) are joined by walking up the seam from their lower common tangent. Each
//! step has a base edge `L→R` across the seam and picks the apex of the next triangle above
//! it: the left candidate is `L`'s first left neighbour counter-clockwise from `R`, the
//! right candidate `R`'s first right neighbour clockwise from `L`. A candidate whose next
//! neighbour lies inside the circle through the base and the candidate is not a Delaunay
//! edge of the union: that edge is deleted (here: the triangle beyond it dies) and the next
//! neighbour becomes the candidate. Of two valid candidates, the one whose circle holds the
//! other is not Delaunay; the other forms the new triangle with the base, and its cross edge
//! is the next base. The walk ends when neither candidate lies above the base: the base is
//! the upper common tangent.
//!
//! With the incircle test under the symbolic perturbation ([`super::perturbation`]) every
//! decision is strict, so the merge builds the unique Delaunay triangulation of the
//! perturbed union: the same triangles as inserting the points one by one in any order.
//! Orientations are exact and unperturbed; a candidate on the base's line is not above it,
//! and the lower tangent is taken strictly, so collinear points on the hull stay vertices
//! of it.
//!
//! In quad-edge terms an edge is deleted; in triangles, the one triangle on the candidate's
//! far side dies and its two other edges stay. An edge whose triangles on both sides died
//! (or lie outside the hull) stays too ("bare"); it is still a candidate, and the two new
//! triangles on its sides are twinned at the end. Each side's candidates are found by
//! rotating around the apex over the original triangles, skipping deleted edges, exactly
//! as a quad-edge `Onext` would.
//!
//! # Complexity
//! O(k + d) for k new triangles and d deleted ones, plus O(m) for m triangles to find the
//! hull vertices where the walk starts. The seam of n uniform points holds O(√n) triangles.
use super::perturbation::{incircle, lexicographic};
use super::{next, prev, EMPTY};
use crate::geometry::{orient2d, Point};
use std::collections::HashMap;

/// A triangulation in flat arrays (as [`super::Triangulation`] holds them), its vertices
/// numbered into a point array shared by every part.
pub(super) struct Part {
    pub triangles: Vec<u32>,
    pub halfedges: Vec<u32>,
}

/// One edge at an apex, as the walk sees it: the neighbour, and the half-edges from the
/// apex to it and back ([`EMPTY`] where the edge is on the hull and that side is outside).
#[derive(Clone, Copy, Debug)]
struct Entry {
    nbr: u32,
    out: u32,
    inn: u32,
}

impl Entry {
    /// The same edge seen from the neighbour.
    fn reversed(self, apex: u32) -> Entry {
        Entry { nbr: apex, out: self.inn, inn: self.out }
    }
}

/// The merge in progress: both parts' arrays, joined, and the new triangles after them.
struct Merge<'a> {
    points: &'a [Point],
    tri: Vec<u32>,
    twin: Vec<u32>,
    /// Triangles of the parts (below this slot); the new ones follow.
    original: u32,
    /// The parts' triangles deleted, a bit each.
    dead: Bits,
    /// Original edges deleted, marked on both half-edges.
    gone: Bits,
    /// Original half-edges with a new triangle on their left in place of theirs.
    covered: Bits,
    /// New half-edges twinned with a part's at the end: the walk reads the parts' own
    /// twins throughout, so that it rotates over their triangles only.
    links: Vec<(u32, u32)>,
    /// New half-edges along bare edges, twinned by their ends at the end.
    pending: Vec<u32>,
}

/// Joins `left` and `right`, Delaunay triangulations of `points` (vertex numbers index it)
/// whose vertices all come before (`left`) or after (`right`) each other in lexicographic
/// order; each must have at least one triangle. `None` if the walk fails a consistency
/// check (which a correct input never does): the caller then builds another way.
pub(super) fn merge(points: &[Point], left: Part, right: Part) -> Option<Part> {
    let Part { triangles: mut tri, halfedges: mut twin } = left;
    let offset = tri.len() as u32;
    // Each of the right's arrays is freed as soon as it is appended: the peak of the merge.
    let Part { triangles, halfedges } = right;
    tri.extend_from_slice(&triangles);
    drop(triangles);
    twin.extend(halfedges.iter().map(|&h| if h == EMPTY { EMPTY } else { h + offset }));
    drop(halfedges);
    let original = tri.len() as u32;
    let mut m = Merge {
        points,
        dead: Bits::new(original / 3),
        gone: Bits::new(original),
        covered: Bits::new(original),
        links: Vec::new(),
        tri,
        twin,
        original,
        pending: Vec::new(),
    };
    let lexicographic = |a: u32, b: u32| lexicographic(points[a as usize], points[b as usize]);
    // The lexicographically last vertex of the left is on its hull, the first of the right
    // on its; start from their hull out-edges.
    let hull_out = |range: std::ops::Range<u32>, want: std::cmp::Ordering| {
        range.filter(|&h| m.twin[h as usize] == EMPTY).reduce(|best, h| {
            match lexicographic(m.tri[h as usize], m.tri[best as usize]) == want {
                true => h,
                false => best,
            }
        })
    };
    let mut l_hull = hull_out(0..offset, std::cmp::Ordering::Greater)?;
    let mut r_hull = hull_out(offset..original, std::cmp::Ordering::Less)?;
    let (mut l, mut r) = (m.tri[l_hull as usize], m.tri[r_hull as usize]);
    // The lower common tangent: move either end down its hull while the next hull vertex
    // is strictly below the line.
    for _ in 0..=original {
        let into_l = m.hull_in(l_hull);
        if orient2d(m.p(l), m.p(r), m.p(m.tri[into_l as usize])) < 0.0 {
            (l, l_hull) = (m.tri[into_l as usize], into_l);
            continue;
        }
        let after_r = m.hull_out_from(next(r_hull));
        if orient2d(m.p(l), m.p(r), m.p(m.tri[after_r as usize])) < 0.0 {
            (r, r_hull) = (m.tri[after_r as usize], after_r);
            continue;
        }
        break;
    }
    let mut left_entry = Entry { nbr: m.tri[next(l_hull) as usize], out: l_hull, inn: EMPTY };
    let into_r = m.hull_in(r_hull);
    let mut right_entry = Entry { nbr: m.tri[into_r as usize], out: EMPTY, inn: into_r };
    // The cross half-edge R→L of the last new triangle, twin of the next one's L→R.
    let mut below = EMPTY;
    // Every step adds a triangle or deletes one: a bound no correct walk reaches.
    let mut budget = 2 * original as usize + 16;
    loop {
        let valid = |m: &Merge, l: u32, r: u32, c: u32| orient2d(m.p(l), m.p(r), m.p(c)) > 0.0;
        if valid(&m, l, r, left_entry.nbr) {
            while let Some(w) = m.left_beyond(left_entry) {
                let [pl, pr, pc] = [l, r, left_entry.nbr].map(|v| m.p(v));
                if incircle(pl, pr, pc, m.p(w)) <= 0.0 {
                    break;
                }
                m.delete(left_entry.out);
                left_entry = m.ccw_surviving(l, left_entry)?;
                budget = budget.checked_sub(1)?;
            }
        }
        if valid(&m, l, r, right_entry.nbr) {
            while let Some(u) = m.right_beyond(right_entry) {
                let [pl, pr, pc] = [l, r, right_entry.nbr].map(|v| m.p(v));
                if incircle(pl, pr, pc, m.p(u)) <= 0.0 {
                    break;
                }
                m.delete(right_entry.inn);
                right_entry = m.cw_surviving(r, right_entry)?;
                budget = budget.checked_sub(1)?;
            }
        }
        let (x, y) = (left_entry.nbr, right_entry.nbr);
        let (left_valid, right_valid) = (valid(&m, l, r, x), valid(&m, l, r, y));
        if !left_valid && !right_valid {
            break;
        }
        budget = budget.checked_sub(1)?;
        let take_right =
            !left_valid || (right_valid && incircle(m.p(l), m.p(r), m.p(x), m.p(y)) > 0.0);
        if take_right {
            // Triangle (L, R, y); its edge y→L is the next base.
            let s = m.add([l, r, y], below);
            m.attach(s + 1, right_entry.inn, right_entry.out);
            below = s + 2;
            right_entry = m.cw_surviving(y, right_entry.reversed(r))?;
            r = y;
        } else {
            // Triangle (L, R, x); its edge R→x is the next base.
            let s = m.add([l, r, x], below);
            m.attach(s + 2, left_entry.out, left_entry.inn);
            below = s + 1;
            left_entry = m.ccw_surviving(x, left_entry.reversed(l))?;
            l = x;
        }
    }
    m.finish()
}

impl Merge<'_> {
    #[inline]
    fn p(&self, v: u32) -> Point {
        self.points[v as usize]
    }

    /// Whether `h` is a half-edge of a part's triangle that is still alive.
    fn alive(&self, h: u32) -> bool {
        h != EMPTY && !self.dead.get(h / 3)
    }

    /// The hull half-edge into the origin of hull half-edge `h`.
    fn hull_in(&self, h: u32) -> u32 {
        let mut i = prev(h);
        while self.twin[i as usize] != EMPTY {
            i = prev(self.twin[i as usize]);
        }
        i
    }

    /// The hull half-edge out of the origin of `o`, found by rotating clockwise from `o`.
    fn hull_out_from(&self, mut o: u32) -> u32 {
        while self.twin[o as usize] != EMPTY {
            o = next(self.twin[o as usize]);
        }
        o
    }

    /// The next edge counter-clockwise around `apex` after `e`, over the parts' triangles.
    fn ccw_step(&self, e: Entry) -> Entry {
        if e.out == EMPTY {
            // Past the outside of the hull, to the apex's hull out-edge.
            let o = self.hull_out_from(next(e.inn));
            return Entry { nbr: self.tri[next(o) as usize], out: o, inn: EMPTY };
        }
        let p = prev(e.out);
        Entry { nbr: self.tri[p as usize], out: self.twin[p as usize], inn: p }
    }

    /// The next edge clockwise around `apex` after `e`.
    fn cw_step(&self, e: Entry) -> Entry {
        if e.inn == EMPTY {
            let i = self.hull_in(e.out);
            return Entry { nbr: self.tri[i as usize], out: EMPTY, inn: i };
        }
        let n = next(e.inn);
        Entry { nbr: self.tri[next(n) as usize], out: n, inn: self.twin[n as usize] }
    }

    fn is_gone(&self, e: Entry) -> bool {
        self.gone.get(if e.out == EMPTY { e.inn } else { e.out })
    }

    /// The first edge counter-clockwise after `e` around `apex` that was not deleted;
    /// `None` if the rotation comes round without one (a broken walk).
    fn ccw_surviving(&self, apex: u32, mut e: Entry) -> Option<Entry> {
        for _ in 0..self.original {
            e = self.ccw_step(e);
            if !self.is_gone(e) {
                debug_assert_eq!(
                    self.tri[(if e.out == EMPTY { next(e.inn) } else { e.out }) as usize],
                    apex
                );
                return Some(e);
            }
        }
        None
    }

    fn cw_surviving(&self, apex: u32, mut e: Entry) -> Option<Entry> {
        for _ in 0..self.original {
            e = self.cw_step(e);
            if !self.is_gone(e) {
                debug_assert_eq!(
                    self.tri[(if e.inn == EMPTY { e.out } else { next(e.inn) }) as usize],
                    apex
                );
                return Some(e);
            }
        }
        None
    }

    /// The vertex whose circle test decides the left candidate `e`: the third corner of
    /// the triangle counter-clockwise beyond it, or, where that triangle died, the next
    /// surviving neighbour (quad-edge `Onext`); `None` where the next edge around is past
    /// the hull's outside or in a new triangle (the base side: nothing to test).
    fn left_beyond(&self, e: Entry) -> Option<u32> {
        let mut f = e;
        for _ in 0..self.original {
            if f.out == EMPTY || self.covered.get(f.out) {
                return None;
            }
            if !self.dead.get(f.out / 3) {
                return Some(self.tri[prev(f.out) as usize]);
            }
            f = self.ccw_step(f);
            if !self.is_gone(f) {
                return Some(f.nbr);
            }
        }
        None
    }

    /// [`left_beyond`](Self::left_beyond) mirrored for the right candidate.
    fn right_beyond(&self, e: Entry) -> Option<u32> {
        let mut f = e;
        for _ in 0..self.original {
            if f.inn == EMPTY || self.covered.get(f.inn) {
                return None;
            }
            if !self.dead.get(f.inn / 3) {
                return Some(self.tri[prev(f.inn) as usize]);
            }
            f = self.cw_step(f);
            if !self.is_gone(f) {
                return Some(f.nbr);
            }
        }
        None
    }

    /// Deletes the edge of half-edge `h`: the triangle of `h` dies.
    fn delete(&mut self, h: u32) {
        self.dead.set(h / 3, true);
        self.gone.set(h, true);
        let t = self.twin[h as usize];
        if t != EMPTY {
            self.gone.set(t, true);
        }
    }

    /// Appends the triangle `corners` (counter-clockwise, the first edge the base) with its
    /// base twinned to `below`; returns its first slot.
    fn add(&mut self, corners: [u32; 3], below: u32) -> u32 {
        let s = self.tri.len() as u32;
        self.tri.extend_from_slice(&corners);
        self.twin.extend_from_slice(&[below, EMPTY, EMPTY]);
        if below != EMPTY {
            self.twin[below as usize] = s;
        }
        s
    }

    /// Records new half-edge `s` along the parts' edge whose half-edges are `h` (the same
    /// direction's twin: its triangle lies beyond the edge from the new one) and `beside`
    /// (the other direction, on the new triangle's side, now covered by it). `s` is
    /// twinned with `h` when `h`'s triangle is alive; otherwise it waits for the new
    /// triangle on the edge's other side.
    fn attach(&mut self, s: u32, h: u32, beside: u32) {
        if beside != EMPTY {
            self.covered.set(beside, true);
        }
        match self.alive(h) {
            true => self.links.push((s, h)),
            false => self.pending.push(s),
        }
    }

    /// Twins the half-edges left pending, checks that no live triangle still faces a dead
    /// one, and moves the last triangles into the dead ones' places.
    fn finish(mut self) -> Option<Part> {
        // A link to a triangle that died after it was made (the edge's other side was
        // cleared later) waits like a bare edge.
        for (s, h) in std::mem::take(&mut self.links) {
            match self.dead.get(h / 3) {
                true => self.pending.push(s),
                false => {
                    self.twin[s as usize] = h;
                    self.twin[h as usize] = s;
                }
            }
        }
        let mut waiting: HashMap<[u32; 2], u32> = HashMap::with_capacity(self.pending.len());
        for &s in &self.pending {
            let (a, b) = (self.tri[s as usize], self.tri[next(s) as usize]);
            match waiting.remove(&[b, a]) {
                Some(t) => {
                    self.twin[s as usize] = t;
                    self.twin[t as usize] = s;
                }
                None => {
                    waiting.insert([a, b], s);
                }
            }
        }
        for t in 0..self.original / 3 {
            if !self.dead.get(t) {
                continue;
            }
            for s in 3 * t..3 * t + 3 {
                let o = self.twin[s as usize];
                if o != EMPTY
                    && self.twin[o as usize] == s
                    && (o >= self.original || !self.dead.get(o / 3))
                {
                    return None; // a live triangle would face a dead one
                }
            }
        }
        // Fill each dead triangle with the last live one.
        let mut count = self.tri.len() as u32 / 3;
        let dead: Vec<u32> = (0..self.original / 3).filter(|&t| self.dead.get(t)).collect();
        let is_dead = |m: &Self, t: u32| t < m.original / 3 && m.dead.get(t);
        for &hole in dead.iter().rev() {
            // Drop dead triangles at the end first.
            while count > 0 && is_dead(&self, count - 1) {
                count -= 1;
            }
            if hole >= count {
                continue;
            }
            let last = count - 1;
            for i in 0..3 {
                let (from, to) = ((3 * last + i) as usize, (3 * hole + i) as usize);
                self.tri[to] = self.tri[from];
                let t = self.twin[from];
                self.twin[to] = t;
                if t != EMPTY {
                    self.twin[t as usize] = to as u32;
                }
            }
            self.dead.set(hole, false);
            count -= 1;
        }
        self.tri.truncate(3 * count as usize);
        self.twin.truncate(3 * count as usize);
        Some(Part { triangles: self.tri, halfedges: self.twin })
    }
}

/// A fixed number of bits, false at first: an eighth of the memory of `Vec<bool>` for the
/// merge's marks on every half-edge of the parts.
struct Bits(Vec<u64>);

impl Bits {
    fn new(len: u32) -> Bits {
        Bits(vec![0; (len as usize).div_ceil(64)])
    }

    #[inline]
    fn get(&self, i: u32) -> bool {
        crate::bits::word_bit(&self.0, i)
    }

    #[inline]
    fn set(&mut self, i: u32, value: bool) {
        let (word, bit) = ((i / 64) as usize, i % 64);
        match value {
            true => self.0[word] |= 1 << bit,
            false => self.0[word] &= !(1 << bit),
        }
    }
}
