//! The result of a method that returns an arbitrary edge set (the classic baselines).
//!
//! CRUST, NN-CRUST, HNN-CRUST and the other graph filters return a set of edges, not a
//! boundary: it may hold closed loops, open paths, isolated points and junctions. This
//! module reads it as chains so that every method's result has the same shape:
//!
//! - a vertex of degree other than 2 is a *node*; each maximal run of edges between nodes
//!   through degree-2 vertices is a *path* (a path may start and end at the same node when
//!   it closes through a junction);
//! - the edges left over form cycles of degree-2 vertices: the *loops*, counter-clockwise,
//!   each starting at its smallest input index.
//!
//! The status is [`Polygon`](Status::Polygon) or [`Polygons`](Status::Polygons) when the
//! loops pass through every distinct point, [`Curves`](Status::Curves) when every degree is
//! at most 2 otherwise, and [`Branching`](Status::Branching) when some vertex has degree 3
//! or more (a method that reads junctions says [`Network`](Status::Network) itself).
//!
//! The same reading serves methods that place vertices of their own
//! ([`Vertices::New`]): their chains index those vertices.
//!
//! # Complexity
//! O(m log m) for `m` edges (the sort), O(n + m) for the walk.
use super::{Reconstruction, Stats, Status, Vertices};
use crate::delaunay::Triangulation;
use crate::geometry::{orient2d, Point};
use crate::graph::{chains, chains_of_slots, two_slots};

/// The result whose edges are the vertex pairs `pairs` of `dt` (any order, repeats and
/// self-pairs ignored), with `stats` as given except the point counts, filled in here.
pub(crate) fn from_vertex_pairs(
    dt: &Triangulation,
    pairs: Vec<[u32; 2]>,
    mut stats: Stats,
) -> Reconstruction {
    let mut rec =
        from_pairs(dt.num_vertices(), pairs, |v| dt.point(v as u32), |v| dt.input_index(v as u32));
    // In place: a million-point result holds 16 MB of edges.
    for edge in &mut rec.edges {
        let (i, j) = (dt.input_index(edge[0] as u32), dt.input_index(edge[1] as u32));
        *edge = [i.min(j), i.max(j)];
    }
    rec.edges.sort_unstable();
    stats.points = dt.input_len();
    stats.distinct_points = dt.num_vertices();
    Reconstruction { duplicates: dt.duplicates().to_vec(), stats, ..rec }
}

/// The result of a method that places vertices of its own (OPTIMALTRANSPORT): `points` in
/// `dt`'s scaled coordinates, `pairs` between them. The result's edges, loops and paths
/// index [`Vertices::New`], which holds the points in the caller's coordinates; its
/// duplicates and point counts are `dt`'s.
pub(crate) fn from_new_vertices(
    dt: &Triangulation,
    points: &[Point],
    pairs: Vec<[u32; 2]>,
) -> Reconstruction {
    let rec = from_pairs(points.len(), pairs, |v| points[v], |v| v);
    Reconstruction {
        duplicates: dt.duplicates().to_vec(),
        vertices: Vertices::New(points.iter().map(|&p| dt.unscale(p)).collect()),
        stats: Stats {
            points: dt.input_len(),
            distinct_points: dt.num_vertices(),
            ..Stats::default()
        },
        ..rec
    }
}

/// The chains and status of the edges `pairs` between vertices `0..n` at `point(v)`; loops
/// and paths are reported through `label(v)`, the edges as sorted vertex pairs.
fn from_pairs(
    n: usize,
    pairs: Vec<[u32; 2]>,
    point: impl Fn(usize) -> Point,
    label: impl Fn(usize) -> usize,
) -> Reconstruction {
    // Sorted and distinct, in place and as `u32`: a million-point result is read in about
    // 40 MB, and its `usize` edges are made last.
    let mut pairs = pairs;
    pairs.retain(|[a, b]| a != b);
    pairs.iter_mut().for_each(|p| *p = [p[0].min(p[1]), p[0].max(p[1])]);
    pairs.sort_unstable();
    pairs.dedup();
    // Paths and cycles (most results) are walked from two neighbour slots a vertex.
    let (chains, max_degree) = match two_slots(n, pairs.iter().copied()) {
        Some(slots) => (chains_of_slots(&slots), 2),
        None => {
            let edges: Vec<[usize; 2]> =
                pairs.iter().map(|&[a, b]| [a as usize, b as usize]).collect();
            (chains(n, &edges, None), 3)
        }
    };
    let (mut loops, mut paths) = (Vec::new(), Vec::new());
    for chain in chains {
        if chain.cycle {
            loops.push(ccw_loop(&point, &label, chain.vertices));
            continue;
        }
        let mut p = chain.vertices;
        p.iter_mut().for_each(|v| *v = label(*v));
        // Open paths start at their smaller end; a path closing through a junction starts
        // there and runs towards its smaller neighbour.
        if p.first() > p.last() || (p.first() == p.last() && p[1] > p[p.len() - 2]) {
            p.reverse();
        }
        paths.push(p);
    }
    loops.sort_unstable();
    paths.sort_unstable();
    let edges: Vec<[usize; 2]> = pairs.iter().map(|&[a, b]| [a as usize, b as usize]).collect();
    drop(pairs);
    let on_loops: usize = loops.iter().map(Vec::len).sum();
    let status = if max_degree > 2 {
        Status::Branching
    } else if paths.is_empty() && on_loops == n && !loops.is_empty() {
        if loops.len() == 1 {
            Status::Polygon
        } else {
            Status::Polygons
        }
    } else {
        Status::Curves
    };
    Reconstruction { edges, loops, paths, status, ..Reconstruction::default() }
}

