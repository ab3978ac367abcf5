//! Points from GeoJSON (RFC 7946): every position of the geometries, in order, as points.
//!
//! Read: a `FeatureCollection`, a `Feature`, a `GeometryCollection` or a bare geometry
//! (`Point`, `MultiPoint`, `LineString`, `MultiLineString`, `Polygon`, `MultiPolygon`), and
//! also a plain JSON array of `[x, y]` pairs. Features with a `null` geometry are skipped.
//! Positions may have a third (and fourth) value, which is dropped. A polygon ring's closing
//! position repeats its first and is dropped.
//!
//! # Errors
//! Invalid JSON gives the file, line and column; a GeoJSON object of an unknown type or a
//! position that is not two or more finite numbers gives the file and the JSON path of the
//! offending value (`features[3].geometry.coordinates[0]`).
//!
//! # Complexity
//! O(length of the text); the document is read whole.

use std::io::Read;

use anyhow::{anyhow, Result};
use serde_json::Value;
use sigdt::Point;

/// The points of the GeoJSON document of `reader`; see the module docs.
pub fn read(reader: impl Read, name: &str, max_points: usize) -> Result<Vec<Point>> {
    let document: Value = serde_json::from_reader(reader).map_err(|e| {
        if e.is_io() {
            anyhow!("{name}: cannot read: {e}")
        } else {
            anyhow!("{name}:{}:{}: not valid JSON: {e}", e.line(), e.column())
        }
    })?;
    let mut walk = Walk { name, points: Vec::new(), max_points };
    match &document {
        Value::Array(items) => {
            for (k, item) in items.iter().enumerate() {
                walk.position(item, &format!("[{k}]"))?;
            }
        }
        object => walk.object(object, "")?,
    }
    Ok(walk.points)
}

struct Walk<'a> {
    name: &'a str,
    points: Vec<Point>,
    max_points: usize,
}

impl Walk<'_> {
    fn fail(&self, path: &str, message: &str) -> anyhow::Error {
        let at = if path.is_empty() { "the document" } else { path };
        anyhow!("{}: GeoJSON: {at}: {message}", self.name)
    }

    /// A GeoJSON object at `path`.
    fn object(&mut self, value: &Value, path: &str) -> Result<()> {
        let join =
            |key: &str| if path.is_empty() { key.to_string() } else { format!("{path}.{key}") };
        let Some(kind) = value.get("type").and_then(Value::as_str) else {
            return Err(self.fail(path, "expected a GeoJSON object with a \"type\""));
        };
        match kind {
            "FeatureCollection" => {
                let features = self.array(value.get("features"), &join("features"))?;
                for (k, feature) in features.iter().enumerate() {
                    self.object(feature, &format!("{}[{k}]", join("features")))?;
                }
            }
            "Feature" => match value.get("geometry") {
                None | Some(Value::Null) => {}
                Some(geometry) => self.object(geometry, &join("geometry"))?,
            },
            "GeometryCollection" => {
                let geometries = self.array(value.get("geometries"), &join("geometries"))?;
                for (k, geometry) in geometries.iter().enumerate() {
                    self.object(geometry, &format!("{}[{k}]", join("geometries")))?;
                }
            }
            "Point" | "MultiPoint" | "LineString" | "MultiLineString" | "Polygon"
            | "MultiPolygon" => {
                let depth = match kind {
                    "Point" => 0,
                    "MultiPoint" | "LineString" => 1,
                    "MultiLineString" | "Polygon" => 2,
                    _ => 3,
                };
                let rings = matches!(kind, "Polygon" | "MultiPolygon");
                let coordinates = value.get("coordinates").unwrap_or(&Value::Null);
                self.nested(coordinates, depth, rings, &join("coordinates"))?;
            }
            other => {
                return Err(self.fail(path, &format!("unknown GeoJSON type \"{other}\"")));
            }
        }
        Ok(())
    }

    fn array<'v>(&self, value: Option<&'v Value>, path: &str) -> Result<&'v Vec<Value>> {
        value.and_then(Value::as_array).ok_or_else(|| self.fail(path, "expected an array"))
    }

    /// Positions nested `depth` arrays deep; with `rings`, arrays one level above the
    /// positions are rings whose closing position is dropped.
    fn nested(&mut self, value: &Value, depth: usize, rings: bool, path: &str) -> Result<()> {
        if depth == 0 {
            return self.position(value, path);
        }
        let items = self.array(Some(value), path)?;
        let first = self.points.len();
        for (k, item) in items.iter().enumerate() {
            self.nested(item, depth - 1, rings, &format!("{path}[{k}]"))?;
        }
        if rings
            && depth == 1
            && self.points.len() > first + 1
            && self.points.last() == self.points.get(first)
        {
            self.points.pop();
        }
        Ok(())
    }

    /// `[x, y, ...]`.
    fn position(&mut self, value: &Value, path: &str) -> Result<()> {
        let numbers: Option<Vec<f64>> =
            value.as_array().map(|a| a.iter().map(Value::as_f64).collect()).unwrap_or(None);
        match numbers.as_deref() {
            Some([x, y, ..]) if x.is_finite() && y.is_finite() => {
                if self.points.len() >= self.max_points {
                    return Err(super::too_many(self.name, self.max_points));
                }
                self.points.push([*x, *y]);
                Ok(())
            }
            _ => {
                Err(self.fail(path, &format!("expected a position [x, y], found {}", short(value))))
            }
        }
    }
}

/// `value` as JSON, cut to 40 characters.
fn short(value: &Value) -> String {
    let text = value.to_string();
    if text.chars().count() > 40 {
        format!("{}...", text.chars().take(40).collect::<String>())
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Vec<Point>> {
        read(text.as_bytes(), "t.geojson", 1000)
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
        let err = parse("{\"type\": \"Point\",\n \"coordinates\": [1, }").unwrap_err().to_string();
        assert!(err.starts_with("t.geojson:2:") && err.contains("not valid JSON"), "{err}");
        let bad = r#"{"type": "FeatureCollection", "features": [{"type": "Feature",
            "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, "a"]]}}]}"#;
        let err = parse(bad).unwrap_err().to_string();
        assert_eq!(
            err,
            "t.geojson: GeoJSON: features[0].geometry.coordinates[1]: expected a position [x, y], \
             found [1,\"a\"]"
        );
        let err = parse(r#"{"type": "Circle"}"#).unwrap_err().to_string();
        assert!(err.contains("unknown GeoJSON type \"Circle\""), "{err}");
        assert!(parse(r#"{"name": 1}"#).unwrap_err().to_string().contains("\"type\""));
    }
}
