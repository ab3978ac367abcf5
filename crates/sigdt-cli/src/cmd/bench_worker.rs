//! `sigdt bench-worker` (hidden): one method on one labelled case, one result line on
//! stdout. `sigdt bench` runs one such process per (case, method); see
//! [`bench::worker`](crate::bench::worker).

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use sigdt::{Method, Options};

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
    /// Method.
    #[arg(long, value_parser = crate::methods::parser())]
    pub method: Method,
    /// Timed runs after the warm-up.
    #[arg(long, default_value_t = 5)]
    pub repeat: usize,
}

/// `sigdt bench-worker`: prints one result line.
pub fn run(args: &WorkerArgs) -> Result<()> {
    let options = Options { method: args.method, ..Options::default() };
    let run =
        worker::measure(&args.points, &args.gt, args.truth.as_deref(), &options, args.repeat)?;
    println!("{}", run.line());
    Ok(())
}
