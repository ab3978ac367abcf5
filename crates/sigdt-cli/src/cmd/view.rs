//! `sigdt view`: the self-contained HTML viewer of one reconstruction, with the steps of
//! inflating and sculpting. The page and its data format are in [`view`](crate::view).

use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use sigdt::{GraphKind, Method, Options, Triangulation};

use crate::input::{ground_truth, picture_title, Input};
use crate::messages::UsageError;
use crate::output::Output;
use crate::view::{view_json, viewer_html, ViewData};

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
    #[arg(long, value_name = "METHOD", value_parser = crate::methods::parser(),
          default_value_t = Method::default())]
    pub method: Method,
    /// Title of the page [default: the input file name].
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
}

/// `sigdt view`.
pub fn run(args: &ViewArgs, input: &Input) -> Result<()> {
    let html = ["html", "htm"];
    if !args.output.extension().is_some_and(|e| html.iter().any(|h| e.eq_ignore_ascii_case(h))) {
        return Err(UsageError {
            command: "view",
            kind: clap::error::ErrorKind::InvalidValue,
            message: format!(
                "{}: the viewer is an HTML file: name it .html or .htm",
                args.output.display()
            ),
        }
        .into());
    }
    let output = Output::new(Some(&args.output), &args.input)?;
    let points = input.points(&args.input)?;
    let gt = ground_truth(args.gt.as_deref(), points.len(), "view")?;
    // One triangulation serves the reconstruction, the graphs and the SIG radii.
    let dt = Triangulation::new(&points)?;
    let options = Options { method: args.method, ..Options::default() };
    let (rec, trace) = sigdt::reconstruct_traced_on(&dt, &options);
    let graph = |kind: GraphKind| sigdt::proximity_graph_on(&dt, kind);
    let (delaunay, sigdt, sigdt2) =
        (graph(GraphKind::Dt), graph(GraphKind::SigDt), graph(GraphKind::SigDt2));
    let nn = sigdt::nearest_neighbour_distances(&dt, &points);
    let inflated = trace.as_ref().map(|t| t.boundary_at(t.inflated_at));
    let mut layers = vec![("dt", &delaunay[..]), ("sigdt", &sigdt[..]), ("sigdt2", &sigdt2[..])];
    if let Some(boundary) = &inflated {
        layers.push(("boundary", boundary));
    }
    layers.push(("result", &rec.edges));
    let title = args.title.clone().unwrap_or_else(|| picture_title(&args.input, points.len()));
    let method = args.method.to_string();
    let data = ViewData {
        title: &title,
        method: &method,
        status: rec.status.name(),
        points: &points,
        nn: &nn,
        layers,
        gt: gt.as_deref(),
        trace: trace.as_ref(),
    };
    let html = viewer_html(&view_json(&data));
    output.write(|w| w.write_all(html.as_bytes()))
}
