//! The legacy `crs` member (GeoJSON 2008, still written by QGIS and GDAL for projected
//! data): `{"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::27700"}}`. Only
//! the name is read; every other member is skipped unread, and `null` is no system.

use std::fmt;

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, Visitor};

use super::walk::Walk;

/// The value of a `crs` member: the system's name, if it gives one.
pub(super) struct CrsMember<'w, 'a> {
    pub(super) walk: &'w mut Walk<'a>,
}

impl<'de> DeserializeSeed<'de> for CrsMember<'_, '_> {
    type Value = Option<String>;
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<Option<String>, D::Error> {
        json.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for CrsMember<'_, '_> {
    type Value = Option<String>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a crs object")
    }
    fn visit_unit<E: de::Error>(self) -> Result<Option<String>, E> {
        Ok(None)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Option<String>, A::Error> {
        let mut name = None;
        while let Some(key) = map.next_key::<String>()? {
            match key.as_str() {
                "properties" => name = map.next_value_seed(Properties { walk: &mut *self.walk })?,
                _ => self.walk.skip(&mut map)?,
            }
        }
        Ok(name)
    }
    fn visit_seq<A: de::SeqAccess<'de>>(self, _: A) -> Result<Option<String>, A::Error> {
        Err(self.walk.refuse("\"crs\" is an array, not a crs object"))
    }
    fn visit_str<E: de::Error>(self, _: &str) -> Result<Option<String>, E> {
        Err(self.walk.refuse("\"crs\" is a string, not a crs object"))
    }
    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Option<String>, E> {
        Err(self.walk.refuse("\"crs\" is a number, not a crs object"))
    }
    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Option<String>, E> {
        Err(self.walk.refuse("\"crs\" is a number, not a crs object"))
    }
    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Option<String>, E> {
        Err(self.walk.refuse("\"crs\" is a number, not a crs object"))
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<Option<String>, E> {
        Err(self.walk.refuse("\"crs\" is true or false, not a crs object"))
    }
}

/// The `properties` of a `crs` member: its `name`, if it is a string.
struct Properties<'w, 'a> {
    walk: &'w mut Walk<'a>,
}

impl<'de> DeserializeSeed<'de> for Properties<'_, '_> {
    type Value = Option<String>;
    fn deserialize<D: Deserializer<'de>>(self, json: D) -> Result<Option<String>, D::Error> {
        json.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Properties<'_, '_> {
    type Value = Option<String>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("the properties of a crs object")
    }
    fn visit_unit<E: de::Error>(self) -> Result<Option<String>, E> {
        Ok(None)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Option<String>, A::Error> {
        let mut name = None;
        while let Some(key) = map.next_key::<String>()? {
            match key.as_str() {
                "name" => name = Some(map.next_value::<String>()?),
                _ => self.walk.skip(&mut map)?,
            }
        }
        Ok(name)
    }
}
