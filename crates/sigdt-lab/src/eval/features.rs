//! The ground truth as a planar graph of features, and the sampling ratio at a point on it.
//!
//! Used by [`epsilon`](fn@super::epsilon). The graph's edges are *arcs*: maximal chains of
//! ground-truth edges between feature vertices (see [`Features::new`]); its vertices are the
//! arc ends. Two features are disjoint when not adjacent: a vertex and an arc it does not
//! end, two arcs without a common end, two distinct vertices not joined by an arc
//! (data/README.md, "Epsilon"). For a point `x` on arc `A`:
//!
//! - `far(x)` = distance to the nearest feature disjoint from `A`;
//! - `pair(x)` = min over disjoint features `F`, `G` both adjacent to `A` of
//!   `max(d(x, F), d(x, G))`: together with `far` this is Ruppert's lfs, the smallest disk
//!   at `x` meeting two disjoint features (any pair involving a feature disjoint from `A` is
//!   dominated by `far`, since the disk meets `A` at radius 0);
//! - `medial(x)` = distance to the medial points of `A` alone ([`medial_points`]);
//! - `ratio(x) = d(x, samples) / min(...)` of the terms the variant uses.
//!
//! All features sit in one [`SegmentTree`] with one group per arc and per vertex, so
//! "nearest feature not adjacent to `A`" skips whole subtrees of `A`; the medial points sit
//! in a second one, grouped by arc.
use super::bvh::SegmentTree;
use super::medial::medial_points;
use sigdt::internals::chains;
use sigdt::internals::KdTree;
use sigdt::{Edge, Point, Result};

/// Which terms of the local feature size to use.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Terms {
    /// Split arcs at degree-2 vertices turning by more than this angle (radians); `None`
    /// makes every ground-truth edge its own arc.
    pub corner_turn: Option<f64>,
    /// Include `pair(x)` (Ruppert's full definition).
    pub pairs: bool,
    /// Include `medial(x)`.
    pub medial: bool,
}

/// An arc: a polyline of ground-truth vertices between feature vertices.
pub(crate) struct Arc {
    /// Point indices along the arc; a cycle's closing edge is implied.
    pub vertices: Vec<usize>,
    /// True for a cycle without feature vertex.
    pub cycle: bool,
    ends: Vec<u32>,
    neighbours: Vec<u32>,
    pairs: Vec<[usize; 2]>,
}

/// The feature graph with its search structures.
pub(crate) struct Features<'a> {
    pub arcs: Vec<Arc>,
    points: &'a [Point],
    vertex_point: Vec<usize>,
    samples: KdTree<'a>,
    sample_points: &'a [Point],
    tree: SegmentTree,
    medial: SegmentTree,
    any_disjoint: Vec<bool>,
    terms: Terms,
}

