//! FITCONNECT's sharp-corner rule: a non-conforming point where exactly two open chains
//! end inside its neighbourhood disc, meeting it at an angle of at most 60°, becomes the
//! corner that joins them.
use std::collections::{BTreeSet, VecDeque};

use super::state::{Points, State, NONE};
use crate::geometry::{orient2d, Point};

/// The largest angle at the corner between the directions to where the two chains leave
/// the neighbourhood disc (\[OW18\]; the same bound as the sampling condition's).
const MAX_CORNER_DEGREES: f64 = 60.0;

/// A neighbourhood as a sorted list, for membership tests.
pub(crate) struct Near(Vec<u32>);

impl Near {
    fn contains(&self, q: &u32) -> bool {
        self.0.binary_search(q).is_ok()
    }

    fn iter(&self) -> std::slice::Iter<'_, u32> {
        self.0.iter()
    }

    fn len(&self) -> usize {
        self.0.len()
    }
}

/// A chain of linked points inside the neighbourhood of `p` that leaves it at one end: the
/// inner end first, the last point inside before it leaves last.
pub(crate) type Chain = VecDeque<u32>;

impl Points<'_> {
    /// The chains through manifold points of `p`'s neighbourhood: `None` if one of them
    /// passes right through (leaves the disc at both ends), else those that leave at one end.
    pub(crate) fn open_chains(&self, p: u32, near: &Near) -> Option<Vec<Chain>> {
        let mut manifold: BTreeSet<u32> =
            near.iter().copied().filter(|&q| self.is(q, State::Manifold)).collect();
        let mut chains = Vec::new();
        while let Some(start) = manifold.pop_first() {
            let mut chain = VecDeque::from([start]);
            let mut leaves = [false; 2];
            for (direction, leaves) in leaves.iter_mut().enumerate() {
                let (mut prev, mut at) = (start, self.links[start as usize][direction]);
                // The guard bounds a walk that a broken link could send round a cycle.
                let mut steps = 0;
                while at != NONE && at != start && near.contains(&at) && steps <= near.len() {
                    if direction == 0 {
                        chain.push_back(at);
                    } else {
                        chain.push_front(at);
                    }
                    manifold.remove(&at);
                    let next = self.beyond(at, prev);
                    prev = at;
                    at = next;
                    steps += 1;
                }
                *leaves = at != NONE && at != p && at != start && !near.contains(&at);
            }
            match leaves {
                [true, true] => return None,
                [true, false] => chains.push(chain),
                [false, true] => chains.push(chain.into_iter().rev().collect()),
                [false, false] => {}
            }
        }
        Some(chains)
    }

    /// Whether `p` is the corner of the two open chains `chains`: where their last edges
    /// leave the disc around `p` through its farthest neighbour, the two exits are at most
    /// 60° apart seen from `p`, and the new edges from `p` to the chains' inner ends cross
    /// (or touch) no link between curve or conforming points of the neighbourhood.
    pub(crate) fn is_corner(&self, p: u32, chains: &[Chain], near: &Near) -> bool {
        let c = self.xy[p as usize];
        let radius = near
            .iter()
            .map(|&q| crate::geometry::distance(c, self.xy[q as usize]))
            .fold(0.0, f64::max);
        let mut exits = [0.0f64; 2];
        for (exit, chain) in exits.iter_mut().zip(chains) {
            let inside = *chain.back().expect("chains are not empty");
            let l = self.links[inside as usize];
            let outside =
                if l[0] != NONE && l[0] != p && !near.contains(&l[0]) { l[0] } else { l[1] };
            if outside == NONE {
                return false;
            }
            let x = leave_disc(c, radius, self.xy[inside as usize], self.xy[outside as usize]);
            *exit = (x[1] - c[1]).atan2(x[0] - c[0]).to_degrees();
        }
        let mut apart = (exits[0] - exits[1]).abs();
        if apart > 180.0 {
            apart = 360.0 - apart;
        }
        if apart > MAX_CORNER_DEGREES {
            return false;
        }
        let live = |q: u32| {
            matches!(self.state[q as usize], State::Manifold | State::Conform | State::Leaf)
        };
        let mut links = Vec::new();
        for &a in near.iter().chain(std::iter::once(&p)) {
            for b in self.links[a as usize] {
                if b != NONE && live(a) && live(b) {
                    links.push([a.min(b), a.max(b)]);
                }
            }
        }
        links.sort_unstable();
        links.dedup();
        chains.iter().all(|chain| {
            let end = chain[0];
            links.iter().all(|&[a, b]| {
                a == end
                    || b == end
                    || !segments_meet(
                        c,
                        self.xy[end as usize],
                        self.xy[a as usize],
                        self.xy[b as usize],
                    )
            })
        })
    }

    /// `p`'s neighbours on both sides.
    pub(crate) fn neighbourhood(&self, p: u32) -> Near {
        Near(self.sides[p as usize].sorted().collect())
    }
}

/// Where the segment from `inside` (within the disc) to `outside` (not within it) crosses
/// the circle of `radius` around `c`.
fn leave_disc(c: Point, radius: f64, inside: Point, outside: Point) -> Point {
    let v = [outside[0] - inside[0], outside[1] - inside[1]];
    let w = [inside[0] - c[0], inside[1] - c[1]];
    let a = v[0] * v[0] + v[1] * v[1];
    let b = 2.0 * (v[0] * w[0] + v[1] * w[1]);
    let cc = w[0] * w[0] + w[1] * w[1] - radius * radius;
    let root = (b * b - 4.0 * a * cc).max(0.0).sqrt();
    let t = ((-b + root) / (2.0 * a)).clamp(0.0, 1.0);
    [inside[0] + t * v[0], inside[1] + t * v[1]]
}

/// Whether the closed segments `ab` and `cd` share a point (exact).
fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (d1, d2) = (orient2d(a, b, c), orient2d(a, b, d));
    let (d3, d4) = (orient2d(c, d, a), orient2d(c, d, b));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return true;
    }
    let on = |p: Point, q: Point, r: Point, o: f64| {
        o == 0.0
            && r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    on(a, b, c, d1) || on(a, b, d, d2) || on(c, d, a, d3) || on(c, d, b, d4)
}
