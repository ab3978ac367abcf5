//! `sigdt sweep`: RMSE and exact rate of every method against a noise level, an outlier
//! share, an lfs-noise level or the sampling density eps (the paper's Figures 14 and
//! 16-18).
//!
//! For each level the perturbed sets are written as a labelled folder
//! (`OUT/data/KIND_LEVEL/`, with `.truth.xy` clean positions for noise and, for the Bézier
//! sweeps, `.curve.xy`/`.curve.gt` the dense curve) and run through the `bench` machinery, so
//! a crash or time-out is recorded like any other result. RMSE is measured against the clean
//! ground-truth polygon for the labelled sweeps and against the Bézier curve itself for the
//! lfs-noise and eps sweeps, as in the paper. `sets.csv` records per set whether SIGDT
//! contains the ground truth ([MOW22] Fig. 14's claim; the bound on exactness of every
//! SIGDT-based method).
//!
//! [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::{bail, Context, Result};
use clap::builder::RangedU64ValueParser;
use clap::{Args, ValueEnum};
use sigdt_lab::{curves, dataset};

use crate::bench::record::{Case, Outcome};
use crate::bench::{cases, chart, runner};
use crate::labelled::{eps_sample, pick, write_labelled, Labelled};
use crate::messages::{note, UsageError};

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
    #[arg(long, value_name = "M1,M2,...|all", default_value = "all",
          value_parser = crate::methods::list_parser())]
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

/// Start offsets per eps-sampled set: k / 20, as in the paper's Bézier experiment.
const OFFSETS: usize = 20;

/// `sigdt sweep`.
pub fn run(args: &SweepArgs) -> Result<()> {
    let methods = crate::methods::names(&args.method)?;
    let levels =
        if args.levels.is_empty() { default_levels(args.kind) } else { args.levels.clone() };
    if let Some(bad) = levels.iter().find(|l| !l.is_finite() || **l < 0.0) {
        bail!("--levels: {bad} is not a level >= 0");
    }
    if !(args.time_limit.is_finite() && args.time_limit > 0.0) {
        bail!("--time-limit must be a positive number of seconds");
    }
    refuse_output_over_input(&args.out, &args.source)?;
    let mut rows = Vec::new();
    let mut set_rows = Vec::new();
    for (k, &level) in levels.iter().enumerate() {
        let dir = args.out.join("data").join(format!("{}_{level}", kind_name(args.kind)));
        std::fs::create_dir_all(&dir)
            .with_context(|| format!("{}: cannot create the folder", dir.display()))?;
        let sets = generate(args, level, k as u64)?;
        let cases = write_folder(&dir, &sets, &args.source)?;
        for (name, set) in &sets {
            let overlap = sigdt_lab::eval::overlap(&set.points, &set.gt)
                .with_context(|| format!("{}: the proximity graphs of {name}", dir.display()))?;
            let n_points = set.points.len();
            let gt_in_sigdt = overlap.gt_in.sigdt.contains;
            set_rows.push(SetRow { level, name: name.clone(), n_points, gt_in_sigdt });
        }
        note(&format!("level {level}: {} sets x {} methods", cases.len(), methods.len()));
        let plan = runner::Plan {
            dir: &dir,
            methods: &methods,
            time_limit: Duration::from_secs_f64(args.time_limit),
            repeat: 1,
            jobs: args.jobs,
        };
        let entries = runner::run_all(&plan, &cases)?;
        for method in &methods {
            let runs: Vec<_> = entries.iter().filter(|e| &e.method == method).collect();
            let done: Vec<_> = runs
                .iter()
                .filter_map(|e| match &e.outcome {
                    Outcome::Done(run) => Some(run),
                    _ => None,
                })
                .collect();
            let rmse: Vec<f64> = done.iter().filter_map(|r| r.rmse).collect();
            rows.push(Row {
                level,
                method: method.clone(),
                sets: runs.len(),
                done: done.len(),
                exact: done.iter().filter(|r| r.exact).count(),
                mean_rmse: (!rmse.is_empty()).then(|| rmse.iter().sum::<f64>() / rmse.len() as f64),
            });
        }
    }
    write_outputs(args, &methods, &rows, &set_rows)
}

