//! FITCONNECT's per-point state and the bookkeeping of links: every change of state and
//! every link removal goes through here, so that the set of unhandled points and the
//! mutual links stay consistent.
use std::collections::BTreeSet;

use super::fit::Fit;
use super::nearest::Nearest;
use crate::delaunay::Triangulation;
use crate::geometry::Point;

/// No link.
pub(crate) const NONE: u32 = u32::MAX;

/// The state of a point (\[OW18\] §4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum State {
    /// Not visited yet.
    Initial,
    /// Its fitted neighbourhood has the point between its extreme neighbours.
    Conform,
    /// Its fitted neighbourhood does not.
    NonConform,
    /// Two links: inside a curve.
    Manifold,
    /// One link: the end of an open curve.
    Leaf,
    /// Two links that meet at a corner of at most 60°.
    Sharp,
    /// Dropped: redundant between linked points, inside an edge, a one-point obstacle, or
    /// its neighbourhood was exhausted without a link.
    Eliminated,
}

impl State {
    /// Initial, Conform and NonConform points are still to be decided.
    pub(crate) fn is_unhandled(self) -> bool {
        matches!(self, State::Initial | State::Conform | State::NonConform)
    }

    /// Points that may take part in an overlap (a link) from a conforming neighbour.
    pub(crate) fn can_overlap(self) -> bool {
        matches!(self, State::Conform | State::Leaf | State::Manifold)
    }

    /// Points on the output curves.
    pub(crate) fn is_curve(self) -> bool {
        matches!(self, State::Manifold | State::Leaf | State::Sharp)
    }
}

/// The neighbours on the two sides of a point along its fit, each outward from the point,
/// with a sorted lookup from neighbour to side.
#[derive(Debug, Clone, Default)]
pub(crate) struct Sides {
    lists: [Vec<u32>; 2],
    lookup: Vec<(u32, u8)>,
}

impl Sides {
    pub(crate) fn new(lists: [Vec<u32>; 2]) -> Self {
        let mut lookup: Vec<(u32, u8)> =
            lists[0].iter().map(|&q| (q, 0)).chain(lists[1].iter().map(|&q| (q, 1))).collect();
        lookup.sort_unstable();
        Sides { lists, lookup }
    }

    /// The side holding `q`, in O(log k).
    pub(crate) fn side_of(&self, q: u32) -> Option<usize> {
        let at = self.lookup.binary_search_by_key(&q, |e| e.0).ok()?;
        Some(self.lookup[at].1 as usize)
    }

    /// Every neighbour, sorted.
    pub(crate) fn sorted(&self) -> impl Iterator<Item = u32> + '_ {
        self.lookup.iter().map(|e| e.0)
    }
}

impl std::ops::Index<usize> for Sides {
    type Output = Vec<u32>;

    fn index(&self, side: usize) -> &Vec<u32> {
        &self.lists[side]
    }
}

/// Everything FITCONNECT knows, indexed by *rank*: the distinct points numbered in input
/// order, so that passes, and every ordered set, go in input order as in the authors'
/// program.
pub(crate) struct Points<'a> {
    /// The Delaunay vertex of each rank.
    pub vertex: Vec<u32>,
    /// The rank of each Delaunay vertex.
    pub rank: Vec<u32>,
    /// The points' coordinates (scaled, as in the triangulation).
    pub xy: Vec<Point>,
    pub state: Vec<State>,
    /// `K(p)`: the neighbours fitted so far, nearest first.
    pub knn: Vec<Vec<u32>>,
    /// The neighbours on the two sides of `p` along its fit, each outward from `p`.
    pub sides: Vec<Sides>,
    pub fits: Vec<Fit>,
    /// `links[p][s]`: the partner on side `s`, or [`NONE`].
    pub links: Vec<[u32; 2]>,
    /// `refs[q]`: the points whose `K` holds `q`.
    pub refs: Vec<Vec<u32>>,
    pub unhandled: BTreeSet<u32>,
    pub nearest: Nearest<'a>,
    /// Neighbours fitted, summed over the fits: the run's work.
    pub work: usize,
}

impl<'a> Points<'a> {
    pub(crate) fn new(dt: &'a Triangulation) -> Self {
        let n = dt.num_vertices();
        let mut vertex: Vec<u32> = (0..n as u32).collect();
        vertex.sort_unstable_by_key(|&v| dt.input_index(v));
        let mut rank = vec![0u32; n];
        for (r, &v) in vertex.iter().enumerate() {
            rank[v as usize] = r as u32;
        }
        Points {
            xy: vertex.iter().map(|&v| dt.point(v)).collect(),
            vertex,
            rank,
            state: vec![State::Initial; n],
            knn: vec![Vec::new(); n],
            sides: vec![Sides::default(); n],
            fits: vec![Fit::default(); n],
            links: vec![[NONE; 2]; n],
            refs: vec![Vec::new(); n],
            unhandled: (0..n as u32).collect(),
            nearest: Nearest::new(dt),
            work: 0,
        }
    }

    pub(crate) fn is(&self, p: u32, state: State) -> bool {
        self.state[p as usize] == state
    }

    /// Sets the state of `p`, moving it in or out of the unhandled set.
    pub(crate) fn set_state(&mut self, p: u32, state: State) {
        self.state[p as usize] = state;
        if state.is_unhandled() {
            self.unhandled.insert(p);
        } else {
            self.unhandled.remove(&p);
        }
    }

    pub(crate) fn link_count(&self, p: u32) -> usize {
        self.links[p as usize].iter().filter(|&&q| q != NONE).count()
    }

