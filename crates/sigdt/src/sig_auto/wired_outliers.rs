//! Outliers the reading went out to: cut where the sampling check sees it double back.
//!
//! The sampling check reports a vertex `v` where the reading turns by more than 150° between
//! two edges that are each at least four times the point spacing at their far ends `a` and
//! `b` ([`doubling_back`]): the reading leaves the curve at `a`, goes out to `v` and comes
//! back to `b`, next to `a`. A sample of the curve is not that far from its neighbours
//! (its nearest neighbour is a curve neighbour, [MOW22] Theorem 1, part 1), so `v` is left
//! out as an outlier and `a` joined to `b`, when `ab` is a Delaunay edge: the reading's
//! other edges are Delaunay edges too, so nothing crosses. SIG-AUTO's own outlier rules
//! (`outliers`) keep a point that the curve's straight continuation passes near, which is
//! what keeps sharp corners in; this rule keeps them too, because a corner leaves along its
//! two sides and does not come back past its neighbours.
//!
//! # Complexity
//! O(k · d) per round for k reading vertices of Delaunay degree d; at most [`MAX_ROUNDS`]
//! rounds (an outlier chain of that many points).
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::Triangulation;
use crate::sampling_check::doubling_back;

/// The most rounds of cutting (each round cuts every doubling-back vertex it finds).
const MAX_ROUNDS: usize = 4;

/// Cuts the vertices where `curves` (vertices of `dt` in order, with whether each is
/// closed) double back, in place; returns the vertices cut.
pub(super) fn cut_wired_outliers(dt: &Triangulation, curves: &mut [(Vec<u32>, bool)]) -> Vec<u32> {
    let mut cut = Vec::new();
    for _ in 0..MAX_ROUNDS {
        let before = cut.len();
        for (curve, closed) in curves.iter_mut() {
            let mut gone = vec![false; curve.len()];
            for (k, _) in doubling_back(dt, curve, *closed) {
                let n = curve.len();
                let (a, b) = ((k + n - 1) % n, (k + 1) % n);
                // Neighbours already cut would leave `a`–`b` unchecked; a loop needs three.
                let left = n - gone.iter().filter(|&&g| g).count();
                if gone[a] || gone[b] || left <= 3 || !dt.has_edge(curve[a], curve[b]) {
                    continue;
                }
                gone[k] = true;
            }
            let mut k = 0;
            curve.retain(|&v| {
                let keep = !gone[k];
                if !keep {
                    cut.push(v);
                }
                k += 1;
                keep
            });
        }
        if cut.len() == before {
            break;
        }
    }
    cut
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    #[test]
    fn an_outlier_wired_between_two_neighbours_is_cut() {
        let mut points: Vec<[f64; 2]> =
            (0..60).map(|i| TAU * i as f64 / 60.0).map(|a| [a.cos(), a.sin()]).collect();
        points.push([2.5, 0.05]);
        let dt = Triangulation::new(&points).unwrap();
        let v = dt.vertex_of_inputs();
        let mut order: Vec<u32> = (0..60).map(|i| v[i]).collect();
        order.insert(1, v[60]);
        let mut curves = vec![(order, true)];
        assert_eq!(cut_wired_outliers(&dt, &mut curves), vec![v[60]]);
        assert_eq!(curves[0].0, (0..60).map(|i| v[i]).collect::<Vec<_>>());
    }

    #[test]
    fn a_sharp_corner_stays() {
        // The tip of a wedge of half-angle 10° (it turns by 160°), sides sampled every 0.5:
        // the samples beside the tip are 0.17 apart, so the tip is not four of their
        // spacings away. (At a half-angle under 7° the sides come closer than a quarter of
        // their spacing and the tip would be cut: the sampling is then too sparse to tell.)
        let (c, s) = (10f64.to_radians().cos(), 10f64.to_radians().sin());
        let mut points = vec![[0.0, 0.0]];
        for i in 1..=20 {
            let t = 0.5 * i as f64;
            points.push([t * c, t * s]);
            points.push([t * c, -t * s]);
        }
        let dt = Triangulation::new(&points).unwrap();
        let v = dt.vertex_of_inputs();
        let mut order: Vec<u32> = (1..=20).rev().map(|i| v[2 * i - 1]).collect();
        order.push(v[0]);
        order.extend((1..=20).map(|i| v[2 * i]));
        let mut curves = vec![(order, false)];
        assert!(cut_wired_outliers(&dt, &mut curves).is_empty());
    }
}
