//! `sigdt view`: one self-contained HTML page to explore a reconstruction.
//!
//! The page draws the points, the proximity graphs (DT, SIG circles, SIGDT, SIGDT2), the
//! boundary after inflating, the result and the ground truth on a canvas, with pan, zoom and
//! layer toggles, and replays the inflating and sculpting steps one triangle at a time (the
//! paper's Figures 4, 6, 7). Everything is inlined: the stylesheet, the scripts and the
//! data, which sits in a `<script type="application/json">` element. The page loads nothing
//! from the network and works from `file://`.
//!
//! [`view_json`] writes the data; [`viewer_html`] wraps it into the page. The format
//! (edges are `[i, j]` point indices with `i < j`, triangles `[i, j, k]`):
//!
//! ```text
//! {"title": "glyph_n_tilde (385 points)", "method": "sig-connect2d", "status": "polygon",
//!  "points": [[x, y], ...], "nn": [r | null, ...],
//!  "layers": {"dt": [[i, j], ...], "sigdt": [...], "sigdt2": [...], "boundary": [...],
//!             "result": [...], "gt": [...] | null},
//!  "trace": null | {"phases": ["inflate", "pocket", "sculpt"],
//!                   "triangles": [[i, j, k], ...], "initial_inside": [0 | 1, ...],
//!                   "initial_boundary": [[i, j], ...],
//!                   "steps": [[t, phase, [[i, j], ...]], ...], "inflated_at": K}}
//! ```
//!
//! `nn` is the SIG circle radius (`null` for a lone point); `boundary` (the boundary after
//! inflating) is there only with a trace. The trace is replayed by the kernel
//! ([`sigdt::Trace`]), never by the page: each step turns its triangle `t` to the other label
//! and toggles the listed edges in or out of the boundary ([`Trace::boundary_changes`]),
//! starting from `initial_boundary` ([`Trace::boundary_at`]`(0)`). Flipping and toggling are
//! their own inverse, so the page steps back by applying the same step again. `phase` is
//! [`Phase::code`], an index into `phases` ([`Phase::ALL`] by name). The page reads the labels
//! only to fill the interior: it orients each boundary edge with its interior triangle on
//! the left, and leaves out the dangling edges, which have none.
//!
//! The scripts are split by concern: `model.js` (data, applying steps), `draw.js` (camera,
//! canvas), `ui.js` (legend, step controls, mouse, keyboard).

use std::fmt::Write;

use sigdt::{Phase, Trace};

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

/// The page's data as JSON; floats are written in their shortest round-trip form and
/// non-finite ones as `null`.
pub fn view_json(data: &ViewData) -> String {
    let mut s = String::with_capacity(64 * data.points.len() + 1024);
    s.push_str("{\"title\": ");
    string(&mut s, data.title);
    s.push_str(", \"method\": ");
    string(&mut s, data.method);
    s.push_str(", \"status\": ");
    string(&mut s, data.status);
    s.push_str(",\n\"points\": ");
    list(&mut s, data.points, |s, &[x, y]| {
        s.push('[');
        number(s, x);
        s.push(',');
        number(s, y);
        s.push(']');
    });
    s.push_str(",\n\"nn\": ");
    list(&mut s, data.nn, |s, &r| number(s, r));
    s.push_str(",\n\"layers\": {");
    for (name, edges) in &data.layers {
        string(&mut s, name);
        s.push_str(": ");
        pairs(&mut s, edges);
        s.push_str(",\n");
    }
    s.push_str("\"gt\": ");
    match data.gt {
        Some(gt) => pairs(&mut s, gt),
        None => s.push_str("null"),
    }
    s.push_str("},\n\"trace\": ");
    match &data.trace {
        Some(trace) => trace_json(&mut s, trace),
        None => s.push_str("null"),
    }
    s.push_str("}\n");
    s
}

