//! `sigdt view`: one self-contained HTML page to explore a reconstruction.
//!
//! The page draws the points, the proximity graphs (DT, SIG circles, SIGDT, SIGDT2), the
//! boundary after inflating, the result and the ground truth on a canvas, with pan, zoom and
//! layer toggles, and replays the inflating and sculpting steps one triangle at a time (the
//! paper's Figures 4, 6, 7). Everything is inlined: the stylesheet, the scripts and the
//! data, which sits in a `<script type="application/json">` element. The page loads nothing
//! from the network and works from `file://`.
//!
//! [`view_json`] writes the data; [`viewer_html`] wraps it into the page. Arrays are base64
//! of their little-endian bytes (`F64[k]`: k doubles; `BITS[k]`: k bits, eight to a byte,
//! low bit first; module `encode`):
//!
//! ```text
//! {"format": 2, "title": "glyph_n_tilde (385 points)", "method": "sig-connect2d",
//!  "status": "polygon", "n": N, "palette": {"ink": "#1a1a1a", ...},
//!  "points": F64[2N] (x0 y0 x1 y1 ...), "nn": F32[N],
//!  "triangles": U32[3T], "extra_edges": U32[2X],
//!  "layers": {"dt": BITS[E], "sigdt": ..., "sigdt2": ..., "boundary": ..., "result": ...,
//!             "gt": BITS[E] | null},
//!  "trace": null | {"phases": ["inflate", "pocket", "sculpt"],
//!                   "initial_inside": BITS[T], "initial_boundary": BITS[E],
//!                   "step_triangles": U32[S], "step_changes": U8[S], "inflated_at": K}}
//! ```
//!
//! The edge list `E` is every side of the Delaunay triangles (input indices, counter-clockwise,
//! duplicates by their representative) and every `extra_edges` pair, as `[i, j]` with
//! `i < j`, sorted and unique; both Rust (`encode::EdgeList`) and the page build it, and
//! each layer is one bit per edge of it. `nn` is the SIG circle radius (0 for a duplicate,
//! infinite for a lone point); `boundary` (the boundary after inflating) is there only with
//! a trace. The palette is `sigdt_lab::render::palette`, shared with `render` and Python.
//!
//! The trace is replayed by the kernel ([`sigdt::Trace`]), never by the page: step `s`
//! turns triangle `step_triangles[s]` to the other label and toggles in or out of the
//! boundary the sides `k` of that triangle set in the low three bits of `step_changes[s]`
//! (side `k` runs from its corner `k` to corner `k + 1`; [`Trace::boundary_change_sides`]);
//! the bits above are [`Phase::code`], an index into `phases`. The boundary before the first
//! step is `initial_boundary` ([`Trace::boundary_at`]`(0)`). Flipping and toggling are their
//! own inverse, so the page steps back by applying the same step again. The page reads the
//! labels only to fill the interior: it orients each boundary edge with its interior
//! triangle on the left, and leaves out the dangling edges, which have none.
//!
//! The scripts are split by concern: `model.js` (decoding, applying steps), `draw.js`
//! (camera, canvas and SVG drawing), `ui.js` (legend, step controls, export, mouse,
//! keyboard).

mod encode;

use std::collections::HashMap;
use std::fmt::Write;

use sigdt::{Edge, Phase, Trace};
use sigdt_lab::render::palette::PALETTE;

use encode::EdgeList;

const TEMPLATE: &str = include_str!("viewer.html");
const CSS: &str = include_str!("viewer.css");
/// The scripts, concatenated in this order into one function body (they share its scope).
const SCRIPTS: [&str; 3] =
    [include_str!("model.js"), include_str!("draw.js"), include_str!("ui.js")];

