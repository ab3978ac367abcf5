//! The greedy simplification of [dGCSAD11] §4: a priority queue of half-edge collapses,
//! each made possible by flips, followed by the relocation of the vertices around it.
//!
//! The queue holds, for each vertex `s` that may be collapsed, its cheapest collapse `s → t`
//! over its neighbours, keyed by the rise in transport cost (`docs/algorithms.md` §0.3: ties
//! by `s`, then `t`, in the mesh's numbering). An operation changes one region (a star, see
//! `region`); the candidates it can change are those of the region's vertices and of the
//! vertices across those boundary edges whose samples changed (`star`). They are evaluated
//! again once per step, after the collapse and its relocations (`relocate`), so the queue
//! always holds every vertex's cheapest collapse as the exhaustive queue would.
//!
//! [dGCSAD11]: https://doi.org/10.1111/j.1467-8659.2011.02033.x
use super::mesh::{Mesh, FRAME};
use super::region::Region;
use super::transport::{segment_distance2, Item, Samples};
use super::Stop;
use crate::geometry::Point;
use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

/// Vertices with more edges than this are neither collapsed nor relocated (ours: it bounds
/// the work per vertex; their degree falls as their neighbours collapse).
pub(super) const MAX_DEGREE: u32 = 64;

/// Relocation rounds after each collapse (CGAL's default).
const RELOCATIONS: usize = 2;

/// At most this many of a star's samples give a candidate's lower bound.
const PROBES: usize = 16;

/// A vertex whose region (its star and the outer sides of its link) holds more samples than
/// the larger of these two bounds waits, like one of too high a degree (ours: it bounds the
/// work per step). The second grows with the samples per vertex left, so that a strong
/// simplification is not held back.
pub(super) const MAX_REGION_SAMPLES: usize = 256;
pub(super) const REGION_SAMPLES_PER_VERTEX: usize = 16;

/// A queued collapse `s → t`, valid while `stamp` is `s`'s.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    rise: f64,
    s: u32,
    t: u32,
    stamp: u32,
}

impl Ord for Candidate {
    fn cmp(&self, o: &Self) -> Ordering {
        self.rise.total_cmp(&o.rise).then((self.s, self.t, self.stamp).cmp(&(o.s, o.t, o.stamp)))
    }
}

impl PartialOrd for Candidate {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl PartialEq for Candidate {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}

impl Eq for Candidate {}

/// The mesh, its samples and costs, and the queue. See the module docs.
pub(super) struct Simplifier {
    pub(super) mesh: Mesh,
    pub(super) samples: Samples,
    /// Per half-edge (both of a pair agree): the cost of its edge and whether it is solid.
    pub(super) cost: Vec<f64>,
    pub(super) solid: Vec<bool>,
    stamp: Vec<u32>,
    queue: BinaryHeap<Reverse<Candidate>>,
    /// Squared bound on a collapse region's RMS transport distance, if any.
    tolerance2: Option<f64>,
    /// The samples' bounding box: relocations stay inside it.
    pub(super) bbox: [Point; 2],
    /// Vertices left, frame corners not counted.
    pub(super) vertices: usize,
    pub(super) region: Region,
    pub(super) star: Vec<u32>,
    pub(super) link: Vec<u32>,
    pub(super) inside: Vec<u32>,
    pub(super) tris: Vec<u32>,
    pub(super) corners: Vec<[u32; 3]>,
    pub(super) group: Vec<Item>,
    pub(super) ring: Vec<u32>,
    pub(super) dirty: Vec<u32>,
    pub(super) marked: Vec<bool>,
    /// Candidates of one vertex: lower bound, target, range of their triangles.
    candidates: Vec<(f64, u32, usize, usize)>,
    candidate_tris: Vec<[u32; 3]>,
    /// Some of a star's samples, with their squared distances to its link.
    probes: Vec<(Point, f64)>,
    /// Before an operation: the outer half-edge of each link edge of the star, and the
    /// samples on its inner side (sorted, delimited by `side_ends`).
    pub(super) outer: Vec<u32>,
    pub(super) sides: Vec<u32>,
    pub(super) side_ends: Vec<usize>,
    pub(super) side: Vec<u32>,
}

impl Simplifier {
    /// The triangulation of `points` (distinct, not all collinear, scaled) and its frame,
    /// every sample on its own vertex, and the queue filled.
    pub(super) fn new(points: &[Point], stop: Stop, scale: f64) -> Simplifier {
        let mesh = Mesh::new(points);
        let slots = 3 * mesh.num_slots() as usize;
        let nv = mesh.pos.len();
        let mut bbox = [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]];
        for p in points {
            for a in 0..2 {
                bbox[0][a] = bbox[0][a].min(p[a]);
                bbox[1][a] = bbox[1][a].max(p[a]);
            }
        }
        let tolerance2 = match stop {
            Stop::Tolerance(t) => Some((t * scale).powi(2)),
            _ => None,
        };
        let mut ot = Simplifier {
            samples: Samples::new(points, FRAME, slots),
            mesh,
            cost: vec![0.0; slots],
            solid: vec![false; slots],
            stamp: vec![0; nv],
            queue: BinaryHeap::new(),
            tolerance2,
            bbox,
            vertices: points.len(),
            region: Region::default(),
            star: Vec::new(),
            link: Vec::new(),
            inside: Vec::new(),
            tris: Vec::new(),
            corners: Vec::new(),
            group: Vec::new(),
            ring: Vec::new(),
            dirty: Vec::new(),
            marked: vec![false; nv],
            candidates: Vec::new(),
            candidate_tris: Vec::new(),
            probes: Vec::new(),
            outer: Vec::new(),
            sides: Vec::new(),
            side_ends: Vec::new(),
            side: Vec::new(),
        };
        for v in FRAME..nv as u32 {
            ot.refresh(v);
        }
        ot
    }

