//! Arguments of the evaluation commands: `bench`, its hidden worker, and `eval`.

use std::path::PathBuf;

use clap::builder::{PossibleValuesParser, RangedU64ValueParser, TypedValueParser};
use clap::Args;
use sigdt::Method;

/// `sigdt bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// A labelled folder: index.csv (name,category,...,epsilon) and NAME.xy / NAME.gt.
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
    /// Methods to compare, comma-separated, or 'all'.
    #[arg(long, value_name = "M1,M2,...|all", default_value = "all")]
    pub method: String,
    /// Folder for report.md, results.csv and the charts (created if missing).
    #[arg(long, value_name = "DIR", default_value = "bench-report")]
    pub out: PathBuf,
    /// (case, method) pairs run at once; more than one distorts the times.
    #[arg(short, long, value_name = "N", default_value_t = 1,
          value_parser = RangedU64ValueParser::<usize>::new().range(1..=256))]
    pub jobs: usize,
    /// Wall-clock limit per (case, method) pair, in seconds; a pair over it is recorded
    /// as a time-out.
    #[arg(long, value_name = "SECONDS", default_value_t = 60.0, value_parser = positive_seconds)]
    pub time_limit: f64,
    /// Timed runs per pair after a warm-up run (the median is reported; runs slower than
    /// 200 ms are timed once).
    #[arg(long, value_name = "N", default_value_t = 5,
          value_parser = RangedU64ValueParser::<usize>::new().range(1..=1000))]
    pub repeat: usize,
    /// Only these categories, comma-separated.
    #[arg(long, value_name = "C1,C2,...", value_delimiter = ',')]
    pub categories: Vec<String>,
    /// Only cases whose name contains this text.
    #[arg(long, value_name = "TEXT")]
    pub names: Option<String>,
    /// Also score precomputed results of another tool: LABEL=DIR, where DIR holds
    /// NAME.edges ('i j' lines) and optionally times.csv ('name,time_ms'). Repeatable.
    #[arg(long = "import", value_name = "LABEL=DIR", value_parser = import_parser)]
    pub imports: Vec<(String, PathBuf)>,
}

/// `sigdt bench-worker` (internal): one method on one case, one result line on stdout.
#[derive(Debug, Args)]
pub struct WorkerArgs {
    /// Point file.
    pub points: PathBuf,
    /// Ground-truth edge file.
    pub gt: PathBuf,
    /// Clean positions of the points, to measure distances against.
    #[arg(long)]
    pub truth: Option<PathBuf>,
    /// Method.
    #[arg(long, value_parser = method_parser())]
    pub method: Method,
    /// Timed runs after the warm-up.
    #[arg(long, default_value_t = 5)]
    pub repeat: usize,
}

/// `sigdt eval`.
#[derive(Debug, Args)]
pub struct EvalArgs {
    /// Point file, or '-' for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,
    /// Ground-truth edges ('i j' per line, indices into INPUT).
    #[arg(long, value_name = "FILE")]
    pub gt: PathBuf,
    /// Score this edge file instead of running a method.
    #[arg(long, value_name = "FILE", conflicts_with = "method")]
    pub edges: Option<PathBuf>,
    /// Method to run and score.
    #[arg(long, value_name = "METHOD", value_parser = method_parser(),
          default_value_t = Method::default())]
    pub method: Method,
}

/// `--method` values, listed in the help and checked by clap.
pub fn method_parser() -> impl TypedValueParser<Value = Method> {
    let names = Method::ALL.iter().map(|m| m.name());
    PossibleValuesParser::new(names).try_map(|s| s.parse::<Method>())
}

/// Parses the methods of `sigdt bench --method`: a comma-separated list or `all`.
pub fn methods(list: &str) -> Result<Vec<Method>, sigdt::Error> {
    if list.trim() == "all" {
        return Ok(Method::ALL.to_vec());
    }
    let mut methods = Vec::new();
    for name in list.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let method: Method = name.parse()?;
        if !methods.contains(&method) {
            methods.push(method);
        }
    }
    if methods.is_empty() {
        return Err(sigdt::Error::InvalidOption("--method lists no method".into()));
    }
    Ok(methods)
}

fn positive_seconds(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if s.is_finite() && s > 0.0 && s <= 86_400.0 => Ok(s),
        _ => Err(format!("'{text}' is not a number of seconds in (0, 86400]")),
    }
}

fn import_parser(text: &str) -> Result<(String, PathBuf), String> {
    match text.split_once('=') {
        Some((label, dir)) if !label.is_empty() && !dir.is_empty() => {
            if label.chars().any(|c| c.is_whitespace() || c == ',') {
                return Err(format!("label '{label}' may not contain spaces or commas"));
            }
            Ok((label.to_string(), PathBuf::from(dir)))
        }
        _ => Err(format!("'{text}' is not LABEL=DIR")),
    }
}
