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

use super::record::Run;

/// How often to run the method for timing: once to warm up, then `repeat` times (fewer
/// when one run takes long), reporting the median.
const SLOW_RUN_MS: f64 = 200.0;

/// The worker's line for a [`Run`]: `key=value` fields; [`Run::parse`] reads it back.
impl Run {
    /// The one-line form.
    pub fn line(&self) -> String {
        let opt = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:e}"));
        format!(
            "exact={} status={} edges={} missing={} extra={} time_ms={:e} rmse={} hausdorff={} \
             symdiff={}",
            u8::from(self.exact),
            self.status,
            self.edges,
            self.missing,
            self.extra,
            self.time_ms,
            opt(self.rmse),
            opt(self.hausdorff),
            opt(self.symdiff)
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
        })
    }
}

/// Runs `options` on the case and measures.
pub fn measure(files: &CaseFiles, options: &Options, repeat: usize) -> Result<Run> {
    let (pts, truth) = read_case(files)?;
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
    score(vertices, indexed_like_input, &truth, &rec.edges, rec.status.name(), time)
        .context("scoring the result")
}

/// The graph-based epsilon of the case (`sigdt_lab::eval::graph_epsilon`).
pub fn graph_epsilon(points: &Path, gt: &Path) -> Result<f64> {
    let pts = sigdt::io::read_points(points)?;
    let gt = sigdt::io::read_edges_of(gt, pts.len())?;
    Ok(sigdt_lab::eval::graph_epsilon(&pts, &gt)?)
}

/// What a result is scored against.
pub struct Truth {
    /// The ground-truth edges, between the input points' indices: exactness.
    pub gt: Vec<Edge>,
    /// The points' clean positions when given, else the input points.
    pub positions: Vec<Point>,
    /// The curve the points were sampled from, as a dense polyline, when given.
    pub curve: Option<(Vec<Point>, Vec<Edge>)>,
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
}

/// A case as read: its input points and what results are scored against.
fn read_case(files: &CaseFiles) -> Result<(Vec<Point>, Truth)> {
    let pts = sigdt::io::read_points(&files.points)?;
    let gt = sigdt::io::read_edges_of(&files.gt, pts.len())?;
    let positions = match &files.truth {
        Some(path) => {
            let clean = sigdt::io::read_points(path)?;
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
            let curve = sigdt::io::read_points(points)?;
            let edges = sigdt::io::read_edges_of(edges, curve.len())?;
            if edges.is_empty() {
                anyhow::bail!("{}: the curve has no edge", points.display());
            }
            Some((curve, edges))
        }
        None => None,
    };
    Ok((pts, Truth { gt, positions, curve }))
}

/// Scores the edge file `edges` (another tool's result on the case) with status
/// `imported`; the time is left NaN for the caller, who has the tool's own times.
pub fn score_file(files: &CaseFiles, edges: &Path) -> Result<Run> {
    let (pts, truth) = read_case(files)?;
    let mut result = sigdt::io::read_edges_of(edges, pts.len())?;
    result.sort_unstable();
    result.dedup();
    score(&pts, true, &truth, &result, "imported", f64::NAN).context("scoring the result")
}

/// Scores `edges`, a result between `vertices`, against `truth`. `indexed_like_input`: vertex
/// `i` of the result is input point `i` (possibly moved), so the edges can be exact; false for
/// a method that places vertices of its own. Distances and areas are measured between the
/// result's vertices and the truth's [reference](Truth::reference) geometry.
pub fn score(
    vertices: &[Point],
    indexed_like_input: bool,
    truth: &Truth,
    edges: &[Edge],
    status: &str,
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
    })
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
        let truth = Truth { gt: square.clone(), positions: square_points.clone(), curve: None };
        let same = score(&square_points, true, &truth, &square, "polygon", 1.0).unwrap();
        assert!(same.exact && same.rmse == Some(0.0));
        let off = score(&moved, true, &truth, &square, "polygon", 1.0).unwrap();
        assert!(off.exact && off.rmse.unwrap() > 0.01 && off.symdiff.unwrap() > 0.1);
        let own = score(&moved, false, &truth, &square, "curves", 1.0).unwrap();
        assert!(!own.exact && own.rmse == off.rmse);
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
        let polygon = Truth { gt: square.clone(), positions: corners.clone(), curve: None };
        let curve =
            Truth { gt: square.clone(), positions: corners.clone(), curve: Some((circle, ring)) };
        let on_polygon = score(&corners, true, &polygon, &square, "polygon", 1.0).unwrap();
        let on_curve = score(&corners, true, &curve, &square, "polygon", 1.0).unwrap();
        assert!(on_polygon.exact && on_curve.exact);
        assert!(on_polygon.rmse.unwrap() < 1e-12);
        // The sagitta of a quarter chord is 1 - cos(pi/4) = 0.29 of the radius, 0.10 of the
        // diagonal 2*sqrt(2); the RMSE is a fraction of that.
        let rmse = on_curve.rmse.unwrap();
        assert!(rmse > 0.02 && rmse < 0.104, "{rmse}");
        assert!(on_curve.symdiff.unwrap() > 0.1);
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
        };
        assert_eq!(Run::parse(&m.line()), Some(m));
        assert_eq!(Run::parse("exact=1 status=polygon"), None);
    }
}