    /// Collapses until `stop` holds or no collapse is left.
    pub(super) fn run(&mut self, stop: Stop) {
        let mut steps = 0;
        loop {
            match stop {
                Stop::Vertices(m) if self.vertices <= m => return,
                Stop::Steps(k) if steps >= k => return,
                _ => {}
            }
            let Some(Reverse(c)) = self.queue.pop() else { return };
            if c.stamp != self.stamp[c.s as usize] {
                continue;
            }
            // Simulation and collapse run the same code on the same state.
            let done = self.collapse(c.s, c.t);
            debug_assert!(done, "a simulated collapse failed");
            steps += usize::from(done);
            for _ in 0..RELOCATIONS {
                self.relocate_ring();
            }
            while let Some(v) = self.dirty.pop() {
                self.marked[v as usize] = false;
                self.refresh(v);
            }
        }
    }

    /// Evaluates `v`'s collapses again and queues the cheapest.
    fn refresh(&mut self, v: u32) {
        self.stamp[v as usize] += 1;
        if let Some((rise, t)) = self.cheapest_collapse(v) {
            let stamp = self.stamp[v as usize];
            self.queue.push(Reverse(Candidate { rise, s: v, t, stamp }));
        }
    }

    /// The cheapest valid collapse of `s` into a neighbour: its cost rise and target.
    ///
    /// In a star of more than `2 · PROBES` samples every candidate first gets a lower bound
    /// on its cost ([`Region::lower_bound`] on [`PROBES`] of the samples); they are evaluated
    /// in the order of their bounds, and the rest are skipped once a bound exceeds the best
    /// cost found. Skipping changes nothing but the work.
    fn cheapest_collapse(&mut self, s: u32) -> Option<(f64, u32)> {
        if !self.may_change(s) {
            return None;
        }
        let before = self.star_cost();
        self.gather(s, false);
        self.region.prepare(&self.mesh, &self.samples, &self.star, &self.link);
        let pos = &self.mesh.pos;
        // Small stars are cheaper to evaluate than to bound.
        let bounded = self.inside.len() > 2 * PROBES;
        let step = self.inside.len().div_ceil(PROBES).max(1);
        self.probes.clear();
        for &k in self.inside.iter().step_by(step).filter(|_| bounded) {
            let p = self.samples.pos[k as usize];
            let d = self.link.len();
            let to_link = (0..d).map(|i| {
                let (a, b) = (self.link[i], self.link[(i + 1) % d]);
                segment_distance2(p, pos[a as usize], pos[b as usize])
            });
            self.probes.push((p, to_link.fold(f64::INFINITY, f64::min)));
        }
        self.candidates.clear();
        self.candidate_tris.clear();
        for &t in &self.link {
            if self.region.make_collapsible(pos[s as usize], &self.link, t, |u| pos[u as usize]) {
                let bound = if bounded {
                    self.region.lower_bound(&self.probes, |u| pos[u as usize])
                } else {
                    0.0
                };
                let start = self.candidate_tris.len();
                self.candidate_tris.extend_from_slice(&self.region.tris);
                self.candidates.push((bound, t, start, self.candidate_tris.len()));
            }
        }
        self.candidates.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut best: Option<(f64, u32, f64)> = None;
        for &(bound, t, start, end) in &self.candidates {
            // The bound and the cost round differently: a margin keeps the skip safe.
            if best.is_some_and(|(_, _, after)| bound * (1.0 - 1e-9) > after) {
                break;
            }
            self.region.tris.clear();
            self.region.tris.extend_from_slice(&self.candidate_tris[start..end]);
            let (after, mass) = self.region.cost(&self.samples, &self.inside, |u| pos[u as usize]);
            if self.tolerance2.is_some_and(|tol2| after > tol2 * mass as f64) {
                continue;
            }
            let rise = after - before;
            if best.map_or(true, |(r, b, _)| rise.total_cmp(&r).then(t.cmp(&b)).is_lt()) {
                best = Some((rise, t, after));
            }
        }
        best.map(|(rise, t, _)| (rise, t))
    }

    /// Performs the collapse `s → t` with its flips; `false` (nothing changed) if it is not
    /// valid. Leaves the link of `s` in `ring` and the region's stencil marked dirty.
    fn collapse(&mut self, s: u32, t: u32) -> bool {
        self.load_star(s);
        let pos = &self.mesh.pos;
        if !self.region.make_collapsible(pos[s as usize], &self.link, t, |u| pos[u as usize]) {
            return false;
        }
        self.mark_stencil();
        self.gather(s, true);
        for i in 0..self.region.removed.len() {
            let b = self.region.removed[i];
            let h = self.mesh.spoke(s, b);
            self.mesh.flip(h);
        }
        let h = self.mesh.spoke(s, t);
        self.mesh.collapse(h);
        self.tris.retain(|&k| self.mesh.alive(k));
        self.assign();
        self.mark_changed_sides();
        self.ring.clone_from(&self.link);
        self.vertices -= 1;
        true
    }
}
