//! A result's region against the true one, as a user would judge an outline (issue 29):
//! how much they overlap (IoU), and whether they have the same polygons and holes.
//!
//! 1. Each edge set is read as rings as for the symmetric difference of area
//!    ([`area_difference`](super::area_difference), `docs/algorithms.md` §4.6): maximal
//!    chains, an open one closed by its chord, rings of fewer than three distinct points
//!    dropped; its region is their even-odd combination, so nested rings make holes.
//! 2. One `i_overlay` graph of both sets of rings gives the region of each (shapes: an outer
//!    ring and its holes) and their intersection `I`; `IoU = I / (|R| + |T| - I)`.
//! 3. [`Topology`]: the region's polygons (the outer rings of its shapes, the rings at even
//!    nesting depth), its holes (odd depth), and the open paths of the edge set (chains whose
//!    ends differ: a dangling end or a junction), counted before they are closed.
//!
//! Degenerate input: an empty region against an empty one has IoU 1 (they are equal),
//! against a non-empty one 0. Self loops are ignored.
//!
//! # Complexity
//! O((m + k) log m) for `m` edges whose rings cross in `k` points, as
//! [`area_difference`](super::area_difference): one sweep for both regions and their
//! intersection.
use super::area::{shapes_area, unit_rings};
use super::input::{check_all, proper_edges};
use i_overlay::core::extract::BooleanExtractionBuffer;
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;
use sigdt::internals::chains;
use sigdt::{Edge, Point, Result};

/// The shape of an edge set's region: what "topology right" compares.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Topology {
    /// Polygons of the even-odd region: rings at even nesting depth.
    pub polygons: usize,
    /// Holes of the region: rings at odd nesting depth.
    pub holes: usize,
    /// Chains of the edge set whose two ends differ (closed by their chord in the region).
    pub open_paths: usize,
}

/// A result's region against the true region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegionOverlap {
    /// Area of the intersection over area of the union, in [0, 1].
    pub iou: f64,
    /// The result's topology.
    pub result: Topology,
    /// The truth's topology.
    pub truth: Topology,
}

impl RegionOverlap {
    /// As many polygons, holes and open paths as the truth: for a truth of closed rings, a
    /// result with an open path is never right.
    pub fn topology_right(&self) -> bool {
        self.result == self.truth
    }
}

/// The overlap of the regions of `result` and `truth`, edges over `points`, and their
/// topologies. Fails on non-finite points or edges out of range.
pub fn region_overlap(points: &[Point], result: &[Edge], truth: &[Edge]) -> Result<RegionOverlap> {
    check_all(points, result, truth)?;
    let (r, t, _) = unit_rings(points, result, truth);
    let open = |edges| open_paths(points.len(), edges);
    let [r_shapes, t_shapes, both] =
        overlay(&r, &t, [OverlayRule::Subject, OverlayRule::Clip, OverlayRule::Intersect]);
    let (r_area, t_area, both) =
        (shapes_area(&r_shapes), shapes_area(&t_shapes), shapes_area(&both));
    let union = r_area + t_area - both;
    let iou = if union > 0.0 {
        (both / union).clamp(0.0, 1.0)
    } else if r_area == t_area {
        1.0
    } else {
        0.0
    };
    Ok(RegionOverlap {
        iou,
        result: topology_of(&r_shapes, open(result)),
        truth: topology_of(&t_shapes, open(truth)),
    })
}

/// The topology of the region of `edges` over `points`. Fails on non-finite points or edges
/// out of range.
pub fn topology(points: &[Point], edges: &[Edge]) -> Result<Topology> {
    check_all(points, edges, &[])?;
    let (r, _, _) = unit_rings(points, edges, &[]);
    let [shapes] = overlay(&r, &[], [OverlayRule::Subject]);
    Ok(topology_of(&shapes, open_paths(points.len(), edges)))
}

type Shapes = Vec<Vec<Vec<Point>>>;

/// The shapes of each of `rules` on one even-odd overlay graph of `subject` and `clip`.
fn overlay<const K: usize>(
    subject: &[Vec<Point>],
    clip: &[Vec<Point>],
    rules: [OverlayRule; K],
) -> [Shapes; K] {
    let mut overlay = FloatOverlay::with_subj_and_clip(&subject.to_vec(), &clip.to_vec());
    let Some(graph) = overlay.build_graph_view(FillRule::EvenOdd) else {
        return std::array::from_fn(|_| Vec::new());
    };
    let mut buffer = BooleanExtractionBuffer::default();
    rules.map(|rule| graph.extract_shapes(rule, &mut buffer))
}

fn topology_of(shapes: &Shapes, open_paths: usize) -> Topology {
    let holes = shapes.iter().map(|shape| shape.len().saturating_sub(1)).sum();
    Topology { polygons: shapes.len(), holes, open_paths }
}

