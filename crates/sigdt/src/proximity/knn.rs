//! The k-nearest-neighbour graph (undirected union).
//!
//! Edge `pq` iff `q` is among the `k` nearest distinct points of `p` or `p` among those of
//! `q` (`docs/algorithms.md` §4.10; ties by input index). Exact duplicates take part through their
//! representative and get no edges.
//!
//! # Complexity
//! O(n log n + nk log k) with a 2-d tree.
use super::kdtree::KdTree;
use crate::delaunay::Triangulation;
use crate::geometry::{Edge, Point};

/// The kNN graph of the triangulation's distinct points as sorted input-index pairs.
pub(crate) fn knn(dt: &Triangulation, k: usize) -> Vec<Edge> {
    let points: Vec<Point> = (0..dt.num_vertices() as u32).map(|v| dt.point(v)).collect();
    let tree = KdTree::new(&points);
    let mut pairs = Vec::with_capacity(points.len() * k);
    for v in 0..points.len() as u32 {
        // Ask for more than k so that exact distance ties are broken by input index.
        let mut near = tree.nearest(points[v as usize], k + 8, v);
        near.sort_by(|a, b| {
            a.0.total_cmp(&b.0).then(dt.input_index(a.1).cmp(&dt.input_index(b.1)))
        });
        pairs.extend(near.into_iter().take(k).map(|(_, w)| [v, w]));
    }
    dt.to_input_edges(pairs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_nn_on_a_line_of_four() {
        let dt = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [6.0, 0.0]]).unwrap();
        assert_eq!(knn(&dt, 1), vec![[0, 1], [1, 2], [2, 3]]);
        assert_eq!(knn(&dt, 2), vec![[0, 1], [0, 2], [1, 2], [1, 3], [2, 3]]);
    }
}
