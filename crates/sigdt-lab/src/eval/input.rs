//! Input checks shared by the metrics: finite coordinates, edge indices in range, and the
//! normal form of an edge list (`[i, j]` with `i < j`, sorted, no duplicates).
//!
//! Every public metric validates here once, at its entry; the helpers behind it assume valid
//! input. O(n + m log m).
use crate::power_of_two::{exponent_into, pow2};
use sigdt::{Edge, Error, Point, Result};

/// Fails with [`Error::NonFinite`] on the first point with a NaN or infinite coordinate.
pub(crate) fn check_points(points: &[Point]) -> Result<()> {
    match points.iter().position(|p| !(p[0].is_finite() && p[1].is_finite())) {
        Some(index) => Err(Error::NonFinite { index, x: points[index][0], y: points[index][1] }),
        None => Ok(()),
    }
}

/// Fails with [`Error::InvalidOption`] naming the first edge of `edges` (called `what`, for
/// example "ground-truth") that refers to a point outside `0..n`.
pub(crate) fn check_edges(what: &str, edges: &[Edge], n: usize) -> Result<()> {
    match edges.iter().position(|e| e[0] >= n || e[1] >= n) {
        Some(k) => {
            let e = edges[k];
            let bad = if e[0] >= n { e[0] } else { e[1] };
            Err(Error::InvalidOption(format!(
                "{what} edge {k} ([{}, {}]) refers to point {bad} of {n}",
                e[0], e[1]
            )))
        }
        None => Ok(()),
    }
}

/// Points and both edge lists checked at once.
pub(crate) fn check_all(points: &[Point], result: &[Edge], gt: &[Edge]) -> Result<()> {
    check_points(points)?;
    check_edges("result", result, points.len())?;
    check_edges("ground-truth", gt, points.len())
}

/// `edges` as `[min, max]` pairs, sorted and deduplicated; self loops `[i, i]` are kept
/// (callers decide what they mean).
pub(crate) fn normalise(edges: &[Edge]) -> Vec<Edge> {
    let mut out: Vec<Edge> = edges.iter().map(|&[i, j]| [i.min(j), i.max(j)]).collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// [`normalise`] without self loops.
pub(crate) fn proper_edges(edges: &[Edge]) -> Vec<Edge> {
    let mut out = normalise(edges);
    out.retain(|e| e[0] != e[1]);
    out
}

/// Axis-aligned bounding box `[min, max]` of the points at the ends of `edges`, or `None`
/// when there are no edges.
pub(crate) fn edge_bbox(points: &[Point], edges: &[Edge]) -> Option<[Point; 2]> {
    let mut it = edges.iter().flat_map(|e| e.iter()).map(|&i| points[i]);
    let first = it.next()?;
    Some(it.fold([first, first], |[lo, hi], p| {
        [[lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])]]
    }))
}

/// Width and height of a box.
pub(crate) fn extent(b: [Point; 2]) -> [f64; 2] {
    [b[1][0] - b[0][0], b[1][1] - b[0][1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_edge() {
        let err = check_edges("ground-truth", &[[0, 1], [3, 999]], 500).unwrap_err();
        assert_eq!(
            err.to_string(),
            "invalid option: ground-truth edge 1 ([3, 999]) refers to point 999 of 500"
        );
        assert!(check_points(&[[0.0, f64::NAN]]).is_err());
        assert_eq!(proper_edges(&[[2, 1], [1, 2], [3, 3]]), vec![[1, 2]]);
    }
}

/// The power of two `2^k` that brings the largest magnitude among some coordinates into
/// [1, 2) (1 when they are all zero or one is not finite), kept as two factors because
/// `2^k` itself may not be a finite `f64` (subnormal input needs k up to 1074).
///
/// Multiplying by it is exact (short of subnormal underflow), so ratios such as distances
/// over the diagonal do not change, while squared lengths and areas can no longer overflow
/// (beyond about 1e154) or vanish (subnormal input): they gave infinite or NaN distances,
/// and an integer overflow inside `i_overlay` (fuzzing findings 4 and 5).
#[derive(Debug, Clone, Copy)]
pub(crate) struct UnitScale([f64; 2]);

impl UnitScale {
    pub(crate) fn of(coordinates: impl Iterator<Item = f64>) -> UnitScale {
        let largest = coordinates.fold(0.0f64, |m, c| m.max(c.abs()));
        let k = exponent_into(largest, 0);
        UnitScale([pow2(k / 2), pow2(k - k / 2)])
    }

    /// `p · 2^k`.
    pub(crate) fn apply(self, p: Point) -> Point {
        let [a, b] = self.0;
        [p[0] * a * b, p[1] * a * b]
    }

    /// An area measured on scaled points, in the original units (`area / 4^k`; it may
    /// overflow or underflow, as the true value does).
    pub(crate) fn unscale_area(self, area: f64) -> f64 {
        let [a, b] = self.0;
        area / a / a / b / b
    }
}
