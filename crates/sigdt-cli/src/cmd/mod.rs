//! The subcommands, one file each: its clap arguments beside the code that runs it.

pub mod bench;
pub mod bench_worker;
pub mod completions;
pub mod eval;
pub mod gallery;
pub mod graph;
pub mod perturb;
pub mod reconstruct;
pub mod render;
pub mod sample;
pub mod sweep;
pub mod view;
