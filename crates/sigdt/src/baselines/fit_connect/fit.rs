//! The fit of one neighbourhood: a circle (or, when the points are too close to a line for
//! a circle, a line), the neighbours ordered along it on the two sides of the point, and
//! the conformity test.
//!
//! The circle is the "hyper" algebraic fit of A. Al-Sharadqah, N. Chernov, *Error analysis
//! for circle fitting algorithms*, Electronic Journal of Statistics 3, 2009: the centred
//! moments of the points, the root of the quartic characteristic polynomial found by
//! Newton's method from 0, then centre and radius in closed form. O(k) for k points, plus
//! O(k log k) to order them.
use crate::geometry::{distance, Point};

/// A fitted neighbourhood of one point `p`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Fit {
    /// The fitted curve.
    pub shape: Shape,
    /// The largest distance of a point of the neighbourhood from the fitted curve (the
    /// noise extent STRETCHDENOISE moves points within).
    pub extent: f64,
    /// Unit normal of the fitted curve at `p` (from the circle's centre through `p`).
    pub normal: Point,
}

/// A circle, or a line for (nearly) collinear neighbourhoods.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Shape {
    Circle {
        centre: Point,
        radius: f64,
    },
    /// Through `origin` with unit direction `direction`.
    Line {
        origin: Point,
        direction: Point,
    },
}

impl Default for Fit {
    fn default() -> Self {
        Fit {
            shape: Shape::Line { origin: [0.0, 0.0], direction: [1.0, 0.0] },
            extent: 0.0,
            normal: [0.0, 1.0],
        }
    }
}

/// A circle whose radius exceeds the neighbourhood's spread by this factor is read as a
/// line: the angles along it would be too small for `f64` to order reliably. A numerical
/// guard, not a tuning constant (a circle that large is a line at the data's precision).
const LINE_RADIUS_RATIO: f64 = 1e8;

/// Fits `p` and its neighbours `neighbours` (nearest first) and orders the neighbours on the
/// two sides of `p` along the fit, each side outward from `p`. Returns the fit, the sides
/// and whether the neighbourhood *conforms*: both sides are non-empty and the chord between
/// the outermost neighbour of each side, projected onto the fit, is longer than the
/// distance from `p`'s projection to either (`p` lies between its extreme neighbours).
/// Ties in the order are broken by `rank` (the input index).
pub(crate) fn fit_and_order(
    points: &[Point],
    p: u32,
    neighbours: &[u32],
    rank: impl Fn(u32) -> usize,
) -> (Fit, [Vec<u32>; 2], bool) {
    let all = || std::iter::once(p).chain(neighbours.iter().copied());
    let shape = fit_shape(all().map(|v| points[v as usize]));
    let at = |v: u32| project(shape, points[v as usize]);
    let here = at(p);
    // Signed position along the fit relative to `p`, as a key that orders like the angle
    // in (−π, π] on a circle (`±(1 − cos θ)`, no trigonometry) or the length on a line.
    let from = points[p as usize];
    let u = match shape {
        Shape::Circle { centre, .. } => [from[0] - centre[0], from[1] - centre[1]],
        Shape::Line { .. } => [0.0, 0.0],
    };
    let u_length = (u[0] * u[0] + u[1] * u[1]).sqrt();
    let position = |v: u32| -> f64 {
        let q = points[v as usize];
        match shape {
            Shape::Circle { centre, .. } => {
                let w = [q[0] - centre[0], q[1] - centre[1]];
                let cross = u[0] * w[1] - u[1] * w[0];
                let dot = u[0] * w[0] + u[1] * w[1];
                let norm = (u_length * (w[0] * w[0] + w[1] * w[1]).sqrt()).max(f64::MIN_POSITIVE);
                let away = 1.0 - (dot / norm).clamp(-1.0, 1.0);
                if cross < 0.0 {
                    -away
                } else if cross > 0.0 || dot < 0.0 {
                    away
                } else {
                    0.0
                }
            }
            Shape::Line { direction, .. } => {
                (q[0] - from[0]) * direction[0] + (q[1] - from[1]) * direction[1]
            }
        }
    };
    let mut keyed: Vec<(f64, usize, u32)> =
        neighbours.iter().map(|&v| (position(v), rank(v), v)).collect();
    keyed.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    // Negative positions are side 0, outward = decreasing; zero and positive are side 1.
    let split = keyed.partition_point(|k| k.0 < 0.0);
    let side0: Vec<u32> = keyed[..split].iter().rev().map(|k| k.2).collect();
    let side1: Vec<u32> = keyed[split..].iter().map(|k| k.2).collect();
    let conforms = match (side0.last(), side1.last()) {
        (Some(&a), Some(&b)) => {
            let (pa, pb) = (at(a), at(b));
            let chord = distance(pa, pb);
            chord > distance(here, pa) && chord > distance(here, pb)
        }
        _ => false,
    };
    let extent = all().map(|v| residual(shape, points[v as usize])).fold(0.0, f64::max);
    let normal = match shape {
        Shape::Circle { centre, .. } => {
            unit([points[p as usize][0] - centre[0], points[p as usize][1] - centre[1]])
        }
        Shape::Line { direction, .. } => [-direction[1], direction[0]],
    };
    (Fit { shape, extent, normal }, [side0, side1], conforms)
}

