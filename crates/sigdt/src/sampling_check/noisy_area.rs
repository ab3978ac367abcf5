//! The sampling check's sixth property: loops whose points scatter like noise, by enough to
//! move the area they enclose.
//!
//! Noise of a quarter of the spacing leaves the order of a loop's points intact, and then no
//! other finding fires; yet the polygon through the noisy points differs from the curve by
//! a strip along its whole length. On a small outline (a few dozen points) that strip is
//! more than a twentieth of the area: the result is right in order and wrong in area.
//!
//! **What a sampled curve does.** Along a curve sampled with ε < 1 the turning direction
//! changes only at the curve's inflections and corners; the curvature read at the samples
//! varies slowly from one sample to the next. Noise does neither: with independent
//! displacements, consecutive turns reverse at 73 % of the samples (1/2 + asin(2/3)/π, the
//! turns' correlation being −2/3), and the curvature jumps at every sample.
//!
//! **The estimate.** At each vertex `v` of a loop with neighbours `u`, `w`, the signed
//! curvature of the circle through them is `k = 2 · cross(v − u, w − v) / (|uv| |vw| |uw|)`.
//! Its jump `k − (k⁻ + k⁺) / 2` against the neighbours' curvatures, times `|uv| |vw| / 2`, is
//! a displacement `d`: zero on circles and straight lines at any spacing, and for independent
//! Gaussian displacements of standard deviation σ across the curve at even spacing
//! `d = 1.5 n₀ − n₋₁ − n₊₁ + (n₋₂ + n₊₂) / 4`, of standard deviation √4.375 σ, so that
//! `median |d| = 1.411 σ` ([`NOISE_MEDIAN`]). The loop's σ is its median `|d|` over that,
//! robust to corners (one vertex each). The polygon through points displaced by σ differs
//! from the curve by an area of `0.648 σ` per unit length ([`AREA_PER_LENGTH`]:
//! `E|linear interpolation of two independent N(0, σ²)|` = √(2/π) · 0.8116 σ).
//!
//! **The finding.** Over the loops of at least [`MIN_LOOP_POINTS`] points: when the turn
//! reverses at more than half of their vertices (as under noise, not on a sampled curve)
//! and the expected symmetric difference `E = Σ 0.648 σ · length` is more than
//! [`AREA_TOLERANCE`] of the union with the enclosed area (`E / (A + E/2)`, `A` the sum
//! of the areas the loops enclose), the result says so: its area is uncertain by about
//! `E / A`. (Counting a hole's area as its loop's own, rather than subtracting it, keeps
//! the check free of nesting; it can only understate the share.)
//! Points too sparse for their curve (ε near 1) look the same, and the area is as
//! uncertain then; a polygon given by its corners, every vertex a turn against the last,
//! can also be reported (`docs/sampling-check.md` counts how often).
//!
//! # Complexity
//! O(k) time for k loop vertices; O(L) memory for L loops until the turns say noise, then
//! O(m) more for the largest loop of m vertices.
use super::{Finding, FindingKind, MIN_LOOP_POINTS};
use crate::delaunay::Triangulation;
use crate::geometry::{distance, orient2d, Point};

/// `median |d| / σ` for independent Gaussian displacements of standard deviation σ at even
/// spacing: `0.67449 · √4.375` (module docs).
pub const NOISE_MEDIAN: f64 = 1.410_796_530_740_039;

/// The mean area between the polygon through points displaced by σ and the curve, per unit
/// length and per σ: `√(2/π) · ∫₀¹ √((1 − t)² + t²) dt` (module docs).
pub const AREA_PER_LENGTH: f64 = 0.647_573_178_906_706_8;

/// The share of the union by which a result's area may be uncertain before it is reported:
/// the accuracy at which an outline counts as right (IoU 0.95, `docs/evaluation.md`).
pub const AREA_TOLERANCE: f64 = 0.05;

/// One loop's noise estimate.
struct LoopNoise {
    /// The estimated σ times the loop's length: its expected area error over
    /// [`AREA_PER_LENGTH`].
    sigma_length: f64,
    /// The vertex with the largest curvature jump.
    worst_vertex: u32,
}

