//! The sampling check: every result read back against the sampling it assumes.
//!
//! [MOW22] Theorem 1 holds for curves sampled with ρ < 1 and local non-uniformity u < 2.
//! Its proof gives two properties of every edge `ab` of the faithful reading, which the check
//! reads back on a result (`r(v)` is the distance from `v` to its nearest other point):
//!
//! 1. **The disk with diameter `ab` is empty** (part 2: `ab` is a Gabriel edge). At a sharp
//!    corner, where ρ < 1 cannot hold, a curve neighbour `c` of `b` can lie in that disk, but
//!    no deeper than `|bc|`, and `|bc| < 2 r(b)` by u < 2. So under u < 2 no sample reaches
//!    **twice the spacing** `2 · max(r(a), r(b))` into the disk, corners included.
//!    Any other sample has no such excuse: under the theorem it lies outside the disk, and
//!    noise moves it in by a fraction of the spacing, so one that reaches **one spacing**
//!    ([`STRAY_DEPTH_RATIO`]) deep is reported too. Slivers and bridges between curves
//!    break this: they pass over the samples they skip, which are not their neighbours.
//!    Finding [`FindingKind::PassesOverSamples`].
//! 2. **The nearest neighbour is a curve neighbour** (part 1), so each edge is shorter than
//!    `2 r` at its ends. An edge at least [`LONG_EDGE_RATIO`] `= 2 · 2` times the spacing at
//!    its far end (twice the bound) is a long edge there. A reading that turns by more than
//!    150° at `v` between two edges that are both long at their far ends goes out to `v`
//!    and comes back: a point wired into a curve it is far from (an outlier), not a sampled
//!    curve, whose samples turn by less than 60° (ε < 1) and, at a corner, leave along its
//!    two sides. Where the point is itself twice as sparse as both its neighbours and the
//!    reading turns by more than 60° at one of them to reach it, edges of twice the spacing
//!    (the bound, not twice it) suffice: a spike out to an outlier two or three spacings
//!    off. Finding [`FindingKind::DoublesBack`].
//!
//! 3. **A closed curve has at least [`MIN_LOOP_POINTS`] samples**: ρ < 1 is ε < 0.5
//!    ([MOW22] Corollary 2), and a circle with `n` evenly spread samples has ε = 2 sin(π/2n),
//!    0.52 for six and 0.45 for seven; any other closed curve needs more. A smaller loop
//!    beside curves of at least that many points is a knot of noise or a curve sampled too
//!    sparsely to tell (a result that is nothing but small loops, such as four points read as
//!    a square, is what was given). Finding [`FindingKind::SmallLoops`].
//!
//! 4. **An open curve ends where its samples end**: the end sample's nearest neighbour is its
//!    curve neighbour (property 2). An open path whose end point has another point nearer
//!    than half its last edge (so that u < 2 fails there even when doubled) stops short of
//!    points it could go on through: a curve broken in two, or closed curve read open.
//!    Finding [`FindingKind::OpenEnds`].
//!
//! 5. **An outlier lies off the curves**: a sample lies on its curve, so a point left out as
//!    an outlier within half its own spacing of an edge of the result is a sample the
//!    reading passed by and dropped (where curves come closer than their spacing, ρ ≥ 1),
//!    not an outlier. So is one nearer to a vertex of the result than half that vertex's
//!    longer edge: by property 2 and u < 2 no other sample is that near (the reading
//!    skipped it and ran on past with a longer edge). And one nearer to an edge of the
//!    result than that edge is long is within the curve's spacing, where noise can put a
//!    sample: no outlier by SIG-AUTO's own rule, so the curve may run through it. Finding
//!    [`FindingKind::OutliersOnCurve`].
//!
//! 6. **A sampled curve turns one way between its inflections**, and its curvature varies
//!    slowly from sample to sample. Loops whose turns reverse at most of their points, with
//!    curvature jumps that put the area they enclose in doubt by more than a twentieth, are
//!    noise (or samples too sparse for their curve): `sampling_check/noisy_area.rs`, finding
//!    [`FindingKind::NoisyArea`].
//!
//! 7. **An open curve ends where its samples end** (property 4 again): two ends of open
//!    paths nearer to each other than [`LONG_EDGE_RATIO`] times their longer last edge
//!    could be joined by an edge like the others: `sampling_check/ends_meet.rs`, finding
//!    [`FindingKind::EndsMeet`].
//!
//! Long straight sides between dense corners (glyphs, buildings) break u < 2 without being
//! wrong; their disks are empty, so neither finding fires on them.
//!
//! The outcome is a list of [`Finding`]s (empty when the result reads as a sampled curve);
//! front ends warn on a non-empty list. It is a diagnosis, not a proof: a result without
//! findings can still be wrong, and a finding does not say which curve the points came from.
//!
//! # Complexity
//! O(k · d) for a result with k vertices of mean Delaunay degree d on readings whose edges
//! are about the point spacing; an edge that passes over samples costs a walk of at most
//! [`MAX_WALK`] steps towards its midpoint. No allocation beyond the findings, but for
//! O(n) neighbour slots when the result left points out as outliers (property 5).
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
mod ends_meet;
mod finding;
mod noisy_area;

