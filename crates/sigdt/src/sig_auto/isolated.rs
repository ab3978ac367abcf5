//! Isolated outliers: small groups of points sampled far more sparsely than the curve next
//! to them, left out unless the reading runs straight past them.
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
//! coarsely than the curve beside it. So is a larger such piece of at most a twentieth of
//! the points of the denser curves beside it (an archipelago's outliers lie beside many
//! small islands) that is a *cloud*: along its minimum spanning tree (which runs along a
//! sampled curve) u < 2 fails at more than one vertex in eight, which scattered points do
//! and islands hardly ever ([`is_cloud`]). Small pieces in a cloud that lie beside no
//! curve, only beside the cloud, are isolated with it ([`isolate_open_sea`]). A larger
//! coarse piece that keeps u < 2, or holds more points, is a curve (an island sampled more
//! coarsely than the coast beside it, a polygon given by its vertices); so is a small piece
//! sampled like its surroundings (a noisy curve's fragments, a glyph's dot).
//!
//! Isolated pieces are left out before the reading ([`isolated_pieces`]) and put back where
//! the reading runs straight past them, or stops on both sides of them, along a Delaunay
//! path ([`put_back`]): a sample on a long straight side between two densely sampled bends
//! is isolated too (such a glyph breaks u < 2, and its polygon is still what the reading
//! finds).
//!
//! Decided on distances of the scaled points; a spacing at exactly the bound is isolated,
//! an edge at exactly the bound links.
//!
//! # Complexity
//! [`isolated_pieces`]: O(n) time and memory beyond the triangulation (a selection per
//! piece, and one walk over the pieces beside one another for [`isolate_open_sea`]).
//! [`put_back`]: O(m + k · d · (d + f)) for m reading edges, k isolated points of
//! Delaunay degree d and f reading edges that are not Delaunay edges of all points; nothing
//! when no piece is isolated.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::Triangulation;
use crate::geometry::{distance, segments_cross};
use crate::graph::UnionFind;
use crate::result::{LONG_EDGE_RATIO, MIN_LOOP_POINTS};
use std::collections::HashMap;

/// The isolated pieces of `dt`: points sampled far more coarsely than a curve beside them,
/// fewer than [`MIN_LOOP_POINTS`] or scattered (module docs); each ascending, the pieces by
/// their lowest vertex. `spacing` is every vertex's nearest-neighbour distance
/// ([`nearest_vertex_distances`](crate::proximity::nearest::nearest_vertex_distances)).
pub(super) fn isolated_pieces(dt: &Triangulation, spacing: &[f64]) -> Vec<Vec<u32>> {
    let n = dt.num_vertices();
    let neighbours = |v: u32| dt.incident(v).map(move |h| dt.other(h, v));
    let length = |a: u32, b: u32| distance(dt.point(a), dt.point(b));
    // Pieces: the components of the linking edges.
    let mut sets = UnionFind::new(n);
    let mut merges = 0;
    for h in dt.edge_halfedges() {
        let (a, b) = (dt.origin(h), dt.dest(h));
        let linked = length(a, b) <= LONG_EDGE_RATIO * spacing[a as usize].min(spacing[b as usize]);
        if linked && sets.union(a, b) {
            merges += 1;
        }
    }
    if merges + 1 >= n {
        return Vec::new(); // one piece: nothing beside it
    }
    // Pieces numbered in the order of their lowest vertex.
    let mut piece = vec![u32::MAX; n];
    let mut id_of_root: HashMap<u32, u32> = HashMap::new();
    let mut members: Vec<Vec<u32>> = Vec::new();
    for v in 0..n as u32 {
        let root = sets.find(v);
        let id = *id_of_root.entry(root).or_insert_with(|| {
            members.push(Vec::new());
            members.len() as u32 - 1
        });
        piece[v as usize] = id;
        members[id as usize].push(v);
    }
    let median: Vec<f64> = members
        .iter()
        .map(|group| {
            let mut s: Vec<f64> = group.iter().map(|&v| spacing[v as usize]).collect();
            let k = s.len() / 2;
            *s.select_nth_unstable_by(k, f64::total_cmp).1
        })
        .collect();
    // The pieces beside each piece (sharing a Delaunay edge), each once.
    let beside: Vec<Vec<usize>> = members
        .iter()
        .enumerate()
        .map(|(id, group)| {
            let mut others: Vec<usize> = group
                .iter()
                .flat_map(|&v| neighbours(v))
                .map(|w| piece[w as usize] as usize)
                .filter(|&other| other != id)
                .collect();
            others.sort_unstable();
            others.dedup();
            others
        })
        .collect();
    let curve = |id: usize| members[id].len() >= MIN_LOOP_POINTS;
    let mut isolated: Vec<bool> = (0..members.len())
        .map(|id| {
            // A small piece beside a denser curve; a larger one only when it is a cloud of
            // a few percent of the points of the denser curves beside it.
            let curve_points: usize = beside[id]
                .iter()
                .filter(|&&o| curve(o) && median[id] >= LONG_EDGE_RATIO * median[o])
                .map(|&o| members[o].len())
                .sum();
            curve_points > 0
                && (!curve(id)
                    || (members[id].len() * CLOUD_FRACTION <= curve_points
                        && is_cloud(dt, &members[id])))
        })
        .collect();
    isolate_open_sea(&beside, &mut isolated, curve);
    members.into_iter().zip(isolated).filter_map(|(group, out)| out.then_some(group)).collect()
}

