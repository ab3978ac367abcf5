//! Random smooth star-shaped closed curves ("blobs") and their samples, equally spaced in
//! arc length or with a smooth, bounded modulation of the spacing.
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use super::arc_length::Cumulative;
use super::{cycle_edges, Rng, Sample};
use crate::geometry::Point;
use std::f64::consts::TAU;

/// A smooth modulation of the sample spacing along a curve: at the fraction `s ∈ [0, 1)` of
/// the perimeter after the first sample, the spacing is proportional to
/// `exp(amplitude · sin(2π·frequency·s + phase))`. The default (amplitude 0) is uniform.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Modulation {
    /// `a`: the spacing varies by the factor `e^(2|a|)` between the sparsest and the densest place.
    pub amplitude: f64,
    /// `f`: number of sparse/dense cycles along the curve.
    pub frequency: u32,
    /// Phase of the sine, in radians.
    pub phase: f64,
}

impl Modulation {
    /// An upper bound on the ratio of the arc lengths from a sample to its two curve
    /// neighbours, for `n` samples: `exp(4π·f·|a|·e^|a| / n)`.
    ///
    /// Proof sketch: gaps are at most `e^|a|/n` of the perimeter, the log-spacing has slope at
    /// most `2π·f·|a|`, and two neighbouring gaps lie within two gaps of each other. So the
    /// non-uniformity `u` of \[MOW22\] stays below 2 whenever `4π·f·|a|·e^|a| < n·ln 2` (e.g.
    /// `a = 1, f = 3` needs `n > 148`). Euclidean distances differ from arc lengths by a
    /// relative `O((h/ρ)²)` for spacing `h` and curvature radius `ρ`, so keep a small margin.
    pub fn non_uniformity_bound(&self, n: usize) -> f64 {
        let a = self.amplitude.abs();
        (2.0 * TAU * f64::from(self.frequency) * a * a.exp() / n as f64).exp()
    }

    fn spacing(&self, s: f64) -> f64 {
        (self.amplitude * (TAU * f64::from(self.frequency) * s + self.phase).sin()).exp()
    }
}

/// A smooth closed star-shaped "blob": `r(θ) = 1 + Σ_k a_k cos(kθ + φ_k)` for `k = 2, 3, …`.
#[derive(Debug, Clone, PartialEq)]
pub struct Blob {
    /// `a_k` for `k = 2, 3, …` (`amplitudes[m]` belongs to harmonic `m + 2`).
    pub amplitudes: Vec<f64>,
    /// `φ_k` in radians, aligned with `amplitudes`.
    pub phases: Vec<f64>,
}

impl Blob {
    /// A random blob with `harmonics` harmonics `k = 2..=harmonics + 1`, amplitudes
    /// `a_k = 0.25·U/k²` and phases `2π·U` (`U` uniform in `[0, 1)`).
    ///
    /// Bounds, for any seed: `Σ a_k < 0.25·(π²/6 − 1) < 0.162`, so `r(θ)` stays in
    /// `[0.838, 1.162] ⊂ [0.6, 1.4]`; the curvature radius stays above
    /// [`curvature_radius_bound`](Self::curvature_radius_bound), whose worst case over all
    /// seeds is 0.325 for 3 harmonics, 0.202 for 6, 0.118 for 12 and 0.066 for 24.
    pub fn random(rng: &mut Rng, harmonics: usize) -> Blob {
        let (mut amplitudes, mut phases) = (Vec::new(), Vec::new());
        for k in 2..harmonics + 2 {
            amplitudes.push(0.25 * rng.uniform() / (k * k) as f64);
            phases.push(TAU * rng.uniform());
        }
        Blob { amplitudes, phases }
    }

    /// A lower bound on the curvature radius of this blob:
    /// `(1 − S₀)³ / ((1 + S₀)² + 2S₁² + (1 + S₀)·S₂)` with `Sₚ = Σ kᵖ·|a_k|`, from the polar
    /// curvature `κ = (r² + 2r'² − r·r'') / (r² + r'²)^{3/2}`. Meaningful when `S₀ < 1`.
    pub fn curvature_radius_bound(&self) -> f64 {
        let mut s = [0.0; 3];
        for (m, a) in self.amplitudes.iter().enumerate() {
            let k = (m + 2) as f64;
            s[0] += a.abs();
            s[1] += k * a.abs();
            s[2] += k * k * a.abs();
        }
        let (lo, hi) = (1.0 - s[0], 1.0 + s[0]);
        lo.powi(3) / (hi * hi + 2.0 * s[1] * s[1] + hi * s[2])
    }

