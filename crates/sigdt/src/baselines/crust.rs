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
//! spade's exact predicates in one BRIO order of samples and centres together (shuffled
//! rounds of doubling size with a fixed seed, each sorted along a Hilbert curve over the
//! samples' bounding box, far centres on its border), each walk starting at the previous
//! vertex. Random rounds bound the expected flips by O(n) whatever the points, as in a
//! randomised incremental construction; plain Hilbert order is quadratic in practice (the
//! thin interior triangles of a dense curve have large overlapping circumcircles, and a
//! sweep along the medial axis keeps destroying the untouched ones ahead of it). Finding
//! the faces where the order matters (below) costs one exact incircle per edge, and
//! O(k log k) for a face of `k` points.
//!
//! The samples first, then the centres (the order that defines ties) is slower: centre `i`
//! then flips O(n / i) edges in expectation, Θ(n log n) in all, and on a flat zigzag
//! `(i, (i mod 2)·δ)` these are long edges to centres about `1/(2δ)` away, whose incircle
//! tests all need the exact stage: an order of magnitude more time than the joint order.
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
//! - Ties: when four or more points of `S ∪ V` lie on an empty circle (grids, glyphs on
//!   integer coordinates), the order of insertion triangulates that face, and may decide an
//!   edge between two of its samples. The result is the one of the order "samples in vertex
//!   order, then centres": spade keeps an edge whose quadrilateral is cocircular, which is
//!   the Delaunay triangulation with each point lifted infinitesimally more than the ones
//!   inserted before it, and in a face of cocircular points that cuts off the latest point
//!   as an ear, recursively. So each sample of such a face, in index order, joins its two
//!   neighbours among the earlier samples of the face (every centre comes later). The joint
//!   order finds these faces (diagonals with an exactly cocircular quadrilateral, joined by
//!   union-find) and gives them those diagonals; everywhere else the triangulation does not
//!   depend on the order. The tests compare both orders on grids and zigzags.
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
use robust::{incircle, Coord};
use spade::handles::{FixedVertexHandle, VertexHandle};
use spade::{DelaunayTriangulation, Point2, Triangulation as _};

/// Largest absolute coordinate spade accepts (2^201).
const MAX_ALLOWED: f64 = spade::MAX_ALLOWED_VALUE;
/// Smallest non-zero absolute coordinate spade accepts (2^-142).
const MIN_ALLOWED: f64 = spade::MIN_ALLOWED_VALUE;

/// The CRUST edges of `dt` (a [`Shape::Proper`](crate::delaunay::Shape::Proper)
/// triangulation) as pairs of vertices, each undirected edge once.
pub fn crust(dt: &Triangulation) -> Vec<[u32; 2]> {
    if dt.num_triangles() == 0 {
        return Vec::new();
    }
    let (samples, centres) = samples_and_centres(dt);
    joint_order(&samples, &centres)
}

/// Step 2: the samples (vertex `v` is sample `v`) and one circumcentre per triangle, both
/// scaled by [`range_scale`], centre coordinates below spade's range rounded to 0.
fn samples_and_centres(dt: &Triangulation) -> (Vec<Point>, Vec<Point>) {
    // Each triangle's corners from its smallest vertex on, the triangles in the order of
    // those corners: the centres (their bits and their order, which decides the second
    // triangulation's insertion order) depend on the triangles alone, not on where the
    // triangulation stores them.
    let mut corners: Vec<[u32; 3]> = (0..dt.num_triangles() as u32)
        .map(|t| {
            let mut corners = [3 * t, 3 * t + 1, 3 * t + 2].map(|h| dt.origin(h));
            let first = (0..3).min_by_key(|&k| corners[k]).unwrap_or(0);
            corners.rotate_left(first);
            corners
        })
        .collect();
    corners.sort_unstable();
    let mut centres: Vec<Point> = corners
        .iter()
        .map(|c| circumcentre(dt.point(c[0]), dt.point(c[1]), dt.point(c[2])))
        .collect();
    drop(corners);
    let scale = range_scale(dt, &centres);
    for w in &mut centres {
        for x in w.iter_mut() {
            *x *= scale;
            if x.abs() < MIN_ALLOWED {
                *x = 0.0; // also turns -0.0 into 0.0
            }
        }
    }
    // Samples were validated by `Triangulation::new`; scaling keeps them in range.
    let samples = (0..dt.num_vertices() as u32).map(|v| dt.point(v).map(|x| x * scale));
    (samples.collect(), centres)
}

