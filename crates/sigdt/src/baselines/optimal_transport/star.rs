//! The bookkeeping around one vertex's star that simulations and operations share: loading
//! it, gathering and assigning its samples, updating edge costs, and marking the vertices
//! whose candidates an operation on it may change.
use super::mesh::Mesh;
use super::simplify::{Simplifier, MAX_DEGREE, MAX_REGION_SAMPLES, REGION_SAMPLES_PER_VERTEX};
use super::transport::{edge_cost, item, locate, Slot};
use crate::delaunay::{next, prev, EMPTY};
use crate::geometry::squared_distance;

impl Simplifier {
    /// Whether `v` may be collapsed or moved: not a frame corner, not collapsed, at most
    /// [`MAX_DEGREE`] edges and not too many samples in its region
    /// ([`MAX_REGION_SAMPLES`]). Loads its star when it may.
    pub(super) fn may_change(&mut self, v: u32) -> bool {
        let degree = self.mesh.degree(v);
        if Mesh::pinned(v) || degree == 0 || degree > MAX_DEGREE {
            return false;
        }
        self.load_star(v);
        let per_vertex = self.samples.pos.len() / self.vertices.max(1);
        let most = MAX_REGION_SAMPLES.max(REGION_SAMPLES_PER_VERTEX * per_vertex);
        let held: usize = self
            .star
            .iter()
            .map(|&h| {
                let inner = next(h);
                self.samples.count(h)
                    + self.samples.count(inner)
                    + self.samples.count(prev(h))
                    + self.samples.count(self.mesh.twin(inner))
            })
            .sum();
        held <= most
    }

    /// `star` and `link` of the interior vertex `v`, and its triangles in `tris`.
    pub(super) fn load_star(&mut self, v: u32) {
        self.mesh.star(v, &mut self.star);
        self.link.clear();
        self.link.extend(self.star.iter().map(|&h| self.mesh.dest(h)));
        self.tris.clear();
        self.tris.extend(self.star.iter().map(|&h| h / 3));
    }

    /// The cost of the loaded star's edges: its spokes and its link.
    pub(super) fn star_cost(&self) -> f64 {
        self.star.iter().map(|&h| self.cost[h as usize] + self.cost[next(h) as usize]).sum()
    }

    /// The samples inside the loaded star of `v` into `inside`; moved out of the mesh when
    /// `take`.
    pub(super) fn gather(&mut self, v: u32, take: bool) {
        self.inside.clear();
        for &k in &self.tris {
            for h in 3 * k..3 * k + 3 {
                if take {
                    self.samples.take(h, &mut self.inside);
                } else {
                    self.inside.extend(self.samples.on(h));
                }
            }
        }
        let on_v = self.samples.on_vertex[v as usize];
        if on_v != EMPTY {
            self.inside.push(on_v);
            if take {
                self.samples.on_vertex[v as usize] = EMPTY;
            }
        }
    }

    /// Assigns the taken samples within the triangles `tris` and updates their edges' costs.
    pub(super) fn assign(&mut self) {
        self.corners.clear();
        self.corners.extend(self.tris.iter().map(|&k| self.mesh.corners(k)));
        let mut hint = 0;
        for &s in &self.inside {
            let pos = &self.mesh.pos;
            let p = self.samples.pos[s as usize];
            let (i, slot) = locate(p, &self.corners, hint, |u| pos[u as usize]);
            hint = i;
            match slot {
                Slot::Vertex(k) => {
                    let v = self.corners[i][k] as usize;
                    debug_assert_eq!(self.samples.on_vertex[v], EMPTY);
                    self.samples.on_vertex[v] = s;
                }
                Slot::Edge(k) => self.samples.push(3 * self.tris[i] + k as u32, s),
            }
        }
        for i in 0..self.tris.len() {
            for h in 3 * self.tris[i]..3 * self.tris[i] + 3 {
                let g = self.mesh.twin(h);
                if g == EMPTY || h < g || !self.tris.contains(&(g / 3)) {
                    self.update_cost(h);
                }
            }
        }
    }

    /// Recomputes the cost of `h`'s edge from its samples.
    pub(super) fn update_cost(&mut self, h: u32) {
        let (a, b) = (self.mesh.origin(h), self.mesh.dest(h));
        let (pa, pb) = (self.mesh.pos[a.min(b) as usize], self.mesh.pos[a.max(b) as usize]);
        let g = self.mesh.twin(h);
        self.group.clear();
        for s in self.samples.on(h).chain(self.samples.on(g)) {
            self.group.push(item(self.samples.pos[s as usize], pa, pb));
        }
        let (cost, solid) = edge_cost(&mut self.group, squared_distance(pa, pb));
        for k in [h, g].into_iter().filter(|&k| k != EMPTY) {
            self.cost[k as usize] = cost;
            self.solid[k as usize] = solid;
        }
    }

    /// Before an operation on the loaded star: marks its vertex and link dirty (their stars
    /// change), and records what the vertices across its link edges see of it.
    pub(super) fn mark_stencil(&mut self) {
        self.mark(self.mesh.origin(self.star[0]));
        self.outer.clear();
        self.sides.clear();
        self.side_ends.clear();
        for i in 0..self.star.len() {
            self.mark(self.link[i]);
            let inner = next(self.star[i]);
            self.outer.push(self.mesh.twin(inner));
            let start = self.sides.len();
            self.sides.extend(self.samples.on(inner));
            self.sides[start..].sort_unstable();
            self.side_ends.push(self.sides.len());
        }
    }

    /// After the operation: marks dirty the vertex across each old link edge whose samples
    /// on the inner side changed. A vertex across an edge depends on the star only through
    /// those samples (its link edge and its cost), so the others keep their candidates.
    pub(super) fn mark_changed_sides(&mut self) {
        for i in 0..self.outer.len() {
            let outer = self.outer[i];
            if outer == EMPTY {
                continue;
            }
            self.side.clear();
            self.side.extend(self.samples.on(self.mesh.twin(outer)));
            self.side.sort_unstable();
            let start = if i == 0 { 0 } else { self.side_ends[i - 1] };
            if self.side[..] != self.sides[start..self.side_ends[i]] {
                self.mark(self.mesh.origin(prev(outer)));
            }
        }
    }

    pub(super) fn mark(&mut self, v: u32) {
        if !std::mem::replace(&mut self.marked[v as usize], true) {
            self.dirty.push(v);
        }
    }

    /// Whether `v`, which has no solid edge, receives mass: a sample on it, or a sample that
    /// a ghost edge at `v` sends to `v` under its vertex plan.
    pub(super) fn has_mass(&mut self, v: u32) -> bool {
        if self.samples.on_vertex[v as usize] != EMPTY {
            return true;
        }
        self.load_star(v);
        let pv = self.mesh.pos[v as usize];
        self.star.iter().any(|&h| {
            let pb = self.mesh.pos[self.mesh.dest(h) as usize];
            let nearer = |s: u32| {
                let p = self.samples.pos[s as usize];
                squared_distance(p, pv) < squared_distance(p, pb)
            };
            let g = self.mesh.twin(h);
            self.samples.on(h).chain(self.samples.on(g)).any(nearer)
        })
    }
}
