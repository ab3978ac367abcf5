//! DISCUR's two passes over the Delaunay edges (`docs/algorithms.md` §3.9, steps 1–3).
use super::curve::Curve;
use super::Variant;
use crate::delaunay::{Triangulation, EMPTY};
use crate::geometry::squared_distance;
use crate::graph::UnionFind;

/// Where a candidate edge stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum State {
    Unprocessed,
    Removed,
    Deferred,
    Connected,
}

/// One Delaunay edge: its length and its two vertices, the lower input index first.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    length: f64,
    ends: [u32; 2],
}

/// The state of one run.
pub(super) struct Growth<'a> {
    dt: &'a Triangulation,
    variant: Variant,
    /// The Delaunay edges, shortest first.
    candidates: Vec<Candidate>,
    /// The candidate of every half-edge.
    candidate_of: Vec<u32>,
    state: Vec<State>,
    /// Curve degree per vertex.
    degree: Vec<u8>,
    /// Pass-1 edges processed per vertex (for `Variant::two_processed`).
    processed: Vec<u8>,
    /// The length of an end's curve edge.
    end_length: Vec<f64>,
    sets: UnionFind,
    /// The curve of each set, at its representative.
    curves: Vec<Curve>,
}

impl<'a> Growth<'a> {
    pub(super) fn new(dt: &'a Triangulation, variant: Variant) -> Growth<'a> {
        let n = dt.num_vertices();
        let mut keyed: Vec<(f64, [usize; 2], u32)> = dt
            .edge_halfedges()
            .map(|h| {
                let (a, b) = (dt.origin(h), dt.dest(h));
                let (i, j) = (dt.input_index(a), dt.input_index(b));
                (squared_distance(dt.point(a), dt.point(b)), [i.min(j), i.max(j)], h)
            })
            .collect();
        keyed.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        let mut candidate_of = vec![u32::MAX; dt.num_halfedges()];
        let candidates = keyed
            .iter()
            .enumerate()
            .map(|(k, &(squared, _, h))| {
                candidate_of[h as usize] = k as u32;
                if dt.twin(h) != EMPTY {
                    candidate_of[dt.twin(h) as usize] = k as u32;
                }
                let (a, b) = (dt.origin(h), dt.dest(h));
                let ends = if dt.input_index(a) < dt.input_index(b) { [a, b] } else { [b, a] };
                Candidate { length: squared.sqrt(), ends }
            })
            .collect();
        Growth {
            dt,
            variant,
            candidates,
            candidate_of,
            state: vec![State::Unprocessed; keyed.len()],
            degree: vec![0; n],
            processed: vec![0; n],
            end_length: vec![0.0; n],
            sets: UnionFind::new(n),
            curves: vec![Curve::single(0.0); n],
        }
    }

    /// Both passes; the connected edges as vertex pairs.
    pub(super) fn run(mut self) -> Vec<[u32; 2]> {
        // Step 2: pass 1.
        for k in 0..self.candidates.len() {
            if self.state[k] != State::Unprocessed {
                continue;
            }
            let [p, q] = self.candidates[k].ends;
            if self.inner(p) || self.inner(q) {
                self.state[k] = State::Removed;
                continue;
            }
            if self.accepts(k) {
                self.connect(k);
            } else {
                self.state[k] = State::Deferred;
            }
            if self.variant.two_processed {
                for v in [p, q] {
                    self.processed[v as usize] += 1;
                    if self.processed[v as usize] == 2 {
                        self.retire(v);
                    }
                }
            }
        }
        // Step 3: pass 2.
        for k in 0..self.candidates.len() {
            if self.state[k] != State::Deferred {
                continue;
            }
            let [p, q] = self.candidates[k].ends;
            if self.inner(p) || self.inner(q) {
                self.state[k] = State::Removed;
            } else if self.accepts(k) {
                self.connect(k);
                self.grow(p);
            }
        }
        (0..self.candidates.len())
            .filter(|&k| self.state[k] == State::Connected)
            .map(|k| self.candidates[k].ends)
            .collect()
    }

    fn inner(&self, v: u32) -> bool {
        self.degree[v as usize] >= 2
    }

    /// Whether candidate `k` (no end inside a curve) is to be connected.
    fn accepts(&mut self, k: usize) -> bool {
        let Candidate { length: d, ends: [p, q] } = self.candidates[k];
        match (self.degree[p as usize], self.degree[q as usize]) {
            (0, 0) => true,
            (_, 0) => self.end_accepts(p, d),
            (0, _) => self.end_accepts(q, d),
            _ => {
                let closing = self.sets.find(p) == self.sets.find(q);
                let both = self.variant.both_ends || (closing && self.variant.close_both_ends);
                let (at_p, at_q) = (self.end_accepts(p, d), self.end_accepts(q, d));
                if both {
                    at_p && at_q
                } else {
                    at_p || at_q
                }
            }
        }
    }

    /// The criterion at curve end `e` for an edge of length `d`.
    fn end_accepts(&mut self, e: u32, d: f64) -> bool {
        let curve = self.curves[self.sets.find(e) as usize];
        curve.accepts(self.end_length[e as usize], d)
    }

    /// Connects candidate `k`: starts, extends, merges or closes a curve.
    fn connect(&mut self, k: usize) {
        let Candidate { length: d, ends: [p, q] } = self.candidates[k];
        self.state[k] = State::Connected;
        let (rp, rq) = (self.sets.find(p), self.sets.find(q));
        let (end_p, end_q) = (self.degree[p as usize] == 1, self.degree[q as usize] == 1);
        let link = Curve::single(d);
        let curve = if end_p && end_q && rp == rq {
            // Two ends of one curve: it closes (pooled statistics have no ends).
            self.curves[rp as usize].pooled(link)
        } else {
            // The far end of `v`'s curve, seen from its end `v`.
            let far = |c: &Curve, v: u32| c.ends.map(|[x, y]| if x == v { y } else { x });
            let (mut curve, mut ends) = (link, [p, q]);
            if end_p {
                let c = self.curves[rp as usize];
                curve = c.pooled(curve);
                ends[0] = far(&c, p).unwrap_or(p);
            }
            if end_q {
                let c = self.curves[rq as usize];
                curve = curve.pooled(c);
                ends[1] = far(&c, q).unwrap_or(q);
            }
            self.sets.union(p, q);
            curve.ends = Some(ends);
            curve
        };
        let root = self.sets.find(p);
        self.curves[root as usize] = curve;
        for v in [p, q] {
            self.degree[v as usize] += 1;
            self.end_length[v as usize] = d;
            if self.inner(v) {
                self.retire(v);
            }
        }
    }

    /// Removes the unprocessed edges at `v`.
    fn retire(&mut self, v: u32) {
        for h in self.dt.incident(v) {
            let k = self.candidate_of[h as usize] as usize;
            if self.state[k] == State::Unprocessed {
                self.state[k] = State::Removed;
            }
        }
    }

    /// Step 3's inner loop: connects deferred edges at the ends of `v`'s curve, shortest
    /// first, until none passes or the curve closes.
    fn grow(&mut self, v: u32) {
        let mut at_ends: Vec<u32> = Vec::new();
        loop {
            let Some(ends) = self.curves[self.sets.find(v) as usize].ends else { return };
            at_ends.clear();
            for e in ends {
                at_ends.extend(self.dt.incident(e).map(|h| self.candidate_of[h as usize]));
            }
            at_ends.sort_unstable();
            at_ends.dedup();
            let passes = at_ends.iter().map(|&k| k as usize).find(|&k| {
                let [p, q] = self.candidates[k].ends;
                self.state[k] == State::Deferred
                    && !self.inner(p)
                    && !self.inner(q)
                    && self.accepts(k)
            });
            match passes {
                Some(k) => self.connect(k),
                None => return,
            }
        }
    }
}
