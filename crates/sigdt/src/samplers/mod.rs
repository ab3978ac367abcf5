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
//! - [`uniform_noise`], [`lfs_noise`] and [`add_outliers`]: perturbed copies of a sample.
//! - [`cocircular_lattice`], [`zigzag`], [`tall_zigzag`], [`line_and_point`],
//!   [`uniform_square`]: inputs that are no sampled curve, each some method's slowest.
//!
//! The research samplers (cubic Bézier paths from SVG files and their ε-sampling) are in the
//! `sigdt-lab` crate.
//!
//! Arc lengths are integrated with 5-point Gauss–Legendre on a grid of 4096 intervals and
//! inverted by Newton's method, so equal spacing is equal up to rounding whatever `n` is.
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.

mod arc_length;
mod blob;
mod hostile;
mod noise;
mod polygon;
mod spiral;

pub use blob::{random_closed_curve, Blob, Modulation};
pub use hostile::{
    cocircular_lattice, line_and_point, tall_zigzag, uniform_square, zigzag, MAX_LATTICE_POINTS,
};
pub use noise::{add_outliers, lfs_noise, uniform_noise, MAX_OUTLIER_FRACTION};
pub use polygon::regular_polygon;
pub use spiral::spiral_band;

use crate::geometry::{Edge, Point};

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

/// The edges of the cycle `0-1-…-(n-1)-0`, sorted (a single edge for `n = 2`): the ground
/// truth of points given in curve order.
pub fn cycle_edges(n: usize) -> Vec<Edge> {
    let mut edges: Vec<Edge> = (1..n).map(|i| [i - 1, i]).collect();
    if n >= 3 {
        edges.push([0, n - 1]);
        edges.sort_unstable();
    }
    edges
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::geometry::distance;

    /// Distances from each point to the next one along the curve.
    pub(crate) fn gaps(sample: &Sample) -> Vec<f64> {
        let p = &sample.points;
        (0..p.len()).map(|i| distance(p[i], p[(i + 1) % p.len()])).collect()
    }

    pub(crate) fn max_ratio(v: &[f64]) -> f64 {
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
}
