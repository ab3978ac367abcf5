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

use std::cell::Cell;
use std::fmt::{self, Display, Write as _};
use std::io::{self, Read};

use anyhow::{anyhow, Result};
use serde::de::{
    self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor,
};
use serde_json::{Number, Value};
use sigdt::io::quoted;
use sigdt::Point;

/// The UTF-8 byte-order mark.
const BOM: &[u8] = b"\xef\xbb\xbf";
/// Open arrays and objects allowed: serde_json's own limit, kept also where it does not look.
const MAX_DEPTH: usize = 127;
/// The longest string read into memory, in bytes.
const MAX_STRING: usize = 1 << 16;
/// The characters of a value that a message shows.
const SHOWN: usize = 40;
/// What a value that should be a GeoJSON object is told.
const NOT_AN_OBJECT: &str = "expected a GeoJSON object with a \"type\"";

/// The points of the GeoJSON document of `reader`; see the module docs.
pub fn read(mut reader: impl Read, name: &str, max_points: usize) -> Result<Vec<Point>> {
    let mut head = [0; 3];
    let got = fill(&mut reader, &mut head).map_err(|e| anyhow!("{name}: cannot read: {e}"))?;
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
        Ok(()) => Ok(walk.points),
        Err(e) => Err(walk.failure.or_else(|| guard.refusal(name)).unwrap_or_else(|| {
            if e.is_io() {
                anyhow!("{name}: cannot read: {e}")
            } else {
                anyhow!("{name}:{}:{}: not valid JSON: {e}", e.line(), e.column())
            }
        })),
    }
}

/// Reads into `buf` until it is full or the input ends; the number of bytes read.
fn fill(reader: &mut impl Read, buf: &mut [u8]) -> io::Result<usize> {
    let mut got = 0;
    while got < buf.len() {
        match reader.read(&mut buf[got..]) {
            Ok(0) => break,
            Ok(n) => got += n,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(got)
}

/// The bytes on their way to serde_json, refused where serde_json would hold unbounded
/// memory: nesting deeper than its limit inside a skipped value (its `IgnoredAny` keeps a
/// byte a level, with no limit), and a long string that is not skipped (serde_json reads a
/// string whole before handing it over). serde_json reads a byte at a time, so `skipping` is
/// up to date when a string's opening quote comes.
struct Guard<'a, R> {
    bytes: R,
    skipping: &'a Cell<bool>,
    /// Open arrays and objects.
    depth: usize,
    in_string: bool,
    escaped: bool,
    /// The bytes so far of the string being read, if it is kept.
    kept: Option<usize>,
    line: usize,
    column: usize,
    refused: Option<&'static str>,
}

impl<'a, R: Read> Guard<'a, R> {
    fn new(bytes: R, skipping: &'a Cell<bool>) -> Self {
        Guard {
            bytes,
            skipping,
            depth: 0,
            in_string: false,
            escaped: false,
            kept: None,
            line: 1,
            column: 0,
            refused: None,
        }
    }

    /// Why and where the guard stopped the reading, if it did.
    fn refusal(&self, name: &str) -> Option<anyhow::Error> {
        self.refused.map(|why| anyhow!("{name}:{}:{}: {why}", self.line, self.column))
    }

    fn scan(&mut self, byte: u8) -> Result<(), &'static str> {
        if byte == b'\n' {
            (self.line, self.column) = (self.line + 1, 0);
        } else {
            self.column += 1;
        }
        if !self.in_string {
            return self.outside_strings(byte);
        }
        if self.escaped {
            self.escaped = false;
        } else if byte == b'\\' {
            self.escaped = true;
        } else if byte == b'"' {
            self.in_string = false;
            return Ok(());
        }
        match &mut self.kept {
            Some(MAX_STRING) => {
                Err("a string longer than 65536 bytes outside properties and other skipped members")
            }
            Some(bytes) => {
                *bytes += 1;
                Ok(())
            }
            None => Ok(()),
        }
    }

    fn outside_strings(&mut self, byte: u8) -> Result<(), &'static str> {
        match byte {
            b'"' => {
                self.in_string = true;
                self.kept = (!self.skipping.get()).then_some(0);
            }
            b'[' | b'{' if self.depth == MAX_DEPTH => {
                return Err("JSON nested more than 127 arrays and objects deep");
            }
            b'[' | b'{' => self.depth += 1,
            b']' | b'}' => self.depth = self.depth.saturating_sub(1),
            _ => {}
        }
        Ok(())
    }
}