use crate::delaunay::Triangulation;
use crate::geometry::{distance, segment_distance};
use ends_meet::{ends_meet, PathEnd};
pub use finding::{Finding, FindingKind};
pub(crate) use noisy_area::noisy_area;
pub use noisy_area::AREA_TOLERANCE;

/// How far (in point spacings `max(r(a), r(b))`) a sample may reach into the disk with
/// diameter `ab` before `ab` is reported: twice, the most that a sampling with u < 2 allows
/// (module docs, property 1).
pub const DEPTH_RATIO: f64 = 2.0;

/// How far (in point spacings) a sample that is *not* a curve neighbour of the edge's ends
/// may reach into its diametral disk before the edge is reported: one spacing. The theorem
/// allows none (every edge is a Gabriel edge); the corner allowance of [`DEPTH_RATIO`] is
/// for a neighbour only. One spacing is the tolerance for noise: a quarter spacing on
/// each of the three points, and the spacing's own variation (module docs, property 1).
pub const STRAY_DEPTH_RATIO: f64 = 1.0;

/// How many times the spacing at its far end an edge must be to count as long where a
/// reading doubles back: twice [MOW22] Theorem 1's bound `u < 2` (module docs, property 2).
///
/// [MOW22]: https://doi.org/10.1111/cgf.14654
pub const LONG_EDGE_RATIO: f64 = 4.0;

/// The fewest points of a loop that a closed curve sampled with ρ < 1 (ε < 0.5) gives
/// (module docs, property 3).
pub const MIN_LOOP_POINTS: usize = 7;

/// The cosine of the largest turn of a curve sampled with ε < 1 at a sample (60°).
const SAMPLED_TURN_COS: f64 = 0.5;

/// The cosine of the turn beyond which a reading doubles back (150°).
const DOUBLING_BACK_COS: f64 = -0.866_025_403_784_438_6;

/// The measures of one edge `ab` of a reading, for [`check_curves`] and the lab.
#[doc(hidden)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgeMeasure {
    /// `|ab| / r(a)` and `|ab| / r(b)`: how much longer the edge is than the point spacing
    /// at each end.
    pub ratio_at: [f64; 2],
    /// How deep the deepest other sample reaches into the disk with diameter `ab`, over
    /// `max(r(a), r(b))` (0 when the disk is empty).
    pub depth: f64,
    /// Whether that sample is the curve's next vertex beyond `a` or `b` (a corner's
    /// neighbour), which may reach [`DEPTH_RATIO`] deep; any other, [`STRAY_DEPTH_RATIO`].
    pub by_neighbour: bool,
    /// `a` and `b` (vertices of the triangulation).
    pub ends: [u32; 2],
}

