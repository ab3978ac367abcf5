//! A DISCUR curve's edge-length statistics and the statistical criterion at its ends
//! (`docs/algorithms.md` §3.9, step 2).

/// A curve's edge-length statistics (count, mean, sum of squared deviations) and its ends
/// (`None` once closed).
#[derive(Debug, Clone, Copy)]
pub(super) struct Curve {
    count: f64,
    mean: f64,
    m2: f64,
    pub(super) ends: Option<[u32; 2]>,
}

impl Curve {
    /// The statistics of one edge of length `length`; no ends yet.
    pub(super) fn single(length: f64) -> Curve {
        Curve { count: 1.0, mean: length, m2: 0.0, ends: None }
    }

    /// The pooled statistics of `self` and `other` (Chan, Golub, LeVeque); no ends.
    pub(super) fn pooled(self, other: Curve) -> Curve {
        let count = self.count + other.count;
        let delta = other.mean - self.mean;
        Curve {
            count,
            mean: self.mean + delta * other.count / count,
            m2: self.m2 + other.m2 + delta * delta * self.count * other.count / count,
            ends: None,
        }
    }

    /// The standard deviation, `k − 1` in the denominator; 0 for a single edge.
    fn deviation(&self) -> f64 {
        if self.count < 2.0 {
            0.0
        } else {
            (self.m2 / (self.count - 1.0)).sqrt()
        }
    }

    /// The criterion at an end of this curve whose edge has length `a`, for an edge of
    /// length `d`: `d < ρ = h̄ · (h/s) · (1 + h̄/s̄)^(s̄/h̄)` with `h = (d + a)/2`,
    /// `s = |d − a|/√2`; true when `s = 0`, the last factor 1 when `s̄ = 0`.
    pub(super) fn accepts(&self, a: f64, d: f64) -> bool {
        let s = (d - a).abs() / std::f64::consts::SQRT_2;
        if s == 0.0 {
            return true;
        }
        let (mean, deviation) = (self.mean, self.deviation());
        let factor = if deviation > 0.0 {
            // (1 + 1/t)^t with t = s̄/h̄, as exp(t (ln(1 + t) − ln t)): no overflow.
            let t = deviation / mean;
            (t * (t.ln_1p() - t.ln())).exp()
        } else {
            1.0
        };
        d < mean * ((d + a) / 2.0 / s) * factor
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn on_a_uniform_curve_the_criterion_stops_near_twice_the_spacing() {
        // h̄ = a = 1, s̄ = 0: ρ = (d + 1) / (√2 |d − 1|), and d < ρ up to d = 2.05; an equal
        // length always passes (s = 0).
        let uniform = Curve::single(1.0);
        for (d, accepted) in [(0.5, true), (1.0, true), (2.0, true), (2.1, false), (5.0, false)] {
            assert_eq!(uniform.accepts(1.0, d), accepted, "d = {d}");
        }
        // An irregular curve (lengths 1 and 2) tolerates more, by (1 + h̄/s̄)^(s̄/h̄).
        let irregular = Curve::single(1.0).pooled(Curve::single(2.0));
        assert!(irregular.accepts(1.0, 2.5) && !irregular.accepts(1.0, 4.0));
        // A tiny deviation neither overflows nor changes the uniform answer.
        let almost = Curve::single(1.0).pooled(Curve::single(1.0 + 1e-15));
        assert!(almost.accepts(1.0, 2.0) && !almost.accepts(1.0, 2.1));
    }

    #[test]
    fn pooled_statistics_are_the_mean_and_sample_deviation() {
        let c = [1.0, 2.0, 4.0].map(Curve::single);
        let all = c[0].pooled(c[1].pooled(c[2]));
        assert!((all.mean - 7.0 / 3.0).abs() < 1e-15);
        let var: f64 = [1.0, 2.0, 4.0].iter().map(|x: &f64| (x - 7.0 / 3.0).powi(2)).sum();
        assert!((all.deviation() - (var / 2.0).sqrt()).abs() < 1e-15);
        assert_eq!(Curve::single(3.0).deviation(), 0.0);
    }
}