impl<R: Read> Read for Guard<'_, R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let got = self.bytes.read(buf)?;
        for &byte in &buf[..got] {
            if let Err(why) = self.scan(byte) {
                self.refused = Some(why);
                return Err(io::Error::new(io::ErrorKind::InvalidData, why));
            }
        }
        Ok(got)
    }
}

/// The reading: the points so far, where it is, and why it stopped.
struct Walk<'a> {
    name: &'a str,
    max_points: usize,
    points: Vec<Point>,
    /// The JSON path of the member being read, as `features[3].geometry`.
    path: String,
    /// Tells the guard when a value is skipped unread.
    skipping: &'a Cell<bool>,
    /// The coordinates being read.
    shape: Shape,
    /// Why a visitor stopped the reading (a serde error cannot carry it).
    failure: Option<anyhow::Error>,
}

impl<'a> Walk<'a> {
    fn new(name: &'a str, max_points: usize, skipping: &'a Cell<bool>) -> Self {
        let (path, shape) = (String::new(), Shape::default());
        Walk { name, max_points, points: Vec::new(), path, skipping, shape, failure: None }
    }

    /// Stops the reading with `failure`.
    fn stop<E: de::Error>(&mut self, failure: anyhow::Error) -> E {
        self.failure = Some(failure);
        E::custom("stopped")
    }

    /// Stops the reading with `message` about the value being read.
    fn refuse<E: de::Error>(&mut self, message: &str) -> E {
        let failure = anyhow::Error::msg(self.about_here(message));
        self.stop(failure)
    }

    /// `message` with the file and the JSON path of the value being read.
    fn about_here(&self, message: &str) -> String {
        let mut at = self.path.clone();
        for k in &self.shape.indices {
            let _ = write!(at, "[{k}]");
        }
        let at = if at.is_empty() { "the document" } else { &at };
        format!("{}: GeoJSON: {at}: {message}", self.name)
    }

    fn push<E: de::Error>(&mut self, point: Point) -> Result<(), E> {
        if self.points.len() >= self.max_points {
            return Err(self.stop(super::too_many(self.name, self.max_points)));
        }
        self.points.push(point);
        Ok(())
    }

    /// Goes down into member `name`; the mark to come back to.
    fn enter(&mut self, name: &str) -> usize {
        let mark = self.path.len();
        if mark > 0 {
            self.path.push('.');
        }
        self.path.push_str(name);
        mark
    }

    fn enter_index(&mut self, k: usize) -> usize {
        let mark = self.path.len();
        let _ = write!(self.path, "[{k}]");
        mark
    }

    fn leave(&mut self, mark: usize) {
        self.path.truncate(mark);
    }

    /// Skips the value of the current member unread.
    fn skip<'de, A: MapAccess<'de>>(&mut self, map: &mut A) -> Result<(), A::Error> {
        self.skipping.set(true);
        let skipped = map.next_value::<IgnoredAny>();
        self.skipping.set(false);
        skipped.map(|_| ())
    }

    /// Notes that the coordinates are not positions `depth` arrays deep: the end of the
    /// reading if the type is known, else the problem kept for the type to pick.
    fn problem<E: de::Error>(&mut self, depth: usize, message: &str) -> Result<(), E> {
        if !self.shape.is_open(depth) {
            return Ok(());
        }
        self.shape.open &= !(1 << depth);
        let problem = self.about_here(message);
        if self.shape.known {
            return Err(self.stop(anyhow::Error::msg(problem)));
        }
        self.shape.problems[depth] = Some(problem);
        Ok(())
    }

