//! `sigdt bench`: every method on every case of a labelled folder, side by side, written
//! up as a Markdown report in the layout of the paper's Table 2 with SVG charts.
//!
//! - `dataset`: the folder's `index.csv` and case files;
//! - `runner` and `worker`: one worker process per (case, method), with a time limit;
//! - `overlap`: proximity-graph statistics of the labelled sets;
//! - `record`, `report`, `chart`: the results, the report and its charts.

pub mod chart;
pub mod dataset;
pub mod overlap;
pub mod record;
pub mod report;
pub mod runner;
pub mod worker;

use std::time::Duration;

use anyhow::{bail, Context, Result};

use crate::args_bench::{methods, BenchArgs, EvalArgs, WorkerArgs};
use record::BenchData;

/// `sigdt bench`.
pub fn bench(args: &BenchArgs) -> Result<()> {
    let methods: Vec<String> = methods(&args.method)?.iter().map(|m| m.to_string()).collect();
    let mut cases = dataset::read_index(&args.dir, &args.categories, args.names.as_deref())?;
    if cases.is_empty() {
        bail!("{}: no case matches", args.dir.join("index.csv").display());
    }
    for (k, (label, _)) in args.imports.iter().enumerate() {
        if methods.contains(label) || args.imports[..k].iter().any(|(l, _)| l == label) {
            bail!("--import {label}=...: '{label}' already names a method or another import");
        }
    }
    let same = |a: &std::path::Path, b: &std::path::Path| matches!((a.canonicalize(), b.canonicalize()), (Ok(a), Ok(b)) if a == b);
    if same(&args.out, &args.dir) {
        bail!("{}: --out is the data folder; choose another folder", args.out.display());
    }
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("{}: cannot create the output folder", args.out.display()))?;
    crate::run::note(&format!(
        "sigdt bench: {} cases x {} methods in {}",
        cases.len(),
        methods.len() + args.imports.len(),
        args.dir.display()
    ));
    overlap::fill_graph_epsilon(&args.dir, &mut cases);
    let plan = runner::Plan {
        dir: &args.dir,
        methods: &methods,
        time_limit: Duration::from_secs_f64(args.time_limit),
        repeat: args.repeat,
        jobs: args.jobs,
    };
    let mut entries = runner::run_all(&plan, &cases)?;
    let mut all_methods = methods.clone();
    for (label, dir) in &args.imports {
        if !dir.is_dir() {
            bail!("{}: --import folder does not exist", dir.display());
        }
        entries.extend(runner::import(label, dir, &args.dir, &cases)?);
        all_methods.push(label.clone());
    }
    let data = BenchData {
        data_dir: args.dir.display().to_string(),
        command: std::env::args().collect::<Vec<_>>().join(" "),
        machine: machine(),
        time_limit_s: args.time_limit,
        methods: all_methods,
        overlap: overlap::overlap_stats(&args.dir, &cases),
        cases,
        entries,
        eps_threshold: 1.0,
    };
    let files = report::write_report(&data, &args.out)
        .with_context(|| format!("{}: cannot write the report", args.out.display()))?;
    for file in files {
        crate::run::note(&format!("wrote {}", file.display()));
    }
    Ok(())
}

/// `sigdt bench-worker`: prints one result line.
pub fn worker(args: &WorkerArgs) -> Result<()> {
    let options = sigdt::Options { method: args.method, ..sigdt::Options::default() };
    let run =
        worker::measure(&args.points, &args.gt, args.truth.as_deref(), &options, args.repeat)?;
    println!("{}", run.line());
    Ok(())
}

/// `sigdt eval`: the metrics of one result, one `name: value` a line on stdout.
pub fn evaluate(args: &EvalArgs) -> Result<()> {
    let points = crate::run::read_input(&args.input)?;
    let gt = sigdt::io::read_edges(&args.gt)?;
    let (label, edges) = match &args.edges {
        Some(file) => (file.display().to_string(), sigdt::io::read_edges(file)?),
        None => {
            let options = sigdt::Options { method: args.method, ..sigdt::Options::default() };
            (args.method.to_string(), sigdt::reconstruct(&points, &options)?.edges)
        }
    };
    let m = sigdt_lab::eval::evaluate(&points, &edges, &gt)?;
    let epsilon = sigdt_lab::eval::graph_epsilon(&points, &gt)?;
    let opt = |v: Option<f64>| v.map_or("undefined".to_string(), |v| format!("{v:.6e}"));
    let mut lines = vec![
        format!("result:             {label}"),
        format!("exact:              {}", if m.exact { "yes" } else { "no" }),
        format!("edges:              {} (ground truth {})", edges.len(), gt.len()),
        format!("missing edges:      {}", m.missing),
        format!("extra edges:        {}", m.extra),
        format!("rmse:               {}", opt(m.distance.map(|d| d.rmse))),
        format!("rmse to gt:         {}", opt(m.distance.map(|d| d.rmse_to_gt))),
        format!("hausdorff:          {}", opt(m.distance.map(|d| d.hausdorff))),
        format!("area difference:    {:.6e}", m.area.area),
        format!("area difference / ground-truth box: {}", opt(m.area.normalised)),
        format!("epsilon:            {epsilon:.4} (graph-based, of the labelled sample)"),
    ];
    lines.push(String::new());
    print!("{}", lines.join("\n"));
    Ok(())
}

/// The processor model and core count, for the report's header.
fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|text| {
            text.lines().find_map(|l| {
                l.strip_prefix("model name")?.split_once(':').map(|(_, v)| v.trim().to_string())
            })
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string());
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!("{cpu}, {cores} cores, {}", std::env::consts::OS)
}