/// Marks as isolated the small pieces that lie in a cloud of outliers with no curve beside
/// them: each group of small pieces joined by Delaunay edges that is beside an isolated
/// cloud (an isolated piece of at least [`MIN_LOOP_POINTS`] points) and beside no curve (a
/// piece of at least [`MIN_LOOP_POINTS`] points) that is not isolated. Outliers scattered
/// far from every curve link into pieces by their own spacing, and the small ones that are
/// not beside a curve are only beside the rest of the cloud. (Small isolated pieces alone
/// do not make a cloud: a glyph's long sides sampled by a few points each are small pieces
/// beside one another, and are put back after the reading.)
fn isolate_open_sea(beside: &[Vec<usize>], isolated: &mut [bool], curve: impl Fn(usize) -> bool) {
    let open = |id: usize, isolated: &[bool]| !isolated[id] && !curve(id);
    let mut seen = vec![false; beside.len()];
    for start in 0..beside.len() {
        if seen[start] || !open(start, isolated) {
            continue;
        }
        // The group of small pieces joined to `start`, and whether anything but isolated
        // pieces lies beside it.
        let (mut group, mut stack) = (Vec::new(), vec![start]);
        seen[start] = true;
        let (mut anchored, mut in_cloud) = (false, false);
        while let Some(id) = stack.pop() {
            group.push(id);
            for &other in &beside[id] {
                if isolated[other] {
                    in_cloud |= curve(other);
                } else if open(other, isolated) {
                    if !seen[other] {
                        seen[other] = true;
                        stack.push(other);
                    }
                } else {
                    anchored = true; // a curve beside it
                }
            }
        }
        if in_cloud && !anchored {
            for id in group {
                isolated[id] = true;
            }
        }
    }
}

/// The share of a piece's tree vertices at which u ≥ 2 beyond which the piece is a cloud
/// of scattered points rather than a sampled curve: between what coarse islands and clouds
/// of outliers measure (`docs/sig-auto.md`, step 6).
const CLOUD_SHARE: f64 = 0.125;

/// A cloud is left out only beside a curve of at least this many times its points:
/// outliers are a few percent of the points (issue 29), and a coarse curve that breaks
/// u < 2 (a blob sampled at random, a polygon given by its vertices) holds more.
const CLOUD_FRACTION: usize = 20;

