//! GeoJSON: one `Feature` whose geometry holds the loops and paths and whose properties give
//! the status and counts (and the points left out, when there are any).
use std::io::{self, Write};

use super::geometry::{geometry, write_pair, Kind, Notation};
use crate::geometry::Point;
use crate::result::{Reconstruction, Status};

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

/// The GeoJSON `Feature` of `rec` and a newline.
pub(super) fn geojson(out: &mut Vec<u8>, points: &[Point], rec: &Reconstruction) -> io::Result<()> {
    out.extend_from_slice(br#"{"type": "Feature", "geometry": "#);
    geometry::<GeoJson>(out, points, rec)?;
    let (n, m, d) = (points.len(), rec.edges.len(), rec.duplicates.len());
    let (k, p, status) = (rec.loops.len(), rec.paths.len(), rec.status.name());
    write!(out, r#", "properties": {{"status": "{status}", "points": {n}, "edges": {m}, "#)?;
    write!(out, r#""loops": {k}, "paths": {p}, "duplicates": {d}"#)?;
    if let Status::SculptingStuck { left_out } = &rec.status {
        let left_out: Vec<_> = left_out.iter().map(usize::to_string).collect();
        write!(out, r#", "left_out": [{}]"#, left_out.join(", "))?;
    }
    out.extend_from_slice(b"}}\n");
    Ok(())
}
