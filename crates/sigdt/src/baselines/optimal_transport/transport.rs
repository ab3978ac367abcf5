//! The transport plan of [dGCSAD11] §3: where each sample sends its mass, and what that
//! costs per edge.
//!
//! - **Assignment.** A sample lies in a triangle of the mesh (its *face*); it is assigned to
//!   the vertex of that face it coincides with, else to the face's edge nearest to it (by
//!   distance to the segment; ties to the edge with the smaller pair of vertex numbers). It is
//!   stored on the half-edge of that edge that faces it.
//! - **Edge cost.** The `M` samples of an edge of length `L` are either spread uniformly along
//!   it (the *edge plan*: sorted by their projections, the `i`-th takes the bin
//!   `[i, i + 1]·L/M`, costing its squared distance to the line plus `(L/M)²/12` plus the squared
//!   offset of its projection from the bin's centre) or sent to the nearer end (the *vertex
//!   plan*: its squared distance to that end). The cheaper plan is the edge's; the edge plan
//!   wins ties. An edge is *solid* (part of the output) when it has samples and uses the edge
//!   plan, otherwise a *ghost*.
//!
//! Every sample has mass 1. Costs are squared lengths in the kernel's scaled coordinates.
//!
//! [dGCSAD11]: https://doi.org/10.1111/j.1467-8659.2011.02033.x
use crate::delaunay::EMPTY;
use crate::geometry::{orient2d, squared_distance, Point};

/// The samples: positions and where each is assigned (see the module docs).
pub(super) struct Samples {
    /// Sample positions, in scaled coordinates.
    pub(super) pos: Vec<Point>,
    /// Per half-edge slot: the first sample assigned to it, linked through `next`.
    head: Vec<u32>,
    next: Vec<u32>,
    /// Per half-edge slot: how many samples are assigned to it.
    count: Vec<u32>,
    /// Per mesh vertex: the sample at its position, if any.
    pub(super) on_vertex: Vec<u32>,
}

impl Samples {
    /// `points[i]` at mesh vertex `first + i`, each assigned to its vertex.
    pub(super) fn new(points: &[Point], first: u32, halfedges: usize) -> Samples {
        let n = points.len();
        let mut on_vertex = vec![EMPTY; first as usize];
        on_vertex.extend(0..n as u32);
        let (head, count) = (vec![EMPTY; halfedges], vec![0; halfedges]);
        Samples { pos: points.to_vec(), head, next: vec![EMPTY; n], count, on_vertex }
    }

    /// The samples assigned to half-edge `h` (none to [`EMPTY`]).
    pub(super) fn on(&self, h: u32) -> impl Iterator<Item = u32> + '_ {
        let mut s = if h == EMPTY { EMPTY } else { self.head[h as usize] };
        std::iter::from_fn(move || {
            let current = s;
            (current != EMPTY).then(|| {
                s = self.next[current as usize];
                current
            })
        })
    }

    /// Moves the samples of half-edge `h` into `into`.
    pub(super) fn take(&mut self, h: u32, into: &mut Vec<u32>) {
        self.count[h as usize] = 0;
        let mut s = std::mem::replace(&mut self.head[h as usize], EMPTY);
        while s != EMPTY {
            into.push(s);
            s = self.next[s as usize];
        }
    }

    /// Assigns sample `s` to half-edge `h`.
    pub(super) fn push(&mut self, h: u32, s: u32) {
        self.count[h as usize] += 1;
        self.next[s as usize] = std::mem::replace(&mut self.head[h as usize], s);
    }

    /// How many samples are assigned to half-edge `h` (none to [`EMPTY`]).
    #[inline]
    pub(super) fn count(&self, h: u32) -> usize {
        if h == EMPTY {
            0
        } else {
            self.count[h as usize] as usize
        }
    }
}

/// One sample as seen from an edge `a → b`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Item {
    /// Position of its projection along the edge, 0 at `a` and 1 at `b`.
    pub(super) u: f64,
    /// Squared distance to the edge's line (the normal part of the edge plan).
    pub(super) normal: f64,
    /// Squared distance to the nearer end (its cost under the vertex plan).
    pub(super) to_end: f64,
}

/// Sample `p` seen from the edge `a → b` (`a != b`).
#[inline]
pub(super) fn item(p: Point, a: Point, b: Point) -> Item {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (px, py) = (p[0] - a[0], p[1] - a[1]);
    let inv = 1.0 / (dx * dx + dy * dy);
    let cross = dx * py - dy * px;
    Item {
        u: (px * dx + py * dy) * inv,
        normal: cross * cross * inv,
        to_end: (px * px + py * py).min(squared_distance(p, b)),
    }
}