    /// The side of `p`'s neighbourhood that holds `q`.
    pub(crate) fn side_of(&self, p: u32, q: u32) -> Option<usize> {
        self.sides[p as usize].side_of(q)
    }

    pub(crate) fn in_side(&self, p: u32, side: usize, q: u32) -> bool {
        self.side_of(p, q) == Some(side)
    }

    /// The slot of `q`'s links that holds `p`.
    fn slot_holding(&self, q: u32, p: u32) -> Option<usize> {
        (0..2).find(|&s| self.links[q as usize][s] == p)
    }

    /// The link of `q` other than the one to `from` (the next point along a chain).
    pub(crate) fn beyond(&self, q: u32, from: u32) -> u32 {
        let l = self.links[q as usize];
        if l[0] == from {
            l[1]
        } else {
            l[0]
        }
    }

    /// Removes `p`'s link on `side` from both ends and demotes the partner: a manifold point
    /// or leaf to conforming, a sharp point to non-conforming along with its other link.
    fn unlink(&mut self, p: u32, side: usize) {
        let q = self.links[p as usize][side];
        if q == NONE {
            return;
        }
        self.links[p as usize][side] = NONE;
        let q_slot = self.slot_holding(q, p);
        if let Some(s) = q_slot {
            self.links[q as usize][s] = NONE;
        }
        match self.state[q as usize] {
            State::Manifold | State::Leaf => self.set_state(q, State::Conform),
            State::Sharp => {
                self.set_state(q, State::NonConform);
                let other = q_slot.map_or(NONE, |s| self.links[q as usize][1 - s]);
                if other != NONE {
                    self.links[q as usize][1 - q_slot.unwrap_or(0)] = NONE;
                    if let Some(s) = self.slot_holding(other, q) {
                        self.links[other as usize][s] = NONE;
                    }
                    if self.is(other, State::Manifold) {
                        self.set_state(other, State::Conform);
                    }
                }
            }
            _ => {}
        }
    }

    /// Removes one link of `p`; `p` itself, if manifold, becomes conforming.
    pub(crate) fn remove_link(&mut self, p: u32, side: usize, affected: &mut BTreeSet<u32>) {
        self.unlink(p, side);
        affected.insert(p);
        if self.is(p, State::Manifold) {
            self.set_state(p, State::Conform);
        }
    }

    /// Removes both links of `p`; `p` goes back to conforming (from manifold or leaf) or
    /// non-conforming (from sharp).
    pub(crate) fn remove_links(&mut self, p: u32, affected: &mut BTreeSet<u32>) {
        for side in 0..2 {
            self.unlink(p, side);
        }
        affected.insert(p);
        match self.state[p as usize] {
            State::Manifold | State::Leaf => self.set_state(p, State::Conform),
            State::Sharp => self.set_state(p, State::NonConform),
            _ => {}
        }
    }

    /// The points reached from `p` by following its link on `side` and the chain beyond it,
    /// while the chain stays inside that side of `p`'s neighbourhood.
    pub(crate) fn followable(&self, p: u32, side: usize) -> BTreeSet<u32> {
        let mut chain = BTreeSet::new();
        let (mut prev, mut at) = (p, self.links[p as usize][side]);
        while at != NONE && at != p && self.in_side(p, side, at) && chain.insert(at) {
            let next = self.beyond(at, prev);
            prev = at;
            at = next;
        }
        chain
    }

    /// Whether a curve point of `p`'s `side` is off the chain followed from its link there
    /// (the link is then inconsistent with the neighbourhood).
    pub(crate) fn has_stray_curve_point(&self, p: u32, side: usize) -> bool {
        let chain = self.followable(p, side);
        self.sides[p as usize][side]
            .iter()
            .any(|q| !chain.contains(q) && self.state[*q as usize].is_curve())
    }

    /// Demotes every curve point of `p`'s `side` that is off the chain followed from `p`'s
    /// link there, removing its links.
    pub(crate) fn demote_strays(&mut self, p: u32, side: usize, affected: &mut BTreeSet<u32>) {
        let chain = self.followable(p, side);
        let strays: Vec<u32> =
            self.sides[p as usize][side].iter().copied().filter(|q| !chain.contains(q)).collect();
        for q in strays {
            if self.state[q as usize].is_curve() {
                self.remove_links(q, affected);
            }
        }
    }

    /// The overlap of `p` on `side`: scanning from the outermost neighbour inward, the first
    /// point that can overlap, whose own neighbourhood holds `p`, and that is free for `p`
    /// (a manifold point already linked to `p`; otherwise its link slot on `p`'s side empty
    /// or already `p`).
    pub(crate) fn overlap(&self, p: u32, side: usize) -> Option<u32> {
        self.sides[p as usize][side].iter().rev().copied().find(|&q| {
            let qs = q as usize;
            self.state[qs].can_overlap()
                && self.side_of(q, p).is_some_and(|s| {
                    if self.state[qs] == State::Manifold {
                        self.links[qs].contains(&p)
                    } else {
                        self.links[qs][s] == NONE || self.links[qs][s] == p
                    }
                })
        })
    }

    /// Swaps `p`'s link slots if a link is not in the side of the same number.
    pub(crate) fn align_links(&mut self, p: u32) {
        let l = self.links[p as usize];
        let misplaced = (0..2).any(|s| l[s] != NONE && !self.in_side(p, s, l[s]));
        if misplaced {
            self.links[p as usize].swap(0, 1);
        }
    }
}