impl<'a> Features<'a> {
    /// Builds the graph of `edges` (normalised, no self loops) over `points` (finite);
    /// `samples` are the ground-truth vertices' coordinates.
    pub(crate) fn new(
        points: &'a [Point],
        samples: &'a [Point],
        edges: &[Edge],
        terms: Terms,
    ) -> Result<Features<'a>> {
        let n = points.len();
        let mut nbrs = vec![Vec::new(); n];
        for &[i, j] in edges {
            nbrs[i].push(j);
            nbrs[j].push(i);
        }
        let mark: Vec<bool> = (0..n)
            .map(|v| match (terms.corner_turn, nbrs[v].as_slice()) {
                (None, _) => true,
                (Some(limit), &[u, w]) => turn(points[u], points[v], points[w]) > limit,
                _ => false,
            })
            .collect();
        let mut vertex_id = vec![u32::MAX; n];
        let mut vertex_point = Vec::new();
        let mut id_of = |v: usize| {
            if vertex_id[v] == u32::MAX {
                vertex_id[v] = vertex_point.len() as u32;
                vertex_point.push(v);
            }
            vertex_id[v]
        };
        let mut arcs = Vec::new();
        for chain in chains(n, edges, Some(&mark)) {
            let v = chain.vertices;
            let mut push = |vertices: Vec<usize>, cycle: bool| {
                let ends = if cycle {
                    Vec::new()
                } else {
                    vec![id_of(vertices[0]), id_of(vertices[vertices.len() - 1])]
                };
                let mut ends = ends;
                ends.dedup();
                arcs.push(Arc { vertices, cycle, ends, neighbours: Vec::new(), pairs: Vec::new() });
            };
            if !chain.cycle && v.len() > 3 && v[0] == v[v.len() - 1] {
                // A loop through one feature vertex is split in two (data/README.md).
                let mid = v.len() / 2;
                push(v[..=mid].to_vec(), false);
                push(v[mid..].to_vec(), false);
            } else {
                push(v, chain.cycle);
            }
        }
        let (na, nv) = (arcs.len() as u32, vertex_point.len() as u32);
        let mut arcs_at = vec![Vec::new(); nv as usize];
        for (a, arc) in arcs.iter().enumerate() {
            for &e in &arc.ends {
                arcs_at[e as usize].push(a as u32);
            }
        }
        let (mut segments, mut groups) = (Vec::new(), Vec::new());
        let (mut medial, mut medial_groups) = (Vec::new(), Vec::new());
        for (a, arc) in arcs.iter().enumerate() {
            for [i, j] in arc_edges(arc) {
                segments.push([points[i], points[j]]);
                groups.push(a as u32);
            }
            if terms.medial {
                let pts: Vec<Point> = arc.vertices.iter().map(|&v| points[v]).collect();
                for m in medial_points(&pts)? {
                    medial.push([m, m]);
                    medial_groups.push(a as u32);
                }
            }
        }
        for (k, &v) in vertex_point.iter().enumerate() {
            segments.push([points[v], points[v]]);
            groups.push(na + k as u32);
        }
        // Neighbours of each arc (its ends and the other arcs at them, as groups) and the
        // disjoint pairs among them.
        let ends_of = |g: u32, arcs: &[Arc]| -> Vec<u32> {
            if g < na {
                arcs[g as usize].ends.clone()
            } else {
                vec![g - na]
            }
        };
        let mut any_disjoint = Vec::with_capacity(arcs.len());
        for a in 0..arcs.len() {
            let mut nb: Vec<u32> = arcs[a].ends.iter().map(|&e| na + e).collect();
            for &e in &arcs[a].ends {
                nb.extend(arcs_at[e as usize].iter().filter(|&&b| b != a as u32));
            }
            nb.sort_unstable();
            nb.dedup();
            let mut pairs = Vec::new();
            for i in 0..nb.len() {
                for j in i + 1..nb.len() {
                    let (f, g) = (nb[i], nb[j]);
                    let disjoint = match (f < na, g < na) {
                        (true, true) => {
                            ends_of(f, &arcs).iter().all(|e| !ends_of(g, &arcs).contains(e))
                        }
                        (true, false) => !ends_of(f, &arcs).contains(&(g - na)),
                        (false, true) => !ends_of(g, &arcs).contains(&(f - na)),
                        (false, false) => !arcs_at[(f - na) as usize]
                            .iter()
                            .any(|&b| arcs[b as usize].ends.contains(&(g - na))),
                    };
                    if disjoint {
                        pairs.push([i, j]);
                    }
                }
            }
            // A feature is disjoint from arc `a` unless it is `a`, one of its ends or an arc
            // at them: compare counts.
            let adjacent_arcs = 1 + nb.iter().filter(|&&g| g < na).count();
            any_disjoint.push((arcs.len() > adjacent_arcs) || (nv as usize > arcs[a].ends.len()));
            arcs[a].neighbours = nb;
            arcs[a].pairs = pairs;
        }
        Ok(Features {
            arcs,
            points,
            vertex_point,
            samples: KdTree::new(samples),
            sample_points: samples,
            tree: SegmentTree::new(segments, groups),
            medial: SegmentTree::new(medial, medial_groups),
            any_disjoint,
            terms,
        })
    }

    /// The samples that may be nearest to some point of the ground-truth edge `pq`, `None`
    /// when there are too many for a scan to be faster than a search. Every point of `pq`
    /// lies within `|pq| / 2` of `p` or `q`, both samples, and of the midpoint: its nearest
    /// sample lies within `|pq|` of the midpoint.
    pub(crate) fn samples_near_edge(&self, p: Point, q: Point, out: &mut Vec<u32>) -> bool {
        const MOST: usize = 32;
        out.clear();
        let mid = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])];
        // A margin for the rounding of the midpoint and the radius.
        self.samples.within(mid, distance(p, q) * (1.0 + 1e-9), out);
        out.len() <= MOST
    }

    /// `ratio(x)` for `x` on arc `a`; exact when above `cap`, otherwise some value ≤ `cap`
    /// (the searches stop at the radius where the ratio can no longer exceed `cap`). `near`
    /// holds `x`'s nearest sample (from [`Features::samples_near_edge`]), or is `None`.
    pub(crate) fn ratio(&self, x: Point, near: Option<&[u32]>, a: usize, cap: f64) -> f64 {
        let d_p = match near {
            Some(near) => {
                let d2 = near.iter().map(|&s| squared(x, self.sample_points[s as usize]));
                d2.fold(f64::INFINITY, f64::min).sqrt()
            }
            None => self.samples.nearest(x, 1, u32::MAX).first().map_or(0.0, |&(d2, _)| d2.sqrt()),
        };
        if d_p == 0.0 {
            return 0.0;
        }
        let na = self.arcs.len() as u32;
        let arc = &self.arcs[a];
        let mut bound = if cap > 0.0 { d_p / cap } else { f64::INFINITY };
        if self.terms.medial {
            bound = bound.min(self.medial.nearest_in_group(x, a as u32, bound));
        }
        if self.terms.pairs && !arc.pairs.is_empty() {
            let dist: Vec<f64> = arc
                .neighbours
                .iter()
                .map(|&g| match g < na {
                    true => self.tree.nearest_in_group(x, g, bound),
                    false => distance(x, self.points[self.vertex_point[(g - na) as usize]]),
                })
                .collect();
            for &[i, j] in &arc.pairs {
                bound = bound.min(dist[i].max(dist[j]));
            }
        }
        let accept = |g: u32| match g {
            g if g < na => {
                g != a as u32 && self.arcs[g as usize].ends.iter().all(|e| !arc.ends.contains(e))
            }
            g => !arc.ends.contains(&(g - na)),
        };
        let best = std::cell::Cell::new(bound);
        if !self.any_disjoint[a] {
            return if bound == f64::INFINITY { 0.0 } else { d_p / bound };
        }
        self.tree.search(x, &accept, &|| best.get(), &mut |_, _, d| best.set(best.get().min(d)));
        let lfs = best.get();
        if lfs == f64::INFINITY {
            0.0
        } else {
            d_p / lfs
        }
    }
}

/// The edges of an arc as point-index pairs, the closing edge of a cycle included.
pub(crate) fn arc_edges(arc: &Arc) -> impl Iterator<Item = [usize; 2]> + '_ {
    let v = &arc.vertices;
    let closing = (arc.cycle && v.len() > 2).then(|| [v[v.len() - 1], v[0]]);
    v.windows(2).map(|w| [w[0], w[1]]).chain(closing)
}

/// Turning angle at `v` between `u → v` and `v → w`, in `[0, π]`; π for coincident points.
fn turn(u: Point, v: Point, w: Point) -> f64 {
    let (a, b) = ([v[0] - u[0], v[1] - u[1]], [w[0] - v[0], w[1] - v[1]]);
    if a == [0.0, 0.0] || b == [0.0, 0.0] {
        return std::f64::consts::PI;
    }
    (a[0] * b[1] - a[1] * b[0]).atan2(a[0] * b[0] + a[1] * b[1]).abs()
}

/// The squared distance, computed as the k-d tree computes it: the same nearest distance
/// whichever finds it.
fn squared(p: Point, q: Point) -> f64 {
    let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
    dx * dx + dy * dy
}

fn distance(p: Point, q: Point) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}
