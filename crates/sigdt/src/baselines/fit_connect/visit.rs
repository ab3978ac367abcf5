//! One visit of an unhandled point: grow and refit its neighbourhood, then apply
//! FITCONNECT's rules in the authors' program's order (steps 1–8 below).
use std::collections::BTreeSet;

use super::fit::fit_and_order;
use super::state::{Points, Sides, State, NONE};

impl Points<'_> {
    /// Visits `p` (an unhandled point).
    pub(crate) fn visit(&mut self, p: u32) {
        let pi = p as usize;
        let old_state = self.state[pi];
        let old_fit = self.fits[pi];
        let old_sides = self.sides[pi].clone();
        let mut affected = BTreeSet::new();

        // 1. Leaf pre-check: a conforming point with one link whose chain continues through
        //    two manifold points of the same side.
        let leaf_side = self.leaf_candidate(p);

        // 2. Grow and refit.
        if !self.grow(p) {
            self.exhausted(p, &mut affected);
        } else if let Some(side) = leaf_side {
            // 3. Growing broke the chain's consistency and the other side is empty: keep
            //    the previous fit and end the curve here.
            if self.has_stray_curve_point(p, side) && self.sides[pi][1 - side].is_empty() {
                self.fits[pi] = old_fit;
                self.sides[pi] = old_sides.clone();
                self.set_state(p, State::Leaf);
                affected.insert(p);
                self.align_links(p);
            }
        }

        // 4. Links of a conforming point.
        if self.is(p, State::Conform) {
            self.link_overlaps(p, &mut affected);
        }

        // 5. A point between two linked points of its two sides is inside an edge.
        if matches!(self.state[pi], State::Conform | State::NonConform) && self.is_inside_edge(p) {
            if self.is(p, State::NonConform) && old_state == State::Conform {
                self.state[pi] = State::Conform;
            }
            self.remove_links(p, &mut affected);
            self.set_state(p, State::Eliminated);
            affected.insert(p);
        }

        // 6. Sharp corner.
        if self.is(p, State::NonConform) {
            let near = self.neighbourhood(p);
            if let Some(chains) = self.open_chains(p, &near) {
                if chains.len() == 2 && self.is_corner(p, &chains, &near) {
                    if old_state == State::Conform {
                        self.state[pi] = State::Conform;
                        self.remove_links(p, &mut affected);
                    }
                    self.set_state(p, State::Sharp);
                    affected.insert(p);
                    for (slot, chain) in chains.iter().enumerate() {
                        let end = chain[0];
                        if !self.is(end, State::Manifold) {
                            self.set_state(end, State::Manifold);
                            affected.insert(end);
                            let free = if self.links[end as usize][0] == NONE { 0 } else { 1 };
                            self.links[end as usize][free] = p;
                        }
                        self.links[pi][slot] = end;
                    }
                }
            }
        }

        // 7. Consistency propagation from every point whose state changed.
        self.propagate(&mut affected);

        // 8. Revert: a conforming point that stopped conforming and became nothing else keeps
        //    its previous fit (its neighbourhood keeps growing, so exhaustion decides it).
        if self.is(p, State::NonConform) && old_state == State::Conform {
            self.fits[pi] = old_fit;
            self.sides[pi] = old_sides;
            self.set_state(p, State::Conform);
        }
    }

    /// Step 1: the side of `p`'s only link if the chain beyond it runs through two more
    /// manifold points inside that side.
    fn leaf_candidate(&self, p: u32) -> Option<usize> {
        if !self.is(p, State::Conform) || self.link_count(p) != 1 {
            return None;
        }
        let side = if self.links[p as usize][0] != NONE { 0 } else { 1 };
        let (mut prev, mut at) = (p, self.links[p as usize][side]);
        for _ in 0..2 {
            let next = self.beyond(at, prev);
            if next == NONE || !self.is(next, State::Manifold) || !self.in_side(p, side, next) {
                return None;
            }
            prev = at;
            at = next;
        }
        Some(side)
    }

    /// Adds the next nearest neighbour to `K(p)` (the two nearest on the first visit) and
    /// refits. False, with nothing changed, once `K(p)` holds every other point.
    fn grow(&mut self, p: u32) -> bool {
        let pi = p as usize;
        let wanted = if self.is(p, State::Initial) { 2 } else { 1 };
        if self.knn[pi].len() + wanted >= self.xy.len() {
            return false;
        }
        for _ in 0..wanted {
            let Some(q) = self.nearest.next(self.vertex[pi]) else {
                return false;
            };
            let q = self.rank[q as usize];
            self.knn[pi].push(q);
            self.refs[q as usize].push(p);
        }
        if self.knn[pi].len() + 1 == self.xy.len() {
            // Every point is in: the walk is no longer needed.
            self.nearest.forget(self.vertex[pi]);
        }
        let (fit, sides, conforms) = fit_and_order(&self.xy, p, &self.knn[pi], |r| r as usize);
        self.work += self.knn[pi].len();
        self.fits[pi] = fit;
        self.sides[pi] = Sides::new(sides);
        self.state[pi] = if conforms { State::Conform } else { State::NonConform };
        true
    }

    /// Step 2 when the neighbourhood cannot grow: a conforming point with a link ends its
    /// curve (or hands the end to the one non-conforming point on its open side); a
    /// non-conforming point with one empty side becomes the end of a curve whose conforming
    /// end is its nearest point there; anything else is eliminated.
    fn exhausted(&mut self, p: u32, affected: &mut BTreeSet<u32>) {
        let pi = p as usize;
        if self.is(p, State::Conform) && self.link_count(p) > 0 {
            let side = if self.links[pi][0] != NONE { 0 } else { 1 };
            let lone: Vec<u32> = self.sides[pi][1 - side]
                .iter()
                .copied()
                .filter(|&q| self.is(q, State::NonConform))
                .collect();
            if let [q] = lone[..] {
                self.links[pi][1 - side] = q;
                let q_side = if self.in_side(q, 0, p) { 0 } else { 1 };
                self.links[q as usize][q_side] = p;
                self.set_state(q, State::Leaf);
                self.set_state(p, State::Manifold);
                affected.extend([q, p]);
            } else {
                self.set_state(p, State::Leaf);
                affected.insert(p);
            }
            return;
        }
        let one_sided = self.sides[pi][0].is_empty() != self.sides[pi][1].is_empty();
        if self.is(p, State::NonConform) && one_sided {
            let side = if self.sides[pi][0].is_empty() { 1 } else { 0 };
            let first =
                self.sides[pi][side].iter().copied().find(|&q| !self.is(q, State::Eliminated));
            if let Some(q) = first {
                if self.is(q, State::Conform) && self.link_count(q) == 1 {
                    let free = if self.links[q as usize][0] == NONE { 0 } else { 1 };
                    self.links[q as usize][free] = p;
                    self.links[pi][side] = q;
                    self.set_state(q, State::Manifold);
                    self.set_state(p, State::Leaf);
                    affected.extend([q, p]);
                    return;
                }
            }
        }
        self.set_state(p, State::Eliminated);
    }

    /// Step 4: link `p` to its overlaps, then thin the points its links make redundant,
    /// demote inconsistent curve points, and drop `p` if one point blocks its second link.
    fn link_overlaps(&mut self, p: u32, affected: &mut BTreeSet<u32>) {
        let pi = p as usize;
        let overlaps = [self.overlap(p, 0), self.overlap(p, 1)];
        for side in 0..2 {
            let q = self.links[pi][side];
            if q != NONE && !overlaps.contains(&Some(q)) {
                self.remove_link(p, side, affected);
            }
        }
        for q in overlaps.into_iter().flatten() {
            if self.links[pi].contains(&q) {
                continue;
            }
            let Some(slot) = (0..2).find(|&s| self.links[pi][s] == NONE) else {
                continue;
            };
            self.links[pi][slot] = q;
            let q_side = if self.in_side(q, 0, p) { 0 } else { 1 };
            self.links[q as usize][q_side] = p;
            if self.links[pi][1 - slot] != NONE {
                self.set_state(p, State::Manifold);
                affected.insert(p);
            }
            if self.links[q as usize][1 - q_side] != NONE {
                self.set_state(q, State::Manifold);
                affected.insert(q);
            }
        }
        self.align_links(p);

        // Redundant points: unhandled points between `p` and a partner in both their
        // neighbourhoods.
        for side in 0..2 {
            let q = self.links[pi][side];
            if q == NONE {
                continue;
            }
            let Some(q_side) = (0..2).find(|&s| self.links[q as usize][s] == p) else {
                continue;
            };
            let before = |a: u32, s: usize, b: u32| -> Option<BTreeSet<u32>> {
                let list = &self.sides[a as usize][s];
                let at = list.iter().position(|&x| x == b)?;
                Some(list[..at].iter().copied().filter(|x| self.unhandled.contains(x)).collect())
            };
            let (Some(mine), Some(theirs)) = (before(p, side, q), before(q, q_side, p)) else {
                continue;
            };
            for r in mine.intersection(&theirs).copied().collect::<Vec<_>>() {
                if matches!(self.state[r as usize], State::Manifold | State::Conform | State::Sharp)
                {
                    self.remove_links(r, affected);
                }
                self.set_state(r, State::Eliminated);
            }
        }

        // Inconsistent points, on `p`'s sides and its partners'.
        for side in 0..2 {
            if self.links[pi][side] == NONE {
                continue;
            }
            self.demote_strays(p, side, affected);
            let q = self.links[pi][side];
            if q != NONE {
                let q_side = if self.links[q as usize][0] == p { 0 } else { 1 };
                self.demote_strays(q, q_side, affected);
            }
        }

        // One-point obstacle: between `p` and its only partner lies a conforming point with
        // one link, to a point on `p`'s other side.
        if self.link_count(p) == 1 {
            let side = if self.links[pi][0] != NONE { 0 } else { 1 };
            let partner = self.links[pi][side];
            let blocker = self.sides[pi][side]
                .iter()
                .copied()
                .find(|&r| r == partner || self.is(r, State::Conform));
            if let Some(r) = blocker.filter(|&r| r != partner) {
                if self.link_count(r) == 1 {
                    let l = self.links[r as usize];
                    let other = if l[0] != NONE { l[0] } else { l[1] };
                    if self.in_side(p, 1 - side, other) {
                        self.remove_link(p, side, affected);
                        self.set_state(p, State::Eliminated);
                    }
                }
            }
        }
    }

    /// Step 5: whether `p` (with no manifold partner) lies between a manifold or sharp point
    /// of each side that are linked to each other, with only eliminated or unvisited points
    /// closer to `p` on both sides. Those two points can only be the first point of each
    /// side that is neither eliminated nor unvisited, so one scan of each side finds them.
    fn is_inside_edge(&self, p: u32) -> bool {
        let pi = p as usize;
        if self.links[pi].iter().any(|&q| q != NONE && self.is(q, State::Manifold)) {
            return false;
        }
        let first_solid = |s: usize| {
            let first = self.sides[pi][s]
                .iter()
                .copied()
                .find(|&x| !matches!(self.state[x as usize], State::Eliminated | State::Initial))?;
            matches!(self.state[first as usize], State::Manifold | State::Sharp).then_some(first)
        };
        match (first_solid(0), first_solid(1)) {
            (Some(a), Some(b)) => self.links[a as usize].contains(&b),
            _ => false,
        }
    }

    /// Step 7: re-checks the linked points whose neighbourhoods hold an affected point; any
    /// inconsistency (a sharp point without two manifold partners, a link outside its side,
    /// a side whose curve points are not all on the chain of its link) removes that point's
    /// links, which may affect more points.
    fn propagate(&mut self, affected: &mut BTreeSet<u32>) {
        while let Some(q) = affected.pop_first() {
            let referrers: BTreeSet<u32> = self.refs[q as usize].iter().copied().collect();
            for n in referrers {
                if self.link_count(n) > 0 && !self.is_consistent(n) {
                    self.remove_links(n, affected);
                }
            }
        }
    }

    fn is_consistent(&self, n: u32) -> bool {
        let l = self.links[n as usize];
        if self.is(n, State::Sharp) {
            return l.iter().all(|&m| m != NONE && self.is(m, State::Manifold));
        }
        (0..2).all(|side| {
            let m = l[side];
            m == NONE
                || self.is(m, State::Sharp)
                || (self.in_side(n, side, m) && !self.has_stray_curve_point(n, side))
        })
    }
}
