//! CRUST: the Delaunay edges between samples that survive adding the Voronoi vertices.
//!
//! [ABE98], `docs/algorithms.md` §3.1:
//! 1. the Delaunay triangulation of the samples `S` (given);
//! 2. `V`, the circumcentres of its triangles (the Voronoi vertices of `S`);
//! 3. the Delaunay triangulation of `S ∪ V`;
//! 4. its edges whose two endpoints are samples.
//!
//! Equivalently, a Delaunay edge `pq` of `S` is kept iff some circle through `p` and `q` is
//! empty of both samples and Voronoi vertices.
//!
//! # Guarantee
//! If `S` is an ε-sample of a smooth closed curve with ε < 0.252, the crust is exactly the
//! polygon connecting curve neighbours ([ABE98]; the bound as quoted in [MOW22]). Nothing is
//! promised for open curves, sharp corners or noise: the crust may then miss edges (leaving
//! leaves or isolated points) or keep chords.
//!
//! # Complexity
//! O(n log n) expected: one more Delaunay triangulation, of at most `3n` points, built with
//! spade's exact predicates: the samples in the first triangulation's (BRIO) vertex order,
//! then the circumcentres in their own BRIO order (fixed seed), each walk starting at the
//! previous vertex.
//!
//! # Departures and decisions
//! - The circumcentres are computed in floating point (relative to one vertex, divided by the
//!   exact-sign orient2d determinant), so `V` is the rounded Voronoi diagram; the second
//!   triangulation then uses spade's exact predicates on those rounded points, as every
//!   floating-point implementation of CRUST does.
//! - Coincident circumcentres (cocircular samples) are merged only when bitwise equal (spade
//!   merges exact duplicates), not within a `1e-12 · diag` tolerance (`docs/algorithms.md`
//!   §3.1 weighs both). Two nearly coincident Voronoi vertices block the same circles except those passing between
//!   them, so the merge tolerance makes no difference outside such ties.
//! - Hull triangles that are almost flat have astronomically far circumcentres. They are
//!   *not* dropped for being far: dropping one can keep a hull chord that it alone blocks
//!   (samples `(0,0)`, `(1,-δ)`, `(2,0)` on the hull: the centre at distance `1/2δ` is the
//!   only Voronoi vertex inside every circle through `(0,0)` and `(2,0)`). Instead, when a
//!   centre exceeds spade's coordinate range (2^201 with samples below 2^31), everything is
//!   rescaled by an exact power of two as far as the smallest non-zero sample coordinate
//!   allows (spade's lower limit 2^-142); centre coordinates that then fall below 2^-142 are
//!   rounded to 0 (far below their own rounding error unless the nearby samples are equally
//!   tiny). A centre that still does not fit, or is not finite, is dropped. With the bounds
//!   of a Delaunay triangle on the f64 grid this can happen only when the non-zero input
//!   coordinates span more than about 2^75, and then it may keep a chord next to that
//!   triangle.
//!
//! # References
//! - [ABE98] N. Amenta, M. Bern, D. Eppstein. The crust and the β-skeleton: combinatorial
//!   curve reconstruction. Graphical Models and Image Processing 60(2), 1998.
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [ABE98]: https://doi.org/10.1006/gmip.1998.0465
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::brio::brio_order_within;
use crate::delaunay::Triangulation;
use crate::geometry::{orient2d, Point};
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, Point2, Triangulation as _};

/// Largest absolute coordinate spade accepts (2^201).
const MAX_ALLOWED: f64 = spade::MAX_ALLOWED_VALUE;
/// Smallest non-zero absolute coordinate spade accepts (2^-142).
const MIN_ALLOWED: f64 = spade::MIN_ALLOWED_VALUE;

