//! Noisy curves read at a coarser scale, then through every point.
//!
//! Noise moves each sample off its curve by some fraction of the sample spacing; once that
//! fraction nears a quarter, neighbouring samples trade places across the curve, SIGDT
//! misses curve edges, and the reading breaks into slivers and small loops. The sampling
//! check ([`check_curves`]) sees this. Thinning the points to
//! `f` times their spacing leaves the noise the same in length but `f` times smaller
//! against the new spacing, back within what a sampled curve allows: the coarse points
//! read as the right curves. The points left out of the coarse reading then go back in,
//! each at its place along the nearest coarse edge.
//!
//! 1. `s` = the median nearest-neighbour distance. For `f` in [`THINNING`] (2, 3, 4): keep
//!    a subset of points at least `f · s` apart (greedy along the Hilbert curve: a
//!    Poisson-disk sample that depends on the point set alone, spaced more evenly along a
//!    curve than a random order gives), and read it at its own scale (SIG-AUTO's steps
//!    1–12 and 14: no coarser scale, networks or candidates).
//! 2. The first coarse reading that is closed curves only (status `polygon` or `polygons`)
//!    and passes the sampling check on its own points is used. Loops too small for a
//!    sampled curve that hold only points the fine reading left out as outliers are dropped
//!    first, and those points stay outliers: thinning keeps every outlier while it spaces
//!    the curve like them, so a cluster of outliers can read as a loop at the coarse scale.
//! 3. Every point goes to the coarse loop edge nearest to it (among the edges at its three
//!    nearest coarse loop vertices), at the parameter of its foot on that edge; each edge's
//!    points follow in that order (ties by index). A point farther than `f · s` from every
//!    candidate edge is left out as an outlier: it is farther from the curve than the
//!    coarse spacing, which no noisy sample of it is. Two such points within the coarse
//!    spacing of each other are a piece of curve the level missed, not outliers: the level
//!    is rejected.
//! 4. Where the fine loops cross themselves (noise across an edge), 2-opt moves undo the
//!    crossings; each shortens the loop, so this ends. A loop that still crosses, or meets
//!    another loop, or a fine reading that fails the sampling check, rejects the level.
//!
//! # Guarantees
//! A reading from here is used only when it has vertex-disjoint simple loops that do not
//! cross or touch (exact predicates) and passes the sampling check on all the points; its
//! edges need not be Delaunay edges. Only readings that fail the sampling check, or whose
//! sculpting got stuck, come here.
//!
//! # Complexity
//! O(n log n) per level (three levels at most, on fewer points each), plus O(n) per pass
//! of crossing repair (at most [`MAX_REPAIR_PASSES`]).
use crate::delaunay::brio::hilbert_order;
use crate::segment_grid::visit_pairs_sharing_cells;
use std::collections::HashMap;

use super::{own_scale_reading, Steps};
use crate::delaunay::Triangulation;
use crate::geometry::{distance, orient2d, segment_foot, segments_cross, Point};
use crate::proximity::kdtree::KdTree;
use crate::result::Status;
use crate::sampling_check::{check_curves, Finding, FindingKind, MIN_LOOP_POINTS};

/// The thinning factors tried, coarsest last: the spacing of the coarse points in units of
/// the median nearest-neighbour distance.
pub const THINNING: [f64; 3] = [2.0, 3.0, 4.0];

/// The most passes of crossing repair per level.
const MAX_REPAIR_PASSES: usize = 64;

/// A fine reading of `dt` from a coarse one: loops of vertices of `dt` and the vertices
/// left out as outliers; `None` when no level gives one.
pub(super) struct FineReading {
    pub loops: Vec<Vec<u32>>,
    pub outliers: Vec<u32>,
}