/// One generated set.
struct SetRow {
    level: f64,
    name: String,
    n_points: usize,
    /// SIGDT of the set's points contains every ground-truth edge.
    gt_in_sigdt: bool,
}

/// One (level, method) aggregate.
struct Row {
    level: f64,
    method: String,
    sets: usize,
    done: usize,
    exact: usize,
    mean_rmse: Option<f64>,
}

fn default_levels(kind: SweepKind) -> Vec<f64> {
    match kind {
        SweepKind::Noise => vec![1e-4, 3e-4, 1e-3, 3e-3, 1e-2],
        SweepKind::Outliers => vec![0.01, 0.02, 0.05, 0.1, 0.2],
        SweepKind::LfsNoise => vec![0.05, 0.1, 0.2, 0.3, 0.4, 0.5],
        SweepKind::Eps => vec![0.1, 0.2, 0.3, 0.4, 0.5],
    }
}

fn kind_name(kind: SweepKind) -> &'static str {
    match kind {
        SweepKind::Noise => "noise",
        SweepKind::Outliers => "outliers",
        SweepKind::LfsNoise => "lfs-noise",
        SweepKind::Eps => "eps",
    }
}

/// The labelled sets of one level, named.
fn generate(args: &SweepArgs, level: f64, k: u64) -> Result<Vec<(String, Labelled)>> {
    let seed = |i: usize| 1000 * (k + 1) + i as u64;
    match args.kind {
        SweepKind::Noise | SweepKind::Outliers => {
            let mut cases = cases::select(&args.source, &args.categories, None)?;
            cases.truncate(args.limit.unwrap_or(usize::MAX));
            if cases.is_empty() {
                bail!("{}: no case of the categories {:?}", args.source.display(), args.categories);
            }
            let mut sets = Vec::new();
            for (i, case) in cases.iter().enumerate() {
                let files = case.row.files(&args.source);
                let clean = crate::input::points_of_file(&files.points)?;
                let gt = sigdt_io::text::read_edges_of(&files.gt, clean.len())?;
                let labelled = if args.kind == SweepKind::Noise {
                    let points = sigdt::samplers::uniform_noise(&clean, level, seed(i))?;
                    Labelled { points, gt, truth: Some(clean), curve: None }
                } else {
                    let points = sigdt::samplers::add_outliers(&clean, level, seed(i))?;
                    Labelled { points, gt, truth: None, curve: None }
                };
                sets.push((case.row.name.clone(), labelled));
            }
            Ok(sets)
        }
        SweepKind::LfsNoise | SweepKind::Eps => {
            let paths = curves::read_svg_paths(&args.source)?;
            let path = pick(&paths, args.path, &args.source)?;
            let (eps, noise) =
                if args.kind == SweepKind::Eps { (level, None) } else { (args.eps, Some(level)) };
            // Distances are measured against the Bézier curve itself, as in [MOW22] Figs.
            // 14 and 17, not against the polygon of its samples.
            let curve = path.polyline(curves::DENSE_STEPS);
            (0..OFFSETS)
                .map(|i| {
                    let offset = i as f64 / OFFSETS as f64;
                    let mut set = eps_sample(path, eps, offset, noise, seed(i), true)?;
                    set.curve = Some(curve.clone());
                    Ok((format!("off{i:02}"), set))
                })
                .collect()
        }
    }
}

/// Refuses an output folder that is, or contains, the input (a folder or an SVG file): the
/// sweep writes `data/...`, `index.csv` and charts into it and would overwrite the input.
fn refuse_output_over_input(out: &Path, source: &Path) -> Result<()> {
    if let (Ok(out_dir), Ok(input)) = (std::fs::canonicalize(out), std::fs::canonicalize(source)) {
        if input.starts_with(&out_dir) {
            return Err(UsageError {
                command: "sweep",
                kind: clap::error::ErrorKind::ArgumentConflict,
                message: format!(
                    "--out {} is, or contains, the input {}: choose an output folder outside it",
                    out.display(),
                    source.display()
                ),
            }
            .into());
        }
    }
    Ok(())
}

