//! Exact reconstruction: is the result's undirected edge set the ground truth's?
//!
//! `docs/algorithms.md` §4.2 (the operational reading of \[MOW22\] Table 2): both lists are
//! normalised to `[min, max]` pairs and deduplicated, then compared as sets. A self loop `[i, i]` in the
//! result is an extra edge (so the result is not exact); one in the ground truth is a missing
//! edge no result can supply. Indices are not checked against a point count here: the
//! comparison needs no points, and an index out of range simply fails to match.
//!
//! # Complexity
//! O((r + g) log(r + g)) for `r` result and `g` ground-truth edges.
//!
//! # References
//! - \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use super::input::normalise;
use sigdt::Edge;

/// How a result's edge set differs from the ground truth's.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct EdgeDiff {
    /// Ground-truth edges absent from the result, normalised and sorted.
    pub missing: Vec<Edge>,
    /// Result edges absent from the ground truth (self loops included), normalised and
    /// sorted.
    pub extra: Vec<Edge>,
}

impl EdgeDiff {
    /// True when nothing is missing and nothing is extra.
    pub fn is_empty(&self) -> bool {
        self.missing.is_empty() && self.extra.is_empty()
    }
}

/// True iff `result` and `gt` are the same undirected edge set and `result` has no self
/// loop. Order and duplicates do not matter.
pub fn is_exact(result: &[Edge], gt: &[Edge]) -> bool {
    let (r, g) = (normalise(result), normalise(gt));
    r == g && r.iter().all(|e| e[0] != e[1])
}

/// The missing and extra edges of `result` with respect to `gt`.
pub fn edge_diff(result: &[Edge], gt: &[Edge]) -> EdgeDiff {
    let (r, g) = (normalise(result), normalise(gt));
    let missing = g.iter().filter(|e| e[0] == e[1] || r.binary_search(e).is_err()).copied();
    let extra = r.iter().filter(|e| e[0] == e[1] || g.binary_search(e).is_err()).copied();
    EdgeDiff { missing: missing.collect(), extra: extra.collect() }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: [Edge; 4] = [[0, 1], [1, 2], [2, 3], [0, 3]];

    #[test]
    fn order_and_direction_do_not_matter() {
        let shuffled = [[3, 2], [1, 0], [3, 0], [2, 1], [0, 1]];
        assert!(is_exact(&shuffled, &SQUARE));
        assert!(edge_diff(&shuffled, &SQUARE).is_empty());
    }

    #[test]
    fn missing_and_extra_edges() {
        let d = edge_diff(&[[0, 1], [1, 2], [2, 3], [0, 2]], &SQUARE);
        assert_eq!(d.missing, vec![[0, 3]]);
        assert_eq!(d.extra, vec![[0, 2]]);
        assert!(!is_exact(&SQUARE[..3], &SQUARE));
        assert!(!is_exact(&[], &SQUARE));
        assert!(is_exact(&[], &[]));
    }

    #[test]
    fn self_loops_are_never_exact() {
        let mut with_loop = SQUARE.to_vec();
        with_loop.push([2, 2]);
        assert!(!is_exact(&with_loop, &SQUARE));
        assert!(!is_exact(&[[1, 1]], &[[1, 1]]));
        assert_eq!(edge_diff(&with_loop, &SQUARE).extra, vec![[2, 2]]);
    }
}
