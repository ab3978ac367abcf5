//! How much of the ground truth each proximity graph contains, and how they overlap.
//!
//! The statistics of \[MOW22\] §5 (`docs/algorithms.md` §4.10), for one labelled point set; average
//! them over sets yourself (the paper takes the arithmetic mean of per-set percentages):
//!
//! | field | formula | paper (mean over 1257 manifold sets) |
//! |---|---|---|
//! | `sig_in_dt` | `|SIG ∩ DT| / |SIG|` | 90.9 % |
//! | `dt_in_sig` | `|SIG ∩ DT| / |DT|` | 47.2 % |
//! | `sigdt_in_gt` | `|GT ∩ SIGDT| / |SIGDT|` | 76.8 % |
//! | `gt_in.sigdt` | `|GT ∩ SIGDT| / |GT|` | 99.9 % |
//! | `gt_in.bc0` | `|GT ∩ BC₀| / |GT|` | 99.6 % |
//! | `gt_in.knn2..4` | `|GT ∩ kNN| / |GT|`, union kNN graph | 98.4, 98.5, 98.6 % |
//!
//! Each [`Coverage`] also says whether the graph contains the whole ground truth (the paper's
//! "contained in almost all cases" may mean either). BC₀ is the EMST plus, at every leaf,
//! its shortest missing Delaunay edge, as in CONNECT2D (`sigdt`'s `baselines/connect2d.rs`).
//!
//! Duplicates: the graphs are built on the distinct points, a duplicate standing for itself
//! through its lowest-index twin. Ground-truth edges are mapped the same way; edges that
//! collapse to a point (and self loops) are dropped, repeated edges count once. A ratio with
//! an empty denominator is 1 (nothing to miss).
//!
//! # Complexity
//! O(n log n) (the triangulation and the graphs).
//!
//! # References
//! - \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use super::input::{check_edges, check_points, proper_edges};
use sigdt::delaunay::Shape;
use sigdt::internals::{eliminate_leaves, emst_mask};
use sigdt::proximity_graph_on;
use sigdt::Triangulation;
use sigdt::{Edge, GraphKind, Point, Result};

/// How much of the ground truth one graph contains.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coverage {
    /// `|GT ∩ G| / |GT|`.
    pub fraction: f64,
    /// Whether every ground-truth edge is in `G`.
    pub contains: bool,
}

/// [`Coverage`] of the ground truth by each graph of Marin et al. 2022, §5.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GtCoverage {
    /// SIGDT = SIG ∩ DT.
    pub sigdt: Coverage,
    /// SIGDT after leaf elimination.
    pub sigdt2: Coverage,
    /// BC₀, CONNECT2D's initial graph (EMST plus leaf edges).
    pub bc0: Coverage,
    /// The 2-nearest-neighbour graph (undirected union).
    pub knn2: Coverage,
    /// The 3-nearest-neighbour graph.
    pub knn3: Coverage,
    /// The 4-nearest-neighbour graph.
    pub knn4: Coverage,
}

/// Proximity-graph statistics of one labelled point set; see the module docs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overlap {
    /// `|SIG ∩ DT| / |SIG|`.
    pub sig_in_dt: f64,
    /// `|SIG ∩ DT| / |DT|`.
    pub dt_in_sig: f64,
    /// `|GT ∩ SIGDT| / |SIGDT|`: the share of SIGDT that is ground truth.
    pub sigdt_in_gt: f64,
    /// How much of the ground truth each graph contains.
    pub gt_in: GtCoverage,
}

