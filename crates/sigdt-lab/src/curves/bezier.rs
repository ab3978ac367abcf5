//! Chains of cubic Bézier segments read from the `<path d="…">` elements of an SVG file.
//!
//! The Bézier experiment of \[MOW22\] (Fig. 14) ε-samples cubic Bézier drawings, as the
//! benchmark authors' `sampling2d` does with their SVG files \[OMW21\]. This module turns such
//! a file into [`BezierPath`]s:
//!
//! 1. A small scanner finds every `<path …>` start tag outside comments and reads its `d`
//!    attribute (single or double quotes, any whitespace, tags spanning several lines).
//!    Other elements (`<rect>`, `<circle>`, …) are ignored.
//! 2. `svgtypes`' simplifying parser turns the path data into absolute move-to, line-to,
//!    cubic and quadratic segments (relative, smooth, horizontal/vertical and arc commands
//!    are converted by it; arcs become cubics).
//! 3. Lines and quadratics are degree-elevated to cubics, which is exact. Segments whose four
//!    control points coincide are dropped.
//! 4. Each subpath (`M …`) becomes its own curve. It is closed if it ends with `Z` (a closing
//!    line is added when its end is not its start) or if its last point equals its first one
//!    exactly; otherwise it is open.
//!
//! Not supported, by design: `transform` attributes (on the path or on enclosing groups) are
//! **ignored**, so coordinates are the raw user units of `d`; units, `viewBox` and CSS are
//! ignored as well; entities in `d` are not decoded (they fail to parse). A `<path>` without
//! `d` draws nothing and is skipped.
//!
//! # Complexity
//! O(length of the file).
//!
//! # Errors
//! [`Error::Parse`] naming the file and the line of the offending `<path` (an unterminated
//! tag, comment or attribute value, bad path data, a non-finite coordinate), and
//! [`Error::Io`] for unreadable files.
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//! \[OMW21\] S. Ohrhallinger, J. Peethambaran, A. Parakkat, T. Dey, R. Muthuganapathy.
//! 2D Points Curve Reconstruction Survey and Benchmark. 2021.
use std::path::Path;

use svgtypes::{PathParser, PathSegment, SimplePathSegment, SimplifyingPathParser};

use crate::power_of_two::scale;
use sigdt::internals::distance;
use sigdt::{Error, Point, Result};

/// The most cubic segments one path may have: 4·10⁶ dense points when ε-sampled, a few
/// hundred megabytes for the triangulation and the lfs (a 20,000-segment polygon used to ask
/// for gigabytes).
pub const MAX_SEGMENTS: usize = 4096;

/// A chain of cubic Bézier segments, each `[start, control1, control2, end]`, where every
/// segment starts where the previous one ends (and, if `closed`, the last one ends where the
/// first one starts).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BezierPath {
    /// The segments in path order.
    pub segments: Vec<[Point; 4]>,
    /// Whether the chain is a closed curve.
    pub closed: bool,
}

impl BezierPath {
    /// The largest magnitude of a control point's coordinate.
    pub fn largest_coordinate(&self) -> f64 {
        self.segments.iter().flatten().flatten().fold(0.0, |m: f64, v| m.max(v.abs()))
    }

    /// The path with every control point multiplied by `2^power` (exactly, in the normal
    /// range).
    pub fn scaled(&self, power: i32) -> BezierPath {
        let s = |p: Point| p.map(|v| scale(v, power));
        let segments = self.segments.iter().map(|segment| segment.map(s)).collect();
        BezierPath { segments, closed: self.closed }
    }

    /// The point at global parameter `u`: segment `⌊u⌋` at its local parameter `u − ⌊u⌋`.
    /// `u` is taken modulo the number of segments for a closed path and clamped to
    /// `[0, segments]` for an open one. The origin for an empty path.
    pub fn point(&self, u: f64) -> Point {
        match self.locate(u) {
            Some((b, t)) => {
                let s = 1.0 - t;
                let w = [s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t];
                let c = |a: usize| (0..4).map(|k| w[k] * b[k][a]).sum::<f64>();
                [c(0), c(1)]
            }
            None => [0.0, 0.0],
        }
    }