    /// `n` samples equally spaced in arc length (or spaced by `modulation`), the first at the
    /// fraction `offset ∈ [0, 1)` of the perimeter measured counter-clockwise from `θ = 0`.
    /// For [`Modulation::default`] the spacing is equal up to rounding; otherwise the ratio of
    /// neighbouring gaps is below [`Modulation::non_uniformity_bound`], which must stay
    /// below 2 for the sample to meet the `u < 2` condition of \[MOW22\].
    pub fn sample(&self, n: usize, offset: f64, modulation: Modulation) -> Sample {
        let shape = Harmonics::new(self);
        let arc = Cumulative::new(|t| shape.speed(t), 0.0, TAU);
        // Spacing ∝ g(s) means the sample index grows like ∫ 1/g: invert that integral.
        let density = Cumulative::new(|s| 1.0 / modulation.spacing(s), 0.0, 1.0);
        let uniform = modulation.amplitude == 0.0 || modulation.frequency == 0;
        let points = (0..n)
            .map(|i| {
                let u = i as f64 / n as f64;
                let s = if uniform { u } else { density.inverse(u * density.total()) };
                shape.point(arc.inverse((offset + s).rem_euclid(1.0) * arc.total()))
            })
            .collect();
        Sample { points, edges: cycle_edges(n) }
    }
}

/// A long smooth random closed curve for benchmarks: [`Blob::random`] with 12 harmonics
/// (curvature radius ≥ 0.118, perimeter ≈ 2π), sampled uniformly with `n` points from a
/// random offset. Deterministic for a seed; well-sampled (`ρ < 1`) for `n ≳ 100`.
pub fn random_closed_curve(seed: u64, n: usize) -> Sample {
    let mut rng = Rng::new(seed);
    let blob = Blob::random(&mut rng, 12);
    blob.sample(n, rng.uniform(), Modulation::default())
}

/// A blob's harmonics with precomputed `(k, a·cos φ, a·sin φ)`, evaluated by rotation.
struct Harmonics(Vec<(f64, f64, f64)>);

impl Harmonics {
    fn new(blob: &Blob) -> Harmonics {
        let terms = blob.amplitudes.iter().zip(&blob.phases).enumerate();
        Harmonics(
            terms.map(|(m, (&a, &phi))| ((m + 2) as f64, a * phi.cos(), a * phi.sin())).collect(),
        )
    }

    /// `(r(θ), r'(θ))`.
    fn radius(&self, t: f64) -> (f64, f64) {
        let (s1, c1) = t.sin_cos();
        let (mut s, mut c) = (s1, c1);
        let (mut r, mut dr) = (1.0, 0.0);
        for &(k, ac, as_) in &self.0 {
            (s, c) = (s * c1 + c * s1, c * c1 - s * s1); // sin, cos of kθ
            r += ac * c - as_ * s;
            dr -= k * (ac * s + as_ * c);
        }
        (r, dr)
    }

    fn speed(&self, t: f64) -> f64 {
        let (r, dr) = self.radius(t);
        r.hypot(dr)
    }

    fn point(&self, t: f64) -> Point {
        let r = self.radius(t).0;
        [r * t.cos(), r * t.sin()]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samplers::tests::{gaps, max_ratio};

    #[test]
    fn spacing_is_uniform_or_within_the_modulation_bound() {
        for seed in 0..5 {
            let mut rng = Rng::new(seed);
            let blob = Blob::random(&mut rng, 12);
            let sample = blob.sample(500, rng.uniform(), Modulation::default());
            assert!(max_ratio(&gaps(&sample)) < 1.01, "seed {seed}");
        }
        let first = Blob::random(&mut Rng::new(9), 4).sample(64, 0.0, Modulation::default());
        assert_eq!(first.points[0][1], 0.0); // offset 0 starts at θ = 0
        let m = Modulation { amplitude: 1.0, frequency: 3, phase: 0.5 };
        let g = gaps(&Blob::random(&mut Rng::new(4), 6).sample(400, 0.7, m));
        let u = (0..400).map(|i| max_ratio(&[g[i], g[(i + 1) % 400]])).fold(0.0, f64::max);
        assert!(u < m.non_uniformity_bound(400) * 1.01 && u < 2.0, "u = {u}");
        assert!(max_ratio(&g) > 4.0, "the modulation should be visible");
    }

    #[test]
    fn curvature_radius_respects_the_bound() {
        for seed in 0..20 {
            let blob = Blob::random(&mut Rng::new(seed), 12);
            let bound = blob.curvature_radius_bound();
            assert!(bound >= 0.118, "seed {seed}");
            for step in 0..2000 {
                let t = TAU * step as f64 / 2000.0;
                let (mut r, mut d1, mut d2) = (1.0, 0.0, 0.0);
                for (m, (&a, &phi)) in blob.amplitudes.iter().zip(&blob.phases).enumerate() {
                    let k = (m + 2) as f64;
                    let (sin, cos) = (k * t + phi).sin_cos();
                    (r, d1, d2) = (r + a * cos, d1 - k * a * sin, d2 - k * k * a * cos);
                }
                let kappa = (r * r + 2.0 * d1 * d1 - r * d2) / (r * r + d1 * d1).powf(1.5);
                assert!(kappa.abs() * bound <= 1.0 && (0.6..1.4).contains(&r));
            }
        }
    }
}