/// Writes the sets and their index.csv into `dir`; returns them as cases.
fn write_folder(dir: &Path, sets: &[(String, Labelled)], source: &Path) -> Result<Vec<Case>> {
    let mut index = String::from("name,category,n_points,epsilon\n");
    let mut cases = Vec::new();
    for (name, set) in sets {
        write_labelled(&dir.join(format!("{name}.xy")), set, source)?;
        writeln!(index, "{name},sweep,{},", set.points.len()).expect("writing to a String");
        let row = dataset::Case {
            name: name.clone(),
            category: "sweep".into(),
            n_points: set.points.len(),
            epsilon: None,
        };
        cases.push(Case { row, graph_epsilon: None });
    }
    std::fs::write(dir.join("index.csv"), index)
        .with_context(|| format!("{}: cannot write index.csv", dir.display()))?;
    Ok(cases)
}

/// `sweep.csv`, `sets.csv`, `rmse.svg` and `exact.svg` in the output folder.
fn write_outputs(
    args: &SweepArgs,
    methods: &[String],
    rows: &[Row],
    set_rows: &[SetRow],
) -> Result<()> {
    let kind = kind_name(args.kind);
    let mut sets_csv = String::from("kind,level,set,n_points,gt_in_sigdt\n");
    for r in set_rows {
        let contained = u8::from(r.gt_in_sigdt);
        writeln!(sets_csv, "{kind},{},{},{},{contained}", r.level, r.name, r.n_points)
            .expect("writing to a String");
    }
    let mut csv = String::from("kind,level,method,sets,done,exact,mean_rmse\n");
    for r in rows {
        let rmse = r.mean_rmse.map_or(String::new(), |v| format!("{v:e}"));
        writeln!(csv, "{kind},{},{},{},{},{},{rmse}", r.level, r.method, r.sets, r.done, r.exact)
            .expect("writing to a String");
    }
    let series = |value: &dyn Fn(&Row) -> Option<f64>| -> Vec<(String, Vec<(f64, f64)>)> {
        methods
            .iter()
            .map(|m| {
                let points = rows
                    .iter()
                    .filter(|r| &r.method == m)
                    .filter_map(|r| Some((r.level, value(r)?)))
                    .collect();
                (m.clone(), points)
            })
            .collect()
    };
    let x_label = match args.kind {
        SweepKind::Noise => "uniform noise (fraction of the bounding-box diagonal)",
        SweepKind::Outliers => "outliers (fraction of the points)",
        SweepKind::LfsNoise => "lfs noise delta",
        SweepKind::Eps => "sampling epsilon",
    };
    let log_x = matches!(args.kind, SweepKind::Noise | SweepKind::Outliers);
    let rmse = chart::line_chart(
        &format!("RMSE against {kind}"),
        x_label,
        "mean RMSE / diagonal",
        log_x,
        true,
        &series(&|r| r.mean_rmse.filter(|v| *v > 0.0)),
    );
    let mut exact_series =
        series(&|r| (r.sets > 0).then(|| 100.0 * r.exact as f64 / r.sets as f64));
    exact_series.push(("GT in SIGDT".to_string(), contained_share(set_rows)));
    let exact = chart::line_chart(
        &format!("Exact reconstructions against {kind}"),
        x_label,
        "exact (%)",
        log_x,
        false,
        &exact_series,
    );
    let outputs =
        [("sweep.csv", csv), ("sets.csv", sets_csv), ("rmse.svg", rmse), ("exact.svg", exact)];
    for (name, text) in outputs {
        let path = args.out.join(name);
        crate::output::write_file(&path, text.as_bytes())?;
        note(&format!("wrote {}", path.display()));
    }
    Ok(())
}

/// Per level, the percentage of sets whose SIGDT contains the ground truth.
fn contained_share(set_rows: &[SetRow]) -> Vec<(f64, f64)> {
    let mut share: Vec<(f64, usize, usize)> = Vec::new();
    for r in set_rows {
        match share.iter_mut().find(|(level, _, _)| *level == r.level) {
            Some((_, all, yes)) => {
                *all += 1;
                *yes += usize::from(r.gt_in_sigdt);
            }
            None => share.push((r.level, 1, usize::from(r.gt_in_sigdt))),
        }
    }
    share.into_iter().map(|(level, all, yes)| (level, 100.0 * yes as f64 / all as f64)).collect()
}