/// Everything the page shows. Edges are input-index pairs `[i, j]`.
#[derive(Debug, Clone)]
pub struct ViewData<'a> {
    /// Shown as the page title, for example `glyph_n_tilde (385 points)`.
    pub title: &'a str,
    /// The method's kebab-case name.
    pub method: &'a str,
    /// The result's status name (`polygon`, `curves`, ...).
    pub status: &'a str,
    /// The input points.
    pub points: &'a [[f64; 2]],
    /// Nearest-neighbour distance per point (the SIG circle radius; 0 for duplicates, `∞`
    /// for a lone point).
    pub nn: &'a [f64],
    /// The Delaunay triangles as input indices (the trace's, when there is one).
    pub triangles: &'a [[usize; 3]],
    /// Named edge layers, in the order `dt`, `sigdt`, `sigdt2`, `boundary`, `result`.
    pub layers: Vec<(&'a str, &'a [[usize; 2]])>,
    /// The ground-truth edges, if known.
    pub gt: Option<&'a [[usize; 2]]>,
    /// The inflating and sculpting steps, for the methods that have them.
    pub trace: Option<&'a Trace>,
}

/// The page for `data_json` (as written by [`view_json`]).
pub fn viewer_html(data_json: &str) -> String {
    // `<` can only occur inside JSON strings, where `\u003c` means the same; this keeps
    // `</script>` and `<!--` out of the data element.
    let data = data_json.replace('<', "\\u003c");
    let script: String = SCRIPTS.concat();
    let mut html = String::with_capacity(TEMPLATE.len() + CSS.len() + script.len() + data.len());
    let mut rest = TEMPLATE;
    for (marker, value) in [("{{css}}", CSS), ("{{data}}", &data), ("{{js}}", &script)] {
        let (before, after) = rest.split_once(marker).expect("template marker");
        html.push_str(before);
        html.push_str(value);
        rest = after;
    }
    html.push_str(rest);
    html
}

/// The page's data as JSON (see the module docs). The points must be at most `u32::MAX`
/// (the caller checks).
pub fn view_json(data: &ViewData) -> String {
    let list = EdgeList::new(data.triangles, data.layers.iter().map(|(_, e)| *e).chain(data.gt));
    let list = &list;
    let mask = move |edges: &[Edge]| encode::bits(list.mask(edges).into_iter());
    // Each array is encoded on a thread of its own: at 10⁶ points most take a good fraction
    // of a second.
    let mut jobs: Vec<(String, Job)> = vec![
        ("points".into(), Box::new(|| encode::f64s(data.points.iter().flatten().copied()))),
        ("nn".into(), Box::new(|| encode::f32s(data.nn.iter().map(|&r| r as f32)))),
        (
            "triangles".into(),
            Box::new(|| encode::u32s(data.triangles.iter().flatten().map(|&i| i as u32))),
        ),
        (
            "extra_edges".into(),
            Box::new(|| encode::u32s(list.extra.iter().flat_map(|&k| encode::ends(k)))),
        ),
    ];
    for &(name, edges) in data.layers.iter().chain(data.gt.map(|gt| ("gt", gt)).iter()) {
        jobs.push((format!("layers.{name}"), Box::new(move || mask(edges))));
    }
    if let Some(trace) = data.trace {
        jobs.push((
            "initial_inside".into(),
            Box::new(|| encode::bits(trace.initial_inside.iter().copied())),
        ));
        jobs.push(("initial_boundary".into(), Box::new(move || mask(&trace.boundary_at(0)))));
        jobs.push((
            "step_triangles".into(),
            Box::new(|| encode::u32s(trace.steps.iter().map(|step| step.triangle as u32))),
        ));
        jobs.push((
            "step_changes".into(),
            Box::new(|| {
                let changes: Vec<u8> = (trace.steps.iter().zip(trace.boundary_change_sides()))
                    .map(|(step, sides)| (step.phase.code() << 3) | sides)
                    .collect();
                encode::u8s(&changes)
            }),
        ));
    }
    let (names, jobs): (Vec<String>, Vec<Job>) = jobs.into_iter().unzip();
    let arrays: HashMap<String, String> = names.into_iter().zip(in_parallel(jobs)).collect();
    let array = |name: &str| &arrays[name];

    let mut s = String::with_capacity(arrays.values().map(String::len).sum::<usize>() + 4096);
    s.push_str("{\"format\": 2, \"title\": ");
    string(&mut s, data.title);
    s.push_str(", \"method\": ");
    string(&mut s, data.method);
    s.push_str(", \"status\": ");
    string(&mut s, data.status);
    let _ = write!(s, ", \"n\": {},\n\"palette\": {{", data.points.len());
    for (k, (role, colour)) in PALETTE.iter().enumerate() {
        let _ = write!(s, "{}\"{role}\": \"{colour}\"", if k > 0 { ", " } else { "" });
    }
    s.push('}');
    for name in ["points", "nn", "triangles", "extra_edges"] {
        let _ = write!(s, ",\n\"{name}\": \"{}\"", array(name));
    }
    s.push_str(",\n\"layers\": {");
    for (name, _) in &data.layers {
        string(&mut s, name);
        let _ = writeln!(s, ": \"{}\",", array(&format!("layers.{name}")));
    }
    match data.gt {
        Some(_) => {
            let _ = write!(s, "\"gt\": \"{}\"", array("layers.gt"));
        }
        None => s.push_str("\"gt\": null"),
    }
    s.push_str("},\n\"trace\": ");
    match data.trace {
        Some(trace) => {
            s.push_str("{\"phases\": [");
            for (k, phase) in Phase::ALL.iter().enumerate() {
                s.push_str(if k > 0 { "," } else { "" });
                string(&mut s, phase.name());
            }
            s.push(']');
            for name in ["initial_inside", "initial_boundary", "step_triangles", "step_changes"] {
                let _ = write!(s, ",\n\"{name}\": \"{}\"", array(name));
            }
            let _ = write!(s, ",\n\"inflated_at\": {}}}", trace.inflated_at);
        }
        None => s.push_str("null"),
    }
    s.push_str("}\n");
    s
}

