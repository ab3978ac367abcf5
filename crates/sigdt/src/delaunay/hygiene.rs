//! Input hygiene shared by every algorithm (`docs/algorithms.md` §0.1): finite coordinates, a safe
//! coordinate range for exact predicates, `-0.0` normalised to `0.0`.
//!
//! Coordinates are scaled by a power of two so that the largest absolute coordinate lies in
//! `[2^30, 2^31)`. Scaling by a power of two is exact, so every predicate and every length
//! comparison gives the same answer as on the caller's coordinates, while spade's exact
//! predicates get the range they need (`[2^-142, 2^201]`, Shewchuk's bounds) and squared
//! lengths can neither overflow nor underflow.
use crate::error::{Error, Result};
use crate::geometry::Point;

/// Smallest non-zero absolute coordinate spade accepts (2^-142).
const MIN_ALLOWED: f64 = spade::MIN_ALLOWED_VALUE;
/// Points per chunk of the parallel checks.
const CHUNK: usize = 1 << 16;
/// The largest absolute coordinate is scaled into `[2^TARGET_EXPONENT, 2^(TARGET_EXPONENT+1))`.
const TARGET_EXPONENT: i32 = 30;

/// The exact power-of-two scaling applied to the input.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scaling {
    exponent: i32,
    largest: f64,
}

impl Scaling {
    /// Checks every point and chooses the scaling; errors name the first offending point.
    pub fn for_points(points: &[Point]) -> Result<Scaling> {
        if points.len() >= u32::MAX as usize {
            return Err(Error::TooManyPoints { got: points.len(), max: u32::MAX as usize - 1 });
        }
        // Chunks are checked in parallel; the first chunk with a problem names the point.
        let mut largest = 0.0f64;
        let found = crate::parallel::map_chunks(points.len(), CHUNK, |chunk| {
            let mut largest = 0.0f64;
            for (index, &[x, y]) in chunk.clone().zip(&points[chunk]) {
                if !x.is_finite() || !y.is_finite() {
                    return Err(Error::NonFinite { index, x, y });
                }
                largest = largest.max(x.abs()).max(y.abs());
            }
            Ok(largest)
        });
        for result in found {
            largest = largest.max(result?);
        }
        let exponent = if largest == 0.0 { 0 } else { TARGET_EXPONENT - floor_log2(largest) };
        let scaling = Scaling { exponent, largest };
        let found = crate::parallel::map_chunks(points.len(), CHUNK, |chunk| {
            for (index, p) in chunk.clone().zip(&points[chunk]) {
                for (raw, s) in p.iter().zip(scaling.apply(*p)) {
                    // Judge by the raw value: a tiny coordinate may scale to exactly 0.0.
                    if *raw != 0.0 && s.abs() < MIN_ALLOWED {
                        return Err(Error::CoordinateRange { index, value: *raw, largest });
                    }
                }
            }
            Ok(())
        });
        found.into_iter().collect::<Result<()>>()?;
        Ok(scaling)
    }

    /// The largest absolute input coordinate.
    pub fn largest(self) -> f64 {
        self.largest
    }

    /// The scaled point, with `-0.0` replaced by `0.0`.
    #[inline]
    pub fn apply(self, p: Point) -> Point {
        let half = self.exponent / 2;
        let (a, b) = (pow2(half), pow2(self.exponent - half));
        // x + 0.0 turns -0.0 into 0.0 and leaves every other value unchanged.
        [p[0] * a * b + 0.0, p[1] * a * b + 0.0]
    }

    /// The caller's coordinates of a point in scaled coordinates: the inverse of
    /// [`apply`](Self::apply), exact unless the result is subnormal or overflows.
    #[inline]
    pub fn unapply(self, p: Point) -> Point {
        let half = self.exponent / 2;
        let (a, b) = (pow2(-half), pow2(half - self.exponent));
        [p[0] * a * b, p[1] * a * b]
    }
}

/// `2^e` for `|e| <= 1000`.
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// `floor(log2(x))` for finite `x > 0`, subnormals included.
fn floor_log2(x: f64) -> i32 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: value = mantissa · 2^-1074.
        let mantissa = bits & ((1u64 << 52) - 1);
        63 - mantissa.leading_zeros() as i32 - 1074
    } else {
        biased - 1023
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_log2_of_normals_and_subnormals() {
        assert_eq!(floor_log2(1.0), 0);
        assert_eq!(floor_log2(3.0), 1);
        assert_eq!(floor_log2(0.75), -1);
        assert_eq!(floor_log2(1e300), 996);
        assert_eq!(floor_log2(f64::MIN_POSITIVE), -1022);
        assert_eq!(floor_log2(f64::MIN_POSITIVE / 2.0), -1023);
        assert_eq!(floor_log2(f64::from_bits(1)), -1074);
    }

    #[test]
    fn scaling_is_exact_and_in_range() {
        for pts in [vec![[1e300, -3e299], [2.5e299, 0.0]], vec![[1e-300, 2e-300]], vec![[0.1, 7.0]]]
        {
            let s = Scaling::for_points(&pts).unwrap();
            for p in &pts {
                let q = s.apply(*p);
                for a in 0..2 {
                    assert!(q[a] == 0.0 || (q[a].abs() >= 1.0 && q[a].abs() < 2f64.powi(31)));
                    // Scaling back recovers the input exactly.
                    assert_eq!(s.unapply(q)[a], p[a]);
                }
            }
        }
    }

    #[test]
    fn rejects_non_finite_and_extreme_ranges() {
        let e = Scaling::for_points(&[[0.0, 0.0], [f64::NAN, 1.0]]).unwrap_err();
        assert!(matches!(e, Error::NonFinite { index: 1, .. }), "{e}");
        let e = Scaling::for_points(&[[1.0, 0.0], [0.0, f64::NEG_INFINITY]]).unwrap_err();
        assert!(e.to_string().contains("point 1"), "{e}");
        let e = Scaling::for_points(&[[1e200, 0.0], [1e-200, 1.0]]).unwrap_err();
        assert!(matches!(e, Error::CoordinateRange { index: 1, .. }), "{e}");
        // 1e-300 next to 1e300 underflows to exactly zero when scaled: still an error.
        let e = Scaling::for_points(&[[1e300, 0.0], [1e-300, 1e300]]).unwrap_err();
        assert!(
            matches!(e, Error::CoordinateRange { index: 1, value, .. } if value == 1e-300),
            "{e}"
        );
    }

    #[test]
    fn negative_zero_becomes_zero() {
        let s = Scaling::for_points(&[[-0.0, 1.0]]).unwrap();
        assert_eq!(s.apply([-0.0, 1.0])[0].to_bits(), 0.0f64.to_bits());
    }
}
