//! Seeded curve samplers for tests, property tests and benchmarks.
//!
//! Each sampler returns a [`Sample`]: points in curve order and the ground-truth edges
//! between curve neighbours. All of them are deterministic: the same arguments (and seed)
//! give bit-identical points on a given platform. [`Rng`] is a tiny SplitMix64 generator,
//! so the core crate needs no `rand`.
//!
//! - [`Blob`]: a random smooth star-shaped closed curve, sampled equally spaced in arc
//!   length or with a smooth [`Modulation`] of the spacing whose non-uniformity is bounded.
//! - [`random_closed_curve`]: a 12-harmonic blob sampled uniformly, for benchmarks.
//! - [`spiral_band`]: a long thin coiled band, the hard case for Delaunay insertion order.
//! - [`regular_polygon`]: `k` points on a circle.
//!
//! Arc lengths are integrated with 5-point Gauss–Legendre on a grid of 4096 intervals and
//! inverted by Newton's method, so equal spacing is equal up to rounding whatever `n` is.
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use crate::{geometry::Point, Edge};
use std::f64::consts::{PI, TAU};

/// Number of grid intervals on which arc length is tabulated before Newton refinement.
const GRID: usize = 4096;

/// A SplitMix64 pseudo-random generator (Steele, Lea, Flood 2014): 64 bits of state,
/// statistically good enough for sampling test inputs, not for cryptography.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rng {
    state: u64,
}

impl Rng {
    /// A generator whose sequence is fixed by `seed`.
    pub fn new(seed: u64) -> Rng {
        Rng { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform `f64` in `[0, 1)` with 53 random bits.
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform integer in `0..n` (multiply-shift; the bias is below `n / 2^64`). Returns 0
    /// for `n == 0`.
    pub fn below(&mut self, n: usize) -> usize {
        ((u128::from(self.next_u64()) * n as u128) >> 64) as usize
    }

    /// Shuffles `items` in place with the Fisher–Yates algorithm.
    pub fn shuffle<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.below(i + 1);
            items.swap(i, j);
        }
    }
}

/// A sampled curve: points in curve order and its ground-truth edges.
///
/// For a closed curve with `n >= 3` points the edges form the cycle `0-1-…-(n-1)-0`; two
/// points give the single edge `[0, 1]`. Edges are `[i, j]` with `i < j`, sorted.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Sample {
    /// The sample points, in curve order.
    pub points: Vec<Point>,
    /// The ground-truth edges between curve neighbours, `[i, j]` with `i < j`, sorted.
    pub edges: Vec<Edge>,
}

impl Sample {
    /// The same sample with points permuted by a seeded shuffle; edges relabelled (still
    /// `[i, j]` with `i < j`, sorted). Point `order[k]` of `self` becomes point `k`, where
    /// `order` is `0..n` shuffled by [`Rng::new(seed)`](Rng::new).
    pub fn shuffled(&self, seed: u64) -> Sample {
        let n = self.points.len();
        let mut order: Vec<usize> = (0..n).collect();
        Rng::new(seed).shuffle(&mut order);
        let mut new_index = vec![0; n];
        for (new, &old) in order.iter().enumerate() {
            new_index[old] = new;
        }
        let points = order.iter().map(|&old| self.points[old]).collect();
        let mut edges: Vec<Edge> = self
            .edges
            .iter()
            .map(|&[i, j]| {
                let (a, b) = (new_index[i], new_index[j]);
                [a.min(b), a.max(b)]
            })
            .collect();
        edges.sort_unstable();
        Sample { points, edges }
    }
}

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

