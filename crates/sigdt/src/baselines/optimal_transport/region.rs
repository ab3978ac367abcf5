//! Simulating an operation on the star of one vertex without touching the mesh: the flips
//! that make a half-edge collapsible, and the transport cost of the retriangulated star.
//!
//! Both a collapse `s → t` and a relocation of `v` rebuild the polygon formed by the star of
//! one vertex (its *region*): the collapse as a fan from `t` (after the flips, which cut ears
//! off the polygon), the relocation as a fan from `v`'s new position. The region's edges are
//! its boundary (the old link, whose outside samples stay where they are) and its new inner
//! edges; the samples inside the polygon are assigned again within the new triangles.
use super::mesh::Mesh;
use super::transport::{item, locate, merged_cost, orient, segment_distance2, sort_by_u};
use super::transport::{Item, Samples, Slot};
use crate::delaunay::next;
use crate::geometry::{distance, Point};

/// Scratch space for simulations around one vertex; see the module docs.
#[derive(Default)]
pub(super) struct Region {
    /// The new triangles of the region.
    pub(super) tris: Vec<[u32; 3]>,
    /// After [`make_collapsible`](Self::make_collapsible): the link left by the flips, and
    /// the vertices the flips took out of it, in order.
    pub(super) link: Vec<u32>,
    pub(super) removed: Vec<u32>,
    /// After [`make_collapsible`](Self::make_collapsible): the new edges inside the region.
    inner: Vec<[u32; 2]>,
    /// Per link edge during the flips: how far the target is behind it.
    behind: Vec<f64>,
    /// The region's edges, `[a, b]` with `a < b`: the boundary's first, then those inside.
    edges: Vec<[u32; 2]>,
    boundary: usize,
    /// The edges of each triangle of `tris` (indices into `edges`).
    tri_edges: Vec<[u32; 3]>,
    /// Per boundary edge: its outside samples, sorted by `u`.
    outside: Vec<Vec<Item>>,
    outside_len: usize,
    /// The outside samples' squared distances to their edges, summed: what they cost at least.
    outside_floor: f64,
    /// Per boundary edge: the cost of its outside samples alone.
    outside_cost: Vec<f64>,
    /// Per edge: the inside samples assigned to it.
    bucket: Vec<Vec<Item>>,
}

impl Region {
    /// Takes the star of an interior vertex (`star[i]` from it to `link[i]`) as the region:
    /// its link edges become the boundary, with the samples assigned to their outer sides.
    pub(super) fn prepare(&mut self, mesh: &Mesh, samples: &Samples, star: &[u32], link: &[u32]) {
        self.edges.clear();
        let d = link.len();
        if self.outside.len() < d {
            self.outside.resize_with(d, Vec::new);
        }
        self.outside_len = 0;
        self.outside_floor = 0.0;
        for i in 0..d {
            let (a, b) = (link[i], link[(i + 1) % d]);
            let key = [a.min(b), a.max(b)];
            self.edges.push(key);
            let (pa, pb) = (mesh.pos[key[0] as usize], mesh.pos[key[1] as usize]);
            let outside = &mut self.outside[i];
            outside.clear();
            for s in samples.on(mesh.twin(next(star[i]))) {
                let p = samples.pos[s as usize];
                outside.push(item(p, pa, pb));
                self.outside_floor += segment_distance2(p, pa, pb);
            }
            sort_by_u(outside);
            self.outside_len += outside.len();
        }
        self.outside_cost.clear();
        for (i, key) in self.edges.iter().enumerate() {
            let l2 = crate::geometry::squared_distance(
                mesh.pos[key[0] as usize],
                mesh.pos[key[1] as usize],
            );
            self.outside_cost.push(merged_cost(&self.outside[i], &[], l2).0);
        }
        self.boundary = d;
    }

