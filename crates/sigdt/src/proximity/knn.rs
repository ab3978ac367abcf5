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
    // No point has more than the others as neighbours; this also keeps `k + 8` finite.
    let k = k.min(points.len().saturating_sub(1));
    let tree = KdTree::new(&points);
    // Each point's neighbours on their own (in parallel on a pool), listed in point order.
    let nearest = crate::parallel::map_range(points.len(), |v| {
        let v = v as u32;
        // Ask for more than k so that exact distance ties are broken by input index.
        let mut near = tree.nearest(points[v as usize], k + 8, v);
        near.sort_by(|a, b| {
            a.0.total_cmp(&b.0).then(dt.input_index(a.1).cmp(&dt.input_index(b.1)))
        });
        near.truncate(k);
        near
    });
    let pairs = nearest
        .iter()
        .enumerate()
        .flat_map(|(v, near)| near.iter().map(move |&(_, w)| [v as u32, w]));
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

    #[test]
    fn a_huge_k_is_all_the_other_points_or_refused() {
        // Issue 30, G6: k = 10^9 allocated 800 GB, k = 2^64 - 1 overflowed.
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let all = vec![[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
        for k in [3, 1_000_000_000, usize::MAX] {
            let edges = crate::proximity_graph(&square, crate::GraphKind::Knn { k }).unwrap();
            assert_eq!(edges, all, "k = {k}");
        }
        let line: Vec<Point> = (0..20_000).map(|i| [f64::from(i), 0.0]).collect();
        let err = crate::proximity_graph(&line, crate::GraphKind::Knn { k: 10_000 }).unwrap_err();
        assert!(err.to_string().contains("at most 100000000 are built"), "{err}");
    }
}