/// The cost of the edge plan and of the vertex plan for `items` on an edge of squared length
/// `l2` (sorts `items` by `u`): `(cost, solid)`, the cheaper one and whether it is the edge
/// plan. No items cost nothing and give a ghost.
pub(super) fn edge_cost(items: &mut [Item], l2: f64) -> (f64, bool) {
    sort_by_u(items);
    merged_cost(items, &[], l2)
}

/// Sorts `items` by `u`.
pub(super) fn sort_by_u(items: &mut [Item]) {
    items.sort_unstable_by(|a, b| a.u.total_cmp(&b.u));
}

/// [`edge_cost`] of the union of `a` and `b`, both sorted by `u`.
pub(super) fn merged_cost(a: &[Item], b: &[Item], l2: f64) -> (f64, bool) {
    let m = a.len() + b.len();
    if m == 0 {
        return (0.0, false);
    }
    let bin = 1.0 / m as f64;
    let (mut normal, mut tangential, mut vertex) = (0.0, 0.0, 0.0);
    let (mut i, mut j) = (0, 0);
    for rank in 0..m {
        let it = if j == b.len() || (i < a.len() && a[i].u <= b[j].u) {
            i += 1;
            a[i - 1]
        } else {
            j += 1;
            b[j - 1]
        };
        let offset = it.u - (rank as f64 + 0.5) * bin;
        normal += it.normal;
        tangential += offset * offset;
        vertex += it.to_end;
    }
    let edge = normal + l2 * (tangential + bin / 12.0);
    if vertex >= edge {
        (edge, true)
    } else {
        (vertex, false)
    }
}

/// Where a located sample goes within its triangle: one of its corners, or the edge from
/// corner `k` to corner `k + 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Slot {
    Vertex(usize),
    Edge(usize),
}

/// The first of the counter-clockwise triangles `tris` (vertex numbers, positions from
/// `pos`), searched from `tris[hint]` on, that contains `p`, and `p`'s slot in it (see the
/// module docs). If rounding left `p` in none of them (never with exact tests on a
/// covering), the one it is least outside of.
pub(super) fn locate(
    p: Point,
    tris: &[[u32; 3]],
    hint: usize,
    pos: impl Fn(u32) -> Point,
) -> (usize, Slot) {
    let n = tris.len();
    let contains = |c: &[u32; 3]| (0..3).all(|k| orient(pos(c[k]), pos(c[(k + 1) % 3]), p) >= 0.0);
    let i = (0..n).map(|k| (hint + k) % n).find(|&i| contains(&tris[i])).unwrap_or_else(|| {
        debug_assert!(false, "sample {p:?} is in no triangle of its region");
        let outside = |c: &[u32; 3]| {
            (0..3).map(|k| orient(pos(c[k]), pos(c[(k + 1) % 3]), p)).fold(f64::INFINITY, f64::min)
        };
        (0..n).max_by(|&a, &b| outside(&tris[a]).total_cmp(&outside(&tris[b]))).unwrap()
    });
    let c = tris[i];
    if let Some(k) = (0..3).find(|&k| pos(c[k]) == p) {
        return (i, Slot::Vertex(k));
    }
    let key = [0, 1, 2].map(|k| {
        let (a, b) = (c[k], c[(k + 1) % 3]);
        (segment_distance2(p, pos(a), pos(b)), a.min(b), a.max(b))
    });
    let k = (0..3).min_by(|&x, &y| key[x].partial_cmp(&key[y]).expect("finite")).unwrap();
    (i, Slot::Edge(k))
}

/// The sign of [`orient2d`]: the floating-point determinant when its error bound (stage A of
/// Shewchuk's adaptive test) proves the sign, the exact predicate otherwise.
#[inline]
pub(super) fn orient(a: Point, b: Point, c: Point) -> f64 {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let det = left - right;
    // (3 + 16ε)ε with ε = 2^-53.
    let bound = 3.330_669_073_875_472e-16 * (left.abs() + right.abs());
    if det > bound || -det > bound {
        det
    } else {
        orient2d(a, b, c)
    }
}

