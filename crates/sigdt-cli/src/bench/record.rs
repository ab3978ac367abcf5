//! The benchmark's data model and its per-case CSV file.
//!
//! A benchmark run is one [`BenchData`]: the labelled cases, the methods, one [`Entry`] per
//! case and method, and the proximity-graph statistics. [`write_results_csv`] writes one row
//! per entry and [`read_results_csv`] reads it back, so a report can be regenerated without
//! running the methods again.
use std::io::{self, Read, Write};

use sigdt_lab::dataset;

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
        }
    }
}

/// The columns of `results.csv`, in order.
pub const CSV_HEADER: [&str; 17] = [
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
];

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
        let fields: Vec<String> = row.iter().map(|f| quote(f)).collect();
        writeln!(w, "{}", fields.join(","))?;
    }
    Ok(())
}

/// Reads a file written by [`write_results_csv`].
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
    if header != CSV_HEADER {
        return Err(invalid(1, "the header is not that of results.csv"));
    }
    let mut data = BenchData::default();
    for (k, rec) in records.enumerate() {
        let line = k + 2;
        if rec.len() == 1 && rec[0].is_empty() {
            continue;
        }
        if rec.len() != CSV_HEADER.len() {
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

fn opt(x: Option<f64>) -> String {
    x.map(|v| v.to_string()).unwrap_or_default()
}

fn quote(field: &str) -> String {
    if field.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", field.replace('"', "\"\""))
    } else {
        field.to_string()
    }
}

/// Splits CSV text into records of unquoted fields (RFC 4180, `\n` or `\r\n` line ends).
fn parse_csv(text: &str) -> Vec<Vec<String>> {
    let mut records = Vec::new();
    let (mut record, mut field) = (Vec::new(), String::new());
    let (mut quoted, mut chars) = (false, text.chars().peekable());
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '"') if chars.peek() == Some(&'"') => {
                chars.next();
                field.push('"');
            }
            (true, '"') => quoted = false,
            (true, c) => field.push(c),
            (false, '"') => quoted = true,
            (false, ',') => record.push(std::mem::take(&mut field)),
            (false, '\r') if chars.peek() == Some(&'\n') => {}
            (false, '\n') => {
                record.push(std::mem::take(&mut field));
                records.push(std::mem::take(&mut record));
            }
            (false, c) => field.push(c),
        }
    }
    if !field.is_empty() || !record.is_empty() {
        record.push(field);
        records.push(record);
    }
    records
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
mod tests {
    use super::*;

    /// Two cases, two methods: a success, a failure with an awkward message, a time-out.
    fn sample() -> BenchData {
        let case = |name: &str, category: &str, n_points, epsilon| Case {
            row: dataset::Case { name: name.into(), category: category.into(), n_points, epsilon },
            graph_epsilon: None,
        };
        let run = Run {
            exact: true,
            status: "manifold".into(),
            edges: 12,
            missing: 0,
            extra: 0,
            time_ms: 0.125,
            rmse: Some(1.5e-7),
            hausdorff: None,
            symdiff: Some(0.0),
        };
        let entry = |case, method: &str, outcome| Entry { case, method: method.into(), outcome };
        BenchData {
            methods: vec!["sig-connect2d".into(), "crust".into()],
            cases: vec![case("a,b", "manifold", 12, Some(0.5)), case("c", "open", 30, None)],
            entries: vec![
                entry(0, "sig-connect2d", Outcome::Done(run)),
                entry(0, "crust", Outcome::Failed("panicked: \"x\", then\nexit 101".into())),
                entry(1, "sig-connect2d", Outcome::TimedOut(2.5)),
            ],
            time_limit_s: 2.5,
            ..BenchData::default()
        }
    }

    #[test]
    fn csv_round_trip() {
        let data = sample();
        let mut buf = Vec::new();
        write_results_csv(&data, &mut buf).unwrap();
        let text = String::from_utf8(buf).unwrap();
        assert!(text.starts_with("name,category,n_points,"));
        assert!(text.contains("\"a,b\",manifold,12,0.5,,sig-connect2d,ok,1,manifold,12,0,0,"));
        assert!(text.contains("\"panicked: \"\"x\"\", then\nexit 101\""));
        assert_eq!(read_results_csv(text.as_bytes()).unwrap(), data);
    }

    #[test]
    fn read_rejects_bad_input() {
        assert!(read_results_csv("x,y\n".as_bytes()).is_err());
        let bad = format!("{}\nc,open,x,,,m,ok,1,s,1,0,0,1,,,,\n", CSV_HEADER.join(","));
        let err = read_results_csv(bad.as_bytes()).unwrap_err();
        assert!(err.to_string().contains("results.csv, row 2"), "{err}");
    }

    #[test]
    fn empty_data_round_trips() {
        let mut buf = Vec::new();
        write_results_csv(&BenchData::default(), &mut buf).unwrap();
        assert_eq!(read_results_csv(&buf[..]).unwrap(), BenchData::default());
    }
}
