//! Runs every (case, method) pair of a benchmark in its own worker process, with a time
//! limit, a progress bar, and as many at once as asked.
//!
//! A worker that exits with an error, crashes, prints nothing usable or outlives the time
//! limit is recorded as a failure or a time-out of that one pair; the run goes on.

use std::collections::HashMap;
use std::ffi::OsStr;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use indicatif::{ProgressBar, ProgressStyle};

use sigdt_lab::dataset;

use super::cases;
use super::record::{Case, Entry, Outcome, Run};

/// What to run: the methods by name and the worker's settings.
pub struct Plan<'a> {
    /// The folder with the cases.
    pub dir: &'a Path,
    /// Method names (as `sigdt reconstruct --method` takes them).
    pub methods: &'a [String],
    /// Per-pair wall-clock limit.
    pub time_limit: Duration,
    /// Timed repetitions per pair (after a warm-up).
    pub repeat: usize,
    /// Pairs run at once.
    pub jobs: usize,
}

/// The program that workers run: this process's own executable. On Linux that is
/// `/proc/self/exe`, which stays the running binary even when a rebuild replaces the file at
/// its path during a long bench (the path would then start the new binary, or nothing).
fn worker_exe() -> Result<PathBuf> {
    let own = Path::new("/proc/self/exe");
    match own.exists() {
        true => Ok(own.to_path_buf()),
        false => std::env::current_exe().context("cannot locate the sigdt executable"),
    }
}

/// Runs `plan` over `cases`; entries are in (case, method) order whatever `jobs` is.
pub fn run_all(plan: &Plan<'_>, cases: &[Case]) -> Result<Vec<Entry>> {
    let exe = worker_exe()?;
    let spacings = cases::spacings(plan.dir)?;
    let tasks: Vec<(usize, &String)> =
        (0..cases.len()).flat_map(|c| plan.methods.iter().map(move |m| (c, m))).collect();
    let bar = ProgressBar::new(tasks.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} {msg}")
            .expect("a valid progress template")
            .progress_chars("=> "),
    );
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Entry>>> = Mutex::new(vec![None; tasks.len()]);
    std::thread::scope(|scope| {
        for _ in 0..plan.jobs.max(1) {
            scope.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                let Some(&(case, method)) = tasks.get(k) else { break };
                let row = &cases[case].row;
                bar.set_message(format!("{} {}", row.name, method));
                let outcome = run_one(&exe, plan, row, spacings.get(&row.name), method);
                let entry = Entry { case, method: method.clone(), outcome };
                results.lock().unwrap_or_else(|e| e.into_inner())[k] = Some(entry);
                bar.inc(1);
            });
        }
    });
    bar.finish_and_clear();
    let results = results.into_inner().unwrap_or_else(|e| e.into_inner());
    Ok(results.into_iter().flatten().collect())
}

/// Runs one worker on `case`, sampled at `spacing` if known, and turns whatever happened into
/// an [`Outcome`].
fn run_one(
    exe: &Path,
    plan: &Plan<'_>,
    case: &dataset::Case,
    spacing: Option<&f64>,
    method: &str,
) -> Outcome {
    let repeat = plan.repeat.to_string();
    let args = ["--method", method, "--repeat", &repeat];
    match spawn_worker(exe, &case.files(plan.dir), spacing, args) {
        Err(e) => Outcome::Failed(format!("cannot start the worker: {e}")),
        Ok(child) => wait(child, plan.time_limit),
    }
}

/// Starts `sigdt bench-worker ARGS POINTS GT [--truth TRUTH] [--curve XY --curve-gt GT]
/// [--spacing S]` on a case's files, its output piped.
fn spawn_worker<A: AsRef<OsStr>>(
    exe: &Path,
    files: &dataset::CaseFiles,
    spacing: Option<&f64>,
    args: impl IntoIterator<Item = A>,
) -> std::io::Result<Child> {
    let mut command = Command::new(exe);
    command.arg("bench-worker").args(args).arg(&files.points).arg(&files.gt);
    if let Some(truth) = &files.truth {
        command.arg("--truth").arg(truth);
    }
    if let Some((points, edges)) = &files.curve {
        command.arg("--curve").arg(points).arg("--curve-gt").arg(edges);
    }
    if let Some(spacing) = spacing {
        command.arg("--spacing").arg(format!("{spacing:e}"));
    }
    command.stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn()
}

/// Waits for `child` at most `limit`, killing it after that, and reads its result line.
fn wait(child: Child, limit: Duration) -> Outcome {
    match finish(child, limit) {
        Err(outcome) => *outcome,
        Ok(stdout) => match stdout.lines().find_map(Run::parse) {
            Some(run) => Outcome::Done(run),
            None => Outcome::Failed(format!("unreadable worker output: {:?}", stdout.trim())),
        },
    }
}

