//! Labelled samples of non-manifold drawings: Bézier curves that cross one another
//! (X-junctions), end on one another (T-junctions) or share end points (Y-junctions), with
//! one shared sample at every junction, for the non-manifold evaluation of \[MOW22\] Fig. 19.
//!
//! The ground truth of a non-manifold drawing is a graph, not a set of polygons: a junction
//! is one vertex of degree 3 or 4. [`sample_with_junctions`] builds it:
//!
//! 1. **Ends.** Each end of an open curve joins an end of another curve within the snap
//!    distance (a shared end), or else the nearest point of any curve within it (a
//!    T-junction, cutting that curve there); its own curve counts only half a
//!    segment or more away from the end, in parameter. The junction keeps the end's
//!    position, so ends typed onto a node of their host stay exact.
//! 2. **Crossings.** Every curve is flattened to a polyline of [`CROSSING_STEPS`] points per
//!    segment at half-step parameters (so that nodes typed on a grid are not polyline
//!    vertices), and every pair of polyline edges that crosses (exact orientation tests),
//!    except neighbours on one curve, is an X-junction at the edges' intersection, unless a
//!    junction already lies within 10⁻³ of the diagonal.
//! 3. **Pieces.** Each curve is cut at its junctions' parameters. A piece of arc length `L`
//!    gets `max(round(L / spacing), k)` edges of equal arc length (`k` = 1, or 2 between two
//!    junctions so that no edge is doubled, or 3 for a closed piece), its interior samples
//!    evaluated on the Bézier curve itself; its ends are the junction vertices or the curve's
//!    free ends. A closed curve without junction is one cycle.
//!
//! The snap distance is [`SNAP`] × the drawing's bounding-box diagonal, `spacing` is a
//! fraction of that diagonal too.
//!
//! # Complexity
//! O(E²) for the `E` polyline edges of the crossing search (`E` = 64 × segments; a drawing of
//! a few dozen segments takes milliseconds), plus O(samples).
//!
//! # Errors
//! [`Error::InvalidOption`] for an empty drawing, a non-finite control point, a
//! degenerate drawing (zero diagonal) or a spacing that is not in (0, 1].
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use sigdt::internals::{orient2d, segments_cross};
use sigdt::samplers::Sample;
use sigdt::{Edge, Error, Point, Result};

use super::eps_sampling::diagonal;
use super::BezierPath;

/// Polyline points per Bézier segment in the crossing search.
pub const CROSSING_STEPS: usize = 64;

/// The snap distance of ends, as a fraction of the drawing's bounding-box diagonal.
pub const SNAP: f64 = 1e-3;

/// Crossings closer than this fraction of the diagonal to a junction are that junction (the
/// polylines' chords can cross next to a T-junction).
const MERGE: f64 = 1e-3;

/// Arc-length resolution per segment when spacing samples along a piece.
const LENGTH_STEPS: usize = 256;

/// A labelled non-manifold sample and how many junctions of each kind it has.
#[derive(Debug, Clone, PartialEq)]
pub struct JunctionSample {
    /// The points (ends and junctions first, then the samples of each piece in curve order)
    /// and the ground-truth edges.
    pub sample: Sample,
    /// Crossings of two curves (or of a curve with itself).
    pub crossings: usize,
    /// Ends of open curves lying on another curve.
    pub tees: usize,
    /// Points where two or more ends of open curves meet.
    pub shared_ends: usize,
}

/// A junction vertex on curve `path` at global parameter `u`.
#[derive(Debug, Clone, Copy)]
struct Cut {
    path: usize,
    u: f64,
    vertex: usize,
}

