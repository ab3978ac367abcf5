//! `sigdt`: reconstruct curves from unorganised 2D points on the command line. The command
//! line lives in the library ([`sigdt_cli::run`]), which the Python package runs too.

use std::process::ExitCode;

/// A failed allocation exits with status 1 and one line instead of aborting.
#[global_allocator]
static ALLOCATOR: sigdt_cli::ExitOnAllocationFailure = sigdt_cli::ExitOnAllocationFailure;

fn main() -> ExitCode {
    // Freed arrays leave the process, so threads' arenas do not keep them resident.
    sigdt_cli::return_large_blocks_to_the_system();
    ExitCode::from(sigdt_cli::run(std::env::args_os()))
}
