//! Arguments of the generators: `sample`, `perturb` and `sweep`.

use std::path::PathBuf;

use clap::builder::RangedU64ValueParser;
use clap::{Args, ValueEnum};

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

/// What `sigdt sweep` varies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepKind {
    /// Uniform noise (fraction of the bounding-box diagonal) on labelled cases (paper
    /// Fig. 16).
    Noise,
    /// Outlier share on labelled cases (paper Fig. 18).
    Outliers,
    /// lfs noise on eps-samples of an SVG path (paper Fig. 17).
    LfsNoise,
    /// eps of eps-samples of an SVG path, 20 start offsets each (paper Fig. 14).
    Eps,
}

/// `sigdt sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// What to vary.
    #[arg(value_enum, value_name = "KIND")]
    pub kind: SweepKind,
    /// A labelled folder (noise, outliers) or an SVG file (lfs-noise, eps).
    #[arg(value_name = "SOURCE")]
    pub source: PathBuf,
    /// Levels, comma-separated [default: noise 0.0001,0.0003,0.001,0.003,0.01;
    /// outliers 0.01,0.02,0.05,0.1,0.2; lfs-noise 0.05,0.1,0.2,0.3,0.4,0.5;
    /// eps 0.1,0.2,0.3,0.4,0.5].
    #[arg(long, value_name = "L1,L2,...", value_delimiter = ',')]
    pub levels: Vec<f64>,
    /// Methods, comma-separated, or 'all'.
    #[arg(long, value_name = "M1,M2,...|all", default_value = "all")]
    pub method: String,
    /// Folder for the generated sets, sweep.csv and rmse.svg.
    #[arg(long, value_name = "DIR", default_value = "sweep")]
    pub out: PathBuf,
    /// Labelled cases to perturb: these categories (noise, outliers).
    #[arg(long, value_name = "C1,C2,...", value_delimiter = ',', default_value = "manifold")]
    pub categories: Vec<String>,
    /// Only the first N cases of those categories (noise, outliers).
    #[arg(long, value_name = "N")]
    pub limit: Option<usize>,
    /// eps of the samples for lfs-noise.
    #[arg(long, value_name = "EPS", default_value_t = 0.2)]
    pub eps: f64,
    /// Which SVG path (lfs-noise, eps).
    #[arg(long, value_name = "K", default_value_t = 0)]
    pub path: usize,
    /// Pairs run at once.
    #[arg(short, long, value_name = "N", default_value_t = 1,
          value_parser = RangedU64ValueParser::<usize>::new().range(1..=256))]
    pub jobs: usize,
    /// Wall-clock limit per (set, method), in seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 60.0)]
    pub time_limit: f64,
}
