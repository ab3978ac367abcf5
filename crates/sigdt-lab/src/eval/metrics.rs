//! All result metrics at once: exactness, edge differences, distances and area.
//!
//! [`evaluate`] validates the input once and runs [`edge_diff`], [`distance_errors`] and
//! [`area_difference`]. The sampling density epsilon
//! ([`graph_epsilon`](super::graph_epsilon)) and the graph statistics
//! ([`overlap`](fn@super::overlap)) depend on the labelled set only, so they are computed
//! separately, once per set rather than once per method.
//!
//! # Complexity
//! O((n + m + s) log(n + m)) for `m` edges and `s` distance samples.
use super::input::check_all;
use super::{area_difference, distance_errors, edge_diff, AreaDifference, DistanceErrors};
use sigdt::{Edge, Point, Result};

/// Every metric of one reconstruction against its ground truth.
#[derive(Debug, Clone, PartialEq)]
pub struct Metrics {
    /// The result's edge set equals the ground truth's (`docs/algorithms.md` §4.2).
    pub exact: bool,
    /// Number of ground-truth edges the result lacks.
    pub missing: usize,
    /// Number of result edges not in the ground truth (self loops included).
    pub extra: usize,
    /// Distance errors; `None` when the result or the ground truth has no edge.
    pub distance: Option<DistanceErrors>,
    /// Symmetric difference of area.
    pub area: AreaDifference,
}

/// Evaluates `result` against `gt`, both edges over `points`. Fails on non-finite points or
/// edges out of range.
pub fn evaluate(points: &[Point], result: &[Edge], gt: &[Edge]) -> Result<Metrics> {
    check_all(points, result, gt)?;
    let diff = edge_diff(result, gt);
    Ok(Metrics {
        exact: diff.is_empty(),
        missing: diff.missing.len(),
        extra: diff.extra.len(),
        distance: distance_errors(points, result, gt)?,
        area: area_difference(points, result, gt)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: [Point; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    const EDGES: [Edge; 4] = [[0, 1], [1, 2], [2, 3], [0, 3]];

    #[test]
    fn square_against_itself_and_with_an_edge_missing() {
        let m = evaluate(&SQUARE, &EDGES, &EDGES).unwrap();
        assert!(m.exact && m.missing == 0 && m.extra == 0);
        assert_eq!(m.distance.unwrap().hausdorff, 0.0);
        assert_eq!(m.area.area, 0.0);
        let m = evaluate(&SQUARE, &EDGES[1..], &EDGES).unwrap();
        assert!(!m.exact && m.missing == 1 && m.extra == 0);
        assert!(m.distance.unwrap().hausdorff > 0.0);
        // The open chain 1-2-3-0 closes back into the square: no area lost.
        assert!(m.area.area.abs() < 1e-9);
    }

    #[test]
    fn empty_result() {
        let m = evaluate(&SQUARE, &[], &EDGES).unwrap();
        assert!(!m.exact && m.missing == 4);
        assert_eq!(m.distance, None);
        assert!((m.area.area - 1.0).abs() < 1e-9);
        let err = evaluate(&SQUARE, &[[1, 7]], &EDGES).unwrap_err().to_string();
        assert!(err.contains("result edge 0 ([1, 7]) refers to point 7 of 4"), "{err}");
    }
}