/// The finding of this module on the closed `rings` of a result (vertices of `dt` in
/// order), if any; `at` in input indices.
pub(crate) fn noisy_area(dt: &Triangulation, rings: &[&[u32]]) -> Option<Finding> {
    // The reversals first: they end the check on sampled curves without allocating (their
    // count does not depend on where a loop starts or which way it runs).
    let large = || rings.iter().filter(|r| r.len() >= MIN_LOOP_POINTS);
    let vertices: usize = large().map(|l| l.len()).sum();
    if 2 * large().map(|l| reversals(dt, l)).sum::<usize>() <= vertices {
        return None;
    }
    // The sums below, in an order that depends only on the loops, not on how a method
    // numbered them: the same finding from every path to the same result.
    let mut rings: Vec<Vec<u32>> =
        rings.iter().filter(|r| r.len() >= 3).map(|r| canonical(dt, r)).collect();
    rings.sort_unstable_by_key(|r| dt.input_index(r[0]));
    let loops: Vec<&[u32]> =
        rings.iter().filter(|r| r.len() >= MIN_LOOP_POINTS).map(Vec::as_slice).collect();
    let reversals: Vec<usize> = loops.iter().map(|l| reversals(dt, l)).collect();
    let mut jumps = Vec::new();
    let estimates: Vec<LoopNoise> = loops.iter().map(|l| loop_noise(dt, l, &mut jumps)).collect();
    let expected = AREA_PER_LENGTH * estimates.iter().map(|m| m.sigma_length).sum::<f64>();
    let area = enclosed_area(dt, &rings);
    let tolerated = AREA_TOLERANCE * (area + 0.5 * expected);
    if expected.partial_cmp(&tolerated) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    // The loops that look noisy themselves; the worst is the one with most area in doubt.
    let noisy: Vec<(usize, &LoopNoise)> =
        estimates.iter().enumerate().filter(|&(k, _)| 2 * reversals[k] > loops[k].len()).collect();
    let (_, worst) = noisy
        .iter()
        .max_by(|(i, a), (j, b)| a.sigma_length.total_cmp(&b.sigma_length).then(j.cmp(i)))?;
    let share = if area > 0.0 { expected / area } else { f64::INFINITY };
    Some(Finding {
        kind: FindingKind::NoisyArea,
        count: noisy.len(),
        worst: share,
        at: dt.input_index(worst.worst_vertex),
        point: super::given_point(dt, worst.worst_vertex),
    })
}

/// `ring` rotated to start at its smallest input index and turned to run on towards the
/// smaller of that vertex's two neighbours.
fn canonical(dt: &Triangulation, ring: &[u32]) -> Vec<u32> {
    let n = ring.len();
    let input = |k: usize| dt.input_index(ring[k % n]);
    let start = (0..n).min_by_key(|&k| input(k)).unwrap_or(0);
    let forwards = input(start + 1) < input(start + n - 1);
    let at = |k: usize| if forwards { ring[(start + k) % n] } else { ring[(start + n - k) % n] };
    (0..n).map(at).collect()
}

/// How many ulps of its largest coordinate a vertex may lie off the line through its
/// neighbours and still count as straight: samples placed on a straight side by
/// interpolation (`shapely.segmentize`, densified GIS lines) are off it by a few roundings,
/// with either sign, and would otherwise read as turns that reverse at random, like noise.
/// No sampled curve or noise turns by so little: 64 ulps is 1.4·10⁻¹⁴ of the coordinates.
pub const ROUNDING_ULPS: f64 = 64.0;

