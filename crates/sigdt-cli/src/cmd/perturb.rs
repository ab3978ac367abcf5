//! `sigdt perturb`: uniform noise or outliers added to points.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use sigdt::samplers;

use crate::input::Input;
use crate::labelled::points_text;
use crate::output::Output;

/// `sigdt perturb`.
#[derive(Debug, Args)]
pub struct PerturbArgs {
    /// Point file, or '-' for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,
    /// Uniform noise: move each point by S x U1 x diag in direction 2 pi U2 (diag: the
    /// bounding-box diagonal); 0.001 is 0.1 % of the diagonal.
    #[arg(long, value_name = "S", required_unless_present = "outliers")]
    pub noise: Option<f64>,
    /// Append round(Q x n) points uniform in the bounding box (indices n, n+1, ...).
    #[arg(long, value_name = "Q")]
    pub outliers: Option<f64>,
    /// Random seed.
    #[arg(long, value_name = "SEED", default_value_t = 1)]
    pub seed: u64,
    /// Output point file ('-' or none: standard output).
    #[arg(short, long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,
}

/// `sigdt perturb`.
pub fn run(args: &PerturbArgs, input: &Input) -> Result<()> {
    let output = Output::new(args.output.as_deref(), &args.input)?;
    let mut points = input.points(&args.input)?;
    if let Some(s) = args.noise {
        points = samplers::uniform_noise(&points, s, args.seed)?;
    }
    if let Some(q) = args.outliers {
        points = samplers::add_outliers(&points, q, args.seed.wrapping_add(1))?;
    }
    output.write(|w| w.write_all(points_text(&points).as_bytes()))
}