    /// The value `level` deep that just ended is not a position: a problem at that depth.
    fn not_a_position<E: de::Error>(&mut self, level: usize) -> Result<(), E> {
        let Some(sketch) = self.shape.sketches.get_mut(level) else { return Ok(()) };
        if !sketch.active {
            return Ok(());
        }
        sketch.active = false;
        let message = format!("expected a position [x, y], found {}", sketch.shown());
        self.problem(level, &message)
    }

    /// A value `level` deep that is not an array: a problem at every greater depth.
    fn not_an_array<E: de::Error>(&mut self, level: usize) -> Result<(), E> {
        for depth in level + 1..4 {
            self.problem(depth, "expected an array")?;
        }
        Ok(())
    }

    /// The ring just read ends with its first position: dropped if it is a polygon's.
    fn close_ring(&mut self) {
        match self.shape.closing {
            Closing::Keep => {}
            Closing::Drop => {
                self.points.pop();
            }
            Closing::DropAndRemember => {
                let index = self.points.len() - 1;
                self.shape.dropped.extend(self.points.pop().map(|p| (index, p)));
            }
        }
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

/// Visitor methods for JSON's scalars, each handing `self.scalar` the value's JSON text.
macro_rules! show_scalars {
    () => {
        fn visit_bool<E: de::Error>(self, v: bool) -> Result<Self::Value, E> {
            self.scalar(&v, Element::Other)
        }
        fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
            self.scalar(&Number::from(v), Element::Number(v as f64))
        }
        fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
            self.scalar(&Number::from(v), Element::Number(v as f64))
        }
        fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
            let number = Number::from_f64(v);
            let text: &dyn Display = match &number {
                Some(number) => number,
                None => &"null",
            };
            self.scalar(text, Element::Number(v))
        }
        fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
            self.scalar(&Value::from(v), Element::Other)
        }
        fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
            self.scalar(&"null", Element::Other)
        }
    };
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

/// Coordinates being read. Before the type is known they are read at every depth at once (0
/// for a Point's, 1 for a LineString's, 2, 3 for a MultiPolygon's): positions are taken at
/// each depth not yet found wrong, and the first problem at each depth is kept for the type
/// to pick (in valid coordinates, every position is at the same depth).
#[derive(Default)]
struct Shape {
    /// Bit `d`: the coordinates may still be positions `d` arrays deep.
    open: u8,
    /// The type is known: the first problem ends the reading.
    known: bool,
    closing: Closing,
    /// Before the type is known, the first problem at each depth (a message: most are never
    /// shown, and an `anyhow::Error` may capture a backtrace).
    problems: [Option<String>; 4],
    /// Before the type is known, the closing positions dropped (with their index), to put
    /// back unless the type has rings.
    dropped: Vec<(usize, Point)>,
    /// The index of the element being read in each open array, for paths.
    indices: Vec<usize>,
    /// The text of the value being read at each depth that may be a position there.
    sketches: [Sketch; 4],
}

/// What to do with a ring's closing position.
#[derive(Clone, Copy, Default)]
enum Closing {
    #[default]
    Keep,
    Drop,
    /// The type is not known yet: drop it, and remember it.
    DropAndRemember,
}

impl Shape {
    /// Starts on coordinates of a geometry of type `kind`, or of a type not known yet.
    fn begin(&mut self, kind: Option<Kind>) {
        (self.open, self.known, self.closing) = match kind {
            Some(Kind::Geometry { depth, rings: true }) => (1 << depth, true, Closing::Drop),
            Some(Kind::Geometry { depth, .. }) => (1 << depth, true, Closing::Keep),
            _ => (0b1111, false, Closing::DropAndRemember),
        };
        self.problems = Default::default();
        self.dropped.clear();
        self.indices.clear();
        self.sketches.iter_mut().for_each(|s| s.active = false);
    }

    fn is_open(&self, depth: usize) -> bool {
        depth < 4 && self.open & (1 << depth) != 0
    }

    /// What remains to check of coordinates read before the type.
    fn deferred(&mut self) -> Deferred {
        let problems = std::mem::take(&mut self.problems);
        Deferred { problems, dropped: std::mem::take(&mut self.dropped) }
    }

