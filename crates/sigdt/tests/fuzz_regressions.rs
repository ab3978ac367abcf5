//! Inputs found by the fuzz targets in `fuzz/` (docs/fuzzing.md), each fed through the same
//! code path as its target: no panic, and every reconstruction passes the invariant checker.
use sigdt::internals::check_reconstruction;
use sigdt::{reconstruct, Method, Options, Point};

/// What the `reconstruct` fuzz target does with one point set.
fn reconstruct_all(points: &[Point]) {
    for &method in Method::ALL {
        for leaf_elimination in [true, false] {
            let options = Options { method, leaf_elimination, ..Options::default() };
            let rec = reconstruct(points, &options).unwrap();
            if let Err(why) = check_reconstruction(points, &rec) {
                panic!("{method} (leaf elimination {leaf_elimination}): {why}\n{rec:?}");
            }
        }
    }
}

/// Inflating left a non-manifold vertex (debug assertion in `inflate`): near-collinear
/// points from one-ulp rounding. Fuzz input `reconstruct/crash_inflate_pocket_stale` in
/// `fuzz/seeds/` (minimised).
#[test]
fn inflate_near_collinear_spike() {
    reconstruct_all(&[
        [0.0, 0.0],
        [0.0, 5.0],
        [2.0, 12.0],
        [12.0, 12.0],
        [7.0, 3.0],
        [2.0, 11.999999999999998],
        [1.0, 5.999999999999999],
        [-7.0, -24.0],
        [5.0, 2.0],
    ]);
}

/// HNN-CRUST returned two crossing edges: three points one ulp apart at 1e17 and three
/// near the origin. Ordering neighbours by `f64` squared distance could not tell the near
/// points apart and broke the tie by index, choosing a farther `nn2`. Fuzz input
/// `reconstruct/crash_hnn_crust_crossing`, minimised from 34 points.
#[test]
fn hnn_crust_far_cluster_near_ties() {
    reconstruct_all(&[
        [4.5, 4.0],
        [1e17, 1e17],
        [1e17, 9.999999999999997e16],
        [9.999999999999997e16, 1e17],
        [11.0, 4.0],
        [5.47213595499958, 11.60845213036123],
    ]);
}
