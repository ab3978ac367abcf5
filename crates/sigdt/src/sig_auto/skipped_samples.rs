//! Samples the reading skipped: points left out as outliers that lie within the sampling of
//! the result's curves, put back into the edge they lie beside.
//!
//! The sampling check reports a point left out as an outlier that lies within half its own
//! spacing of a result edge, or nearer to a result vertex than half that vertex's longer
//! edge (`outliers-on-curve`, `docs/sampling-check.md`): under u < 2 no sample is that near
//! to a curve it does not belong to ([MOW22] Theorem 1, part 1). Where the outlier rules
//! and the check disagree so, the point is a sample the reading went past, usually where
//! two curves come closer than their spacing and a round of reading joined the wrong ones.
//! A point `v` within half its spacing of a result edge `ab` is put back between `a` and
//! `b` when `av` and `vb` are Delaunay edges that cross no result edge: Delaunay edges
//! never cross one another, so only the edges of a coarse reading, which are not all
//! Delaunay edges, are tested (with exact predicates). The result then turns at `v`
//! by less than 60°, what a curve sampled with ε < 1 turns at a sample: `v` is at least its
//! spacing from `a` and from `b`, so each side of the triangle `avb` makes an angle of
//! less than 30° with `ab`. The check's other rule, a point nearer to a vertex than half
//! that vertex's longer edge, puts nothing back: where the reading is wrong that edge is
//! long, and the rule holds for outliers beside it.
//!
//! Of the edges a point may go into, the one it lengthens least is taken (ties by the input
//! indices of the edge's ends), and points are put back in ascending order, each into the
//! result as the ones before left it.
//!
//! # Complexity
//! O(m + k · d · (d + f)) for m result edges, k outliers of Delaunay degree d and f result
//! edges that are not Delaunay edges (none but after a coarse reading).
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use super::isolated::crosses;
use super::reading::{Reading, NONE};
use crate::geometry::{distance, segment_distance};

/// Puts the `outliers` (vertices of `reading`'s triangulation, ascending) that lie within the
/// sampling of `reading`'s curves back into it (module docs); returns those put back,
/// ascending.
pub(super) fn put_back_skipped(reading: &mut Reading<'_>, outliers: &[u32]) -> Vec<u32> {
    if outliers.is_empty() {
        return Vec::new();
    }
    let dt = reading.dt;
    // Result edges that are not Delaunay edges: the only ones a Delaunay edge can cross.
    let foreign: Vec<[u32; 2]> =
        reading.pairs().into_iter().filter(|&[a, b]| !dt.has_edge(a, b)).collect();
    let mut back = Vec::new();
    for &v in outliers {
        let p = dt.point(v);
        let spacing = dt.incident(v).map(|h| dt.length(h)).fold(f64::INFINITY, f64::min);
        let delaunay: Vec<u32> = dt.incident(v).map(|h| dt.other(h, v)).collect();
        // Each reading edge `ab` with `a` a Delaunay neighbour of `v`: the candidates.
        let mut best: Option<(f64, [usize; 2], u32, u32)> = None;
        for &a in &delaunay {
            for b in reading.neighbours(a) {
                if b == NONE || !delaunay.contains(&b) {
                    continue;
                }
                let (pa, pb) = (dt.point(a), dt.point(b));
                let key = [a.min(b), a.max(b)];
                if segment_distance(p, pa, pb) >= 0.5 * spacing
                    || crosses(dt, &[a, v, b], &foreign, key)
                {
                    continue;
                }
                let longer_by = distance(pa, p) + distance(p, pb) - distance(pa, pb);
                let (i, j) = (dt.input_index(a), dt.input_index(b));
                let by_input = [i.min(j), i.max(j)];
                let better = match best {
                    None => true,
                    Some((cost, at, _, _)) => {
                        longer_by < cost || (longer_by == cost && by_input < at)
                    }
                };
                if better {
                    best = Some((longer_by, by_input, a, b));
                }
            }
        }
        if let Some((_, _, a, b)) = best {
            reading.relink(a, b, v);
            reading.relink(b, a, v);
            reading.relink(v, NONE, a);
            reading.relink(v, NONE, b);
            back.push(v);
        }
    }
    back
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::Triangulation;
    use std::f64::consts::TAU;

    fn circle(n: usize) -> Vec<[f64; 2]> {
        (0..n).map(|i| TAU * i as f64 / n as f64).map(|a| [a.cos(), a.sin()]).collect()
    }

    #[test]
    fn a_skipped_sample_goes_back_between_its_neighbours() {
        let points = circle(40);
        let dt = Triangulation::new(&points).unwrap();
        let v = dt.vertex_of_inputs();
        // The loop without sample 5, which is left out as an outlier.
        let order: Vec<u32> = (0..40).filter(|&i| i != 5).map(|i| v[i]).collect();
        let pairs: Vec<[u32; 2]> =
            (0..order.len()).map(|k| [order[k], order[(k + 1) % order.len()]]).collect();
        let mut reading = Reading::new(&dt, &pairs);
        assert_eq!(put_back_skipped(&mut reading, &[v[5]]), vec![v[5]]);
        let mut slots = reading.neighbours(v[5]);
        slots.sort_unstable();
        let mut expected = [v[4], v[6]];
        expected.sort_unstable();
        assert_eq!(slots, expected);
        assert!(!reading.joined(v[4], v[6]));
    }

    #[test]
    fn an_outlier_off_the_curve_stays_out() {
        // Two spacings outside a circle of 40 samples: its nearest point is about as far as
        // the curve, so it is not within half its spacing of any edge.
        let mut points = circle(40);
        points.push([1.3 * (0.3f64).cos(), 1.3 * (0.3f64).sin()]);
        let dt = Triangulation::new(&points).unwrap();
        let v = dt.vertex_of_inputs();
        let pairs: Vec<[u32; 2]> = (0..40).map(|k| [v[k], v[(k + 1) % 40]]).collect();
        let mut reading = Reading::new(&dt, &pairs);
        assert!(put_back_skipped(&mut reading, &[v[40]]).is_empty());
        assert_eq!(reading.degree(v[40]), 0);
    }
}
