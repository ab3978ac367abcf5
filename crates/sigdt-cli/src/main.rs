//! `sigdt`: reconstruct curves from unorganised 2D points on the command line. The command
//! line lives in the library ([`sigdt_cli::run`]), which the Python package runs too.

use std::process::ExitCode;

/// A failed allocation exits with status 1 and one line instead of aborting.
#[global_allocator]
static ALLOCATOR: sigdt_cli::ExitOnAllocationFailure = sigdt_cli::ExitOnAllocationFailure;

fn main() -> ExitCode {
    ExitCode::from(sigdt_cli::run(std::env::args_os()))
}
