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
//! scan, ties by index. Each node keeps its left subtree's largest key and its right
//! subtree's smallest, the subtrees' true extent along the split axis: with many equal keys
//! (points on two lines), the split point's own key left the other line's cell at distance
//! zero from every query on the first.
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
    /// Per node: the largest key (split-axis coordinate) of its left subtree and the
    /// smallest of its right one; a far subtree is at least that far along the axis.
    extremes: Vec<[f64; 2]>,
}

impl<'a> KdTree<'a> {
    /// Builds the tree over all of `points`.
    pub fn new(points: &'a [Point]) -> KdTree<'a> {
        let mut order: Vec<u32> = (0..points.len() as u32).collect();
        let mut axes = vec![0; points.len()];
        let mut extremes = vec![[0.0; 2]; points.len()];
        build(points, &mut order, &mut axes, &mut extremes);
        KdTree { points, order, axes, extremes }
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
        let ([left_offsets, right_offsets], left_first) = self.children(mid, axis, q, offsets);
        let (near, far) = match left_first {
            true => (((lo, mid), left_offsets), ((mid + 1, hi), right_offsets)),
            false => (((mid + 1, hi), right_offsets), ((lo, mid), left_offsets)),
        };
        self.knn(near.0 .0, near.0 .1, q, near.1, k, exclude, best);
        if best.len() < k || cell_distance(far.1) <= best[best.len() - 1].0 {
            self.knn(far.0 .0, far.0 .1, q, far.1, k, exclude, best);
        }
    }

    /// The offsets of the cells of node `mid`'s two subtrees from `q` (splitting on `axis`,
    /// its own cell `offsets` away), and whether to search the left one first: the nearer,
    /// or on a tie the side of `q`'s key.
    fn children(
        &self,
        mid: usize,
        axis: usize,
        q: Point,
        offsets: [f64; 2],
    ) -> ([[f64; 2]; 2], bool) {
        let [left_max, right_min] = self.extremes[mid];
        let (mut left, mut right) = (offsets, offsets);
        // Each gap is a rounded difference of q and an actual point's coordinate: no larger
        // than the difference to any point beyond it.
        if q[axis] > left_max {
            left[axis] = left[axis].max(q[axis] - left_max);
        }
        if q[axis] < right_min {
            right[axis] = right[axis].max(right_min - q[axis]);
        }
        let (l, r) = (cell_distance(left), cell_distance(right));
        let left_first = l < r || (l == r && q[axis] < self.points[self.order[mid] as usize][axis]);
        ([left, right], left_first)
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
        let ([left, right], _) = self.children(mid, axis, q, offsets);
        if cell_distance(left) <= r2 {
            self.range(lo, mid, q, left, r2, out);
        }
        if cell_distance(right) <= r2 {
            self.range(mid + 1, hi, q, right, r2, out);
        }
    }
}

/// Squared distance from the query to a cell with these offsets.
#[inline]
fn cell_distance([dx, dy]: [f64; 2]) -> f64 {
    dx * dx + dy * dy
}

/// Splits `order` at its median along the axis of widest spread, recording the axis in
/// `axes` and the halves' largest and smallest keys in `extremes` (the same positions as
/// `order`), then splits both halves.
fn build(points: &[Point], order: &mut [u32], axes: &mut [u8], extremes: &mut [[f64; 2]]) {
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
    let key = |i: u32| points[i as usize][axis];
    let mid = order.len() / 2;
    order.select_nth_unstable_by(mid, |&a, &b| key(a).total_cmp(&key(b)));
    axes[mid] = axis as u8;
    let (left, right) = order.split_at_mut(mid);
    let left_max = left.iter().map(|&i| key(i)).fold(f64::NEG_INFINITY, f64::max);
    let right_min = right[1..].iter().map(|&i| key(i)).fold(f64::INFINITY, f64::min);
    extremes[mid] = [left_max, right_min];
    let (left_axes, right_axes) = axes.split_at_mut(mid);
    let (left_extremes, right_extremes) = extremes.split_at_mut(mid);
    build(points, left, left_axes, left_extremes);
    build(points, &mut right[1..], &mut right_axes[1..], &mut right_extremes[1..]);
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

    /// Two rows, `y = 0` and `y = 1`, 10⁻⁴⁰ apart along each (a zigzag between them): with
    /// equal keys on both sides of a split, a query on a row could prune neither side, and
    /// HNN-CRUST took 293 s at 2.56·10⁵ points. Each subtree's nearest key bounds it now.
    #[test]
    fn points_on_two_lines_are_searched_in_few_nodes() {
        let n = 4096u32;
        let rows: Vec<Point> = (0..n).map(|i| [f64::from(i) * 1e-40, f64::from(i % 2)]).collect();
        let tree = KdTree::new(&rows);
        VISITS.with(|v| v.set(0));
        for i in (0..n).step_by(16) {
            let q = rows[i as usize];
            let mut brute: Vec<(f64, u32)> =
                (0..n).filter(|&j| j != i).map(|j| (sq(rows[j as usize], q), j)).collect();
            brute.sort_by(|a, b| cmp(*a, *b));
            assert_eq!(tree.nearest(q, 2, i), brute[..2].to_vec());
            let mut got = Vec::new();
            tree.within(q, 0.5, &mut got);
            assert_eq!(got.len() as u32, n / 2, "the row of point {i}");
        }
        let per_query = VISITS.with(Cell::get) / (n as usize / 16);
        assert!(per_query < 300, "{per_query} nodes visited per query, of {n}");
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
