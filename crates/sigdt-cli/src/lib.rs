//! `sigdt`: reconstruct curves from unorganised 2D points on the command line.
//!
//! The command line is a library so that two programs can run it: the `sigdt` binary
//! (`main.rs`) and the Python package's `sigdt` script and `python -m sigdt` (through the
//! extension `sigdt._core`). It is not an API: [`run`] takes the arguments and returns the
//! exit status, and a usage error or a signal may end the process from inside.
//!
//! [`run`] only parses the arguments, runs the command and maps errors to exit statuses:
//! 0 for success, 1 for an error (one line `sigdt: <message>` on stderr), 2 for a usage
//! error (reported by clap).
//!
//! Each subcommand has a file of its own in [`cmd`], holding its arguments beside the code
//! that runs it. The commands share [`input`] (reading points and ground truth),
//! [`messages`] (stderr), [`methods`] (the `--method` parser), [`labelled`] (labelled
//! samples and their files), [`output`] and [`format`](mod@format); none of those imports a command.

mod bench;
mod cli;
mod cmd;
mod format;
mod gis;

/// Longitude/latitude reconstructed in a local plane: for the Python package.
#[doc(hidden)]
pub use gis::local::reconstruct_in_plane;
mod input;
mod labelled;
mod messages;
mod methods;
mod output;
mod png;
mod progress;
mod read;
mod stream;
mod view;

use std::ffi::OsString;
use std::io::Write;

use clap::{CommandFactory, Parser};

use crate::cli::{Cli, Command};
use crate::input::Input;
use crate::messages::UsageError;

pub use bench::runner::set_worker_command;

/// Why [`read_points_file`] failed, so that a caller can raise the matching exception.
#[derive(Debug)]
pub enum ReadError {
    /// The file cannot be opened or read (`sigdt::Error::Io`).
    Io(sigdt::Error),
    /// The request does not fit the file (`columns` of a format without columns) or is not
    /// understood (bad `columns`).
    Usage(String),
    /// The file's content is not points: the message names the file (and line).
    Data(String),
}

/// The points of the file at `path` in any format the command line reads (with `columns`
/// as `--columns`, `layer` as `--layer`, and at most `max_points`), one reader for the
/// binary and the Python package's `read_points`.
pub fn read_points_file(
    path: &std::path::Path,
    columns: Option<&str>,
    layer: Option<&str>,
    max_points: usize,
) -> Result<Vec<sigdt::Point>, ReadError> {
    let columns = parse_columns(columns)?;
    let input = Input::new(max_points, columns).with_gis(layer.map(str::to_string), None);
    input.points(path).map_err(read_error)
}

/// [`read_points_file`] of `bytes` named `name` (whose extension chooses the reader as a
/// file's would): for the fuzz targets of the readers.
#[doc(hidden)]
pub fn read_points_bytes(
    bytes: &[u8],
    name: &str,
    columns: Option<&str>,
    max_points: usize,
) -> Result<Vec<sigdt::Point>, ReadError> {
    let columns = parse_columns(columns)?;
    let how = read::Reading { columns: columns.as_ref(), ..read::Reading::at_most(max_points) };
    read::points(bytes, name, how).map(|read| read.points).map_err(read_error)
}

/// `columns` as `--columns` reads them.
fn parse_columns(columns: Option<&str>) -> Result<Option<read::Columns>, ReadError> {
    columns
        .map(|text| text.parse().map_err(|m| ReadError::Usage(format!("columns: {m}"))))
        .transpose()
}

/// The [`ReadError`] of a reader's error.
fn read_error(err: anyhow::Error) -> ReadError {
    if let Some(usage) = err.downcast_ref::<UsageError>() {
        return ReadError::Usage(usage.message.clone());
    }
    match err.downcast::<sigdt::Error>() {
        Ok(io @ sigdt::Error::Io { .. }) => ReadError::Io(io),
        Ok(other) => ReadError::Data(other.to_string()),
        Err(err) => ReadError::Data(messages::one_line(&err)),
    }
}