/// How many vertices of the closed `ring` turn the other way than the last vertex that
/// turned (exact orientations; a straight vertex, or one within [`ROUNDING_ULPS`] of
/// straight, reverses nothing and is passed over).
fn reversals(dt: &Triangulation, ring: &[u32]) -> usize {
    let n = ring.len();
    let at = |k: usize| dt.point(ring[k % n]);
    let turn = |k: usize| {
        let (u, v, w) = (at(k + n - 1), at(k), at(k + 1));
        let side = orient2d(u, v, w);
        let scale = [u, v, w].iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
        // |side| / |uw| is how far v lies off the line uw.
        match side.abs() <= ROUNDING_ULPS * f64::EPSILON * scale * distance(u, w) {
            true => 0.0,
            false => side.signum(),
        }
    };
    let mut before = (1..=n).map(|k| turn(n - k)).find(|&t| t != 0.0).unwrap_or(0.0);
    let mut count = 0;
    for k in 0..n {
        let now = turn(k);
        if now != 0.0 {
            count += usize::from(before * now < 0.0);
            before = now;
        }
    }
    count
}

/// The noise estimate of the closed `ring` (at least [`MIN_LOOP_POINTS`] vertices);
/// `jumps` is scratch space.
fn loop_noise(dt: &Triangulation, ring: &[u32], jumps: &mut Vec<f64>) -> LoopNoise {
    let n = ring.len();
    let at = |k: usize| dt.point(ring[k % n]);
    // Signed curvature of the circle through vertex `k` and its neighbours, with the two
    // edge lengths at the vertex.
    let bend = |k: usize| {
        let (u, v, w) = (at(k + n - 1), at(k), at(k + 1));
        let (uv, vw, uw) = (distance(u, v), distance(v, w), distance(u, w));
        let cross = (v[0] - u[0]) * (w[1] - v[1]) - (v[1] - u[1]) * (w[0] - v[0]);
        let denominator = uv * vw * uw;
        let curvature = if denominator > 0.0 { 2.0 * cross / denominator } else { 0.0 };
        (curvature, uv, vw)
    };
    jumps.clear();
    let (mut worst_jump, mut worst_vertex) = (f64::NEG_INFINITY, ring[0]);
    let mut length = 0.0;
    let (mut before, mut here) = (bend(n - 1), bend(0));
    for (k, &vertex) in ring.iter().enumerate() {
        let after = bend(k + 1);
        let (curvature, uv, vw) = here;
        let jump = ((curvature - 0.5 * (before.0 + after.0)) * uv * vw * 0.5).abs();
        let jump = if jump.is_finite() { jump } else { f64::MAX };
        let better = jump > worst_jump
            || (jump == worst_jump && dt.input_index(vertex) < dt.input_index(worst_vertex));
        if better {
            (worst_jump, worst_vertex) = (jump, vertex);
        }
        jumps.push(jump);
        length += vw;
        (before, here) = (here, after);
    }
    let (_, median, _) = jumps.select_nth_unstable_by(n / 2, f64::total_cmp);
    LoopNoise { sigma_length: *median / NOISE_MEDIAN * length, worst_vertex }
}

