//! Points from GeoJSON (RFC 7946): every position of the geometries, in order, as points.
//!
//! Read: a `FeatureCollection`, a `Feature`, a `GeometryCollection` or a bare geometry
//! (`Point`, `MultiPoint`, `LineString`, `MultiLineString`, `Polygon`, `MultiPolygon`), and
//! also a plain JSON array of `[x, y]` pairs. Features with a `null` geometry are skipped.
//! Positions may have a third (and fourth) value, which is dropped. A polygon ring's closing
//! position repeats its first and is dropped. Members come in any order (`"type"` last, as
//! sorted keys put it, too); a member the type does not read, like a foreign member, gives no
//! points. A UTF-8 byte-order mark at the start is skipped.
//!
//! # Errors
//! Invalid JSON gives the file, line and column; a GeoJSON object of an unknown type, a
//! repeated member or a position that is not two or more finite numbers gives the file and the
//! JSON path of the offending value (`features[3].geometry.coordinates[0]`). Reading stops at
//! the first error, or at the point after `max_points`.
//!
//! Members read before the type is known (`coordinates`, `features`, `geometry`,
//! `geometries`) are read as that type would read them, their points kept until the type says
//! whether they count: so a foreign member of such a name, before the type, counts against
//! `max_points` and its errors are reported, and when coordinates hold both a wrong depth and
//! too many points, either error may come first.
//!
//! # Complexity
//! Streaming, in O(length of the text); memory is the points kept plus a constant, whatever
//! the input: members that give no points (properties, foreign members) are skipped unread,
//! nesting stops at serde_json's limit (127 levels), and a string read into memory (a member
//! name, a type, anything in coordinates) stops at 64 KiB.

mod coordinates;
mod crs;
mod guard;
#[cfg(test)]
mod tests;
mod walk;

use std::cell::Cell;
use std::fmt;
use std::io::Read;

use crate::text::quoted;
use anyhow::{anyhow, Result};
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use sigdt::Point;

use coordinates::{Deferred, Node};
use guard::Guard;
use walk::Walk;

/// The UTF-8 byte-order mark.
const BOM: &[u8] = b"\xef\xbb\xbf";
/// What a value that should be a GeoJSON object is told.
const NOT_AN_OBJECT: &str = "expected a GeoJSON object with a \"type\"";

/// The points of the GeoJSON document of `reader`; see the module docs.
#[cfg(test)]
pub fn read(reader: impl Read, name: &str, max_points: usize) -> Result<Vec<Point>> {
    read_with_crs(reader, name, max_points).map(|(points, _)| points)
}

/// The points of the GeoJSON document of `reader` (module docs), and the name in the legacy
/// `crs` member if the document has one (the first).
pub fn read_with_crs(
    mut reader: impl Read,
    name: &str,
    max_points: usize,
) -> Result<(Vec<Point>, Option<String>)> {
    let mut head = [0; 3];
    let got = crate::stream::read_full(&mut reader, &mut head)
        .map_err(|e| anyhow!("{name}: cannot read: {e}"))?;
    let head = if head[..got] == *BOM { &[][..] } else { &head[..got] };
    let skipping = Cell::new(false);
    let mut guard = Guard::new(head.chain(reader), &skipping);
    let mut walk = Walk::new(name, max_points, &skipping);
    let parsed = {
        let mut json = serde_json::Deserializer::from_reader(&mut guard);
        let document = Object { walk: &mut walk, place: Place::Document };
        document.deserialize(&mut json).and_then(|()| json.end())
    };
    match parsed {
        Ok(()) => Ok((walk.points, walk.crs)),
        Err(e) => Err(walk.failure.or_else(|| guard.refusal(name)).unwrap_or_else(|| {
            if e.is_io() {
                anyhow!("{name}: cannot read: {e}")
            } else {
                anyhow!("{name}:{}:{}: not valid JSON: {e}", e.line(), e.column())
            }
        })),
    }
}

/// What a GeoJSON object is.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    FeatureCollection,
    Feature,
    GeometryCollection,
    /// A geometry: its positions `depth` arrays deep in `coordinates`, maybe in rings.
    Geometry {
        depth: usize,
        rings: bool,
    },
}

impl Kind {
    fn named(name: &str) -> Option<Kind> {
        let geometry = |depth, rings| Some(Kind::Geometry { depth, rings });
        match name {
            "FeatureCollection" => Some(Kind::FeatureCollection),
            "Feature" => Some(Kind::Feature),
            "GeometryCollection" => Some(Kind::GeometryCollection),
            "Point" => geometry(0, false),
            "MultiPoint" | "LineString" => geometry(1, false),
            "MultiLineString" => geometry(2, false),
            "Polygon" => geometry(2, true),
            "MultiPolygon" => geometry(3, true),
            _ => None,
        }
    }