    /// A value `level` deep starts, `after` another in its array.
    fn start(&mut self, level: usize, after: bool) {
        if after {
            self.show(&",");
        }
        if self.is_open(level) {
            self.sketches[level].start();
        }
    }

    fn show(&mut self, text: &dyn Display) {
        for sketch in self.sketches.iter_mut().filter(|s| s.active && !s.cut) {
            let _ = write!(sketch, "{text}");
        }
    }
}

/// What remains to check of coordinates read before the type.
struct Deferred {
    problems: [Option<String>; 4],
    dropped: Vec<(usize, Point)>,
}

impl Deferred {
    /// Checks the coordinates of a geometry with positions `depth` arrays deep.
    fn settle<E: de::Error>(mut self, walk: &mut Walk, depth: usize, rings: bool) -> Result<(), E> {
        if let Some(problem) = self.problems[depth].take() {
            return Err(walk.stop(anyhow::Error::msg(problem)));
        }
        if !rings {
            put_back(&mut walk.points, &self.dropped);
            if walk.points.len() > walk.max_points {
                return Err(walk.stop(super::too_many(walk.name, walk.max_points)));
            }
        }
        Ok(())
    }
}

/// Puts back the points `dropped` in turn, each at the index it had before it was dropped.
fn put_back(points: &mut Vec<Point>, dropped: &[(usize, Point)]) {
    let mut from = points.len();
    points.resize(from + dropped.len(), [0.0; 2]);
    let mut to = points.len();
    // From the end: the `k`th dropped point goes to its index plus the `k` put back before it.
    for (k, &(index, point)) in dropped.iter().enumerate().rev() {
        while to > index + k + 1 {
            (to, from) = (to - 1, from - 1);
            points[to] = points[from];
        }
        to -= 1;
        points[to] = point;
    }
}

/// The JSON text of a value, cut after `SHOWN` characters, for messages.
#[derive(Default)]
struct Sketch {
    text: String,
    chars: usize,
    cut: bool,
    active: bool,
}

impl Sketch {
    fn start(&mut self) {
        (self.chars, self.cut, self.active) = (0, false, true);
        self.text.clear();
    }

    /// The text as a message shows it.
    fn shown(&self) -> String {
        let text = quoted(&self.text);
        if self.cut {
            text + "..."
        } else {
            text
        }
    }
}

impl fmt::Write for Sketch {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for c in s.chars() {
            if self.chars == SHOWN {
                self.cut = true;
                return Err(fmt::Error);
            }
            self.text.push(c);
            self.chars += 1;
        }
        Ok(())
    }
}

/// A value inside coordinates, `level` arrays deep; `after` another in its array.
struct Node<'w, 'a> {
    walk: &'w mut Walk<'a>,
    level: usize,
    after: bool,
}

/// What a value inside coordinates was, for the array holding it.
#[derive(Clone, Copy, PartialEq)]
enum Element {
    Number(f64),
    /// A position, taken.
    Position,
    /// Another array.
    Array,
    Other,
}

/// The elements of an array so far, as a position.
#[derive(Default)]
struct Position {
    elements: usize,
    x: f64,
    y: f64,
    /// An element is not a number.
    other: bool,
}

impl Position {
    fn add(&mut self, element: Element) {
        match element {
            Element::Number(v) if self.elements == 0 => self.x = v,
            Element::Number(v) if self.elements == 1 => self.y = v,
            Element::Number(_) => {}
            _ => self.other = true,
        }
        self.elements += 1;
    }

    fn point(&self) -> Option<Point> {
        let fits = !self.other && self.elements >= 2 && self.x.is_finite() && self.y.is_finite();
        fits.then_some([self.x, self.y])
    }
}

impl Node<'_, '_> {
    fn scalar<E: de::Error>(self, text: &dyn Display, element: Element) -> Result<Element, E> {
        let Node { walk, level, after } = self;
        walk.shape.start(level, after);
        walk.shape.show(text);
        walk.not_an_array(level)?;
        walk.not_a_position(level)?;
        Ok(element)
    }
}

