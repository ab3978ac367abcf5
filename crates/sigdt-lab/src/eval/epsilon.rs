//! The sampling density epsilon of a labelled point set, from its ground-truth graph.
//!
//! \[MOW22\] §3.1 measures how well a set samples its curve by `eps = max over x of
//! d(x, samples) / lfs(x)` with a planar-graph local feature size (Ruppert's: the radius of
//! the smallest disk centred at `x` meeting two disjoint features). Only the labelled set is
//! known here, so `x` runs over the ground-truth polygon. Variants ([`EpsilonVariant`]):
//!
//! - `Graph`, `docs/algorithms.md` §4.4 variant E: every ground-truth edge is a feature,
//!   `lfs(x)` = distance from `x` on edge `ab` to the nearest vertex other than `a`, `b` or
//!   edge touching neither. A dense uniform sample of a circle gives about 1/3 whatever its
//!   density (half a spacing over one and a half).
//! - `Ruppert`: the literal definition on the same graph. At the midpoint of edge `ab` the
//!   disk of radius `|ab|/2` meets `a` and an edge at `b`, so `eps >= 1` for every set with
//!   a vertex of degree 2; kept for calibration only.
//! - `Arcs` (default, [`graph_epsilon`]): mirrors how the data set's `epsilon` column was
//!   computed from the source curves (data/README.md): the polygon is cut into arcs at
//!   vertices turning by more than `corner_turn_deg` (and at vertices of degree ≠ 2), the
//!   arcs and their end vertices are the features, and
//!   `lfs(x) = min(Ruppert lfs on that graph, distance to the medial points of x's arc)`,
//!   the medial points being the circumcentres of the Delaunay triangles of the arc's
//!   vertices ([`medial`](super::medial)). A uniform `n`-gon gives `tan(π/n) ≈ π/n`, close
//!   to the curve's `2 sin(π/2n)`.
//!
//! Steps ([`epsilon`]): build the features ([`features`](super::features)); evaluate the
//! ratio at 64 interior parameters `k/65` of every ground-truth edge; refine the best
//! parameter of each edge whose samples come within 5 % of the running maximum by
//! golden-section search on its bracket (tolerance 1e-6 of the edge); report the maximum.
//! Vertices have ratio 0. Samples are the ground-truth vertices (outliers, points in no edge,
//! are ignored).
//!
//! # Agreement with the data set
//! `examples/epsilon_check.rs` compares both variants with the `epsilon` column of
//! `data/curves`; the numbers are in `docs/evaluation.md` (section "Epsilon").
//!
//! # Degenerate input
//! No edge gives 0. A point of the polygon touching a disjoint feature (a self-touching
//! ground truth) with a positive distance to the samples gives infinity, and so does a
//! ground truth whose edges cross (found first by a sweep, [`crossing`](super::crossing),
//! without the searches, which take quadratic time on such input). Self loops and
//! repeated edges are ignored.
//!
//! # Complexity
//! O(n log n + 64 m q) for `m` edges, with `q` the cost of a query: O(log n) on well-spread
//! curves (the searches stop once the ratio cannot beat 95 % of the running maximum). The
//! 64 samples per edge dominate.
//!
//! # References
//! - \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//! - \[Rup95\] J. Ruppert. A Delaunay refinement algorithm for quality 2-dimensional mesh
//!   generation. Journal of Algorithms 18(3), 1995.
use super::crossing::proper_crossing;
use super::features::{arc_edges, Features, Terms};
use super::input::{check_edges, check_points, proper_edges};
use sigdt::{Edge, Point, Result};

/// Which local feature size [`epsilon`] divides by; see the module docs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EpsilonVariant {
    /// `docs/algorithms.md` §4.4 variant E: distance to features disjoint from the edge.
    Graph,
    /// Ruppert's literal definition on the ground-truth graph (always ≥ 1 on a polygon).
    Ruppert,
    /// Arcs between corners, Ruppert lfs between arcs and medial lfs within them.
    Arcs {
        /// Turning angle, in degrees, above which a degree-2 vertex is a corner.
        corner_turn_deg: f64,
    },
}

impl Default for EpsilonVariant {
    fn default() -> EpsilonVariant {
        EpsilonVariant::Arcs { corner_turn_deg: 60.0 }
    }
}

/// Parameters per edge evaluated before refinement (`docs/algorithms.md` §4.4 step 3).
const SAMPLES: usize = 64;
/// Edges whose samples reach this fraction of the running maximum are refined.
const REFINE: f64 = 0.95;

