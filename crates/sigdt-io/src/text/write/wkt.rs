//! Well-known text: `POLYGON`, `MULTIPOLYGON`, `LINESTRING`, `MULTILINESTRING`, or a
//! `GEOMETRYCOLLECTION` of the loops and paths.
use std::io;

use super::geometry::{geometry, write_pair, Kind, Notation};
use crate::gis::outlines::Outlines;
use sigdt::Point;

/// The WKT notation.
pub(super) struct Wkt;

impl Notation for Wkt {
    const OPEN: &'static str = "(";
    const CLOSE: &'static str = ")";
    const EMPTY: &'static str = "GEOMETRYCOLLECTION EMPTY";
    const COLLECTION: [&'static str; 2] = ["GEOMETRYCOLLECTION (", ")"];

    fn tag(kind: Kind) -> [&'static str; 2] {
        let name = match kind {
            Kind::Polygon => "POLYGON ",
            Kind::MultiPolygon => "MULTIPOLYGON ",
            Kind::LineString => "LINESTRING ",
            Kind::MultiLineString => "MULTILINESTRING ",
        };
        [name, ""]
    }

    fn point(out: &mut Vec<u8>, p: Point) -> io::Result<()> {
        write_pair(out, p, " ")
    }
}

/// The WKT of `outlines` and a newline.
pub(super) fn wkt(out: &mut Vec<u8>, outlines: &Outlines) -> io::Result<()> {
    geometry::<Wkt>(out, outlines)?;
    out.push(b'\n');
    Ok(())
}
