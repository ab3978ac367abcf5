//! Perturbations of clean samples for the noise and outlier experiments of \[MOW22\]
//! (Fig. 15–18), as specified in `docs/algorithms.md` §4.7 and §4.8.
//!
//! - [`uniform_noise`]: each point moves by `s·U₁·diag` in direction `2π·U₂` (`diag` = the
//!   bounding-box diagonal of the input), the convention of the authors' FitConnect test
//!   harness. The displacement is at most `s·diag` (not uniform in the disk: its radius is
//!   uniform).
//! - [`lfs_noise`]: each point moves along its curve normal by `(2U − 1)·δ·lfs`, the "lfs
//!   noise" of `sampling2d` \[OMW21\]; normals and lfs come from
//!   `eps_sample_with_frames` (in `sigdt-lab`).
//! - [`add_outliers`]: `round(q·n)` points uniform in the bounding box are appended, so the
//!   ground truth (indices `0..n`) is unchanged and outliers get indices `n..`. They are not
//!   kept away from the curve.
//!
//! The points keep their order. The random numbers come from [`Rng::new(seed)`](Rng::new),
//! drawn point by point in input order, so the result is fixed by the seed.
//!
//! # Complexity
//! O(n) each.
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//! \[OMW21\] S. Ohrhallinger, J. Peethambaran, A. Parakkat, T. Dey, R. Muthuganapathy.
//! 2D Points Curve Reconstruction Survey and Benchmark. 2021.
use std::f64::consts::TAU;

use super::Rng;
use crate::error::{Error, Result};
use crate::geometry::Point;

/// Largest outlier fraction accepted by [`add_outliers`] (10 outliers per curve point).
pub const MAX_OUTLIER_FRACTION: f64 = 10.0;

/// `points`, each moved by `s·U₁·diag` in direction `2π·U₂`, where `diag` is the diagonal of
/// their bounding box and `U₁, U₂` are uniform in `[0, 1)`. `s` is a fraction (`1e-4` is
/// 0.01% of the diagonal).
///
/// # Errors
/// [`Error::InvalidOption`] if `s` is negative or not finite, or if a moved point would
/// leave the finite range of `f64` (a huge `s`, or an extent near `f64::MAX`);
/// [`Error::NonFinite`] for a non-finite point.
pub fn uniform_noise(points: &[Point], s: f64, seed: u64) -> Result<Vec<Point>> {
    let s = fraction("noise level s", s)?;
    let diag = bounding_box(points)?.map_or(0.0, |(lo, hi)| (hi[0] - lo[0]).hypot(hi[1] - lo[1]));
    let mut rng = Rng::new(seed);
    let moved = points.iter().map(|p| {
        let radius = s * rng.uniform() * diag;
        let angle = TAU * rng.uniform();
        [p[0] + radius * angle.cos(), p[1] + radius * angle.sin()]
    });
    finite(moved.collect(), "noise level s", s)
}

/// `points`, each moved along its unit normal by `(2U − 1)·delta·lfs`, `U` uniform in
/// `[0, 1)`: at most `delta` times the local feature size, to either side.
///
/// # Errors
/// [`Error::InvalidOption`] if `delta` is negative or not finite, the three slices differ in
/// length, or an lfs is negative or not finite; [`Error::NonFinite`] for a non-finite point.
pub fn lfs_noise(
    points: &[Point],
    normals: &[Point],
    lfs: &[f64],
    delta: f64,
    seed: u64,
) -> Result<Vec<Point>> {
    let delta = fraction("lfs noise delta", delta)?;
    if normals.len() != points.len() || lfs.len() != points.len() {
        return Err(Error::InvalidOption(format!(
            "lfs noise needs one normal and one lfs per point: {} points, {} normals, {} lfs",
            points.len(),
            normals.len(),
            lfs.len()
        )));
    }
    bounding_box(points)?;
    if let Some(i) = lfs.iter().position(|l| !(l.is_finite() && *l >= 0.0)) {
        return Err(Error::InvalidOption(format!("lfs of point {i} is {}", lfs[i])));
    }
    let mut rng = Rng::new(seed);
    let moved = points.iter().zip(normals).zip(lfs).map(|((p, n), l)| {
        let t = (2.0 * rng.uniform() - 1.0) * delta * l;
        [p[0] + t * n[0], p[1] + t * n[1]]
    });
    finite(moved.collect(), "lfs noise delta", delta)
}

