//! Small geometric helpers shared by every algorithm: points, lengths, exact orientation.
//!
//! Lengths and costs use plain `f64`; every yes/no geometric question goes through the exact
//! adaptive predicates of the `robust` crate (Shewchuk's orient2d/incircle).

/// A point in the plane.
pub type Point = [f64; 2];

/// An undirected edge `[i, j]` between input point indices, `i < j`.
pub type Edge = [usize; 2];

/// Euclidean distance between `p` and `q`, computed as `sqrt(dx² + dy²)`.
///
/// Callers pass coordinates that [`crate::delaunay::Triangulation`] has brought into a safe
/// range, so the squares neither overflow nor underflow.
#[inline]
pub fn distance(p: Point, q: Point) -> f64 {
    squared_distance(p, q).sqrt()
}

/// Squared Euclidean distance `dx² + dy²` (same range caveat as [`distance`]).
#[inline]
pub fn squared_distance(p: Point, q: Point) -> f64 {
    let dx = p[0] - q[0];
    let dy = p[1] - q[1];
    dx * dx + dy * dy
}

/// Exact orientation of `r` relative to the directed line `p → q`: positive if `r` lies to
/// the left (counter-clockwise), negative to the right, zero if the three are collinear.
#[inline]
pub fn orient2d(p: Point, q: Point, r: Point) -> f64 {
    robust::orient2d(
        robust::Coord { x: p[0], y: p[1] },
        robust::Coord { x: q[0], y: q[1] },
        robust::Coord { x: r[0], y: r[1] },
    )
}

/// Whether the segments `ab` and `cd` cross at a point interior to both (exact). Segments
/// that only touch at an end point, or overlap collinearly, do not count as crossing.
pub fn segments_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    let d1 = orient2d(a, b, c);
    let d2 = orient2d(a, b, d);
    let d3 = orient2d(c, d, a);
    let d4 = orient2d(c, d, b);
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_signs() {
        assert!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]) > 0.0);
        assert!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, -1.0]) < 0.0);
        assert_eq!(orient2d([0.0, 0.0], [1.0, 1.0], [3.0, 3.0]), 0.0);
    }

    #[test]
    fn crossing_segments() {
        assert!(segments_cross([0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]));
        assert!(!segments_cross([0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]));
        assert!(!segments_cross([0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]));
    }

    #[test]
    fn distance_is_euclidean() {
        assert_eq!(distance([0.0, 0.0], [3.0, 4.0]), 5.0);
    }
}
