//! The benchmark's data model and its per-case CSV file.
//!
//! A benchmark run is one [`BenchData`]: the labelled cases, the methods, one [`Entry`] per
//! case and method, and the proximity-graph statistics. [`write_results_csv`] writes one row
//! per entry and [`read_results_csv`] reads it back, so a report can be regenerated without
//! running the methods again.
use std::io::{self, Read, Write};

use sigdt_lab::dataset;

use super::csv::{parse_csv, quote};

/// One labelled point set of the data folder: its row of `index.csv`, as the lab's
/// [`dataset`] reader gives it, and what the benchmark computes about it.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// Name, category, number of points and the `epsilon` column of `index.csv`.
    pub row: dataset::Case,
    /// The sampling ε computed by this benchmark (graph lfs, variant E), if computed.
    pub graph_epsilon: Option<f64>,
}

/// The result of a method that ran to completion on one case.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// The output equals the ground truth: no missing and no extra edge.
    pub exact: bool,
    /// The method's own status, as it displays (for example `manifold` or `sculpt-failed`).
    pub status: String,
    /// Number of output edges.
    pub edges: usize,
    /// Ground-truth edges missing from the output.
    pub missing: usize,
    /// Output edges not in the ground truth.
    pub extra: usize,
    /// Wall-clock time of the reconstruction in milliseconds, excluding I/O.
    pub time_ms: f64,
    /// Two-sided RMS distance to the ground-truth curve, normalised by its diagonal.
    pub rmse: Option<f64>,
    /// Hausdorff distance to the ground-truth curve, normalised by its diagonal.
    pub hausdorff: Option<f64>,
    /// Symmetric difference of area, normalised by the ground truth's bounding-box area.
    pub symdiff: Option<f64>,
    /// The result judged against the case's true curve, for cases that have one
    /// (`NAME.curve.xy` and `NAME.curve.gt`).
    pub curve: Option<CurveScore>,
}

/// A result judged against the case's true curve as a user would (`docs/evaluation.md`,
/// "Judged as a user would").
///
/// A result is good, the answer a user can take as is, when it has the truth's topology,
/// covers its region (IoU at least [`GOOD_IOU`](Self::GOOD_IOU)) and stays near its curve
/// (Hausdorff distance at most [`hausdorff_bound_over_s`](Self::hausdorff_bound_over_s)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveScore {
    /// Area of the intersection over area of the union of the result's region and the true
    /// one, both even-odd (`sigdt_lab::eval::region_overlap`).
    pub iou: f64,
    /// As many polygons, holes and open paths as the truth.
    pub topology_right: bool,
    /// The symmetric Hausdorff distance to the true curve over the case's spacing (its
    /// `spacing` column, else the median ground-truth edge length); infinite for a result
    /// without edges, `None` when the case gives no spacing.
    pub hausdorff_over_s: Option<f64>,
    /// The most [`hausdorff_over_s`](Self::hausdorff_over_s) of a good result: 1 + d_max / s,
    /// where d_max is the largest distance from a labelled point (one on some ground-truth
    /// edge) to the true curve (`sigdt_lab::eval::stray`): 1 on clean data, more on noisy data, where
    /// the input points themselves stray that far. `None` when the case gives no spacing (or
    /// in a `results.csv` written before it): then no result is good.
    pub hausdorff_bound_over_s: Option<f64>,
    /// The result said it may be wrong (`Reconstruction::warns`); imported results never do.
    pub warned: bool,
    /// The points the result passes through no edge of, against the truth's; `None` for a
    /// method that places vertices of its own.
    pub left_out: Option<LeftOut>,
}

/// The points a result leaves without edges, counted against the ground truth: the truth's
/// points without edges are its outliers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LeftOut {
    /// Points without ground-truth edges.
    pub outliers: usize,
    /// Of those, the ones the result leaves without edges too.
    pub outliers_left_out: usize,
    /// Points on the true curve that the result leaves without edges.
    pub curve_points_left_out: usize,
}

