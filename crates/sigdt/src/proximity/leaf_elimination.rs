//! Leaf elimination: SIGDT2, a graph with vertex degree ≥ 2 everywhere.
//!
//! [MOW22] §4.2.3: leaves appear where the curve is undersampled; each leaf gets its shortest
//! incident Delaunay edge not yet in the graph. The paper says this "does not affect results
//! in general" and helps point sets with sharp corners.
//!
//! Order (our decision, `docs/algorithms.md` §1.4): leaves are served in ascending length of
//! that candidate edge (ties by input index), and a leaf that an earlier addition already
//! gave a second edge is skipped. This never gives a vertex a third edge when two leaves
//! choose each other, and unlike index order it does not depend on how the input happens to
//! be ordered.
//!
//! # Complexity
//! O(n log n) for sorting the leaves, O(n) otherwise ([MOW22]: O(kn) for degree k).
//!
//! # References
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::Triangulation;
use crate::graph::EdgeMask;

/// Adds to `graph` the edges that eliminate its leaves; returns how many were added.
pub fn eliminate_leaves(dt: &Triangulation, graph: &mut EdgeMask) -> usize {
    let degree = graph.degrees(dt);
    eliminate_leaves_with_degrees(dt, graph, degree)
}

/// [`eliminate_leaves`] given the degree of every vertex in `graph`.
pub(crate) fn eliminate_leaves_with_degrees(
    dt: &Triangulation,
    graph: &mut EdgeMask,
    mut degree: Vec<u32>,
) -> usize {
    let n = dt.num_vertices() as u32;
    let mut leaves: Vec<(f64, usize, u32, u32)> = (0..n)
        .filter(|&v| degree[v as usize] == 1)
        .filter_map(|v| {
            let h = dt.incident(v).filter(|&h| !graph.contains(h)).min_by(|&a, &b| {
                dt.length(a)
                    .total_cmp(&dt.length(b))
                    .then(dt.input_index(dt.other(a, v)).cmp(&dt.input_index(dt.other(b, v))))
            })?;
            Some((dt.length(h), dt.input_index(v), v, h))
        })
        .collect();
    leaves.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let mut added = 0;
    for (_, _, v, h) in leaves {
        if degree[v as usize] == 1 && !graph.contains(h) {
            graph.set(dt, h, true);
            degree[v as usize] += 1;
            degree[dt.other(h, v) as usize] += 1;
            added += 1;
        }
    }
    added
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proximity::sigdt::sigdt_mask;

    #[test]
    fn every_vertex_gets_degree_two() {
        // Two clusters joined by nothing in SIGDT, each a path of three points.
        let pts = [[0.0, 0.0], [1.0, 0.1], [2.0, 0.0], [0.0, 5.0], [1.0, 5.1], [2.0, 5.0]];
        let dt = Triangulation::new(&pts).unwrap();
        let mut g = sigdt_mask(&dt);
        let added = eliminate_leaves(&dt, &mut g);
        assert!(added > 0);
        for v in 0..dt.num_vertices() as u32 {
            assert!(g.degree(&dt, v) >= 2, "vertex {v}");
        }
    }
}