    /// The derivative with respect to `u` at global parameter `u` (same conventions as
    /// [`point`](Self::point)). It may vanish where control points coincide.
    pub fn derivative(&self, u: f64) -> Point {
        match self.locate(u) {
            Some((b, t)) => {
                let s = 1.0 - t;
                let w = [3.0 * s * s, 6.0 * s * t, 3.0 * t * t];
                let c = |a: usize| (0..3).map(|k| w[k] * (b[k + 1][a] - b[k][a])).sum::<f64>();
                [c(0), c(1)]
            }
            None => [0.0, 0.0],
        }
    }

    /// The chain as a polyline of `steps` points per segment, at parameters `k / steps` (an
    /// open chain also at its end), with its edges in chain order: the "original curve"
    /// against which the Bézier experiments measure distances (\[MOW22\] Figs. 14, 17).
    /// Edges are `[i, j]` with `i < j`, sorted. Empty for an empty chain or `steps == 0`.
    pub fn polyline(&self, steps: usize) -> sigdt::samplers::Sample {
        let m = self.segments.len();
        if m == 0 || steps == 0 {
            return sigdt::samplers::Sample { points: Vec::new(), edges: Vec::new() };
        }
        let n = steps * m + usize::from(!self.closed);
        let points: Vec<Point> = (0..n).map(|k| self.point(k as f64 / steps as f64)).collect();
        let mut edges: Vec<sigdt::Edge> = (1..n).map(|k| [k - 1, k]).collect();
        if self.closed && n > 2 {
            edges.insert(1, [0, n - 1]);
        }
        sigdt::samplers::Sample { points, edges }
    }

    /// The segment and local parameter of global parameter `u`.
    fn locate(&self, u: f64) -> Option<(&[Point; 4], f64)> {
        let m = self.segments.len();
        if m == 0 || !u.is_finite() {
            return self.segments.first().map(|b| (b, 0.0));
        }
        let span = m as f64;
        let u = if self.closed { u.rem_euclid(span) } else { u.clamp(0.0, span) };
        let k = (u.floor() as usize).min(m - 1);
        Some((&self.segments[k], u - k as f64))
    }
}

/// Reads every `<path>` of the SVG file `path` as Bézier chains, one per subpath, in file
/// order.
///
/// Lines and quadratics are elevated to cubics, arcs become cubics, zero-length segments are
/// dropped. A subpath is closed if it ends with `Z` (adding a closing line if needed) or
/// returns exactly to its start. `transform` attributes, units, `viewBox` and CSS are
/// **ignored**: coordinates are the raw numbers of `d`. Every `<path>` outside comments counts,
/// also one inside `<defs>`; a `<path>` without `d` is skipped.
///
/// # Errors
/// [`Error::Io`] if the file cannot be read; [`Error::Parse`] with the file and the line of
/// the offending `<path` for an unterminated tag, comment or value, bad path data or a
/// non-finite coordinate.
pub fn read_svg_paths(path: &Path) -> Result<Vec<BezierPath>> {
    let name = path.display().to_string();
    let text =
        std::fs::read_to_string(path).map_err(|source| Error::Io { path: name.clone(), source })?;
    parse_svg_paths(&text, &name)
}

/// Parses the `<path>` elements of the SVG document `text`; `name` is the file name used in
/// error messages. Returns no curve for a document without paths.
///
/// # Errors
/// As [`read_svg_paths`], without I/O errors.
pub fn parse_svg_paths(text: &str, name: &str) -> Result<Vec<BezierPath>> {
    let mut curves = Vec::new();
    for (d, line) in path_data(text, name)? {
        subpaths(&d, name, line, &mut curves)?;
    }
    Ok(curves)
}

