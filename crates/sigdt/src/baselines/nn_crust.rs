//! NN-CRUST: every point joined to its nearest neighbour and to its nearest "half neighbour".
//!
//! [DK99], `docs/algorithms.md` §3.2, on the Delaunay triangulation (given):
//! 1. for each point `p`, its nearest neighbour `q`: the other end of the shortest Delaunay
//!    edge at `p` (every nearest-neighbour edge is a Delaunay edge); add `pq`;
//! 2. for each `p`, among the Delaunay edges `ps` with `(s - p)·(q - p) <= 0` (the angle
//!    `qps` is at least 90°: `s` lies in the closed half-plane through `p` away from `q`),
//!    the shortest one, the half neighbour; add `ps` if there is one;
//! 3. the union of both sets.
//!
//! Lengths are compared as `f64` squared lengths with ties broken by input index; the
//! half-plane test is exact (an error-free expansion of the dot product, see
//! `sign_of_sum_of_products`).
//!
//! # Guarantee
//! If the points are an ε-sample of a smooth closed curve with ε < 1/3, NN-CRUST returns
//! exactly the polygon connecting curve neighbours ([DK99]; bound as quoted in [MOW22]).
//! Otherwise nothing is promised: every point gets degree ≥ 1 and usually 2, so the
//! endpoints of an open curve get a wrong "half neighbour" edge, and undersampled regions
//! give crossings or chords.
//!
//! # Complexity
//! O(n) given the triangulation (each Delaunay edge is looked at twice per step), so
//! O(n log n) in all.
//!
//! # Departures
//! [DK99] looks for the half neighbour among all points; following `docs/algorithms.md` §3.2 only
//! Delaunay neighbours are candidates. The two agree whenever the nearest point in the
//! half-plane is a Delaunay neighbour, which the ε < 1/3 proof of [DK99] establishes.
//!
//! # References
//! - [DK99] T. K. Dey, P. Kumar. A simple provable algorithm for curve reconstruction.
//!   SODA 1999.
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [DK99]: https://dl.acm.org/doi/10.5555/314500.315085
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::Triangulation;
use crate::geometry::{squared_distance, Point};
use std::cmp::Ordering;

/// The NN-CRUST edges of `dt` (a [`Shape::Proper`](crate::delaunay::Shape::Proper)
/// triangulation) as pairs of vertices; an edge may appear twice.
pub fn nn_crust(dt: &Triangulation) -> Vec<[u32; 2]> {
    // Each point's two edges on their own (in parallel on a pool), listed in point order.
    let chosen = crate::parallel::map_range(dt.num_vertices(), |p| {
        let p = p as u32;
        let pp = dt.point(p);
        // (squared length, input index, vertex) of a neighbour; smaller is nearer.
        let key = |s: u32| (squared_distance(pp, dt.point(s)), dt.input_index(s), s);
        let nearer =
            |a: &(f64, usize, u32), b: &(f64, usize, u32)| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1));
        let neighbours = || dt.incident(p).map(|h| dt.other(h, p));
        // Step 1: nearest neighbour.
        let Some((_, _, q)) = neighbours().map(key).min_by(nearer) else {
            return [None, None]; // unreachable: every vertex of a proper triangulation has an edge
        };
        // Step 2: nearest neighbour in the closed half-plane away from q.
        let qq = dt.point(q);
        let half = neighbours()
            .filter(|&s| dot_sign(pp, qq, dt.point(s)) != Ordering::Greater)
            .map(key)
            .min_by(nearer);
        [Some([p, q]), half.map(|(_, _, s)| [p, s])]
    });
    chosen.into_iter().flatten().flatten().collect()
}

/// The exact sign of `(s - p)·(q - p)`.
fn dot_sign(p: Point, q: Point, s: Point) -> Ordering {
    // (s - p)·(q - p) = s·q - s·p - p·q + p·p, coordinate by coordinate.
    let [px, py] = p;
    let [qx, qy] = q;
    let [sx, sy] = s;
    sign_of_sum_of_products(&[
        (sx, qx),
        (-sx, px),
        (-px, qx),
        (px, px),
        (sy, qy),
        (-sy, py),
        (-py, qy),
        (py, py),
    ])
}

/// The exact sign of `Σ a·b` over `terms` (at most 8), as `Ordering` against zero.
///
/// A floating-point sum decides when it is clear of its error bound; otherwise each product
/// is split into two doubles without error (Dekker's product) and the sum is accumulated
/// as a Shewchuk expansion, whose largest component has the sign of the exact sum. Exact
/// for factors of magnitude in `[2^-142, 2^201]` or zero, the range
/// [`Triangulation`] guarantees (products then neither overflow nor underflow).
pub(crate) fn sign_of_sum_of_products(terms: &[(f64, f64)]) -> Ordering {
    debug_assert!(terms.len() <= 8);
    let (mut sum, mut magnitude) = (0.0f64, 0.0f64);
    for &(a, b) in terms {
        sum += a * b;
        magnitude += (a * b).abs();
    }
    // Each product and partial sum rounds with relative error 2^-53; 8 terms give well
    // under 10 · ε · Σ|ab| in total.
    if sum.abs() > 10.0 * f64::EPSILON * magnitude {
        return sum.total_cmp(&0.0);
    }
    let mut expansion = [0.0f64; 16];
    let mut len = 0;
    for &(a, b) in terms {
        let (hi, lo) = two_product(a, b);
        for part in [lo, hi] {
            len = grow_expansion(&mut expansion, len, part);
        }
    }
    expansion[..len]
        .iter()
        .rev()
        .find(|&&x| x != 0.0)
        .map_or(Ordering::Equal, |x| x.total_cmp(&0.0))
}