/// The fine reading of the first level of [`THINNING`] that works (module docs), or
/// `None`. `left_out` are the vertices the fine reading left out as outliers (step 2);
/// `spacing` every vertex's nearest-neighbour distance.
pub(super) fn coarse_reading(
    dt: &Triangulation,
    steps: &Steps,
    left_out: &[u32],
    spacing: &[f64],
) -> Option<FineReading> {
    let mut r = spacing.to_vec();
    let middle = r.len() / 2;
    let (_, &mut spacing, _) = r.select_nth_unstable_by(middle, f64::total_cmp);
    if !(spacing > 0.0 && spacing.is_finite()) {
        return None;
    }
    let order = hilbert_order(|v| dt.point(v), dt.num_vertices());
    for factor in THINNING {
        let radius = factor * spacing;
        let kept = thin(dt, &order, radius);
        if kept.len() < 3 || kept.len() == dt.num_vertices() {
            continue;
        }
        let points: Vec<Point> = kept.iter().map(|&v| dt.point(v)).collect();
        let Ok(sub) = Triangulation::new(&points) else { continue };
        // A coarse reading is used only when it is closed curves.
        let coarse = own_scale_reading(&sub, steps);
        if !matches!(coarse.status, Status::Polygon | Status::Polygons) {
            continue;
        }
        let loops: Vec<Vec<u32>> =
            coarse.loops.iter().map(|l| l.iter().map(|&i| kept[i]).collect()).collect();
        let Some((loops, settled)) = passing_loops(loops, &coarse.diagnosis, left_out) else {
            continue;
        };
        if let Some(fine) = refine(dt, &loops, radius, &settled) {
            let found = check_curves(dt, fine.loops.iter().map(|l| (l.as_slice(), true)));
            if !super::curves_fail(&found) {
                return Some(fine);
            }
        }
    }
    None
}

/// The coarse `loops` to refine and the vertices settled as outliers, if the coarse
/// reading passes the sampling check (its `findings`). One failure is forgiven: loops too
/// small for a sampled curve made only of points the fine reading `left_out` as outliers.
/// Thinning keeps every outlier (none has a neighbour within the radius) while it spaces
/// the curve like a cluster of them, so at the coarse scale a few outliers can read as a
/// curve; they are dropped, and stay outliers.
fn passing_loops(
    loops: Vec<Vec<u32>>,
    findings: &[Finding],
    left_out: &[u32],
) -> Option<(Vec<Vec<u32>>, Vec<u32>)> {
    let failing = || findings.iter().filter(|f| super::fails(f));
    if failing().next().is_none() {
        return (!loops.is_empty()).then_some((loops, Vec::new()));
    }
    if !failing().all(|f| f.kind == FindingKind::SmallLoops) {
        return None;
    }
    let (small, rest): (Vec<_>, Vec<_>) =
        loops.into_iter().partition(|l| l.len() < MIN_LOOP_POINTS);
    let mut settled = small.concat();
    settled.sort_unstable();
    let all_left_out = settled.iter().all(|v| left_out.contains(v));
    (all_left_out && !rest.is_empty()).then_some((rest, settled))
}

/// Points bucketed in square cells of side `radius`, to ask whether a new point has one
/// within `radius`.
struct Cells<'a> {
    dt: &'a Triangulation,
    radius: f64,
    cells: HashMap<(i64, i64), Vec<u32>>,
}

impl<'a> Cells<'a> {
    fn new(dt: &'a Triangulation, radius: f64) -> Self {
        Cells { dt, radius, cells: HashMap::new() }
    }

    fn cell(&self, p: Point) -> (i64, i64) {
        ((p[0] / self.radius).floor() as i64, (p[1] / self.radius).floor() as i64)
    }

    /// Whether a point already added lies within `radius` of `v`.
    fn has_near(&self, v: u32) -> bool {
        let p = self.dt.point(v);
        let (cx, cy) = self.cell(p);
        (cx - 1..=cx + 1)
            .flat_map(|x| (cy - 1..=cy + 1).map(move |y| (x, y)))
            .filter_map(|key| self.cells.get(&key))
            .flatten()
            .any(|&w| distance(p, self.dt.point(w)) < self.radius)
    }

