//! The incircle test under a symbolic perturbation: what makes the triangulation canonical.
//!
//! Four cocircular points have two Delaunay triangulations, and which one an algorithm builds
//! depends on the order it meets them in. Lifting every point to the paraboloid
//! `z = x² + y²` and raising it by an infinitesimal that grows with its rank in lexicographic
//! order (`x`, then `y`) breaks every such tie the same way: the Delaunay triangulation of
//! the perturbed points, the lower convex hull of their lifts, is unique, so every correct
//! construction (any insertion order, any thread count) returns the same triangles. The
//! scheme is Devillers and Teillaud's (*Perturbations for Delaunay and weighted Delaunay 3D
//! triangulations*, CGTA 44(3), 2011), the lifting-only case of Edelsbrunner and Mücke's
//! Simulation of Simplicity (*ACM TOG* 9(1), 1990); the ranks depend on the coordinates
//! alone, so the rule needs no input index.
//!
//! The incircle determinant is linear in each lift, and raising one point's lift moves the
//! determinant by that point's cofactor: the orientation of the other three points, signed
//! by the raised point's place. So when the exact determinant is zero, its perturbed sign is
//! the sign of the first non-zero cofactor, taken from the lexicographically largest point
//! down. A triangle among the four is never flat where the triangulation asks, so the answer
//! is never zero.
//!
//! # Complexity
//! O(1): one exact incircle, plus at most three exact orientations on exact ties only.
use crate::geometry::{orient2d, Point};

/// The sign of `incircle(a, b, c, d)` under the perturbation: positive if `d` lies inside the
/// circle through the counter-clockwise `a, b, c` (negative if they are clockwise), negative
/// if outside; exact when the points are not cocircular. Zero only when all four are
/// collinear.
#[inline]
pub fn incircle(a: Point, b: Point, c: Point, d: Point) -> f64 {
    let coord = |p: Point| robust::Coord { x: p[0], y: p[1] };
    let exact = robust::incircle(coord(a), coord(b), coord(c), coord(d));
    if exact != 0.0 {
        return exact;
    }
    tie_break([a, b, c, d])
}

/// The sign of the leading non-zero term of the perturbed determinant (module docs).
#[cold]
fn tie_break(points: [Point; 4]) -> f64 {
    let [a, b, c, d] = points;
    // Raising a point's lift: for `d` the determinant falls with `orient(a, b, c)`; for each
    // of `a, b, c` it rises with the orientation of the triangle where `d` takes its place.
    let cofactor = |k: usize| match k {
        0 => orient2d(d, b, c),
        1 => orient2d(a, d, c),
        2 => orient2d(a, b, d),
        _ => -orient2d(a, b, c),
    };
    let mut by_rank = [0, 1, 2, 3];
    by_rank.sort_unstable_by(|&i, &j| lexicographic(points[j], points[i]));
    by_rank.into_iter().map(cofactor).find(|&term| term != 0.0).unwrap_or(0.0)
}

/// Lexicographic order on points (`x`, then `y`): the ranks of the perturbation, and the
/// order the divide-and-conquer triangulation splits in.
pub(super) fn lexicographic(p: Point, q: Point) -> std::cmp::Ordering {
    p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_signs_are_kept() {
        let (a, b, c) = ([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
        assert!(incircle(a, b, c, [0.4, 0.4]) > 0.0);
        assert!(incircle(a, b, c, [2.0, 2.0]) < 0.0);
        assert!(incircle(a, c, b, [0.4, 0.4]) < 0.0);
    }

    /// The four corners of a square: whichever triangle is asked about, the diagonal chosen
    /// is the same one, so the test is antisymmetric in swapping points and consistent.
    #[test]
    fn cocircular_points_are_decided_the_same_way_in_every_order() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        // With ccw triangle (p, q, r) and query s, "inside" means edge pr (the diagonal
        // through q's triangle) must flip to qs.
        let mut diagonals = std::collections::BTreeSet::new();
        for [p, q, r, s] in [[0, 1, 2, 3], [1, 2, 3, 0], [2, 3, 0, 1], [3, 0, 1, 2]] {
            let sign = incircle(square[p], square[q], square[r], square[s]);
            assert_ne!(sign, 0.0);
            let diagonal = if sign > 0.0 { [q.min(s), q.max(s)] } else { [p.min(r), p.max(r)] };
            diagonals.insert(diagonal);
        }
        assert_eq!(diagonals.len(), 1, "{diagonals:?}");
    }

    /// Swapping two points negates the perturbed determinant, as it does the exact one.
    #[test]
    fn the_perturbed_sign_is_antisymmetric() {
        let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let s = incircle(pts[0], pts[1], pts[2], pts[3]);
        assert_eq!(incircle(pts[1], pts[0], pts[2], pts[3]), -s);
        assert_eq!(incircle(pts[0], pts[1], pts[3], pts[2]), -s);
        assert_eq!(incircle(pts[3], pts[1], pts[2], pts[0]), -s);
    }

    #[test]
    fn only_four_collinear_points_tie() {
        let line = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]];
        assert_eq!(incircle(line[0], line[1], line[2], line[3]), 0.0);
    }
}
