//! The state of the reading: the points so far, the JSON path of the value being read, and
//! why the reading stopped.

use std::cell::Cell;
use std::fmt::Write as _;

use serde::de::{self, IgnoredAny, MapAccess};
use sigdt::Point;

use super::coordinates::Shape;

/// The reading: the points so far, where it is, and why it stopped.
pub(super) struct Walk<'a> {
    pub(super) name: &'a str,
    pub(super) max_points: usize,
    pub(super) points: Vec<Point>,
    /// The JSON path of the member being read, as `features[3].geometry`.
    path: String,
    /// Tells the guard when a value is skipped unread.
    skipping: &'a Cell<bool>,
    /// The coordinates being read.
    pub(super) shape: Shape,
    /// Why a visitor stopped the reading (a serde error cannot carry it).
    pub(super) failure: Option<anyhow::Error>,
    /// The name in the first legacy `crs` member.
    pub(super) crs: Option<String>,
}

impl<'a> Walk<'a> {
    pub(super) fn new(name: &'a str, max_points: usize, skipping: &'a Cell<bool>) -> Self {
        let (path, shape) = (String::new(), Shape::default());
        let points = Vec::new();
        Walk { name, max_points, points, path, skipping, shape, failure: None, crs: None }
    }

    /// Stops the reading with `failure`.
    pub(super) fn stop<E: de::Error>(&mut self, failure: anyhow::Error) -> E {
        self.failure = Some(failure);
        E::custom("stopped")
    }

    /// Stops the reading with `message` about the value being read.
    pub(super) fn refuse<E: de::Error>(&mut self, message: &str) -> E {
        let failure = anyhow::Error::msg(self.about_here(message));
        self.stop(failure)
    }

    /// `message` with the file and the JSON path of the value being read.
    pub(super) fn about_here(&self, message: &str) -> String {
        let mut at = self.path.clone();
        for k in &self.shape.indices {
            let _ = write!(at, "[{k}]");
        }
        let at = if at.is_empty() { "the document" } else { &at };
        format!("{}: GeoJSON: {at}: {message}", self.name)
    }

    pub(super) fn push<E: de::Error>(&mut self, point: Point) -> Result<(), E> {
        if self.points.len() >= self.max_points {
            return Err(self.stop(super::super::too_many(self.name, self.max_points)));
        }
        self.points.push(point);
        Ok(())
    }

    /// Goes down into member `name`; the mark to come back to.
    pub(super) fn enter(&mut self, name: &str) -> usize {
        let mark = self.path.len();
        if mark > 0 {
            self.path.push('.');
        }
        self.path.push_str(name);
        mark
    }

    pub(super) fn enter_index(&mut self, k: usize) -> usize {
        let mark = self.path.len();
        let _ = write!(self.path, "[{k}]");
        mark
    }

    pub(super) fn leave(&mut self, mark: usize) {
        self.path.truncate(mark);
    }

    /// Skips the value of the current member unread.
    pub(super) fn skip<'de, A: MapAccess<'de>>(&mut self, map: &mut A) -> Result<(), A::Error> {
        self.skipping.set(true);
        let skipped = map.next_value::<IgnoredAny>();
        self.skipping.set(false);
        skipped.map(|_| ())
    }
}
