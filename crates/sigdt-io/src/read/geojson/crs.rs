//! The legacy `crs` member (GeoJSON 2008, still written by QGIS and GDAL for projected
//! data): `{"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::27700"}}`. Only
//! the name is read; every other member is skipped unread, and `null` is no system.

use std::fmt;

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, Visitor};

use super::walk::Walk;

/// The `crs` member's value: the string at `properties.name`, if there is one.
pub(super) fn crs_seed<'w, 'a>(walk: &'w mut Walk<'a>) -> NameAt<'w, 'a> {
    NameAt { walk, keys: &["properties", "name"] }
}

/// The string reached through the members `keys`, in objects; `None` where one is missing
/// or `null`.
pub(super) struct NameAt<'w, 'a> {
    walk: &'w mut Walk<'a>,
    keys: &'static [&'static str],
}

impl<'de> DeserializeSeed<'de> for NameAt<'_, '_> {
    type Value = Option<String>;
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<Option<String>, D::Error> {
        json.deserialize_any(self)
    }
}

impl NameAt<'_, '_> {
    fn refuse<E: de::Error>(self, what: &str) -> Result<Option<String>, E> {
        Err(self.walk.refuse(&format!("\"crs\" is {what}, not a crs object")))
    }
}

impl<'de> Visitor<'de> for NameAt<'_, '_> {
    type Value = Option<String>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a crs object")
    }
    fn visit_unit<E: de::Error>(self) -> Result<Option<String>, E> {
        Ok(None)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Option<String>, A::Error> {
        let mut found = None;
        while let Some(key) = map.next_key::<String>()? {
            match self.keys {
                [last] if key == *last => found = Some(map.next_value::<String>()?),
                [first, rest @ ..] if key == *first => {
                    let inner = NameAt { walk: &mut *self.walk, keys: rest };
                    found = map.next_value_seed(inner)?;
                }
                _ => self.walk.skip(&mut map)?,
            }
        }
        Ok(found)
    }
    fn visit_seq<A: de::SeqAccess<'de>>(self, _: A) -> Result<Option<String>, A::Error> {
        self.refuse("an array")
    }
    fn visit_str<E: de::Error>(self, _: &str) -> Result<Option<String>, E> {
        self.refuse("a string")
    }
    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Option<String>, E> {
        self.refuse("a number")
    }
    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Option<String>, E> {
        self.refuse("a number")
    }
    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Option<String>, E> {
        self.refuse("a number")
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<Option<String>, E> {
        self.refuse("true or false")
    }
}