/// `moved`, unless some point left the finite range of `f64` (then an error naming the
/// option that moved it there and its value), so no `inf` is ever written for a later
/// command to refuse.
fn finite(moved: Vec<Point>, what: &str, value: f64) -> Result<Vec<Point>> {
    match moved.iter().position(|p| !(p[0].is_finite() && p[1].is_finite())) {
        None => Ok(moved),
        Some(i) => {
            // Display writes 1e308 with all its 309 digits.
            let value = if value >= 1e15 { format!("{value:e}") } else { value.to_string() };
            Err(Error::InvalidOption(format!(
                "{what} {value} moves point {i} beyond the finite range of coordinates"
            )))
        }
    }
}

/// `points` followed by `round(q·n)` outliers uniform in their bounding box (`n` the number
/// of points, `q` a fraction: `0.05` adds 5%).
///
/// # Errors
/// [`Error::InvalidOption`] if `q` is negative, not finite or above
/// [`MAX_OUTLIER_FRACTION`], or if the bounding box is too wide for `f64` (an extent beyond
/// `f64::MAX`); [`Error::NonFinite`] for a non-finite point.
pub fn add_outliers(points: &[Point], q: f64, seed: u64) -> Result<Vec<Point>> {
    let q = fraction("outlier fraction q", q)?;
    if q > MAX_OUTLIER_FRACTION {
        return Err(Error::InvalidOption(format!(
            "outlier fraction q must be at most {MAX_OUTLIER_FRACTION} (it is a fraction: 0.2 \
             adds 20%), got {q}"
        )));
    }
    let mut out = points.to_vec();
    if let Some((lo, hi)) = bounding_box(points)? {
        let mut rng = Rng::new(seed);
        let count = (q * points.len() as f64).round() as usize;
        out.extend((0..count).map(|_| {
            let (u, v) = (rng.uniform(), rng.uniform());
            [lo[0] + u * (hi[0] - lo[0]), lo[1] + v * (hi[1] - lo[1])]
        }));
    }
    finite(out, "outlier fraction q", q)
}

/// `value` if it is finite and non-negative.
fn fraction(what: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidOption(format!("{what} must be finite and non-negative, got {value}")))
    }
}

