//! `sigdt`: reconstruct curves from unorganised 2D points on the command line.
//!
//! The command line is a library behind a thin `main.rs`, and the same binary is what the
//! Python wheel ships as its `sigdt` script (`python/sigdt/_cli.py` runs it). It is not an
//! API: [`run`] takes the arguments and returns the exit status, and a usage error or a
//! signal may end the process from inside. Readers and writers are the crate `sigdt-io`.
//!
//! [`run`] only parses the arguments, runs the command and maps errors to exit statuses:
//! 0 for success, 1 for an error (one line `sigdt: <message>` on stderr), 2 for a usage
//! error (reported by clap).
//!
//! Each subcommand has a file of its own in [`cmd`], holding its arguments beside the code
//! that runs it. The commands share [`input`] (reading points and ground truth),
//! [`messages`] (stderr), [`methods`] (the `--method` parser), [`labelled`] (labelled
//! samples and their files), [`output`], [`format`](mod@format), [`gis_output`] and
//! [`groups`] (`--by`); none of those imports a command.

mod allocation_failure;
mod bench;
mod cli;
mod cmd;
mod format;
mod gis_output;
mod groups;
mod input;
mod labelled;
mod large_blocks;
mod memory;
mod messages;
mod methods;
mod output;
mod png;
mod progress;
mod view;

pub use allocation_failure::ExitOnAllocationFailure;
pub use large_blocks::return_large_blocks_to_the_system;

use std::ffi::OsString;
use std::io::Write;

use clap::{CommandFactory, Parser};

use crate::cli::{Cli, Command};
use crate::input::Input;
use crate::messages::UsageError;

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
        Err(err) => match usage_error(&err) {
            Some(usage) => usage.exit(Cli::command()),
            None => {
                messages::note(&format!("sigdt: {}", messages::one_line(&err)));
                1
            }
        },
    }
}

/// The usage error `err` is, if it is one: the command's own, or a reader's
/// [`sigdt_io::Misuse`] (an option that does not fit the file).
fn usage_error(err: &anyhow::Error) -> Option<UsageError> {
    if let Some(misuse) = err.downcast_ref::<sigdt_io::Misuse>() {
        let kind = clap::error::ErrorKind::ArgumentConflict;
        return Some(UsageError { command: "", kind, message: misuse.message.clone() });
    }
    err.downcast_ref::<UsageError>()
        .map(|usage| UsageError { message: usage.message.clone(), ..*usage })
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
                        sigdt_io::text::quoted(&value.to_string_lossy())
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
        // The definitions are passed down, so that no command imports the command line.
        Command::Completions(args) => cmd::completions::completions(&args, Cli::command()),
        Command::Manpages(args) => cmd::completions::manpages(&args, Cli::command()),
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
