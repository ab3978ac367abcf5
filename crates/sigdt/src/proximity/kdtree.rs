//! A static 2-d tree for k-nearest-neighbour and radius queries (Bentley 1975).
//!
//! Built once by median splits into an implicit layout (the median of each range is its
//! node), so it needs only an index array and one split axis per node. Each range is split
//! along the axis on which its points spread most.
//!
//! Departure from alternating axes: on points along a horizontal or vertical line, an
//! alternating tree splits half its levels on a coordinate all points share. Such a split
//! separates nothing, every query descends both sides, and a query costs O(√n) instead of
//! O(log n) (HNN-CRUST became quadratic on points along a line plus one point off it).
//!
//! # Complexity
//! Build O(n log n); a query visits O(log n + output) nodes on well-spread data.
use crate::geometry::Point;

/// A 2-d tree over points `0..n` of a slice.
pub struct KdTree<'a> {
    points: &'a [Point],
    order: Vec<u32>,
    /// The split axis of the node at each position of `order`.
    axes: Vec<u8>,
}

impl<'a> KdTree<'a> {
    /// Builds the tree over all of `points`.
    pub fn new(points: &'a [Point]) -> KdTree<'a> {
        let mut order: Vec<u32> = (0..points.len() as u32).collect();
        let mut axes = vec![0; points.len()];
        build(points, &mut order, &mut axes);
        KdTree { points, order, axes }
    }

    /// The `k` points nearest to `q` other than `exclude`, nearest first, as
    /// `(squared distance, index)`; ties by index.
    pub fn nearest(&self, q: Point, k: usize, exclude: u32) -> Vec<(f64, u32)> {
        let mut best: Vec<(f64, u32)> = Vec::with_capacity(k + 1);
        if k > 0 {
            self.knn(0, self.order.len(), q, k, exclude, &mut best);
        }
        best
    }

    /// Every point within distance `radius` of `q` (inclusive), unordered.
    pub fn within(&self, q: Point, radius: f64, out: &mut Vec<u32>) {
        self.range(0, self.order.len(), q, radius * radius, out);
    }

    fn knn(
        &self,
        lo: usize,
        hi: usize,
        q: Point,
        k: usize,
        exclude: u32,
        best: &mut Vec<(f64, u32)>,
    ) {
        if lo >= hi {
            return;
        }
        let mid = lo + (hi - lo) / 2;
        let (i, axis) = (self.order[mid], usize::from(self.axes[mid]));
        let p = self.points[i as usize];
        if i != exclude {
            let d = sq(p, q);
            let candidate = (d, i);
            if best.len() < k || cmp(candidate, best[best.len() - 1]).is_lt() {
                let at = best.partition_point(|&b| cmp(b, candidate).is_lt());
                best.insert(at, candidate);
                best.truncate(k);
            }
        }
        let delta = q[axis] - p[axis];
        let (near, far) =
            if delta <= 0.0 { ((lo, mid), (mid + 1, hi)) } else { ((mid + 1, hi), (lo, mid)) };
        self.knn(near.0, near.1, q, k, exclude, best);
        if best.len() < k || delta * delta <= best[best.len() - 1].0 {
            self.knn(far.0, far.1, q, k, exclude, best);
        }
    }

    fn range(&self, lo: usize, hi: usize, q: Point, r2: f64, out: &mut Vec<u32>) {
        if lo >= hi {
            return;
        }
        let mid = lo + (hi - lo) / 2;
        let (i, axis) = (self.order[mid], usize::from(self.axes[mid]));
        let p = self.points[i as usize];
        if sq(p, q) <= r2 {
            out.push(i);
        }
        let delta = q[axis] - p[axis];
        if delta <= 0.0 || delta * delta <= r2 {
            self.range(lo, mid, q, r2, out);
        }
        if delta >= 0.0 || delta * delta <= r2 {
            self.range(mid + 1, hi, q, r2, out);
        }
    }
}

/// Splits `order` at its median along the axis of widest spread, recording the axis in
/// `axes` (the same positions as `order`), then splits both halves.
fn build(points: &[Point], order: &mut [u32], axes: &mut [u8]) {
    if order.is_empty() {
        return;
    }
    let spread = |axis: usize| {
        let (lo, hi) = order.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &i| {
            let c = points[i as usize][axis];
            (lo.min(c), hi.max(c))
        });
        hi - lo
    };
    let axis = usize::from(spread(1) > spread(0));
    let mid = order.len() / 2;
    axes[mid] = axis as u8;
    order.select_nth_unstable_by(mid, |&a, &b| {
        points[a as usize][axis].total_cmp(&points[b as usize][axis])
    });
    let (left, right) = order.split_at_mut(mid);
    let (left_axes, right_axes) = axes.split_at_mut(mid);
    build(points, left, left_axes);
    build(points, &mut right[1..], &mut right_axes[1..]);
}

#[inline]
fn sq(p: Point, q: Point) -> f64 {
    let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
    dx * dx + dy * dy
}

fn cmp(a: (f64, u32), b: (f64, u32)) -> std::cmp::Ordering {
    a.0.total_cmp(&b.0).then(a.1.cmp(&b.1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_brute_force() {
        let pts: Vec<Point> =
            (0..500).map(|i| [((i * 37) % 101) as f64, ((i * 91) % 103) as f64 * 0.5]).collect();
        let tree = KdTree::new(&pts);
        for qi in [0u32, 17, 250, 499] {
            let q = pts[qi as usize];
            let mut brute: Vec<(f64, u32)> =
                (0..500u32).filter(|&j| j != qi).map(|j| (sq(pts[j as usize], q), j)).collect();
            brute.sort_by(|a, b| cmp(*a, *b));
            assert_eq!(tree.nearest(q, 5, qi), brute[..5].to_vec());
            let mut got = Vec::new();
            tree.within(q, 10.0, &mut got);
            got.sort();
            let mut want: Vec<u32> =
                (0..500u32).filter(|&j| sq(pts[j as usize], q) <= 100.0).collect();
            want.sort();
            assert_eq!(got, want);
        }
    }
}
