//! Whether two edges of a graph cross: the Shamos–Hoey sweep.
//!
//! \[SH76\]: sweep a vertical line from left to right, keep the edges it meets ordered from
//! bottom to top, and test only edges that become neighbours in that order (on insertion,
//! and when the edge between two neighbours is removed). The leftmost crossing is between
//! two edges that are neighbours just before it, so the sweep finds a crossing whenever
//! there is one. It reports *proper* crossings only: two edges whose interiors cross at a
//! single point, decided by exact orientation tests. Edges that share an end point, touch,
//! or overlap along a line are not reported (the graph-epsilon already handles touching;
//! a curve crosses itself only properly).
//!
//! Used to answer the graph-epsilon of a ground truth that crosses itself without the
//! nearest-feature searches, which degrade to quadratic time on such input: at a crossing
//! the curve meets itself, its local feature size is 0, and epsilon is infinite.
//!
//! # Complexity
//! O(m log m) comparisons for `m` edges, plus the moves of a sorted vector holding the
//! edges that one vertical line meets (small on curves; at worst O(m) a step).
//!
//! # References
//! - \[SH76\] M. I. Shamos, D. Hoey. Geometric intersection problems. FOCS 1976.
use sigdt::internals::orient2d;
use sigdt::{Edge, Point};
use std::cmp::Ordering;

/// Two edges of `edges` (indices into it) whose interiors cross at a single point, if any.
/// Zero-length edges are ignored.
pub(crate) fn proper_crossing(points: &[Point], edges: &[Edge]) -> Option<(usize, usize)> {
    let lexicographic = |p: Point, q: Point| p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]));
    // Each edge from its lexicographically smaller end (left) to its larger one (right).
    let segments: Vec<[Point; 2]> = edges
        .iter()
        .map(|&[i, j]| match lexicographic(points[i], points[j]) {
            Ordering::Greater => [points[j], points[i]],
            _ => [points[i], points[j]],
        })
        .collect();
    // Events: (point, 0 = remove / 1 = insert, edge); removals first at a shared point, so
    // a chain's consecutive edges never meet in the status.
    let mut events: Vec<(Point, u8, usize)> = Vec::with_capacity(2 * edges.len());
    for (e, s) in segments.iter().enumerate() {
        if lexicographic(s[0], s[1]) != Ordering::Equal {
            events.push((s[0], 1, e));
            events.push((s[1], 0, e));
        }
    }
    events.sort_by(|x, y| lexicographic(x.0, y.0).then(x.1.cmp(&y.1)).then(x.2.cmp(&y.2)));
    let crosses = |e: usize, f: usize| {
        let ([a, b], [c, d]) = (segments[e], segments[f]);
        let opposite = |x: f64, y: f64| (x > 0.0 && y < 0.0) || (x < 0.0 && y > 0.0);
        opposite(orient2d(a, b, c), orient2d(a, b, d))
            && opposite(orient2d(c, d, a), orient2d(c, d, b))
    };
    let found = |e: usize, f: usize| crosses(e, f).then_some((e.min(f), e.max(f)));
    // Whether edge `new`, starting at its left end, goes below edge `old` of the status.
    let below = |new: usize, old: usize| {
        let ([a, b], [p, q]) = (segments[old], segments[new]);
        let side = orient2d(a, b, p);
        let side = if side == 0.0 { orient2d(a, b, q) } else { side };
        match side {
            s if s < 0.0 => Ordering::Less,
            s if s > 0.0 => Ordering::Greater,
            _ => new.cmp(&old),
        }
    };
    let mut status: Vec<usize> = Vec::new();
    for (_, kind, e) in events {
        if kind == 1 {
            let at = status.partition_point(|&old| below(e, old) == Ordering::Greater);
            status.insert(at, e);
            let neighbours = [at.checked_sub(1), Some(at + 1)];
            for f in neighbours.into_iter().flatten().filter_map(|k| status.get(k)) {
                if let Some(pair) = found(e, *f) {
                    return Some(pair);
                }
            }
        } else if let Some(at) = status.iter().position(|&x| x == e) {
            status.remove(at);
            if at > 0 && at < status.len() {
                if let Some(pair) = found(status[at - 1], status[at]) {
                    return Some(pair);
                }
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cross_is_found_and_a_square_has_none() {
        let points = [[0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]];
        assert_eq!(proper_crossing(&points, &[[0, 1], [2, 3]]), Some((0, 1)));
        // The square 0-3-1-2 has no crossing; its diagonal pair does.
        let square = [[0, 3], [3, 1], [1, 2], [2, 0]];
        assert_eq!(proper_crossing(&points, &square), None);
    }

    #[test]
    fn touching_sharing_and_overlapping_are_not_proper_crossings() {
        let points = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0], [3.0, 0.0], [4.0, 0.0]];
        // A T: 2-3 ends on 0-1. Shared ends. Collinear overlap 0-1 and 2-4.
        assert_eq!(proper_crossing(&points, &[[0, 1], [2, 3]]), None);
        assert_eq!(proper_crossing(&points, &[[0, 1], [1, 3], [3, 0]]), None);
        assert_eq!(proper_crossing(&points, &[[0, 1], [2, 4], [4, 5]]), None);
        assert_eq!(proper_crossing(&points, &[[0, 0], [0, 1]]), None);
    }

    #[test]
    fn agrees_with_every_pair_on_random_polygons() {
        // Random polygons (crossing) and their sorted-angle versions (simple): the sweep
        // finds a crossing exactly when some pair of edges crosses.
        let mut rng = sigdt::samplers::Rng::new(11);
        for round in 0..200 {
            let n = 4 + round % 20;
            let points: Vec<Point> = (0..n).map(|_| [rng.uniform(), rng.uniform()]).collect();
            let mut order: Vec<usize> = (0..n).collect();
            if round % 2 == 0 {
                let angle = |&i: &usize| (points[i][1] - 0.5).atan2(points[i][0] - 0.5);
                order.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
            }
            let edges: Vec<Edge> = (0..n).map(|k| [order[k], order[(k + 1) % n]]).collect();
            let brute = (0..n).any(|e| {
                (e + 1..n).any(|f| {
                    let ([a, b], [c, d]) = (edges[e], edges[f]);
                    let [a, b, c, d] = [a, b, c, d].map(|i| points[i]);
                    let opposite = |x: f64, y: f64| x * y < 0.0;
                    opposite(orient2d(a, b, c), orient2d(a, b, d))
                        && opposite(orient2d(c, d, a), orient2d(c, d, b))
                })
            });
            assert_eq!(proper_crossing(&points, &edges).is_some(), brute, "round {round}");
        }
    }
}
