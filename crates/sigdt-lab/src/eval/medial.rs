//! Medial points of a polyline: the circumcentres of the Delaunay triangles of its vertices.
//!
//! The Voronoi vertices of a dense sample of a smooth curve converge to its medial axis
//! (\[ABE98\], the poles of the crust); the data set's generator approximates the medial axis
//! of each smooth arc the same way, from the arc's dense points (data/README.md, "Epsilon").
//! Here the arc's own samples stand in for the dense points. Fewer than three distinct or
//! only collinear points have no triangle and so no medial point (a straight arc has
//! infinite local feature size).
//!
//! # Complexity
//! O(k log k) for `k` points (the triangulation).
//!
//! # References
//! - \[ABE98\] N. Amenta, M. Bern, D. Eppstein. The crust and the β-skeleton: combinatorial
//!   curve reconstruction. Graphical Models and Image Processing 60(2), 1998.
use sigdt::delaunay::Shape;
use sigdt::Triangulation;
use sigdt::{Point, Result};

/// The circumcentres of the Delaunay triangles of `points` (finite ones only), in triangle
/// order.
pub(crate) fn medial_points(points: &[Point]) -> Result<Vec<Point>> {
    if points.len() < 3 {
        return Ok(Vec::new());
    }
    let dt = Triangulation::new(points)?;
    if dt.shape() != Shape::Proper {
        return Ok(Vec::new());
    }
    let corner = |h: u32| points[dt.input_index(dt.origin(h))];
    Ok((0..dt.num_triangles() as u32)
        .filter_map(|t| circumcentre(corner(3 * t), corner(3 * t + 1), corner(3 * t + 2)))
        .collect())
}

/// Centre of the circle through `a`, `b`, `c`, computed relative to `a`; `None` when they are
/// (numerically) collinear.
fn circumcentre(a: Point, b: Point, c: Point) -> Option<Point> {
    let (bx, by) = (b[0] - a[0], b[1] - a[1]);
    let (cx, cy) = (c[0] - a[0], c[1] - a[1]);
    let d = 2.0 * (bx * cy - by * cx);
    let (b2, c2) = (bx * bx + by * by, cx * cx + cy * cy);
    let centre = [a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d];
    (centre[0].is_finite() && centre[1].is_finite()).then_some(centre)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regular_polygon_has_its_centre() {
        let pts: Vec<Point> = (0..8)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 8.0;
                [3.0 + a.cos(), a.sin()]
            })
            .collect();
        let m = medial_points(&pts).unwrap();
        assert_eq!(m.len(), 6);
        assert!(m.iter().all(|p| (p[0] - 3.0).abs() < 1e-9 && p[1].abs() < 1e-9));
        assert!(medial_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]).unwrap().is_empty());
        assert!(medial_points(&pts[..2]).unwrap().is_empty());
    }
}