/// The CRUST edges of `dt` (a [`Shape::Proper`](crate::delaunay::Shape::Proper)
/// triangulation) as pairs of vertices, each undirected edge once.
pub fn crust(dt: &Triangulation) -> Vec<[u32; 2]> {
    let m = dt.num_vertices();
    if dt.num_triangles() == 0 {
        return Vec::new();
    }
    // Step 2: one circumcentre per triangle.
    let mut centres: Vec<Point> = (0..dt.num_triangles() as u32)
        .map(|t| {
            let [a, b, c] = [3 * t, 3 * t + 1, 3 * t + 2].map(|h| dt.point(dt.origin(h)));
            circumcentre(a, b, c)
        })
        .collect();
    let scale = range_scale(dt, &centres);
    for w in &mut centres {
        for x in w.iter_mut() {
            *x *= scale;
            if x.abs() < MIN_ALLOWED {
                *x = 0.0; // also turns -0.0 into 0.0
            }
        }
    }

    // Step 3: samples first, in vertex order, so that spade's vertex `v < m` is sample `v`.
    let mut del: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::with_capacity(m + centres.len(), 3 * (m + centres.len()), 0);
    let mut hint = FixedVertexHandle::from_index(0);
    for v in 0..m as u32 {
        let [x, y] = dt.point(v);
        // Samples were validated by `Triangulation::new`; scaling keeps them in range.
        match del.insert_with_hint(Point2::new(x * scale, y * scale), hint) {
            Ok(handle) => hint = handle,
            Err(_) => return Vec::new(), // unreachable
        }
        debug_assert_eq!(hint.index(), v as usize);
    }
    // Circumcentres in BRIO order (shuffled rounds of doubling size, each sorted along a
    // Hilbert curve), each walk starting at the previous centre. Plain Hilbert order is
    // quadratic in practice: the thin interior triangles of a dense curve have large
    // overlapping circumcircles, and a sweep along the medial axis keeps destroying the
    // untouched ones ahead of it; random rounds bound the expected total work.
    let mut order: Vec<u32> = (0..centres.len() as u32).collect();
    let samples = (0..m as u32).map(|v| dt.point(v).map(|x| x * scale));
    brio_order_within(|i| centres[i as usize], &mut order, samples);
    for i in order {
        let [x, y] = centres[i as usize];
        if x.is_finite() && y.is_finite() && x.abs() <= MAX_ALLOWED && y.abs() <= MAX_ALLOWED {
            // An exact duplicate of an earlier point is merged by spade.
            if let Ok(handle) = del.insert_with_hint(Point2::new(x, y), hint) {
                hint = handle;
            }
        }
    }

    // Step 4: edges between two samples.
    del.undirected_edges()
        .map(|e| e.vertices().map(|v| v.fix().index()))
        .filter(|&[a, b]| a < m && b < m)
        .map(|[a, b]| [a as u32, b as u32])
        .collect()
}

/// Circumcentre of the counter-clockwise triangle `abc`, in floating point; may be far away
/// or non-finite for an almost flat triangle.
fn circumcentre(a: Point, b: Point, c: Point) -> Point {
    let (bx, by) = (b[0] - a[0], b[1] - a[1]);
    let (cx, cy) = (c[0] - a[0], c[1] - a[1]);
    let (b2, c2) = (bx * bx + by * by, cx * cx + cy * cy);
    // orient2d has the exact sign (positive for a Delaunay triangle), never 0.
    let d = 2.0 * orient2d(a, b, c);
    [a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d]
}