/// One array's encoding, run by [`in_parallel`].
type Job<'a> = Box<dyn FnOnce() -> String + Send + 'a>;

/// The results of `jobs`, in order, each computed on a thread of its own.
fn in_parallel(jobs: Vec<Job<'_>>) -> Vec<String> {
    std::thread::scope(|scope| {
        let running: Vec<_> = jobs.into_iter().map(|job| scope.spawn(job)).collect();
        running.into_iter().map(joined).collect()
    })
}

/// The result of a scoped thread; its panic, if any, goes on in this thread.
pub fn joined<T>(handle: std::thread::ScopedJoinHandle<'_, T>) -> T {
    handle.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))
}

fn string(s: &mut String, text: &str) {
    s.push('"');
    for c in text.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            '\n' => s.push_str("\\n"),
            '\t' => s.push_str("\\t"),
            c if u32::from(c) < 0x20 || c == '<' || c == '>' || c == '&' => {
                let _ = write!(s, "\\u{:04x}", u32::from(c));
            }
            c => s.push(c),
        }
    }
    s.push('"');
}

#[cfg(test)]
mod tests {
    use super::*;
    use base64::engine::general_purpose::STANDARD;
    use base64::Engine as _;
    use sigdt::Step;

    /// A square split into two triangles: the first starts interior; inflating takes the
    /// second, sculpting then removes the first. `[0, 3]` starts dangling; the result has an
    /// edge `[1, 3]` that no triangle has.
    fn square() -> String {
        let points = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.1, 1e-7]];
        let nn = [1.0, 1.0, 1.0, f64::INFINITY];
        let edges = [[0, 1], [0, 3], [1, 2], [2, 3]];
        let result = [[0, 2], [1, 3]];
        let trace = Trace {
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            graph: vec![[0, 1], [0, 3], [1, 2]],
            initial_inside: vec![true, false],
            dangling: vec![[0, 3]],
            steps: vec![
                Step { triangle: 1, inside: true, phase: Phase::Inflate },
                Step { triangle: 0, inside: false, phase: Phase::Sculpt },
            ],
            inflated_at: 1,
        };
        view_json(&ViewData {
            title: "a \"square\" </script><!-- \u{1}",
            method: "sig-connect2d",
            status: "polygon",
            points: &points,
            nn: &nn,
            triangles: &trace.triangles,
            layers: vec![("dt", &edges), ("result", &result)],
            gt: None,
            trace: Some(&trace),
        })
    }

    fn decoded(json: &serde_json::Value, path: &[&str]) -> Vec<u8> {
        let value = path.iter().fold(json, |v, k| &v[k]);
        STANDARD.decode(value.as_str().expect("a base64 string")).expect("valid base64")
    }

    #[test]
    fn json_is_exact() {
        let json: serde_json::Value = serde_json::from_str(&square()).expect("valid JSON");
        assert_eq!(json["format"], 2);
        assert_eq!(json["title"], "a \"square\" </script><!-- \u{1}");
        assert_eq!(json["n"], 4);
        assert_eq!(json["palette"]["ink"], "#1a1a1a");
        let xs: Vec<f64> = decoded(&json, &["points"])
            .chunks(8)
            .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
            .collect();
        assert_eq!(xs, [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.1, 1e-7], "coordinates are exact");
        let nn: Vec<f32> = decoded(&json, &["nn"])
            .chunks(4)
            .map(|b| f32::from_le_bytes(b.try_into().unwrap()))
            .collect();
        assert_eq!(nn, [1.0, 1.0, 1.0, f32::INFINITY]);
        let u32s = |path: &[&str]| -> Vec<u32> {
            decoded(&json, path)
                .chunks(4)
                .map(|b| u32::from_le_bytes(b.try_into().unwrap()))
                .collect()
        };
        assert_eq!(u32s(&["triangles"]), [0, 1, 2, 0, 2, 3]);
        assert_eq!(u32s(&["extra_edges"]), [1, 3]);
        // The edge list: 0-1, 0-2, 0-3, 1-2, 1-3, 2-3.
        assert_eq!(decoded(&json, &["layers", "dt"]), [0b101101]);
        assert_eq!(decoded(&json, &["layers", "result"]), [0b010010]);
        assert_eq!(json["layers"]["gt"], serde_json::Value::Null);
        let trace = &json["trace"];
        assert_eq!(trace["phases"], serde_json::json!(["inflate", "pocket", "sculpt"]));
        assert_eq!(decoded(&json, &["trace", "initial_inside"]), [0b01]);
        // Boundary 0-1, 0-2, 0-3 (dangling), 1-2.
        assert_eq!(decoded(&json, &["trace", "initial_boundary"]), [0b001111]);
        assert_eq!(u32s(&["trace", "step_triangles"]), [1, 0]);
        // Inflating triangle [0, 2, 3] toggles its sides 0-2 and 2-3 (0-3 stays, no longer
        // dangling but now a side of the interior); sculpting [0, 1, 2] all three.
        assert_eq!(decoded(&json, &["trace", "step_changes"]), [0b000_011, 0b010_111]);
        assert_eq!(trace["inflated_at"], 1);
    }

    #[test]
    fn page_is_self_contained() {
        let html = viewer_html(&square());
        assert!(html.starts_with("<!DOCTYPE html>"));
        assert!(!html.contains("{{"), "a template marker is left");
        // The only `</script>` are the two closing tags; nothing loads from elsewhere.
        assert_eq!(html.matches("</script").count(), 2);
        // The one address is the SVG namespace of exported pictures, which loads nothing.
        let html_without_namespace = html.replace("xmlns=\"http://www.w3.org/2000/svg\"", "");
        for needle in ["<!--", "src=", "http://", "https://", "url(", "@import"] {
            assert!(!html_without_namespace.contains(needle), "the page contains {needle:?}");
        }
        // The data is in the page, unchanged apart from `<`.
        assert!(html.contains(&square().replace('<', "\\u003c")));
        // A hostile string cannot close the data element.
        let hostile = viewer_html("{\"title\": \"</script><script>alert(1)</script>\"}");
        assert_eq!(hostile.matches("</script").count(), 2);
    }
}
