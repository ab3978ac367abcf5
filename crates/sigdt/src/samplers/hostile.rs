//! Inputs that are no sampled curve, each the slowest found for some method
//! (`docs/reliability.md`, "Worst case of each method"): the degenerate tests and the
//! worst-case benchmark (`make bench`) build them here, so both measure the same inputs.
use super::Rng;
use crate::geometry::Point;

/// The Gaussian primes `a + bi` whose products place lattice points on one circle; their
/// norms 5, 13, 17, ... are the primes ≡ 1 (mod 4).
const GAUSSIAN_PRIMES: [(i64, i64); 9] =
    [(1, 2), (2, 3), (1, 4), (2, 5), (1, 6), (4, 5), (2, 7), (5, 6), (3, 8)];

/// The most points [`cocircular_lattice`] gives: 4 · 5 · 3⁸, with
/// r = 5² · 13 · 17 · 29 · 37 · 41 · 53 · 61 · 73 ≈ 5.7 · 10¹³.
pub const MAX_LATTICE_POINTS: usize = 131_220;

/// `n` integer points exactly on one circle centred at the origin, counter-clockwise from
/// angle 0: the smallest circle of the form r = 5^e · 13 · 17 · ... with at least `n` lattice
/// points (4 ∏ (2e + 1) of them), every (len / n)-th of them kept. Neighbouring gaps differ
/// by factors in the thousands, and every four points are cocircular: the worst case of the
/// incircle test's ties. Coordinates are below 2⁵³, so exact as `f64`.
///
/// # Panics
/// If `n` exceeds [`MAX_LATTICE_POINTS`].
pub fn cocircular_lattice(n: usize) -> Vec<Point> {
    assert!(n <= MAX_LATTICE_POINTS, "at most {MAX_LATTICE_POINTS} lattice points, asked {n}");
    let mul = |[a, b]: [i64; 2], [c, d]: [i64; 2]| [a * c - b * d, a * d + b * c];
    let power = |z: [i64; 2], k: u32| (0..k).fold([1, 0], |w, _| mul(w, z));
    // Exponents: one a prime, as few primes as give n points, then 5² for the last factor.
    let mut primes: Vec<(i64, i64, u32)> = Vec::new();
    let count = |primes: &[(i64, i64, u32)]| {
        primes.iter().map(|p| 2 * p.2 as usize + 1).product::<usize>() * 4
    };
    for &(a, b) in &GAUSSIAN_PRIMES {
        if count(&primes) >= n {
            break;
        }
        primes.push((a, b, 1));
    }
    if count(&primes) < n {
        primes[0].2 = 2;
    }
    let mut lattice = vec![[1i64, 0]];
    for &(a, b, e) in &primes {
        lattice = lattice
            .iter()
            .flat_map(|&z| {
                (0..=2 * e).map(move |k| mul(z, mul(power([a, b], k), power([a, -b], 2 * e - k))))
            })
            .collect();
    }
    lattice = lattice.iter().flat_map(|&[x, y]| [[x, y], [-y, x], [-x, -y], [y, -x]]).collect();
    let angle = |p: &[i64; 2]| (p[1] as f64).atan2(p[0] as f64).rem_euclid(std::f64::consts::TAU);
    lattice.sort_by(|p, q| angle(p).total_cmp(&angle(q)));
    lattice.dedup();
    debug_assert_eq!(lattice.len(), count(&primes));
    let len = lattice.len();
    (0..n).map(|k| lattice[k * len / n]).map(|[x, y]| [x as f64, y as f64]).collect()
}

/// The zigzag `(i, (i mod 2) · height)`, `i < n`: for a tiny height, a line of points whose
/// triangulation is all slivers (CRUST's worst case).
pub fn zigzag(n: usize, height: f64) -> Vec<Point> {
    (0..n).map(|i| [i as f64, (i % 2) as f64 * height]).collect()
}

/// The zigzag `(i · width, i mod 2)`, `i < n`: for a tiny width, two rows of equal keys in a
/// k-d tree (HNN-CRUST's worst case).
pub fn tall_zigzag(n: usize, width: f64) -> Vec<Point> {
    (0..n).map(|i| [i as f64 * width, (i % 2) as f64]).collect()
}

/// `n` points `(i, 0)` on a line and, last, one point `(n/2 + 1/2, 1)` off it: the
/// triangulation is a fan around a vertex of degree `n` (the worst case of FITCONNECT and
/// STRETCHDENOISE, whose fits around it grow to the whole line).
pub fn line_and_point(n: usize) -> Vec<Point> {
    let mut points: Vec<Point> = (0..n).map(|i| [i as f64, 0.0]).collect();
    points.push([n as f64 / 2.0 + 0.5, 1.0]);
    points
}

/// `n` points uniform at random in the unit square: no curve at all (SIG-AUTO's worst case,
/// whose outlier rules see one long tangle).
pub fn uniform_square(n: usize, seed: u64) -> Vec<Point> {
    let mut rng = Rng::new(seed);
    (0..n).map(|_| [rng.uniform(), rng.uniform()]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_points_are_exactly_cocircular_and_distinct() {
        for n in [1, 12, 13, 108, 972, 1000, MAX_LATTICE_POINTS] {
            let points = cocircular_lattice(n);
            assert_eq!(points.len(), n);
            let r2 = |p: &Point| (p[0] as i128).pow(2) + (p[1] as i128).pow(2);
            assert!(points.iter().all(|p| r2(p) == r2(&points[0])), "n = {n}");
            let mut sorted = points.clone();
            sorted.sort_by(|p, q| p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1])));
            sorted.dedup();
            assert_eq!(sorted.len(), n, "n = {n}: repeated points");
        }
        // The smallest circles: 4 · 3 points on r = 5, 4 · 3³ on r = 5 · 13 · 17.
        assert_eq!(cocircular_lattice(12)[0], [5.0, 0.0]);
        assert_eq!(cocircular_lattice(108)[0], [1105.0, 0.0]);
    }
}
