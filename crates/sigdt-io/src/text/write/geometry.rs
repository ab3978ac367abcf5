//! The geometry of a result (its loops as polygons with holes, its paths as lines, as
//! [`outlines`](crate::gis::outlines) gives them) written in either notation: WKT
//! ([`Wkt`](super::wkt::Wkt)) or GeoJSON ([`GeoJson`](super::geojson::GeoJson)).
//!
//! Shells run counter-clockwise, holes clockwise (as both formats recommend). A ring
//! repeats its first point at the end.
use std::io::{self, Write};

use crate::gis::outlines::Outlines;
use sigdt::Point;

/// The geometry types both notations share.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Polygon,
    MultiPolygon,
    LineString,
    MultiLineString,
}

/// How a notation spells geometries.
pub(super) trait Notation {
    /// Opens and closes a list (of rings, of points).
    const OPEN: &'static str;
    /// See [`Notation::OPEN`].
    const CLOSE: &'static str;
    /// The empty geometry.
    const EMPTY: &'static str;
    /// Around the members of a geometry collection.
    const COLLECTION: [&'static str; 2];
    /// Around the coordinates of a geometry of `kind`.
    fn tag(kind: Kind) -> [&'static str; 2];
    /// One coordinate pair.
    fn point(out: &mut Vec<u8>, p: Point) -> io::Result<()>;
}

/// Writes the geometry of `outlines` in notation `N`.
pub(super) fn geometry<N: Notation>(out: &mut Vec<u8>, outlines: &Outlines) -> io::Result<()> {
    let polygons = &outlines.polygons;
    let lines: Vec<&Vec<Point>> = outlines.lines.iter().flat_map(|l| &l.pieces).collect();
    match (polygons.is_empty(), lines.is_empty()) {
        (true, true) => out.extend_from_slice(N::EMPTY.as_bytes()),
        (false, true) => write_polygons::<N>(out, polygons)?,
        (true, false) => write_lines::<N>(out, &lines)?,
        (false, false) => {
            let [open, close] = N::COLLECTION;
            out.extend_from_slice(open.as_bytes());
            write_polygons::<N>(out, polygons)?;
            out.extend_from_slice(b", ");
            write_lines::<N>(out, &lines)?;
            out.extend_from_slice(close.as_bytes());
        }
    }
    Ok(())
}

/// The polygons as one polygon, or a multi-polygon when there are several.
fn write_polygons<N: Notation>(out: &mut Vec<u8>, polygons: &[Vec<Vec<Point>>]) -> io::Result<()> {
    let multi = polygons.len() > 1;
    let [before, after] = N::tag(if multi { Kind::MultiPolygon } else { Kind::Polygon });
    out.extend_from_slice(before.as_bytes());
    if multi {
        out.extend_from_slice(N::OPEN.as_bytes());
    }
    for (k, rings) in polygons.iter().enumerate() {
        separate(out, k);
        out.extend_from_slice(N::OPEN.as_bytes());
        for (r, ring) in rings.iter().enumerate() {
            separate(out, r);
            coordinates::<N>(out, ring.iter().chain(ring.first()))?;
        }
        out.extend_from_slice(N::CLOSE.as_bytes());
    }
    if multi {
        out.extend_from_slice(N::CLOSE.as_bytes());
    }
    out.extend_from_slice(after.as_bytes());
    Ok(())
}

/// The lines as one line string, or a multi-line string when there are several.
fn write_lines<N: Notation>(out: &mut Vec<u8>, lines: &[&Vec<Point>]) -> io::Result<()> {
    let multi = lines.len() > 1;
    let [before, after] = N::tag(if multi { Kind::MultiLineString } else { Kind::LineString });
    out.extend_from_slice(before.as_bytes());
    if multi {
        out.extend_from_slice(N::OPEN.as_bytes());
    }
    for (k, line) in lines.iter().enumerate() {
        separate(out, k);
        coordinates::<N>(out, line.iter())?;
    }
    if multi {
        out.extend_from_slice(N::CLOSE.as_bytes());
    }
    out.extend_from_slice(after.as_bytes());
    Ok(())
}

/// `points` as one list.
fn coordinates<'a, N: Notation>(
    out: &mut Vec<u8>,
    points: impl Iterator<Item = &'a Point>,
) -> io::Result<()> {
    out.extend_from_slice(N::OPEN.as_bytes());
    for (k, &p) in points.enumerate() {
        separate(out, k);
        N::point(out, p)?;
    }
    out.extend_from_slice(N::CLOSE.as_bytes());
    Ok(())
}

/// `", "` before every member of a list but the first.
fn separate(out: &mut Vec<u8>, k: usize) {
    if k > 0 {
        out.extend_from_slice(b", ");
    }
}

/// `x y` with the shortest decimals that read back to the same numbers.
pub(super) fn write_pair(out: &mut Vec<u8>, [x, y]: Point, between: &str) -> io::Result<()> {
    write!(out, "{x:?}{between}{y:?}")
}
