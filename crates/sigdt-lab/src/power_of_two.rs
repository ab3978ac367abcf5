//! Exact scaling by powers of two: multiplying by `2^k` changes only the exponent, so it is
//! exact short of overflow or subnormal underflow, and ratios, orders and predicates are the
//! same at every scale. The evaluation ([`eval`](crate::eval)) and the SVG reader and
//! ε-sampling ([`curves`](crate::curves)) work at a fixed size this way.

/// `2^k` for `|k| ≤ 1022` (a normal `f64`).
pub(crate) fn pow2(k: i32) -> f64 {
    f64::from_bits(((1023 + k) as u64) << 52)
}

/// `v · 2^k`, in two steps so that `k` may reach ±2044 (subnormal input needs up to 1074).
pub(crate) fn scale(v: f64, k: i32) -> f64 {
    let half = k / 2;
    v * pow2(half) * pow2(k - half)
}

/// The `k` that brings `largest` into `[2^target, 2^(target+1))`; 0 for zero or a value
/// that is not finite.
pub(crate) fn exponent_into(largest: f64, target: i32) -> i32 {
    match largest.is_finite() && largest > 0.0 {
        // log2 of a subnormal is exact enough for its exponent.
        true => target - largest.log2().floor() as i32,
        false => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scaling_is_exact_and_reaches_subnormals() {
        assert_eq!(exponent_into(1000.0, 9), 0);
        assert_eq!(exponent_into(1e18, 9), 9 - 59);
        assert_eq!(exponent_into(0.0, 9), 0);
        let tiny = 5e-324;
        let k = exponent_into(tiny, 0);
        assert_eq!(scale(scale(tiny, k), -k), tiny);
        assert_eq!(scale(0.1, 700), 0.1 * 2f64.powi(700));
    }
}
