//! Input decoding shared by the fuzz targets: fuzzer bytes to point sets and edge lists.
//!
//! The first byte picks the mode. Even: **raw**, every 16 bytes are the bits of one point
//! (two little-endian `f64`), so NaN, ±inf, subnormals and huge values all occur. Odd:
//! **structured**, a tiny program whose instructions build degenerate sets from a few bytes:
//! duplicates of earlier points, points on a line through two earlier points, exactly and
//! nearly cocircular points, collinear runs, grids, one-ulp perturbations, and a scale and
//! offset (huge, tiny, subnormal, `1e9`) applied to every point that follows.
//!
//! Every decoder stops at [`MAX_POINTS`] points so that executions stay fast.

/// The largest number of points a decoder returns.
pub const MAX_POINTS: usize = 256;

/// A point, as in `sigdt`.
pub type Point = [f64; 2];
/// An edge between point indices, as in `sigdt` (here not necessarily `i < j`).
pub type Edge = [usize; 2];

/// Scales the structured mode can switch to (`Scale` instruction).
const SCALES: [f64; 12] =
    [1.0, 1e300, 1e-300, 4.9e-324, 1e-310, 1e9, 1e-9, 0.1, 3.0, 1e154, 1e-154, 2e307];
/// Offsets the structured mode can switch to (`Offset` instruction).
const OFFSETS: [f64; 8] = [0.0, 1e9, -1e9, 1e15, 0.5, 1e300, -1e-300, 1e17];
/// Integer points on circles around the origin: every sign and swap of these lies on the
/// circle of radius 5, 13, 25, 65 (exactly cocircular sets).
const TRIPLES: [(i32, i32, i32); 6] =
    [(3, 4, 5), (5, 12, 13), (7, 24, 25), (15, 20, 25), (16, 63, 65), (33, 56, 65)];

/// A cursor over the fuzzer's bytes; reading past the end gives zeros.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    fn u8(&mut self) -> u8 {
        let (&b, rest) = self.0.split_first().unwrap_or((&0, &[]));
        self.0 = rest;
        b
    }

    fn i8(&mut self) -> f64 {
        f64::from(self.u8() as i8)
    }

    fn f64(&mut self) -> f64 {
        let mut b = [0u8; 8];
        for x in &mut b {
            *x = self.u8();
        }
        f64::from_le_bytes(b)
    }
}

/// The points encoded by `data` (see the module docs), at most [`MAX_POINTS`].
pub fn points(data: &[u8]) -> Vec<Point> {
    match data.split_first() {
        None => Vec::new(),
        Some((mode, rest)) if mode % 2 == 0 => raw(rest),
        Some((_, rest)) => structured(rest),
    }
}

/// Every 16 bytes are one point's raw bits.
pub fn raw(data: &[u8]) -> Vec<Point> {
    data.chunks_exact(16)
        .take(MAX_POINTS)
        .map(|c| {
            let x = f64::from_le_bytes(c[..8].try_into().unwrap());
            let y = f64::from_le_bytes(c[8..].try_into().unwrap());
            [x, y]
        })
        .collect()
}

