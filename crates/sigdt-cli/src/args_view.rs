//! Arguments of the picture commands: `render` and `view`.

use std::path::PathBuf;

use clap::builder::RangedU64ValueParser;
use clap::{Args, ValueEnum};
use sigdt::Method;

use crate::args_bench::method_parser;

/// A layer of `sigdt render`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Layer {
    /// The input points.
    Points,
    /// Delaunay triangulation edges.
    Dt,
    /// Spheres of influence: a circle of nearest-neighbour radius around each point.
    Sig,
    /// SIG ∩ DT.
    Sigdt,
    /// SIGDT after leaf elimination.
    Sigdt2,
    /// The boundary after inflating (before sculpting).
    Boundary,
    /// The reconstruction.
    Result,
    /// The ground truth (with --gt); with `result`, missing and extra edges are highlighted.
    Gt,
}

/// `sigdt render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// Point file, or '-' for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,
    /// Output picture: .svg or .png.
    #[arg(short, long = "output", value_name = "OUT")]
    pub output: PathBuf,
    /// Layers to draw, comma-separated [default: points,result, and gt with --gt].
    #[arg(long, value_enum, value_name = "L1,L2,...", value_delimiter = ',')]
    pub layers: Vec<Layer>,
    /// Ground-truth edges ('i j' per line, indices into INPUT).
    #[arg(long, value_name = "FILE")]
    pub gt: Option<PathBuf>,
    /// Reconstruction method for the result and boundary layers.
    #[arg(long, value_name = "METHOD", value_parser = method_parser(),
          default_value_t = Method::default())]
    pub method: Method,
    /// Width of the picture in pixels.
    #[arg(long, value_name = "PX", default_value_t = 800,
          value_parser = RangedU64ValueParser::<u32>::new().range(16..=16384))]
    pub width: u32,
    /// Title drawn above the picture [default: the input file name].
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
}

/// `sigdt view`.
#[derive(Debug, Args)]
pub struct ViewArgs {
    /// Point file, or '-' for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,
    /// Output HTML file.
    #[arg(short, long = "output", value_name = "OUT.html")]
    pub output: PathBuf,
    /// Ground-truth edges ('i j' per line, indices into INPUT).
    #[arg(long, value_name = "FILE")]
    pub gt: Option<PathBuf>,
    /// Reconstruction method (sig-connect2d and connect2d record their steps).
    #[arg(long, value_name = "METHOD", value_parser = method_parser(),
          default_value_t = Method::default())]
    pub method: Method,
    /// Title of the page [default: the input file name].
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
}
