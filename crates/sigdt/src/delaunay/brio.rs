//! Biased randomised insertion order (BRIO) with Hilbert-sorted rounds.
//!
//! Amenta, Choi and Rote (*Incremental constructions con BRIO*, SoCG 2003): put each point in
//! the last round with probability 1/2, in the one before with 1/4, and so on, and sort each
//! round along a space-filling curve. Random rounds keep the expected conflict structure of
//! randomised incremental construction; the Hilbert order inside a round keeps consecutive
//! insertions close, so a walk from the previous vertex finds the next triangle in O(1)
//! expected steps.
//!
//! Why: on curve samples, spade's `bulk_load` and the `delaunator` crate go quadratic, while
//! BRIO with hints stays near-linear (the measurements are in `docs/algorithms.md` §0.2).
//!
//! [`canonical_order`] draws each point's round from a hash of its coordinates and breaks
//! Hilbert-cell ties by coordinates, so the order depends on the point set alone: the vertex
//! and triangle numbering that insertion produces is the same for every order of the input.
//! [`brio_order_within`] (CRUST's second triangulation) shuffles with a fixed seed instead.
//! [`put_first_triangle_first`] then moves three points that span a triangle to the front,
//! for the insertion of all the points and of each part of a divided triangulation.
//!
//! # Complexity
//! O(n log n) for the sorts.

use crate::geometry::{orient2d, Point};
use std::cmp::Ordering;

/// Fixed seed of the shuffle and the coordinate hash: results are reproducible bit for bit.
const SEED: u64 = 0x5157_4454_2d32_4431;
/// Rounds smaller than this are merged into the first round.
const MIN_ROUND: usize = 64;
/// Bits per axis of the Hilbert grid (2^16 × 2^16 cells, keys fit in 32 bits).
const HILBERT_BITS: u32 = 16;

/// The insertion order of the points `0..n`: BRIO rounds drawn from a hash of each point's
/// coordinates, Hilbert order inside a round, ties by coordinates (lexicographic), then by
/// index (exact duplicates only). A function of the point set alone (module docs).
pub fn canonical_order(points: impl Fn(u32) -> [f64; 2] + Sync + Send, n: usize) -> Vec<u32> {
    let Some(bbox) = bounding_box((0..n as u32).map(&points)) else { return Vec::new() };
    let rounds = round_count(n);
    // Each point's `(round << 32) | key`, computed on the pool.
    let round_key: Vec<u64> = crate::parallel::map_range(n, |i| {
        let p = points(i as u32);
        (u64::from(round_of(p, rounds)) << 32) | u64::from(hilbert_key(p, &bbox))
    });
    // Counting sort by round (stable, so each round holds ascending indices), then a sort of
    // `(key << 32) | index` inside each round.
    let mut start = vec![0usize; usize::from(rounds) + 1];
    for &rk in &round_key {
        start[(rk >> 32) as usize + 1] += 1;
    }
    for r in 0..usize::from(rounds) {
        start[r + 1] += start[r];
    }
    let mut keyed = vec![0u64; n];
    let mut fill = start.clone();
    for (i, &rk) in round_key.iter().enumerate() {
        let r = (rk >> 32) as usize;
        keyed[fill[r]] = (rk << 32) | i as u64;
        fill[r] += 1;
    }
    drop(round_key);
    for r in 0..usize::from(rounds) {
        let round = &mut keyed[start[r]..start[r + 1]];
        crate::parallel::sort_unstable(round);
        break_cell_ties(round, &points);
    }
    keyed.into_iter().map(|k| k as u32).collect()
}

/// The points `0..n` along the Hilbert curve over their bounding box, ties by coordinates
/// (lexicographic), then by index: a function of the point set alone, spatially coherent.
pub fn hilbert_order(points: impl Fn(u32) -> [f64; 2] + Sync + Send, n: usize) -> Vec<u32> {
    let Some(bbox) = bounding_box((0..n as u32).map(&points)) else { return Vec::new() };
    let mut keyed: Vec<u64> = crate::parallel::map_range(n, |i| {
        (u64::from(hilbert_key(points(i as u32), &bbox)) << 32) | i as u64
    });
    crate::parallel::sort_unstable(&mut keyed);
    break_cell_ties(&mut keyed, &points);
    keyed.into_iter().map(|k| k as u32).collect()
}

/// Inside each run of equal Hilbert keys, orders the points by coordinates, then index.
fn break_cell_ties(round: &mut [u64], points: &(impl Fn(u32) -> [f64; 2] + Sync + Send)) {
    let same_cell = |a: &u64, b: &u64| a >> 32 == b >> 32;
    crate::parallel::for_each_run(round, same_cell, |cell| {
        if cell.len() > 1 {
            cell.sort_unstable_by(|&j, &k| {
                lexicographic(points(j as u32), points(k as u32)).then(j.cmp(&k))
            });
        }
    });
}

/// Lexicographic order of coordinates, `-0.0` and `0.0` alike (they are the same point).
fn lexicographic(p: [f64; 2], q: [f64; 2]) -> Ordering {
    p[0].partial_cmp(&q[0])
        .unwrap_or(Ordering::Equal)
        .then(p[1].partial_cmp(&q[1]).unwrap_or(Ordering::Equal))
}

