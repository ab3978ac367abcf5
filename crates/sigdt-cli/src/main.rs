//! `sigdt`: reconstruct curves from unorganised 2D points on the command line.
//!
//! `main` only parses the arguments, runs the command and maps errors to exit statuses:
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
mod input;
mod labelled;
mod messages;
mod methods;
mod output;
mod png;
mod view;

use std::io::Write;
use std::process::ExitCode;

use clap::{CommandFactory, Parser};

use crate::cli::{Cli, Command};
use crate::input::Input;
use crate::messages::UsageError;

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(err) => return clap_exit(&err),
    };
    let input = Input::new(cli.max_points);
    output::remove_pending_on_signals();
    let result = match cli.command {
        Command::Reconstruct(args) => cmd::reconstruct::run(&args, &input),
        Command::Graph(args) => cmd::graph::run(&args, &input),
        Command::Bench(args) => cmd::bench::run(&args),
        Command::Eval(args) => cmd::eval::run(&args, &input),
        Command::Sample(args) => cmd::sample::run(&args),
        Command::Perturb(args) => cmd::perturb::run(&args, &input),
        Command::Sweep(args) => cmd::sweep::run(&args),
        Command::Render(args) => cmd::render::run(&args, &input),
        Command::Gallery(args) => cmd::gallery::run(&args),
        Command::View(args) => cmd::view::run(&args, &input),
        Command::BenchWorker(args) => cmd::bench_worker::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => match err.downcast_ref::<UsageError>() {
            Some(usage) => usage.exit(Cli::command()),
            None => {
                messages::note(&format!("sigdt: {}", messages::one_line(&err)));
                ExitCode::FAILURE
            }
        },
    }
}

/// Prints clap's help, version or usage error and returns its exit status, or 1 when the
/// text cannot be written (`--help > /dev/full` must not report success).
fn clap_exit(err: &clap::Error) -> ExitCode {
    let printed = err.print().and_then(|()| std::io::stdout().flush());
    match printed {
        Ok(()) => ExitCode::from(err.exit_code().clamp(0, 255) as u8),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            messages::note(&format!("sigdt: <stdout>: {e}"));
            ExitCode::FAILURE
        }
    }
}