    /// The member that holds the points.
    fn part(self) -> Part {
        match self {
            Kind::FeatureCollection => Part::Features,
            Kind::Feature => Part::Geometry,
            Kind::GeometryCollection => Part::Geometries,
            Kind::Geometry { .. } => Part::Coordinates,
        }
    }
}

/// A member that holds points, for some type.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Part {
    Features,
    Geometry,
    Geometries,
    Coordinates,
}

impl Part {
    fn name(self) -> &'static str {
        match self {
            Part::Features => "features",
            Part::Geometry => "geometry",
            Part::Geometries => "geometries",
            Part::Coordinates => "coordinates",
        }
    }
}

/// Where a GeoJSON object stands, which says what else may stand there.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Place {
    /// The whole document: also a plain array of positions.
    Document,
    /// A feature's geometry: also `null`.
    Geometry,
    /// An element of `features` or `geometries`.
    Element,
}

/// Visitor methods for JSON's scalars, each refusing the value with `message`.
macro_rules! refuse_scalars {
    ($message:expr; $($method:ident($($value:ty)?)),*) => {$(
        fn $method<E: de::Error>(self $(, _: $value)?) -> Result<Self::Value, E> {
            Err(self.walk.refuse($message))
        }
    )*};
}

/// A GeoJSON object, read at the walk's path.
struct Object<'w, 'a> {
    walk: &'w mut Walk<'a>,
    place: Place,
}

impl<'de> DeserializeSeed<'de> for Object<'_, '_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<(), D::Error> {
        json.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Object<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a GeoJSON object")
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<(), A::Error> {
        members(self.walk, map)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<(), A::Error> {
        if self.place != Place::Document {
            return Err(self.walk.refuse(NOT_AN_OBJECT));
        }
        // Positions, as a MultiPoint's coordinates.
        self.walk.shape.begin(Some(Kind::Geometry { depth: 1, rings: false }));
        Node { walk: self.walk, level: 0, after: false }.visit_seq(seq).map(|_| ())
    }
    fn visit_unit<E: de::Error>(self) -> Result<(), E> {
        match self.place {
            Place::Geometry => Ok(()),
            _ => Err(self.walk.refuse(NOT_AN_OBJECT)),
        }
    }
    refuse_scalars!(NOT_AN_OBJECT; visit_bool(bool), visit_i64(i64), visit_u64(u64),
        visit_f64(f64), visit_str(&str));
}

/// A member read before the type: its points, and for coordinates what remains to check.
struct Early {
    part: Part,
    points: std::ops::Range<usize>,
    coordinates: Option<Deferred>,
}

/// The members of a GeoJSON object.
fn members<'de, A: MapAccess<'de>>(walk: &mut Walk, mut map: A) -> Result<(), A::Error> {
    let mut kind = None;
    let mut seen = 0u8;
    let mut early = Vec::new();
    while let Some(member) = map.next_key_seed(MemberName)? {
        let part = match member {
            Member::Other => {
                walk.skip(&mut map)?;
                continue;
            }
            Member::Crs => {
                let mark = walk.enter("crs");
                let name = map.next_value_seed(crs::crs_seed(&mut *walk))?;
                walk.leave(mark);
                walk.crs = walk.crs.take().or(name);
                continue;
            }
            Member::Type if kind.is_some() => return Err(walk.refuse("more than one \"type\"")),
            Member::Type => {
                kind = Some(map.next_value_seed(TypeName { walk: &mut *walk })?);
                continue;
            }
            Member::Part(part) => part,
        };
        if seen & (1 << part as u8) != 0 {
            return Err(walk.refuse(&format!("more than one \"{}\"", part.name())));
        }
        seen |= 1 << part as u8;
        match kind {
            Some(kind) if kind.part() == part => {
                read_part(walk, &mut map, part, Some(kind))?;
            }
            Some(_) => walk.skip(&mut map)?,
            None => {
                let start = walk.points.len();
                let coordinates = read_part(walk, &mut map, part, None)?;
                early.push(Early { part, points: start..walk.points.len(), coordinates });
            }
        }
    }
    let Some(kind) = kind else { return Err(walk.refuse(NOT_AN_OBJECT)) };
    settle(walk, kind, early)?;
    if seen & (1 << kind.part() as u8) == 0 {
        return missing(walk, kind);
    }
    Ok(())
}

/// Reads member `part` as `kind`, if known, reads it; coordinates read before the type
/// come back with what remains to check.
fn read_part<'de, A: MapAccess<'de>>(
    walk: &mut Walk,
    map: &mut A,
    part: Part,
    kind: Option<Kind>,
) -> Result<Option<Deferred>, A::Error> {
    let mark = walk.enter(part.name());
    let mut deferred = None;
    match part {
        Part::Features | Part::Geometries => map.next_value_seed(Objects { walk: &mut *walk })?,
        Part::Geometry => {
            map.next_value_seed(Object { walk: &mut *walk, place: Place::Geometry })?;
        }
        Part::Coordinates => {
            walk.shape.begin(kind);
            map.next_value_seed(Node { walk: &mut *walk, level: 0, after: false })?;
            if kind.is_none() {
                deferred = Some(walk.shape.deferred());
            }
        }
    }
    walk.leave(mark);
    Ok(deferred)
}

/// Once the type is known: drops the points of the members read before it that it does not
/// read, and checks the coordinates read before it.
fn settle<E: de::Error>(walk: &mut Walk, kind: Kind, early: Vec<Early>) -> Result<(), E> {
    // From the last, so that the ranges before stay in place.
    for member in early.into_iter().rev() {
        if member.part != kind.part() {
            walk.points.drain(member.points);
        } else if let (Some(coordinates), Kind::Geometry { depth, rings }) =
            (member.coordinates, kind)
        {
            coordinates.settle(walk, depth, rings)?;
        }
    }
    Ok(())
}

/// The error for an object without the member its type reads, as if it were `null`.
fn missing<E: de::Error>(walk: &mut Walk, kind: Kind) -> Result<(), E> {
    let message = match kind {
        Kind::Feature => return Ok(()),
        Kind::Geometry { depth: 0, .. } => {
            format!("expected a position [x, y], found {}", quoted("null"))
        }
        _ => "expected an array".to_string(),
    };
    walk.enter(kind.part().name());
    Err(walk.refuse(&message))
}

/// A member name, sorted by what it holds.
enum Member {
    Type,
    Part(Part),
    /// The legacy `crs` member.
    Crs,
    Other,
}

struct MemberName;

impl<'de> DeserializeSeed<'de> for MemberName {
    type Value = Member;
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<Member, D::Error> {
        json.deserialize_identifier(self)
    }
}

impl<'de> Visitor<'de> for MemberName {
    type Value = Member;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a member name")
    }
    fn visit_str<E: de::Error>(self, name: &str) -> Result<Member, E> {
        Ok(match name {
            "type" => Member::Type,
            "features" => Member::Part(Part::Features),
            "geometry" => Member::Part(Part::Geometry),
            "geometries" => Member::Part(Part::Geometries),
            "coordinates" => Member::Part(Part::Coordinates),
            "crs" => Member::Crs,
            _ => Member::Other,
        })
    }
}