impl LeftOut {
    /// Counts over `n` points, of the edges of the `result` and of the `truth`.
    pub fn count(n: usize, result: &[[usize; 2]], truth: &[[usize; 2]]) -> LeftOut {
        let touched = |edges: &[[usize; 2]]| {
            let mut seen = vec![false; n];
            for &[i, j] in edges {
                if i != j {
                    seen[i] = true;
                    seen[j] = true;
                }
            }
            seen
        };
        let (r, t) = (touched(result), touched(truth));
        let mut count = LeftOut::default();
        for (in_result, in_truth) in r.into_iter().zip(t) {
            match (in_truth, in_result) {
                (false, false) => {
                    (count.outliers, count.outliers_left_out) =
                        (count.outliers + 1, count.outliers_left_out + 1)
                }
                (false, true) => count.outliers += 1,
                (true, false) => count.curve_points_left_out += 1,
                (true, true) => {}
            }
        }
        count
    }
}

impl CurveScore {
    /// The least IoU of a good result.
    pub const GOOD_IOU: f64 = 0.95;

    /// Topology right, IoU at least [`Self::GOOD_IOU`] and the Hausdorff distance to the
    /// true curve within its bound: at most one spacing farther from it than the labelled
    /// points themselves are. A spike out to an outlier is not good, however little area it
    /// adds.
    pub fn good(&self) -> bool {
        let near = match (self.hausdorff_over_s, self.hausdorff_bound_over_s) {
            (Some(h), Some(bound)) => h <= bound,
            _ => false,
        };
        self.topology_right && self.iou >= Self::GOOD_IOU && near
    }

    /// Good, and no warning: the answer a user can take as is.
    pub fn good_silent(&self) -> bool {
        self.good() && !self.warned
    }

    /// Good, but warned: a false alarm.
    pub fn good_warned(&self) -> bool {
        self.good() && self.warned
    }

    /// Not good, and no warning said so.
    pub fn silent_wrong(&self) -> bool {
        !self.good() && !self.warned
    }
}

/// How one method fared on one case.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The method finished.
    Done(Run),
    /// The method crashed or returned an error; the message says which.
    Failed(String),
    /// The method was stopped at the time limit, in seconds.
    TimedOut(f64),
}

/// One method on one case.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Index into [`BenchData::cases`].
    pub case: usize,
    /// The method's name in kebab case, as on the command line.
    pub method: String,
    /// What happened.
    pub outcome: Outcome,
}

/// One proximity-graph overlap statistic (`docs/algorithms.md` §4.10).
#[derive(Clone, Debug, PartialEq)]
pub struct OverlapStat {
    /// The statistic, for example `recon in SIGDT`.
    pub name: String,
    /// The mean over the manifold cases of the per-case percentage.
    pub mean_percent: f64,
    /// The percentage of cases where one set is fully contained in the other, if meaningful.
    pub sets_contained_percent: Option<f64>,
    /// The paper's value, if it gives one.
    pub paper_percent: Option<f64>,
}

/// Everything a benchmark report is made from.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchData {
    /// The data folder that was run.
    pub data_dir: String,
    /// The command line that produced the data.
    pub command: String,
    /// A one-line description of the machine.
    pub machine: String,
    /// The time limit per run, in seconds.
    pub time_limit_s: f64,
    /// The methods, in the order they are reported.
    pub methods: Vec<String>,
    /// The cases, in the order of `index.csv`.
    pub cases: Vec<Case>,
    /// One entry per case and method.
    pub entries: Vec<Entry>,
    /// The proximity-graph overlap statistics (may be empty).
    pub overlap: Vec<OverlapStat>,
    /// Manifold cases with `epsilon` below this are "well sampled" (the paper uses 1).
    pub eps_threshold: f64,
    /// The half of each case, by index into [`cases`](Self::cases): the `half` column of
    /// `index.csv` (`design`, `held-out`), empty (or shorter than the cases) without one.
    pub halves: Vec<String>,
}

impl BenchData {
    /// The half of case `case` (`index.csv`'s `half` column), `""` when it has none.
    pub fn half(&self, case: usize) -> &str {
        self.halves.get(case).map_or("", String::as_str)
    }
}

impl Default for BenchData {
    fn default() -> Self {
        BenchData {
            data_dir: String::new(),
            command: String::new(),
            machine: String::new(),
            time_limit_s: 0.0,
            methods: Vec::new(),
            cases: Vec::new(),
            entries: Vec::new(),
            overlap: Vec::new(),
            eps_threshold: 1.0,
            halves: Vec::new(),
        }
    }
}

