//! The loops of a result grouped into polygons with holes, decided with exact predicates.
//!
//! The loops of every method are vertex-disjoint and no two of their edges cross, so one
//! loop lies inside another exactly when one of its vertices does. A loop inside an even
//! number of others is a *shell*; the loops directly inside it (one level deeper) are its
//! *holes*; a loop inside a hole is a shell again. The writers (WKT, GeoJSON), the pictures
//! and the Python views all group loops this way.
//!
//! Point in loop is the even-odd crossing count of a ray towards `+x`, with every crossing
//! decided by comparisons and `orient2d` on exactly scaled coordinates, so the answer is
//! exact for any finite input.
//!
//! # Complexity
//! O(k log k + Σ |loop|) for `k` loops when bounding boxes separate them (the boxes that may
//! hold a loop are found through a hierarchy of boxes), O(k · Σ |loop|) at worst (loops
//! nested in one another).
use super::Reconstruction;
use crate::delaunay::hygiene::Scaling;
use crate::geometry::{orient2d, Point};

/// A polygon of a result: indices into [`Reconstruction::loops`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Polygon {
    /// The loop that bounds the polygon (counter-clockwise, as every loop).
    pub shell: usize,
    /// The loops directly inside the shell, in loop order.
    pub holes: Vec<usize>,
}

impl Reconstruction {
    /// The loops grouped into polygons with holes, shells in loop order (see the module
    /// docs). `points` are the points the result was computed from.
    ///
    /// ```
    /// // A square inside a larger square: one polygon with a hole.
    /// let points = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0],
    ///               [1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]];
    /// let rec = sigdt::Reconstruction {
    ///     loops: vec![vec![0, 1, 2, 3], vec![4, 5, 6, 7]],
    ///     ..Default::default()
    /// };
    /// let polygons = rec.polygons(&points);
    /// assert_eq!(polygons, vec![sigdt::Polygon { shell: 0, holes: vec![1] }]);
    /// ```
    pub fn polygons(&self, points: &[Point]) -> Vec<Polygon> {
        nest(points, &self.loops)
    }
}

fn nest(points: &[Point], loops: &[Vec<usize>]) -> Vec<Polygon> {
    // Loops are made of input points, which `Scaling` accepts unless they are unusable for
    // any predicate; unscaled coordinates then still give the answer for ordinary input.
    let scaled: Vec<Point> = match Scaling::for_points(points) {
        Ok(scaling) => points.iter().map(|&p| scaling.apply(p)).collect(),
        Err(_) => points.to_vec(),
    };
    let boxes: Vec<[f64; 4]> = loops
        .iter()
        .map(|l| {
            l.iter().fold(
                [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY],
                |b, &i| {
                    let [x, y] = scaled[i];
                    [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)]
                },
            )
        })
        .collect();
    // Loop `i` is inside loop `j` when a vertex of `i` that is not on `j` is (the first
    // vertex, for the vertex-disjoint loops of a reconstruction).
    let inside = |i: usize, j: usize| {
        if i == j || loops[j].is_empty() {
            return false;
        }
        let Some(&v) = loops[i].iter().find(|v| !loops[j].contains(v)) else { return false };
        in_ring(&scaled, &loops[j], scaled[v])
    };
    // Only loops whose box holds the first vertex of `i` can hold `i`: found through a
    // hierarchy of boxes, so that many separate loops (islands) cost O(k log k), not O(k²).
    let tree = BoxTree::new(&boxes);
    let mut containers: Vec<Vec<usize>> = vec![Vec::new(); loops.len()];
    let mut candidates = Vec::new();
    for (i, ring) in loops.iter().enumerate() {
        let Some(&first) = ring.first() else { continue };
        candidates.clear();
        tree.containing(scaled[first], &mut candidates);
        candidates.sort_unstable();
        containers[i] = candidates.iter().copied().filter(|&j| inside(i, j)).collect();
    }
    let depth: Vec<usize> = containers.iter().map(Vec::len).collect();
    // A hole's shell is its container one level up.
    let mut holes: Vec<Vec<usize>> = vec![Vec::new(); loops.len()];
    for h in (0..loops.len()).filter(|&h| depth[h] % 2 == 1) {
        if let Some(&shell) = containers[h].iter().find(|&&j| depth[j] + 1 == depth[h]) {
            holes[shell].push(h);
        }
    }
    (0..loops.len())
        .filter(|&i| depth[i] % 2 == 0)
        .map(|shell| Polygon { shell, holes: std::mem::take(&mut holes[shell]) })
        .collect()
}