/// A "spiral band": a closed curve that winds out along an Archimedean spiral and back along
/// a parallel spiral just outside it, closed by two semicircular caps, like a coiled ribbon.
///
/// In units of the band width `w`: the inner edge is `r = 2 + θ/π` for `θ ∈ [0, 2π·T]`
/// (pitch 2, so the gap between neighbouring windings is ≈ `w`), the outer edge is 1 further
/// out, and the caps have radius 1/2. The number of turns `T` (real, → `sqrt(n / 16π)` for
/// large `n`: 3.4 for `n = 1000`, 12.9 for `10⁴`, 140 for `10⁶`) is chosen so that the `n`
/// samples, equally spaced in arc length, are `w/4` apart (within 0.6%); then `ρ ≤ 1/2`
/// everywhere (the local feature size is ≈ `w/2`). For `n < 13` there are no turns: the
/// sample is a circle of diameter `w`. The result is scaled into the unit disk. This is the
/// hard case for Delaunay insertion order: many long thin, nearly cocircular triangles.
pub fn spiral_band(n: usize) -> Sample {
    const R0: f64 = 2.0;
    const C: f64 = 1.0 / PI; // r grows by C per radian: pitch 2π·C = 2 band widths
                             // Length n/4 ≈ ∫ (r_in + r_out) dθ + π = B·end + C·end² + π with B = 2·R0 + 1: solve.
    let (b, excess) = (2.0 * R0 + 1.0, (n as f64 / 4.0 - PI).max(0.0));
    let end = ((b * b + 4.0 * C * excess).sqrt() - b) / (2.0 * C); // θ at the far cap
    let inner = Cumulative::new(|t: f64| (R0 + C * t).hypot(C), 0.0, end);
    let outer = Cumulative::new(|t: f64| (R0 + 1.0 + C * t).hypot(C), 0.0, end);
    let (len_in, len_out, len_cap) = (inner.total(), outer.total(), 0.5 * PI);
    let length = len_in + len_out + 2.0 * len_cap;
    let polar = |r: f64, t: f64| [r * t.cos(), r * t.sin()];
    // A cap from the inner to the outer edge at angle t, bulging along `side` (±1 = ±tangent).
    let cap = |t: f64, alpha: f64, side: f64| {
        let (radial, tangent) = ([t.cos(), t.sin()], [-side * t.sin(), side * t.cos()]);
        let (c, s) = (-0.5 * alpha.cos(), 0.5 * alpha.sin());
        let centre = R0 + 0.5 + C * t;
        [0, 1].map(|d| centre * radial[d] + c * radial[d] + s * tangent[d])
    };
    let scale = 1.0 / (R0 + 1.5 + C * end);
    let points = (0..n)
        .map(|i| {
            let s = length * i as f64 / n as f64;
            let p = if s < len_in {
                let t = inner.inverse(s);
                polar(R0 + C * t, t)
            } else if s < len_in + len_cap {
                cap(end, 2.0 * (s - len_in), 1.0)
            } else if s < len_in + len_cap + len_out {
                let t = outer.inverse(len_out - (s - len_in - len_cap));
                polar(R0 + 1.0 + C * t, t)
            } else {
                cap(0.0, PI - 2.0 * (s - len_in - len_cap - len_out), -1.0)
            };
            p.map(|x| x * scale)
        })
        .collect();
    Sample { points, edges: cycle_edges(n) }
}