/// Whether `group` is a cloud: along the minimum spanning tree of the Delaunay edges between
/// its points, which runs along a sampled curve, the non-uniformity u (the longer over the
/// shorter tree edge at a vertex, [MOW22]) is at least 2 at more than [`CLOUD_SHARE`] of the
/// vertices with two or more tree edges. Ties in the tree are broken by input indices.
///
/// [MOW22]: https://doi.org/10.1111/cgf.14654
fn is_cloud(dt: &Triangulation, group: &[u32]) -> bool {
    let local: HashMap<u32, usize> = group.iter().enumerate().map(|(k, &v)| (v, k)).collect();
    let mut edges: Vec<(u64, usize, usize, usize, usize)> = Vec::new();
    for (k, &v) in group.iter().enumerate() {
        for w in dt.incident(v).map(|h| dt.other(h, v)) {
            match local.get(&w) {
                Some(&j) if v < w => {
                    let (p, q) = (dt.point(v), dt.point(w));
                    let length = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).to_bits();
                    let (a, b) = (dt.input_index(v), dt.input_index(w));
                    edges.push((length, a.min(b), a.max(b), k, j));
                }
                _ => {}
            }
        }
    }
    edges.sort_unstable();
    let mut sets = UnionFind::new(group.len());
    // The shortest and longest squared tree edge at each vertex, and how many.
    let mut at = vec![(f64::INFINITY, 0.0f64, 0usize); group.len()];
    for (bits, _, _, k, j) in edges {
        if !sets.union(k as u32, j as u32) {
            continue;
        }
        let length = f64::from_bits(bits);
        for x in [k, j] {
            let (short, long, count) = &mut at[x];
            (*short, *long, *count) = (short.min(length), long.max(length), *count + 1);
        }
    }
    let inner: Vec<&(f64, f64, usize)> = at.iter().filter(|a| a.2 >= 2).collect();
    // u ≥ 2 on squared lengths: the longer at least four times the shorter.
    let breaking = inner.iter().filter(|&&&(short, long, _)| long >= 4.0 * short).count();
    !inner.is_empty() && breaking as f64 > CLOUD_SHARE * inner.len() as f64
}

