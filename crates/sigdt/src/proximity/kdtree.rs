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
//! Queries prune a subtree by the distance from the query to its cell (the rectangle its
//! splits bound), kept as one offset per axis (Arya and Mount 1993), not by the distance to
//! the one split line: far from a tight cluster, as from the medial points of a circle, the
//! split lines pass close to the query's axes while the cells stay far, and pruning by the
//! line alone visited every node (quadratic ε-sampling of circles). The cell distance is the
//! sum of the squared offsets, each a rounded coordinate difference no larger than the
//! point's own, so it never exceeds a point's computed squared distance: a subtree is
//! skipped only when none of its points could tie or win, and results are those of a full
//! scan, ties by index.
//!
//! # Complexity
//! Build O(n log n); a query visits O(log n + output) nodes on well-spread data, and
//! O(√n) on a tight cluster seen from afar.
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
            self.knn(0, self.order.len(), q, [0.0; 2], k, exclude, &mut best);
        }
        best
    }

    /// Every point within distance `radius` of `q` (inclusive), unordered.
    pub fn within(&self, q: Point, radius: f64, out: &mut Vec<u32>) {
        self.range(0, self.order.len(), q, [0.0; 2], radius * radius, out);
    }

    /// The k-nearest search in `order[lo..hi]`, whose cell is `offsets` away from `q` along
    /// each axis.
    #[allow(clippy::too_many_arguments)]
    fn knn(
        &self,
        lo: usize,
        hi: usize,
        q: Point,
        offsets: [f64; 2],
        k: usize,
        exclude: u32,
        best: &mut Vec<(f64, u32)>,
    ) {
        if lo >= hi {
            return;
        }
        #[cfg(test)]
        tests::VISITS.with(|v| v.set(v.get() + 1));
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
        self.knn(near.0, near.1, q, offsets, k, exclude, best);
        let far_offsets = beyond(offsets, axis, delta);
        if best.len() < k || cell_distance(far_offsets) <= best[best.len() - 1].0 {
            self.knn(far.0, far.1, q, far_offsets, k, exclude, best);
        }
    }

    /// The points of `order[lo..hi]` within squared distance `r2` of `q`; the range's cell is
    /// `offsets` away from `q` along each axis.
    fn range(
        &self,
        lo: usize,
        hi: usize,
        q: Point,
        offsets: [f64; 2],
        r2: f64,
        out: &mut Vec<u32>,
    ) {
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
        let far = beyond(offsets, axis, delta);
        let (low, high) = if delta <= 0.0 { (offsets, far) } else { (far, offsets) };
        if delta <= 0.0 || cell_distance(low) <= r2 {
            self.range(lo, mid, q, low, r2, out);
        }
        if delta >= 0.0 || cell_distance(high) <= r2 {
            self.range(mid + 1, hi, q, high, r2, out);
        }
    }
}

/// The offsets of the cell beyond a split at `delta` from the query along `axis`: that axis's
/// offset becomes the distance to the split line (the nearer bounds the cell had along it lie
/// on the query's side).
#[inline]
fn beyond(mut offsets: [f64; 2], axis: usize, delta: f64) -> [f64; 2] {
    offsets[axis] = delta.abs();
    offsets
}

/// Squared distance from the query to a cell with these offsets.
#[inline]
fn cell_distance([dx, dy]: [f64; 2]) -> f64 {
    dx * dx + dy * dy
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
    use std::cell::Cell;

    thread_local! {
        /// Nodes visited by k-nearest searches on this thread.
        pub(super) static VISITS: Cell<usize> = const { Cell::new(0) };
    }

    /// The medial points of a circle drawn with cubics crowd within 10⁻⁹ of its centre;
    /// seen from the circle, every split line of such a cluster passes near the query's
    /// axes. Pruning by the split line alone visited all 4096 nodes per query; by the cell,
    /// a few dozen.
    #[test]
    fn a_tight_cluster_seen_from_afar_is_searched_in_few_nodes() {
        let n = 4096;
        let cluster: Vec<Point> = (0..n)
            .map(|i| {
                let t = i as f64 * 2.399_963; // golden angle: an even spread in a disk
                let r = 1e-9 * ((i as f64 + 0.5) / n as f64).sqrt();
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let tree = KdTree::new(&cluster);
        let queries = 256;
        VISITS.with(|v| v.set(0));
        for k in 0..queries {
            let a = k as f64 * std::f64::consts::TAU / queries as f64;
            let q = [a.cos(), a.sin()];
            let brute = (0..n as u32)
                .map(|j| (sq(cluster[j as usize], q), j))
                .min_by(|a, b| cmp(*a, *b))
                .unwrap();
            assert_eq!(tree.nearest(q, 1, u32::MAX), vec![brute]);
        }
        let per_query = VISITS.with(Cell::get) / queries;
        assert!(per_query < 300, "{per_query} nodes visited per query, of {n}");
    }

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
