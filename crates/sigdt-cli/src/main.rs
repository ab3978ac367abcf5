//! `sigdt`: reconstruct curves from unorganised 2D points on the command line.
//!
//! `main` only parses the arguments, runs the command and maps errors to exit statuses:
//! 0 for success, 1 for an error (one line `sigdt: <message>` on stderr), 2 for a usage
//! error (reported by clap).

mod args;
mod args_bench;
mod args_generate;
mod args_view;
mod bench;
mod format;
mod generate;
mod output;
mod picture;
mod png;
mod run;
mod sweep;
mod view;

use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = args::parse();
    match run::run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => {
            run::note(&format!("sigdt: {}", run::message(&err)));
            ExitCode::FAILURE
        }
    }
}