/// The corners of the bounding box of `points` (`None` if empty), checking they are finite.
fn bounding_box(points: &[Point]) -> Result<Option<(Point, Point)>> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for (index, &[x, y]) in points.iter().enumerate() {
        if !(x.is_finite() && y.is_finite()) {
            return Err(Error::NonFinite { index, x, y });
        }
        lo = [lo[0].min(x), lo[1].min(y)];
        hi = [hi[0].max(x), hi[1].max(y)];
    }
    Ok((!points.is_empty()).then_some((lo, hi)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::distance;
    use crate::samplers::regular_polygon;

    #[test]
    fn uniform_noise_is_seeded_and_bounded() {
        let points = regular_polygon(50, 2.0).points; // bounding-box diagonal about 4√2
        let diag = 4.0 * 2f64.sqrt();
        let a = uniform_noise(&points, 0.01, 7).unwrap();
        assert_eq!(a, uniform_noise(&points, 0.01, 7).unwrap());
        assert_ne!(a, uniform_noise(&points, 0.01, 8).unwrap());
        let moves: Vec<f64> = points.iter().zip(&a).map(|(&p, &q)| distance(p, q)).collect();
        assert!(moves.iter().all(|&d| d <= 0.01 * diag));
        assert!(moves.iter().any(|&d| d > 0.005 * diag));
        assert_eq!(uniform_noise(&points, 0.0, 7).unwrap(), points);
        assert!(uniform_noise(&[], 0.1, 1).unwrap().is_empty());
    }

    #[test]
    fn perturbations_never_leave_the_finite_range() {
        let points = regular_polygon(20, 1.0).points;
        let err = uniform_noise(&points, 1e308, 1).unwrap_err().to_string();
        assert!(err.contains("noise level s 1e308 moves point"), "{err}");
        let wide = [[-1.7e308, 0.0], [1.7e308, 0.0], [0.0, 1.0]];
        assert!(uniform_noise(&wide, 0.5, 1).is_err());
        let err = add_outliers(&wide, 1.0, 1).unwrap_err().to_string();
        assert!(err.contains("outlier fraction q 1 moves point"), "{err}");
        assert!(add_outliers(&points, 1.0, 1).unwrap().iter().all(|p| p[0].is_finite()));
    }

    #[test]
    fn lfs_noise_moves_along_normals() {
        let points = vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        let normals = vec![[0.0, 1.0]; 3];
        let lfs = [1.0, 2.0, 0.0];
        let moved = lfs_noise(&points, &normals, &lfs, 0.5, 3).unwrap();
        assert_eq!(moved, lfs_noise(&points, &normals, &lfs, 0.5, 3).unwrap());
        for ((p, q), l) in points.iter().zip(&moved).zip(lfs) {
            assert_eq!(p[0], q[0]);
            assert!(q[1].abs() <= 0.5 * l);
        }
        assert_eq!(moved[2], [2.0, 0.0]);
        let err = lfs_noise(&points, &normals[..2], &lfs, 0.5, 3).unwrap_err().to_string();
        assert!(err.contains("3 points, 2 normals"), "{err}");
        let err = lfs_noise(&points, &normals, &[1.0, f64::NAN, 1.0], 0.5, 3).unwrap_err();
        assert!(err.to_string().contains("lfs of point 1 is NaN"));
    }

    #[test]
    fn outliers_are_appended_in_the_box() {
        let points = regular_polygon(40, 1.0).points;
        let with = add_outliers(&points, 0.2, 5).unwrap();
        assert_eq!((with.len(), &with[..40]), (48, &points[..]));
        assert!(with[40..].iter().all(|p| p[0].abs() <= 1.0 && p[1].abs() <= 1.0));
        assert_eq!(with, add_outliers(&points, 0.2, 5).unwrap());
        assert_eq!(add_outliers(&points, 0.01, 5).unwrap().len(), 40); // round(0.4) = 0
        assert_eq!(add_outliers(&points, 0.05, 5).unwrap().len(), 42);
        assert!(add_outliers(&[], 0.5, 5).unwrap().is_empty());
    }

    #[test]
    fn bad_parameters_are_errors() {
        let points = [[0.0, 0.0], [1.0, 1.0]];
        let message = |r: Result<Vec<Point>>| r.unwrap_err().to_string();
        for bad in [-0.1, f64::NAN, f64::INFINITY] {
            assert!(message(uniform_noise(&points, bad, 1)).contains("noise level s must be"));
            assert!(message(add_outliers(&points, bad, 1)).contains("outlier fraction q must be"));
            let normals = [[0.0, 1.0]; 2];
            assert!(message(lfs_noise(&points, &normals, &[1.0; 2], bad, 1)).contains("delta"));
        }
        assert!(message(add_outliers(&points, 20.0, 1)).contains("at most 10"));
        let nan = [[0.0, 0.0], [f64::NAN, 1.0]];
        assert!(message(uniform_noise(&nan, 0.1, 1)).contains("point 1 has a non-finite"));
    }
}