    /// Flips spokes of `s` (at `ps`, link `link`, counter-clockwise) until its neighbour `t`
    /// sees every link edge that does not end at `t`; `false` if no flip helps. The flips are
    /// simulated: [`link`](Self::link) and [`removed`](Self::removed) hold their outcome, and
    /// [`tris`](Self::tris) the region's triangles once `s` is collapsed into `t`.
    ///
    /// The rule is ours: take the link edge that `t` is farthest behind; of its two ends,
    /// flip away one whose spoke can flip (the quadrilateral is strictly convex), preferring
    /// the one whose new link edge leaves `t` farther in front (or ends at `t`).
    pub(super) fn make_collapsible(
        &mut self,
        ps: Point,
        link: &[u32],
        t: u32,
        pos: impl Fn(u32) -> Point,
    ) -> bool {
        self.link.clear();
        self.link.extend_from_slice(link);
        self.removed.clear();
        self.tris.clear();
        self.inner.clear();
        let pt = pos(t);
        // How far `t` is behind the link edge `a → b`: its signed distance from the line
        // when not strictly in front, else +∞ (and +∞ for the edges at `t`).
        let behind = |a: u32, b: u32| {
            let o = if a == t || b == t { 1.0 } else { orient(pos(a), pos(b), pt) };
            if o > 0.0 {
                f64::INFINITY
            } else {
                o / distance(pos(a), pos(b))
            }
        };
        let d = link.len();
        self.behind.clear();
        self.behind.extend((0..d).map(|i| behind(link[i], link[(i + 1) % d])));
        loop {
            let m = self.link.len();
            let worst = (0..m)
                .filter(|&i| self.behind[i] <= 0.0)
                .min_by(|&x, &y| self.behind[x].total_cmp(&self.behind[y]).then(x.cmp(&y)));
            let Some(i) = worst else { break };
            let at = |j: usize| self.link[j % m];
            // Flipping the spoke to `at(j)` replaces its two link edges by `at(j-1) at(j+1)`.
            let score = |j: usize| -> Option<f64> {
                let (p, b, q) = (at(j + m - 1), at(j), at(j + 1));
                let convex = m > 3
                    && orient(pos(p), pos(b), pos(q)) > 0.0
                    && orient(ps, pos(p), pos(q)) > 0.0;
                let ahead = || {
                    let o = orient(pos(p), pos(q), pt);
                    if p == t || q == t {
                        f64::INFINITY
                    } else {
                        o / distance(pos(p), pos(q))
                    }
                };
                (b != t && convex).then(ahead)
            };
            let j = match (score(i), score(i + 1)) {
                (Some(x), Some(y)) if y > x => i + 1,
                (Some(_), _) => i,
                (None, Some(_)) => i + 1,
                (None, None) => return false,
            } % m;
            let (p, q) = (at(j + m - 1), at(j + 1));
            self.tris.push([p, at(j), q]);
            self.inner.push([p, q]);
            self.removed.push(self.link.remove(j));
            self.behind.remove(j);
            let before = (j + m - 2) % (m - 1);
            self.behind[before] = behind(p, q);
        }
        // The fan from `t` over what is left of the link.
        let m = self.link.len();
        let k = self.link.iter().position(|&v| v == t).expect("t stays in the link");
        for i in 1..m - 1 {
            let (a, b) = (self.link[(k + i) % m], self.link[(k + i + 1) % m]);
            self.tris.push([t, a, b]);
            if i > 1 {
                self.inner.push([t, a]);
            }
        }
        true
    }

    /// A lower bound on [`cost`](Self::cost) after [`make_collapsible`](Self::make_collapsible):
    /// each sample goes to a point of an edge of the region, so it costs at least its squared
    /// distance to the nearest one (an outside sample, to its own edge). `probes` are some of
    /// the inside samples, each with its squared distance to the nearest boundary edge.
    pub(super) fn lower_bound(&self, probes: &[(Point, f64)], pos: impl Fn(u32) -> Point) -> f64 {
        let mut total = self.outside_floor;
        for &(p, to_boundary) in probes {
            let to_inner = self.inner.iter().map(|&[a, b]| segment_distance2(p, pos(a), pos(b)));
            total += to_inner.fold(to_boundary, f64::min);
        }
        total
    }

    /// Sets [`tris`](Self::tris) to the fan from `v` over `link` (a relocation of `v`).
    pub(super) fn fan(&mut self, v: u32, link: &[u32]) {
        self.tris.clear();
        let d = link.len();
        self.tris.extend((0..d).map(|i| [v, link[i], link[(i + 1) % d]]));
    }