/// The distance from `v` to its nearest other vertex (its shortest Delaunay edge).
fn nearest_distance(dt: &Triangulation, v: u32) -> f64 {
    dt.incident(v).map(|h| dt.length(h)).fold(f64::INFINITY, f64::min)
}

/// Where the check reads every vertex's nearest-neighbour distance `r(v)`: measured around
/// the vertex, or from the caller's `nearest_vertex_distances` (the same values; a lookup
/// instead of a walk around each vertex, which on a large result read in an order unlike
/// the vertices' misses the cache at every step).
#[derive(Clone, Copy)]
pub(crate) enum Spacing<'a> {
    Measured,
    Known(&'a [f64]),
}

impl Spacing<'_> {
    fn at(self, dt: &Triangulation, v: u32) -> f64 {
        match self {
            Spacing::Measured => nearest_distance(dt, v),
            Spacing::Known(r) => r[v as usize],
        }
    }
}

/// The most steps of the walk towards an edge's midpoint ([`diametral_depth`]): a bound for
/// adversarial results; a walk cut short gives a lower bound of the depth.
const MAX_WALK: usize = 64;

/// `|ab|/2 − d`, where `d` is the distance from the midpoint `m` of `ab` to the nearest
/// other vertex, when that vertex lies in the disk with diameter `ab` (`0` otherwise), and
/// that vertex.
///
/// Found by a greedy walk from an end towards `m` over Delaunay edges: a vertex that is not the
/// nearest to `m` always has a Delaunay neighbour nearer to `m` (the segment from it to `m`
/// leaves its Voronoi cell into a neighbour's), so the walk ends at `m`'s nearest vertex; if
/// that is `a` (or `b`, at the same distance), the disk holds no vertex deeper than its rim.
fn diametral_depth(dt: &Triangulation, a: u32, b: u32) -> (f64, u32) {
    let (pa, pb) = (dt.point(a), dt.point(b));
    let mid = [0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])];
    let half = 0.5 * distance(pa, pb);
    // From the lower-numbered end, so that a walk cut short does not depend on the
    // direction the edge is read in.
    let start = a.min(b);
    let (mut v, mut nearest) = (start, distance(mid, dt.point(start)));
    for _ in 0..MAX_WALK {
        let closer = dt
            .incident(v)
            .map(|h| dt.other(h, v))
            .map(|w| (distance(mid, dt.point(w)), w))
            .filter(|&(d, _)| d < nearest)
            .min_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        match closer {
            Some((d, w)) => (nearest, v) = (d, w),
            None => break,
        }
    }
    if v == a || v == b {
        (0.0, v)
    } else {
        ((half - nearest).max(0.0), v)
    }
}

/// The cosine of the turn at `b` from `ab` onto `bc` (1 for a zero-length edge).
fn turn_cos(dt: &Triangulation, a: u32, b: u32, c: u32) -> f64 {
    let (pa, pb, pc) = (dt.point(a), dt.point(b), dt.point(c));
    let (u, w) = ([pb[0] - pa[0], pb[1] - pa[1]], [pc[0] - pb[0], pc[1] - pb[1]]);
    let norm = u[0].hypot(u[1]) * w[0].hypot(w[1]);
    if norm == 0.0 {
        1.0
    } else {
        ((u[0] * w[0] + u[1] * w[1]) / norm).clamp(-1.0, 1.0)
    }
}

/// Calls `visit` with the measures of every edge of `curve` (vertices of `dt` in order;
/// `closed`: the last joins the first), in order along it.
#[doc(hidden)]
pub fn measure_curve(
    dt: &Triangulation,
    curve: &[u32],
    closed: bool,
    visit: impl FnMut(EdgeMeasure),
) {
    measure_curve_with(dt, curve, closed, Spacing::Measured, visit)
}

