//! The worker: runs one method on one labelled case and prints one line of results.
//!
//! `sigdt bench` starts a worker process per (case, method), so that a crash, an abort or a
//! hang of one method on one case is recorded and never takes the whole run down. The line
//! is `key=value` fields separated by spaces (values have no spaces); see [`Run::line`].

use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result};
use sigdt::{Edge, Options, Point};
use sigdt_lab::dataset::CaseFiles;

use super::record::{CurveScore, LeftOut, Run};

/// How often to run the method for timing: once to warm up, then `repeat` times (fewer
/// when one run takes long), reporting the median.
const SLOW_RUN_MS: f64 = 200.0;

/// The worker's line for a [`Run`]: `key=value` fields; [`Run::parse`] reads it back.
impl Run {
    /// The one-line form.
    pub fn line(&self) -> String {
        let opt = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:e}"));
        let flag = |b: Option<bool>| b.map_or("-".to_string(), |b| u8::from(b).to_string());
        let curve = self.curve.as_ref();
        format!(
            "exact={} status={} edges={} missing={} extra={} time_ms={:e} rmse={} hausdorff={} \
             symdiff={} iou={} topology_right={} h_over_s={} h_bound={} warned={} left_out={}",
            u8::from(self.exact),
            self.status,
            self.edges,
            self.missing,
            self.extra,
            self.time_ms,
            opt(self.rmse),
            opt(self.hausdorff),
            opt(self.symdiff),
            opt(curve.map(|c| c.iou)),
            flag(curve.map(|c| c.topology_right)),
            opt(curve.and_then(|c| c.hausdorff_over_s)),
            opt(curve.and_then(|c| c.hausdorff_bound_over_s)),
            flag(curve.map(|c| c.warned)),
            curve.and_then(|c| c.left_out).map_or("-".to_string(), |l| format!(
                "{}/{}/{}",
                l.outliers, l.outliers_left_out, l.curve_points_left_out
            )),
        )
    }

    /// Parses [`Run::line`]; `None` if anything is missing or malformed.
    pub fn parse(line: &str) -> Option<Run> {
        let field = |key: &str| {
            line.split_whitespace().find_map(|kv| kv.strip_prefix(key)?.strip_prefix('='))
        };
        let opt = |key: &str| -> Option<Option<f64>> {
            match field(key)? {
                "-" => Some(None),
                text => text.parse().ok().map(Some),
            }
        };
        let curve = match opt("iou")? {
            None => None,
            Some(iou) => Some(CurveScore {
                iou,
                topology_right: field("topology_right")? == "1",
                hausdorff_over_s: opt("h_over_s")?,
                hausdorff_bound_over_s: opt("h_bound")?,
                warned: field("warned")? == "1",
                left_out: match field("left_out")? {
                    "-" => None,
                    text => {
                        let mut counts = text.split('/').map(|c| c.parse().ok());
                        let mut next = || counts.next().flatten();
                        Some(LeftOut {
                            outliers: next()?,
                            outliers_left_out: next()?,
                            curve_points_left_out: next()?,
                        })
                    }
                },
            }),
        };
        Some(Run {
            exact: field("exact")? == "1",
            status: field("status")?.to_string(),
            edges: field("edges")?.parse().ok()?,
            missing: field("missing")?.parse().ok()?,
            extra: field("extra")?.parse().ok()?,
            time_ms: field("time_ms")?.parse().ok()?,
            rmse: opt("rmse")?,
            hausdorff: opt("hausdorff")?,
            symdiff: opt("symdiff")?,
            curve,
        })
    }
}

/// Runs `options` on the case, sampled at `spacing` when known, and measures.
pub fn measure(
    files: &CaseFiles,
    spacing: Option<f64>,
    options: &Options,
    repeat: usize,
) -> Result<Run> {
    let (pts, truth) = read_case(files, spacing)?;
    let run = || sigdt::reconstruct(&pts, options);
    let start = Instant::now();
    let rec = run()?;
    let mut times = vec![start.elapsed().as_secs_f64() * 1e3];
    if times[0] < SLOW_RUN_MS {
        times.clear();
        for _ in 0..repeat.max(1) {
            let start = Instant::now();
            let again = run()?;
            times.push(start.elapsed().as_secs_f64() * 1e3);
            debug_assert_eq!(again, rec);
        }
    }
    times.sort_by(f64::total_cmp);
    // The result's edges index its vertices: the input points, the points it moved
    // (STRETCHDENOISE) or vertices it placed (OPTIMALTRANSPORT, which are not the input's).
    let indexed_like_input = !matches!(rec.vertices, sigdt::Vertices::New(_));
    let time = times[times.len() / 2];
    let vertices = rec.vertex_positions(&pts);
    let status = rec.status.name();
    score(vertices, indexed_like_input, &truth, &rec.edges, status, rec.warns(), time)
        .context("scoring the result")
}