/// The area each of the `rings` encloses, summed (a hole counts as its own loop's area, so
/// that no nesting is needed: the share of the area in doubt is then a lower bound of the
/// region's).
fn enclosed_area(dt: &Triangulation, rings: &[Vec<u32>]) -> f64 {
    let ring_area = |ring: &[u32]| {
        let p = |k: usize| dt.point(ring[k % ring.len()]);
        let twice: f64 = (0..ring.len())
            .map(|k| {
                let (a, b): (Point, Point) = (p(k), p(k + 1));
                a[0] * b[1] - b[0] * a[1]
            })
            .sum();
        0.5 * twice.abs()
    };
    rings.iter().map(|r| ring_area(r)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    /// `n` samples of a circle of radius 1, each moved across it by `noise · spacing` times
    /// a seeded standard normal.
    fn noisy_circle(n: usize, noise: f64, seed: u64) -> Vec<Point> {
        let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
        let mut uniform = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        let spacing = TAU / n as f64;
        (0..n)
            .map(|i| {
                let gauss = (-2.0 * uniform().ln()).sqrt() * (TAU * uniform()).cos();
                let r = 1.0 + noise * spacing * gauss;
                let a = TAU * i as f64 / n as f64;
                [r * a.cos(), r * a.sin()]
            })
            .collect()
    }

    fn finding(points: &[Point]) -> Option<Finding> {
        let dt = Triangulation::new(points).unwrap();
        let vertex_of = dt.vertex_of_inputs();
        let ring: Vec<u32> = (0..points.len()).map(|i| vertex_of[i]).collect();
        noisy_area(&dt, &[&ring])
    }

    #[test]
    fn a_sampled_circle_is_not_noisy_at_any_size() {
        for n in [7, 12, 40, 1000] {
            assert_eq!(finding(&noisy_circle(n, 0.0, 1)), None, "{n} points");
        }
    }

    #[test]
    fn samples_interpolated_on_straight_sides_do_not_reverse() {
        // A jagged polygon of 24 corners whose sides are densified by interpolation, as
        // `shapely.segmentize` does: the samples lie off their sides by roundings, with either
        // sign. They turn nowhere; only the corners do, and those alternate at most half the
        // time by construction (every second corner juts out).
        let corners: Vec<Point> = (0..24)
            .map(|k| {
                let (a, r) = (TAU * k as f64 / 24.0 + 0.1, if k % 2 == 0 { 1000.3 } else { 900.7 });
                [r * a.cos() + 3.1e5, r * a.sin() - 7.7e4]
            })
            .collect();
        let mut points = Vec::new();
        for (k, &a) in corners.iter().enumerate() {
            let b = corners[(k + 1) % 24];
            points.extend(
                (0..10)
                    .map(|j| j as f64 / 10.0)
                    .map(|t| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]),
            );
        }
        let dt = Triangulation::new(&points).unwrap();
        let vertex_of = dt.vertex_of_inputs();
        let ring: Vec<u32> = vertex_of.clone();
        assert_eq!(reversals(&dt, &ring), 24, "every corner turns against the last");
        let on_sides = (0..points.len()).filter(|k| k % 10 != 0).map(|k| vertex_of[k]);
        let turns = on_sides.filter(|&v| {
            let k = ring.iter().position(|&w| w == v).unwrap();
            let n = ring.len();
            orient2d(dt.point(ring[(k + n - 1) % n]), dt.point(v), dt.point(ring[(k + 1) % n]))
                != 0.0
        });
        assert!(turns.count() > 0, "the test needs samples off their sides by roundings");
    }

    #[test]
    fn noise_on_a_small_loop_moves_its_area_and_is_found() {
        // 40 samples moved by half their spacing: the strip 0.648 · σ · 2π, σ = 0.5 · 2π/40,
        // is 10 % of the area π (more on the longer noisy polygon; the median of 40 values
        // varies).
        for seed in 1..=8 {
            let found = finding(&noisy_circle(40, 0.5, seed)).expect("40 noisy samples");
            assert_eq!((found.kind, found.count), (FindingKind::NoisyArea, 1));
            assert!(found.worst > 0.06 && found.worst < 0.3, "{found:?}");
            assert!(found.to_string().contains("uncertain"), "{found}");
        }
    }

    #[test]
    fn the_same_noise_on_a_large_loop_is_within_tolerance() {
        // 400 samples: σ = 0.4 · 2π/400, the strip 0.8 % of the area.
        assert_eq!(finding(&noisy_circle(400, 0.4, 3)), None);
    }

    #[test]
    fn the_estimate_recovers_the_noise() {
        let points = noisy_circle(4000, 0.2, 5);
        let dt = Triangulation::new(&points).unwrap();
        let vertex_of = dt.vertex_of_inputs();
        let ring: Vec<u32> = (0..points.len()).map(|i| vertex_of[i]).collect();
        let noise = loop_noise(&dt, &ring, &mut Vec::new());
        // The triangulation's coordinates are scaled into a safe range.
        let scale = distance(dt.point(ring[0]), dt.point(ring[1])) / distance(points[0], points[1]);
        let sigma = noise.sigma_length / scale / scale / TAU;
        let expected = 0.2 * TAU / 4000.0;
        assert!((sigma / expected - 1.0).abs() < 0.1, "σ {sigma} against {expected}");
        let share = reversals(&dt, &ring) as f64 / 4000.0;
        assert!((0.65..0.8).contains(&share), "reversals {share}");
    }
}