/// The `d` value and 1-based line of every `<path` start tag of `text`, in order.
fn path_data(text: &str, name: &str) -> Result<Vec<(String, usize)>> {
    let bytes = text.as_bytes();
    // Lines are counted from the last position asked for, which only moves forward, so the
    // whole scan stays linear in the file (not quadratic in its number of paths).
    let counted = std::cell::Cell::new((0usize, 1usize));
    let line_at = |pos: usize| {
        let (from, line) = counted.get();
        let line = line + bytes[from..pos].iter().filter(|&&b| b == b'\n').count();
        counted.set((pos, line));
        line
    };
    let fail = |pos: usize, message: String| Error::Parse {
        path: name.to_string(),
        line: line_at(pos),
        message,
    };
    let mut found = Vec::new();
    let mut pos = 0;
    while let Some(off) = text[pos..].find('<') {
        let start = pos + off;
        let rest = &text[start..];
        if rest.starts_with("<!--") {
            let end = rest.find("-->").ok_or_else(|| fail(start, "unterminated comment".into()))?;
            pos = start + end + 3;
            continue;
        }
        if rest.starts_with("<![CDATA[") {
            let end =
                rest.find("]]>").ok_or_else(|| fail(start, "unterminated CDATA section".into()))?;
            pos = start + end + 3;
            continue;
        }
        let is_path = rest.starts_with("<path")
            && rest[5..].chars().next().is_some_and(|c| c.is_whitespace() || c == '/' || c == '>');
        if !is_path {
            pos = start + 1;
            continue;
        }
        let (d, end) = attribute_d(text, start + 5).map_err(|message| fail(start, message))?;
        if let Some(d) = d {
            found.push((d, line_at(start)));
        }
        pos = end;
    }
    Ok(found)
}

/// Scans the attributes of a start tag from byte `pos` (just after the element name) to its
/// closing `>`; returns the value of `d` (if any) and the position after the tag.
fn attribute_d(text: &str, mut pos: usize) -> std::result::Result<(Option<String>, usize), String> {
    let b = text.as_bytes();
    let skip_ws = |mut p: usize| {
        while p < b.len() && b[p].is_ascii_whitespace() {
            p += 1;
        }
        p
    };
    let mut d = None;
    loop {
        pos = skip_ws(pos);
        match b.get(pos) {
            None => return Err("unterminated <path> tag".into()),
            Some(b'>') => return Ok((d, pos + 1)),
            Some(b'/') if b.get(pos + 1) == Some(&b'>') => return Ok((d, pos + 2)),
            _ => {}
        }
        let name_start = pos;
        while pos < b.len()
            && !b[pos].is_ascii_whitespace()
            && !matches!(b[pos], b'=' | b'>' | b'/')
        {
            pos += 1;
        }
        let attr = &text[name_start..pos];
        if attr.is_empty() {
            return Err(format!("unexpected '{}' in <path> tag", b[pos] as char));
        }
        pos = skip_ws(pos);
        if b.get(pos) != Some(&b'=') {
            continue; // an attribute without value (not XML, but harmless)
        }
        pos = skip_ws(pos + 1);
        let quote = match b.get(pos) {
            Some(&q @ (b'"' | b'\'')) => q,
            _ => return Err(format!("attribute '{attr}' of <path> has no quoted value")),
        };
        let len = text[pos + 1..]
            .find(quote as char)
            .ok_or_else(|| format!("unterminated value of attribute '{attr}'"))?;
        if attr == "d" {
            d = Some(text[pos + 1..pos + 1 + len].to_string());
        }
        pos += len + 2;
    }
}