fn measure_curve_with(
    dt: &Triangulation,
    curve: &[u32],
    closed: bool,
    spacing: Spacing,
    visit: impl FnMut(EdgeMeasure),
) {
    let edges = edge_count(curve, closed);
    measure_edges(dt, curve, closed, spacing, 0..edges, visit);
}

/// The number of edges of `curve` (`closed`: the last vertex joins the first, when there
/// are three or more).
fn edge_count(curve: &[u32], closed: bool) -> usize {
    match curve.len() {
        0 | 1 => 0,
        n if closed && n >= 3 => n,
        n => n - 1,
    }
}

/// [`measure_curve_with`] on the edges `range` only (edge `k` runs from `curve[k]`).
fn measure_edges(
    dt: &Triangulation,
    curve: &[u32],
    closed: bool,
    spacing: Spacing,
    range: std::ops::Range<usize>,
    mut visit: impl FnMut(EdgeMeasure),
) {
    let n = curve.len();
    if n < 2 || range.is_empty() {
        return;
    }
    let closed = closed && n >= 3;
    let mut r_a = spacing.at(dt, curve[range.start]);
    // The vertex at position `k` along the curve, if there is one.
    let vertex = |k: isize| match closed {
        true => Some(curve[k.rem_euclid(n as isize) as usize]),
        false => usize::try_from(k).ok().and_then(|k| curve.get(k).copied()),
    };
    for k in range {
        let (a, b) = (curve[k], curve[(k + 1) % n]);
        let r_b = spacing.at(dt, b);
        let length = distance(dt.point(a), dt.point(b));
        let (depth, deepest) = diametral_depth(dt, a, b);
        let beside = [vertex(k as isize - 1), vertex(k as isize + 2)];
        visit(EdgeMeasure {
            ratio_at: [length / r_a, length / r_b],
            depth: depth / r_a.max(r_b),
            by_neighbour: beside.contains(&Some(deepest)),
            ends: [a, b],
        });
        r_a = r_b;
    }
}

/// Edges measured on one thread at a time: long curves are split into runs this long.
const EDGES_A_TASK: usize = 4096;

/// The edges of `curve` whose diametral disk holds another vertex deeper than the sampling
/// allows (property 1 of the module docs): each edge's depth and its end of lowest input
/// index, in order along the curve. Long curves are measured in runs on the pool; the
/// result is the same on every thread count.
fn passes_over(
    dt: &Triangulation,
    curve: &[u32],
    closed: bool,
    spacing: Spacing,
) -> Vec<(f64, u32)> {
    let input = |v: u32| dt.input_index(v);
    let runs = crate::parallel::map_chunks(edge_count(curve, closed), EDGES_A_TASK, |range| {
        let mut found = Vec::new();
        measure_edges(dt, curve, closed, spacing, range, |m| {
            let allowed = if m.by_neighbour { DEPTH_RATIO } else { STRAY_DEPTH_RATIO };
            if m.depth >= allowed {
                found.push((m.depth, *m.ends.iter().min_by_key(|&&v| input(v)).unwrap()));
            }
        });
        found
    });
    runs.concat()
}

/// The positions `k` in `curve` (vertices of `dt` in order; `closed`: the last joins the
/// first) where the reading doubles back (property 2 of the module docs), each with its
/// turn in degrees: the reading turns by more than 150° at `curve[k]` between two edges
/// that are each at least [`LONG_EDGE_RATIO`] times the spacing at their far ends.
pub(crate) fn doubling_back(dt: &Triangulation, curve: &[u32], closed: bool) -> Vec<(usize, f64)> {
    doubling_back_with(dt, curve, closed, Spacing::Measured)
}