/// Regular `k`-gon on a circle of radius `r` (`k` points), centred at the origin, first
/// vertex at angle 0, counter-clockwise.
pub fn regular_polygon(k: usize, r: f64) -> Sample {
    let points = (0..k)
        .map(|i| {
            let t = TAU * i as f64 / k as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    Sample { points, edges: cycle_edges(k) }
}

/// The edges of the cycle `0-1-…-(n-1)-0`, sorted (a single edge for `n = 2`).
fn cycle_edges(n: usize) -> Vec<Edge> {
    let mut edges: Vec<Edge> = (1..n).map(|i| [i - 1, i]).collect();
    if n >= 3 {
        edges.push([0, n - 1]);
        edges.sort_unstable();
    }
    edges
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

/// The integral of a positive smooth function `f` from `start`, tabulated on [`GRID`]
/// intervals and evaluated or inverted exactly (to rounding) between grid points.
struct Cumulative<F> {
    f: F,
    start: f64,
    step: f64,
    sums: Vec<f64>,
}

impl<F: Fn(f64) -> f64> Cumulative<F> {
    fn new(f: F, start: f64, end: f64) -> Self {
        let step = (end - start) / GRID as f64;
        let mut sums = vec![0.0];
        for k in 0..GRID {
            let a = start + k as f64 * step;
            sums.push(sums[k] + gauss(&f, a, a + step));
        }
        Cumulative { f, start, step, sums }
    }

    fn total(&self) -> f64 {
        self.sums[GRID]
    }

    /// The `x` with `∫ f` from `start` to `x` equal to `y ∈ [0, total]`: linear interpolation
    /// in the table, then Newton steps on the exact partial integral.
    fn inverse(&self, y: f64) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{distance, segments_cross};

    /// Distances from each point to the next one along the curve.
    fn gaps(sample: &Sample) -> Vec<f64> {
        let p = &sample.points;
        (0..p.len()).map(|i| distance(p[i], p[(i + 1) % p.len()])).collect()
    }

    fn max_ratio(v: &[f64]) -> f64 {
        v.iter().copied().fold(0.0, f64::max) / v.iter().copied().fold(f64::MAX, f64::min)
    }

    #[test]
    fn rng_is_seeded_uniform_and_shuffles() {
        let (mut a, mut b) = (Rng::new(3), Rng::new(3));
        assert!((0..100).all(|_| a.next_u64() == b.next_u64()));
        let u: Vec<f64> = (0..10_000).map(|_| a.uniform()).collect();
        assert!(u.iter().all(|x| (0.0..1.0).contains(x)));
        assert!((u.iter().sum::<f64>() / 1e4 - 0.5).abs() < 0.01);
        let mut v: Vec<usize> = (0..50).collect();
        a.shuffle(&mut v);
        assert_ne!(v, (0..50).collect::<Vec<_>>());
        v.sort_unstable();
        assert_eq!(v, (0..50).collect::<Vec<_>>());
    }

    #[test]
    fn samplers_give_cycles_deterministically() {
        let blob = Blob::random(&mut Rng::new(1), 5).sample(100, 0.2, Modulation::default());
        let cases = [(blob, 100), (random_closed_curve(2, 257), 257), (spiral_band(1000), 1000)];
        for (sample, n) in cases.iter().chain(&[(spiral_band(7), 7), (regular_polygon(8, 2.0), 8)])
        {
            assert_eq!((sample.points.len(), sample.edges.len()), (*n, *n));
            assert!(sample.edges.windows(2).all(|w| w[0] < w[1]));
            let mut degree = vec![0; *n];
            sample.edges.iter().flatten().for_each(|&i| degree[i] += 1);
            assert!(degree.iter().all(|&d| d == 2));
            assert!((1..*n).all(|i| sample.edges.binary_search(&[i - 1, i]).is_ok()));
        }
        assert_eq!(regular_polygon(2, 1.0).edges, vec![[0, 1]]);
        assert_eq!(regular_polygon(8, 2.0).points[0], [2.0, 0.0]);
        assert!(spiral_band(0).points.is_empty() && regular_polygon(1, 1.0).edges.is_empty());
        assert_eq!(random_closed_curve(5, 300), random_closed_curve(5, 300));
        assert_ne!(random_closed_curve(5, 300), random_closed_curve(6, 300));
        assert_eq!(spiral_band(500), spiral_band(500));
    }

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

    #[test]
    fn shuffled_relabels() {
        let sample = random_closed_curve(8, 200);
        let shuffled = sample.shuffled(7);
        let key = |p: Point| p.map(f64::to_bits);
        let new_index: std::collections::HashMap<_, _> =
            shuffled.points.iter().enumerate().map(|(k, &p)| (key(p), k)).collect();
        let perm: Vec<usize> = sample.points.iter().map(|&p| new_index[&key(p)]).collect();
        let map = |[i, j]: Edge| [perm[i].min(perm[j]), perm[i].max(perm[j])];
        let mut edges: Vec<Edge> = sample.edges.iter().map(|&e| map(e)).collect();
        edges.sort_unstable();
        assert_eq!((shuffled.points.len(), shuffled.edges), (200, edges));
        assert_ne!(shuffled.points, sample.points);
    }

    #[test]
    fn spiral_band_is_simple_and_well_sampled() {
        let sample = spiral_band(1000);
        let (p, n, g) = (&sample.points, 1000, gaps(&sample));
        let spacing = g.iter().sum::<f64>() / n as f64;
        assert!(max_ratio(&g) < 1.02);
        for (a, &[i, j]) in sample.edges.iter().enumerate() {
            for &[k, l] in &sample.edges[a + 1..] {
                let disjoint = i != k && i != l && j != k && j != l;
                assert!(!disjoint || !segments_cross(p[i], p[j], p[k], p[l]), "{i}-{j} x {k}-{l}");
            }
            for k in (0..n).filter(|&k| (2..n - 1).contains(&((i + n - k) % n))) {
                assert!(distance(p[i], p[k]) > 1.5 * spacing, "{i} {k}");
            }
        }
    }
}