/// The overlap statistics of `points` with ground truth `gt`. Fails on non-finite points,
/// ground-truth edges out of range, or points the triangulation cannot handle.
pub fn overlap(points: &[Point], gt: &[Edge]) -> Result<Overlap> {
    check_points(points)?;
    check_edges("ground-truth", gt, points.len())?;
    let dt = Triangulation::new(points)?;
    let mut rep: Vec<usize> = (0..points.len()).collect();
    for &[dup, first] in dt.duplicates() {
        rep[dup] = first;
    }
    let gt: Vec<Edge> =
        proper_edges(&gt.iter().map(|&[i, j]| [rep[i], rep[j]]).collect::<Vec<_>>());
    let graph = |kind| proximity_graph_on(&dt, kind);
    let (all, sig, sigdt) = (graph(GraphKind::Dt), graph(GraphKind::Sig), graph(GraphKind::SigDt));
    let bc0 = match dt.shape() {
        Shape::Proper => {
            let mut mask = emst_mask(&dt);
            eliminate_leaves(&dt, &mut mask);
            mask.edges(&dt)
        }
        _ => all.clone(),
    };
    let common = |a: &[Edge], b: &[Edge]| a.iter().filter(|e| b.binary_search(e).is_ok()).count();
    let coverage = |g: &[Edge]| {
        let hit = common(&gt, g);
        Coverage { fraction: ratio(hit, gt.len()), contains: hit == gt.len() }
    };
    let sig_dt = common(&sig, &all);
    Ok(Overlap {
        sig_in_dt: ratio(sig_dt, sig.len()),
        dt_in_sig: ratio(sig_dt, all.len()),
        sigdt_in_gt: ratio(common(&sigdt, &gt), sigdt.len()),
        gt_in: GtCoverage {
            sigdt: coverage(&sigdt),
            sigdt2: coverage(&graph(GraphKind::SigDt2)),
            bc0: coverage(&bc0),
            knn2: coverage(&graph(GraphKind::Knn { k: 2 })),
            knn3: coverage(&graph(GraphKind::Knn { k: 3 })),
            knn4: coverage(&graph(GraphKind::Knn { k: 4 })),
        },
    })
}

/// `a / b`, and 1 when `b` is 0.
fn ratio(a: usize, b: usize) -> f64 {
    if b == 0 {
        1.0
    } else {
        a as f64 / b as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn polygon(n: usize) -> (Vec<Point>, Vec<Edge>) {
        let pts = (0..n)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / n as f64;
                [(1.0 + 0.2 * (3.0 * a).cos()) * a.cos(), (1.0 + 0.2 * (3.0 * a).cos()) * a.sin()]
            })
            .collect();
        let gt = (0..n).map(|i| [i.min((i + 1) % n), i.max((i + 1) % n)]).collect();
        (pts, gt)
    }

    #[test]
    fn dense_curve_is_contained_in_every_graph() {
        let (pts, gt) = polygon(60);
        let o = overlap(&pts, &gt).unwrap();
        let g = o.gt_in;
        for c in [g.sigdt, g.sigdt2, g.bc0, g.knn2, g.knn3, g.knn4] {
            assert_eq!(c, Coverage { fraction: 1.0, contains: true });
        }
        assert!(o.sigdt_in_gt > 0.5 && o.sigdt_in_gt <= 1.0);
        assert!(o.sig_in_dt > 0.0 && o.sig_in_dt <= 1.0 && o.dt_in_sig < 1.0);
    }

    #[test]
    fn duplicates_and_degenerate_input_do_not_panic() {
        let (mut pts, mut gt) = polygon(12);
        pts.push(pts[3]);
        gt.extend([[3, 12], [4, 12], [4, 12]]); // collapses to [3, 3]; duplicates [3, 4]
        let o = overlap(&pts, &gt).unwrap();
        assert!(o.gt_in.sigdt.contains);
        let line: Vec<Point> = (0..5).map(|i| [i as f64, 0.0]).collect();
        let o = overlap(&line, &[[0, 1], [1, 2]]).unwrap();
        assert!(o.gt_in.bc0.contains);
        let o = overlap(&[], &[]).unwrap();
        assert_eq!(o.gt_in.sigdt.fraction, 1.0);
        assert!(overlap(&line, &[[0, 5]]).is_err());
    }
}