/// Runs the command line `args` (the first one is the program's name) and returns the exit
/// status. Usage errors found after parsing, and SIGINT, SIGTERM or SIGHUP, end the process
/// from inside with status 2 or 130.
pub fn run(args: impl IntoIterator<Item = OsString>) -> u8 {
    let status = run_command(args);
    // Text written without a final newline must not wait for a process exit to be flushed.
    let _ = std::io::stdout().flush();
    status
}

fn run_command(args: impl IntoIterator<Item = OsString>) -> u8 {
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(err) => return clap_exit(&err),
    };
    let input = Input::new(cli.max_points, cli.columns.clone())
        .with_gis(cli.layer.clone(), cli.crs.clone());
    output::remove_pending_on_signals();
    // A pool of its own, not the global one: the Python package runs this in process, and
    // rayon's global pool panics when it cannot start its threads.
    let result =
        thread_count(cli.threads, std::env::var_os("RAYON_NUM_THREADS")).and_then(|threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .map_err(|e| {
                    anyhow::anyhow!(
                        "cannot start {threads} threads ({e}): use fewer with --threads, or \
                         free memory"
                    )
                })
                .and_then(|pool| pool.install(|| run_subcommand(cli.command, &input)))
        });
    match result {
        Ok(()) => 0,
        Err(err) => match err.downcast_ref::<UsageError>() {
            Some(usage) => usage.exit(Cli::command()),
            None => {
                messages::note(&format!("sigdt: {}", messages::one_line(&err)));
                1
            }
        },
    }
}

/// The threads to run on: `--threads`, else `RAYON_NUM_THREADS` (rayon's own variable, 0
/// meaning every core), else every core; at most the cores, since the output is the same at
/// every count and more threads only cost memory. A variable that is not a count is a usage
/// error.
fn thread_count(flag: Option<usize>, variable: Option<OsString>) -> anyhow::Result<usize> {
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let wanted = match (flag, variable) {
        (Some(threads), _) => threads,
        (None, Some(value)) => match value.to_str().map(str::trim).map(str::parse::<usize>) {
            Some(Ok(0)) => cores,
            Some(Ok(threads)) => threads,
            _ => {
                return Err(UsageError {
                    command: "",
                    kind: clap::error::ErrorKind::InvalidValue,
                    message: format!(
                        "RAYON_NUM_THREADS={}: not a thread count (a whole number; 0 or unset \
                         for every core)",
                        sigdt::io::quoted(&value.to_string_lossy())
                    ),
                }
                .into())
            }
        },
        (None, None) => cores,
    };
    Ok(wanted.min(cores))
}

fn run_subcommand(command: Command, input: &Input) -> anyhow::Result<()> {
    match command {
        Command::Reconstruct(args) => cmd::reconstruct::run(&args, input),
        Command::Graph(args) => cmd::graph::run(&args, input),
        Command::Bench(args) => cmd::bench::run(&args),
        Command::Eval(args) => cmd::eval::run(&args, input),
        Command::Sample(args) => cmd::sample::run(&args),
        Command::Perturb(args) => cmd::perturb::run(&args, input),
        Command::Sweep(args) => cmd::sweep::run(&args),
        Command::Render(args) => cmd::render::run(&args, input),
        Command::Gallery(args) => cmd::gallery::run(&args),
        Command::View(args) => cmd::view::run(&args, input),
        Command::Completions(args) => cmd::completions::completions(&args),
        Command::Manpages(args) => cmd::completions::manpages(&args),
        Command::BenchWorker(args) => cmd::bench_worker::run(&args),
    }
}

/// Prints clap's help, version or usage error and returns its exit status, or 1 when the
/// text cannot be written (`--help > /dev/full` must not report success).
fn clap_exit(err: &clap::Error) -> u8 {
    let printed = err.print().and_then(|()| std::io::stdout().flush());
    match printed {
        Ok(()) => err.exit_code().clamp(0, 255) as u8,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => 0,
        Err(e) => {
            messages::note(&format!("sigdt: <stdout>: {e}"));
            1
        }
    }
}