impl<'de> DeserializeSeed<'de> for Node<'_, '_> {
    type Value = Element;
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<Element, D::Error> {
        json.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Node<'_, '_> {
    type Value = Element;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("coordinates")
    }
    show_scalars!();

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Element, A::Error> {
        let Node { walk, level, after } = self;
        walk.shape.start(level, after);
        walk.shape.show(&"[");
        let first = walk.points.len();
        let mut position = Position::default();
        let mut positions = 0;
        loop {
            let k = position.elements;
            walk.shape.indices.push(k);
            let node = Node { walk: &mut *walk, level: level + 1, after: k > 0 };
            let element = seq.next_element_seed(node);
            walk.shape.indices.pop();
            let Some(element) = element? else { break };
            position.add(element);
            positions += usize::from(element == Element::Position);
            // A known type's wrong position is refused once its shown text is complete.
            let sketch = walk.shape.sketches.get(level);
            if walk.shape.known && position.other && sketch.is_some_and(|s| s.active && s.cut) {
                break;
            }
        }
        walk.shape.show(&"]");
        let element = match position.point() {
            Some(point) if walk.shape.is_open(level) => {
                walk.shape.sketches[level].active = false;
                walk.push(point)?;
                Element::Position
            }
            _ => {
                walk.not_a_position(level)?;
                Element::Array
            }
        };
        if positions > 1 && walk.points.last() == walk.points.get(first) {
            walk.close_ring();
        }
        Ok(element)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Element, A::Error> {
        let Node { walk, level, after } = self;
        walk.shape.start(level, after);
        walk.not_an_array(level)?;
        show_map(walk, &mut map, level)?;
        walk.not_a_position(level)?;
        Ok(Element::Other)
    }
}

/// Reads an object `level` deep in coordinates, only to show it: what it holds is read one
/// level deeper than any depth a position may have.
fn show_map<'de, A: MapAccess<'de>>(
    walk: &mut Walk,
    map: &mut A,
    level: usize,
) -> Result<(), A::Error> {
    let inside = level.max(3) + 1;
    walk.shape.show(&"{");
    let mut after = false;
    while map.next_key_seed(Node { walk: &mut *walk, level: inside, after })?.is_some() {
        walk.shape.show(&":");
        map.next_value_seed(Node { walk: &mut *walk, level: inside, after: false })?;
        after = true;
    }
    walk.shape.show(&"}");
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Vec<Point>> {
        read(text.as_bytes(), "t.geojson", 1000)
    }

    fn error(text: &str) -> String {
        parse(text).unwrap_err().to_string()
    }

    /// `text` cut for an assertion's message.
    fn cut(text: &str) -> &str {
        &text[..text.len().min(300)]
    }

    #[test]
    fn features_and_geometries_give_their_positions() {
        let text = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [0, 0, 5]}},
            {"type": "Feature", "geometry": null},
            {"type": "Feature", "geometry": {"type": "Polygon",
              "coordinates": [[[1, 0], [2, 0], [2, 1], [1, 0]]]}},
            {"type": "Feature", "geometry": {"type": "GeometryCollection", "geometries": [
              {"type": "MultiLineString", "coordinates": [[[3, 3], [4, 4]]]},
              {"type": "MultiPoint", "coordinates": [[5, 5]]}]}}]}"#;
        let points = parse(text).unwrap();
        assert_eq!(
            points,
            [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [3.0, 3.0], [4.0, 4.0], [5.0, 5.0]]
        );
        assert_eq!(parse("[[1, 2], [3.5, 4]]").unwrap(), [[1.0, 2.0], [3.5, 4.0]]);
    }

    #[test]
    fn errors_name_the_place() {
        let err = error("{\"type\": \"Point\",\n \"coordinates\": [1, }");
        assert!(err.starts_with("t.geojson:2:") && err.contains("not valid JSON"), "{err}");
        let bad = r#"{"type": "FeatureCollection", "features": [{"type": "Feature",
            "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, "a"]]}}]}"#;
        assert_eq!(
            error(bad),
            "t.geojson: GeoJSON: features[0].geometry.coordinates[1]: expected a position [x, y], \
             found '[1,\"a\"]'"
        );
        let err = error(r#"{"type": "Circle"}"#);
        assert!(err.contains("unknown GeoJSON type 'Circle'"), "{err}");
        assert!(error(r#"{"name": 1}"#).contains("\"type\""));
        let err = error("5");
        assert_eq!(
            err,
            "t.geojson: GeoJSON: the document: expected a GeoJSON object with a \"type\""
        );
    }

    /// `[`, then `[1,1],` without end; fails once it has given `limit` bytes.
    struct Endless {
        given: usize,
        limit: usize,
    }

    impl Read for Endless {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            if self.given >= self.limit {
                return Err(std::io::Error::other("the endless input was read too far"));
            }
            for byte in buf.iter_mut() {
                *byte = if self.given == 0 { b'[' } else { b"[1,1],"[(self.given - 1) % 6] };
                self.given += 1;
            }
            Ok(buf.len())
        }
    }

    #[test]
    fn an_endless_array_stops_at_the_limit() {
        let mut endless = Endless { given: 0, limit: 4 << 20 };
        let err = read(&mut endless, "t.geojson", 5).unwrap_err().to_string();
        assert_eq!(err, "t.geojson: more than 5 points (raise --max-points to read more)");
        assert!(endless.given < 1 << 16, "read {} bytes", endless.given);
        let mut endless = Endless { given: 0, limit: 1000 };
        let err = read(&mut endless, "t.geojson", usize::MAX).unwrap_err().to_string();
        assert!(err.starts_with("t.geojson: cannot read: the endless input"), "{err}");
    }

    #[test]
    fn a_byte_order_mark_is_skipped() {
        let text = "\u{feff}{\"type\": \"Point\", \"coordinates\": [1, 2]}";
        assert_eq!(parse(text).unwrap(), [[1.0, 2.0]]);
        assert_eq!(parse("\u{feff}[[1, 2]]").unwrap(), [[1.0, 2.0]]);
    }

    #[test]
    fn echoed_text_is_quoted_and_cut() {
        let err = error(r#"{"type": "Cir\ncle"}"#);
        assert!(err.ends_with("unknown GeoJSON type 'Cir\\u{a}cle'"), "{err}");
        let long = "x".repeat(50);
        let err = error(&format!(r#"{{"type": "{long}"}}"#));
        assert!(err.ends_with(&format!("'{}...' (50 characters)", &long[..40])), "{err}");
        let err = error(r#"{"type": "LineString", "coordinates": [[0, 0], "it's"]}"#);
        assert!(
            err.ends_with(r#"coordinates[1]: expected a position [x, y], found '"it\'s"'"#),
            "{err}"
        );
        let wide = format!("[{}]", vec!["[1,2]"; 20].join(","));
        let err = error(&format!(r#"{{"type": "Point", "coordinates": {wide}}}"#));
        assert!(err.ends_with(&format!("found '{}'...", &wide[..40])), "{err}");
    }

    #[test]
    fn strings_kept_in_memory_are_short() {
        let long = "x".repeat(70_000);
        let err = error(&format!(r#"{{"type": "{long}"}}"#));
        assert!(
            err.contains("t.geojson:1:") && err.contains("longer than 65536 bytes"),
            "{}",
            cut(&err)
        );
        let err = error(&format!(r#"{{"type": "Point", "{long}": 1, "coordinates": [0, 0]}}"#));
        assert!(err.contains("longer than 65536 bytes"), "{}", cut(&err));
        // Skipped members are not kept, so their strings may be long.
        let text = format!(
            r#"{{"type": "Feature", "properties": {{"note": "{long}", "{long}": ["{long}"]}},
                "geometry": {{"type": "Point", "coordinates": [0, 0]}}, "id": "{long}"}}"#
        );
        assert_eq!(parse(&text).unwrap(), [[0.0, 0.0]]);
    }

    #[test]
    fn deep_nesting_is_a_clean_error() {
        for at in ["properties", "coordinates"] {
            let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
            let text = format!(r#"{{"type": "Point", "{at}": {deep}}}"#);
            let err = error(&text);
            assert!(err.contains("nested more than 127"), "{at}: {err}");
        }
        let deep = format!("{}{}", "[".repeat(120), "]".repeat(120));
        let text = format!(r#"{{"type": "Point", "properties": {deep}, "coordinates": [0, 0]}}"#);
        assert_eq!(parse(&text).unwrap(), [[0.0, 0.0]]);
    }

    #[test]
    fn the_type_may_come_after_the_members_it_gives_meaning_to() {
        let text = r#"{"features": [
            {"geometry": {"coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]], "type": "Polygon"},
             "properties": {"coordinates": [[9, 9]]}, "type": "Feature"},
            {"geometry": {"coordinates": [[2, 2], [3, 2], [2, 2]], "type": "LineString"},
             "type": "Feature"},
            {"geometries": [{"coordinates": [[[4, 4], [5, 4], [4, 4]]], "type": "MultiLineString"}],
             "type": "GeometryCollection"}],
            "type": "FeatureCollection"}"#;
        let points = parse(text).unwrap();
        let expected = [[0, 0], [1, 0], [1, 1], [2, 2], [3, 2], [2, 2], [4, 4], [5, 4], [4, 4]];
        assert_eq!(points, expected.map(|[x, y]| [f64::from(x), f64::from(y)]));
        // A member the type does not use is a foreign member, read for nothing.
        let text = r#"{"features": [{"type": "Point", "coordinates": [8, 8]}],
            "coordinates": [1, 2], "geometry": {"type": "Point", "coordinates": [7, 7]},
            "type": "Point"}"#;
        assert_eq!(parse(text).unwrap(), [[1.0, 2.0]]);
        let err = error(r#"{"coordinates": [[1, 2]], "type": "Point"}"#);
        assert!(err.ends_with("coordinates: expected a position [x, y], found '[[1,2]]'"), "{err}");
        let err = error(r#"{"coordinates": [1, 2], "type": "LineString"}"#);
        assert!(err.ends_with("coordinates[0]: expected a position [x, y], found '1'"), "{err}");
        let err = error(r#"{"coordinates": [[1, 2]], "type": "MultiPolygon"}"#);
        assert!(err.ends_with("coordinates[0][0]: expected an array"), "{err}");
    }

    #[test]
    fn the_limit_counts_the_same_points_whatever_the_order() {
        let lines = r#"[[[0, 0], [1, 1], [0, 0]], [[2, 2], [3, 3]]]"#;
        let rings = r#"[[[0, 0], [1, 1], [2, 2], [0, 0]], [[5, 5], [6, 6], [7, 7], [5, 5]]]"#;
        for (kind, coordinates, fits) in [("MultiLineString", lines, 5), ("Polygon", rings, 7)] {
            let first = format!(r#"{{"type": "{kind}", "coordinates": {coordinates}}}"#);
            let last = format!(r#"{{"coordinates": {coordinates}, "type": "{kind}"}}"#);
            for text in [first, last] {
                let points = read(text.as_bytes(), "t", fits).unwrap();
                assert_eq!(points.len(), fits - usize::from(kind == "Polygon"), "{text}");
                let err = read(text.as_bytes(), "t", fits - 1).unwrap_err().to_string();
                assert!(err.contains("more than"), "{text}: {err}");
            }
        }
    }

    #[test]
    fn missing_and_repeated_members() {
        let err = error(r#"{"type": "FeatureCollection"}"#);
        assert!(err.ends_with("GeoJSON: features: expected an array"), "{err}");
        let err = error(r#"{"type": "Point"}"#);
        assert!(err.ends_with("coordinates: expected a position [x, y], found 'null'"), "{err}");
        let err = error(r#"{"type": "Feature", "geometry": {"type": "Polygon"}}"#);
        assert!(err.ends_with("geometry.coordinates: expected an array"), "{err}");
        assert!(parse(r#"{"type": "Feature"}"#).unwrap().is_empty());
        let err = error(r#"{"type": "Point", "type": "Point", "coordinates": [0, 0]}"#);
        assert!(err.ends_with("the document: more than one \"type\""), "{err}");
        let err = error(r#"{"type": "Point", "coordinates": [0, 0], "coordinates": [1, 1]}"#);
        assert!(err.ends_with("the document: more than one \"coordinates\""), "{err}");
    }
}
