//! `sigdt sample`: an eps-sample of a cubic Bézier path of an SVG file, with its ground
//! truth (and clean positions when lfs noise is added).

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use sigdt_lab::curves;

use crate::labelled::{eps_sample, pick, write_labelled};

/// `sigdt sample`.
#[derive(Debug, Args)]
pub struct SampleArgs {
    /// SVG file with cubic Bézier <path> elements (transforms are ignored).
    #[arg(value_name = "SVG")]
    pub svg: PathBuf,
    /// Target epsilon: every curve point is within eps x lfs of a sample, spacing maximal.
    #[arg(long, value_name = "EPS")]
    pub eps: f64,
    /// Start offset along the path, a fraction in [0, 1).
    #[arg(long, value_name = "F", default_value_t = 0.0)]
    pub offset: f64,
    /// Which path (subpath) of the file, counted from 0 in file order.
    #[arg(long, value_name = "K", default_value_t = 0)]
    pub path: usize,
    /// Move each sample along the curve normal by (2U-1) x DELTA x lfs (lfs noise).
    #[arg(long, value_name = "DELTA")]
    pub lfs_noise: Option<f64>,
    /// Seed of the noise and of the point order.
    #[arg(long, value_name = "SEED", default_value_t = 1)]
    pub seed: u64,
    /// Keep the points in curve order instead of a seeded random order.
    #[arg(long)]
    pub ordered: bool,
    /// Output point file; the ground truth goes to the same name with extension .gt, and
    /// with --lfs-noise the clean positions to .truth.xy (what `sigdt bench` measures
    /// distances against).
    #[arg(short, long = "output", value_name = "OUT.xy")]
    pub output: PathBuf,
}

/// `sigdt sample`.
pub fn run(args: &SampleArgs) -> Result<()> {
    let paths = curves::read_svg_paths(&args.svg)?;
    let path = pick(&paths, args.path, &args.svg)?;
    let labelled =
        eps_sample(path, args.eps, args.offset, args.lfs_noise, args.seed, !args.ordered)?;
    write_labelled(&args.output, &labelled, &args.svg)
}