/// Marks a vertex of the second triangulation that is not a sample.
const NO_SAMPLE: u32 = u32::MAX;

/// Steps 3–4 with samples and centres in one BRIO order; the diagonals of degenerate faces
/// are those of the samples-first order (see the module docs).
fn joint_order(samples: &[Point], centres: &[Point]) -> Vec<[u32; 2]> {
    let m = samples.len();
    let point = |i: u32| match samples.get(i as usize) {
        Some(&p) => p,
        None => centres[i as usize - m],
    };
    let mut order: Vec<u32> = (0..(m + centres.len()) as u32).collect();
    brio_order_within(point, &mut order, samples.iter().copied());
    let mut del: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::with_capacity(order.len(), 3 * order.len(), 0);
    // The sample at each vertex of `del`, or NO_SAMPLE; a centre equal to a sample merges.
    let mut sample: Vec<u32> = Vec::with_capacity(order.len());
    let mut hint = FixedVertexHandle::from_index(0);
    for i in order {
        let [x, y] = point(i);
        if fits(x) && fits(y) {
            match del.insert_with_hint(Point2::new(x, y), hint) {
                Ok(handle) => hint = handle,
                Err(_) => continue, // unreachable
            }
            if hint.index() == sample.len() {
                sample.push(NO_SAMPLE);
            }
            if (i as usize) < m {
                sample[hint.index()] = i;
            }
        }
    }

    // Step 4: edges between two samples. A diagonal of a face of the Delaunay subdivision
    // with four or more vertices on one empty circle (its quadrilateral is cocircular) was
    // chosen by the order; such faces are gathered instead (union-find on spade's faces,
    // the outer face being 0) and given the diagonals of the samples-first order.
    let mut group: Vec<u32> = (0..del.num_all_faces() as u32).collect();
    let mut merged = vec![false; group.len()];
    let mut edges = Vec::new();
    for e in del.undirected_edges().map(|e| e.as_directed()) {
        if let (Some(c), Some(d)) = (e.opposite_vertex(), e.rev().opposite_vertex()) {
            let at = |v: VertexHandle<Point2<f64>>| Coord { x: v.position().x, y: v.position().y };
            if incircle(at(e.from()), at(e.to()), at(c), at(d)) == 0.0 {
                let [f, g] = [e.face(), e.rev().face()].map(|f| find(&mut group, f.fix().index()));
                group[f as usize] = g;
                merged[g as usize] = true;
                continue;
            }
        }
        let [a, b] = e.vertices().map(|v| sample[v.fix().index()]);
        if a != NO_SAMPLE && b != NO_SAMPLE {
            edges.push([a, b]);
        }
    }
    if !merged.contains(&true) {
        return edges;
    }
    // Each degenerate face's boundary as (face, from, to), counter-clockwise.
    let mut boundary: Vec<[u32; 3]> = Vec::new();
    for e in del.directed_edges() {
        let [f, g] = [e.face(), e.rev().face()].map(|f| find(&mut group, f.fix().index()));
        if merged[f as usize] && f != g {
            boundary.push([f, e.from().fix().index() as u32, e.to().fix().index() as u32]);
        }
    }
    boundary.sort_unstable();
    for face in boundary.chunk_by(|a, b| a[0] == b[0]) {
        let mut cycle = vec![face[0][1]];
        while cycle.len() < face.len() {
            let from = cycle[cycle.len() - 1];
            let next = face.binary_search_by_key(&from, |e| e[1]).map_or(from, |k| face[k][2]);
            cycle.push(next);
        }
        edges.extend(samples_first_diagonals(&cycle, &sample));
    }
    edges
}