/// The columns of `results.csv`, in order: those of earlier versions, then the
/// [`CurveScore`] (empty for cases without a true curve; its Hausdorff bound last), then the
/// case's half (empty without a `half` column in `index.csv`).
pub const CSV_HEADER: [&str; 28] = [
    "name",
    "category",
    "n_points",
    "epsilon",
    "graph_epsilon",
    "method",
    "outcome",
    "exact",
    "status",
    "edges",
    "missing",
    "extra",
    "time_ms",
    "rmse",
    "hausdorff",
    "symdiff",
    "message",
    "iou",
    "topology_right",
    "hausdorff_over_s",
    "warned",
    "good",
    "silent_wrong",
    "outliers",
    "outliers_left_out",
    "curve_points_left_out",
    "hausdorff_bound_over_s",
    "half",
];

/// The columns of `results.csv` before the [`CurveScore`], and before its Hausdorff bound
/// and the half: such files are still read.
const OLD_COLUMNS: [usize; 2] = [17, 26];

/// The columns before the [`CurveScore`]'s.
const CURVE_START: usize = OLD_COLUMNS[0];

/// Writes one row per entry (case × method) with the header [`CSV_HEADER`].
///
/// `outcome` is `ok`, `failed` or `timeout`. A failure keeps its message in `message`; a
/// time-out writes its limit in `time_ms`. Missing numbers are empty fields. Fields with a
/// comma, a quote or a line break are quoted, with quotes doubled.
pub fn write_results_csv(data: &BenchData, mut w: impl Write) -> io::Result<()> {
    writeln!(w, "{}", CSV_HEADER.join(","))?;
    for entry in &data.entries {
        let case = data
            .cases
            .get(entry.case)
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "entry names no case"))?;
        let mut row = vec![
            case.row.name.clone(),
            case.row.category.clone(),
            case.row.n_points.to_string(),
            opt(case.row.epsilon),
            opt(case.graph_epsilon),
            entry.method.clone(),
        ];
        let curve = match &entry.outcome {
            Outcome::Done(Run { curve: Some(c), .. }) => curve_fields(c),
            _ => Default::default(),
        };
        row.extend(match &entry.outcome {
            Outcome::Done(r) => [
                "ok".into(),
                u8::from(r.exact).to_string(),
                r.status.clone(),
                r.edges.to_string(),
                r.missing.to_string(),
                r.extra.to_string(),
                r.time_ms.to_string(),
                opt(r.rmse),
                opt(r.hausdorff),
                opt(r.symdiff),
                String::new(),
            ],
            Outcome::Failed(message) => outcome_row("failed", String::new(), message.clone()),
            Outcome::TimedOut(limit) => {
                let message = format!("timed out after {limit} s");
                outcome_row("timeout", (limit * 1000.0).to_string(), message)
            }
        });
        row.extend(curve);
        row.push(data.half(entry.case).to_string());
        let fields: Vec<String> = row.iter().map(|f| quote(f)).collect();
        writeln!(w, "{}", fields.join(","))?;
    }
    Ok(())
}