/// How many rounds `n` points take: the first holds about `n / 2^(rounds - 1)`, at least
/// [`MIN_ROUND`] expected.
fn round_count(n: usize) -> u8 {
    let mut rounds = 1;
    while n >> rounds >= MIN_ROUND && rounds < 32 {
        rounds += 1;
    }
    rounds
}

/// The round of a point, `0` the first: the last with probability 1/2, the one before with
/// 1/4, and so on, drawn from a hash of the coordinates (`-0.0` hashed as `0.0`).
fn round_of(p: [f64; 2], rounds: u8) -> u8 {
    let bits = |x: f64| (x + 0.0).to_bits();
    let hash = mix(mix(SEED ^ bits(p[0])) ^ bits(p[1]));
    let depth = (hash.trailing_zeros() as u8).min(rounds - 1);
    rounds - 1 - depth
}

/// SplitMix64's finaliser.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// BRIO with a fixed shuffle, the Hilbert grid laid over the bounding box of `extent` instead of
/// the points' own; points outside it (or not finite) are clamped to its border cells. CRUST
/// uses it to order Voronoi vertices on the samples' grid, unspoilt by far-away centres.
pub fn brio_order_within(
    points: impl Fn(u32) -> [f64; 2] + Sync + Send,
    indices: &mut [u32],
    extent: impl Iterator<Item = [f64; 2]>,
) {
    let Some(bbox) = bounding_box(extent) else {
        shuffle(indices, SEED ^ indices.len() as u64);
        return;
    };
    let mut keyed: Vec<u64> = crate::parallel::map_slice(indices, |&i| {
        (u64::from(hilbert_key(points(i), &bbox)) << 32) | u64::from(i)
    });
    sort_rounds(&mut keyed);
    for (slot, k) in indices.iter_mut().zip(&keyed) {
        *slot = *k as u32;
    }
}

/// Shuffles the `(key << 32) | index` values (the permutation depends on the length only),
/// then sorts each round, from the last (largest) to the first.
fn sort_rounds(keyed: &mut [u64]) {
    shuffle(keyed, SEED ^ keyed.len() as u64);
    let mut end = keyed.len();
    while end > 0 {
        let start = if end / 2 < MIN_ROUND { 0 } else { end / 2 };
        crate::parallel::sort_unstable(&mut keyed[start..end]);
        end = start;
    }
}

struct BoundingBox {
    min: [f64; 2],
    scale: [f64; 2],
}