/// The labelled sample of the drawing `paths` with samples `spacing` × its diagonal apart,
/// every junction a shared vertex; see the module docs.
///
/// # Errors
/// See the module docs.
pub fn sample_with_junctions(paths: &[BezierPath], spacing: f64) -> Result<JunctionSample> {
    let bad = |what: String| Error::InvalidOption(format!("cannot sample the drawing: {what}"));
    let paths: Vec<&BezierPath> = paths.iter().filter(|p| !p.segments.is_empty()).collect();
    if paths.is_empty() {
        return Err(bad("it has no curve".into()));
    }
    if paths.iter().flat_map(|p| p.segments.iter().flatten().flatten()).any(|v| !v.is_finite()) {
        return Err(bad("a control point is not finite".into()));
    }
    if !(spacing > 0.0 && spacing <= 1.0) {
        return Err(bad(format!(
            "spacing {spacing} is not in (0, 1] (a fraction of the diagonal)"
        )));
    }
    let lines: Vec<Polyline> = paths.iter().map(|p| Polyline::of(p)).collect();
    let all: Vec<Point> = lines.iter().flat_map(|l| l.points.iter().copied()).collect();
    let diag = diagonal(&all);
    if !(diag > 0.0 && diag.is_finite()) {
        return Err(bad("its curves have no extent".into()));
    }
    let snap = SNAP * diag;
    let mut points: Vec<Point> = Vec::new();
    let mut cuts: Vec<Cut> = Vec::new();
    let (mut tees, mut shared_ends) = (0, 0);

    // 1. Ends of open curves: shared with another end, or on another curve.
    let ends: Vec<(usize, f64, Point)> = paths
        .iter()
        .enumerate()
        .filter(|(_, path)| !path.closed)
        .flat_map(|(k, path)| [0.0, path.segments.len() as f64].map(|u| (k, u, path.point(u))))
        .collect();
    let mut end_vertex: Vec<usize> = Vec::with_capacity(ends.len());
    for (e, &(k, u, at)) in ends.iter().enumerate() {
        let near = |f: &usize| *f != e && dist(ends[*f].2, at) <= snap;
        if let Some(f) = (0..e).find(near) {
            let vertex = end_vertex[f];
            end_vertex.push(vertex);
            cuts.push(Cut { path: k, u, vertex });
            continue;
        }
        let vertex = points.len();
        let shared = (e + 1..ends.len()).any(|f| near(&f));
        let host = if shared {
            None
        } else {
            lines
                .iter()
                .enumerate()
                .filter_map(|(h, line)| {
                    let exclude = (h == k).then_some(u);
                    line.nearest(at, exclude).map(|(d, v)| (d, h, v))
                })
                .filter(|&(d, _, _)| d <= snap)
                .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)))
        };
        match host {
            Some((_, h, v)) => {
                points.push(at);
                cuts.push(Cut { path: h, u: v, vertex });
                tees += 1;
            }
            None => {
                points.push(at);
                shared_ends += usize::from(shared);
            }
        }
        cuts.push(Cut { path: k, u, vertex });
        end_vertex.push(vertex);
    }

    // 2. Crossings between polyline edges.
    let mut crossings = 0;
    for (a, la) in lines.iter().enumerate() {
        for (b, lb) in lines.iter().enumerate().skip(a) {
            for i in 0..la.edges() {
                let first = if a == b { i + 2 } else { 0 };
                for j in first..lb.edges() {
                    if a == b && la.closed && i == 0 && j == la.edges() - 1 {
                        continue; // the closing edge neighbours the first one
                    }
                    let (p, q) = la.edge(i);
                    let (r, s) = lb.edge(j);
                    if !segments_cross(p, q, r, s) {
                        continue;
                    }
                    let (t, w) = intersection(p, q, r, s);
                    let at = lerp(p, q, t);
                    if points.iter().any(|&x| dist(x, at) <= MERGE * diag) {
                        continue;
                    }
                    let vertex = points.len();
                    points.push(at);
                    cuts.push(Cut { path: a, u: la.param(i, t), vertex });
                    cuts.push(Cut { path: b, u: lb.param(j, w), vertex });
                    crossings += 1;
                }
            }
        }
    }

    // 3. Pieces between the cuts of each curve.
    let mut edges: Vec<Edge> = Vec::new();
    for (k, path) in paths.iter().enumerate() {
        let span = path.segments.len() as f64;
        let mut mine: Vec<(f64, usize)> =
            cuts.iter().filter(|c| c.path == k).map(|c| (c.u, c.vertex)).collect();
        mine.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        mine.dedup_by(|x, y| x.1 == y.1 && (x.0 - y.0).abs() < 1e-12);
        let pieces: Vec<(PieceEnd, PieceEnd)> = if path.closed {
            if mine.is_empty() {
                vec![((0.0, None), (span, None))]
            } else {
                (0..mine.len())
                    .map(|i| {
                        let (u0, v0) = mine[i];
                        let (u1, v1) = mine[(i + 1) % mine.len()];
                        let u1 = if i + 1 == mine.len() { u1 + span } else { u1 };
                        ((u0, Some(v0)), (u1, Some(v1)))
                    })
                    .collect()
            }
        } else {
            // Open curves always have cuts at both ends (step 1).
            mine.windows(2).map(|w| ((w[0].0, Some(w[0].1)), (w[1].0, Some(w[1].1)))).collect()
        };
        for (from, to) in pieces {
            piece(path, from, to, spacing * diag, &mut points, &mut edges);
        }
    }
    for e in &mut edges {
        e.sort_unstable();
    }
    edges.sort_unstable();
    edges.dedup();
    Ok(JunctionSample { sample: Sample { points, edges }, crossings, tees, shared_ends })
}

