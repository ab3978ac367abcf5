//! A uniform grid over line segments for nearest-segment queries.
//!
//! Each segment is cut into pieces no longer than a cell and listed in every cell its pieces'
//! bounding boxes touch, in a compressed (CSR) layout. A query visits square rings of cells
//! around the query point, nearest ring first, and stops once the next ring cannot hold
//! anything closer than the caller's current bound. The cell side is that of about four cells
//! per segment over the box (at most `2√m + 1` cells a side), enlarged so that the segments
//! are cut into at most about 16 pieces each on average.
//!
//! # Complexity
//! Build O(m log m) for `m` segments (at most about `17 m` pieces). A query costs O(r² + k)
//! for `r` rings and `k` listed segments visited: O(1) on curves sampled about evenly when
//! the bound is a few segment lengths, the segments crossing a few cells among long random
//! segments, and O(m) at worst (every cell once).
use sigdt::Point;

/// The most pieces a segment is cut into on average: bounds the build's memory when the
/// segments are long against the box.
const PIECES_PER_SEGMENT: f64 = 16.0;

/// Segments `[p, q]` (a point is the segment `[p, p]`) bucketed into a uniform grid.
pub(crate) struct SegmentGrid {
    segments: Vec<[Point; 2]>,
    origin: Point,
    cell: f64,
    size: [i64; 2],
    start: Vec<u32>,
    items: Vec<u32>,
}