/// Reads a file written by [`write_results_csv`], or by a version before the [`CurveScore`]
/// columns or before the Hausdorff bound and the half (no result read from such a file is
/// good: [`CurveScore::hausdorff_bound_over_s`]).
///
/// Cases and methods are listed in the order they first appear. The fields that the CSV does
/// not hold (`data_dir`, `command`, `machine`, `overlap`) are left empty, and `time_limit_s`
/// is the largest time-out found (0 if none).
// Lets a report be regenerated without rerunning; the runner need not call it.
#[cfg_attr(not(test), allow(dead_code))]
pub fn read_results_csv(mut r: impl Read) -> io::Result<BenchData> {
    let mut text = String::new();
    r.read_to_string(&mut text)?;
    let mut records = parse_csv(&text).into_iter();
    let header = records.next().unwrap_or_default();
    if header != CSV_HEADER && !OLD_COLUMNS.iter().any(|&n| header == CSV_HEADER[..n]) {
        return Err(invalid(1, "the header is not that of results.csv"));
    }
    let mut data = BenchData::default();
    for (k, rec) in records.enumerate() {
        let line = k + 2;
        if rec.len() == 1 && rec[0].is_empty() {
            continue;
        }
        if rec.len() != header.len() {
            return Err(invalid(line, "wrong number of fields"));
        }
        let case = match data.cases.iter().position(|c| c.row.name == rec[0]) {
            Some(i) => i,
            None => {
                let row = dataset::Case {
                    name: rec[0].clone(),
                    category: rec[1].clone(),
                    n_points: num(&rec[2], line)?,
                    epsilon: opt_num(&rec[3], line)?,
                };
                data.cases.push(Case { row, graph_epsilon: opt_num(&rec[4], line)? });
                data.halves.push(rec.get(CSV_HEADER.len() - 1).cloned().unwrap_or_default());
                data.cases.len() - 1
            }
        };
        if !data.methods.contains(&rec[5]) {
            data.methods.push(rec[5].clone());
        }
        let outcome = match rec[6].as_str() {
            "ok" => Outcome::Done(Run {
                exact: rec[7] == "1",
                status: rec[8].clone(),
                edges: num(&rec[9], line)?,
                missing: num(&rec[10], line)?,
                extra: num(&rec[11], line)?,
                time_ms: num(&rec[12], line)?,
                rmse: opt_num(&rec[13], line)?,
                hausdorff: opt_num(&rec[14], line)?,
                symdiff: opt_num(&rec[15], line)?,
                curve: read_curve(&rec[CURVE_START..], line)?,
            }),
            "failed" => Outcome::Failed(rec[16].clone()),
            "timeout" => {
                let limit = num::<f64>(&rec[12], line)? / 1000.0;
                data.time_limit_s = data.time_limit_s.max(limit);
                Outcome::TimedOut(limit)
            }
            other => return Err(invalid(line, &format!("unknown outcome {other:?}"))),
        };
        data.entries.push(Entry { case, method: rec[5].clone(), outcome });
    }
    if data.halves.iter().all(String::is_empty) {
        data.halves.clear();
    }
    Ok(data)
}

/// The outcome columns of a run that did not finish.
fn outcome_row(outcome: &str, time_ms: String, message: String) -> [String; 11] {
    let mut row: [String; 11] = Default::default();
    row[0] = outcome.into();
    row[6] = time_ms;
    row[10] = message;
    row
}

/// The [`CurveScore`] columns of a run.
fn curve_fields(c: &CurveScore) -> [String; 10] {
    let flag = |b: bool| u8::from(b).to_string();
    let count =
        |f: fn(&LeftOut) -> usize| c.left_out.as_ref().map_or(String::new(), |l| f(l).to_string());
    [
        c.iou.to_string(),
        flag(c.topology_right),
        opt(c.hausdorff_over_s),
        flag(c.warned),
        flag(c.good()),
        flag(c.silent_wrong()),
        count(|l| l.outliers),
        count(|l| l.outliers_left_out),
        count(|l| l.curve_points_left_out),
        opt(c.hausdorff_bound_over_s),
    ]
}

/// The [`CurveScore`] of the columns from [`CURVE_START`]: `None` when they are empty or
/// absent (`good` and `silent_wrong` follow from the others).
fn read_curve(fields: &[String], line: usize) -> io::Result<Option<CurveScore>> {
    let Some(iou) = fields.first().filter(|f| !f.is_empty()) else { return Ok(None) };
    Ok(Some(CurveScore {
        iou: num(iou, line)?,
        topology_right: fields[1] == "1",
        hausdorff_over_s: opt_num(&fields[2], line)?,
        hausdorff_bound_over_s: match fields.get(9) {
            Some(bound) => opt_num(bound, line)?,
            None => None,
        },
        warned: fields[3] == "1",
        left_out: match fields.get(6).filter(|f| !f.is_empty()) {
            None => None,
            Some(outliers) => Some(LeftOut {
                outliers: num(outliers, line)?,
                outliers_left_out: num(&fields[7], line)?,
                curve_points_left_out: num(&fields[8], line)?,
            }),
        },
    }))
}

fn opt(x: Option<f64>) -> String {
    x.map(|v| v.to_string()).unwrap_or_default()
}

fn num<T: std::str::FromStr>(s: &str, line: usize) -> io::Result<T> {
    s.parse().map_err(|_| invalid(line, &format!("not a number: {s:?}")))
}

fn opt_num(s: &str, line: usize) -> io::Result<Option<f64>> {
    if s.is_empty() {
        Ok(None)
    } else {
        num(s, line).map(Some)
    }
}

fn invalid(line: usize, message: &str) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, format!("results.csv, row {line}: {message}"))
}

#[cfg(test)]
#[path = "record_tests.rs"]
mod tests;