fn doubling_back_with(
    dt: &Triangulation,
    curve: &[u32],
    closed: bool,
    spacing: Spacing,
) -> Vec<(usize, f64)> {
    let n = curve.len();
    let closed = closed && n >= 3;
    let inner = if closed { 0..n } else { 1..n.saturating_sub(1) };
    let doubles_back = |k: usize| {
        let (a, v, b) = (curve[(k + n - 1) % n], curve[k], curve[(k + 1) % n]);
        let cos = turn_cos(dt, a, v, b);
        if cos >= DOUBLING_BACK_COS {
            return None;
        }
        let far =
            |w: u32, ratio: f64| distance(dt.point(v), dt.point(w)) >= ratio * spacing.at(dt, w);
        // A point whose own spacing is twice its neighbours' on both sides, reached by a turn
        // sharper than a sampled curve's (60°, ε < 1) at one of them at least, is no corner
        // of the curve (whose sides run on straight at both) but a point the reading goes
        // out to: edges beyond the bound `u < 2` itself, not twice it, make it a wired point.
        let isolated = spacing.at(dt, v) >= DEPTH_RATIO * spacing.at(dt, a).max(spacing.at(dt, b))
            && (closed || (k >= 2 && k + 2 < n))
            && (turn_cos(dt, curve[(k + n - 2) % n], a, v) < SAMPLED_TURN_COS
                || turn_cos(dt, v, b, curve[(k + 2) % n]) < SAMPLED_TURN_COS);
        let ratio = if isolated { DEPTH_RATIO } else { LONG_EDGE_RATIO };
        (far(a, ratio) && far(b, ratio)).then(|| (k, cos.acos().to_degrees()))
    };
    // Long curves in runs on the pool, in order: the same on every thread count.
    let runs = crate::parallel::map_chunks(inner.len(), EDGES_A_TASK, |run| {
        run.filter_map(|j| doubles_back(inner.start + j)).collect::<Vec<_>>()
    });
    runs.concat()
}

/// The findings of the sampling check on `curves` (vertices of `dt` in order, each with
/// whether it is closed); `at` in input indices.
pub(crate) fn check_curves<'a>(
    dt: &Triangulation,
    curves: impl IntoIterator<Item = (&'a [u32], bool)>,
) -> Vec<Finding> {
    check_curves_with(dt, curves, Spacing::Measured)
}

fn check_curves_with<'a>(
    dt: &Triangulation,
    curves: impl IntoIterator<Item = (&'a [u32], bool)>,
    spacing: Spacing,
) -> Vec<Finding> {
    let mut over = Tally::new(FindingKind::PassesOverSamples);
    let mut back = Tally::new(FindingKind::DoublesBack);
    let mut small = Tally::new(FindingKind::SmallLoops);
    let mut ends = Tally::new(FindingKind::OpenEnds);
    // Small loops count only beside a curve of sampled size: a lone square of four points
    // is a reading of what was given, a knot of three beside a coastline is noise.
    let mut has_large_curve = false;
    let mut path_ends = Vec::new();
    for (curve, closed) in curves {
        let input = |v: u32| dt.input_index(v);
        if !closed && curve.len() >= 2 {
            let n = curve.len();
            for (end, next) in [(curve[0], curve[1]), (curve[n - 1], curve[n - 2])] {
                let last = distance(dt.point(end), dt.point(next));
                let ratio = last / spacing.at(dt, end);
                if ratio > 2.0 {
                    ends.add(dt, ratio, end);
                }
                path_ends.push(PathEnd { end, next, last });
            }
        }
        if closed && curve.len() < MIN_LOOP_POINTS {
            if let Some(&smallest) = curve.iter().min_by_key(|&&v| input(v)) {
                small.add(dt, -(curve.len() as f64), smallest);
            }
        }
        has_large_curve |= curve.len() >= MIN_LOOP_POINTS;
        for (k, degrees) in doubling_back_with(dt, curve, closed, spacing) {
            back.add(dt, degrees, curve[k]);
        }
        for (depth, at) in passes_over(dt, curve, closed, spacing) {
            over.add(dt, depth, at);
        }
    }
    if !has_large_curve {
        small.count = 0;
    }
    let mut found: Vec<Finding> = [over, back, small, ends]
        .into_iter()
        .filter(|t| t.count > 0)
        .map(|t| t.finding(dt))
        .collect();
    found.extend(ends_meet(dt, &path_ends));
    found
}