    /// The transport cost of the region's edges, the boundary's outside samples and the
    /// samples `inside` assigned within [`tris`](Self::tris), with vertex positions from
    /// `pos`; and the number of samples counted.
    pub(super) fn cost(
        &mut self,
        samples: &Samples,
        inside: &[u32],
        pos: impl Fn(u32) -> Point,
    ) -> (f64, usize) {
        self.edges.truncate(self.boundary);
        self.tri_edges.clear();
        for c in &self.tris {
            let mut ids = [0; 3];
            for (k, id) in ids.iter_mut().enumerate() {
                let (a, b) = (c[k], c[(k + 1) % 3]);
                let key = [a.min(b), a.max(b)];
                *id = match self.edges.iter().position(|&e| e == key) {
                    Some(e) => e as u32,
                    None => {
                        self.edges.push(key);
                        self.edges.len() as u32 - 1
                    }
                };
            }
            self.tri_edges.push(ids);
        }
        if self.bucket.len() < self.edges.len() {
            self.bucket.resize_with(self.edges.len(), Vec::new);
        }
        self.bucket.iter_mut().for_each(Vec::clear);
        let mut hint = 0;
        for &s in inside {
            let p = samples.pos[s as usize];
            let (i, slot) = locate(p, &self.tris, hint, &pos);
            hint = i;
            if let Slot::Edge(k) = slot {
                let e = self.tri_edges[i][k] as usize;
                let [a, b] = self.edges[e];
                self.bucket[e].push(item(p, pos(a), pos(b)));
            }
        }
        let mut total = 0.0;
        for (e, &[a, b]) in self.edges.iter().enumerate() {
            let inside = &mut self.bucket[e];
            if inside.is_empty() {
                total += if e < self.boundary { self.outside_cost[e] } else { 0.0 };
                continue;
            }
            let outside: &[Item] = if e < self.boundary { &self.outside[e] } else { &[] };
            sort_by_u(inside);
            let l2 = crate::geometry::squared_distance(pos(a), pos(b));
            total += merged_cost(outside, inside, l2).0;
        }
        (total, self.outside_len + inside.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::orient2d;

    const SQUARE: [Point; 5] = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]];

    #[test]
    fn a_convex_star_needs_no_flip() {
        let pos = |v: u32| SQUARE[v as usize];
        let mut r = Region::default();
        assert!(r.make_collapsible(SQUARE[4], &[0, 1, 2, 3], 0, pos));
        assert!(r.removed.is_empty());
        assert_eq!(r.tris, vec![[0, 1, 2], [0, 2, 3]]);
    }

    #[test]
    fn a_blocking_link_edge_is_flipped_away() {
        // s = (0, 0) with link 0 (-2, 0), 1 (-1, -2), 2 (1, -2), 3 (2, -3), 4 (2, 1),
        // 5 (-1, 2). Vertex 0 is behind the edge 2 → 3. The corner at 2 is reflex, the one at
        // 3 convex: flipping the spoke to 3 leaves the link edge 2 → 4, which 0 sees.
        let pts = [[-2.0, 0.0], [-1.0, -2.0], [1.0, -2.0], [2.0, -3.0], [2.0, 1.0], [-1.0, 2.0]];
        let pos = |v: u32| pts[v as usize];
        let mut r = Region::default();
        assert!(r.make_collapsible([0.0, 0.0], &[0, 1, 2, 3, 4, 5], 0, pos));
        assert_eq!(r.removed, vec![3]);
        assert_eq!(r.link, vec![0, 1, 2, 4, 5]);
        assert_eq!(r.tris, vec![[2, 3, 4], [0, 1, 2], [0, 2, 4], [0, 4, 5]]);
        for t in &r.tris {
            assert!(orient2d(pos(t[0]), pos(t[1]), pos(t[2])) > 0.0);
        }
        // Into 2 instead: it is behind nothing (its own edges do not count).
        assert!(r.make_collapsible([0.0, 0.0], &[0, 1, 2, 3, 4, 5], 2, pos));
        assert!(r.removed.is_empty());
    }
}