    fn add(&mut self, v: u32) {
        let key = self.cell(self.dt.point(v));
        self.cells.entry(key).or_default().push(v);
    }
}

/// Vertices of `dt` at least `radius` apart, chosen greedily in `order` (its vertices along
/// the Hilbert curve).
fn thin(dt: &Triangulation, order: &[u32], radius: f64) -> Vec<u32> {
    let mut cells = Cells::new(dt, radius);
    let mut kept = Vec::new();
    for &v in order {
        if !cells.has_near(v) {
            cells.add(v);
            kept.push(v);
        }
    }
    kept
}

/// Every vertex of `dt` placed along the coarse `loops` (step 3 of the module docs), with
/// crossings repaired (step 4); `None` if a crossing or touch remains. The `settled`
/// vertices (sorted) are outliers already.
fn refine(
    dt: &Triangulation,
    loops: &[Vec<u32>],
    radius: f64,
    settled: &[u32],
) -> Option<FineReading> {
    // Coarse loop vertices, and for each its loop and position.
    let on_loop: Vec<(usize, usize)> =
        loops.iter().enumerate().flat_map(|(l, lp)| (0..lp.len()).map(move |k| (l, k))).collect();
    let coarse_points: Vec<Point> = on_loop.iter().map(|&(l, k)| dt.point(loops[l][k])).collect();
    let tree = KdTree::new(&coarse_points);
    let mut is_coarse = vec![false; dt.num_vertices()];
    loops.iter().flatten().for_each(|&v| is_coarse[v as usize] = true);
    // Per coarse edge (loop, position of its first vertex): (parameter, vertex).
    let mut along: HashMap<(usize, usize), Vec<(f64, u32)>> = HashMap::new();
    let mut outliers = Vec::new();
    for v in 0..dt.num_vertices() as u32 {
        if is_coarse[v as usize] || settled.binary_search(&v).is_ok() {
            continue;
        }
        let p = dt.point(v);
        let mut best: Option<(f64, (usize, usize), f64)> = None;
        for (_, c) in tree.nearest(p, 3, u32::MAX) {
            let (l, k) = on_loop[c as usize];
            let n = loops[l].len();
            for edge in [(l, k), (l, (k + n - 1) % n)] {
                let (a, b) = (dt.point(loops[l][edge.1]), dt.point(loops[l][(edge.1 + 1) % n]));
                let (d, t) = segment_foot(p, a, b);
                if best.map_or(true, |(bd, be, _)| (d, edge) < (bd, be)) {
                    best = Some((d, edge, t));
                }
            }
        }
        match best {
            Some((d, edge, t)) if d <= radius => along.entry(edge).or_default().push((t, v)),
            _ => outliers.push(v),
        }
    }
    if !isolated(dt, &outliers, radius) {
        return None;
    }
    outliers.extend(settled);
    outliers.sort_unstable();
    let mut fine = Vec::with_capacity(loops.len());
    for (l, lp) in loops.iter().enumerate() {
        let mut seq = Vec::new();
        for (k, &v) in lp.iter().enumerate() {
            seq.push(v);
            if let Some(points) = along.get_mut(&(l, k)) {
                points.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
                seq.extend(points.iter().map(|&(_, v)| v));
            }
        }
        if !untangle(dt, &mut seq) {
            return None;
        }
        fine.push(seq);
    }
    if loops_meet(dt, &fine) {
        return None;
    }
    Some(FineReading { loops: fine, outliers })
}

/// Whether no two of `points` are closer than `radius` to each other: outliers lie apart, and
/// points the coarse curves pass by in a group are a curve of their own (SIG-AUTO's "own
/// curves" rule) that this level failed to read.
fn isolated(dt: &Triangulation, points: &[u32], radius: f64) -> bool {
    let mut cells = Cells::new(dt, radius);
    for &v in points {
        if cells.has_near(v) {
            return false;
        }
        cells.add(v);
    }
    true
}