/// The largest distance of one of `points` (at least two, not all equal) from the curve
/// fitted to them all.
pub(crate) fn spread(points: &[Point]) -> f64 {
    let shape = fit_shape(points.iter().copied());
    points.iter().map(|&q| residual(shape, q)).fold(0.0, f64::max)
}

/// The orthogonal projection of `q` onto the fitted curve.
pub(crate) fn project(shape: Shape, q: Point) -> Point {
    match shape {
        Shape::Circle { centre, radius } => {
            let u = unit([q[0] - centre[0], q[1] - centre[1]]);
            [centre[0] + radius * u[0], centre[1] + radius * u[1]]
        }
        Shape::Line { origin, direction } => {
            let t = (q[0] - origin[0]) * direction[0] + (q[1] - origin[1]) * direction[1];
            [origin[0] + t * direction[0], origin[1] + t * direction[1]]
        }
    }
}

/// The distance of `q` from the fitted curve.
fn residual(shape: Shape, q: Point) -> f64 {
    match shape {
        Shape::Circle { centre, radius } => (distance(q, centre) - radius).abs(),
        Shape::Line { origin, direction } => {
            ((q[0] - origin[0]) * direction[1] - (q[1] - origin[1]) * direction[0]).abs()
        }
    }
}

/// `v / |v|`, or `(1, 0)` for the zero vector (a point at the centre has no direction).
fn unit(v: Point) -> Point {
    let len = v[0].hypot(v[1]);
    if len > 0.0 {
        [v[0] / len, v[1] / len]
    } else {
        [1.0, 0.0]
    }
}