/// An end of a piece: its curve parameter and its vertex (`None`: the curve is closed and
/// has no cut, so the piece is the whole cycle).
type PieceEnd = (f64, Option<usize>);

/// Samples the piece of `path` from `(u0, v0)` to `(u1, v1)` (`u1 > u0`, taken modulo the
/// span on a closed curve), appending its interior points and its edges.
fn piece(
    path: &BezierPath,
    (u0, v0): PieceEnd,
    (u1, v1): PieceEnd,
    spacing: f64,
    points: &mut Vec<Point>,
    edges: &mut Vec<Edge>,
) {
    let steps = (((u1 - u0) * LENGTH_STEPS as f64).ceil() as usize).max(8);
    let params: Vec<f64> = (0..=steps).map(|s| u0 + (u1 - u0) * s as f64 / steps as f64).collect();
    let mut length = vec![0.0];
    for w in params.windows(2) {
        let last = length[length.len() - 1];
        length.push(last + dist(path.point(w[0]), path.point(w[1])));
    }
    let total = length[steps];
    let least = match (v0, v1) {
        (None, _) | (_, None) => 3,
        (Some(a), Some(b)) if a == b => 3,
        _ => 2,
    };
    let n = ((total / spacing).round() as usize).max(least);
    let first = match v0 {
        Some(v) => v,
        None => {
            points.push(path.point(u0));
            points.len() - 1
        }
    };
    let mut previous = first;
    let mut s = 0;
    for k in 1..n {
        let target = total * k as f64 / n as f64;
        while s + 1 < steps && length[s + 1] < target {
            s += 1;
        }
        let f = (target - length[s]) / (length[s + 1] - length[s]).max(f64::MIN_POSITIVE);
        let u = params[s] + f.clamp(0.0, 1.0) * (params[s + 1] - params[s]);
        points.push(path.point(u));
        edges.push([previous, points.len() - 1]);
        previous = points.len() - 1;
    }
    edges.push([previous, v1.unwrap_or(first)]);
}

/// A curve flattened for the crossing search: points at half-step parameters, plus the ends
/// of an open curve.
struct Polyline {
    points: Vec<Point>,
    params: Vec<f64>,
    closed: bool,
}

impl Polyline {
    fn of(path: &BezierPath) -> Polyline {
        let m = path.segments.len() * CROSSING_STEPS;
        let mut params: Vec<f64> =
            (0..m).map(|k| (k as f64 + 0.5) / CROSSING_STEPS as f64).collect();
        if !path.closed {
            params.insert(0, 0.0);
            params.push(path.segments.len() as f64);
        }
        let points = params.iter().map(|&u| path.point(u)).collect();
        Polyline { points, params, closed: path.closed }
    }

    fn edges(&self) -> usize {
        if self.closed {
            self.points.len()
        } else {
            self.points.len() - 1
        }
    }

    fn edge(&self, i: usize) -> (Point, Point) {
        (self.points[i], self.points[(i + 1) % self.points.len()])
    }

    /// The curve parameter at fraction `t` of edge `i`.
    fn param(&self, i: usize, t: f64) -> f64 {
        let u0 = self.params[i];
        let mut u1 = self.params[(i + 1) % self.params.len()];
        if u1 < u0 {
            u1 += self.params.len() as f64 / CROSSING_STEPS as f64; // the closing edge
        }
        u0 + t * (u1 - u0)
    }

