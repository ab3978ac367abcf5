//! Axis ranges and ticks: "nice" linear steps (1, 2 or 5 × 10^k) and decades on log axes.

/// A numeric axis: its range, labelled ticks and unlabelled minor ticks.
#[derive(Debug)]
pub(super) struct Axis {
    /// The range, in log10 units on a log axis.
    lo: f64,
    hi: f64,
    log: bool,
    /// Labelled ticks: value and label.
    pub ticks: Vec<(f64, String)>,
    /// Unlabelled ticks (2..9 × 10^k on a log axis).
    pub minor: Vec<f64>,
}

impl Axis {
    /// A linear axis covering `values` (non-finite ones ignored), widened to whole steps.
    /// With `zero`, the range includes 0. Without values it is 0..1.
    pub fn linear(values: impl IntoIterator<Item = f64>, zero: bool) -> Axis {
        let (mut lo, mut hi) = range(values.into_iter().filter(|v| v.is_finite()));
        if zero {
            (lo, hi) = (lo.min(0.0), hi.max(0.0));
        }
        if lo > hi {
            (lo, hi) = (0.0, 1.0);
        } else if lo == hi {
            let pad = if lo == 0.0 { 1.0 } else { lo.abs() * 0.1 };
            (lo, hi) = (lo - pad, hi + pad);
        }
        let (mantissa, exponent) = nice_step((hi - lo) / 5.0);
        let step = mantissa as f64 * 10f64.powi(exponent);
        let (first, last) = ((lo / step).floor() as i64, (hi / step).ceil() as i64);
        let ticks: Vec<(f64, String)> =
            (first..=last).map(|k| tick(k * mantissa, exponent)).collect();
        Axis { lo: ticks[0].0, hi: ticks[ticks.len() - 1].0, log: false, ticks, minor: vec![] }
    }

    /// A linear axis from `lo` to `hi` with a tick every `step`.
    pub fn fixed(lo: f64, hi: f64, step: f64) -> Axis {
        let n = ((hi - lo) / step).round() as usize;
        let ticks = (0..=n)
            .map(|k| {
                let v = lo + k as f64 * step;
                (v, format!("{v}"))
            })
            .collect();
        Axis { lo, hi, log: false, ticks, minor: vec![] }
    }

    /// A log axis over whole decades covering the positive finite `values`; 1..10 without any.
    pub fn log(values: impl IntoIterator<Item = f64>) -> Axis {
        let logs = values.into_iter().filter(|v| v.is_finite() && *v > 0.0).map(f64::log10);
        let (lo, hi) = range(logs);
        let (mut first, mut last) =
            if lo > hi { (0, 1) } else { (lo.floor() as i32, hi.ceil() as i32) };
        if first == last {
            last += 1;
        }
        if last - first > 12 {
            first = last - 12;
        }
        let every = if last - first > 6 { 2 } else { 1 };
        let ticks = (first..=last)
            .filter(|k| (k - first) % every == 0)
            .map(|k| (k as f64, decade(k)))
            .collect();
        let minor = if last - first <= 6 {
            (first..last)
                .flat_map(|k| (2..10).map(move |j| k as f64 + (j as f64).log10()))
                .collect()
        } else {
            vec![]
        };
        Axis { lo: first as f64, hi: last as f64, log: true, ticks, minor }
    }

    /// Where `v` falls on the axis, from 0 (start) to 1 (end), clamped; `None` if `v` cannot
    /// be shown (not finite, or not positive on a log axis).
    pub fn frac(&self, v: f64) -> Option<f64> {
        let v = if self.log { (v > 0.0).then(|| v.log10())? } else { v };
        let f = (v - self.lo) / (self.hi - self.lo);
        f.is_finite().then(|| f.clamp(0.0, 1.0))
    }

    /// Like [`Axis::frac`] for a tick position, which on a log axis is already a log10.
    pub fn tick_frac(&self, t: f64) -> f64 {
        ((t - self.lo) / (self.hi - self.lo)).clamp(0.0, 1.0)
    }
}

/// The smallest and largest value; (+∞, −∞) if there are none.
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// The step 1, 2 or 5 × 10^exponent nearest above `raw`, as (mantissa, exponent).
fn nice_step(raw: f64) -> (i64, i32) {
    let exponent = raw.log10().floor() as i32;
    let scaled = raw / 10f64.powi(exponent);
    match scaled {
        s if s <= 1.0 => (1, exponent),
        s if s <= 2.0 => (2, exponent),
        s if s <= 5.0 => (5, exponent),
        _ => (1, exponent + 1),
    }
}

/// The tick `units × 10^exponent`, its value parsed from its decimal text (no rounding drift).
fn tick(units: i64, exponent: i32) -> (f64, String) {
    let value: f64 = format!("{units}e{exponent}").parse().unwrap_or(0.0);
    let label = if units == 0 {
        "0".to_string()
    } else if (-5..6).contains(&exponent) && value.abs() < 1e6 {
        format!("{:.*}", (-exponent).max(0) as usize, value)
    } else {
        format!("{value:e}")
    };
    (value, label)
}

/// The label of the decade 10^k: plain from 0.001 to 100000, otherwise `1e{k}`.
fn decade(k: i32) -> String {
    if (-3..=5).contains(&k) {
        tick(1, k).1
    } else {
        format!("1e{k}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(a: &Axis) -> Vec<&str> {
        a.ticks.iter().map(|(_, l)| l.as_str()).collect()
    }

    #[test]
    fn linear_ticks_are_nice() {
        assert_eq!(labels(&Axis::linear([0.3, 9.2], true)), ["0", "2", "4", "6", "8", "10"]);
        let small = Axis::linear([1e-5, 4.4e-5], false);
        assert_eq!(labels(&small), ["0.00001", "0.00002", "0.00003", "0.00004", "0.00005"]);
        let tiny = Axis::linear([1e-7, 3e-7], false);
        assert_eq!(labels(&tiny)[0], "1e-7");
    }

    #[test]
    fn degenerate_linear_ranges() {
        assert_eq!(labels(&Axis::linear([], false)), ["0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
        let one = Axis::linear([5.0, f64::NAN], false);
        assert!(one.frac(5.0).unwrap() > 0.0 && one.frac(5.0).unwrap() < 1.0);
        assert_eq!(Axis::linear([0.0], false).frac(0.0), Some(0.5));
    }

    #[test]
    fn log_axis_uses_decades() {
        let a = Axis::log([3.0, 2500.0, -1.0, 0.0]);
        assert_eq!(labels(&a), ["1", "10", "100", "1000", "10000"]);
        assert_eq!(a.minor.len(), 4 * 8);
        assert_eq!(a.frac(100.0), Some(0.5));
        assert_eq!(a.frac(0.0), None);
        assert_eq!(labels(&Axis::log([])), ["1", "10"]);
        assert_eq!(labels(&Axis::log([1e-9, 1e-8]))[0], "1e-9");
    }
}