/// The findings of the sampling check on `rec`, a result on `dt`'s points (input indices);
/// none for results whose vertices are not the input points, or without triangles.
pub(crate) fn diagnose(dt: &Triangulation, rec: &crate::result::Reconstruction) -> Vec<Finding> {
    diagnose_with(dt, rec, Spacing::Measured)
}

/// [`diagnose`], reading `r(v)` from `spacing`.
pub(crate) fn diagnose_with(
    dt: &Triangulation,
    rec: &crate::result::Reconstruction,
    spacing: Spacing,
) -> Vec<Finding> {
    if rec.vertices != crate::result::Vertices::Input
        || dt.shape() != crate::delaunay::Shape::Proper
    {
        return Vec::new();
    }
    let vertex_of = dt.vertex_of_inputs();
    let as_vertices =
        |curve: &Vec<usize>| -> Vec<u32> { curve.iter().map(|&i| vertex_of[i]).collect() };
    let loops = rec.loops.iter().map(|l| (as_vertices(l), true));
    let curves: Vec<(Vec<u32>, bool)> =
        loops.chain(rec.paths.iter().map(|p| (as_vertices(p), false))).collect();
    let curve_slices = curves.iter().map(|(c, closed)| (c.as_slice(), *closed));
    let mut found = check_curves_with(dt, curve_slices, spacing);
    let outliers: Vec<u32> = rec
        .left_out
        .iter()
        .filter(|l| l.reason == crate::result::LeftOutReason::Outlier)
        .map(|l| vertex_of[l.index])
        .collect();
    if !outliers.is_empty() {
        let on_curve = outliers_on_curve(dt, &outliers, &curves, spacing);
        if on_curve.count > 0 {
            found.push(on_curve.finding(dt));
        }
    }
    let rings: Vec<&[u32]> =
        curves.iter().filter(|(_, closed)| *closed).map(|(c, _)| c.as_slice()).collect();
    found.extend(noisy_area(dt, &rings));
    found
}

/// The finding `open-outlines` of `rec` (a result on `dt`'s points), when the caller said
/// the points outline areas: its open paths, the worst the one whose ends lie farthest
/// apart against its longest edge, at its end of smaller input index. `None` without open
/// paths, or for results on vertices of their own.
pub(crate) fn open_outlines(
    dt: &Triangulation,
    rec: &crate::result::Reconstruction,
) -> Option<Finding> {
    if rec.paths.is_empty() || rec.vertices != crate::result::Vertices::Input {
        return None;
    }
    let vertex_of = dt.vertex_of_inputs();
    let at = |i: usize| dt.point(vertex_of[i]);
    let gap = |path: &Vec<usize>| {
        let longest = path.windows(2).map(|w| distance(at(w[0]), at(w[1]))).fold(0.0, f64::max);
        let ends = distance(at(path[0]), at(path[path.len() - 1]));
        if longest > 0.0 {
            ends / longest
        } else {
            0.0
        }
    };
    let mut worst: Option<(f64, usize)> = None;
    for path in rec.paths.iter().filter(|p| p.len() >= 2) {
        let (g, end) = (gap(path), path[0].min(path[path.len() - 1]));
        if worst.map_or(true, |(w, e)| g > w || (g == w && end < e)) {
            worst = Some((g, end));
        }
    }
    let (worst, at) = worst?;
    let point = given_point(dt, vertex_of[at]);
    Some(Finding { kind: FindingKind::OpenOutlines, count: rec.paths.len(), worst, at, point })
}