/// Squared distance from `p` to the segment `ab`.
pub(super) fn segment_distance2(p: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (px, py) = (p[0] - a[0], p[1] - a[1]);
    let dot = px * dx + py * dy;
    let l2 = dx * dx + dy * dy;
    if dot <= 0.0 {
        px * px + py * py
    } else if dot >= l2 {
        squared_distance(p, b)
    } else {
        let cross = dx * py - dy * px;
        cross * cross / l2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn evenly_spread_samples_on_their_edge_cost_the_bin_variance() {
        // Four samples at the centres of the four bins of an edge of length 4: the edge plan
        // costs 4 · 1/12, the vertex plan 0.25 + 2.25 + 2.25 + 0.25.
        let (a, b) = ([0.0, 0.0], [4.0, 0.0]);
        let mut items: Vec<Item> =
            [0.5, 1.5, 2.5, 3.5].iter().map(|&x| item([x, 0.0], a, b)).collect();
        let (cost, solid) = edge_cost(&mut items, 16.0);
        assert!(solid);
        assert!((cost - 4.0 / 12.0).abs() < 1e-12, "{cost}");
    }

    #[test]
    fn merging_two_sorted_halves_is_sorting_them_together() {
        let (a, b) = ([0.0, 0.0], [4.0, 0.0]);
        let at = |x: f64, y: f64| item([x, y], a, b);
        let mut all = vec![at(0.3, 0.1), at(2.0, -0.2), at(1.1, 0.0), at(3.7, 0.4)];
        let mut left = vec![all[0], all[3]];
        let mut right = vec![all[2], all[1]];
        sort_by_u(&mut left);
        sort_by_u(&mut right);
        assert_eq!(merged_cost(&left, &right, 16.0), edge_cost(&mut all, 16.0));
    }

    #[test]
    fn filtered_orientation_agrees_with_the_exact_one() {
        let big = 2f64.powi(31);
        for (a, b, c) in [
            ([0.0, 0.0], [1.0, 0.0], [0.5, 1e-300]),
            ([big, big], [big + 1.0, big + 1.0], [big + 2.0, big + 2.0]),
            ([0.1, 0.2], [0.3, 0.6], [0.5, 1.0]),
            ([-3.0, 2.0], [4.0, 1.0], [0.0, 7.0]),
        ] {
            let sign = |x: f64| (x > 0.0) as i8 - (x < 0.0) as i8;
            assert_eq!(sign(orient(a, b, c)), sign(orient2d(a, b, c)), "{a:?} {b:?} {c:?}");
        }
    }

    #[test]
    fn samples_at_the_ends_prefer_the_vertex_plan() {
        let (a, b) = ([0.0, 0.0], [4.0, 0.0]);
        let mut items = vec![item([0.1, 0.0], a, b), item([3.9, 0.0], a, b)];
        let (cost, solid) = edge_cost(&mut items, 16.0);
        assert!(!solid);
        assert!((cost - 0.02).abs() < 1e-12);
        assert_eq!(edge_cost(&mut [], 16.0), (0.0, false));
    }

    #[test]
    fn an_offset_sample_pays_its_normal_distance() {
        let it = item([1.0, 3.0], [0.0, 0.0], [4.0, 0.0]);
        assert_eq!((it.u, it.normal, it.to_end), (0.25, 9.0, 10.0));
    }

    #[test]
    fn located_samples_go_to_the_nearest_edge_or_their_vertex() {
        let pos = |v: u32| [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [4.0, 4.0]][v as usize];
        let tris = [[0, 1, 2], [1, 3, 2]];
        assert_eq!(locate([1.0, 0.5], &tris, 0, pos), (0, Slot::Edge(0)));
        assert_eq!(locate([3.5, 2.0], &tris, 0, pos), (1, Slot::Edge(0)));
        assert_eq!(locate([4.0, 4.0], &tris, 1, pos), (1, Slot::Vertex(1)));
        // On the shared diagonal: the first triangle searched, the diagonal itself.
        assert_eq!(locate([2.0, 2.0], &tris, 0, pos), (0, Slot::Edge(1)));
        assert_eq!(locate([2.0, 2.0], &tris, 1, pos), (1, Slot::Edge(2)));
    }

    #[test]
    fn sample_lists_move_and_push() {
        let mut s = Samples::new(&[[0.0, 0.0], [1.0, 0.0]], 4, 6);
        assert_eq!(s.on_vertex, vec![EMPTY, EMPTY, EMPTY, EMPTY, 0, 1]);
        s.push(3, 0);
        s.push(3, 1);
        assert_eq!(s.on(3).collect::<Vec<_>>(), vec![1, 0]);
        let mut taken = Vec::new();
        s.take(3, &mut taken);
        assert_eq!((taken, s.on(3).count()), (vec![1, 0], 0));
    }
}
