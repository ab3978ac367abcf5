//! `sigdt graph`: a proximity graph of the points, one edge `i j` a line.

use std::path::PathBuf;

use anyhow::Result;
use clap::builder::{PossibleValuesParser, RangedU64ValueParser};
use clap::error::ErrorKind;
use clap::Args;
use sigdt::GraphKind;

use crate::input::Input;
use crate::messages::UsageError;
use crate::output::Output;

/// `sigdt graph`.
#[derive(Debug, Args)]
pub struct GraphArgs {
    /// Point file, or '-' for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,
    /// The graph: Delaunay triangulation, spheres-of-influence graph, SIGDT, SIGDT with
    /// leaf elimination, Euclidean minimum spanning tree, or k nearest neighbours.
    #[arg(long, value_name = "KIND", value_parser = PossibleValuesParser::new(GraphKind::NAMES))]
    pub kind: String,
    /// Number of neighbours for --kind knn (required there, and only allowed there).
    #[arg(short = 'k', value_name = "K", required_if_eq("kind", "knn"),
          value_parser = RangedU64ValueParser::<usize>::new().range(1..))]
    pub k: Option<usize>,
    /// Write the edges to OUT instead of standard output ('-' is standard output).
    #[arg(short, long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,
}

impl GraphArgs {
    /// The graph asked for. clap has checked `--kind` against [`GraphKind::NAMES`] and that
    /// knn has `-k`; that `-k` goes with knn alone it cannot say, so that usage error is
    /// raised here, before any file is touched.
    fn kind(&self) -> Result<GraphKind> {
        if self.k.is_some() && self.kind != "knn" {
            let message = format!("-k is only used with --kind knn, not --kind {}", self.kind);
            return Err(UsageError {
                command: "graph",
                kind: ErrorKind::ArgumentConflict,
                message,
            }
            .into());
        }
        Ok(GraphKind::from_name(&self.kind, self.k)?)
    }
}

/// `sigdt graph`.
pub fn run(args: &GraphArgs, input: &Input) -> Result<()> {
    let kind = args.kind()?;
    let output = Output::new(args.output.as_deref(), &args.input)?;
    let points = input.plane_points(&args.input, "graph")?;
    let edges = sigdt::proximity_graph(&points, kind)?;
    output.write(|w| sigdt_io::text::write_edges(w, &edges))
}