/// A bounding-volume hierarchy over boxes `[min x, min y, max x, max y]`: each node holds the
/// box around its items, split at the median centre along its longer side. Built in
/// O(k log k); finding the boxes that hold a point visits O(log k) nodes plus those whose
/// box holds it.
struct BoxTree<'a> {
    boxes: &'a [[f64; 4]],
    /// Item indices, ordered so that every node's items are a run of them.
    order: Vec<usize>,
    /// Nodes: the box around the run, the run, and the first child (the second follows the
    /// first's subtree); leaves have no child.
    nodes: Vec<Node>,
}

struct Node {
    bounds: [f64; 4],
    run: std::ops::Range<usize>,
    children: Option<[usize; 2]>,
}

/// Items a leaf holds at most.
const LEAF: usize = 8;

impl<'a> BoxTree<'a> {
    fn new(boxes: &'a [[f64; 4]]) -> BoxTree<'a> {
        // Empty loops have an inverted box, which holds no point: left out.
        let order: Vec<usize> = (0..boxes.len()).filter(|&i| boxes[i][0] <= boxes[i][2]).collect();
        let mut tree = BoxTree { boxes, nodes: Vec::new(), order };
        if !tree.order.is_empty() {
            tree.build(0..tree.order.len());
        }
        tree
    }

    /// Adds the node of `run` and its subtree; its index.
    fn build(&mut self, run: std::ops::Range<usize>) -> usize {
        let bounds = self.order[run.clone()].iter().fold(
            [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY],
            |b, &i| {
                let c = self.boxes[i];
                [b[0].min(c[0]), b[1].min(c[1]), b[2].max(c[2]), b[3].max(c[3])]
            },
        );
        let node = self.nodes.len();
        self.nodes.push(Node { bounds, run: run.clone(), children: None });
        if run.len() > LEAF {
            let axis = usize::from(bounds[3] - bounds[1] > bounds[2] - bounds[0]);
            let centre = |i: usize| self.boxes[i][axis] + self.boxes[i][axis + 2];
            let mid = run.start + run.len() / 2;
            // Ties broken by index, so that the tree does not depend on the sort's order.
            let key = |&i: &usize| (centre(i), i);
            self.order[run.clone()].select_nth_unstable_by(mid - run.start, |a, b| {
                key(a).partial_cmp(&key(b)).unwrap_or(std::cmp::Ordering::Equal)
            });
            let left = self.build(run.start..mid);
            let right = self.build(mid..run.end);
            self.nodes[node].children = Some([left, right]);
        }
        node
    }

    /// Pushes onto `found` every item whose box holds `p` (closed boxes).
    fn containing(&self, p: Point, found: &mut Vec<usize>) {
        let holds = |b: &[f64; 4]| b[0] <= p[0] && p[0] <= b[2] && b[1] <= p[1] && p[1] <= b[3];
        let mut stack = if self.nodes.is_empty() { vec![] } else { vec![0] };
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n];
            if !holds(&node.bounds) {
                continue;
            }
            match node.children {
                Some(children) => stack.extend(children),
                None => found.extend(
                    self.order[node.run.clone()].iter().filter(|&&i| holds(&self.boxes[i])),
                ),
            }
        }
    }
}

