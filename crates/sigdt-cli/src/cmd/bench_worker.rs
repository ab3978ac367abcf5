//! `sigdt bench-worker` (hidden): one method on one labelled case, or the score of another
//! tool's result file (`--score`), one result line on stdout. `sigdt bench` runs one such
//! process per (case, method) and per imported result, under its time limit; see
//! [`bench::worker`](crate::bench::worker).

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use sigdt::{Method, Options};
use sigdt_lab::dataset::CaseFiles;

use crate::bench::worker;

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
    /// The points of the curve the case was sampled from, to measure distances against.
    #[arg(long, requires = "curve_gt")]
    pub curve: Option<PathBuf>,
    /// The edges of that curve.
    #[arg(long, requires = "curve")]
    pub curve_gt: Option<PathBuf>,
    /// The spacing the points were sampled at: the unit of the Hausdorff distance to the
    /// curve (default: the median ground-truth edge length).
    #[arg(long, value_name = "S", value_parser = positive)]
    pub spacing: Option<f64>,
    /// Method.
    #[arg(long, value_parser = crate::methods::parser(),
          required_unless_present_any = ["score", "epsilon"])]
    pub method: Option<Method>,
    /// Score this edge file (another tool's result) instead of running a method.
    #[arg(long, value_name = "EDGES", conflicts_with = "method")]
    pub score: Option<PathBuf>,
    /// Print the graph-based epsilon of the case (`graph_epsilon=E`) instead.
    #[arg(long, conflicts_with_all = ["method", "score"])]
    pub epsilon: bool,
    /// Timed runs after the warm-up.
    #[arg(long, default_value_t = 5)]
    pub repeat: usize,
}

/// `sigdt bench-worker`: prints one result line.
pub fn run(args: &WorkerArgs) -> Result<()> {
    if args.epsilon {
        println!("graph_epsilon={:e}", worker::graph_epsilon(&args.points, &args.gt)?);
        return Ok(());
    }
    let files = CaseFiles {
        points: args.points.clone(),
        gt: args.gt.clone(),
        truth: args.truth.clone(),
        curve: args.curve.clone().zip(args.curve_gt.clone()),
    };
    let run = match (&args.score, args.method) {
        (Some(edges), _) => worker::score_file(&files, args.spacing, edges)?,
        (None, Some(method)) => {
            let options = Options { method, ..Options::default() };
            worker::measure(&files, args.spacing, &options, args.repeat)?
        }
        (None, None) => anyhow::bail!("bench-worker needs --method or --score"),
    };
    println!("{}", run.line());
    Ok(())
}

fn positive(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if s.is_finite() && s > 0.0 => Ok(s),
        _ => Err(format!("'{text}' is not a number > 0")),
    }
}