/// The power of two `2^-s`, `s >= 0`, that brings the finite centres within spade's range
/// while keeping every non-zero sample coordinate at or above 2^-142 (see the module docs).
fn range_scale(dt: &Triangulation, centres: &[Point]) -> f64 {
    let largest = centres
        .iter()
        .flat_map(|w| w.iter())
        .filter(|x| x.is_finite())
        .fold(0.0f64, |acc, x| acc.max(x.abs()));
    if largest <= MAX_ALLOWED {
        return 1.0;
    }
    let smallest = (0..dt.num_vertices() as u32)
        .flat_map(|v| dt.point(v))
        .filter(|&x| x != 0.0)
        .fold(f64::INFINITY, |acc, x| acc.min(x.abs()));
    // Both logarithms are of positive finite values; exponents stay well inside ±1022.
    let needed = (largest / MAX_ALLOWED).log2().ceil() as i32;
    let allowed = (smallest / MIN_ALLOWED).log2().floor() as i32;
    2f64.powi(-needed.min(allowed).max(0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Edge;
    use crate::internals::filter_edges;
    use crate::samplers::cycle_edges as cycle;
    use crate::samplers::regular_polygon;

    fn crust_edges(points: &[Point]) -> Vec<Edge> {
        filter_edges(points, crust)
    }

    #[test]
    fn regular_16_gon_gives_its_sides() {
        let pts = regular_polygon(16, 1.0).points;
        assert_eq!(crust_edges(&pts), cycle(16));
    }

    #[test]
    fn dense_ellipse_is_reconstructed_exactly() {
        let n = 200;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * (i as f64 + 0.3) / n as f64;
                [3.0 * t.cos() + 0.25, t.sin() - 0.5]
            })
            .collect();
        assert_eq!(crust_edges(&pts), cycle(n));
    }

    #[test]
    fn square_keeps_its_sides_and_drops_the_diagonal() {
        // Both diagonals' circles contain the (single, merged) Voronoi vertex at the centre.
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(crust_edges(&pts), vec![[0, 1], [0, 3], [1, 2], [2, 3]]);
    }

    #[test]
    fn flat_hull_triangle_blocks_its_chord() {
        // The module docs' example: the far centre above (1, -δ) is the only blocker of the
        // hull chord (0,0)-(2,0); a point well below closes the curve.
        let delta = 1e-9;
        let pts = [[0.0, 0.0], [1.0, -delta], [2.0, 0.0], [1.0, -3.0]];
        let edges = crust_edges(&pts);
        assert!(!edges.contains(&[0, 2]), "{edges:?}");
        assert!(edges.contains(&[0, 1]) && edges.contains(&[1, 2]), "{edges:?}");
    }

    #[test]
    fn centres_beyond_spade_range_are_rescaled() {
        // `b` lies 2^-182 off the hull chord `ac` near the origin: after `Triangulation::new`
        // scales by 2^30, the flat triangle's centre is about 2^212 away, beyond spade's
        // range, and a rescaling by about 2^-12 (room left by `b`'s 2^-100) brings it back.
        let s = 2f64.powi(-130);
        let pts = [[-1.0, -1.0], [s * (1.0 + f64::EPSILON), s], [1.0, 1.0], [1.0, -1.0]];
        let dt = Triangulation::new(&pts).unwrap();
        let far = (0..dt.num_triangles() as u32).any(|t| {
            let [a, b, c] = [3 * t, 3 * t + 1, 3 * t + 2].map(|h| dt.point(dt.origin(h)));
            circumcentre(a, b, c).iter().any(|x| x.abs() > MAX_ALLOWED)
        });
        assert!(far);
        let edges = dt.to_input_edges(crust(&dt));
        assert!(!edges.contains(&[0, 2]), "{edges:?}");
        assert!(edges.contains(&[0, 1]) && edges.contains(&[1, 2]), "{edges:?}");
    }

    #[test]
    fn permuting_the_input_relabels_the_output() {
        let n = 60;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * (i as f64 + 0.17) / n as f64;
                let r = 1.0 + 0.2 * (3.0 * t).sin();
                [r * t.cos(), 0.7 * r * t.sin()]
            })
            .collect();
        let perm: Vec<usize> = (0..n).map(|i| (i * 23 + 5) % n).collect();
        let permuted: Vec<Point> = perm.iter().map(|&i| pts[i]).collect();
        let mut back: Vec<Edge> = crust_edges(&permuted)
            .into_iter()
            .map(|[a, b]| [perm[a].min(perm[b]), perm[a].max(perm[b])])
            .collect();
        back.sort_unstable();
        assert_eq!(back, crust_edges(&pts));
    }
}