/// Puts back into the reading `pairs` (edges between vertices of `dt`) the isolated points
/// that lie along one of its edges, or across the gap between two of its path ends, as a
/// straight stretch of samples: an edge or gap `ab` such that `a`, the isolated points
/// straight between `a` and `b` (an angle of at least 150° at each, where the sampling
/// check's doubling back is a turn of more than 150°) in order along `ab`, and `b` are
/// joined by Delaunay edges, go straight on at each point, and cross no edge of the
/// reading. That is how samples on a long straight side between two densely
/// sampled bends look (a glyph that breaks u < 2); a point off a straight or convex coast
/// never does (the coast's edges beside it subtend less than 90° at it). Returns the points
/// put back, ascending.
pub(super) fn put_back(
    dt: &Triangulation,
    pairs: &mut Vec<[u32; 2]>,
    pieces: &[Vec<u32>],
) -> Vec<u32> {
    if pieces.is_empty() {
        return Vec::new();
    }
    let key = |a: u32, b: u32| [a.min(b), a.max(b)];
    let mut index: HashMap<[u32; 2], usize> =
        pairs.iter().enumerate().map(|(k, &[a, b])| (key(a, b), k)).collect();
    let mut partners: HashMap<u32, Vec<u32>> = HashMap::new();
    for &[a, b] in pairs.iter() {
        partners.entry(a).or_default().push(b);
        partners.entry(b).or_default().push(a);
    }
    // Reading edges that are not Delaunay edges of `dt` (the first round read without the
    // pieces) are the only ones the Delaunay edges of a stretch can cross.
    let mut foreign: Vec<[u32; 2]> =
        pairs.iter().copied().filter(|&[a, b]| !dt.has_edge(a, b)).collect();
    let mut waiting: Vec<u32> = pieces.concat();
    waiting.sort_unstable();
    let piece_of: HashMap<u32, usize> =
        pieces.iter().enumerate().flat_map(|(k, p)| p.iter().map(move |&v| (v, k))).collect();
    let mut back = Vec::new();
    for v in waiting.clone() {
        if waiting.binary_search(&v).is_err() {
            continue; // put back with an earlier point's stretch
        }
        let try_between = |a: u32, b: u32| {
            if !straight(dt, a, v, b) {
                return None;
            }
            let chain = along(dt, a, b, &stretch(dt, a, b, v, &waiting))?;
            (!crosses(dt, &chain, &foreign, key(a, b))).then_some((a, b, chain))
        };
        // Into a reading edge beside `v`, or across the gap between two path ends beside
        // `v`'s piece.
        let into_edge = dt
            .incident(v)
            .map(|h| dt.other(h, v))
            .find_map(|a| partners.get(&a)?.iter().find_map(|&b| try_between(a, b)));
        let found = into_edge.map(|found| (found, true)).or_else(|| {
            let piece = &pieces[*piece_of.get(&v)?];
            let ends = ends_beside(dt, piece, &partners, &waiting);
            let mut gaps = ends
                .iter()
                .enumerate()
                .flat_map(|(i, &a)| ends[i + 1..].iter().map(move |&b| (a, b)));
            gaps.find_map(|(a, b)| try_between(a, b)).map(|found| (found, false))
        });
        let Some(((a, b, chain), replaces)) = found else { continue };
        let mut slot = if replaces { index.remove(&key(a, b)) } else { None };
        for w in chain.windows(2) {
            let edge = [w[0], w[1]];
            match slot.take() {
                Some(k) => {
                    pairs[k] = edge;
                    index.insert(key(w[0], w[1]), k);
                }
                None => {
                    index.insert(key(w[0], w[1]), pairs.len());
                    pairs.push(edge);
                }
            }
        }
        if replaces {
            foreign.retain(|&[x, y]| key(x, y) != key(a, b));
            for (x, y) in [(a, b), (b, a)] {
                let list = partners.get_mut(&x).expect("a reading vertex");
                list.retain(|&z| z != y);
            }
        }
        for w in chain.windows(2) {
            partners.entry(w[0]).or_default().push(w[1]);
            partners.entry(w[1]).or_default().push(w[0]);
        }
        let inner = &chain[1..chain.len() - 1];
        waiting.retain(|u| !inner.contains(u));
        back.extend_from_slice(inner);
    }
    back.sort_unstable();
    back
}

/// The ends of the reading's open paths (one partner) that are Delaunay neighbours of
/// `piece` and not `waiting` themselves, ascending.
fn ends_beside(
    dt: &Triangulation,
    piece: &[u32],
    partners: &HashMap<u32, Vec<u32>>,
    waiting: &[u32],
) -> Vec<u32> {
    let mut ends: Vec<u32> = piece
        .iter()
        .flat_map(|&v| dt.incident(v).map(move |h| dt.other(h, v)))
        .filter(|w| waiting.binary_search(w).is_err())
        .filter(|w| partners.get(w).is_some_and(|p| p.len() == 1))
        .collect();
    ends.sort_unstable();
    ends.dedup();
    ends
}

/// The `waiting` points straight between `a` and `b` reached from `v` along Delaunay edges
/// between such points, `v` first.
fn stretch(dt: &Triangulation, a: u32, b: u32, v: u32, waiting: &[u32]) -> Vec<u32> {
    let mut found = vec![v];
    let mut k = 0;
    while let Some(&u) = found.get(k) {
        for w in dt.incident(u).map(|h| dt.other(h, u)) {
            let between = waiting.binary_search(&w).is_ok() && straight(dt, a, w, b);
            if between && !found.contains(&w) {
                found.push(w);
            }
        }
        k += 1;
    }
    found
}