fn bounding_box(mut pts: impl Iterator<Item = [f64; 2]>) -> Option<BoundingBox> {
    let first = pts.next()?;
    let (mut lo, mut hi) = (first, first);
    for p in pts {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    let cells = f64::from((1u32 << HILBERT_BITS) - 1);
    let scale = [0, 1].map(|a| {
        let extent = hi[a] - lo[a];
        if extent > 0.0 && extent.is_finite() {
            cells / extent
        } else {
            0.0
        }
    });
    Some(BoundingBox { min: lo, scale })
}

fn hilbert_key(p: [f64; 2], bbox: &BoundingBox) -> u32 {
    let max = (1u32 << HILBERT_BITS) - 1;
    let cell = |a: usize| (((p[a] - bbox.min[a]) * bbox.scale[a]) as u32).min(max);
    hilbert_index(cell(0), cell(1))
}

/// Position of cell `(x, y)` along the Hilbert curve over a 2^16 × 2^16 grid, four levels
/// (a nibble of `x` and of `y`) per step through [`HILBERT_STEPS`].
fn hilbert_index(x: u32, y: u32) -> u32 {
    let mut d = 0;
    let mut state = 0;
    for shift in [12, 8, 4, 0] {
        let nibbles = ((x >> shift) & 15) << 4 | ((y >> shift) & 15);
        let step = HILBERT_STEPS[state][nibbles as usize];
        d = d << 8 | u32::from(step & 0xff);
        state = usize::from(step >> 8);
    }
    d
}

/// `HILBERT_STEPS[state][x << 4 | y]` for nibbles `x`, `y`: the next eight bits of the index
/// (low byte) and the state after the four levels (high byte). A state is the transform the
/// curve has applied to the remaining levels so far: bit 0 swaps `x` and `y`, bit 1
/// complements both (they commute, so four states cover every composition).
static HILBERT_STEPS: [[u16; 256]; 4] = hilbert_steps();

const fn hilbert_steps() -> [[u16; 256]; 4] {
    let mut table = [[0u16; 256]; 4];
    let mut start = 0;
    while start < 4 {
        let mut nibbles = 0;
        while nibbles < 256 {
            let (mut state, mut digits) = (start, 0u16);
            let mut level = 4;
            while level > 0 {
                level -= 1;
                let (bx, by) = ((nibbles >> (4 + level)) & 1, (nibbles >> level) & 1);
                let (mut rx, mut ry) = if state & 1 == 1 { (by, bx) } else { (bx, by) };
                if state & 2 == 2 {
                    (rx, ry) = (rx ^ 1, ry ^ 1);
                }
                digits = digits << 2 | ((3 * rx) ^ ry) as u16;
                // The quadrant's transform: complement when rx = 1, then swap (ry = 0 only).
                if ry == 0 {
                    state ^= 1 | (rx << 1);
                }
            }
            table[start][nibbles] = (state as u16) << 8 | digits;
            nibbles += 1;
        }
        start += 1;
    }
    table
}

/// Fisher-Yates shuffle driven by SplitMix64.
fn shuffle<T>(items: &mut [T], seed: u64) {
    let mut state = seed;
    for i in (1..items.len()).rev() {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        let j = (z % (i as u64 + 1)) as usize;
        items.swap(i, j);
    }
}

/// Moves to the front of `order` the first three points in it that span a triangle: the
/// first point, the first point different from it, and the first point off the line through
/// both; the rest keep their order. `false` if all points are collinear (or fewer than three
/// are distinct).
///
/// Inserting these first matters: spade's insertion is quadratic while all its vertices are
/// collinear.
pub(super) fn put_first_triangle_first(order: &mut [u32], p: impl Fn(u32) -> Point) -> bool {
    let Some(&a) = order.first() else { return false };
    let Some(b) = (1..order.len()).find(|&k| p(order[k]) != p(a)) else { return false };
    let off_line = |&k: &usize| orient2d(p(a), p(order[b]), p(order[k])) != 0.0;
    let Some(c) = (b + 1..order.len()).find(off_line) else { return false };
    order[1..=b].rotate_right(1);
    order[2..=c].rotate_right(1);
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hilbert_visits_neighbouring_cells() {
        // On a 4 × 4 corner of the grid the first 16 keys form a connected walk.
        let mut cells: Vec<(u32, u32, u32)> =
            (0..4).flat_map(|x| (0..4).map(move |y| (hilbert_index(x, y), x, y))).collect();
        cells.sort();
        assert_eq!(cells[0].0, 0);
        for w in cells.windows(2) {
            assert_eq!(w[1].0, w[0].0 + 1);
            assert_eq!(w[0].1.abs_diff(w[1].1) + w[0].2.abs_diff(w[1].2), 1);
        }
    }

    /// The curve as its textbook definition computes it, one level at a time.
    fn hilbert_index_by_levels(mut x: u32, mut y: u32) -> u32 {
        let n = 1u32 << HILBERT_BITS;
        let (mut d, mut s) = (0, n / 2);
        while s > 0 {
            let (rx, ry) = (u32::from(x & s > 0), u32::from(y & s > 0));
            d += s * s * ((3 * rx) ^ ry);
            if ry == 0 {
                if rx == 1 {
                    (x, y) = (n - 1 - x, n - 1 - y);
                }
                std::mem::swap(&mut x, &mut y);
            }
            s /= 2;
        }
        d
    }

    #[test]
    fn hilbert_steps_agree_with_the_level_by_level_curve() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut cells: Vec<(u32, u32)> =
            (0..256).flat_map(|x| (0..256).map(move |y| (x, y))).collect();
        for _ in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            cells.push((state as u32 & 0xffff, (state >> 32) as u32 & 0xffff));
        }
        cells.extend([(0xffff, 0), (0, 0xffff), (0xffff, 0xffff), (0x8000, 0x7fff)]);
        for (x, y) in cells {
            assert_eq!(hilbert_index(x, y), hilbert_index_by_levels(x, y), "cell ({x}, {y})");
        }
    }

    #[test]
    fn order_is_a_permutation_that_depends_on_the_points_alone() {
        let pts: Vec<[f64; 2]> =
            (0..1000).map(|i| [(i as f64).sin(), (i as f64 * 0.7).cos()]).collect();
        let order = canonical_order(|i| pts[i as usize], pts.len());
        let mut sorted = order.clone();
        sorted.sort();
        assert_eq!(sorted, (0..1000).collect::<Vec<u32>>());
        // Reversed input: the same points in the same order.
        let reversed: Vec<[f64; 2]> = pts.iter().rev().copied().collect();
        let again = canonical_order(|i| reversed[i as usize], pts.len());
        let positions = |o: &[u32], p: &[[f64; 2]]| -> Vec<[f64; 2]> {
            o.iter().map(|&i| p[i as usize]).collect()
        };
        assert_eq!(positions(&order, &pts), positions(&again, &reversed));
    }

    #[test]
    fn rounds_double() {
        assert_eq!(round_count(100), 1);
        assert_eq!(round_count(128), 2);
        assert_eq!(round_count(1 << 20), 15);
        let rounds = round_count(1 << 16);
        let mut sizes = vec![0usize; usize::from(rounds)];
        for i in 0..1 << 16 {
            sizes[usize::from(round_of([f64::from(i), 0.5], rounds))] += 1;
        }
        // The last round holds about half the points, the one before a quarter.
        let n = f64::from(1 << 16);
        let last = sizes[sizes.len() - 1] as f64 / n;
        let before = sizes[sizes.len() - 2] as f64 / n;
        assert!((last - 0.5).abs() < 0.02 && (before - 0.25).abs() < 0.02, "{sizes:?}");
    }
}