/// Appends the subpaths of path data `d` (from the `<path` on `line`) to `curves`.
fn subpaths(d: &str, name: &str, line: usize, curves: &mut Vec<BezierPath>) -> Result<()> {
    let fail = |message: String| Error::Parse { path: name.to_string(), line, message };
    // svgtypes expands arcs to an absolute tolerance: at the drawing's own scale a circle
    // of radius 1e18 became thousands of cubics. The data are read scaled by a power of two
    // to a fixed size instead, and the cubics scaled back (exactly): the same curves at any
    // scale.
    let (scaled, power) = scaled_to_fixed_size(d);
    let d = scaled.as_deref().unwrap_or(d);
    let first_new = curves.len();
    let mut current = BezierPath::default();
    let (mut start, mut at) = ([0.0, 0.0], [0.0, 0.0]);
    let mut finish = |path: &mut BezierPath, at: Point, start: Point| {
        let mut path = std::mem::take(path);
        if !path.segments.is_empty() {
            path.closed |= at == start;
            curves.push(path.scaled(-power));
        }
    };
    check_arcs(d, power).map_err(fail)?;
    for segment in SimplifyingPathParser::from(d) {
        let segment = segment.map_err(|e| fail(format!("bad path data: {e}")))?;
        let (cubic, end) = match segment {
            SimplePathSegment::MoveTo { x, y } => {
                finish(&mut current, at, start);
                start = finite([x, y]).ok_or_else(|| fail(non_finite(x, y)))?;
                at = start;
                continue;
            }
            SimplePathSegment::ClosePath => {
                if rounding_apart(&current, at, start) {
                    // The decimal text only missed the start (a circle drawn as arcs ends
                    // 1e-14 away): snap the end onto it instead of adding a closing line
                    // that short, whose noisy corners would make lfs vanish there.
                    if let Some(last) = current.segments.last_mut() {
                        last[3] = start;
                    }
                } else if at != start {
                    current.segments.push(line_cubic(at, start));
                }
                current.closed = true;
                finish(&mut current, start, start);
                at = start;
                continue;
            }
            SimplePathSegment::LineTo { x, y } => {
                let end = finite([x, y]).ok_or_else(|| fail(non_finite(x, y)))?;
                (line_cubic(at, end), end)
            }
            SimplePathSegment::Quadratic { x1, y1, x, y } => {
                let c = finite([x1, y1]).ok_or_else(|| fail(non_finite(x1, y1)))?;
                let end = finite([x, y]).ok_or_else(|| fail(non_finite(x, y)))?;
                let lerp = |p: Point, q: Point| {
                    [p[0] + (q[0] - p[0]) * 2.0 / 3.0, p[1] + (q[1] - p[1]) * 2.0 / 3.0]
                };
                ([at, lerp(at, c), lerp(end, c), end], end)
            }
            SimplePathSegment::CurveTo { x1, y1, x2, y2, x, y } => {
                let c1 = finite([x1, y1]).ok_or_else(|| fail(non_finite(x1, y1)))?;
                let c2 = finite([x2, y2]).ok_or_else(|| fail(non_finite(x2, y2)))?;
                let end = finite([x, y]).ok_or_else(|| fail(non_finite(x, y)))?;
                ([at, c1, c2, end], end)
            }
        };
        if cubic.iter().any(|&p| p != at) {
            current.segments.push(cubic);
            if current.segments.len() > MAX_SEGMENTS {
                // An elliptical arc of radius 1e33 becomes about a million cubics (the
                // conversion's tolerance is absolute): stop reading instead.
                return Err(fail(format!(
                    "a subpath of more than {MAX_SEGMENTS} cubic segments (a huge arc?)"
                )));
            }
        }
        at = end;
    }
    finish(&mut current, at, start);
    // Relative coordinates may add up past f64::MAX, which the fixed size hides until the
    // cubics are scaled back.
    if curves[first_new..].iter().any(|c| !c.largest_coordinate().is_finite()) {
        return Err(fail("a non-finite coordinate: the path data overflow f64".to_string()));
    }
    Ok(())
}

/// The size path data are read at: coordinates up to 2^10, as in a drawing in points or
/// millimetres (svgtypes' arc tolerance, 0.1, is made for that).
const READ_SIZE_POWER: i32 = 10;