impl SegmentGrid {
    /// Builds the grid over `segments`, whose coordinates must be finite.
    pub(crate) fn new(segments: Vec<[Point; 2]>) -> SegmentGrid {
        let (lo, hi) = bbox(&segments);
        let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
        let m = segments.len().max(1) as f64;
        let total: f64 = segments.iter().map(|s| dist(s[0], s[1])).sum();
        // sqrt(w h / 4m) with the square roots first, so it cannot overflow for finite
        // extents (coordinates beyond ~1e154 made `w * h` infinite, the cell fell back to 1
        // and the cell count overflowed). The cell is at least max(w, h) / (2 √m), so there
        // are at most 2 √m + 1 cells a side and a query never walks more than O(m) cells
        // (with a fixed lower bound of max(w, h) / 4096, a few segments far apart made
        // every query walk millions of empty cells: fuzzing finding 4). The cell is infinite
        // only when the extents or the total length overflow, and then one cell holds
        // everything. It is not tied to the mean segment length: long crossing segments (a
        // random polygon) made cells as wide as the box, and every query read every segment.
        let area = w.sqrt() * h.sqrt() / (2.0 * m.sqrt());
        let mut cell =
            (total / (PIECES_PER_SEGMENT * m)).max(area).max(w.max(h) / (2.0 * m.sqrt()));
        if cell.is_nan() || cell <= 0.0 {
            cell = 1.0;
        }
        let count = |extent: f64| (extent / cell).min(4096.0) as i64 + 1;
        let size = [count(w), count(h)];
        let mut grid =
            SegmentGrid { segments, origin: lo, cell, size, start: Vec::new(), items: Vec::new() };
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        for (s, &[p, q]) in grid.segments.iter().enumerate() {
            let pieces = (dist(p, q) / cell).ceil().clamp(1.0, 8192.0) as usize;
            for k in 0..pieces {
                let (a, b) = (
                    lerp(p, q, k as f64 / pieces as f64),
                    lerp(p, q, (k + 1) as f64 / pieces as f64),
                );
                let [x0, y0] = grid.cell_of([a[0].min(b[0]), a[1].min(b[1])]);
                let [x1, y1] = grid.cell_of([a[0].max(b[0]), a[1].max(b[1])]);
                for y in y0..=y1 {
                    for x in x0..=x1 {
                        pairs.push(((y * size[0] + x) as u32, s as u32));
                    }
                }
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        let cells = (size[0] * size[1]) as usize;
        grid.start = vec![0; cells + 1];
        for &(c, _) in &pairs {
            grid.start[c as usize + 1] += 1;
        }
        for c in 0..cells {
            grid.start[c + 1] += grid.start[c];
        }
        grid.items = pairs.into_iter().map(|(_, s)| s).collect();
        grid
    }

    /// Distance from `q` to the nearest segment, or infinity if there is none. Visits
    /// square rings of cells around `q` until the next ring lies beyond the best distance.
    pub(crate) fn nearest_distance(&self, q: Point) -> f64 {
        let mut best = f64::INFINITY;
        let fx = (q[0] - self.origin[0]) / self.cell;
        let fy = (q[1] - self.origin[1]) / self.cell;
        if !(fx.is_finite() && fy.is_finite()) {
            return best;
        }
        let (cx, cy) = (fx.floor().clamp(-1e15, 1e15) as i64, fy.floor().clamp(-1e15, 1e15) as i64);
        // Distance from q to the sides of its own cell, in cells.
        let inner = (fx - cx as f64)
            .min(1.0 - (fx - cx as f64))
            .min(fy - cy as f64)
            .min(1.0 - (fy - cy as f64));
        let [nx, ny] = self.size;
        let first = (cx - (nx - 1)).max(-cx).max(cy - (ny - 1)).max(-cy).max(0);
        let last = (cx).max(nx - 1 - cx).max(cy).max(ny - 1 - cy);
        for r in first..=last {
            let reach = if r == 0 { 0.0 } else { ((r - 1) as f64 + inner) * self.cell };
            if reach > best {
                return best;
            }
            for y in (cy - r).max(0)..=(cy + r).min(ny - 1) {
                let (x0, x1) = ((cx - r).max(0), (cx + r).min(nx - 1));
                let row = y == cy - r || y == cy + r;
                let mut x = if row { x0 } else { cx - r };
                while x <= x1 {
                    if x >= x0 {
                        let c = (y * nx + x) as usize;
                        for &s in &self.items[self.start[c] as usize..self.start[c + 1] as usize] {
                            let [a, b] = self.segments[s as usize];
                            best = best.min(point_segment_distance(q, a, b));
                        }
                    }
                    x = if row || x == cx + r { x + 1 } else { cx + r };
                }
            }
        }
        best
    }

    fn cell_of(&self, p: Point) -> [i64; 2] {
        let f = |v: f64, o: f64, n: i64| (((v - o) / self.cell) as i64).clamp(0, n - 1);
        [f(p[0], self.origin[0], self.size[0]), f(p[1], self.origin[1], self.size[1])]
    }
}

/// Euclidean distance from `q` to the closed segment `ab`.
pub(crate) fn point_segment_distance(q: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(q, [a[0] + t * dx, a[1] + t * dy])
}

/// The point `(1 - t) p + t q`.
pub(crate) fn lerp(p: Point, q: Point, t: f64) -> Point {
    [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
}

fn dist(p: Point, q: Point) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

fn bbox(segments: &[[Point; 2]]) -> (Point, Point) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in segments.iter().flatten() {
        lo = [lo[0].min(p[0]), lo[1].min(p[1])];
        hi = [hi[0].max(p[0]), hi[1].max(p[1])];
    }
    if segments.is_empty() {
        ([0.0; 2], [0.0; 2])
    } else {
        (lo, hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_matches_brute_force() {
        let segs: Vec<[Point; 2]> = (0..50)
            .map(|i| {
                let a = i as f64 * 0.37;
                [[a.cos() * i as f64, a.sin()], [a.sin() * 3.0, (a * 1.7).cos() * i as f64]]
            })
            .collect();
        let grid = SegmentGrid::new(segs.clone());
        for k in 0..200 {
            let q = [(k as f64 * 0.71).sin() * 80.0, (k as f64 * 1.3).cos() * 70.0];
            let brute = segs
                .iter()
                .map(|s| point_segment_distance(q, s[0], s[1]))
                .fold(f64::INFINITY, f64::min);
            assert_eq!(grid.nearest_distance(q), brute);
        }
        assert_eq!(SegmentGrid::new(Vec::new()).nearest_distance([1.0, 2.0]), f64::INFINITY);
        assert_eq!(SegmentGrid::new(vec![[[1.0, 1.0]; 2]]).nearest_distance([4.0, 5.0]), 5.0);
    }

    #[test]
    fn long_crossing_segments_spread_over_many_cells() {
        // A random polygon of 2000 vertices in the unit square: segments half as long as
        // the box. Cells as wide as twice the mean length held every segment in one cell.
        let mut seed = 7u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let vertices: Vec<Point> = (0..2000).map(|_| [next(), next()]).collect();
        let segs: Vec<[Point; 2]> =
            (0..2000).map(|i| [vertices[i], vertices[(i + 1) % 2000]]).collect();
        let grid = SegmentGrid::new(segs);
        let fullest = grid.start.windows(2).map(|w| w[1] - w[0]).max().unwrap();
        assert!(fullest < 400, "a cell lists {fullest} of 2000 segments");
    }
}
