//! GeoJSON: one `Feature` whose geometry holds the loops and paths and whose properties give
//! the status (its name and what it means), the method when the caller names it, and counts
//! (and, when asked, the legacy `crs` member of GeoJSON 2008) (`points` counts the input; `vertices`, written only when the
//! method moved the points or placed its own, counts the positions the geometry uses), the
//! points left out with their reasons (when there are any), whether front ends warn, and
//! the sampling check's findings (when there are any).
use std::io::{self, Write};

use super::geometry::{geometry, write_pair, Kind, Notation};
use crate::gis::outlines::Outlines;
use sigdt::Point;
use sigdt::{Finding, Reconstruction, Vertices};

/// The GeoJSON notation of geometry objects.
pub(super) struct GeoJson;

impl Notation for GeoJson {
    const OPEN: &'static str = "[";
    const CLOSE: &'static str = "]";
    const EMPTY: &'static str = "null";
    const COLLECTION: [&'static str; 2] =
        [r#"{"type": "GeometryCollection", "geometries": ["#, "]}"];

    fn tag(kind: Kind) -> [&'static str; 2] {
        let name = match kind {
            Kind::Polygon => r#"{"type": "Polygon", "coordinates": "#,
            Kind::MultiPolygon => r#"{"type": "MultiPolygon", "coordinates": "#,
            Kind::LineString => r#"{"type": "LineString", "coordinates": "#,
            Kind::MultiLineString => r#"{"type": "MultiLineString", "coordinates": "#,
        };
        [name, "}"]
    }

    /// JSON has no non-finite numbers: such a point is `[null, null]`.
    fn point(out: &mut Vec<u8>, p: Point) -> io::Result<()> {
        if p.iter().all(|c| c.is_finite()) {
            out.push(b'[');
            write_pair(out, p, ", ")?;
            out.push(b']');
        } else {
            out.extend_from_slice(b"[null, null]");
        }
        Ok(())
    }
}

/// The GeoJSON `Feature` of `rec`, from `n` input points, whose geometry is `outlines` and
/// whose positions are `vertices` ([`Reconstruction::vertex_positions`]), and a newline.
pub(super) fn geojson(
    out: &mut Vec<u8>,
    n: usize,
    vertices: &[Point],
    outlines: &Outlines,
    rec: &Reconstruction,
    options: &super::WriteOptions,
) -> io::Result<()> {
    out.extend_from_slice(br#"{"type": "Feature", "#);
    if let Some(name) = &options.legacy_crs {
        let name = json_text(name);
        write!(out, r#""crs": {{"type": "name", "properties": {{"name": "{name}"}}}}, "#)?;
    }
    out.extend_from_slice(br#""geometry": "#);
    geometry::<GeoJson>(out, outlines)?;
    let (m, d, status) = (rec.edges.len(), rec.duplicates.len(), rec.status.name());
    let message = json_text(&rec.status.to_string());
    write!(out, r#", "properties": {{"status": "{status}", "status_message": "{message}", "#)?;
    if let Some(method) = options.method {
        write!(out, r#""method": "{method}", "#)?;
    }
    write!(out, r#""points": {n}, "#)?;
    if !matches!(rec.vertices, Vertices::Input) {
        write!(out, r#""vertices": {}, "#, vertices.len())?;
    }
    let (k, p) = (rec.loops.len(), rec.paths.len());
    write!(out, r#""edges": {m}, "loops": {k}, "paths": {p}, "duplicates": {d}"#)?;
    if !rec.left_out.is_empty() {
        let indices: Vec<_> = rec.left_out.iter().map(|l| l.index.to_string()).collect();
        let reasons: Vec<_> =
            rec.left_out.iter().map(|l| format!("\"{}\"", l.reason.name())).collect();
        write!(out, r#", "left_out": [{}]"#, indices.join(", "))?;
        write!(out, r#", "left_out_reasons": [{}]"#, reasons.join(", "))?;
    }
    let junctions = rec.junctions();
    if !junctions.is_empty() {
        let indices: Vec<_> = junctions.iter().map(usize::to_string).collect();
        write!(out, r#", "junctions": [{}]"#, indices.join(", "))?;
    }
    write!(out, r#", "warning": {}"#, rec.warns())?;
    if !rec.diagnosis.is_empty() {
        let findings: Vec<String> = rec.diagnosis.iter().map(finding_object).collect();
        write!(out, r#", "diagnosis": [{}]"#, findings.join(", "))?;
    }
    out.extend_from_slice(b"}}\n");
    Ok(())
}

/// One finding of the sampling check as a JSON object: `kind`, `count`, `worst` (a number
/// written as the coordinates are, always with a fraction or an exponent; `null` if it is
/// not finite), `at` (an input index), `point` (its coordinates, as given) and the
/// `message` front ends print.
fn finding_object(f: &Finding) -> String {
    let message = json_text(&f.to_string());
    let number = |x: f64| if x.is_finite() { format!("{x:?}") } else { "null".into() };
    let (worst, [x, y]) = (number(f.worst), f.point.map(number));
    format!(
        r#"{{"kind": "{}", "count": {}, "worst": {worst}, "at": {}, "point": [{x}, {y}], "message": "{message}"}}"#,
        f.kind.name(),
        f.count,
        f.at
    )
}

/// `text` inside a JSON string: backslashes and quotes escaped (sigdt's messages have no
/// control characters).
fn json_text(text: &str) -> String {
    text.replace('\\', "\\\\").replace('"', "\\\"")
}
