//! [`render_svg`]: the layers of a reconstruction drawn as one standalone SVG picture.

use std::fmt::Write as _;

use super::frame::{is_finite, Frame, Px};
use super::legend::{self, Entry, Swatch};
use super::palette::{
    BACKGROUND, BLUE, FILL, GREEN, GREY, INK, ORANGE, PURPLE, SKY, TRUTH, VERMILLION,
};
use super::path::{pixels, polylines, PathData};
use sigdt::{Edge, Point, Reconstruction};

/// What to draw over the points; every layer is off by default. Edges refer to indices of
/// the points given to [`render_svg`]; edges with an index out of range, a loop or a
/// non-finite end are left out.
#[derive(Debug, Clone, Copy, Default)]
pub struct Layers<'a> {
    /// The input points, as dots (left out automatically when they are dense, see
    /// [`render_svg`]).
    pub points: bool,
    /// The Delaunay triangulation's edges, thin and grey.
    pub dt: Option<&'a [Edge]>,
    /// The nearest-neighbour distance of every point: its SIG circle is drawn.
    pub sig: Option<&'a [f64]>,
    /// The SIGDT edges.
    pub sigdt: Option<&'a [Edge]>,
    /// The SIGDT2 edges (SIGDT after leaf elimination), drawn wider beneath SIGDT.
    pub sigdt2: Option<&'a [Edge]>,
    /// A boundary edge set, for example the boundary after inflating.
    pub boundary: Option<&'a [Edge]>,
    /// A reconstruction: loops filled lightly, edges, and the points not on any edge.
    pub result: Option<&'a Reconstruction>,
    /// Ground-truth edges. With [`result`](Self::result) the edges are compared: missing
    /// and extra edges get their own colours.
    pub gt: Option<&'a [Edge]>,
}

/// The page: its width, a title and whether to draw the legend.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RenderOptions {
    /// Width of the picture in pixels (kept within 64..=20000); the height follows from
    /// the points' aspect ratio (at most 1.25 times the width for the drawing), the title
    /// and the legend.
    pub width_px: u32,
    /// A title drawn above the picture (and its `<title>`).
    pub title: Option<String>,
    /// Draw a legend below the picture: one entry per layer, with its count.
    pub legend: bool,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions { width_px: 800, title: None, legend: true }
    }
}

/// Missing and extra edges shorter than this (pixels) also get a ring, so they can be
/// found in a dense picture.
const MARK_BELOW_PX: f64 = 8.0;
/// Radius of those rings, in pixels.
const MARK_PX: f64 = 5.0;
/// Height of the title band, in pixels.
const TITLE_PX: f64 = 30.0;

