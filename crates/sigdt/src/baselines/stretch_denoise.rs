//! STRETCHDENOISE: FITCONNECT's connectivity, then every curve point moved along its
//! fitted normal, within its noise extent, so that the curve turns as little as the noise
//! allows while staying centred among the samples.
//!
//! \[OW18b\] S. Ohrhallinger, M. Wimmer, *StretchDenoise: Parametric Curve Reconstruction
//! with Guarantees by Separating Connectivity from Residual Uncertainty of Samples*, Pacific
//! Graphics 2018 (short papers). The authors' program (github stefango74/stretchdenoise
//! @6aa1a56, GPL-3) computes the same connectivity as FITCONNECT's and then repositions the
//! points by a constrained least-squares solve; its structure was read to learn the
//! behaviour (`../shared/BASELINES.md` §2.2), not every line of its solver, and no code was
//! taken. What is ours is said below.
//!
//! # Steps
//! 1. FITCONNECT's links ([`fit_connect`](super::fit_connect)). Each point `v` has a unit
//!    normal `n_v` (of its last fit) and a noise extent `e_v`: the largest residual of its
//!    last fit (the program's estimate) or, if larger, of the circle fitted to `v` and the
//!    two curve points on either side of it. (Ours: a point that conformed with two
//!    neighbours has a fit through three points, whose residual is 0, so the program's
//!    estimate alone would pin most points of a noisy curve where they are.)
//! 2. Each curve point may move to `x_v = p_v + t_v n_v` with `|t_v| ≤ e_v` (the program's
//!    bounds). Every point left out is attached to the first curve point of its nearest
//!    neighbours (the program attaches it to the nearest curve edge).
//! 3. The `t` minimise `Σ_v |x_v − (x_u + x_w)/2|² / |p_u p_w|²` over the curve points with
//!    two neighbours `u, w`: the squared turning angle, to first order (the program
//!    minimises a linearised angle per vertex weighted by the inverse of the same base
//!    length). FITCONNECT's sharp corners have no term, as the program drops the angles
//!    at sharp corners (it finds them as vertices whose three noise discs no line meets;
//!    we take FITCONNECT's own corners).
//! 4. Subject to `Σ_s (s − p_v(s))·n_v(s) = Σ_v c_v t_v`, per curve, where `s` runs over the
//!    curve's points and the points attached to it and `c_v` counts the points attached to
//!    `v` (itself included): to first order, the signed distances of the samples from the
//!    curve sum to zero (the program's single equality constraint), so straightening does
//!    not shrink a loop.
//!
//! The problem is a convex quadratic with one equality per curve and box bounds. It is solved
//! by projected Gauss–Seidel sweeps with an augmented Lagrangian for the equalities, until
//! no point moves by more than [`TOLERANCE`] times the curve's mean edge length or after
//! [`MAX_SWEEPS`] sweeps.
//! (Ours: the program solves a bounded least-squares problem per run of vertices between
//! corners with a library solver.)
//!
//! # Output
//! FITCONNECT's edges, loops, paths, left-out points and status, and
//! [`Vertices::Moved`]: every input point's new position (points
//! off the curves and their duplicates do not move). Exact scoring uses the edges, RMSE the
//! moved points.
//!
//! # Guarantee
//! Every curve point stays within its noise extent of where it was sampled; the edges are
//! FITCONNECT's. [OW18b] states guarantees for the connectivity under its noise model.
//!
//! # Complexity
//! FITCONNECT's, plus O(n) per sweep.
//!
//! [OW18b]: https://doi.org/10.2312/pg.20181266
use super::fit_connect::{connect, crossing, result_of, spread, Connectivity, PASS_LIMIT};
use crate::delaunay::Triangulation;
use crate::geometry::Point;
use crate::result::{degenerate_result, Reconstruction, Vertices};
use crate::Status;

/// Sweeps stop once no point moves by more than this fraction of the curve's mean edge
/// length.
pub const TOLERANCE: f64 = 1e-6;

/// The most Gauss–Seidel sweeps. Noise is undone in the first few sweeps (each sweep
/// straightens a vertex against its neighbours); more sweeps only spread the balancing of
/// step 4 along long curves.
pub const MAX_SWEEPS: usize = 200;

/// STRETCHDENOISE on `dt` as a full result (see the module docs).
pub(crate) fn stretch_denoise_on(dt: &Triangulation) -> Reconstruction {
    if let Some(result) = degenerate_result(dt) {
        return result;
    }
    let connectivity = connect(dt, PASS_LIMIT);
    let mut rec = result_of(dt, &connectivity);
    let moved = denoise(dt, &connectivity, &rec.loops, &rec.paths);
    // Every input point at its vertex's new place; a duplicate at its representative's.
    let mut by_input = dt.vertex_of_inputs();
    for &[duplicate, representative] in dt.duplicates() {
        by_input[duplicate] = by_input[representative];
    }
    let moved: Vec<Point> = by_input.iter().map(|&v| dt.unscale(moved[v as usize])).collect();
    // Moving points can make edges cross that did not.
    if rec.status != Status::Unfinished
        && rec.status != Status::Crossing
        && crossing(dt, &rec, Some(&moved))
    {
        rec.status = Status::Crossing;
    }
    rec.vertices = Vertices::Moved(moved);
    rec
}