/// The graph-based epsilon of the case (`sigdt_lab::eval::graph_epsilon`).
pub fn graph_epsilon(points: &Path, gt: &Path) -> Result<f64> {
    let pts = crate::input::points_of_file(points)?;
    let gt = sigdt_io::text::read_edges_of(gt, pts.len())?;
    Ok(sigdt_lab::eval::graph_epsilon(&pts, &gt)?)
}

/// What a result is scored against.
#[derive(Clone)]
pub struct Truth {
    /// The ground-truth edges, between the input points' indices: exactness.
    pub gt: Vec<Edge>,
    /// The points' clean positions when given, else the input points.
    pub positions: Vec<Point>,
    /// The curve the points were sampled from, as a dense polyline, when given.
    pub curve: Option<(Vec<Point>, Vec<Edge>)>,
    /// The spacing the points were sampled at, when known: the unit of the Hausdorff
    /// distance to the curve (else the median ground-truth edge length).
    pub spacing: Option<f64>,
    /// `d_max`: how far the labelled input points stray from the curve at most
    /// ([`sigdt_lab::eval::stray`]); 0 without a curve.
    pub stray: f64,
}

impl Truth {
    /// The geometry distances and areas are measured against: the curve when given, else
    /// the ground-truth edges between the clean positions.
    fn reference(&self) -> (&[Point], &[Edge]) {
        match &self.curve {
            Some((points, edges)) => (points, edges),
            None => (&self.positions, &self.gt),
        }
    }

    /// The length the Hausdorff distance to the curve is counted in: the spacing when known,
    /// else the median length of the ground-truth edges; `None` if that is 0.
    fn unit(&self) -> Option<f64> {
        let length = |&[i, j]: &Edge| {
            let (p, q) = (self.positions[i], self.positions[j]);
            (p[0] - q[0]).hypot(p[1] - q[1])
        };
        let median = || {
            let mut lengths: Vec<f64> = self.gt.iter().map(length).collect();
            lengths.sort_by(f64::total_cmp);
            lengths.get(lengths.len() / 2).copied()
        };
        self.spacing.or_else(median).filter(|&u| u > 0.0 && u.is_finite())
    }
}

/// A case as read, sampled at `spacing` when known: its input points and what results are
/// scored against.
fn read_case(files: &CaseFiles, spacing: Option<f64>) -> Result<(Vec<Point>, Truth)> {
    let pts = crate::input::points_of_file(&files.points)?;
    let gt = sigdt_io::text::read_edges_of(&files.gt, pts.len())?;
    let positions = match &files.truth {
        Some(path) => {
            let clean = crate::input::points_of_file(path)?;
            if clean.len() != pts.len() {
                anyhow::bail!(
                    "{}: the clean positions have {} points, the case has {}",
                    path.display(),
                    clean.len(),
                    pts.len()
                );
            }
            clean
        }
        None => pts.clone(),
    };
    let curve = match &files.curve {
        Some((points, edges)) => {
            let curve = crate::input::points_of_file(points)?;
            let edges = sigdt_io::text::read_edges_of(edges, curve.len())?;
            if edges.is_empty() {
                anyhow::bail!("{}: the curve has no edge", points.display());
            }
            Some((curve, edges))
        }
        None => None,
    };
    let stray = curve
        .as_ref()
        .map_or(0.0, |(points, edges)| sigdt_lab::eval::stray(&pts, &gt, (points, edges)));
    Ok((pts, Truth { gt, positions, curve, spacing, stray }))
}

