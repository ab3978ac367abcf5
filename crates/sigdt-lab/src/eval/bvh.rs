//! A bounding-box tree over grouped segments for filtered nearest-segment queries.
//!
//! Every segment (a point is the segment `[p, p]`) carries a group number. The tree splits
//! the segments at the median of their midpoints along the longer side of the box, down to
//! leaves of at most [`LEAF`] segments, and stores in every node its box and the range of
//! groups below it. A query skips whole subtrees whose only group is refused, which is what
//! makes "nearest feature not adjacent to this arc" cheap: on a curve, most nodes near the
//! query hold one arc only.
//!
//! # Complexity
//! Build O(m log m). A query visits O(log m) nodes plus those its final radius reaches that
//! hold accepted or mixed groups.
use super::grid::point_segment_distance;
use sigdt::Point;

/// Maximum number of segments in a leaf.
const LEAF: usize = 8;
const NONE: u32 = u32::MAX;

struct Node {
    lo: Point,
    hi: Point,
    groups: [u32; 2],
    range: [u32; 2],
    children: [u32; 2],
}

/// Segments with group numbers in a bounding-box tree.
pub(crate) struct SegmentTree {
    segments: Vec<[Point; 2]>,
    groups: Vec<u32>,
    order: Vec<u32>,
    nodes: Vec<Node>,
}

impl SegmentTree {
    /// Builds the tree; `segments` and `groups` have the same length, coordinates finite.
    pub(crate) fn new(segments: Vec<[Point; 2]>, groups: Vec<u32>) -> SegmentTree {
        debug_assert_eq!(segments.len(), groups.len());
        let order = (0..segments.len() as u32).collect();
        let mut tree = SegmentTree { segments, groups, order, nodes: Vec::new() };
        if !tree.segments.is_empty() {
            tree.build(0, tree.segments.len());
        }
        tree
    }

    /// Visits, nearest subtrees first, every segment whose group passes `accept` and that may
    /// lie within `bound()` of `q`, calling `visit(segment, group, distance)`. Subtrees
    /// farther than the current bound are pruned.
    pub(crate) fn search(
        &self,
        q: Point,
        accept: &impl Fn(u32) -> bool,
        bound: &impl Fn() -> f64,
        visit: &mut impl FnMut(u32, u32, f64),
    ) {
        if !self.nodes.is_empty() {
            self.go(0, q, accept, bound, visit);
        }
    }

    /// Distance from `q` to the nearest segment of group `g`, or `limit` if none is closer.
    pub(crate) fn nearest_in_group(&self, q: Point, g: u32, limit: f64) -> f64 {
        let best = std::cell::Cell::new(limit);
        self.search(q, &|h| h == g, &|| best.get(), &mut |_, _, d| best.set(best.get().min(d)));
        best.get()
    }

    fn go(
        &self,
        n: u32,
        q: Point,
        accept: &impl Fn(u32) -> bool,
        bound: &impl Fn() -> f64,
        visit: &mut impl FnMut(u32, u32, f64),
    ) {
        let node = &self.nodes[n as usize];
        if node.groups[0] == node.groups[1] && !accept(node.groups[0]) {
            return;
        }
        if node.children[0] == NONE {
            for &s in &self.order[node.range[0] as usize..node.range[1] as usize] {
                let g = self.groups[s as usize];
                if accept(g) {
                    let [a, b] = self.segments[s as usize];
                    let d = point_segment_distance(q, a, b);
                    if d <= bound() {
                        visit(s, g, d);
                    }
                }
            }
            return;
        }
        let [c0, c1] = node.children;
        let (d0, d1) = (self.box_distance(c0, q), self.box_distance(c1, q));
        let (near, far, dfar) = if d0 <= d1 { (c0, c1, d1) } else { (c1, c0, d0) };
        if d0.min(d1) <= bound() {
            self.go(near, q, accept, bound, visit);
        }
        if dfar <= bound() {
            self.go(far, q, accept, bound, visit);
        }
    }

    /// A lower bound on the distance from `q` to node `n`'s box.
    fn box_distance(&self, n: u32, q: Point) -> f64 {
        let node = &self.nodes[n as usize];
        let dx = (node.lo[0] - q[0]).max(q[0] - node.hi[0]).max(0.0);
        let dy = (node.lo[1] - q[1]).max(q[1] - node.hi[1]).max(0.0);
        // Only pruning reads this, and every search keeps the least distance visited: a
        // lower bound prunes less but finds the same. The root of the rounded sum is within
        // a few units in the last place (hypot, exact to one, is 40% of an evaluation).
        let d2 = dx * dx + dy * dy;
        match d2.is_finite() {
            true => d2.sqrt() * (1.0 - 8.0 * f64::EPSILON),
            false => dx.hypot(dy),
        }
    }

    fn build(&mut self, lo: usize, hi: usize) -> u32 {
        let mut node = Node {
            lo: [f64::INFINITY; 2],
            hi: [f64::NEG_INFINITY; 2],
            groups: [u32::MAX, 0],
            range: [lo as u32, hi as u32],
            children: [NONE; 2],
        };
        for &s in &self.order[lo..hi] {
            for p in self.segments[s as usize] {
                node.lo = [node.lo[0].min(p[0]), node.lo[1].min(p[1])];
                node.hi = [node.hi[0].max(p[0]), node.hi[1].max(p[1])];
            }
            let g = self.groups[s as usize];
            node.groups = [node.groups[0].min(g), node.groups[1].max(g)];
        }
        let id = self.nodes.len() as u32;
        let axis = usize::from(node.hi[1] - node.lo[1] > node.hi[0] - node.lo[0]);
        self.nodes.push(node);
        if hi - lo > LEAF {
            let mid = lo + (hi - lo) / 2;
            let segments = &self.segments;
            let key = |s: &u32| {
                let [a, b] = segments[*s as usize];
                a[axis] + b[axis]
            };
            self.order[lo..hi]
                .select_nth_unstable_by(mid - lo, |x, y| key(x).total_cmp(&key(y)).then(x.cmp(y)));
            let left = self.build(lo, mid);
            let right = self.build(mid, hi);
            self.nodes[id as usize].children = [left, right];
        }
        id
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filtered_nearest_matches_brute_force() {
        let segs: Vec<[Point; 2]> = (0..300)
            .map(|i| {
                let (a, b) = (i as f64 * 0.021, (i + 1) as f64 * 0.021);
                [[a.cos() * (1.0 + a), a.sin()], [b.cos() * (1.0 + b), b.sin()]]
            })
            .collect();
        let groups: Vec<u32> = (0..300).map(|i| i / 40).collect();
        let tree = SegmentTree::new(segs.clone(), groups.clone());
        for k in 0..100 {
            let q = [(k as f64 * 0.7).sin() * 8.0, (k as f64 * 1.3).cos() * 2.0];
            for g in 0..8 {
                let brute = (0..300)
                    .filter(|&s| groups[s] == g)
                    .map(|s| point_segment_distance(q, segs[s][0], segs[s][1]))
                    .fold(f64::INFINITY, f64::min);
                assert_eq!(tree.nearest_in_group(q, g, f64::INFINITY), brute);
            }
        }
        assert_eq!(
            SegmentTree::new(Vec::new(), Vec::new()).nearest_in_group([0.0; 2], 0, 1.0),
            1.0
        );
    }
}
