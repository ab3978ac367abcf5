//! How far a case's labelled samples stray from its true curve: `d_max`, the largest distance
//! from a point on some ground-truth edge to the curve's segments. It is 0 (up to rounding) on
//! clean data and the noise's reach on noisy data, so the Hausdorff bound of a good result
//! ([`CurveScore::good`](super::record::CurveScore::good)) forgives what the input points
//! themselves stray, and no more.
//!
//! # Complexity
//! A uniform grid over the curve's segments, each cut into pieces no longer than a cell: at
//! most about `2√m` cells a side and `17 m` listed pieces for `m` segments. A query visits
//! square rings of cells around its point until the next ring lies beyond the best distance
//! found: O(1) cells for a sample near an evenly sampled curve, O(m) at worst. So O(n + m)
//! for `n` samples near a dense curve, against O(n m) by brute force.
use sigdt::{Edge, Point};

/// The largest distance from a point of `points` on some edge of `gt` (a self loop is no
/// edge) to the polyline `curve` (its points and edges); 0 without such a point, infinite
/// when the curve has no edge.
pub fn stray(points: &[Point], gt: &[Edge], curve: (&[Point], &[Edge])) -> f64 {
    let (curve_points, curve_edges) = curve;
    let grid = Grid::new(curve_edges.iter().map(|&[i, j]| [curve_points[i], curve_points[j]]));
    let mut labelled = vec![false; points.len()];
    for &[i, j] in gt.iter().filter(|[i, j]| i != j) {
        (labelled[i], labelled[j]) = (true, true);
    }
    let samples = points.iter().zip(labelled).filter_map(|(&p, on)| on.then_some(p));
    samples.fold(0.0, |worst: f64, q| worst.max(grid.nearest(q, worst)))
}

/// The pieces of a polyline's segments, listed per cell of a uniform grid (CSR layout).
struct Grid {
    segments: Vec<[Point; 2]>,
    origin: Point,
    cell: f64,
    size: [i64; 2],
    start: Vec<usize>,
    items: Vec<usize>,
}

/// The most pieces a segment is cut into on average: bounds the memory when the segments are
/// long against the box.
const PIECES_PER_SEGMENT: f64 = 16.0;

