//! `sigdt render` (SVG or PNG pictures with layers) and `sigdt view` (the interactive HTML
//! viewer that replays inflating and sculpting).

use std::path::Path;

use anyhow::{bail, Result};
use sigdt::{Edge, GraphKind, Options, Point};
use sigdt_lab::render::{render_svg, Layers, RenderOptions};

use crate::args_view::{Layer, RenderArgs, ViewArgs};
use crate::output::Output;

/// `sigdt render`.
pub fn render(args: &RenderArgs) -> Result<()> {
    let png = match args.output.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("png") => true,
        Some(e) if e.eq_ignore_ascii_case("svg") => false,
        _ => bail!("{}: the picture must be a .svg or .png file", args.output.display()),
    };
    let output = Output::new(Some(&args.output), &args.input)?;
    let points = crate::run::read_input(&args.input)?;
    let gt = read_gt(args.gt.as_deref(), points.len())?;
    let mut wanted = args.layers.clone();
    if wanted.is_empty() {
        wanted = vec![Layer::Points, Layer::Result];
        if gt.is_some() {
            wanted.push(Layer::Gt);
        }
    }
    if wanted.contains(&Layer::Gt) && gt.is_none() {
        bail!("--layers gt needs --gt FILE");
    }
    let has = |l: Layer| wanted.contains(&l);
    let graph = |l: Layer, kind: GraphKind| -> Result<Option<Vec<Edge>>> {
        Ok(if has(l) { Some(sigdt::proximity_graph(&points, kind)?) } else { None })
    };
    let (dt, sigdt, sigdt2) = (
        graph(Layer::Dt, GraphKind::Dt)?,
        graph(Layer::Sigdt, GraphKind::SigDt)?,
        graph(Layer::Sigdt2, GraphKind::SigDt2)?,
    );
    let nn = if has(Layer::Sig) { Some(nearest_distances(&points)?) } else { None };
    let options = Options { method: args.method, ..Options::default() };
    let (rec, trace) = if has(Layer::Result) || has(Layer::Boundary) {
        let (rec, trace) = sigdt::reconstruct_traced(&points, &options)?;
        (Some(rec), trace)
    } else {
        (None, None)
    };
    let boundary = match (has(Layer::Boundary), &trace) {
        (true, Some(t)) => Some(t.boundary_at(t.inflated_at)),
        (true, None) => bail!("--layers boundary: method {} has no inflating step", args.method),
        (false, _) => None,
    };
    let layers = Layers {
        points: has(Layer::Points),
        dt: dt.as_deref(),
        sig: nn.as_deref(),
        sigdt: sigdt.as_deref(),
        sigdt2: sigdt2.as_deref(),
        boundary: boundary.as_deref(),
        result: if has(Layer::Result) { rec.as_ref() } else { None },
        gt: if has(Layer::Gt) { gt.as_deref() } else { None },
    };
    let title = args.title.clone().unwrap_or_else(|| file_title(&args.input, points.len()));
    let render_options =
        RenderOptions { width_px: args.width, title: Some(title), ..RenderOptions::default() };
    let svg = render_svg(&points, &layers, &render_options);
    if png {
        let bytes = crate::png::svg_to_png(&svg)?;
        output.write(|w| w.write_all(&bytes))
    } else {
        output.write(|w| w.write_all(svg.as_bytes()))
    }
}

/// `sigdt view`.
pub fn view(args: &ViewArgs) -> Result<()> {
    if !args.output.extension().is_some_and(|e| e.eq_ignore_ascii_case("html")) {
        bail!("{}: the viewer is an .html file", args.output.display());
    }
    let output = Output::new(Some(&args.output), &args.input)?;
    let points = crate::run::read_input(&args.input)?;
    let gt = read_gt(args.gt.as_deref(), points.len())?;
    let options = Options { method: args.method, ..Options::default() };
    let (rec, trace) = sigdt::reconstruct_traced(&points, &options)?;
    let dt = sigdt::proximity_graph(&points, GraphKind::Dt)?;
    let sigdt = sigdt::proximity_graph(&points, GraphKind::SigDt)?;
    let sigdt2 = sigdt::proximity_graph(&points, GraphKind::SigDt2)?;
    let nn = nearest_distances(&points)?;
    let steps: Vec<(usize, bool, char)> = trace
        .as_ref()
        .map(|t| t.steps.iter().map(|s| (s.triangle, s.inside, phase_code(s.phase))).collect())
        .unwrap_or_default();
    let trace_data = trace.as_ref().map(|t| crate::view::TraceData {
        triangles: &t.triangles,
        initial_inside: &t.initial_inside,
        dangling: &t.dangling,
        steps: &steps,
        inflated_at: t.inflated_at,
    });
    let title = args.title.clone().unwrap_or_else(|| file_title(&args.input, points.len()));
    let status = rec.status.name();
    let method = args.method.to_string();
    let data = crate::view::ViewData {
        title: &title,
        method: &method,
        status,
        points: &points,
        nn: &nn,
        layers: vec![("dt", &dt), ("sigdt", &sigdt), ("sigdt2", &sigdt2), ("result", &rec.edges)],
        gt: gt.as_deref(),
        trace: trace_data,
    };
    let html = crate::view::viewer_html(&crate::view::view_json(&data));
    output.write(|w| w.write_all(html.as_bytes()))
}

fn phase_code(phase: sigdt::Phase) -> char {
    use sigdt::Phase;
    match phase {
        Phase::Inflate => 'i',
        Phase::Pocket => 'p',
        Phase::Sculpt => 's',
    }
}

/// The ground truth of `--gt`, checked against the number of points.
fn read_gt(path: Option<&Path>, n: usize) -> Result<Option<Vec<Edge>>> {
    let Some(path) = path else { return Ok(None) };
    let gt = sigdt::io::read_edges(path)?;
    if let Some((k, [i, j])) = gt.iter().enumerate().find(|(_, e)| e[1] >= n) {
        bail!(
            "{}: edge {} ([{i}, {j}]) refers to point {j}, but the input has {n} points",
            path.display(),
            k + 1
        );
    }
    Ok(Some(gt))
}

/// Nearest-neighbour distance of every input point (0 for exact duplicates), in input
/// coordinates.
fn nearest_distances(points: &[Point]) -> Result<Vec<f64>> {
    let dt = sigdt::Triangulation::new(points)?;
    let mut nn = vec![0.0; points.len()];
    for [i, j] in dt.edges() {
        let d = (points[i][0] - points[j][0]).hypot(points[i][1] - points[j][1]);
        for k in [i, j] {
            if nn[k] == 0.0 || d < nn[k] {
                nn[k] = d;
            }
        }
    }
    Ok(nn)
}

fn file_title(input: &Path, n: usize) -> String {
    let name = if crate::output::is_dash(input) {
        "standard input".to_string()
    } else {
        input
            .file_stem()
            .map_or_else(|| input.display().to_string(), |s| s.to_string_lossy().into_owned())
    };
    format!("{name} ({n} points)")
}