/// The epsilon of `points` labelled by `gt` with the default variant
/// ([`EpsilonVariant::default`]). Fails on non-finite points or edges out of range.
pub fn graph_epsilon(points: &[Point], gt: &[Edge]) -> Result<f64> {
    epsilon(points, gt, EpsilonVariant::default())
}

/// The epsilon of `points` labelled by `gt` with the given variant.
pub fn epsilon(points: &[Point], gt: &[Edge], variant: EpsilonVariant) -> Result<f64> {
    check_points(points)?;
    check_edges("ground-truth", gt, points.len())?;
    let terms = match variant {
        EpsilonVariant::Graph => Terms { corner_turn: None, pairs: false, medial: false },
        EpsilonVariant::Ruppert => Terms { corner_turn: None, pairs: true, medial: false },
        EpsilonVariant::Arcs { corner_turn_deg } => {
            Terms { corner_turn: Some(corner_turn_deg.to_radians()), pairs: true, medial: true }
        }
    };
    let edges = proper_edges(gt);
    if proper_crossing(points, &edges).is_some() {
        // The curve meets itself there: its local feature size is 0 (every variant).
        return Ok(f64::INFINITY);
    }
    let mut vertices: Vec<usize> = edges.iter().flatten().copied().collect();
    vertices.sort_unstable();
    vertices.dedup();
    let samples: Vec<Point> = vertices.iter().map(|&v| points[v]).collect();
    let features = Features::new(points, &samples, &edges, terms)?;
    let mut eps = 0.0f64;
    let mut near = Vec::new();
    for (a, arc) in features.arcs.iter().enumerate() {
        for [i, j] in arc_edges(arc) {
            let (p, q) = (points[i], points[j]);
            let at = |t: f64| [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            // One search an edge instead of one a parameter: its samples' nearest candidates.
            let candidates = features.samples_near_edge(p, q, &mut near).then_some(&near[..]);
            let cap = REFINE * eps;
            let (mut best, mut best_k) = (0.0f64, 0);
            for k in 1..=SAMPLES {
                let r = features.ratio(at(k as f64 / (SAMPLES + 1) as f64), candidates, a, cap);
                if r > best {
                    (best, best_k) = (r, k);
                }
            }
            eps = eps.max(best);
            if best > cap && best.is_finite() {
                let f = |t: f64| features.ratio(at(t), candidates, a, cap);
                let step = 1.0 / (SAMPLES + 1) as f64;
                let t = best_k as f64 * step;
                eps = eps.max(golden_max(f, t - step, t + step, 1e-6));
            }
        }
    }
    Ok(eps)
}

/// Golden-section search for the maximum of `f` on `[lo, hi]` down to width `tol`; returns
/// the largest value seen.
fn golden_max(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, tol: f64) -> f64 {
    const INV_PHI: f64 = 0.618_033_988_749_894_9;
    let mut x1 = hi - INV_PHI * (hi - lo);
    let mut x2 = lo + INV_PHI * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    let mut best = f1.max(f2);
    while hi - lo > tol {
        if f1 >= f2 {
            (hi, x2, f2) = (x2, x1, f1);
            x1 = hi - INV_PHI * (hi - lo);
            f1 = f(x1);
            best = best.max(f1);
        } else {
            (lo, x1, f1) = (x1, x2, f2);
            x2 = lo + INV_PHI * (hi - lo);
            f2 = f(x2);
            best = best.max(f2);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::super::grid::lerp;
    use super::*;
    use std::f64::consts::PI;

    fn ngon(n: usize) -> (Vec<Point>, Vec<Edge>) {
        let pts = (0..n)
            .map(|i| {
                let a = i as f64 * 2.0 * PI / n as f64;
                [a.cos(), a.sin()]
            })
            .collect();
        (pts, (0..n).map(|i| [i.min((i + 1) % n), i.max((i + 1) % n)]).collect())
    }

    #[test]
    fn circle_with_the_medial_definition() {
        for n in [12, 50, 200] {
            let (pts, gt) = ngon(n);
            let eps = graph_epsilon(&pts, &gt).unwrap();
            // Midpoint of a chord: sin(π/n) from the samples, cos(π/n) from the centre.
            assert!((eps - (PI / n as f64).tan()).abs() < 1e-6, "{n}: {eps}");
        }
    }

    #[test]
    fn circle_with_variant_e_is_about_a_third() {
        for n in [50, 200] {
            let (pts, gt) = ngon(n);
            let eps = epsilon(&pts, &gt, EpsilonVariant::Graph).unwrap();
            assert!((eps - 1.0 / 3.0).abs() < 0.01, "{n}: {eps}");
            let literal = epsilon(&pts, &gt, EpsilonVariant::Ruppert).unwrap();
            assert!(literal >= 1.0 - 1e-6, "{n}: {literal}");
        }
    }

    #[test]
    fn square_corners_split_arcs() {
        // The unit square sampled at its corners only: each side is an arc between two
        // corners with no interior sample, so eps = 1 (data/README.md).
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let gt = [[0, 1], [1, 2], [2, 3], [0, 3]];
        let eps = graph_epsilon(&sq, &gt).unwrap();
        assert!((eps - 1.0).abs() < 1e-6, "{eps}");
        // With one midpoint per side the midpoints halve the distance to the samples.
        let mut pts = sq.to_vec();
        pts.extend([[0.5, 0.0], [1.0, 0.5], [0.5, 1.0], [0.0, 0.5]]);
        let gt = [[0, 4], [1, 4], [1, 5], [2, 5], [2, 6], [3, 6], [3, 7], [0, 7]];
        let eps = graph_epsilon(&pts, &gt).unwrap();
        assert!(eps > 0.2 && eps < 0.6, "{eps}");
    }

    #[test]
    fn an_edges_candidates_give_the_nearest_sample_of_every_place() {
        // Random polylines (long edges beside dense runs, points of the input that are no
        // sample): the ratio from an edge's candidates is the k-d tree's, bit for bit.
        let mut rng = sigdt::samplers::Rng::new(5);
        for case in 0..200 {
            let n = 3 + rng.below(40);
            let points: Vec<Point> = (0..n)
                .map(|_| match rng.below(3) {
                    0 => [rng.uniform() * 0.01, rng.uniform() * 0.01],
                    _ => [rng.uniform(), rng.uniform()],
                })
                .collect();
            let gt: Vec<Edge> = (1..n - 2).map(|i| [i - 1, i]).collect();
            let edges = proper_edges(&gt);
            let mut vertices: Vec<usize> = edges.iter().flatten().copied().collect();
            vertices.sort_unstable();
            vertices.dedup();
            let samples: Vec<Point> = vertices.iter().map(|&v| points[v]).collect();
            let terms = Terms { corner_turn: Some(1.0), pairs: true, medial: true };
            let features = Features::new(&points, &samples, &edges, terms).unwrap();
            let mut near = Vec::new();
            for (a, arc) in features.arcs.iter().enumerate() {
                for [i, j] in arc_edges(arc) {
                    let (p, q) = (points[i], points[j]);
                    let Some(near) = features.samples_near_edge(p, q, &mut near).then_some(&near)
                    else {
                        continue;
                    };
                    for k in 0..=20 {
                        let x = lerp(p, q, k as f64 / 20.0);
                        let (with, without) = (
                            features.ratio(x, Some(near), a, 0.0),
                            features.ratio(x, None, a, 0.0),
                        );
                        assert_eq!(with.to_bits(), without.to_bits(), "case {case}, edge {i} {j}");
                    }
                }
            }
        }
    }

    #[test]
    fn degenerate_inputs() {
        let line = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [5.0, 5.0]];
        assert_eq!(graph_epsilon(&line, &[]).unwrap(), 0.0);
        assert_eq!(graph_epsilon(&line, &[[1, 1]]).unwrap(), 0.0);
        let eps = graph_epsilon(&line, &[[0, 1], [1, 2]]).unwrap();
        assert!(eps.is_finite());
        // Duplicate points and a self-touching ground truth do not panic.
        let dup = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        for v in [EpsilonVariant::Graph, EpsilonVariant::Ruppert, EpsilonVariant::default()] {
            assert!(epsilon(&dup, &[[0, 1], [1, 2], [2, 3], [0, 3]], v).is_ok());
        }
        assert!(graph_epsilon(&line, &[[0, 4]]).is_err());
    }

    #[test]
    fn a_ground_truth_that_crosses_itself_has_infinite_epsilon_in_every_variant() {
        // A bow tie: 0-2 and 1-3 cross at (0.5, 0.5).
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let bow_tie = [[0, 2], [2, 1], [1, 3], [3, 0]];
        for v in [EpsilonVariant::Graph, EpsilonVariant::Ruppert, EpsilonVariant::default()] {
            assert_eq!(epsilon(&pts, &bow_tie, v).unwrap(), f64::INFINITY, "{v:?}");
        }
    }
}