/// `d` with every coordinate and radius multiplied by `2^power`, the power that brings the
/// largest into `[2^9, 2^10)`, and that power; `(None, 0)` when `d` does not parse (the
/// simplifying parser then reports it) or has no non-zero finite coordinate.
fn scaled_to_fixed_size(d: &str) -> (Option<String>, i32) {
    let Ok(segments) = PathParser::from(d).collect::<std::result::Result<Vec<_>, _>>() else {
        return (None, 0);
    };
    let mut largest = 0.0f64;
    for segment in &segments {
        let lengths: &[f64] = match segment {
            PathSegment::MoveTo { x, y, .. }
            | PathSegment::LineTo { x, y, .. }
            | PathSegment::SmoothQuadratic { x, y, .. } => &[*x, *y],
            PathSegment::HorizontalLineTo { x, .. } => &[*x],
            PathSegment::VerticalLineTo { y, .. } => &[*y],
            PathSegment::CurveTo { x1, y1, x2, y2, x, y, .. } => &[*x1, *y1, *x2, *y2, *x, *y],
            PathSegment::SmoothCurveTo { x2, y2, x, y, .. }
            | PathSegment::Quadratic { x1: x2, y1: y2, x, y, .. } => &[*x2, *y2, *x, *y],
            PathSegment::EllipticalArc { rx, ry, x, y, .. } => &[*rx, *ry, *x, *y],
            PathSegment::ClosePath { .. } => &[],
        };
        if lengths.iter().any(|v| !v.is_finite()) {
            return (None, 0); // refused, with the value, by the simplifying parser's reading
        }
        largest = lengths.iter().fold(largest, |m, v| m.max(v.abs()));
    }
    let power = fixed_size_power(largest);
    if power == 0 {
        return (None, 0);
    }
    let s = |v: f64| format!("{:?}", scale(v, power));
    let mut out = String::with_capacity(d.len());
    for segment in segments {
        let (letter, abs, numbers): (char, bool, Vec<String>) = match segment {
            PathSegment::MoveTo { abs, x, y } => ('M', abs, vec![s(x), s(y)]),
            PathSegment::LineTo { abs, x, y } => ('L', abs, vec![s(x), s(y)]),
            PathSegment::HorizontalLineTo { abs, x } => ('H', abs, vec![s(x)]),
            PathSegment::VerticalLineTo { abs, y } => ('V', abs, vec![s(y)]),
            PathSegment::CurveTo { abs, x1, y1, x2, y2, x, y } => {
                ('C', abs, vec![s(x1), s(y1), s(x2), s(y2), s(x), s(y)])
            }
            PathSegment::SmoothCurveTo { abs, x2, y2, x, y } => {
                ('S', abs, vec![s(x2), s(y2), s(x), s(y)])
            }
            PathSegment::Quadratic { abs, x1, y1, x, y } => {
                ('Q', abs, vec![s(x1), s(y1), s(x), s(y)])
            }
            PathSegment::SmoothQuadratic { abs, x, y } => ('T', abs, vec![s(x), s(y)]),
            PathSegment::EllipticalArc { abs, rx, ry, x_axis_rotation, large_arc, sweep, x, y } => {
                let flag = |f: bool| u8::from(f).to_string();
                let rotation = format!("{x_axis_rotation:?}");
                ('A', abs, vec![s(rx), s(ry), rotation, flag(large_arc), flag(sweep), s(x), s(y)])
            }
            PathSegment::ClosePath { abs } => ('Z', abs, vec![]),
        };
        out.push(if abs { letter } else { letter.to_ascii_lowercase() });
        for v in numbers {
            out.push(' ');
            out.push_str(&v);
        }
        out.push(' ');
    }
    (Some(out), power)
}

/// The power of two that brings `largest` into `[2^9, 2^10)`; 0 for zero or non-finite.
pub(crate) fn fixed_size_power(largest: f64) -> i32 {
    crate::power_of_two::exponent_into(largest, READ_SIZE_POWER - 1)
}

/// Whether `at` misses `start` only by floating-point rounding of the path's coordinates:
/// by at most 2^-40 (about 1e-12) of their largest magnitude, and not at all.
fn rounding_apart(path: &BezierPath, at: Point, start: Point) -> bool {
    let scale = path.segments.iter().flatten().flatten().fold(0.0, |m: f64, v| m.max(v.abs()));
    at != start && !path.segments.is_empty() && distance(at, start) <= scale * 2f64.powi(-40)
}

