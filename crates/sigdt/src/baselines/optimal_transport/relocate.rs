//! Vertex relocation ([dGCSAD11] §4.3): after each collapse, the vertices around it move to
//! the position that best fits the samples on their edges, when that keeps their stars
//! valid and lowers the transport cost.
//!
//! [dGCSAD11]: https://doi.org/10.1111/j.1467-8659.2011.02033.x
use super::simplify::Simplifier;
use crate::delaunay::EMPTY;
use crate::geometry::{orient2d, squared_distance, Point};

impl Simplifier {
    /// One relocation round over `ring` ([dGCSAD11] §4.3): each vertex's optimal position is
    /// computed first, then each move is made if it keeps the star valid, stays inside the
    /// samples' bounding box and lowers the star's transport cost.
    ///
    /// [dGCSAD11]: https://doi.org/10.1111/j.1467-8659.2011.02033.x
    pub(super) fn relocate_ring(&mut self) {
        let mut ring = std::mem::take(&mut self.ring);
        ring.sort_unstable();
        ring.dedup();
        let targets: Vec<(u32, Point)> =
            ring.iter().filter_map(|&v| Some((v, self.optimal_position(v)?))).collect();
        for (v, p) in targets {
            let inside_box = (0..2).all(|a| p[a] >= self.bbox[0][a] && p[a] <= self.bbox[1][a]);
            if p == self.mesh.pos[v as usize] || !inside_box {
                continue;
            }
            self.load_star(v);
            let d = self.link.len();
            let pos = &self.mesh.pos;
            let sees = |i: usize| {
                let (a, b) = (self.link[i], self.link[(i + 1) % d]);
                orient2d(pos[a as usize], pos[b as usize], p) > 0.0
            };
            if !(0..d).all(sees) {
                continue;
            }
            let before = self.star_cost();
            self.gather(v, false);
            self.region.prepare(&self.mesh, &self.samples, &self.star, &self.link);
            self.region.fan(v, &self.link);
            let pos = &self.mesh.pos;
            let at = |u: u32| if u == v { p } else { pos[u as usize] };
            let (after, _) = self.region.cost(&self.samples, &self.inside, at);
            if after < before {
                self.mark_stencil();
                self.gather(v, true);
                self.mesh.pos[v as usize] = p;
                self.assign();
                self.mark_changed_sides();
            }
        }
        self.ring = ring;
    }

    /// The position of `v` that minimises the transport cost of the samples on its edges,
    /// their assignment and plans fixed: an edge-plan sample at `c` along `v → b` goes to
    /// `(1 − c)·x + c·b`, a vertex-plan sample nearer to `v` and a sample on `v` go to `x`.
    /// `None` if `v` may not move or nothing pulls it.
    fn optimal_position(&mut self, v: u32) -> Option<Point> {
        if !self.may_change(v) {
            return None;
        }
        let pv = self.mesh.pos[v as usize];
        let (mut coef, mut rhs) = (0.0, [0.0, 0.0]);
        for &h in &self.star {
            let pb = self.mesh.pos[self.mesh.dest(h) as usize];
            let b = [pb[0] - pv[0], pb[1] - pv[1]];
            let l2 = b[0] * b[0] + b[1] * b[1];
            let g = self.mesh.twin(h);
            for s in self.samples.on(h).chain(self.samples.on(g)) {
                let p = self.samples.pos[s as usize];
                let q = [p[0] - pv[0], p[1] - pv[1]];
                if self.solid[h as usize] {
                    let c = (q[0] * b[0] + q[1] * b[1]) / l2;
                    let w = 1.0 - c;
                    coef += w * w;
                    rhs = [rhs[0] + w * (q[0] - c * b[0]), rhs[1] + w * (q[1] - c * b[1])];
                } else if q[0] * q[0] + q[1] * q[1] < squared_distance(p, pb) {
                    coef += 1.0;
                    rhs = [rhs[0] + q[0], rhs[1] + q[1]];
                }
            }
        }
        if self.samples.on_vertex[v as usize] != EMPTY {
            coef += 1.0;
        }
        (coef > 0.0).then(|| [pv[0] + rhs[0] / coef, pv[1] + rhs[1] / coef])
    }
}