/// Runs the point-building program in `data`.
pub fn structured(data: &[u8]) -> Vec<Point> {
    let mut b = Bytes(data);
    let mut pts: Vec<Point> = Vec::new();
    let (mut scale, mut offset) = (1.0, 0.0);
    let at = |x: f64, y: f64, scale: f64, offset: f64| [x * scale + offset, y * scale + offset];
    while !b.is_empty() && pts.len() < MAX_POINTS {
        let op = b.u8();
        let pick = |b: &mut Bytes, pts: &[Point]| match pts.len() {
            0 => [0.0, 0.0],
            n => pts[b.u8() as usize % n],
        };
        match op % 12 {
            // A point with small integer coordinates.
            0 | 1 => {
                let (x, y) = (b.i8(), b.i8());
                pts.push(at(x, y, scale, offset));
            }
            // An exact duplicate of an earlier point.
            2 => {
                let p = pick(&mut b, &pts);
                pts.push(p);
            }
            // A point on the line through two earlier points: p + t (q - p), t = k / 4.
            3 => {
                let (p, q) = (pick(&mut b, &pts), pick(&mut b, &pts));
                let t = b.i8() / 4.0;
                pts.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
            }
            // A collinear run of k points from p to q (evenly spaced in floating point).
            4 => {
                let (p, q) = (pick(&mut b, &pts), pick(&mut b, &pts));
                let k = 2 + b.u8() as usize % 16;
                for s in 0..=k {
                    let t = s as f64 / k as f64;
                    pts.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
                }
            }
            // Exactly cocircular integer points: a Pythagorean triple, signed and swapped.
            5 => {
                let (x, y, _) = TRIPLES[b.u8() as usize % TRIPLES.len()];
                let s = b.u8();
                let (x, y) = if s & 4 == 0 { (x, y) } else { (y, x) };
                let x = if s & 1 == 0 { x } else { -x };
                let y = if s & 2 == 0 { y } else { -y };
                pts.push(at(f64::from(x), f64::from(y), scale, offset));
            }
            // A nearly cocircular regular polygon (cos / sin round), 3 to 34 vertices.
            6 => {
                let c = pick(&mut b, &pts);
                let n = 3 + b.u8() as usize % 32;
                let r = (1.0 + f64::from(b.u8())) * scale;
                for k in 0..n {
                    let a = k as f64 * std::f64::consts::TAU / n as f64;
                    pts.push([c[0] + r * a.cos(), c[1] + r * a.sin()]);
                }
            }
            // A point given by its raw bits.
            7 => {
                let (x, y) = (b.f64(), b.f64());
                pts.push([x, y]);
            }
            // An earlier point moved by one ulp in x and/or y.
            8 => {
                let p = pick(&mut b, &pts);
                let s = b.u8();
                let step = |v: f64, up: bool| if up { v.next_up() } else { v.next_down() };
                let x = if s & 1 == 0 { p[0] } else { step(p[0], s & 2 == 0) };
                let y = if s & 4 == 0 { p[1] } else { step(p[1], s & 8 == 0) };
                pts.push([x, y]);
            }
            // A w x h grid (collinear rows, columns and diagonals; cocircular squares).
            9 => {
                let (w, h) = (1 + b.u8() as usize % 8, 1 + b.u8() as usize % 8);
                for i in 0..w {
                    for j in 0..h {
                        pts.push(at(i as f64, j as f64, scale, offset));
                    }
                }
            }
            10 => scale = SCALES[b.u8() as usize % SCALES.len()],
            _ => offset = OFFSETS[b.u8() as usize % OFFSETS.len()],
        }
    }
    pts.truncate(MAX_POINTS);
    pts
}

/// Edges `[i, j]` read from pairs of bytes; indices run up to `n + 1`, so some are out of
/// range, and some are self loops or repeated.
pub fn edges(data: &[u8], n: usize) -> Vec<Edge> {
    data.chunks_exact(2).map(|c| [c[0] as usize % (n + 2), c[1] as usize % (n + 2)]).collect()
}

/// The `eval` target's input: `[split][edge bytes (2 · split)][points]`, at most 32 points,
/// and the edges halved into result and ground truth; `None` for empty input.
pub fn eval_input(data: &[u8]) -> Option<(Vec<Point>, Vec<Edge>, Vec<Edge>)> {
    let (&split, rest) = data.split_first()?;
    let (edge_bytes, point_bytes) = rest.split_at((split as usize * 2).min(rest.len()));
    let mut points = points(point_bytes);
    points.truncate(32);
    let mut result = edges(edge_bytes, points.len());
    let gt = result.split_off(result.len() / 2);
    Some((points, result, gt))
}

/// Panics unless `edges` are `[i, j]` with `i < j < n`, sorted and unique.
pub fn assert_edge_list(what: &str, edges: &[Edge], n: usize) {
    for &[i, j] in edges {
        assert!(i < j && j < n, "{what}: edge [{i}, {j}] is not i < j < {n}");
    }
    for w in edges.windows(2) {
        assert!(w[0] < w[1], "{what}: edges not sorted and unique at {:?}, {:?}", w[0], w[1]);
    }
}