/// Whether non-adjacent segments `ab` and `cd` cross or touch (an end on the other
/// segment), with exact orientations.
fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    let on = |p: Point, q: Point, r: Point| {
        orient2d(p, q, r) == 0.0
            && r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    segments_cross(a, b, c, d) || on(a, b, c) || on(a, b, d) || on(c, d, a) || on(c, d, b)
}

/// The pairs of edges `(i, j)`, `i < j`, of the closed sequences `loops` (edge `(l, i)`
/// joins `loops[l][i]` to the next) that are not adjacent and meet, found through a grid
/// with cells as large as the longest edge.
fn meeting_edges(dt: &Triangulation, loops: &[Vec<u32>]) -> Vec<((usize, usize), (usize, usize))> {
    let ends = |(l, i): (usize, usize)| {
        let lp = &loops[l];
        (lp[i], lp[(i + 1) % lp.len()])
    };
    let edges: Vec<(usize, usize)> =
        loops.iter().enumerate().flat_map(|(l, lp)| (0..lp.len()).map(move |i| (l, i))).collect();
    let longest = edges
        .iter()
        .map(|&e| {
            let (a, b) = ends(e);
            distance(dt.point(a), dt.point(b))
        })
        .fold(0.0, f64::max);
    if longest.is_nan() || longest <= 0.0 {
        return Vec::new();
    }
    let cell = |p: Point| ((p[0] / longest).floor() as i64, (p[1] / longest).floor() as i64);
    let segment = |k: usize| {
        let (a, b) = ends(edges[k]);
        (dt.point(a), dt.point(b))
    };
    let mut found = Vec::new();
    visit_pairs_sharing_cells(edges.len(), segment, cell, |e, f| {
        let (ea, eb) = (edges[e].min(edges[f]), edges[e].max(edges[f]));
        let ((a, b), (c, d)) = (ends(ea), ends(eb));
        let adjacent = a == c || a == d || b == c || b == d;
        if !adjacent && segments_meet(dt.point(a), dt.point(b), dt.point(c), dt.point(d)) {
            found.push((ea, eb));
        }
        false
    });
    found.sort_unstable();
    found.dedup();
    found
}

/// Repairs the crossings of the closed sequence `seq` by 2-opt moves (reversing the run
/// between two crossing edges), in passes of disjoint moves; false if a crossing or touch
/// remains after [`MAX_REPAIR_PASSES`] passes or cannot be undone by a move.
fn untangle(dt: &Triangulation, seq: &mut Vec<u32>) -> bool {
    if seq.len() < 3 {
        return false;
    }
    for _ in 0..MAX_REPAIR_PASSES {
        let found = meeting_edges(dt, std::slice::from_ref(seq));
        if found.is_empty() {
            return true;
        }
        let mut busy_until = None;
        for ((_, i), (_, j)) in found {
            let (a, b, c, d) = (seq[i], seq[(i + 1) % seq.len()], seq[j], seq[(j + 1) % seq.len()]);
            if !segments_cross(dt.point(a), dt.point(b), dt.point(c), dt.point(d)) {
                return false; // a touch: no move makes it a proper crossing to undo
            }
            if busy_until.is_some_and(|end| i <= end) {
                continue;
            }
            seq[i + 1..=j].reverse();
            busy_until = Some(j + 1);
        }
    }
    meeting_edges(dt, std::slice::from_ref(seq)).is_empty()
}

