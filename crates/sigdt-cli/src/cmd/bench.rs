//! `sigdt bench`: every method on every case of a labelled folder, written up as a report.
//! The machinery is in [`bench`](crate::bench); this file checks the arguments and says
//! what was done.

use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::{bail, Context, Result};
use clap::builder::RangedU64ValueParser;
use clap::Args;

use crate::bench::{cases, report, runner, suite};
use crate::messages::note;

/// `sigdt bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// A labelled folder: index.csv (name,category,...,epsilon) and NAME.xy / NAME.gt.
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
    /// Methods to compare, comma-separated, or 'all'.
    #[arg(long, value_name = "M1,M2,...|all", default_value = "all",
          value_parser = crate::methods::list_parser())]
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

/// `sigdt bench`.
pub fn run(args: &BenchArgs) -> Result<()> {
    let methods = crate::methods::names(&args.method)?;
    let cases = cases::select(&args.dir, &args.categories, args.names.as_deref())?;
    if cases.is_empty() {
        bail!("{}: no case matches", args.dir.join("index.csv").display());
    }
    for (k, (label, _)) in args.imports.iter().enumerate() {
        if methods.contains(label) || args.imports[..k].iter().any(|(l, _)| l == label) {
            bail!("--import {label}=...: '{label}' already names a method or another import");
        }
    }
    if same_folder(&args.out, &args.dir) {
        bail!("{}: --out is the data folder; choose another folder", args.out.display());
    }
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("{}: cannot create the output folder", args.out.display()))?;
    note(&format!(
        "sigdt bench: {} cases x {} methods in {}",
        cases.len(),
        methods.len() + args.imports.len(),
        args.dir.display()
    ));
    let plan = runner::Plan {
        dir: &args.dir,
        methods: &methods,
        time_limit: Duration::from_secs_f64(args.time_limit),
        repeat: args.repeat,
        jobs: args.jobs,
    };
    let data = suite::run(&plan, args.time_limit, &args.imports, cases)?;
    let files = report::write_report(&data, &args.out)
        .with_context(|| format!("{}: cannot write the report", args.out.display()))?;
    for file in files {
        note(&format!("wrote {}", file.display()));
    }
    Ok(())
}

/// Whether `a` and `b` are the same existing folder.
fn same_folder(a: &Path, b: &Path) -> bool {
    matches!((a.canonicalize(), b.canonicalize()), (Ok(a), Ok(b)) if a == b)
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