/// One curve as vertex numbers in order, closed or not.
struct Curve {
    vertices: Vec<u32>,
    closed: bool,
}

/// The moved positions of every vertex of `dt` (scaled coordinates); `loops` and `paths`
/// are in input indices, as in the result.
fn denoise(
    dt: &Triangulation,
    connectivity: &Connectivity,
    loops: &[Vec<usize>],
    paths: &[Vec<usize>],
) -> Vec<Point> {
    let n = dt.num_vertices();
    let xy: Vec<Point> = (0..n as u32).map(|v| dt.point(v)).collect();
    let vertex = dt.vertex_of_inputs();
    let to_vertices = |c: &[usize]| c.iter().map(|&i| vertex[i]).collect::<Vec<u32>>();
    let curves: Vec<Curve> = loops
        .iter()
        .map(|c| Curve { vertices: to_vertices(c), closed: true })
        .chain(paths.iter().map(|c| Curve { vertices: to_vertices(c), closed: false }))
        .collect();
    // Which curve each curve point is on, then the points attached to each curve point.
    let mut curve_of = vec![usize::MAX; n];
    for (k, c) in curves.iter().enumerate() {
        for &v in &c.vertices {
            curve_of[v as usize] = k;
        }
    }
    let fits = &oriented(&xy, &connectivity.fits, &curves);
    let mut attached = vec![1.0f64; n];
    let mut offset_sum = vec![0.0f64; curves.len()];
    for (v, nearest) in connectivity.neighbours.iter().enumerate() {
        if curve_of[v] != usize::MAX {
            continue;
        }
        if let Some(&u) = nearest.iter().find(|&&u| curve_of[u as usize] != usize::MAX) {
            let u = u as usize;
            attached[u] += 1.0;
            let normal = fits[u].normal;
            offset_sum[curve_of[u]] +=
                (xy[v][0] - xy[u][0]) * normal[0] + (xy[v][1] - xy[u][1]) * normal[1];
        }
    }
    let mut t = vec![0.0f64; n];
    for (k, curve) in curves.iter().enumerate() {
        solve_curve(&xy, fits, &connectivity.sharp, curve, &attached, offset_sum[k], &mut t);
    }
    (0..n)
        .map(|v| {
            let normal = fits[v].normal;
            [xy[v][0] + t[v] * normal[0], xy[v][1] + t[v] * normal[1]]
        })
        .collect()
}

/// The fits with their normals turned to the left of each curve's direction, so that a
/// move `t` means the same side all along a curve (the program orients them likewise).
fn oriented(
    xy: &[Point],
    fits: &[super::fit_connect::Fit],
    curves: &[Curve],
) -> Vec<super::fit_connect::Fit> {
    let mut fits = fits.to_vec();
    for curve in curves {
        let vs = &curve.vertices;
        let m = vs.len();
        for i in 0..m {
            let before = if curve.closed || i > 0 { vs[(i + m - 1) % m] } else { vs[i] };
            let after = if curve.closed || i + 1 < m { vs[(i + 1) % m] } else { vs[i] };
            let (a, b) = (xy[before as usize], xy[after as usize]);
            let left = [a[1] - b[1], b[0] - a[0]];
            let fit = &mut fits[vs[i] as usize];
            if fit.normal[0] * left[0] + fit.normal[1] * left[1] < 0.0 {
                fit.normal = [-fit.normal[0], -fit.normal[1]];
            }
        }
    }
    fits
}

