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

/// Distance from `q` to the closed segment `ab` (to `a` when the segment is a point).
pub fn segment_distance(q: Point, a: Point, b: Point) -> f64 {
    segment_foot(q, a, b).0
}

/// Distance from `q` to the closed segment `ab`, and the parameter in `[0, 1]` of the
/// nearest point of the segment (`0` when the segment is a point). Measured as [`distance`]
/// measures (not `hypot`, which guards a range the coordinates never reach, slowly).
pub fn segment_foot(q: Point, a: Point, b: Point) -> (f64, f64) {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let foot = [a[0] + t * dx, a[1] + t * dy];
    (distance(q, foot), t)
}

/// Distance from `q` to the ray that starts at `from` and goes on in the direction
/// `behind → from` (to `from` when the two coincide): the straight continuation of the
/// segment `behind from` beyond `from`, plus `from` itself.
pub fn ray_distance(q: Point, behind: Point, from: Point) -> f64 {
    let (dx, dy) = (from[0] - behind[0], from[1] - behind[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((q[0] - from[0]) * dx + (q[1] - from[1]) * dy) / len2).max(0.0)
    } else {
        0.0
    };
    let foot = [from[0] + t * dx, from[1] + t * dy];
    distance(q, foot)
}

/// How much the polyline `p → q → r` turns at `q`, in radians: 0 straight on, π straight
/// back. A cost, not a predicate: plain `f64` (`atan2` of the cross and dot products).
pub fn turning(p: Point, q: Point, r: Point) -> f64 {
    let (u, v) = ([q[0] - p[0], q[1] - p[1]], [r[0] - q[0], r[1] - q[1]]);
    let cross = u[0] * v[1] - u[1] * v[0];
    let dot = u[0] * v[0] + u[1] * v[1];
    cross.abs().atan2(dot)
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
    fn segments_rays_and_turns() {
        assert_eq!(segment_distance([1.0, 2.0], [0.0, 0.0], [2.0, 0.0]), 2.0);
        assert_eq!(segment_distance([5.0, 0.0], [0.0, 0.0], [2.0, 0.0]), 3.0);
        assert_eq!(segment_distance([0.0, 1.0], [3.0, 3.0], [3.0, 3.0]), 13f64.sqrt());
        // The ray from (1, 0) goes on towards +x; behind it only its start counts.
        assert_eq!(ray_distance([5.0, 1.0], [0.0, 0.0], [1.0, 0.0]), 1.0);
        assert_eq!(ray_distance([-3.0, 0.0], [0.0, 0.0], [1.0, 0.0]), 4.0);
        let quarter = turning([0.0, 0.0], [1.0, 0.0], [1.0, 1.0]);
        assert!((quarter - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert_eq!(turning([0.0, 0.0], [1.0, 0.0], [2.0, 0.0]), 0.0);
        assert_eq!(turning([0.0, 0.0], [1.0, 0.0], [0.0, 0.0]), std::f64::consts::PI);
    }

    #[test]
    fn distance_is_euclidean() {
        assert_eq!(distance([0.0, 0.0], [3.0, 4.0]), 5.0);
    }
}