/// Whether two different loops cross or touch.
fn loops_meet(dt: &Triangulation, loops: &[Vec<u32>]) -> bool {
    loops.len() > 1 && meeting_edges(dt, loops).iter().any(|(e, f)| e.0 != f.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proximity::nearest::nearest_vertex_distances;
    use crate::samplers::Rng;
    use std::f64::consts::TAU;

    fn noisy_circle(n: usize, noise: f64, seed: u64) -> Vec<Point> {
        let mut rng = Rng::new(seed);
        let spacing = TAU / n as f64;
        (0..n)
            .map(|i| {
                let a = TAU * (i as f64 + 0.6 * (rng.uniform() - 0.5)) / n as f64;
                let r = 1.0 + noise * spacing * (2.0 * rng.uniform() - 1.0);
                [r * a.cos(), r * a.sin()]
            })
            .collect()
    }

    /// A coarse loop too small for a sampled curve is dropped, and its points stay
    /// outliers, only when the fine reading had left every one of them out already.
    #[test]
    fn small_coarse_loops_of_known_outliers_are_dropped() {
        let small_loops =
            Finding { kind: FindingKind::SmallLoops, count: 1, worst: 3.0, at: 7, point: [0.0; 2] };
        let curve: Vec<u32> = (10..40).collect();
        let loops = || vec![vec![7, 8, 9], curve.clone()];
        let (kept, settled) = passing_loops(loops(), &[small_loops], &[7, 8, 9, 50]).unwrap();
        assert_eq!((kept, settled), (vec![curve.clone()], vec![7, 8, 9]));
        // One of the small loop's points is a curve point: the level fails.
        assert!(passing_loops(loops(), &[small_loops], &[7, 9]).is_none());
        // Another failing finding: the level fails whatever the loops.
        let sliver = Finding {
            kind: FindingKind::DoublesBack,
            count: 1,
            worst: 170.0,
            at: 12,
            point: [0.0; 2],
        };
        assert!(passing_loops(loops(), &[small_loops, sliver], &[7, 8, 9]).is_none());
        // Nothing fails: every loop is kept.
        assert_eq!(passing_loops(loops(), &[], &[]).unwrap().0.len(), 2);
    }

    #[test]
    fn thinning_keeps_points_apart_and_covers_the_rest() {
        let points = noisy_circle(400, 0.3, 1);
        let dt = Triangulation::new(&points).unwrap();
        let mut r = nearest_vertex_distances(&dt);
        r.sort_by(f64::total_cmp);
        let radius = 3.0 * r[r.len() / 2];
        let order = hilbert_order(|v| dt.point(v), dt.num_vertices());
        let kept = thin(&dt, &order, radius);
        for (i, &a) in kept.iter().enumerate() {
            for &b in &kept[i + 1..] {
                assert!(distance(dt.point(a), dt.point(b)) >= radius);
            }
        }
        // Every point is within the radius of a kept one.
        for v in 0..dt.num_vertices() as u32 {
            assert!(kept.iter().any(|&k| distance(dt.point(v), dt.point(k)) < radius || k == v));
        }
        assert!(kept.len() < 400 && kept.len() > 10, "{}", kept.len());
    }

    #[test]
    fn a_crossing_is_undone() {
        // A square read as a bow tie.
        let points = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let dt = Triangulation::new(&points).unwrap();
        let v = dt.vertex_of_inputs();
        let mut seq = vec![v[0], v[2], v[1], v[3]];
        assert!(untangle(&dt, &mut seq));
        assert!(meeting_edges(&dt, std::slice::from_ref(&seq)).is_empty());
        assert_eq!(seq.len(), 4);
    }

    #[test]
    fn a_noisy_circle_reads_as_one_loop_through_its_points() {
        let points = noisy_circle(300, 0.5, 7);
        let dt = Triangulation::new(&points).unwrap();
        let spacing = nearest_vertex_distances(&dt);
        let fine = coarse_reading(&dt, &Steps::default(), &[], &spacing).expect("a fine reading");
        assert_eq!(fine.loops.len(), 1);
        assert_eq!(fine.loops[0].len() + fine.outliers.len(), 300);
        assert!(fine.outliers.is_empty());
    }
}