/// The hyper circle fit of `points` (at least two, not all equal), or their total
/// least-squares line when the circle degenerates.
fn fit_shape(points: impl Iterator<Item = Point> + Clone) -> Shape {
    let n = points.clone().count() as f64;
    let (sx, sy) = points.clone().fold((0.0, 0.0), |(a, b), q| (a + q[0], b + q[1]));
    let mean = [sx / n, sy / n];
    let (mut mxx, mut myy, mut mxy, mut mxz, mut myz, mut mzz) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for q in points {
        let (x, y) = (q[0] - mean[0], q[1] - mean[1]);
        let z = x * x + y * y;
        mxx += x * x;
        myy += y * y;
        mxy += x * y;
        mxz += x * z;
        myz += y * z;
        mzz += z * z;
    }
    let (mxx, myy, mxy, mxz, myz, mzz) = (mxx / n, myy / n, mxy / n, mxz / n, myz / n, mzz / n);
    let line = || {
        // The principal axis of the covariance.
        let angle = 0.5 * (2.0 * mxy).atan2(mxx - myy);
        Shape::Line { origin: mean, direction: [angle.cos(), angle.sin()] }
    };
    let mz = mxx + myy;
    let cov_xy = mxx * myy - mxy * mxy;
    let var_z = mzz - mz * mz;
    // The characteristic polynomial 4x⁴ + a2 x² + a1 x + a0 (its cubic term vanishes).
    let a2 = 4.0 * cov_xy - 3.0 * mz * mz - mzz;
    let a1 = var_z * mz + 4.0 * cov_xy * mz - mxz * mxz - myz * myz;
    let a0 = mxz * (mxz * myy - myz * mxy) + myz * (myz * mxx - mxz * mxy) - var_z * cov_xy;
    let (mut x, mut y) = (0.0f64, a0);
    // Newton's method from 0 reaches the root that gives the fit; it stops when a step no
    // longer reduces |P| (a handful of steps in practice; 99 bounds it).
    for _ in 0..99 {
        let slope = a1 + x * (2.0 * a2 + 16.0 * x * x);
        let next = x - y / slope;
        if next == x || !next.is_finite() {
            break;
        }
        let value = a0 + next * (a1 + next * (a2 + 4.0 * next * next));
        if value.abs() >= y.abs() {
            break;
        }
        x = next;
        y = value;
    }
    let det = x * x - x * mz + cov_xy;
    let cx = (mxz * (myy - x) - myz * mxy) / det / 2.0;
    let cy = (myz * (mxx - x) - mxz * mxy) / det / 2.0;
    let radius = (cx * cx + cy * cy + mz - 2.0 * x).sqrt();
    let degenerate = det.is_nan() || det <= 0.0;
    if degenerate || !radius.is_finite() || radius > LINE_RADIUS_RATIO * mz.sqrt() {
        return line();
    }
    Shape::Circle { centre: [cx + mean[0], cy + mean[1]], radius }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn on_circle(c: Point, r: f64, angles: &[f64]) -> Vec<Point> {
        angles.iter().map(|a| [c[0] + r * a.cos(), c[1] + r * a.sin()]).collect()
    }

    #[test]
    fn fits_a_circle_through_exact_samples() {
        let pts = on_circle([2.0, -1.0], 3.0, &[0.0, 0.3, 0.7, 1.0, 1.6]);
        let Shape::Circle { centre, radius } = fit_shape(pts.iter().copied()) else {
            panic!("expected a circle")
        };
        assert!((centre[0] - 2.0).abs() < 1e-9 && (centre[1] + 1.0).abs() < 1e-9);
        assert!((radius - 3.0).abs() < 1e-9);
    }

    #[test]
    fn collinear_points_give_a_line() {
        let pts = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]];
        assert!(matches!(fit_shape(pts.iter().copied()), Shape::Line { .. }));
    }

    #[test]
    fn orders_sides_outward_and_tests_conformity() {
        // p at angle 0.5; neighbours at 0.3, 0.1 (one side) and 0.7, 1.0 (the other).
        let pts = on_circle([0.0, 0.0], 1.0, &[0.5, 0.3, 0.7, 0.1, 1.0]);
        let (fit, sides, conforms) = fit_and_order(&pts, 0, &[1, 2, 3, 4], |v| v as usize);
        assert!(conforms);
        assert!(fit.extent < 1e-9);
        let mut s = sides.clone();
        s.sort();
        assert_eq!(s, [vec![1, 3], vec![2, 4]]);
        // Neighbours all on one side: p is an end, not between them.
        let (_, sides, conforms) = fit_and_order(&pts, 3, &[0, 1, 2], |v| v as usize);
        assert!(!conforms);
        assert!(sides[0].is_empty() || sides[1].is_empty());
    }
}