/// The chains of `edges` whose ends differ.
fn open_paths(n: usize, edges: &[Edge]) -> usize {
    let chains = chains(n, &proper_edges(edges), None);
    chains.iter().filter(|c| !c.cycle && c.vertices.first() != c.vertices.last()).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A regular `n`-gon of radius `r` about `c`, its points from index `first`.
    fn gon(n: usize, r: f64, c: Point, first: usize) -> (Vec<Point>, Vec<Edge>) {
        let tau = std::f64::consts::TAU;
        let points = (0..n)
            .map(|k| tau * k as f64 / n as f64)
            .map(|a| [c[0] + r * a.cos(), c[1] + r * a.sin()]);
        let mut edges: Vec<Edge> = (1..n).map(|k| [first + k - 1, first + k]).collect();
        edges.push([first, first + n - 1]);
        (points.collect(), edges)
    }

    /// Several polygons in one point array, their edges each.
    fn gons(shapes: &[(usize, f64, Point)]) -> (Vec<Point>, Vec<Vec<Edge>>) {
        let (mut points, mut edges) = (Vec::new(), Vec::new());
        for &(n, r, c) in shapes {
            let (p, e) = gon(n, r, c, points.len());
            points.extend(p);
            edges.push(e);
        }
        (points, edges)
    }

    #[test]
    fn concentric_circles_are_one_polygon_with_one_hole() {
        let (points, edges) = gons(&[(64, 2.0, [0.0, 0.0]), (48, 1.0, [0.0, 0.0])]);
        let annulus = [edges[0].clone(), edges[1].clone()].concat();
        let t = topology(&points, &annulus).unwrap();
        assert_eq!(t, Topology { polygons: 1, holes: 1, open_paths: 0 });
        // An island in the hole is a second polygon.
        let (mut more, island) = gon(16, 0.3, [0.0, 0.0], points.len());
        more.splice(0..0, points.iter().copied());
        let t = topology(&more, &[annulus, island].concat()).unwrap();
        assert_eq!(t, Topology { polygons: 2, holes: 1, open_paths: 0 });
    }

    #[test]
    fn identical_regions_have_iou_1_and_disjoint_ones_0() {
        let (points, edges) =
            gons(&[(64, 2.0, [0.0, 0.0]), (48, 1.0, [0.0, 0.0]), (32, 1.0, [9.0, 0.0])]);
        let annulus = [edges[0].clone(), edges[1].clone()].concat();
        let same = region_overlap(&points, &annulus, &annulus).unwrap();
        assert!((same.iou - 1.0).abs() < 1e-9 && same.topology_right(), "{same:?}");
        let apart = region_overlap(&points, &edges[2], &annulus).unwrap();
        assert_eq!(apart.iou, 0.0);
        // One disc against two of equal area, identical to one: IoU 1/2, topology wrong.
        let (points, edges) = gons(&[(32, 1.0, [0.0, 0.0]), (32, 1.0, [5.0, 0.0])]);
        let two = [edges[0].clone(), edges[1].clone()].concat();
        let half = region_overlap(&points, &edges[0], &two).unwrap();
        assert!((half.iou - 0.5).abs() < 1e-9 && !half.topology_right(), "{half:?}");
        // The disc without its hole: IoU 3/4 of the annulus over the disc (radii 2 and 1).
        let (points, edges) = gons(&[(256, 2.0, [0.0, 0.0]), (256, 1.0, [0.0, 0.0])]);
        let annulus = [edges[0].clone(), edges[1].clone()].concat();
        let filled = region_overlap(&points, &edges[0], &annulus).unwrap();
        assert!((filled.iou - 0.75).abs() < 1e-3, "{filled:?}");
        assert_eq!((filled.result.holes, filled.truth.holes), (0, 1));
    }

    #[test]
    fn an_extra_sliver_loop_or_an_open_path_is_the_wrong_topology() {
        // The true disc, and the result: the disc plus a thin triangle beside it. Its area is
        // tiny, so the IoU stays near 1, but there is one polygon too many.
        let (mut points, edges) = gons(&[(64, 1.0, [0.0, 0.0])]);
        points.extend([[1.5, 0.0], [3.0, 0.0], [3.0, 0.001]]);
        let sliver = [edges[0].clone(), vec![[64, 65], [65, 66], [64, 66]]].concat();
        let o = region_overlap(&points, &sliver, &edges[0]).unwrap();
        assert!(o.iou > 0.999 && !o.topology_right(), "{o:?}");
        assert_eq!(o.result, Topology { polygons: 2, holes: 0, open_paths: 0 });
        // The disc with one edge missing: closed by its chord the region is the same, but
        // the result has an open path.
        let open = region_overlap(&points, &edges[0][1..], &edges[0]).unwrap();
        assert!(open.iou > 0.99 && !open.topology_right(), "{open:?}");
        assert_eq!(open.result, Topology { polygons: 1, holes: 0, open_paths: 1 });
    }

    #[test]
    fn degenerate_inputs() {
        let (points, edges) = gons(&[(8, 1.0, [0.0, 0.0])]);
        let none = region_overlap(&points, &[], &[]).unwrap();
        assert_eq!((none.iou, none.topology_right()), (1.0, true));
        let empty = region_overlap(&points, &[[3, 3]], &edges[0]).unwrap();
        assert_eq!(empty.iou, 0.0);
        assert_eq!(empty.result, Topology::default());
        // A single edge: no area, one open path.
        assert_eq!(topology(&points, &[[0, 1]]).unwrap().open_paths, 1);
        assert!(region_overlap(&points, &[[0, 99]], &edges[0]).is_err());
        assert!(topology(&[[f64::NAN, 0.0]], &[]).is_err());
    }
}