/// Whether `p` lies inside the closed ring through `ring` (even-odd rule). A crossing of the
/// ray from `p` towards `+x` with edge `ab` (one end above `p`, the other not) lies right of
/// `p` exactly when `p` is on the left of the edge directed upwards.
fn in_ring(points: &[Point], ring: &[usize], p: Point) -> bool {
    let mut inside = false;
    for k in 0..ring.len() {
        let (a, b) = (points[ring[k]], points[ring[(k + 1) % ring.len()]]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let side = orient2d(a, b, p);
            if (side > 0.0) == (b[1] > a[1]) && side != 0.0 {
                inside = !inside;
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, s: f64) -> [Point; 4] {
        [[x, y], [x + s, y], [x + s, y + s], [x, y + s]]
    }

    #[test]
    fn nested_squares_alternate_shells_and_holes() {
        // Squares of side 8, 4 and 2 nested in one another, and one of side 1 beside them.
        let points: Vec<Point> = [square(0.0, 0.0, 8.0), square(2.0, 2.0, 4.0)]
            .into_iter()
            .chain([square(3.0, 3.0, 2.0), square(10.0, 0.0, 1.0)])
            .flatten()
            .collect();
        let loops: Vec<Vec<usize>> = (0..4).map(|k| (4 * k..4 * k + 4).collect()).collect();
        let polygons = nest(&points, &loops);
        assert_eq!(
            polygons,
            vec![
                Polygon { shell: 0, holes: vec![1] },
                Polygon { shell: 2, holes: vec![] },
                Polygon { shell: 3, holes: vec![] },
            ]
        );
    }

    /// The grouping by definition: every pair of loops tested (O(k²)).
    fn nest_by_every_pair(points: &[Point], loops: &[Vec<usize>]) -> Vec<Polygon> {
        let inside = |i: usize, j: usize| i != j && in_ring(points, &loops[j], points[loops[i][0]]);
        let containers: Vec<Vec<usize>> = (0..loops.len())
            .map(|i| (0..loops.len()).filter(|&j| inside(i, j)).collect())
            .collect();
        let depth: Vec<usize> = containers.iter().map(Vec::len).collect();
        (0..loops.len())
            .filter(|&i| depth[i] % 2 == 0)
            .map(|shell| Polygon {
                shell,
                holes: (0..loops.len())
                    .filter(|&h| depth[h] == depth[shell] + 1 && containers[h].contains(&shell))
                    .collect(),
            })
            .collect()
    }

    #[test]
    fn many_islands_group_as_every_pair_says() {
        // Issue 47, S1: every loop was tested against every other, 16 s for 40,000 islands.
        // A grid of islands, every third with a lake, every ninth lake with an islet, and two
        // large rings around parts of the grid (one inside the other), in a shuffled order.
        let mut rings: Vec<[Point; 4]> = Vec::new();
        for k in 0..900 {
            let (x, y) = ((k % 30) as f64 * 10.0, (k / 30) as f64 * 10.0);
            rings.push(square(x, y, 8.0));
            if k % 3 == 0 {
                rings.push(square(x + 2.0, y + 2.0, 4.0));
            }
            if k % 9 == 0 {
                rings.push(square(x + 3.0, y + 3.0, 2.0));
            }
        }
        rings.push(square(-1.0, -1.0, 155.0));
        rings.push(square(-2.0, -2.0, 157.0));
        let mut order: Vec<usize> = (0..rings.len()).collect();
        let mut rng = crate::samplers::Rng::new(7);
        for i in (1..order.len()).rev() {
            order.swap(i, (rng.uniform() * (i + 1) as f64) as usize % (i + 1));
        }
        let points: Vec<Point> = order.iter().flat_map(|&r| rings[r]).collect();
        let loops: Vec<Vec<usize>> =
            (0..rings.len()).map(|k| (4 * k..4 * k + 4).collect()).collect();
        let polygons = nest(&points, &loops);
        assert_eq!(polygons, nest_by_every_pair(&points, &loops));
        // Shells: the outer ring (the inner one is its hole), every island (inside both rings
        // at depth two) and every islet.
        assert_eq!(polygons.len(), 1 + 900 + 100);
    }

    #[test]
    fn a_vertex_level_with_a_ring_vertex_counts_once() {
        // The ray from (1, 1) passes exactly through the ring's vertex (3, 1).
        let points = [[0.0, 0.0], [3.0, 1.0], [0.0, 2.0], [1.0, 1.0]];
        assert!(in_ring(&points, &[0, 1, 2], points[3]));
        assert!(!in_ring(&points, &[0, 1, 2], [3.5, 1.0]));
        // Far beyond f64 squares: exact all the same.
        let huge: Vec<Point> = points.iter().map(|p| [p[0] * 1e300, p[1] * 1e300]).collect();
        assert_eq!(nest(&huge, &[vec![0, 1, 2], vec![3]]).len(), 1);
    }
}