/// The value of `type`.
struct TypeName<'w, 'a> {
    walk: &'w mut Walk<'a>,
}

impl<'de> DeserializeSeed<'de> for TypeName<'_, '_> {
    type Value = Kind;
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<Kind, D::Error> {
        json.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for TypeName<'_, '_> {
    type Value = Kind;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a GeoJSON type")
    }
    fn visit_str<E: de::Error>(self, name: &str) -> Result<Kind, E> {
        let unknown = || format!("unknown GeoJSON type {}", quoted(name));
        Kind::named(name).ok_or_else(|| self.walk.refuse(&unknown()))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> Result<Kind, A::Error> {
        Err(self.walk.refuse(NOT_AN_OBJECT))
    }
    fn visit_map<A: MapAccess<'de>>(self, _: A) -> Result<Kind, A::Error> {
        Err(self.walk.refuse(NOT_AN_OBJECT))
    }
    refuse_scalars!(NOT_AN_OBJECT; visit_bool(bool), visit_i64(i64), visit_u64(u64),
        visit_f64(f64), visit_unit());
}

/// `features` or `geometries`: an array of GeoJSON objects.
struct Objects<'w, 'a> {
    walk: &'w mut Walk<'a>,
}

impl<'de> DeserializeSeed<'de> for Objects<'_, '_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<(), D::Error> {
        json.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Objects<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an array of GeoJSON objects")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let walk = self.walk;
        for k in 0.. {
            let mark = walk.enter_index(k);
            let object = Object { walk: &mut *walk, place: Place::Element };
            let more = seq.next_element_seed(object)?.is_some();
            walk.leave(mark);
            if !more {
                break;
            }
        }
        Ok(())
    }
    fn visit_map<A: MapAccess<'de>>(self, _: A) -> Result<(), A::Error> {
        Err(self.walk.refuse("expected an array"))
    }
    refuse_scalars!("expected an array"; visit_bool(bool), visit_i64(i64), visit_u64(u64),
        visit_f64(f64), visit_str(&str), visit_unit());
}
