//! One benchmark run, from the selected cases to the data of its report: the graph-based ε
//! of every case, every (case, method) pair in a worker process, the imported results of
//! other tools, the proximity-graph statistics, the halves of the cases and a description
//! of the machine.

use std::path::PathBuf;

use anyhow::{bail, Result};

use super::overlap;
use super::record::{BenchData, Case};
use super::runner::{self, Plan};

/// Runs `plan` on `cases`, then scores each `(label, folder)` of `imports` as one more
/// method; `time_limit_s` is the limit as given, for the report.
pub fn run(
    plan: &Plan<'_>,
    time_limit_s: f64,
    imports: &[(String, PathBuf)],
    mut cases: Vec<Case>,
) -> Result<BenchData> {
    runner::fill_graph_epsilon(plan, &mut cases)?;
    let mut entries = runner::run_all(plan, &cases)?;
    let mut methods = plan.methods.to_vec();
    for (label, dir) in imports {
        if !dir.is_dir() {
            bail!("{}: --import folder does not exist", dir.display());
        }
        entries.extend(runner::import(label, dir, plan, &cases)?);
        methods.push(label.clone());
    }
    let half = super::cases::halves(plan.dir)?;
    let halves = cases.iter().map(|c| half.get(&c.row.name).cloned().unwrap_or_default());
    let halves = halves.collect();
    Ok(BenchData {
        data_dir: plan.dir.display().to_string(),
        command: std::env::args().collect::<Vec<_>>().join(" "),
        machine: machine(),
        time_limit_s,
        methods,
        overlap: overlap::overlap_stats(plan.dir, &cases),
        cases,
        entries,
        eps_threshold: 1.0,
        halves,
    })
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
