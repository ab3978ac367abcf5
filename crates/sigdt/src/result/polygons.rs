//! The loops of a result grouped into polygons with holes, decided with exact predicates.
//!
//! The loops of every method are vertex-disjoint and no two of their edges cross, so one
//! loop lies inside another exactly when one of its vertices does. A loop inside an even
//! number of others is a *shell*; the loops directly inside it (one level deeper) are its
//! *holes*; a loop inside a hole is a shell again. The writers (WKT, GeoJSON), the pictures
//! and the Python views all group loops this way.
//!
//! Point in loop is the even-odd crossing count of a ray towards `+x`, with every crossing
//! decided by comparisons and `orient2d` on exactly scaled coordinates, so the answer is
//! exact for any finite input.
//!
//! # Complexity
//! O(k² + Σ |loop|) for `k` loops when bounding boxes separate them, O(k · Σ |loop|) at worst
//! (loops nested in one another).
use super::Reconstruction;
use crate::delaunay::hygiene::Scaling;
use crate::geometry::{orient2d, Point};

/// A polygon of a result: indices into [`Reconstruction::loops`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Polygon {
    /// The loop that bounds the polygon (counter-clockwise, as every loop).
    pub shell: usize,
    /// The loops directly inside the shell, in loop order.
    pub holes: Vec<usize>,
}

impl Reconstruction {
    /// The loops grouped into polygons with holes, shells in loop order (see the module
    /// docs). `points` are the points the result was computed from.
    ///
    /// ```
    /// // A square inside a larger square: one polygon with a hole.
    /// let points = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0],
    ///               [1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]];
    /// let rec = sigdt::Reconstruction {
    ///     loops: vec![vec![0, 1, 2, 3], vec![4, 5, 6, 7]],
    ///     ..Default::default()
    /// };
    /// let polygons = rec.polygons(&points);
    /// assert_eq!(polygons, vec![sigdt::Polygon { shell: 0, holes: vec![1] }]);
    /// ```
    pub fn polygons(&self, points: &[Point]) -> Vec<Polygon> {
        nest(points, &self.loops)
    }
}

fn nest(points: &[Point], loops: &[Vec<usize>]) -> Vec<Polygon> {
    // Loops are made of input points, which `Scaling` accepts unless they are unusable for
    // any predicate; unscaled coordinates then still give the answer for ordinary input.
    let scaled: Vec<Point> = match Scaling::for_points(points) {
        Ok(scaling) => points.iter().map(|&p| scaling.apply(p)).collect(),
        Err(_) => points.to_vec(),
    };
    let boxes: Vec<[f64; 4]> = loops
        .iter()
        .map(|l| {
            l.iter().fold(
                [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY],
                |b, &i| {
                    let [x, y] = scaled[i];
                    [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)]
                },
            )
        })
        .collect();
    // Loop `i` is inside loop `j` when a vertex of `i` that is not on `j` is (the first
    // vertex, for the vertex-disjoint loops of a reconstruction).
    let inside = |i: usize, j: usize| {
        let b = boxes[j];
        let in_box = |[x, y]: Point| (b[0]..=b[2]).contains(&x) && (b[1]..=b[3]).contains(&y);
        if i == j || loops[j].is_empty() || !loops[i].first().is_some_and(|&v| in_box(scaled[v])) {
            return false;
        }
        let Some(&v) = loops[i].iter().find(|v| !loops[j].contains(v)) else { return false };
        in_ring(&scaled, &loops[j], scaled[v])
    };
    let containers: Vec<Vec<usize>> =
        (0..loops.len()).map(|i| (0..loops.len()).filter(|&j| inside(i, j)).collect()).collect();
    let depth: Vec<usize> = containers.iter().map(Vec::len).collect();
    (0..loops.len())
        .filter(|&i| depth[i] % 2 == 0)
        .map(|shell| Polygon {
            shell,
            holes: (0..loops.len())
                .filter(|&h| depth[h] == depth[shell] + 1 && containers[h].contains(&shell))
                .collect(),
        })
        .collect()
}

/// Whether `p` lies inside the closed ring through `ring` (even-odd rule). A crossing of the
/// ray from `p` towards `+x` with edge `ab` (one end above `p`, the other not) lies right of
/// `p` exactly when `p` is on the left of the edge directed upwards.
fn in_ring(points: &[Point], ring: &[usize], p: Point) -> bool {
    let mut inside = false;
    for k in 0..ring.len() {
        let (a, b) = (points[ring[k]], points[ring[(k + 1) % ring.len()]]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let side = orient2d(a, b, p);
            if (side > 0.0) == (b[1] > a[1]) && side != 0.0 {
                inside = !inside;
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, s: f64) -> [Point; 4] {
        [[x, y], [x + s, y], [x + s, y + s], [x, y + s]]
    }

    #[test]
    fn nested_squares_alternate_shells_and_holes() {
        // Squares of side 8, 4 and 2 nested in one another, and one of side 1 beside them.
        let points: Vec<Point> = [square(0.0, 0.0, 8.0), square(2.0, 2.0, 4.0)]
            .into_iter()
            .chain([square(3.0, 3.0, 2.0), square(10.0, 0.0, 1.0)])
            .flatten()
            .collect();
        let loops: Vec<Vec<usize>> = (0..4).map(|k| (4 * k..4 * k + 4).collect()).collect();
        let polygons = nest(&points, &loops);
        assert_eq!(
            polygons,
            vec![
                Polygon { shell: 0, holes: vec![1] },
                Polygon { shell: 2, holes: vec![] },
                Polygon { shell: 3, holes: vec![] },
            ]
        );
    }

    #[test]
    fn a_vertex_level_with_a_ring_vertex_counts_once() {
        // The ray from (1, 1) passes exactly through the ring's vertex (3, 1).
        let points = [[0.0, 0.0], [3.0, 1.0], [0.0, 2.0], [1.0, 1.0]];
        assert!(in_ring(&points, &[0, 1, 2], points[3]));
        assert!(!in_ring(&points, &[0, 1, 2], [3.5, 1.0]));
        // Far beyond f64 squares: exact all the same.
        let huge: Vec<Point> = points.iter().map(|p| [p[0] * 1e300, p[1] * 1e300]).collect();
        assert_eq!(nest(&huge, &[vec![0, 1, 2], vec![3]]).len(), 1);
    }
}