/// Whether the angle `x v y` is at least 150°: cos ≤ -cos 30°, a negative cosine whose
/// square is at least 3/4.
fn straight(dt: &Triangulation, x: u32, v: u32, y: u32) -> bool {
    let (p, q, r) = (dt.point(x), dt.point(v), dt.point(y));
    let (dx, dy) = ([p[0] - q[0], p[1] - q[1]], [r[0] - q[0], r[1] - q[1]]);
    let dot = dx[0] * dy[0] + dx[1] * dy[1];
    let (lx, ly) = (dx[0] * dx[0] + dx[1] * dx[1], dy[0] * dy[0] + dy[1] * dy[1]);
    dot < 0.0 && dot * dot >= 0.75 * lx * ly
}

/// Whether an edge of `chain` crosses one of the `foreign` edges other than `skip` (exact).
pub(super) fn crosses(
    dt: &Triangulation,
    chain: &[u32],
    foreign: &[[u32; 2]],
    skip: [u32; 2],
) -> bool {
    chain.windows(2).any(|w| {
        let (p, q) = (dt.point(w[0]), dt.point(w[1]));
        foreign
            .iter()
            .filter(|&&[c, d]| [c.min(d), c.max(d)] != skip)
            .any(|&[c, d]| segments_cross(p, q, dt.point(c), dt.point(d)))
    })
}