/// The `outliers` (vertices of `dt`) that lie within the sampling of `curves` (property 5):
/// within half their own spacing of an edge, or nearer to a curve vertex than half that
/// vertex's longer edge. The worst is the nearest, as a fraction of the spacing it is
/// measured against.
fn outliers_on_curve(
    dt: &Triangulation,
    outliers: &[u32],
    curves: &[(Vec<u32>, bool)],
    r: Spacing,
) -> Tally {
    // The result's neighbours of each vertex.
    let mut next = vec![[u32::MAX; 2]; dt.num_vertices()];
    for (curve, closed) in curves {
        let n = curve.len();
        let edges = if *closed && n >= 3 { n } else { n.saturating_sub(1) };
        for k in 0..edges {
            let (a, b) = (curve[k], curve[(k + 1) % n]);
            for (x, y) in [(a, b), (b, a)] {
                let slots = &mut next[x as usize];
                let free = usize::from(slots[0] != u32::MAX);
                slots[free.min(1)] = y;
            }
        }
    }
    let mut tally = Tally::new(FindingKind::OutliersOnCurve);
    for &v in outliers {
        let (p, spacing) = (dt.point(v), r.at(dt, v));
        let on_curve = |w: u32| next[w as usize].into_iter().filter(|&u| u != u32::MAX);
        let (mut nearest, mut within_spacing) = (f64::INFINITY, false);
        for w in dt.incident(v).map(|h| dt.other(h, v)) {
            // Under u < 2 a vertex's nearest sample is no nearer than half its longer
            // edge: a point nearer than that is inside the curve's sampling.
            let longer =
                on_curve(w).map(|u| distance(dt.point(w), dt.point(u))).fold(0.0, f64::max);
            if longer > 0.0 {
                nearest = nearest.min(distance(p, dt.point(w)) / longer);
            }
            for u in on_curve(w) {
                let off = segment_distance(p, dt.point(w), dt.point(u));
                nearest = nearest.min(off / spacing);
                // The outlier rule's own bound: no nearer to an edge than its length.
                within_spacing |= off < distance(dt.point(w), dt.point(u));
            }
        }
        if nearest < 0.5 || within_spacing {
            // Negated, so that the nearest is the worst.
            tally.add(dt, -nearest, v);
        }
    }
    tally
}

/// Counts one kind of finding and keeps its worst value, at the smallest input index among
/// equal worst values (so that the finding does not depend on where a loop starts).
struct Tally {
    kind: FindingKind,
    count: usize,
    worst: f64,
    at: usize,
    /// The vertex of `at`.
    vertex: u32,
}

impl Tally {
    fn new(kind: FindingKind) -> Tally {
        Tally { kind, count: 0, worst: f64::NEG_INFINITY, at: usize::MAX, vertex: u32::MAX }
    }

    /// Counts `value`, found at vertex `v` of `dt`.
    fn add(&mut self, dt: &Triangulation, value: f64, v: u32) {
        self.count += 1;
        let at = dt.input_index(v);
        if value > self.worst || (value == self.worst && at < self.at) {
            (self.worst, self.at, self.vertex) = (value, at, v);
        }
    }

    fn finding(&self, dt: &Triangulation) -> Finding {
        // Small loops keep the negated size, outliers on curves the negated distance, so
        // that the smallest is the worst.
        let negated = matches!(self.kind, FindingKind::SmallLoops | FindingKind::OutliersOnCurve);
        let worst = if negated { -self.worst } else { self.worst };
        let point = given_point(dt, self.vertex);
        Finding { kind: self.kind, count: self.count, worst, at: self.at, point }
    }
}

/// The coordinates of vertex `v` of `dt` as the caller gave them.
pub(crate) fn given_point(dt: &Triangulation, v: u32) -> [f64; 2] {
    dt.unscale(dt.point(v))
}

#[cfg(test)]
mod tests;
