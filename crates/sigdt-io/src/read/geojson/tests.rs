//! Unit tests of the GeoJSON reader.

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
    assert_eq!(err, "t.geojson: GeoJSON: the document: expected a GeoJSON object with a \"type\"");
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
fn endless_white_space_ends() {
    // `(echo '{"type":"MultiPoint","coordinates":[[0,0]'; yes '') | sigdt reconstruct -` (G4).
    let start = &br#"{"type":"MultiPoint","coordinates":[[0,0]"#[..];
    let endless = start.chain(std::io::repeat(b'\n'));
    let err = read(endless, "t.geojson", 9).unwrap_err().to_string();
    let want = ":0: more than 1048576 bytes of white space in a row";
    assert!(err.starts_with("t.geojson:") && err.ends_with(want), "{err}");
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

#[test]
fn the_legacy_crs_member_gives_its_name() {
    // As QGIS writes projected layers.
    let text = r#"{"type": "FeatureCollection", "name": "pts",
        "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::27700"}},
        "features": [{"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 2]}}]}"#;
    let (points, crs) = read_with_crs(text.as_bytes(), "t.geojson", 9).unwrap();
    assert_eq!((points, crs.as_deref()), (vec![[1.0, 2.0]], Some("urn:ogc:def:crs:EPSG::27700")));
    // The crs after the features, null, or with other members: read alike.
    let late = r#"{"type": "MultiPoint", "coordinates": [[0, 0]], "crs": {"properties": {"x": [1], "name": "EPSG:3857"}, "type": "name"}}"#;
    assert_eq!(read_with_crs(late.as_bytes(), "t", 9).unwrap().1.as_deref(), Some("EPSG:3857"));
    let none = r#"{"type": "MultiPoint", "coordinates": [[0, 0]], "crs": null}"#;
    assert_eq!(read_with_crs(none.as_bytes(), "t", 9).unwrap().1, None);
    let bad = r#"{"type": "MultiPoint", "coordinates": [[0, 0]], "crs": [1]}"#;
    let err = read_with_crs(bad.as_bytes(), "t", 9).unwrap_err().to_string();
    assert_eq!(err, "t: GeoJSON: crs: \"crs\" is an array, not a crs object");
}