/// The trace as the page replays it: the initial labels and boundary, and per step the
/// triangle, the phase code and the edges it toggles.
fn trace_json(s: &mut String, trace: &Trace) {
    s.push_str("{\"phases\": ");
    list(s, &Phase::ALL, |s, phase| string(s, phase.name()));
    s.push_str(",\n\"triangles\": ");
    list(s, &trace.triangles, |s, [i, j, k]| {
        let _ = write!(s, "[{i},{j},{k}]");
    });
    s.push_str(",\n\"initial_inside\": ");
    list(s, &trace.initial_inside, |s, &inside| s.push(if inside { '1' } else { '0' }));
    s.push_str(",\n\"initial_boundary\": ");
    pairs(s, &trace.boundary_at(0));
    s.push_str(",\n\"steps\": ");
    let changes = trace.boundary_changes();
    let steps: Vec<_> = trace.steps.iter().zip(&changes).collect();
    list(s, &steps, |s, (step, toggled)| {
        let _ = write!(s, "[{},{},", step.triangle, step.phase.code());
        pairs(s, toggled);
        s.push(']');
    });
    let _ = write!(s, ",\n\"inflated_at\": {}}}", trace.inflated_at);
}

fn pairs(s: &mut String, edges: &[[usize; 2]]) {
    list(s, edges, |s, [i, j]| {
        let _ = write!(s, "[{i},{j}]");
    });
}

fn list<T>(s: &mut String, items: &[T], mut item: impl FnMut(&mut String, &T)) {
    s.push('[');
    for (n, x) in items.iter().enumerate() {
        if n > 0 {
            s.push(',');
        }
        item(s, x);
    }
    s.push(']');
}

/// `Debug` prints the shortest string that reads back as the same `f64`, switching to
/// exponent notation (`1e-7`, `1e16`) for very small or large magnitudes: valid JSON.
fn number(s: &mut String, x: f64) {
    if x.is_finite() {
        let _ = write!(s, "{x:?}");
    } else {
        s.push_str("null");
    }
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
    use sigdt::Step;

    /// A square split into two triangles: the first starts interior; inflating takes the
    /// second, sculpting then removes the first. `[0, 3]` starts dangling.
    fn square() -> String {
        let points = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1e-7]];
        let nn = [1.0, 1.0, 1.0, f64::INFINITY];
        let edges = [[0, 1], [0, 3], [1, 2], [2, 3]];
        let diagonal = [[0, 2]];
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
            layers: vec![("dt", &edges), ("result", &diagonal)],
            gt: None,
            trace: Some(&trace),
        })
    }

    #[test]
    fn json_is_exact() {
        assert_eq!(
            square(),
            "{\"title\": \"a \\\"square\\\" \\u003c/script\\u003e\\u003c!-- \\u0001\", \
             \"method\": \"sig-connect2d\", \"status\": \"polygon\",\n\
             \"points\": [[0.0,0.0],[1.0,0.0],[1.0,1.0],[0.0,1e-7]],\n\
             \"nn\": [1.0,1.0,1.0,null],\n\
             \"layers\": {\"dt\": [[0,1],[0,3],[1,2],[2,3]],\n\"result\": [[0,2]],\n\"gt\": null},\n\
             \"trace\": {\"phases\": [\"inflate\",\"pocket\",\"sculpt\"],\n\
             \"triangles\": [[0,1,2],[0,2,3]],\n\"initial_inside\": [1,0],\n\
             \"initial_boundary\": [[0,1],[0,2],[0,3],[1,2]],\n\
             \"steps\": [[1,0,[[0,2],[2,3]]],[0,2,[[0,1],[0,2],[1,2]]]],\n\"inflated_at\": 1}}\n"
        );
    }

    #[test]
    fn floats_round_trip() {
        for x in [0.1, 1.0 / 3.0, 1e300, -2.5e-300, 933.7133121, f64::MIN_POSITIVE, 123456789.0] {
            let mut s = String::new();
            number(&mut s, x);
            assert_eq!(s.parse::<f64>().unwrap(), x, "{s}");
        }
    }

    #[test]
    fn page_is_self_contained() {
        let html = viewer_html(&square());
        assert!(html.starts_with("<!DOCTYPE html>"));
        assert!(!html.contains("{{"), "a template marker is left");
        // The only `</script>` are the two closing tags; nothing loads from elsewhere.
        assert_eq!(html.matches("</script").count(), 2);
        for needle in ["<!--", "src=", "http://", "https://", "url(", "@import"] {
            assert!(!html.contains(needle), "the page contains {needle:?}");
        }
        // The data is in the page, unchanged apart from `<`.
        assert!(html.contains(&square().replace('<', "\\u003c")));
        // A hostile string cannot close the data element.
        let hostile = viewer_html("{\"title\": \"</script><script>alert(1)</script>\"}");
        assert_eq!(hostile.matches("</script").count(), 2);
    }
}
