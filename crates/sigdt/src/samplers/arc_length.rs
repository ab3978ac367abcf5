//! Arc length by numerical integration: the integral of a positive smooth function,
//! tabulated with 5-point Gauss–Legendre on a grid and inverted by Newton's method.

/// Number of grid intervals on which arc length is tabulated before Newton refinement.
const GRID: usize = 4096;

/// The integral of a positive smooth function `f` from `start`, tabulated on [`GRID`]
/// intervals and evaluated or inverted exactly (to rounding) between grid points.
pub(super) struct Cumulative<F> {
    f: F,
    start: f64,
    step: f64,
    sums: Vec<f64>,
}

impl<F: Fn(f64) -> f64> Cumulative<F> {
    pub(super) fn new(f: F, start: f64, end: f64) -> Self {
        let step = (end - start) / GRID as f64;
        let mut sums = vec![0.0];
        for k in 0..GRID {
            let a = start + k as f64 * step;
            sums.push(sums[k] + gauss(&f, a, a + step));
        }
        Cumulative { f, start, step, sums }
    }

    pub(super) fn total(&self) -> f64 {
        self.sums[GRID]
    }

    /// The `x` with `∫ f` from `start` to `x` equal to `y ∈ [0, total]`: linear interpolation
    /// in the table, then Newton steps on the exact partial integral.
    pub(super) fn inverse(&self, y: f64) -> f64 {
        let k = self.sums.partition_point(|&s| s <= y).saturating_sub(1).min(GRID - 1);
        let (a, lo, hi) = (self.start + k as f64 * self.step, self.sums[k], self.sums[k + 1]);
        let mut x = a + self.step * ((y - lo) / (hi - lo)).clamp(0.0, 1.0);
        for _ in 0..6 {
            let dx = (lo + gauss(&self.f, a, x) - y) / (self.f)(x);
            x = (x - dx).clamp(a, a + self.step);
            if dx.abs() <= 1e-14 * self.step {
                break;
            }
        }
        x
    }
}

/// `∫ f` from `a` to `b` by 5-point Gauss–Legendre quadrature.
fn gauss(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const NODES: [(f64, f64); 5] = [
        (0.0, 0.568_888_888_888_888_9),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
        (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    half * NODES.iter().map(|&(x, w)| w * f(mid + half * x)).sum::<f64>()
}
