//! `sigdt sample`: an eps-sample of a cubic Bézier path of an SVG file, with its ground
//! truth (and clean positions when lfs noise is added); or, with `--junctions`, a sample of
//! the whole drawing whose curves cross or end on one another, every junction one shared
//! point of the ground truth.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use sigdt_lab::curves;

use crate::labelled::{eps_sample, pick, write_labelled, Labelled};

/// `sigdt sample`.
#[derive(Debug, Args)]
pub struct SampleArgs {
    /// SVG file with cubic Bézier <path> elements (transforms are ignored).
    #[arg(value_name = "SVG")]
    pub svg: PathBuf,
    /// Target epsilon: every curve point is within eps x lfs of a sample, spacing maximal.
    #[arg(long, value_name = "EPS", required_unless_present = "junctions")]
    pub eps: Option<f64>,
    /// Sample every path of the file together, cut where curves cross (X), where an open
    /// curve ends on another (T) or where ends meet, each junction one shared point (a
    /// non-manifold ground truth). Spacing from --spacing instead of eps.
    #[arg(long, conflicts_with_all = ["eps", "offset", "path", "lfs_noise"])]
    pub junctions: bool,
    /// With --junctions: the distance between samples along each curve, a fraction of the
    /// drawing's bounding-box diagonal.
    #[arg(long, value_name = "F", default_value_t = 0.02, requires = "junctions")]
    pub spacing: f64,
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
    let labelled = match args.eps {
        Some(eps) => {
            let path = pick(&paths, args.path, &args.svg)?;
            let labelled =
                eps_sample(path, eps, args.offset, args.lfs_noise, args.seed, !args.ordered)?;
            // A curve that crosses itself has no manifold ground truth: the edges would cross
            // where two samples should share a junction (issue 30, G18).
            let clean = labelled.truth.as_ref().unwrap_or(&labelled.points);
            if let Some(([i, j], _)) = sigdt::internals::first_crossing(clean, &labelled.gt) {
                let at = |k: usize| clean[k];
                anyhow::bail!(
                    "{}: path {} crosses itself (between {:?} and {:?}): its ground truth \
                     would cross; sample the drawing with --junctions, which joins crossing \
                     curves at a shared point",
                    args.svg.display(),
                    args.path,
                    at(i),
                    at(j)
                );
            }
            labelled
        }
        None => {
            if paths.is_empty() {
                anyhow::bail!("{}: no <path> with curve data", args.svg.display());
            }
            let junctions = curves::sample_with_junctions(&paths, args.spacing)?;
            let sample = junctions.sample;
            let sample = if args.ordered { sample } else { sample.shuffled(args.seed) };
            crate::messages::note(&format!(
                "{} points, {} crossings, {} T-junctions, {} shared ends",
                sample.points.len(),
                junctions.crossings,
                junctions.tees,
                junctions.shared_ends
            ));
            Labelled { points: sample.points, gt: sample.edges, truth: None, curve: None }
        }
    };
    write_labelled(&args.output, &labelled, &args.svg)
}