/// The `layers` over `points` as a standalone SVG document.
///
/// The drawing fits the finite points' bounding box, y pointing up, with equal scales on
/// both axes and a margin, `options.width_px` wide. Line widths and dot sizes follow the
/// point spacing `s`, the median nearest-neighbour distance in pixels: lines are `s / 10`
/// wide within 0.8–2.2 px and dots `s / 5` within 1–3.5 px, so a 50-point glyph and a
/// 100,000-point contour both read well. When `s` is below 3 px, dots would merge into a
/// band wider than the curve, so the points are not drawn if any other layer is (the legend
/// says so); alone they are still drawn, at 1 px.
///
/// With both `result` and `gt`, edges in both are drawn as the result; edges only in the
/// ground truth are **missing** (vermillion, dashed) and edges only in the result are
/// **extra** (blue), each with its count in the legend; where they are shorter than a few
/// pixels a ring marks them. Points without a result edge (duplicates aside) are ringed.
///
/// Every layer is one `<path>` whose coordinates are rounded to 0.01 px and written as
/// relative moves, so 100,000 points take about a megabyte. The output depends only on the
/// input, and has no NaN.
pub fn render_svg(points: &[Point], layers: &Layers, options: &RenderOptions) -> String {
    let n = points.len();
    let clean = |edges: &[Edge]| clean_edges(points, edges);
    let width = f64::from(options.width_px.clamp(64, 20000));
    let circles: Vec<(usize, f64)> = layers.sig.map_or_else(Vec::new, |radii| {
        let ok =
            |&(i, &r): &(usize, &f64)| i < n && r.is_finite() && r > 0.0 && is_finite(points[i]);
        radii.iter().enumerate().filter(ok).map(|(i, &r)| (i, r)).collect()
    });
    let pad = circles.iter().map(|&(_, r)| r).fold(0.0, f64::max);
    let mut frame = Frame::new(points, width, pad);
    let line = frame.line();

    let dt = layers.dt.map(clean);
    let sigdt = layers.sigdt.map(clean);
    let sigdt2 = layers.sigdt2.map(clean);
    let boundary = layers.boundary.map(clean);
    let result = layers.result.map(|rec| clean(&rec.edges));
    let gt = layers.gt.map(clean);
    let diff = result.as_deref().zip(gt.as_deref()).map(|(r, g)| compare(r, g));
    let lonely = layers.result.map_or_else(Vec::new, |rec| lonely(points, rec, result.as_deref()));
    let junctions = layers.result.map_or_else(Vec::new, Reconstruction::junctions);
    let others = dt.is_some()
        || layers.sig.is_some()
        || sigdt.is_some()
        || sigdt2.is_some()
        || boundary.is_some()
        || result.is_some()
        || gt.is_some();
    let dots = layers.points && !(others && frame.dense());
    let dot = frame.dot();
    let ring = dot + 2.0;

    // Legend, in reading order.
    let mut entries = Vec::new();
    let mut add = |swatch, label: String| entries.push(Entry { swatch, label });
    if layers.points {
        let hidden = if dots { "" } else { " (too dense to draw)" };
        add(Swatch::Dot(INK), format!("points {n}{hidden}"));
    }
    let thin = (0.5 * line).max(0.4);
    if let Some(e) = &dt {
        add(Swatch::Line(GREY, thin, false), format!("Delaunay {}", e.len()));
    }
    if layers.sig.is_some() {
        add(Swatch::Ring(SKY, 6.0), format!("SIG circles {}", circles.len()));
    }
    let wide = if sigdt.is_some() { 2.2 * line } else { line };
    if let Some(e) = &sigdt {
        add(Swatch::Line(GREEN, line, false), format!("SIGDT {}", e.len()));
    }
    if let Some(e) = &sigdt2 {
        add(Swatch::Line(PURPLE, wide, false), format!("SIGDT2 {}", e.len()));
    }
    if let Some(e) = &boundary {
        add(Swatch::Line(ORANGE, line, false), format!("boundary {}", e.len()));
    }
    let bold = (2.0 * line).max(2.0);
    if let (Some(rec), Some(edges)) = (layers.result, &result) {
        let loops = match rec.loops.len() {
            0 => String::new(),
            1 => ", 1 loop".to_string(),
            k => format!(", {k} loops"),
        };
        let status = rec.status.name();
        let swatch = match rec.loops.is_empty() {
            true => Swatch::Line(INK, line, false),
            false => Swatch::Fill(FILL, INK),
        };
        match &diff {
            None => add(swatch, format!("result {} edges{loops} ({status})", edges.len())),
            Some([both, missing, extra]) => {
                add(swatch, format!("in both {}{loops} ({status})", both.len()));
                add(Swatch::Line(VERMILLION, bold, true), format!("missing {}", missing.len()));
                add(Swatch::Line(BLUE, bold, false), format!("extra {}", extra.len()));
            }
        }
        if !lonely.is_empty() {
            add(Swatch::Ring(INK, ring), format!("not on result {}", lonely.len()));
        }
        if !junctions.is_empty() {
            add(Swatch::Ring(ORANGE, ring), format!("junctions {}", junctions.len()));
        }
    } else if let Some(e) = &gt {
        add(Swatch::Line(TRUTH, line, true), format!("ground truth {}", e.len()));
    }

    let top = if options.title.is_some() { TITLE_PX } else { 0.0 };
    let bottom = if options.legend { legend::height(&entries, width) } else { 0.0 };
    let legend_top = frame.bands(top, bottom);
    let px: Vec<Option<Px>> = points.iter().map(|&p| frame.map(p)).collect();

    let (w, h) = (pixels(frame.width), pixels(frame.height));
    let title =
        options.title.as_deref().map_or_else(|| format!("sigdt: {n} points"), legend::escape);
    let mut out = String::with_capacity(1024 + 12 * n);
    let _ = write!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
         viewBox=\"0 0 {w} {h}\">\n<title>{title}</title>\n\
         <rect width=\"100%\" height=\"100%\" fill=\"{BACKGROUND}\"/>\n"
    );
    if options.title.is_some() {
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"20\" font-family=\"sans-serif\" font-size=\"15\" \
             font-weight=\"bold\" fill=\"{INK}\">{title}</text>",
            pixels(super::frame::MARGIN)
        );
    }
    let stroke = |out: &mut String, d: String, colour: &str, width: f64, rest: &str| {
        if !d.is_empty() {
            let _ = writeln!(
                out,
                "<path fill=\"none\" stroke=\"{colour}\" stroke-width=\"{}\" \
                 stroke-linecap=\"round\" stroke-linejoin=\"round\"{rest} d=\"{d}\"/>",
                pixels(width)
            );
        }
    };
    // The result's outline: when nothing is drawn between the fill and the result's edges
    // and the loops are exactly those edges, one path both fills and strokes them, which
    // halves the size of large pictures.
    let ink = match (&result, &diff) {
        (_, Some([both, _, _])) => Some(both.as_slice()),
        (Some(e), None) => Some(e.as_slice()),
        (None, _) => None,
    };
    let between = dt.is_some() || !circles.is_empty() || sigdt.is_some() || sigdt2.is_some();
    let mut outlined = false;
    if let Some(rec) = layers.result {
        let (d, ring_edges) = rings(&rec.loops, &px);
        outlined = !between && boundary.is_none() && ink == Some(ring_edges.as_slice());
        let outline = match outlined {
            true => format!(
                " stroke=\"{INK}\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
                pixels(line)
            ),
            false => " stroke=\"none\"".to_string(),
        };
        if !d.is_empty() {
            let _ =
                writeln!(out, "<path fill=\"{FILL}\" fill-rule=\"evenodd\"{outline} d=\"{d}\"/>");
        }
    }
    let edges = |edges: &[Edge]| {
        let mut d = PathData::default();
        for chain in polylines(edges, n) {
            let ps: Vec<Px> = chain.iter().filter_map(|&i| px[i]).collect();
            d.polyline(&ps);
        }
        d.finish()
    };
    if let Some(e) = &dt {
        stroke(&mut out, edges(e), GREY, thin, "");
    }
    if !circles.is_empty() {
        let mut d = PathData::default();
        for &(i, r) in &circles {
            if let Some(p) = px[i] {
                d.circle(p, frame.length(r));
            }
        }
        stroke(&mut out, d.finish(), SKY, thin, " stroke-opacity=\"0.8\"");
    }
    if let Some(e) = &sigdt2 {
        stroke(&mut out, edges(e), PURPLE, wide, "");
    }
    if let Some(e) = &sigdt {
        stroke(&mut out, edges(e), GREEN, line, "");
    }
    if let Some(e) = &boundary {
        stroke(&mut out, edges(e), ORANGE, line, "");
    }
    if let (Some(e), false) = (ink, outlined) {
        stroke(&mut out, edges(e), INK, line, "");
    }
    if dots {
        let mut d = PathData::default();
        px.iter().flatten().for_each(|&p| d.dot(p));
        stroke(&mut out, d.finish(), INK, 2.0 * dot, "");
    }
    match (&result, &diff) {
        (_, Some([_, missing, extra])) => {
            let dash =
                format!(" stroke-dasharray=\"{} {}\"", pixels(2.5 * bold), pixels(1.5 * bold));
            stroke(&mut out, edges(missing), VERMILLION, bold, &dash);
            stroke(&mut out, edges(extra), BLUE, bold, "");
            for (list, colour) in [(missing, VERMILLION), (extra, BLUE)] {
                stroke(&mut out, marks(list, &px), colour, 1.2, "");
            }
        }
        (Some(_), None) => {}
        (None, _) => {
            if let Some(e) = &gt {
                let dash =
                    format!(" stroke-dasharray=\"{} {}\"", pixels(3.0 * line), pixels(2.0 * line));
                stroke(&mut out, edges(e), TRUTH, line, &dash);
            }
        }
    }
    if !lonely.is_empty() {
        let mut d = PathData::default();
        lonely
            .iter()
            .filter_map(|&i| px[i])
            .for_each(|p| d.circle(p, (100.0 * ring).round() as i64));
        stroke(&mut out, d.finish(), INK, 1.2, "");
    }
    if !junctions.is_empty() {
        let mut d = PathData::default();
        let radius = (100.0 * 1.5 * ring).round() as i64;
        junctions
            .iter()
            .filter_map(|&i| px.get(i).copied().flatten())
            .for_each(|p| d.circle(p, radius));
        stroke(&mut out, d.finish(), ORANGE, 2.0, "");
    }
    if options.legend {
        legend::draw(&mut out, &entries, width, legend_top);
    }
    out.push_str("</svg>\n");
    out
}

