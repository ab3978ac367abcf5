//! `sigdt render`: a picture of the points and the layers asked for, as SVG or PNG.

use std::path::PathBuf;

use anyhow::{bail, Result};
use clap::builder::RangedU64ValueParser;
use clap::{Args, ValueEnum};
use sigdt::{GraphKind, Method, Options, Triangulation};
use sigdt_lab::render::{render_svg, Layers, RenderOptions};

use crate::input::{ground_truth, picture_title, Input};
use crate::messages::UsageError;
use crate::output::Output;
use crate::progress::{thousands, Stages};

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
    /// Reconstruction method for the result and boundary layers (the boundary layer needs
    /// sig-connect2d or connect2d).
    #[arg(long, value_name = "METHOD", value_parser = crate::methods::parser(),
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

/// `sigdt render`.
pub fn run(args: &RenderArgs, input: &Input) -> Result<()> {
    let png = match args.output.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("png") => true,
        Some(e) if e.eq_ignore_ascii_case("svg") => false,
        other => {
            let why = match other.map(str::to_ascii_lowercase).as_deref() {
                Some("jpg" | "jpeg") => " (JPEG is not written: its compression blurs thin lines)",
                _ => "",
            };
            return Err(UsageError {
                command: "render",
                kind: clap::error::ErrorKind::InvalidValue,
                message: format!(
                    "{}: the picture must be a .svg or .png file{why}",
                    args.output.display()
                ),
            }
            .into());
        }
    };
    let output = Output::new(Some(&args.output), &args.input)?;
    let progress = Stages::new("render");
    progress.stage(format!("reading {}", args.input.display()));
    let points = input.plane_points(&args.input, "render")?;
    too_many_to_draw(&args.input, points.len())?;
    let name = args.input.display().to_string();
    crate::memory::check(&name, points.len(), crate::memory::Cost::Render)?;
    let gt = ground_truth(args.gt.as_deref(), points.len())?;
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
    // One triangulation serves every layer; the points and the ground truth alone need none.
    let computed =
        [Layer::Dt, Layer::Sig, Layer::Sigdt, Layer::Sigdt2, Layer::Boundary, Layer::Result];
    let dt = match computed.into_iter().any(has) {
        true => {
            progress.stage(format!("triangulating {} points", thousands(points.len())));
            Some(Triangulation::new(&points)?)
        }
        false => None,
    };
    let on = |l: Layer| dt.as_ref().filter(|_| has(l));
    if [Layer::Dt, Layer::Sig, Layer::Sigdt, Layer::Sigdt2].into_iter().any(has) {
        progress.stage("proximity graphs");
    }
    let graph = |l: Layer, kind: GraphKind| on(l).map(|dt| sigdt::proximity_graph_on(dt, kind));
    let (delaunay, sigdt, sigdt2) = (
        graph(Layer::Dt, GraphKind::Dt),
        graph(Layer::Sigdt, GraphKind::SigDt),
        graph(Layer::Sigdt2, GraphKind::SigDt2),
    );
    let nn = on(Layer::Sig).map(|dt| sigdt::nearest_neighbour_distances(dt, &points));
    let options = Options { method: args.method, ..Options::default() };
    let (rec, trace) = match on(Layer::Result).or_else(|| on(Layer::Boundary)) {
        Some(dt) => {
            progress.stage(format!("reconstructing ({})", args.method));
            // Only the boundary layer needs the steps, which cost time and memory to record.
            let (rec, trace) = match has(Layer::Boundary) {
                true => sigdt::reconstruct_traced_on(dt, &options),
                false => (sigdt::reconstruct_on(dt, &options), None),
            };
            (Some(rec), trace)
        }
        None => (None, None),
    };
    let boundary = match (has(Layer::Boundary), &trace) {
        (true, Some(t)) => Some(t.boundary_at(t.inflated_at)),
        (true, None) => bail!(
            "--layers boundary: method {} has no inflating step of its own to draw (sig-connect2d \
             and connect2d have: --method sig-connect2d)",
            args.method
        ),
        (false, _) => None,
    };
    let layers = Layers {
        points: has(Layer::Points),
        dt: delaunay.as_deref(),
        sig: nn.as_deref(),
        sigdt: sigdt.as_deref(),
        sigdt2: sigdt2.as_deref(),
        boundary: boundary.as_deref(),
        result: if has(Layer::Result) { rec.as_ref() } else { None },
        gt: if has(Layer::Gt) { gt.as_deref() } else { None },
    };
    let title = args.title.clone().unwrap_or_else(|| picture_title(&args.input, points.len()));
    let render_options =
        RenderOptions { width_px: args.width, title: Some(title), ..RenderOptions::default() };
    progress.stage("drawing");
    let svg = render_svg(&points, &layers, &render_options);
    if png {
        progress.stage("rasterising");
        let bytes = crate::png::svg_to_png(&svg)?;
        progress.stage(format!("writing {}", args.output.display()));
        output.write(|w| w.write_all(&bytes))
    } else {
        progress.stage(format!("writing {}", args.output.display()));
        output.write(|w| w.write_all(svg.as_bytes()))
    }
}

/// The most points a picture shows: with every layer its SVG takes about 570 bytes a point
/// to build (and a PNG is rasterised from it), so 2·10⁶ points need about 1.1 GB.
const MAX_PICTURE_POINTS: usize = 2_000_000;

/// Refuses more points than [`MAX_PICTURE_POINTS`], saying why and what to do instead.
fn too_many_to_draw(input: &std::path::Path, n: usize) -> Result<()> {
    if n > MAX_PICTURE_POINTS {
        bail!(
            "{}: {} points are more than a picture shows ({}: it takes about 570 bytes a \
             point to draw); write the result with `sigdt reconstruct --format wkt` (or \
             geojson) for a GIS tool, or draw a part of the points",
            input.display(),
            thousands(n),
            thousands(MAX_PICTURE_POINTS)
        );
    }
    Ok(())
}

#[cfg(test)]
mod size_tests {
    use super::*;

    #[test]
    fn too_many_points_for_a_picture_are_refused_saying_why() {
        // Issue 30, G15: 10⁶ points aborted under 512 MB, 10⁷ under 4 GB.
        let input = std::path::Path::new("a.xy");
        assert!(too_many_to_draw(input, MAX_PICTURE_POINTS).is_ok());
        let err = too_many_to_draw(input, 10_000_000).unwrap_err().to_string();
        assert!(err.starts_with("a.xy: 10,000,000 points are more than a picture shows"));
    }
}
