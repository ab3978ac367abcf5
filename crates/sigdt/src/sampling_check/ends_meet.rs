//! The sampling check's seventh property: open ends that meet.
//!
//! An open curve sampled with u < 2 ([MOW22] Theorem 1) ends where its samples end. Where
//! two ends of the reading's open paths (of two paths, or the two ends of one) lie closer
//! to each other than [`LONG_EDGE_RATIO`] times the longer of their last edges (twice the
//! bound u < 2, as for the long edges of property 2: real samplings are less regular than
//! the theorem asks), an edge between them would be an edge like the others: the reading
//! cannot tell a curve that stops there from one that goes on (two pieces of one curve, or
//! a closed curve read open).
//!
//! Only ends that are Delaunay neighbours count: a point between two ends is nearer to
//! each of them than they are to each other, which property 4 (`open-ends`) reads.
//!
//! # Complexity
//! O(e · (d + log e)) for e path ends of mean Delaunay degree d.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use super::{Finding, FindingKind, LONG_EDGE_RATIO};
use crate::delaunay::Triangulation;

/// One end of an open path of a result.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PathEnd {
    /// The end vertex.
    pub end: u32,
    /// Its neighbour along the path.
    pub next: u32,
    /// The length of the edge between them.
    pub last: f64,
}

/// The finding of this module on the `ends` of a result's open paths, if any: pairs of ends
/// that are Delaunay neighbours, not joined by a path edge, nearer to each other than
/// [`LONG_EDGE_RATIO`] times the longer of their last edges. The worst is the smallest gap
/// over that longer edge, at the lower input index of its pair.
pub(crate) fn ends_meet(dt: &Triangulation, ends: &[PathEnd]) -> Option<Finding> {
    let mut by_vertex: Vec<PathEnd> = ends.to_vec();
    by_vertex.sort_unstable_by_key(|e| e.end);
    let lookup = |v: u32| by_vertex.binary_search_by_key(&v, |e| e.end).ok().map(|k| by_vertex[k]);
    let (mut count, mut worst, mut at, mut vertex) = (0, f64::INFINITY, usize::MAX, u32::MAX);
    for a in &by_vertex {
        for h in dt.incident(a.end) {
            let Some(b) = lookup(dt.other(h, a.end)) else { continue };
            // Each pair once, and not the two ends of a one-edge path.
            if b.end < a.end || a.next == b.end || b.next == a.end {
                continue;
            }
            let ratio = dt.length(h) / a.last.max(b.last);
            if ratio < LONG_EDGE_RATIO {
                count += 1;
                let nearer =
                    if dt.input_index(a.end) < dt.input_index(b.end) { a.end } else { b.end };
                let index = dt.input_index(nearer);
                if ratio < worst || (ratio == worst && index < at) {
                    (worst, at, vertex) = (ratio, index, nearer);
                }
            }
        }
    }
    (count > 0).then(|| {
        let point = super::given_point(dt, vertex);
        Finding { kind: FindingKind::EndsMeet, count, worst, at, point }
    })
}

#[cfg(test)]
mod tests {
    use crate::geometry::Point;
    use crate::result::Reconstruction;
    use crate::sampling_check::{diagnose, Finding, FindingKind};
    use std::f64::consts::TAU;

    fn circle(n: usize) -> Vec<Point> {
        (0..n).map(|i| TAU * i as f64 / n as f64).map(|a| [a.cos(), a.sin()]).collect()
    }

    fn ends_meet(points: &[Point], paths: Vec<Vec<usize>>) -> Option<Finding> {
        let dt = crate::delaunay::Triangulation::new(points).unwrap();
        let rec = Reconstruction { paths, ..Reconstruction::default() };
        diagnose(&dt, &rec).into_iter().find(|f| f.kind == FindingKind::EndsMeet)
    }

    #[test]
    fn a_closed_curve_read_open_has_ends_that_meet() {
        // 40 samples of a circle read as the path 0..39: its ends are one spacing apart.
        let found = ends_meet(&circle(40), vec![(0..40).collect()]).expect("ends meet");
        assert_eq!((found.count, found.at), (1, 0));
        assert!((found.worst - 1.0).abs() < 1e-9, "{found:?}");
        assert!(found.to_string().contains("may go on, or close"), "{found}");
        // Two pieces of it, 0..=19 and 20..=39: two pairs of ends.
        let found = ends_meet(&circle(40), vec![(0..20).collect(), (20..40).collect()]);
        assert_eq!(found.map(|f| f.count), Some(2));
        // Three samples missing: the gap is 3.9 last edges, within the bound; four missing,
        // 4.9, where an open curve may end.
        let points: Vec<Point> = circle(40).into_iter().take(37).collect();
        assert!(ends_meet(&points, vec![(0..37).collect()]).is_some());
        let points: Vec<Point> = circle(40).into_iter().take(36).collect();
        assert_eq!(ends_meet(&points, vec![(0..36).collect()]), None);
    }

    #[test]
    fn an_open_arc_with_a_wide_gap_is_an_open_curve() {
        // Samples 0..=29 of the 40: the ends are eleven spacings apart.
        let points: Vec<Point> = circle(40).into_iter().take(30).collect();
        assert_eq!(ends_meet(&points, vec![(0..30).collect()]), None);
        // And a one-edge path has no ends that meet.
        assert_eq!(ends_meet(&points[..2], vec![vec![0, 1]]), None);
    }
}
