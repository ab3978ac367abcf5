//! `sigdt view`: the self-contained HTML viewer of one reconstruction, with the steps of
//! inflating and sculpting. The page and its data format are in [`view`](crate::view).

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use clap::Args;
use sigdt::{GraphKind, Method, Options, Triangulation};

use crate::input::{ground_truth, picture_title, Input};
use crate::messages::UsageError;
use crate::output::Output;
use crate::progress::{size, thousands, Stages};
use crate::view::{joined, view_json, viewer_html, ViewData};

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
    /// Reconstruction method (sig-connect2d and connect2d record their steps, for the replay).
    #[arg(long, value_name = "METHOD", value_parser = crate::methods::parser(),
          default_value_t = Method::default())]
    pub method: Method,
    /// Title of the page [default: the input file name].
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
    /// Leave out the replay of inflating and sculpting: a smaller page for large inputs.
    #[arg(long)]
    pub no_steps: bool,
}

/// Pages larger than this get a warning: browsers take a while to open them.
const LARGE_PAGE_BYTES: usize = 50_000_000;

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
    let progress = Stages::new("view");
    progress.stage(format!("reading {}", args.input.display()));
    let points = input.plane_points(&args.input, "view")?;
    too_many_to_view(&args.input, points.len())?;
    let name = args.input.display().to_string();
    crate::memory::check(&name, points.len(), crate::memory::Cost::View)?;
    let gt = ground_truth(args.gt.as_deref(), points.len())?;
    // One triangulation serves the reconstruction, the graphs and the SIG radii.
    progress.stage(format!("triangulating {} points", thousands(points.len())));
    let dt = Triangulation::new(&points)?;
    progress.stage(format!("reconstructing ({})", args.method));
    let options = Options { method: args.method, ..Options::default() };
    let (rec, trace) = match args.no_steps {
        true => (sigdt::reconstruct_on(&dt, &options), None),
        false => sigdt::reconstruct_traced_on(&dt, &options),
    };
    progress.stage("proximity graphs");
    // The layers are independent: one thread each.
    let ((delaunay, sigdt, sigdt2), (nn, inflated)) = std::thread::scope(|scope| {
        let dt = &dt;
        let graph = |kind| scope.spawn(move || sigdt::proximity_graph_on(dt, kind));
        let graphs = [GraphKind::Dt, GraphKind::SigDt, GraphKind::SigDt2].map(graph);
        let nn = scope.spawn(|| sigdt::nearest_neighbour_distances(dt, &points));
        let inflated = trace.as_ref().map(|t| t.boundary_at(t.inflated_at));
        let [a, b, c] = graphs.map(joined);
        ((a, b, c), (joined(nn), inflated))
    });
    let mut layers = vec![("dt", &delaunay[..]), ("sigdt", &sigdt[..]), ("sigdt2", &sigdt2[..])];
    if let Some(boundary) = &inflated {
        layers.push(("boundary", boundary));
    }
    layers.push(("result", &rec.edges));
    // The trace's triangles are the triangulation's, in an order that does not depend on
    // how its arrays are laid out (which varies with the thread count); without a trace
    // they are made here in the same order.
    let made;
    let triangles: &[[usize; 3]] = match &trace {
        Some(trace) => &trace.triangles,
        None => {
            made = dt.input_triangles_in_canonical_order();
            &made
        }
    };
    let title = args.title.clone().unwrap_or_else(|| picture_title(&args.input, points.len()));
    let method = args.method.to_string();
    let data = ViewData {
        title: &title,
        method: &method,
        status: rec.status.name(),
        points: &points,
        nn: &nn,
        triangles,
        layers,
        gt: gt.as_deref(),
        trace: trace.as_ref(),
    };
    progress.stage("encoding the page");
    let html = viewer_html(&view_json(&data));
    if let Some(warning) = size_warning(&args.output, html.len(), trace.is_some()) {
        progress.note(&warning);
    }
    progress.stage(format!("writing {} ({})", args.output.display(), size(html.len())));
    output.write(|w| w.write_all(html.as_bytes()))
}

/// The warning for a page of `bytes` bytes written to `path`, if it is over
/// [`LARGE_PAGE_BYTES`]; `steps`: whether it holds the replay, which `--no-steps` leaves out.
fn size_warning(path: &Path, bytes: usize, steps: bool) -> Option<String> {
    (bytes > LARGE_PAGE_BYTES).then(|| {
        let smaller = if steps { "; --no-steps leaves out the replay" } else { "" };
        format!(
            "sigdt view: warning: {} will be {}, more than {}: a browser takes a while to \
             open it{smaller}",
            path.display(),
            size(bytes),
            size(LARGE_PAGE_BYTES)
        )
    })
}

/// The most points the viewer shows: building its page takes about 780 bytes a point (the
/// triangulation, the graphs, the replay and the page text held at once), so 2·10⁶ points
/// need about 1.6 GB, and a browser slows to a crawl well before.
const MAX_VIEW_POINTS: usize = 2_000_000;

/// Refuses more points than [`MAX_VIEW_POINTS`], saying why and what to do instead.
fn too_many_to_view(input: &Path, n: usize) -> Result<()> {
    if n > MAX_VIEW_POINTS {
        bail!(
            "{}: {} points are more than the viewer shows ({}: its page takes about 780 bytes \
             a point to build); draw them with `sigdt render --layers points,result -o \
             picture.png`, or view a part of them",
            input.display(),
            thousands(n),
            thousands(MAX_VIEW_POINTS)
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn too_many_points_for_a_page_are_refused_saying_why() {
        // Issue 30, G15: 10⁷ points aborted under 4 GB.
        assert!(too_many_to_view(Path::new("a.xy"), MAX_VIEW_POINTS).is_ok());
        let err = too_many_to_view(Path::new("a.xy"), 10_000_000).unwrap_err().to_string();
        assert!(err.starts_with("a.xy: 10,000,000 points are more than the viewer shows"));
        assert!(err.contains("sigdt render"), "{err}");
    }

    #[test]
    fn large_pages_are_announced() {
        let path = Path::new("big.html");
        assert_eq!(size_warning(path, LARGE_PAGE_BYTES, true), None);
        assert_eq!(
            size_warning(path, LARGE_PAGE_BYTES + 1, true).as_deref(),
            Some(
                "sigdt view: warning: big.html will be 51 MB, more than 50 MB: a browser takes \
                 a while to open it; --no-steps leaves out the replay"
            )
        );
        let without = size_warning(path, 74_559_694, false).expect("a warning");
        assert!(without.ends_with("75 MB, more than 50 MB: a browser takes a while to open it"));
    }
}