/// The diagonals between samples that the samples-first order gives a convex polygon of
/// cocircular vertices (`cycle`, in order): each sample, in index order, joins its two
/// neighbours among the earlier samples of the polygon (module docs).
fn samples_first_diagonals(cycle: &[u32], sample: &[u32]) -> Vec<[u32; 2]> {
    let k = cycle.len();
    let mut ranked: Vec<(u32, usize)> =
        (0..k).map(|p| (sample[cycle[p] as usize], p)).filter(|&(s, _)| s != NO_SAMPLE).collect();
    ranked.sort_unstable();
    let mut earlier = std::collections::BTreeSet::new();
    let mut diagonals = Vec::new();
    for (s, p) in ranked {
        let before = earlier.range(..p).next_back().or(earlier.last());
        let after = earlier.range(p..).next().or(earlier.first());
        let mut near: Vec<usize> = [before, after].into_iter().flatten().copied().collect();
        near.dedup();
        for q in near {
            if (p + 1) % k != q && (q + 1) % k != p {
                diagonals.push([sample[cycle[q] as usize], s]);
            }
        }
        earlier.insert(p);
    }
    diagonals
}

/// The root of `f` in the union-find forest `group`, halving the path.
fn find(group: &mut [u32], mut f: usize) -> u32 {
    while group[f] as usize != f {
        group[f] = group[group[f] as usize];
        f = group[f] as usize;
    }
    f as u32
}