impl Grid {
    fn new(segments: impl Iterator<Item = [Point; 2]>) -> Grid {
        let segments: Vec<[Point; 2]> = segments.collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in segments.iter().flatten() {
            (lo, hi) = ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])]);
        }
        let m = segments.len().max(1) as f64;
        let (w, h) = ((hi[0] - lo[0]).max(0.0), (hi[1] - lo[1]).max(0.0));
        let total: f64 = segments.iter().map(|&[p, q]| distance(p, q)).sum();
        // About one cell per segment over the box, at least 2√m + 1 cells a side at most,
        // and large enough that the pieces stay few.
        let mut cell = (w.sqrt() * h.sqrt() / m.sqrt())
            .max(w.max(h) / (2.0 * m.sqrt()))
            .max(total / (PIECES_PER_SEGMENT * m));
        if !(cell.is_finite() && cell > 0.0) {
            cell = 1.0;
        }
        let count = |extent: f64| (extent / cell).min(4096.0) as i64 + 1;
        let size = [count(w), count(h)];
        let mut grid =
            Grid { segments, origin: lo, cell, size, start: Vec::new(), items: Vec::new() };
        if grid.segments.is_empty() {
            return grid;
        }
        let mut pairs: Vec<(usize, usize)> = Vec::new();
        for (s, &[p, q]) in grid.segments.iter().enumerate() {
            let pieces = (distance(p, q) / cell).ceil().clamp(1.0, 8192.0) as usize;
            let at = |k: usize| {
                let t = k as f64 / pieces as f64;
                [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
            };
            for k in 0..pieces {
                let (a, b) = (at(k), at(k + 1));
                let [x0, y0] = grid.cell_of([a[0].min(b[0]), a[1].min(b[1])]);
                let [x1, y1] = grid.cell_of([a[0].max(b[0]), a[1].max(b[1])]);
                for y in y0..=y1 {
                    pairs.extend((x0..=x1).map(|x| ((y * size[0] + x) as usize, s)));
                }
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        let cells = (size[0] * size[1]) as usize;
        grid.start = vec![0; cells + 1];
        for &(c, _) in &pairs {
            grid.start[c + 1] += 1;
        }
        for c in 0..cells {
            grid.start[c + 1] += grid.start[c];
        }
        grid.items = pairs.into_iter().map(|(_, s)| s).collect();
        grid
    }

    /// The distance from `q` to the nearest segment, or a value at most `enough` once one is
    /// found that near (the caller's maximum cannot grow then); infinite without segments.
    fn nearest(&self, q: Point, enough: f64) -> f64 {
        let mut best = f64::INFINITY;
        if self.segments.is_empty() {
            return best;
        }
        let (fx, fy) = ((q[0] - self.origin[0]) / self.cell, (q[1] - self.origin[1]) / self.cell);
        if !(fx.is_finite() && fy.is_finite()) {
            return best;
        }
        let (cx, cy) = (fx.floor().clamp(-1e15, 1e15) as i64, fy.floor().clamp(-1e15, 1e15) as i64);
        let [nx, ny] = self.size;
        // The rings of cells around q's cell that meet the grid; ring r lies at least
        // (r - 1) cells from q.
        let first = (cx - (nx - 1)).max(-cx).max(cy - (ny - 1)).max(-cy).max(0);
        let last = cx.max(nx - 1 - cx).max(cy).max(ny - 1 - cy);
        for r in first..=last {
            if (r - 1) as f64 * self.cell > best || best <= enough {
                break;
            }
            for y in (cy - r).max(0)..=(cy + r).min(ny - 1) {
                let edge_row = y == cy - r || y == cy + r;
                let xs: Vec<i64> = if edge_row {
                    ((cx - r).max(0)..=(cx + r).min(nx - 1)).collect()
                } else {
                    [cx - r, cx + r].into_iter().filter(|x| (0..nx).contains(x)).collect()
                };
                for x in xs {
                    let c = (y * nx + x) as usize;
                    for &s in &self.items[self.start[c]..self.start[c + 1]] {
                        let [a, b] = self.segments[s];
                        best = best.min(point_segment_distance(q, a, b));
                    }
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

/// The distance from `q` to the closed segment `ab`.
fn point_segment_distance(q: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    distance(q, [a[0] + t * dx, a[1] + t * dy])
}

fn distance(p: Point, q: Point) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A regular `n`-gon of radius `r` as points and a closed ring of edges.
    fn ring(n: usize, r: f64) -> (Vec<Point>, Vec<Edge>) {
        let points = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        let mut edges: Vec<Edge> = (1..n).map(|k| [k - 1, k]).collect();
        edges.push([0, n - 1]);
        (points, edges)
    }

    #[test]
    fn samples_on_the_curve_stray_nothing_and_outliers_do_not_count() {
        // The unit square as curve; its corners and mid-sides as samples, one of them moved
        // 0.25 out; an outlier far away without edges, a self loop that is no edge.
        let square = (
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            vec![[0, 1], [1, 2], [2, 3], [0, 3]],
        );
        let curve = (&square.0[..], &square.1[..]);
        let mut points =
            vec![[0.0, 0.0], [0.5, 0.0], [1.0, 0.0], [1.0, 0.5], [1.0, 1.0], [9.0, 9.0]];
        let gt = [[0, 1], [1, 2], [2, 3], [3, 4], [5, 5]];
        assert_eq!(stray(&points, &gt, curve), 0.0);
        points[3] = [1.25, 0.5];
        assert_eq!(stray(&points, &gt, curve), 0.25);
        assert_eq!(stray(&points, &[], curve), 0.0, "no labelled sample");
        assert_eq!(stray(&points, &gt, (&square.0, &[])), f64::INFINITY, "no curve");
    }

    #[test]
    fn the_grid_matches_brute_force() {
        // Noisy samples of a circle against the dense circle and a few long chords.
        let (mut curve, mut edges) = ring(700, 10.0);
        curve.extend([[-30.0, -2.0], [40.0, 3.0]]);
        edges.push([700, 701]);
        let mut seed = 11u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let (mut points, gt) = ring(300, 10.0);
        for p in &mut points {
            (p[0], p[1]) = (p[0] + next(), p[1] + next());
        }
        points[17] = [25.0, -14.0];
        let brute = points
            .iter()
            .map(|&q| {
                let d = |&[i, j]: &Edge| point_segment_distance(q, curve[i], curve[j]);
                edges.iter().map(d).fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max);
        assert_eq!(stray(&points, &gt, (&curve, &edges)), brute);
        let grid = Grid::new(edges.iter().map(|&[i, j]| [curve[i], curve[j]]));
        for &q in &points {
            let d = |&[i, j]: &Edge| point_segment_distance(q, curve[i], curve[j]);
            assert_eq!(grid.nearest(q, 0.0), edges.iter().map(d).fold(f64::INFINITY, f64::min));
        }
    }
}