/// Minimises the curve's turning over the moves `t` of its vertices (module docs, steps 3–4).
/// Everything is indexed by position along the curve.
fn solve_curve(
    xy: &[Point],
    fits: &[super::fit_connect::Fit],
    sharp: &[bool],
    curve: &Curve,
    attached: &[f64],
    offset_sum: f64,
    t: &mut [f64],
) {
    let vs: Vec<usize> = curve.vertices.iter().map(|&v| v as usize).collect();
    let m = vs.len();
    if m < 3 {
        return;
    }
    let closed = curve.closed;
    // The neighbour positions of position i, if it has both.
    let around = |i: usize| -> Option<(usize, usize)> {
        if closed {
            Some(((i + m - 1) % m, (i + 1) % m))
        } else if i > 0 && i + 1 < m {
            Some((i - 1, i + 1))
        } else {
            None
        }
    };
    // Step 3's weight per position (0: no term: a path's ends, sharp corners).
    let weight: Vec<f64> = (0..m)
        .map(|i| match around(i) {
            Some((u, w)) if !sharp[vs[i]] => {
                let base2 = crate::geometry::squared_distance(xy[vs[u]], xy[vs[w]]);
                if base2 > 0.0 {
                    1.0 / base2
                } else {
                    0.0
                }
            }
            _ => 0.0,
        })
        .collect();
    // Noise extents (step 1): the fit's, or the spread of the five curve points around i.
    let bound: Vec<f64> = (0..m)
        .map(|i| {
            let window: Vec<Point> = (0..5)
                .filter_map(|d| {
                    let j = i as isize + d - 2;
                    if closed {
                        Some(xy[vs[j.rem_euclid(m as isize) as usize]])
                    } else {
                        (0..m as isize).contains(&j).then(|| xy[vs[j as usize]])
                    }
                })
                .collect();
            fits[vs[i]].extent.max(spread(&window))
        })
        .collect();
    let normal = |i: usize| fits[vs[i]].normal;
    let moved = |i: usize, t: &[f64]| {
        let (v, n) = (vs[i], normal(i));
        [xy[v][0] + t[v] * n[0], xy[v][1] + t[v] * n[1]]
    };
    // Residual of the term at position c: x_c − (x_u + x_w)/2.
    let residual = |c: usize, t: &[f64]| {
        let (u, w) = around(c).expect("a weighted position has two neighbours");
        let (a, b, d) = (moved(c, t), moved(u, t), moved(w, t));
        [a[0] - 0.5 * (b[0] + d[0]), a[1] - 0.5 * (b[1] + d[1])]
    };
    // The equality: Σ c_v t_v = offset_sum, with an augmented Lagrangian (multiplier λ,
    // penalty μ scaled to the energy's curvature so that neither dominates).
    let weighted = weight.iter().filter(|&&w| w > 0.0).count().max(1);
    let mean_weight = weight.iter().sum::<f64>() / weighted as f64;
    let total_attached: f64 = vs.iter().map(|&v| attached[v]).sum();
    let mu = mean_weight / total_attached.max(1.0);
    let mut lambda = 0.0;
    let mut constraint = vs.iter().map(|&v| attached[v] * t[v]).sum::<f64>() - offset_sum;
    let edges = if closed { m } else { m - 1 };
    let mean_edge =
        (0..edges).map(|i| crate::geometry::distance(xy[vs[i]], xy[vs[(i + 1) % m]])).sum::<f64>()
            / edges as f64;
    for _ in 0..MAX_SWEEPS {
        let mut largest_move = 0.0f64;
        for i in 0..m {
            let v = vs[i];
            if bound[i] <= 0.0 {
                continue;
            }
            let n = normal(i);
            // The energy along t_v is a parabola a t² + b t + const: the terms centred at i
            // (coefficient 1) and at its two neighbours (coefficient −1/2).
            let (mut a, mut b) = (0.0, 0.0);
            let mut add = |c: usize, coefficient: f64| {
                if weight[c] > 0.0 {
                    let r = residual(c, t);
                    let along = coefficient * (r[0] * n[0] + r[1] * n[1]);
                    a += weight[c] * coefficient * coefficient;
                    b += weight[c] * 2.0 * (along - coefficient * coefficient * t[v]);
                }
            };
            add(i, 1.0);
            if let Some((u, w)) = around(i) {
                add(u, -0.5);
                add(w, -0.5);
            } else if !closed {
                // A path's end is the neighbour of the next position in only.
                let next = if i == 0 { 1 } else { m - 2 };
                add(next, -0.5);
            }
            let c = attached[v];
            // Penalty λ g + μ/2 g², with g = constraint, linear in t_v with slope c.
            let g_rest = constraint - c * t[v];
            a += 0.5 * mu * c * c;
            b += lambda * c + mu * c * g_rest;
            if a <= 0.0 {
                continue;
            }
            let best = (-b / (2.0 * a)).clamp(-bound[i], bound[i]);
            constraint += c * (best - t[v]);
            largest_move = largest_move.max((best - t[v]).abs());
            t[v] = best;
        }
        lambda += mu * constraint;
        if largest_move <= TOLERANCE * mean_edge {
            break;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::internals::check_reconstruction;

    #[test]
    fn a_noisy_circle_gets_rounder_and_keeps_its_size() {
        let n = 60;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / n as f64;
                let r = 1.0 + if i % 2 == 0 { 0.01 } else { -0.01 };
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        let dt = Triangulation::new(&pts).unwrap();
        let rec = stretch_denoise_on(&dt);
        check_reconstruction(&pts, &rec).unwrap();
        let Vertices::Moved(moved) = &rec.vertices else { panic!("points are moved") };
        let on_curve: Vec<usize> = rec.loops.iter().flatten().copied().collect();
        assert!(!on_curve.is_empty(), "{:?}", rec.status);
        let error = |ps: &[Point]| {
            on_curve.iter().map(|&i| (ps[i][0].hypot(ps[i][1]) - 1.0).powi(2)).sum::<f64>()
        };
        assert!(error(moved) < 0.25 * error(&pts), "{} vs {}", error(moved), error(&pts));
        let mean_radius: f64 =
            on_curve.iter().map(|&i| moved[i][0].hypot(moved[i][1])).sum::<f64>()
                / on_curve.len() as f64;
        assert!((mean_radius - 1.0).abs() < 0.005, "{mean_radius}");
        assert_ne!(rec.status, Status::Unfinished);
    }
}