/// Adds `b` to the nonoverlapping expansion `e[..len]` (increasing magnitude, no zeros)
/// and returns the new length (Shewchuk's Grow-Expansion with zero elimination).
fn grow_expansion(e: &mut [f64; 16], len: usize, b: f64) -> usize {
    let mut q = b;
    let mut k = 0;
    for i in 0..len {
        let (sum, err) = two_sum(q, e[i]);
        if err != 0.0 {
            e[k] = err;
            k += 1;
        }
        q = sum;
    }
    if q != 0.0 {
        e[k] = q;
        k += 1;
    }
    k
}

/// `a + b = x + y` exactly, with `x = fl(a + b)` (Knuth's Two-Sum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    let bv = x - a;
    let av = x - bv;
    (x, (a - av) + (b - bv))
}

/// `a · b = x + y` exactly, with `x = fl(a · b)` (Dekker's Two-Product, no FMA needed).
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let x = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let err = x - ah * bh - al * bh - ah * bl;
    (x, al * bl - err)
}

/// `a = hi + lo` with both halves of at most 26 significant bits (Dekker's split).
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Edge;
    use crate::internals::filter_edges;
    use crate::samplers::cycle_edges as cycle;
    use crate::samplers::regular_polygon;

    fn nn_crust_edges(points: &[Point]) -> Vec<Edge> {
        filter_edges(points, nn_crust)
    }

    #[test]
    fn exact_sign_beyond_the_floating_point_sum() {
        // p, q, s on a line through huge coordinates: the naive dot product cancels.
        let big = 2f64.powi(30);
        assert_eq!(dot_sign([big, big], [big + 1.0, big], [big, big + 1.0]), Ordering::Equal);
        let tiny = 2f64.powi(-20);
        assert_eq!(dot_sign([big, 0.0], [big + 1.0, 0.0], [big - tiny, 1.0]), Ordering::Less);
        assert_eq!(dot_sign([big, 0.0], [big + 1.0, 0.0], [big + tiny, 1.0]), Ordering::Greater);
        assert_eq!(
            sign_of_sum_of_products(&[(1e30, 1e30), (-1e30, 1e30), (1e-40, 1e-40)]),
            Ordering::Greater
        );
        assert_eq!(sign_of_sum_of_products(&[]), Ordering::Equal);
    }

    #[test]
    fn regular_16_gon_gives_its_sides() {
        let pts = regular_polygon(16, 1.0).points;
        assert_eq!(nn_crust_edges(&pts), cycle(16));
    }

    #[test]
    fn dense_circle_is_reconstructed_exactly() {
        let n = 300;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * (i as f64 + 0.41) / n as f64;
                [2.0 * t.cos() - 1.0, 1.5 * t.sin() + 3.0]
            })
            .collect();
        assert_eq!(nn_crust_edges(&pts), cycle(n));
    }

    #[test]
    fn half_neighbour_on_a_small_case() {
        // Delaunay edges 01, 13, 32, 20 (hull) and 03. Point 0's nearest is 1; its half-plane
        // x <= 0 holds 2 and 3, and 2 is nearer. Points 1, 2, 3 all have 0 as nearest and no
        // Delaunay neighbour in the half-plane away from it.
        let pts = [[0.0, 0.0], [1.0, 0.0], [-2.0, 0.5], [0.0, 3.0]];
        assert_eq!(nn_crust_edges(&pts), vec![[0, 1], [0, 2], [0, 3]]);
    }

    fn ellipse_arc(n: usize, degrees: f64) -> Vec<Point> {
        (0..n)
            .map(|i| {
                let t = degrees.to_radians() * i as f64 / (n - 1) as f64;
                [1.3 * t.cos(), t.sin()]
            })
            .collect()
    }

    #[test]
    fn open_arcs() {
        // A quarter arc is convex and short: the endpoints have no half neighbour, and the
        // result is the path.
        let n = 20;
        let path: Vec<Edge> = (0..n - 1).map(|i| [i, i + 1]).collect();
        assert_eq!(nn_crust_edges(&ellipse_arc(n, 90.0)), path);
        // A 300° arc: each endpoint takes the other as half neighbour across the gap, so the
        // arc is closed into a polygon (the wrong edge `docs/algorithms.md` §3.2 warns about).
        let n = 60;
        assert_eq!(nn_crust_edges(&ellipse_arc(n, 300.0)), cycle(n));
    }

    #[test]
    fn permuting_the_input_relabels_the_output() {
        let n = 80;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * (i as f64 + 0.23) / n as f64;
                let r = 1.0 + 0.3 * (2.0 * t).cos();
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let perm: Vec<usize> = (0..n).map(|i| (i * 31 + 7) % n).collect();
        let permuted: Vec<Point> = perm.iter().map(|&i| pts[i]).collect();
        let mut back: Vec<Edge> = nn_crust_edges(&permuted)
            .into_iter()
            .map(|[a, b]| [perm[a].min(perm[b]), perm[a].max(perm[b])])
            .collect();
        back.sort_unstable();
        assert_eq!(back, nn_crust_edges(&pts));
    }
}
