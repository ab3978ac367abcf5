//! SIGDT: the spheres-of-influence graph restricted to Delaunay edges.
//!
//! A Delaunay edge `uv` is kept iff `|uv| <= r(u) + r(v)`, where `r(x)` is the distance from
//! `x` to its nearest neighbour (the closed SIG rule of [Tou88]: the two disks of influence
//! touch or overlap). Ties are kept with a relative slack of 1e-12, so that exactly touching
//! disks (regular spacing) stay in despite rounding (our decision, `docs/algorithms.md` §1.2).
//!
//! # Guarantee
//! If the points sample a smooth closed curve with ρ < 1 and non-uniformity u < 2, SIGDT
//! contains every edge between consecutive samples ([MOW22], Theorem 1). It may contain
//! extra edges inside and outside the curve; inflating and sculpting remove them.
//!
//! # Complexity
//! O(n) time and memory given the triangulation ([MOW22] Algorithm 1, l. 3–10).
//!
//! # References
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//! - [Tou88] G. T. Toussaint. A graph-theoretical primal sketch. 1988.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
//! [Tou88]: https://doi.org/10.1016/0167-8655(88)90029-4
use super::nearest::nearest_vertex_distances;
use crate::bits::word_bit;
use crate::delaunay::{Shape, Triangulation, EMPTY};
use crate::geometry::Edge;
use crate::geometry::{distance, squared_distance};
use crate::graph::EdgeMask;

/// Relative slack of the SIG test: `|uv| <= (r(u) + r(v)) · (1 + TIE_SLACK)`.
pub(crate) const TIE_SLACK: f64 = 1e-12;

/// Whether an edge of length `len` between points with nearest-neighbour distances `ru`,
/// `rv` is a (closed) SIG edge.
#[inline]
pub(crate) fn is_sig_edge(len: f64, ru: f64, rv: f64) -> bool {
    len <= (ru + rv) * (1.0 + TIE_SLACK)
}

/// The SIGDT edges of a proper triangulation as an edge mask.
///
/// Same test as `is_sig_edge`, on squared lengths: `|uv|² <= ((r(u) + r(v))·(1 + slack))²`
/// (both sides are non-negative, so squaring keeps the order; the slack absorbs the
/// rounding difference).
pub fn sigdt_mask(dt: &Triangulation) -> EdgeMask {
    sigdt_with_degrees(dt).0
}

/// [`sigdt_mask`] and the degree of every vertex in it. Each half-edge is tested on its own
/// (the test is symmetric bit for bit: `+` commutes and `dx² + dy²` does not depend on the
/// direction), 64 to a word of the mask, in parallel when the pool has several threads;
/// then one pass over the half-edges (split among the threads, `parallel::tally`) counts,
/// at the origin of every kept half-edge (and at both ends of a kept hull half-edge, which
/// has no twin), each edge once at each end. Both passes
/// are branch-free: the test keeps about every other edge, and branching on it mispredicted
/// that often.
pub(crate) fn sigdt_with_degrees(dt: &Triangulation) -> (EdgeMask, Vec<u32>) {
    sigdt_with_degrees_for(dt, &nearest_vertex_distances(dt))
}

/// [`sigdt_with_degrees`] given every vertex's nearest-neighbour distance `r` (as
/// [`nearest_vertex_distances`] gives it), for callers that need `r` too.
pub(crate) fn sigdt_with_degrees_for(dt: &Triangulation, r: &[f64]) -> (EdgeMask, Vec<u32>) {
    let is_sig = |h: u32| {
        let (a, b) = (dt.origin(h), dt.dest(h));
        let reach = (r[a as usize] + r[b as usize]) * (1.0 + TIE_SLACK);
        squared_distance(dt.point(a), dt.point(b)) <= reach * reach
    };
    let halfedges = dt.num_halfedges();
    let words = crate::parallel::map_range(halfedges.div_ceil(64), |w| {
        (64 * w..(64 * w + 64).min(halfedges))
            .rev()
            .fold(0u64, |word, h| word << 1 | u64::from(is_sig(h as u32)))
    });
    let add_range = |range: std::ops::Range<usize>, degree: &mut [u32]| {
        for h in range.start as u32..range.end as u32 {
            let kept = u32::from(word_bit(&words, h));
            degree[dt.origin(h) as usize] += kept;
            if dt.twin(h) == EMPTY {
                degree[dt.dest(h) as usize] += kept;
            }
        }
    };
    let degree = crate::parallel::tally(halfedges, dt.num_vertices(), 0, add_range, |d, e| *d += e);
    let count = degree.iter().map(|&d| d as usize).sum::<usize>() / 2;
    (EdgeMask::from_words(words, count), degree)
}

/// The SIGDT edges as sorted input-index pairs; for collinear input, the SIG-conforming
/// segments between consecutive points.
pub(crate) fn sigdt(dt: &Triangulation) -> Vec<Edge> {
    match dt.shape() {
        Shape::Proper => sigdt_mask(dt).edges(dt),
        _ => {
            let r = nearest_vertex_distances(dt);
            let keep = dt.line_edges().filter(|&[a, b]| {
                is_sig_edge(distance(dt.point(a), dt.point(b)), r[a as usize], r[b as usize])
            });
            dt.to_input_edges(keep)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_keeps_sides_and_diagonal() {
        // Diagonal √2 <= 1 + 1: the diagonal is a SIG edge too.
        let dt = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).unwrap();
        assert_eq!(sigdt(&dt).len(), 5);
    }

    #[test]
    fn regular_polygon_with_centre_keeps_spokes() {
        // 12-gon of radius 1: side 2·sin(15°) ≈ 0.518. The centre's nearest neighbour is at
        // distance 1, so every spoke (1 <= 1 + 0.518) is a SIG edge; the Delaunay
        // triangulation is the fan, so SIGDT = 12 sides + 12 spokes.
        let mut pts: Vec<[f64; 2]> = (0..12)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 12.0;
                [a.cos(), a.sin()]
            })
            .collect();
        pts.push([0.0, 0.0]);
        let dt = Triangulation::new(&pts).unwrap();
        let edges = sigdt(&dt);
        assert_eq!(edges.len(), 24);
        assert_eq!(edges.iter().filter(|e| e.contains(&12)).count(), 12);
    }

    #[test]
    fn degrees_and_count_agree_with_the_mask() {
        // Random points (a hull with many edges) and a spiral band; counted by walking stars.
        let mut rng = crate::samplers::Rng::new(3);
        let scattered: Vec<[f64; 2]> = (0..2000).map(|_| [rng.uniform(), rng.uniform()]).collect();
        for points in [scattered, crate::samplers::spiral_band(3000).points] {
            let dt = Triangulation::new(&points).unwrap();
            let (mask, degree) = sigdt_with_degrees(&dt);
            let r = nearest_vertex_distances(&dt);
            for h in 0..dt.num_halfedges() as u32 {
                let (a, b) = (dt.origin(h), dt.dest(h));
                let kept = is_sig_edge(dt.length(h), r[a as usize], r[b as usize]);
                assert_eq!(mask.contains(h), kept, "half-edge {h}");
            }
            let walked: Vec<u32> =
                (0..dt.num_vertices() as u32).map(|v| mask.degree(&dt, v) as u32).collect();
            assert_eq!(degree, walked);
            assert_eq!(mask.len(), dt.edge_halfedges().filter(|&h| mask.contains(h)).count());
        }
    }

    #[test]
    fn collinear_gap_is_cut() {
        let dt = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [11.0, 0.0], [12.0, 0.0]]).unwrap();
        assert_eq!(sigdt(&dt), vec![[0, 1], [2, 3]]);
    }
}