/// The standard output of `child` once it succeeds within `limit`; otherwise the outcome
/// that says what happened (killed after `limit`, failed with its last message), boxed: a
/// finished [`Outcome`] is large, and this one never is.
fn finish(mut child: Child, limit: Duration) -> Result<String, Box<Outcome>> {
    // Drain the pipes on threads so that a chatty worker never blocks on a full pipe.
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = String::new();
            if let Some(pipe) = pipe {
                let _ = pipe.take(1 << 20).read_to_string(&mut text);
            }
            text
        })
    };
    let stdout = drain(child.stdout.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let stderr = drain(child.stderr.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed() >= limit => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(2)),
            Err(e) => {
                return Err(Box::new(Outcome::Failed(format!("waiting for the worker: {e}"))))
            }
        }
    };
    let (stdout, stderr) = (stdout.join().unwrap_or_default(), stderr.join().unwrap_or_default());
    let Some(status) = status else {
        return Err(Box::new(Outcome::TimedOut(limit.as_secs_f64())));
    };
    if !status.success() {
        let message = stderr.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("");
        let message = message.strip_prefix("sigdt: ").unwrap_or(message);
        return Err(Box::new(Outcome::Failed(match status.code() {
            Some(code) => format!("exit status {code}: {message}"),
            None => format!("killed by a signal ({status}): {message}"),
        })));
    }
    Ok(stdout)
}

/// The graph-based epsilon of every case, each computed by a worker under the plan's time
/// limit (on a ground truth with crossing edges it can take minutes); `None` where the
/// files cannot be read, the computation fails or runs out of time.
pub fn fill_graph_epsilon(plan: &Plan<'_>, cases: &mut [Case]) -> Result<()> {
    let exe = worker_exe()?;
    for case in cases.iter_mut() {
        case.graph_epsilon = spawn_worker(&exe, &case.row.files(plan.dir), None, ["--epsilon"])
            .ok()
            .and_then(|child| finish(child, plan.time_limit).ok())
            .and_then(|out| out.trim().strip_prefix("graph_epsilon=")?.parse::<f64>().ok())
            .filter(|e| e.is_finite());
    }
    Ok(())
}

/// Scores precomputed results (`DIR/NAME.edges`, one `i j` a line, and optionally
/// `DIR/times.csv` with `name,time_ms` rows) as method `label`, each in a worker process
/// under the plan's time limit (scoring a wild result, with many crossing edges, is slow).
pub fn import(label: &str, results: &Path, plan: &Plan<'_>, cases: &[Case]) -> Result<Vec<Entry>> {
    let exe = worker_exe()?;
    let times = read_times(&results.join("times.csv"))?;
    let spacings: HashMap<String, f64> = cases::spacings(plan.dir)?;
    let mut entries = Vec::new();
    for (case, c) in cases.iter().enumerate() {
        let edges = results.join(format!("{}.edges", c.row.name));
        let outcome = if edges.is_file() {
            let score = [OsStr::new("--score"), edges.as_os_str()];
            match spawn_worker(&exe, &c.row.files(plan.dir), spacings.get(&c.row.name), score) {
                Err(e) => Outcome::Failed(format!("cannot start the worker: {e}")),
                Ok(child) => match wait(child, plan.time_limit) {
                    Outcome::Done(mut run) => {
                        let time = times.iter().find(|(n, _)| *n == c.row.name);
                        run.time_ms = time.map_or(f64::NAN, |t| t.1);
                        Outcome::Done(run)
                    }
                    other => other,
                },
            }
        } else {
            Outcome::Failed(format!("no result file {}", edges.display()))
        };
        entries.push(Entry { case, method: label.to_string(), outcome });
    }
    Ok(entries)
}

/// `name,time_ms` rows (a header line is skipped); a missing file gives no times.
fn read_times(path: &PathBuf) -> Result<Vec<(String, f64)>> {
    let Ok(text) = std::fs::read_to_string(path) else { return Ok(Vec::new()) };
    let mut times = Vec::new();
    for (k, line) in text.lines().enumerate().skip(1) {
        let Some((name, ms)) = line.split_once(',') else { continue };
        let ms: f64 = ms.trim().parse().with_context(|| {
            format!("{}:{}: '{}' is not a time in ms", path.display(), k + 1, ms.trim())
        })?;
        times.push((name.trim().to_string(), ms));
    }
    Ok(times)
}
