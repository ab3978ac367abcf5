//! `sigdt eval`: the metrics of one result against ground truth, one `name: value` a line.

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use sigdt::{Method, Options};

use crate::input::{edges_of, Input};
use crate::progress::{thousands, Stages};

/// `sigdt eval`.
#[derive(Debug, Args)]
pub struct EvalArgs {
    /// Point file, or '-' for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,
    /// Ground-truth edges ('i j' per line, indices into INPUT).
    #[arg(long, value_name = "FILE")]
    pub gt: PathBuf,
    /// Score this edge file instead of running a method.
    #[arg(long, value_name = "FILE", conflicts_with = "method")]
    pub edges: Option<PathBuf>,
    /// Method to run and score.
    #[arg(long, value_name = "METHOD", value_parser = crate::methods::parser(),
          default_value_t = Method::default())]
    pub method: Method,
}

/// `sigdt eval`.
pub fn run(args: &EvalArgs, input: &Input) -> Result<()> {
    let progress = Stages::new("eval");
    progress.stage(format!("reading {}", args.input.display()));
    let points = input.plane_points(&args.input, "eval")?;
    let gt = edges_of(&args.gt, points.len(), "--gt")?;
    let (label, edges) = match &args.edges {
        Some(file) => (file.display().to_string(), edges_of(file, points.len(), "--edges")?),
        None => {
            let options = Options { method: args.method, ..Options::default() };
            (args.method.to_string(), sigdt::reconstruct(&points, &options)?.edges)
        }
    };
    progress.stage(format!(
        "comparing {} edges with {}",
        thousands(edges.len()),
        thousands(gt.len())
    ));
    let m = sigdt_lab::eval::evaluate(&points, &edges, &gt)?;
    // The graph-based epsilon measures 64 places an edge: on a well-sampled
    // curve about 20 µs an edge on one core (docs/reliability.md), so the spinner says how
    // long to expect.
    let expected = gt.len() as f64 * 20e-6;
    progress.stage(format!(
        "epsilon of the ground truth ({} edges, about {expected:.0} s on one core)",
        thousands(gt.len())
    ));
    let epsilon = sigdt_lab::eval::graph_epsilon(&points, &gt)?;
    drop(progress);
    let opt = |v: Option<f64>| v.map_or("undefined".to_string(), |v| format!("{v:.6e}"));
    let mut lines = vec![
        format!("result:             {label}"),
        format!("exact:              {}", if m.exact { "yes" } else { "no" }),
        format!("edges:              {} (ground truth {})", edges.len(), gt.len()),
        format!("missing edges:      {}", m.missing),
        format!("extra edges:        {}", m.extra),
        format!("rmse:               {}", opt(m.distance.map(|d| d.rmse))),
        format!("rmse to gt:         {}", opt(m.distance.map(|d| d.rmse_to_gt))),
        format!("hausdorff:          {}", opt(m.distance.map(|d| d.hausdorff))),
        format!("area difference:    {:.6e}", m.area.area),
        format!("area difference / ground-truth box: {}", opt(m.area.normalised)),
        format!("epsilon:            {epsilon:.4} (graph-based, of the labelled sample)"),
    ];
    lines.push(String::new());
    print!("{}", lines.join("\n"));
    Ok(())
}