/// The loop through vertices `cycle` as labels, counter-clockwise, starting at its smallest
/// label. The orientation is that of the corner at the lowest vertex (lowest `y`, then
/// lowest `x`), which is convex in a simple polygon: one exact `orient2d`.
fn ccw_loop(
    point: impl Fn(usize) -> Point,
    label: impl Fn(usize) -> usize,
    cycle: Vec<usize>,
) -> Vec<usize> {
    let k = cycle.len();
    let at = |a: usize| point(cycle[a % k]);
    let lowest = (0..k)
        .min_by(|&a, &b| {
            let (p, q) = (at(a), at(b));
            p[1].total_cmp(&q[1]).then(p[0].total_cmp(&q[0]))
        })
        .unwrap_or(0);
    let clockwise = k >= 3 && orient2d(at(lowest + k - 1), at(lowest), at(lowest + 1)) < 0.0;
    let mut indices = cycle;
    indices.iter_mut().for_each(|v| *v = label(*v));
    if clockwise {
        indices.reverse();
    }
    let smallest = (0..k).min_by_key(|&a| indices[a]).unwrap_or(0);
    indices.rotate_left(smallest);
    indices
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::internals::check_reconstruction;

    fn result(points: &[[f64; 2]], edges: &[[usize; 2]]) -> Reconstruction {
        let dt = Triangulation::new(points).unwrap();
        let vertex_of: Vec<u32> = {
            let mut v = vec![0; points.len()];
            for x in 0..dt.num_vertices() as u32 {
                v[dt.input_index(x)] = x;
            }
            v
        };
        let pairs = edges.iter().map(|&[i, j]| [vertex_of[i], vertex_of[j]]).collect();
        let rec = from_vertex_pairs(&dt, pairs, Stats::default());
        check_reconstruction(points, &rec).unwrap();
        rec
    }

    const SQUARE_AND_TAIL: [[f64; 2]; 6] =
        [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [2.0, 1.0], [3.0, 1.5]];

    #[test]
    fn a_clockwise_cycle_becomes_a_ccw_polygon() {
        let rec = result(&SQUARE_AND_TAIL[..4], &[[0, 3], [3, 2], [2, 1], [1, 0]]);
        assert_eq!(rec.status, Status::Polygon);
        assert_eq!(rec.loops, vec![vec![0, 1, 2, 3]]);
    }

    #[test]
    fn open_paths_and_isolated_points_are_curves() {
        let rec = result(&SQUARE_AND_TAIL, &[[2, 4], [4, 5], [0, 1]]);
        assert_eq!(rec.status, Status::Curves);
        assert_eq!(rec.paths, vec![vec![0, 1], vec![2, 4, 5]]);
        assert!(rec.loops.is_empty());
    }

    #[test]
    fn a_junction_makes_branching_paths() {
        let square = [[0, 1], [1, 2], [2, 3], [0, 3]];
        let rec = result(&SQUARE_AND_TAIL, &[square.as_slice(), &[[2, 4], [4, 5]]].concat());
        assert_eq!(rec.status, Status::Branching);
        assert!(rec.loops.is_empty());
        // The square closes through the junction 2; the tail hangs off it.
        assert_eq!(rec.paths, vec![vec![2, 1, 0, 3, 2], vec![2, 4, 5]]);
        let reversed = result(&SQUARE_AND_TAIL, &[[4, 5], [2, 4], [0, 3], [2, 3], [0, 1], [1, 2]]);
        assert_eq!(reversed.paths, rec.paths);
        assert_eq!(rec.edges.len(), 6);
    }
}
