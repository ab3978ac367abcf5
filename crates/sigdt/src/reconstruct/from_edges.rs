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
//! at most 2 otherwise, and [`Network`](Status::Network) when some vertex has degree 3 or
//! more.
//!
//! # Complexity
//! O(m log m) for `m` edges (the sort), O(n + m) for the walk.
use super::result::{Reconstruction, Stats, Status};
use crate::delaunay::Triangulation;

/// The result whose edges are the vertex pairs `pairs` of `dt` (any order, repeats and
/// self-pairs ignored), with `stats` as given except the point counts, filled in here.
pub fn from_vertex_pairs(
    dt: &Triangulation,
    pairs: Vec<[u32; 2]>,
    mut stats: Stats,
) -> Reconstruction {
    let n = dt.num_vertices();
    let mut pairs: Vec<[u32; 2]> =
        pairs.into_iter().filter(|[a, b]| a != b).map(|[a, b]| [a.min(b), a.max(b)]).collect();
    pairs.sort_unstable();
    pairs.dedup();
    let adjacency = Adjacency::new(n, &pairs);
    let mut used = vec![false; pairs.len()];
    let mut paths = Vec::new();
    for v in 0..n as u32 {
        if adjacency.degree(v) == 2 {
            continue;
        }
        for &(w, e) in adjacency.neighbours(v) {
            if !used[e] {
                paths.push(adjacency.walk(v, w, e, &mut used));
            }
        }
    }
    let mut loops = Vec::new();
    for (e, &[a, b]) in pairs.iter().enumerate() {
        if !used[e] {
            let mut cycle = adjacency.walk(a, b, e, &mut used);
            cycle.pop(); // the walk returns to `a`
            loops.push(cycle);
        }
    }
    let mut loops: Vec<Vec<usize>> = loops.into_iter().map(|c| ccw_loop(dt, c)).collect();
    loops.sort_unstable();
    let mut paths: Vec<Vec<usize>> = paths
        .into_iter()
        .map(|p| {
            let mut p: Vec<usize> = p.into_iter().map(|v| dt.input_index(v)).collect();
            // Open paths start at their smaller end; a path closing through a junction
            // starts there and runs towards its smaller neighbour.
            if p.first() > p.last() || (p.first() == p.last() && p[1] > p[p.len() - 2]) {
                p.reverse();
            }
            p
        })
        .collect();
    paths.sort_unstable();
    let max_degree = (0..n as u32).map(|v| adjacency.degree(v)).max().unwrap_or(0);
    let on_loops: usize = loops.iter().map(Vec::len).sum();
    let status = if max_degree > 2 {
        Status::Network
    } else if paths.is_empty() && on_loops == n && !loops.is_empty() {
        if loops.len() == 1 {
            Status::Polygon
        } else {
            Status::Polygons
        }
    } else {
        Status::Curves
    };
    stats.points = dt.input_len();
    stats.distinct_points = n;
    Reconstruction {
        edges: dt.to_input_edges(pairs),
        loops,
        paths,
        status,
        duplicates: dt.duplicates().to_vec(),
        stats,
    }
}

/// Compressed adjacency lists: `(neighbour, edge number)` per vertex.
struct Adjacency {
    start: Vec<usize>,
    entries: Vec<(u32, usize)>,
}

impl Adjacency {
    fn new(n: usize, pairs: &[[u32; 2]]) -> Adjacency {
        let mut start = vec![0; n + 1];
        for &[a, b] in pairs {
            start[a as usize + 1] += 1;
            start[b as usize + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut entries = vec![(0, 0); 2 * pairs.len()];
        for (e, &[a, b]) in pairs.iter().enumerate() {
            for (x, y) in [(a, b), (b, a)] {
                entries[fill[x as usize]] = (y, e);
                fill[x as usize] += 1;
            }
        }
        Adjacency { start, entries }
    }

    fn degree(&self, v: u32) -> usize {
        self.start[v as usize + 1] - self.start[v as usize]
    }

    fn neighbours(&self, v: u32) -> &[(u32, usize)] {
        &self.entries[self.start[v as usize]..self.start[v as usize + 1]]
    }

    /// Walks from `from` over edge `e` to `to`, then on through degree-2 vertices until a
    /// node or an edge already used; returns the vertices visited, `from` first.
    fn walk(&self, from: u32, to: u32, e: usize, used: &mut [bool]) -> Vec<u32> {
        let mut chain = vec![from, to];
        used[e] = true;
        let mut v = to;
        while self.degree(v) == 2 {
            let Some(&(w, f)) = self.neighbours(v).iter().find(|&&(_, f)| !used[f]) else {
                break;
            };
            used[f] = true;
            chain.push(w);
            v = w;
        }
        chain
    }
}

/// The loop through vertices `cycle` as input indices, counter-clockwise, starting at its
/// smallest index.
fn ccw_loop(dt: &Triangulation, cycle: Vec<u32>) -> Vec<usize> {
    let k = cycle.len();
    let twice_area: f64 = (0..k)
        .map(|a| {
            let (p, q) = (dt.point(cycle[a]), dt.point(cycle[(a + 1) % k]));
            p[0] * q[1] - q[0] * p[1]
        })
        .sum();
    let mut indices: Vec<usize> = cycle.into_iter().map(|v| dt.input_index(v)).collect();
    if twice_area < 0.0 {
        indices.reverse();
    }
    let smallest = (0..k).min_by_key(|&a| indices[a]).unwrap_or(0);
    indices.rotate_left(smallest);
    indices
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::check_reconstruction;

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
    fn a_junction_makes_a_network_of_paths() {
        let square = [[0, 1], [1, 2], [2, 3], [0, 3]];
        let rec = result(&SQUARE_AND_TAIL, &[square.as_slice(), &[[2, 4], [4, 5]]].concat());
        assert_eq!(rec.status, Status::Network);
        assert!(rec.loops.is_empty());
        // The square closes through the junction 2; the tail hangs off it.
        assert_eq!(rec.paths, vec![vec![2, 1, 0, 3, 2], vec![2, 4, 5]]);
        let reversed = result(&SQUARE_AND_TAIL, &[[4, 5], [2, 4], [0, 3], [2, 3], [0, 1], [1, 2]]);
        assert_eq!(reversed.paths, rec.paths);
        assert_eq!(rec.edges.len(), 6);
    }
}
