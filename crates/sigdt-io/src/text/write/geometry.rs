//! The geometry of a result (its loops as polygons with holes, its paths as lines) in one
//! walk, written in either notation: WKT ([`Wkt`](super::wkt::Wkt)) or GeoJSON
//! ([`GeoJson`](super::geojson::GeoJson)).
//!
//! Loops are grouped by [`Reconstruction::polygons`]: shells counter-clockwise, holes
//! clockwise (as both formats recommend). A ring repeats its first point at the end.
use std::io::{self, Write};

use sigdt::Point;
use sigdt::Reconstruction;

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

/// Writes the geometry of `rec` (indices into `points`) in notation `N`.
pub(super) fn geometry<N: Notation>(
    out: &mut Vec<u8>,
    points: &[Point],
    rec: &Reconstruction,
) -> io::Result<()> {
    match (rec.loops.is_empty(), rec.paths.is_empty()) {
        (true, true) => out.extend_from_slice(N::EMPTY.as_bytes()),
        (false, true) => polygons::<N>(out, points, rec)?,
        (true, false) => lines::<N>(out, points, &rec.paths)?,
        (false, false) => {
            let [open, close] = N::COLLECTION;
            out.extend_from_slice(open.as_bytes());
            polygons::<N>(out, points, rec)?;
            out.extend_from_slice(b", ");
            lines::<N>(out, points, &rec.paths)?;
            out.extend_from_slice(close.as_bytes());
        }
    }
    Ok(())
}

/// The loops as one polygon, or a multi-polygon when there are several shells.
fn polygons<N: Notation>(
    out: &mut Vec<u8>,
    points: &[Point],
    rec: &Reconstruction,
) -> io::Result<()> {
    let polygons = rec.polygons(points);
    let multi = polygons.len() > 1;
    let [before, after] = N::tag(if multi { Kind::MultiPolygon } else { Kind::Polygon });
    out.extend_from_slice(before.as_bytes());
    if multi {
        out.extend_from_slice(N::OPEN.as_bytes());
    }
    for (k, polygon) in polygons.iter().enumerate() {
        separate(out, k);
        out.extend_from_slice(N::OPEN.as_bytes());
        let rings =
            std::iter::once((polygon.shell, false)).chain(polygon.holes.iter().map(|&h| (h, true)));
        for (r, (l, reversed)) in rings.enumerate() {
            separate(out, r);
            let ring = &rec.loops[l];
            if reversed {
                coordinates::<N>(out, points, ring.iter().rev().chain(ring.last()))?;
            } else {
                coordinates::<N>(out, points, ring.iter().chain(ring.first()))?;
            }
        }
        out.extend_from_slice(N::CLOSE.as_bytes());
    }
    if multi {
        out.extend_from_slice(N::CLOSE.as_bytes());
    }
    out.extend_from_slice(after.as_bytes());
    Ok(())
}

/// The paths as one line string, or a multi-line string when there are several.
fn lines<N: Notation>(out: &mut Vec<u8>, points: &[Point], paths: &[Vec<usize>]) -> io::Result<()> {
    let multi = paths.len() > 1;
    let [before, after] = N::tag(if multi { Kind::MultiLineString } else { Kind::LineString });
    out.extend_from_slice(before.as_bytes());
    if multi {
        out.extend_from_slice(N::OPEN.as_bytes());
    }
    for (k, path) in paths.iter().enumerate() {
        separate(out, k);
        coordinates::<N>(out, points, path.iter())?;
    }
    if multi {
        out.extend_from_slice(N::CLOSE.as_bytes());
    }
    out.extend_from_slice(after.as_bytes());
    Ok(())
}

/// The coordinates of `indices` as one list.
fn coordinates<'a, N: Notation>(
    out: &mut Vec<u8>,
    points: &[Point],
    indices: impl Iterator<Item = &'a usize>,
) -> io::Result<()> {
    out.extend_from_slice(N::OPEN.as_bytes());
    for (k, &i) in indices.enumerate() {
        separate(out, k);
        N::point(out, points[i])?;
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