/// `a`, the `points` ordered along `ab`, and `b`, when each step is a Delaunay edge, every
/// point projects strictly inside `ab`, and the angle at each point is at least 150°.
fn along(dt: &Triangulation, a: u32, b: u32, points: &[u32]) -> Option<Vec<u32>> {
    let (pa, pb) = (dt.point(a), dt.point(b));
    let ab = [pb[0] - pa[0], pb[1] - pa[1]];
    let reach = ab[0] * ab[0] + ab[1] * ab[1];
    let t = |v: u32| {
        let p = dt.point(v);
        (p[0] - pa[0]) * ab[0] + (p[1] - pa[1]) * ab[1]
    };
    let mut order = points.to_vec();
    order.sort_by(|&x, &y| t(x).total_cmp(&t(y)).then(x.cmp(&y)));
    if order.iter().any(|&v| !(t(v) > 0.0 && t(v) < reach)) {
        return None;
    }
    let chain: Vec<u32> = [a].into_iter().chain(order).chain([b]).collect();
    let ok = chain.windows(2).all(|w| dt.has_edge(w[0], w[1]))
        && chain.windows(3).all(|w| straight(dt, w[0], w[1], w[2]));
    ok.then_some(chain)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proximity::nearest::nearest_vertex_distances;
    use crate::Point;

    /// A circle of `n` samples of radius 1 about the origin.
    fn circle(n: usize) -> Vec<Point> {
        let tau = std::f64::consts::TAU;
        (0..n).map(|k| tau * k as f64 / n as f64).map(|a| [a.cos(), a.sin()]).collect()
    }

    /// The pieces of `points` as input indices.
    fn pieces(points: &[Point]) -> Vec<Vec<usize>> {
        let dt = Triangulation::new(points).unwrap();
        let mut pieces: Vec<Vec<usize>> = isolated_pieces(&dt, &nearest_vertex_distances(&dt))
            .iter()
            .map(|piece| {
                let mut p: Vec<usize> = piece.iter().map(|&v| dt.input_index(v)).collect();
                p.sort_unstable();
                p
            })
            .collect();
        pieces.sort_unstable();
        pieces
    }

    #[test]
    fn scattered_points_and_small_groups_are_isolated() {
        // A 200-gon (spacing 0.031), a point inside it, two points 0.2 apart outside, and a
        // far chain of five points 1 apart: pieces of 1, 2 and 5 points.
        let mut points = circle(200);
        points.push([0.5, 0.0]);
        points.extend([[2.0, 0.0], [2.0, 0.2]]);
        points.extend((0..5).map(|k| [-3.0 - k as f64, 3.0]));
        assert_eq!(pieces(&points), [vec![200], vec![201, 202], vec![203, 204, 205, 206, 207]]);
    }

    #[test]
    fn clouds_beside_a_curve_are_isolated_and_coarse_islands_are_not() {
        // A 400-gon (spacing 0.016); beside it twelve points scattered at spacings from 0.3
        // to 1.5 (u ≥ 2 at most of their tree), and a 20-gon island of spacing 0.5.
        let mut points = circle(400);
        let first = points.len();
        let steps = [0.3, 1.2, 0.4, 1.5, 0.3, 1.0, 0.35, 1.4, 0.3, 1.1, 0.45];
        let mut x = 3.0;
        points.push([x, 0.0]);
        for (k, step) in steps.iter().enumerate() {
            x += step;
            points.push([x, if k % 2 == 0 { 0.2 } else { -0.2 }]);
        }
        let cloud: Vec<usize> = (first..points.len()).collect();
        points.extend(circle(20).into_iter().map(|[x, y]| [1.6 * x, 3.5 + 1.6 * y]));
        assert_eq!(pieces(&points), [cloud]);
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
        assert!(pieces(&points).is_empty());
    }

    #[test]
    fn straight_sparse_stretches_are_put_back_and_outliers_are_not() {
        // A rectangle 10 x 1 sampled every 0.1 but for its top side, where two samples
        // divide it in three; and a point 1 below the middle of its bottom side.
        let mut points: Vec<Point> = (0..=100).map(|k| [0.1 * k as f64, 0.0]).collect();
        points.extend((1..10).map(|k| [10.0, 0.1 * k as f64]));
        points.extend([[10.0, 1.0], [20.0 / 3.0, 1.0], [10.0 / 3.0, 1.0], [0.0, 1.0]]);
        points.extend((1..10).rev().map(|k| [0.0, 0.1 * k as f64]));
        let n = points.len();
        points.push([5.0, -1.0]);
        let dt = Triangulation::new(&points).unwrap();
        let v = |i: usize| (0..dt.num_vertices() as u32).find(|&v| dt.input_index(v) == i).unwrap();
        let found: Vec<Vec<u32>> = isolated_pieces(&dt, &nearest_vertex_distances(&dt));
        let (top, outlier) = (vec![v(111), v(112)], vec![v(n)]);
        let mut top_sorted = top.clone();
        top_sorted.sort_unstable();
        assert!(found.contains(&top_sorted) && found.contains(&outlier), "{found:?}");
        // The reading without them: the rectangle with its top side from 110 to 113.
        let ring: Vec<usize> = (0..n).filter(|&i| i != 111 && i != 112).collect();
        let mut pairs: Vec<[u32; 2]> =
            (0..ring.len()).map(|k| [v(ring[k]), v(ring[(k + 1) % ring.len()])]).collect();
        let mut back = put_back(&dt, &mut pairs, &[top_sorted.clone(), outlier]);
        back.sort_unstable();
        assert_eq!(back, top_sorted);
        let joined = |a: u32, b: u32| pairs.contains(&[a, b]) || pairs.contains(&[b, a]);
        assert!(joined(v(110), v(111)) && joined(v(111), v(112)) && joined(v(112), v(113)));
        assert!(!joined(v(110), v(113)) && pairs.len() == n);
        // A reading that left the gap open, 113 to 110 an open path: the stretch closes it.
        let open: Vec<usize> = ring[111..].iter().chain(&ring[..111]).copied().collect();
        let mut pairs: Vec<[u32; 2]> = open.windows(2).map(|w| [v(w[0]), v(w[1])]).collect();
        let path = pairs.len();
        assert_eq!(put_back(&dt, &mut pairs, &[top_sorted.clone()]), top_sorted);
        let joined = |a: u32, b: u32| pairs.contains(&[a, b]) || pairs.contains(&[b, a]);
        assert!(joined(v(110), v(111)) && joined(v(111), v(112)) && joined(v(112), v(113)));
        assert_eq!(pairs.len(), path + 3);
    }
}