    /// The distance from `x` to the polyline and the parameter of the nearest point; edges
    /// within half a segment of parameter `exclude` are skipped.
    fn nearest(&self, x: Point, exclude: Option<f64>) -> Option<(f64, f64)> {
        (0..self.edges())
            .filter(|&i| exclude.map_or(true, |u| (self.param(i, 0.5) - u).abs() >= 0.5))
            .map(|i| {
                let (p, q) = self.edge(i);
                let t = project(p, q, x);
                (dist(lerp(p, q, t), x), self.param(i, t))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }
}

/// The fractions along `pq` and `rs` of their intersection (the segments cross).
fn intersection(p: Point, q: Point, r: Point, s: Point) -> (f64, f64) {
    // Areas from exact orientations: t = |pr s| / (|pr s| - |qr s|), likewise for w.
    let (a, b) = (orient2d(r, s, p), orient2d(r, s, q));
    let (c, d) = (orient2d(p, q, r), orient2d(p, q, s));
    ((a / (a - b)).clamp(0.0, 1.0), (c / (c - d)).clamp(0.0, 1.0))
}

/// The fraction along `pq` of the point nearest to `x`.
fn project(p: Point, q: Point, x: Point) -> f64 {
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    let len2 = dx * dx + dy * dy;
    if len2 == 0.0 {
        return 0.0;
    }
    (((x[0] - p[0]) * dx + (x[1] - p[1]) * dy) / len2).clamp(0.0, 1.0)
}

fn lerp(p: Point, q: Point, t: f64) -> Point {
    [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
}

/// Euclidean distance by `hypot`, which the stored `data/non-manifold` was generated with.
fn dist(p: Point, q: Point) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

#[cfg(test)]
mod tests {
    use super::super::parse_svg_paths;
    use super::*;

    fn drawing(d: &str) -> Vec<BezierPath> {
        let svg: String = d.split('|').map(|d| format!("<path d='{d}'/>")).collect();
        parse_svg_paths(&svg, "t.svg").unwrap()
    }

    /// Vertex degrees, counted as (degree, how many vertices).
    fn degrees(s: &Sample) -> Vec<(usize, usize)> {
        let mut degree = vec![0; s.points.len()];
        for &[i, j] in &s.edges {
            degree[i] += 1;
            degree[j] += 1;
        }
        let mut count = std::collections::BTreeMap::new();
        for d in degree {
            *count.entry(d).or_insert(0) += 1;
        }
        count.into_iter().collect()
    }

    #[test]
    fn a_cross_is_one_shared_vertex_of_degree_four() {
        let j = sample_with_junctions(&drawing("M -1,0 L 1,0|M 0,-1 L 0,1"), 0.1).unwrap();
        assert_eq!((j.crossings, j.tees, j.shared_ends), (1, 0, 0));
        assert_eq!(j.sample.points[4], [0.0, 0.0], "after the four free ends");
        // Four arms of length 1 at spacing 0.1 * 2√2: 4 edges each.
        assert_eq!(degrees(&j.sample), [(1, 4), (2, 12), (4, 1)]);
        assert!(j.sample.edges.windows(2).all(|w| w[0] < w[1]));
        assert!(j.sample.edges.iter().all(|&[a, b]| a < b));
    }

    #[test]
    fn a_chord_ending_on_a_loop_makes_two_tees() {
        // A square loop and a vertical chord from its bottom side to its top side.
        let j =
            sample_with_junctions(&drawing("M 0,0 H 4 V 4 H 0 Z|M 1,0 C 1.5,1 0.5,3 1,4"), 0.05)
                .unwrap();
        assert_eq!((j.crossings, j.tees, j.shared_ends), (0, 2, 0));
        assert_eq!(degrees(&j.sample), [(2, j.sample.points.len() - 2), (3, 2)]);
        assert!(j.sample.points.contains(&[1.0, 0.0]) && j.sample.points.contains(&[1.0, 4.0]));
    }

    #[test]
    fn strokes_from_one_point_share_it() {
        let j =
            sample_with_junctions(&drawing("M 0,0 L 1,0|M 0,0 L 0,1|M -1,-1 L 0,0"), 0.2).unwrap();
        assert_eq!((j.crossings, j.tees, j.shared_ends), (0, 0, 1));
        let centre = j.sample.points.iter().position(|&p| p == [0.0, 0.0]).unwrap();
        let degree = j.sample.edges.iter().filter(|e| e.contains(&centre)).count();
        assert_eq!(degree, 3);
    }

    #[test]
    fn a_loop_without_junction_is_a_cycle_and_a_figure_eight_crosses_itself() {
        let circle = drawing("M 1,0 A 1 1 0 0 1 -1,0 A 1 1 0 0 1 1,0 Z");
        let j = sample_with_junctions(&circle, 0.05).unwrap();
        assert_eq!((j.crossings, j.sample.points.len(), j.sample.edges.len()), (0, 44, 44));
        let eight =
            drawing("M 0,0 C 1,1 2,1 2,0 C 2,-1 1,-1 0,0 C -1,1 -2,1 -2,0 C -2,-1 -1,-1 0,0 Z");
        // The curve passes its own start twice; the crossing at a node is found between
        // half-step polyline edges.
        let j = sample_with_junctions(&eight, 0.05).unwrap();
        assert_eq!(j.crossings, 1);
        assert_eq!(degrees(&j.sample), [(2, j.sample.points.len() - 1), (4, 1)]);
    }

    #[test]
    fn bad_drawings_are_refused() {
        assert!(sample_with_junctions(&[], 0.1).is_err());
        let line = drawing("M 0,0 L 1,0");
        assert!(sample_with_junctions(&line, 0.0).is_err());
        assert!(sample_with_junctions(&line, f64::NAN).is_err());
        let bad = BezierPath { segments: vec![[[0.0, f64::NAN]; 4]], closed: false };
        assert!(sample_with_junctions(&[bad], 0.1).is_err());
    }
}