/// Whether spade accepts the coordinate `x`.
fn fits(x: f64) -> bool {
    x.is_finite() && x.abs() <= MAX_ALLOWED
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
    use crate::samplers::{regular_polygon, Rng};

    fn crust_edges(points: &[Point]) -> Vec<Edge> {
        filter_edges(points, crust)
    }

    /// Steps 3–4 in the order that defines ties (module docs): the samples in vertex order
    /// (spade's vertex `v < m` is sample `v`), then the centres in their own BRIO order.
    fn samples_first(samples: &[Point], centres: &[Point]) -> Vec<[u32; 2]> {
        let m = samples.len();
        let mut del: DelaunayTriangulation<Point2<f64>> =
            DelaunayTriangulation::with_capacity(m + centres.len(), 3 * (m + centres.len()), 0);
        let mut hint = FixedVertexHandle::from_index(0);
        for (v, &[x, y]) in samples.iter().enumerate() {
            match del.insert_with_hint(Point2::new(x, y), hint) {
                Ok(handle) => hint = handle,
                Err(_) => return Vec::new(), // unreachable
            }
            debug_assert_eq!(hint.index(), v);
        }
        let mut order: Vec<u32> = (0..centres.len() as u32).collect();
        brio_order_within(|i| centres[i as usize], &mut order, samples.iter().copied());
        for i in order {
            let [x, y] = centres[i as usize];
            if fits(x) && fits(y) {
                if let Ok(handle) = del.insert_with_hint(Point2::new(x, y), hint) {
                    hint = handle;
                }
            }
        }
        del.undirected_edges()
            .map(|e| e.vertices().map(|v| v.fix().index()))
            .filter(|&[a, b]| a < m && b < m)
            .map(|[a, b]| [a as u32, b as u32])
            .collect()
    }

    /// Both orders' edges for `points`, each `[i, j]` with `i < j`, sorted.
    fn both_orders(points: &[Point]) -> [Vec<[u32; 2]>; 2] {
        let dt = Triangulation::new(points).unwrap();
        let (samples, centres) = samples_and_centres(&dt);
        [joint_order(&samples, &centres), samples_first(&samples, &centres)].map(|mut edges| {
            edges.iter_mut().for_each(|e| e.sort_unstable());
            edges.sort_unstable();
            edges
        })
    }

    /// The zigzag `(i, (i mod 2)·h)`, shuffled: the points and where each went.
    fn shuffled_zigzag(n: usize, h: f64, seed: u64) -> (Vec<Point>, Vec<usize>) {
        let mut at: Vec<usize> = (0..n).collect();
        Rng::new(seed).shuffle(&mut at);
        let mut points = vec![[0.0; 2]; n];
        for (i, &k) in at.iter().enumerate() {
            points[k] = [i as f64, (i % 2) as f64 * h];
        }
        (points, at)
    }

    /// The flat zigzag's crust is the zigzag itself, one path through every sample.
    fn assert_flat_zigzag_gives_its_path(n: usize) {
        let (points, at) = shuffled_zigzag(n, 1e-40, 7);
        let mut path: Vec<Edge> =
            (1..n).map(|i| [at[i - 1].min(at[i]), at[i - 1].max(at[i])]).collect();
        path.sort_unstable();
        assert_eq!(crust_edges(&points), path);
    }

    #[test]
    fn flat_zigzag_gives_its_path_in_either_order() {
        // Every triangle is flat: the centres lie on two rows 1/(2·10^-40) away, so every
        // incircle test of the second triangulation needs the exact stage (module docs).
        assert_flat_zigzag_gives_its_path(400);
        let (points, _) = shuffled_zigzag(400, 1e-40, 7);
        let [joint, first] = both_orders(&points);
        assert_eq!(joint, first);
    }

    #[test]
    #[ignore = "2.56e5 points: about 5 s in release; inserting samples first took minutes"]
    fn large_flat_zigzag_gives_its_path() {
        assert_flat_zigzag_gives_its_path(256_000);
    }

    #[test]
    fn ties_get_the_diagonals_of_the_samples_first_order() {
        // A grid side and the centres of its two cells lie on one empty circle, and so do
        // the integer points on a circle with the centres near theirs; zigzags of integers.
        let grid = |k: usize| -> Vec<Point> {
            (0..k * k).map(|i| [(i % k) as f64, (i / k) as f64]).collect()
        };
        let mut shuffled = grid(9);
        Rng::new(3).shuffle(&mut shuffled);
        // Integer points on the circle of radius 65 (the square roots are exact).
        let circle: Vec<Point> = (-65..=65)
            .flat_map(|x: i32| {
                [-1.0, 1.0].map(|s| [f64::from(x), s * f64::from(4225 - x * x).sqrt()])
            })
            .filter(|p| p[1].fract() == 0.0)
            .collect();
        let mut circle_and_grid = circle.clone();
        circle_and_grid.extend(grid(5).iter().map(|p| [p[0] * 10.0 - 20.0, p[1] * 10.0 - 20.0]));
        for (case, points) in [
            ("grid 12x12", grid(12)),
            ("grid 9x9, shuffled", shuffled),
            ("integer circle", circle),
            ("integer circle and grid", circle_and_grid),
            ("unit zigzag", shuffled_zigzag(300, 1.0, 5).0),
            (
                "zigzag of 1e-40",
                shuffled_zigzag(300, 1.0, 5).0.iter().map(|p| p.map(|x| x * 1e-40)).collect(),
            ),
        ] {
            let [joint, first] = both_orders(&points);
            assert_eq!(joint, first, "{case}");
        }
    }

    #[test]
    fn samples_first_diagonals_join_earlier_neighbours() {
        // A hexagon of cocircular vertices 0..6: samples 2, 0, 1 at positions 0, 2, 4, centres
        // between. Sample 1 joins sample 0 (its only earlier one), sample 2 joins both.
        let sample = [2, NO_SAMPLE, 0, NO_SAMPLE, 1, NO_SAMPLE];
        let mut diagonals = samples_first_diagonals(&[0, 1, 2, 3, 4, 5], &sample);
        diagonals.iter_mut().for_each(|e| e.sort_unstable());
        diagonals.sort_unstable();
        assert_eq!(diagonals, vec![[0, 1], [0, 2], [1, 2]]);
        // Four samples on a square: sides are no diagonals; only the third joins the first.
        let sample = [0, 1, 2, 3];
        assert_eq!(samples_first_diagonals(&[0, 1, 2, 3], &sample), vec![[0, 2]]);
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
            // From the smallest vertex on, so that the centre has the same bits wherever
            // the triangle is stored and whichever corner it starts at.
            let mut corners = [3 * t, 3 * t + 1, 3 * t + 2].map(|h| dt.origin(h));
            let first = (0..3).min_by_key(|&k| corners[k]).unwrap_or(0);
            corners.rotate_left(first);
            let [a, b, c] = corners.map(|v| dt.point(v));
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