/// The edges with both ends valid and finite, as `[i, j]` with `i < j`, sorted, without
/// repeats.
fn clean_edges(points: &[Point], edges: &[Edge]) -> Vec<Edge> {
    let ok = |i: usize| i < points.len() && is_finite(points[i]);
    let mut out: Vec<Edge> = edges
        .iter()
        .filter(|&&[i, j]| i != j && ok(i) && ok(j))
        .map(|&[i, j]| [i.min(j), i.max(j)])
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// `[in both, only in truth (missing), only in result (extra)]` of two sorted edge lists.
fn compare(result: &[Edge], truth: &[Edge]) -> [Vec<Edge>; 3] {
    let [mut both, mut missing, mut extra] = [Vec::new(), Vec::new(), Vec::new()];
    let (mut a, mut b) = (0, 0);
    loop {
        match (result.get(a), truth.get(b)) {
            (Some(r), Some(t)) if r == t => {
                both.push(*r);
                (a, b) = (a + 1, b + 1);
            }
            (Some(r), Some(t)) if r < t => {
                extra.push(*r);
                a += 1;
            }
            (Some(r), None) => {
                extra.push(*r);
                a += 1;
            }
            (_, Some(t)) => {
                missing.push(*t);
                b += 1;
            }
            (None, None) => break,
        }
    }
    [both, missing, extra]
}

/// The finite points without a result edge, duplicates of other points aside, in order.
fn lonely(points: &[Point], rec: &Reconstruction, edges: Option<&[Edge]>) -> Vec<usize> {
    let mut covered = vec![false; points.len()];
    for &[i, j] in edges.unwrap_or_default() {
        (covered[i], covered[j]) = (true, true);
    }
    for &[duplicate, _] in &rec.duplicates {
        if let Some(c) = covered.get_mut(duplicate) {
            *c = true;
        }
    }
    (0..points.len()).filter(|&i| !covered[i] && is_finite(points[i])).collect()
}

/// The loops whose points are all drawn, as closed polylines, and their edges (sorted).
fn rings(loops: &[Vec<usize>], px: &[Option<Px>]) -> (String, Vec<Edge>) {
    let mut d = PathData::default();
    let mut edges = Vec::new();
    for indices in loops {
        let ring: Option<Vec<Px>> =
            indices.iter().chain(indices.first()).map(|&i| px.get(i).copied().flatten()).collect();
        if let (Some(ring), [.., last]) = (ring, indices.as_slice()) {
            d.polyline(&ring);
            let steps = indices.windows(2).map(|w| [w[0], w[1]]).chain([[*last, indices[0]]]);
            edges.extend(steps.filter(|[i, j]| i != j).map(|[i, j]| [i.min(j), i.max(j)]));
        }
    }
    edges.sort_unstable();
    edges.dedup();
    (d.finish(), edges)
}

/// Rings around the middles of the edges that are too short to see.
fn marks(edges: &[Edge], px: &[Option<Px>]) -> String {
    let mut d = PathData::default();
    for &[i, j] in edges {
        if let (Some(p), Some(q)) = (px[i], px[j]) {
            let length = ((p[0] - q[0]) as f64).hypot((p[1] - q[1]) as f64) / 100.0;
            if length < MARK_BELOW_PX {
                d.circle([(p[0] + q[0]) / 2, (p[1] + q[1]) / 2], (100.0 * MARK_PX) as i64);
            }
        }
    }
    d.finish()
}