/// Scores the edge file `edges` (another tool's result on the case, sampled at `spacing`
/// when known) with status `imported`, never warned; the time is left NaN for the caller,
/// who has the tool's own times.
pub fn score_file(files: &CaseFiles, spacing: Option<f64>, edges: &Path) -> Result<Run> {
    let (pts, truth) = read_case(files, spacing)?;
    let mut result = sigdt_io::text::read_edges_of(edges, pts.len())?;
    result.sort_unstable();
    result.dedup();
    score(&pts, true, &truth, &result, "imported", false, f64::NAN).context("scoring the result")
}

/// Scores `edges`, a result between `vertices`, against `truth`. `indexed_like_input`: vertex
/// `i` of the result is input point `i` (possibly moved), so the edges can be exact; false for
/// a method that places vertices of its own. Distances and areas are measured between the
/// result's vertices and the truth's [reference](Truth::reference) geometry; where the truth
/// has a curve, the result is also judged against it ([`CurveScore`], with `warned`).
pub fn score(
    vertices: &[Point],
    indexed_like_input: bool,
    truth: &Truth,
    edges: &[Edge],
    status: &str,
    warned: bool,
    time_ms: f64,
) -> Result<Run> {
    let diff = sigdt_lab::eval::edge_diff(edges, &truth.gt);
    // One point array: the result's vertices, then the reference's points.
    let (reference, reference_edges) = truth.reference();
    let r = vertices.len();
    let all = [vertices, reference].concat();
    let reference_edges: Vec<Edge> = reference_edges.iter().map(|&[i, j]| [i + r, j + r]).collect();
    let distances = sigdt_lab::eval::distance_errors(&all, edges, &reference_edges)?;
    let area = sigdt_lab::eval::area_difference(&all, edges, &reference_edges)?;
    let curve = match truth.curve {
        None => None,
        Some(_) => {
            let region = sigdt_lab::eval::region_overlap(&all, edges, &reference_edges)?;
            // The Hausdorff distance is a fraction of the curve's diagonal; none: no edge.
            let hausdorff =
                distances.map_or(f64::INFINITY, |d| d.hausdorff * diagonal(&all, &reference_edges));
            let unit = truth.unit();
            Some(CurveScore {
                iou: region.iou,
                topology_right: region.topology_right(),
                hausdorff_over_s: unit.map(|unit| hausdorff / unit),
                hausdorff_bound_over_s: unit.map(|unit| 1.0 + truth.stray / unit),
                warned,
                left_out: indexed_like_input
                    .then(|| LeftOut::count(vertices.len(), edges, &truth.gt)),
            })
        }
    };
    Ok(Run {
        exact: indexed_like_input && diff.missing.is_empty() && diff.extra.is_empty(),
        status: status.to_string(),
        edges: edges.len(),
        missing: diff.missing.len(),
        extra: diff.extra.len(),
        time_ms,
        rmse: distances.map(|d| d.rmse),
        hausdorff: distances.map(|d| d.hausdorff),
        symdiff: area.normalised,
        curve,
    })
}