/// Refuses path data with an elliptical arc that svgtypes would expand without bound.
///
/// svgtypes turns an arc into cubics to an absolute tolerance of 0.1, about `(11·r)^(1/6)`
/// of them a turn: a radius past the limit below makes more than [`MAX_SEGMENTS`], and a
/// radius of 1e33 takes seconds inside the parser, before any later limit can act (and the
/// parser then hands the cubics out one by one from the front of a list, quadratic in
/// their number). Radii too small to span the chord grow as SVG says ([`arc_radius`]), so
/// the current point is followed through the raw segments to measure the chord.
fn check_arcs(d: &str, power: i32) -> std::result::Result<(), String> {
    let limit = 0.1 / 1.1163 * (MAX_SEGMENTS as f64).powi(6);
    let (mut at, mut start) = ([0.0f64; 2], [0.0f64; 2]);
    let to =
        |abs: bool, at: [f64; 2], x: f64, y: f64| if abs { [x, y] } else { [at[0] + x, at[1] + y] };
    for segment in PathParser::from(d) {
        let Ok(segment) = segment else { break }; // the simplifying parser reports it
        let end = match segment {
            PathSegment::MoveTo { abs, x, y } => {
                start = to(abs, at, x, y);
                start
            }
            PathSegment::LineTo { abs, x, y }
            | PathSegment::CurveTo { abs, x, y, .. }
            | PathSegment::SmoothCurveTo { abs, x, y, .. }
            | PathSegment::Quadratic { abs, x, y, .. }
            | PathSegment::SmoothQuadratic { abs, x, y } => to(abs, at, x, y),
            PathSegment::HorizontalLineTo { abs, x } => [if abs { x } else { at[0] + x }, at[1]],
            PathSegment::VerticalLineTo { abs, y } => [at[0], if abs { y } else { at[1] + y }],
            PathSegment::ClosePath { .. } => start,
            PathSegment::EllipticalArc { abs, rx, ry, x_axis_rotation, x, y, .. } => {
                let end = to(abs, at, x, y);
                // The arc converter draws a radius up to 1e-5 as a straight line, an absolute
                // bound: read at the fixed size, a radius that small against the drawing
                // would turn an arc of the file into a line. Such an arc is refused instead.
                let thin = |r: f64| r.abs() > 0.0 && r.abs() <= 1e-5 && scale(r, -power) != r;
                if thin(rx) || thin(ry) {
                    let [rx, ry] = [rx, ry].map(|r| scale(r, -power));
                    return Err(format!(
                        "an elliptical arc of radii {rx:.1e} and {ry:.1e}: one is too small \
                         against the size of the drawing to draw as an arc"
                    ));
                }
                let size = arc_radius(at, end, rx, ry, x_axis_rotation);
                if size.is_nan() || size > limit {
                    // The radius as the file gives it, not at the size it is read at.
                    let size = scale(size, -power);
                    return Err(format!(
                        "an elliptical arc of radius {size:.1e} (grown, as SVG does, to span its \
                         chord) would need more than {MAX_SEGMENTS} cubic segments"
                    ));
                }
                end
            }
        };
        at = end;
    }
    Ok(())
}

/// The larger radius of the arc from `from` to `to` with radii `rx`, `ry` and x-axis
/// rotation `degrees`, after SVG's correction of radii too small to span the chord (SVG 1.1
/// F.6.6: both scaled by `√Λ` when `Λ = x₁′²/rx² + y₁′²/ry² > 1`). A thin ellipse across a
/// long chord grows by the chord over its small radius: `ry = 14` across 5·10²⁰ scales
/// `rx = 10¹⁹` to 10³⁸. Infinite or NaN when it overflows; zero for a zero radius (a line).
fn arc_radius(from: [f64; 2], to: [f64; 2], rx: f64, ry: f64, degrees: f64) -> f64 {
    let (rx, ry) = (rx.abs(), ry.abs());
    if rx == 0.0 || ry == 0.0 {
        return 0.0;
    }
    let (sin, cos) = degrees.to_radians().sin_cos();
    let (dx, dy) = (0.5 * (from[0] - to[0]), 0.5 * (from[1] - to[1]));
    let (x1, y1) = (cos * dx + sin * dy, cos * dy - sin * dx);
    let lambda = (x1 / rx).powi(2) + (y1 / ry).powi(2);
    rx.max(ry) * lambda.sqrt().max(1.0)
}

/// The cubic tracing the straight segment from `p` to `q` at constant speed.
fn line_cubic(p: Point, q: Point) -> [Point; 4] {
    let lerp = |s: f64| [p[0] + (q[0] - p[0]) * s, p[1] + (q[1] - p[1]) * s];
    [p, lerp(1.0 / 3.0), lerp(2.0 / 3.0), q]
}

fn finite(p: Point) -> Option<Point> {
    p.iter().all(|v| v.is_finite()).then_some(p)
}

fn non_finite(x: f64, y: f64) -> String {
    format!("non-finite coordinate ({x}, {y}) in path data")
}

#[cfg(test)]
#[path = "bezier_tests.rs"]
mod tests;
