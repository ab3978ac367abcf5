//! Isolated outliers: small groups of points sampled far more sparsely than the curve next
//! to them, cut off the reading where it reads them as curves of their own.
//!
//! A point's spacing is the distance to its nearest neighbour, one of its Delaunay
//! neighbours. On a curve sampled with ρ < 1 and u < 2 ([MOW22] Theorem 1) that neighbour is
//! a curve neighbour and the other one is less than twice as far, so consecutive samples are
//! joined by a Delaunay edge no longer than [`LONG_EDGE_RATIO`] times the smaller spacing
//! of its two ends. Those edges group the points into pieces each sampled at its own scale.
//! Points scattered off the curves fall into pieces of their own: a lone point in the sea,
//! or a few that lie closer to one another than to any curve, which read as a curve at a
//! coarser scale (an open path or a small loop beside a dense coastline) that the other
//! outlier rules keep (`Steps::own_curves`). Such a piece is *isolated* when it has fewer
//! than [`MIN_LOOP_POINTS`] points (fewer than a closed curve sampled within the condition
//! has) and its median spacing is at least [`LONG_EDGE_RATIO`] times that of a piece of at
//! least [`MIN_LOOP_POINTS`] points it shares a Delaunay edge with: sampled far more
//! coarsely than the curve beside it. A larger coarse piece is a curve; so is a small piece
//! sampled like its surroundings (a noisy curve's fragments, a glyph's dot).
//!
//! Isolated points are not left out outright: a sample on a long straight side between two
//! densely sampled bends is isolated too (such a glyph breaks u < 2, and its polygon is
//! still what the reading finds). They are cut off the finished reading only where it reads
//! them apart from the curves ([`cut_isolated`]): a loop or open path all of whose points
//! are isolated, and the isolated points at the ends of an open path (a chain of outliers
//! hung onto a curve's end).
//!
//! Decided on squared distances of the scaled points; a spacing at exactly the bound is
//! isolated, an edge at exactly the bound links.
//!
//! # Complexity
//! O(n) time and memory beyond the triangulation, plus sorting each piece's spacings
//! (O(n log n) in all).
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use super::reading::{Reading, NONE};
use crate::delaunay::Triangulation;
use crate::result::{LONG_EDGE_RATIO, MIN_LOOP_POINTS};

/// Whether each vertex of `dt` is isolated: in a small piece sampled far more coarsely than
/// a curve beside it.
pub(super) fn isolated_points(dt: &Triangulation) -> Vec<bool> {
    let n = dt.num_vertices();
    let neighbours = |v: u32| dt.incident(v).map(move |h| dt.other(h, v));
    let squared = |a: u32, b: u32| {
        let (p, q) = (dt.point(a), dt.point(b));
        (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)
    };
    // Squared nearest-neighbour distances.
    let spacing: Vec<f64> = (0..n as u32)
        .map(|v| neighbours(v).map(|w| squared(v, w)).fold(f64::INFINITY, f64::min))
        .collect();
    let bound = LONG_EDGE_RATIO * LONG_EDGE_RATIO;
    let linked =
        |v: u32, w: u32| squared(v, w) <= bound * spacing[v as usize].min(spacing[w as usize]);
    // Pieces: components of the linking edges, by depth-first search from the lowest
    // vertex of each.
    let mut piece = vec![u32::MAX; n];
    let mut members: Vec<Vec<u32>> = Vec::new();
    for start in 0..n as u32 {
        if piece[start as usize] != u32::MAX {
            continue;
        }
        let id = members.len() as u32;
        piece[start as usize] = id;
        let (mut stack, mut group) = (vec![start], Vec::new());
        while let Some(v) = stack.pop() {
            group.push(v);
            for w in neighbours(v) {
                if piece[w as usize] == u32::MAX && linked(v, w) {
                    piece[w as usize] = id;
                    stack.push(w);
                }
            }
        }
        members.push(group);
    }
    let median: Vec<f64> = members
        .iter()
        .map(|group| {
            let mut s: Vec<f64> = group.iter().map(|&v| spacing[v as usize]).collect();
            let k = s.len() / 2;
            *s.select_nth_unstable_by(k, f64::total_cmp).1
        })
        .collect();
    let mut isolated = vec![false; n];
    for (id, group) in members.iter().enumerate() {
        if group.len() >= MIN_LOOP_POINTS {
            continue;
        }
        let beside_denser_curve = group.iter().flat_map(|&v| neighbours(v)).any(|w| {
            let other = piece[w as usize] as usize;
            members[other].len() >= MIN_LOOP_POINTS && median[id] >= bound * median[other]
        });
        if !beside_denser_curve {
            continue;
        }
        for &v in group {
            isolated[v as usize] = true;
        }
    }
    isolated
}

