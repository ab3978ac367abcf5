//! The coordinates reader: positions at whatever depth the type gives, or at every depth while
//! the type is not known yet, with the text of a wrong value kept for its message.

use std::fmt::{self, Display, Write as _};

use crate::text::quoted;
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::{Number, Value};
use sigdt::Point;

use super::{Kind, Walk};

/// The characters of a value that a message shows.
const SHOWN: usize = 40;

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

/// What reading coordinates does to the walk.
impl Walk<'_> {
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

/// Coordinates being read. Before the type is known they are read at every depth at once (0
/// for a Point's, 1 for a LineString's, 2, 3 for a MultiPolygon's): positions are taken at
/// each depth not yet found wrong, and the first problem at each depth is kept for the type
/// to pick (in valid coordinates, every position is at the same depth).
#[derive(Default)]
pub(super) struct Shape {
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
    pub(super) indices: Vec<usize>,
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
    pub(super) fn begin(&mut self, kind: Option<Kind>) {
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
    pub(super) fn deferred(&mut self) -> Deferred {
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
pub(super) struct Deferred {
    problems: [Option<String>; 4],
    dropped: Vec<(usize, Point)>,
}

impl Deferred {
    /// Checks the coordinates of a geometry with positions `depth` arrays deep.
    pub(super) fn settle<E: de::Error>(
        mut self,
        walk: &mut Walk,
        depth: usize,
        rings: bool,
    ) -> Result<(), E> {
        if let Some(problem) = self.problems[depth].take() {
            return Err(walk.stop(anyhow::Error::msg(problem)));
        }
        if !rings {
            put_back(&mut walk.points, &self.dropped);
            if walk.points.len() > walk.max_points {
                return Err(walk.stop(super::super::too_many(walk.name, walk.max_points)));
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
pub(super) struct Node<'w, 'a> {
    pub(super) walk: &'w mut Walk<'a>,
    pub(super) level: usize,
    pub(super) after: bool,
}

/// What a value inside coordinates was, for the array holding it.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Element {
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