/// The diagonal of the bounding box of the ends of `edges`: what [`distance_errors`] divides
/// by when they are the ground truth.
///
/// [`distance_errors`]: sigdt_lab::eval::distance_errors
fn diagonal(points: &[Point], edges: &[Edge]) -> f64 {
    let (lo, hi) = edges
        .iter()
        .flatten()
        .map(|&i| points[i])
        .fold(([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]), |(lo, hi), p| {
            ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])])
        });
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_are_measured_on_their_own_vertices() {
        // The unit square as truth; the result's edges are the same indices on vertices
        // moved 0.1 outward in x. Measured on its own vertices, the result is 0.1 off; as
        // vertices of its own, it is not exact even though its indices match.
        let square_points = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let moved = [[-0.1, 0.0], [1.1, 0.0], [1.1, 1.0], [-0.1, 1.0]];
        let square = vec![[0, 1], [0, 3], [1, 2], [2, 3]];
        let (positions, gt) = (square_points.clone(), square.clone());
        let truth = Truth { gt, positions, curve: None, spacing: None, stray: 0.0 };
        let same = score(&square_points, true, &truth, &square, "polygon", false, 1.0).unwrap();
        assert!(same.exact && same.rmse == Some(0.0));
        let off = score(&moved, true, &truth, &square, "polygon", false, 1.0).unwrap();
        assert!(off.exact && off.rmse.unwrap() > 0.01 && off.symdiff.unwrap() > 0.1);
        let own = score(&moved, false, &truth, &square, "curves", false, 1.0).unwrap();
        assert!(!own.exact && own.rmse == off.rmse);
        // Without a true curve, no curve score.
        assert!(same.curve.is_none() && own.curve.is_none());
    }

    #[test]
    fn a_given_curve_is_the_geometry_measured_against() {
        // The samples are the square's corners; the curve they were taken from is the
        // circle through them. Against the polygon the exact result is 0 off; against the
        // circle it is off by the gap between chords and arcs, and still exact.
        let corners = vec![[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];
        let square = vec![[0, 1], [0, 3], [1, 2], [2, 3]];
        let n = 400;
        let circle: Vec<Point> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                [a.cos(), a.sin()]
            })
            .collect();
        let mut ring: Vec<Edge> = (1..n).map(|k| [k - 1, k]).collect();
        ring.push([0, n - 1]);
        let (gt, positions) = (square.clone(), corners.clone());
        let polygon = Truth { gt, positions, curve: None, spacing: None, stray: 0.0 };
        let curve = Truth { curve: Some((circle, ring)), ..polygon.clone() };
        let on_polygon = score(&corners, true, &polygon, &square, "polygon", true, 1.0).unwrap();
        let on_curve = score(&corners, true, &curve, &square, "polygon", true, 1.0).unwrap();
        assert!(on_polygon.exact && on_curve.exact);
        assert!(on_polygon.rmse.unwrap() < 1e-12);
        // The sagitta of a quarter chord is 1 - cos(pi/4) = 0.29 of the radius, 0.10 of the
        // diagonal 2*sqrt(2); the RMSE is a fraction of that.
        let rmse = on_curve.rmse.unwrap();
        assert!(rmse > 0.02 && rmse < 0.104, "{rmse}");
        assert!(on_curve.symdiff.unwrap() > 0.1);
        // As a user would judge it: the square covers 2/pi of the disc, with its topology;
        // 0.29 off at most, over the median edge length sqrt 2 (no spacing given), or over
        // the spacing when given. A warning is kept; an empty result is infinitely far.
        let judged = on_curve.curve.unwrap();
        assert!((judged.iou - 2.0 / std::f64::consts::PI).abs() < 1e-3, "{judged:?}");
        assert!(judged.topology_right && judged.warned && !judged.good());
        let h = 1.0 - std::f64::consts::FRAC_PI_4.cos();
        assert!((judged.hausdorff_over_s.unwrap() - h / 2f64.sqrt()).abs() < 1e-3, "{judged:?}");
        let spaced = Truth { spacing: Some(0.5), ..curve.clone() };
        let at = score(&corners, true, &spaced, &square, "polygon", false, 1.0).unwrap();
        let judged = at.curve.unwrap();
        assert!((judged.hausdorff_over_s.unwrap() - h / 0.5).abs() < 2e-3, "{judged:?}");
        assert!(judged.silent_wrong());
        let empty = score(&corners, true, &curve, &[], "empty", false, 1.0).unwrap();
        let judged = empty.curve.unwrap();
        assert_eq!((judged.iou, judged.hausdorff_over_s), (0.0, Some(f64::INFINITY)));
        let left_out = LeftOut { outliers: 0, outliers_left_out: 0, curve_points_left_out: 4 };
        assert_eq!(judged.left_out, Some(left_out));
        assert_eq!(on_curve.curve.unwrap().left_out, Some(LeftOut::default()));
        let own = score(&corners, false, &curve, &square, "curves", false, 1.0).unwrap();
        assert_eq!(own.curve.unwrap().left_out, None, "its own vertices: nothing to count");
    }

    /// A circle of radius 1 sampled at `n` points, radius `1 + bump(k)` for sample `k`, and an
    /// outlier 2.5 spacings out between samples 0 and 1; its true curve a dense 720-gon.
    fn sampled_circle(n: usize, bump: impl Fn(usize) -> f64) -> (Vec<Point>, Truth) {
        let at = |a: f64, r: f64| [r * a.cos(), r * a.sin()];
        let s = std::f64::consts::TAU / n as f64;
        let mut points: Vec<Point> = (0..n).map(|k| at(s * k as f64, 1.0 + bump(k))).collect();
        points.push(at(s / 2.0, 1.0 + 2.5 * s));
        let ring = |n: usize| (1..n).map(|k| [k - 1, k]).chain([[0, n - 1]]).collect::<Vec<_>>();
        let curve: Vec<Point> =
            (0..720).map(|k| at(std::f64::consts::TAU * k as f64 / 720.0, 1.0)).collect();
        let gt = ring(n);
        let stray = sigdt_lab::eval::stray(&points, &gt, (&curve, &ring(720)));
        let truth = Truth {
            gt,
            positions: points.clone(),
            curve: Some((curve, ring(720))),
            spacing: Some(s),
            stray,
        };
        (points, truth)
    }

    #[test]
    fn a_spike_out_to_an_outlier_is_not_good_noise_is_forgiven() {
        // Clean samples: the ring is good; through the outlier instead of edge [0, 1], it
        // has the right topology and IoU 0.99 but is 2.5 spacings off: silently wrong.
        let n = 64;
        let (points, truth) = sampled_circle(n, |_| 0.0);
        assert!(truth.stray < 1e-4, "on the 720-gon, up to its sagitta: {}", truth.stray);
        let ring: Vec<Edge> = truth.gt.clone();
        let good = score(&points, true, &truth, &ring, "polygon", false, 1.0).unwrap();
        let judged = good.curve.unwrap();
        assert!(judged.good_silent(), "{judged:?}");
        let mut spike: Vec<Edge> = ring[1..].to_vec();
        spike.extend([[0, n], [1, n]]);
        let judged =
            score(&points, true, &truth, &spike, "polygon", false, 1.0).unwrap().curve.unwrap();
        assert!(judged.topology_right && judged.iou > 0.99, "{judged:?}");
        assert!((judged.hausdorff_over_s.unwrap() - 2.5).abs() < 0.05, "{judged:?}");
        assert!((judged.hausdorff_bound_over_s.unwrap() - 1.0).abs() < 1e-3, "{judged:?}");
        assert!(!judged.good() && judged.silent_wrong(), "{judged:?}");
        // Noisy samples, ±0.3 spacings and one 1.2 spacings out: the ring through them is
        // more than a spacing off, and good; the spike, 2.5 spacings off, is still beyond
        // the bound of 2.2.
        let s = std::f64::consts::TAU / n as f64;
        let bump = |k: usize| match k {
            9 => 1.2 * s,
            k if k % 2 == 0 => 0.3 * s,
            _ => -0.3 * s,
        };
        let (points, truth) = sampled_circle(n, bump);
        assert!((truth.stray / s - 1.2).abs() < 1e-3, "{}", truth.stray / s);
        let judged =
            score(&points, true, &truth, &ring, "polygon", false, 1.0).unwrap().curve.unwrap();
        assert!(judged.hausdorff_over_s.unwrap() > 1.1 && judged.good(), "{judged:?}");
        let judged =
            score(&points, true, &truth, &spike, "polygon", false, 1.0).unwrap().curve.unwrap();
        assert!(judged.iou > 0.95 && !judged.good(), "{judged:?}");
    }

    #[test]
    fn line_round_trips() {
        let m = Run {
            exact: true,
            status: "polygon".into(),
            edges: 4,
            missing: 0,
            extra: 0,
            time_ms: 0.125,
            rmse: Some(1e-3),
            hausdorff: None,
            symdiff: Some(0.0),
            curve: None,
        };
        assert_eq!(Run::parse(&m.line()), Some(m.clone()));
        let curve = CurveScore {
            iou: 0.25,
            topology_right: true,
            hausdorff_over_s: Some(f64::INFINITY),
            hausdorff_bound_over_s: Some(1.25),
            warned: true,
            left_out: Some(LeftOut { outliers: 3, outliers_left_out: 2, curve_points_left_out: 1 }),
        };
        let judged = Run { curve: Some(curve), ..m.clone() };
        assert_eq!(Run::parse(&judged.line()), Some(judged));
        let unspaced = Run {
            curve: Some(CurveScore {
                hausdorff_over_s: None,
                hausdorff_bound_over_s: None,
                left_out: None,
                ..curve
            }),
            ..m
        };
        assert_eq!(Run::parse(&unspaced.line()), Some(unspaced));
        assert_eq!(Run::parse("exact=1 status=polygon"), None);
    }
}