/// Cuts off `reading` its loops and paths made only of `isolated` vertices and the
/// isolated vertices at the ends of its open paths; returns the vertices cut, ascending.
pub(super) fn cut_isolated(reading: &mut Reading<'_>, isolated: impl Fn(u32) -> bool) -> Vec<u32> {
    let n = reading.dt.num_vertices();
    let mut cut = Vec::new();
    let mut seen = vec![false; n];
    for start in 0..n as u32 {
        if seen[start as usize] || reading.degree(start) == 0 {
            continue;
        }
        let mut component = vec![start];
        seen[start as usize] = true;
        let mut k = 0;
        while let Some(&v) = component.get(k) {
            for w in reading.neighbours(v) {
                if w != NONE && !seen[w as usize] {
                    seen[w as usize] = true;
                    component.push(w);
                }
            }
            k += 1;
        }
        if component.iter().all(|&v| isolated(v)) {
            cut.extend_from_slice(&component);
        }
    }
    for path in reading.open_paths() {
        if path.iter().all(|&v| isolated(v)) {
            continue; // cut whole above
        }
        cut.extend(path.iter().take_while(|&&v| isolated(v)));
        cut.extend(path.iter().rev().take_while(|&&v| isolated(v)));
    }
    for &v in &cut {
        for w in reading.neighbours(v) {
            if w != NONE {
                reading.relink(w, v, NONE);
            }
        }
        reading.detach(v);
    }
    cut.sort_unstable();
    cut
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point;

    /// A circle of `n` samples of radius 1 about the origin.
    fn circle(n: usize) -> Vec<Point> {
        let tau = std::f64::consts::TAU;
        (0..n).map(|k| tau * k as f64 / n as f64).map(|a| [a.cos(), a.sin()]).collect()
    }

    #[test]
    fn scattered_points_and_small_groups_are_isolated() {
        // A 200-gon (spacing 0.031), a point inside it, two points 0.2 apart outside, and a
        // far chain of five points 1 apart: pieces of 1, 2 and 5 points.
        let mut points = circle(200);
        points.push([0.5, 0.0]);
        points.extend([[2.0, 0.0], [2.0, 0.2]]);
        points.extend((0..5).map(|k| [-3.0 - k as f64, 3.0]));
        let dt = Triangulation::new(&points).unwrap();
        let isolated = isolated_points(&dt);
        let mut found: Vec<usize> = (0..dt.num_vertices() as u32)
            .filter(|&v| isolated[v as usize])
            .map(|v| dt.input_index(v))
            .collect();
        found.sort_unstable();
        assert_eq!(found, (200..208).collect::<Vec<_>>());
    }

    #[test]
    fn curves_of_different_spacing_and_coarse_groups_stay() {
        // Two concentric circles sampled 24 times apart in spacing, a coarse 8-point loop
        // beside them, and a jittered circle: every piece is a curve.
        let mut points = circle(400);
        points.extend(circle(50).into_iter().map(|[x, y]| [3.0 * x, 3.0 * y]));
        points.extend(circle(8).into_iter().map(|[x, y]| [8.0 + 4.0 * x, 4.0 * y]));
        let jitter = |k: usize| 0.3 * (((k * 7919) % 13) as f64 / 13.0 - 0.5);
        points.extend(circle(100).into_iter().enumerate().map(|(k, [x, y])| {
            let r = 1.0 + 0.0628 * jitter(k);
            [-20.0 + r * x, r * y]
        }));
        let dt = Triangulation::new(&points).unwrap();
        assert!(!isolated_points(&dt).contains(&true));
    }

    #[test]
    fn the_reading_loses_its_isolated_pieces_and_ends() {
        // Vertices 0-9 a path whose last two are isolated, 10-12 an isolated loop, 13-14 an
        // isolated pair, 15-17 a loop with one isolated vertex (kept: it is not apart).
        let points: Vec<Point> = (0..18).map(|k| [k as f64, (k * k % 7) as f64]).collect();
        let dt = Triangulation::new(&points).unwrap();
        let v = |i: usize| (0..dt.num_vertices() as u32).find(|&v| dt.input_index(v) == i).unwrap();
        let mut pairs: Vec<[u32; 2]> = (1..10).map(|k| [v(k - 1), v(k)]).collect();
        pairs.extend([[v(10), v(11)], [v(11), v(12)], [v(10), v(12)], [v(13), v(14)]]);
        pairs.extend([[v(15), v(16)], [v(16), v(17)], [v(15), v(17)]]);
        let mut reading = Reading::new(&dt, &pairs);
        let isolated = |u: u32| matches!(dt.input_index(u), 8..=14 | 16);
        let mut cut: Vec<usize> =
            cut_isolated(&mut reading, isolated).into_iter().map(|u| dt.input_index(u)).collect();
        cut.sort_unstable();
        assert_eq!(cut, (8..15).collect::<Vec<_>>());
        let mut left: Vec<[usize; 2]> = reading
            .pairs()
            .into_iter()
            .map(|[a, b]| {
                let (a, b) = (dt.input_index(a), dt.input_index(b));
                [a.min(b), a.max(b)]
            })
            .collect();
        left.sort_unstable();
        let mut expected: Vec<[usize; 2]> = (1..8).map(|k| [k - 1, k]).collect();
        expected.extend([[15, 16], [15, 17], [16, 17]]);
        assert_eq!(left, expected);
    }
}
