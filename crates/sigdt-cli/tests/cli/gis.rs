//! GIS input and output (issue 31): GeoPackage, Shapefile and FlatGeobuf files written by
//! GeoPandas/pyogrio (`data/gis/`, made by `python/tests/make_gis_fixtures.py`), the
//! coordinate system carried through, longitude/latitude reconstructed in a local plane.

use super::*;

/// `data/gis/NAME` of the repository.
fn gis(name: &str) -> PathBuf {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/gis").join(name);
    assert!(path.is_file(), "test data missing: {}", path.display());
    path
}

fn arg(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

#[test]
fn every_gis_file_of_the_glyph_gives_the_glyphs_polygon() {
    // The same 245 points (glyph_sigma) in metres on the British grid, and in degrees.
    let glyph = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/inputs/glyph_sigma.xy");
    let want = sigdt(&["reconstruct", arg(&glyph)]).ok().stdout.clone();
    let cases = [
        ("sigma_27700.gpkg", "layer 'points' of a GeoPackage; in EPSG:27700"),
        ("sigma_27700.shp", "a Shapefile (its .prj read); in a coordinate system"),
        ("sigma_27700.fgb", "FlatGeobuf; in EPSG:27700"),
        ("sigma_4326.gpkg", "EPSG:4326 is longitude/latitude: reconstructed in an azimuthal"),
        ("sigma_4326_latlon.csv", "the columns are longitude and latitude: reconstructed"),
        ("two_layers.gpkg", "layer 'points' of a GeoPackage"),
    ];
    for (name, how) in cases {
        let run = sigdt(&["reconstruct", arg(&gis(name)), "-v"]);
        if name.ends_with(".fgb") {
            // GDAL writes FlatGeobuf with a spatial index, its features in Hilbert order:
            // the same polygon through points numbered otherwise.
            assert_eq!(run.expect(0).stdout.lines().count(), 245, "{run}");
            assert!(run.stderr.contains("status:                    polygon"), "{run}");
        } else {
            run.expect(0).stdout_is(&want);
        }
        assert!(run.stderr.contains(how), "{name}: -v lacks {how:?}\n{run}");
    }
}

#[test]
fn a_geopackage_layer_is_chosen_by_name() {
    let two = gis("two_layers.gpkg");
    // The hull layer: its polygon's vertices (the closing one once).
    let run = sigdt(&["reconstruct", arg(&two), "--layer", "hull", "-v"]);
    assert!(run.expect(0).stderr.contains("layer 'hull' of a GeoPackage"), "{run}");
    sigdt(&["reconstruct", arg(&two), "--layer", "roads"]).error(&[
        "two_layers.gpkg: --layer: no feature layer 'roads' (the layers: 'hull', 'points')",
    ]);
    // --layer on a file without layers is a usage error.
    sigdt(&["reconstruct", arg(&gis("sigma_27700.fgb")), "--layer", "x"]).usage_error();
}

#[test]
fn geopackage_and_flatgeobuf_output_keep_the_coordinate_system() {
    let dir = tempdir();
    for (input, out) in [("sigma_27700.shp", "o.gpkg"), ("sigma_27700.gpkg", "o.fgb")] {
        sigdt_in(dir.path(), &["reconstruct", arg(&gis(input)), "-o", out], None).ok();
        // Read back by sigdt: the curve's 245 vertices, in EPSG:27700.
        let args = ["reconstruct", out, "-v", "-o", "again.edges"];
        let args: Vec<&str> = match out.ends_with("gpkg") {
            true => args.iter().copied().chain(["--layer", "areas"]).collect(),
            false => args.to_vec(),
        };
        let run = sigdt_in(dir.path(), &args, None);
        assert!(run.expect(0).stderr.contains("points:                    245"), "{run}");
        let crs = if input.ends_with("shp") { "in a coordinate system" } else { "in EPSG:27700" };
        assert!(run.stderr.contains(crs), "{out}: {run}");
    }
    // --crs gives a system to input without one; a file that has another is refused.
    let glyph = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/inputs/glyph_sigma.xy");
    let args = ["reconstruct", arg(&glyph), "--crs", "EPSG:3857", "-o", "c.gpkg"];
    sigdt_in(dir.path(), &args, None).ok();
    let run = sigdt_in(dir.path(), &["reconstruct", "c.gpkg", "--layer", "areas", "-v"], None);
    assert!(run.expect(0).stderr.contains("in EPSG:3857"), "{run}");
    sigdt(&["reconstruct", arg(&gis("sigma_27700.gpkg")), "--crs", "EPSG:4326"])
        .error(&["is in EPSG:27700, but --crs says EPSG:4326: sigdt does not transform"]);
    sigdt(&["reconstruct", arg(&glyph), "--crs", "WGS84"]).usage_error();
    // A .prj without an EPSG code: --crs names it.
    let shp = gis("sigma_27700.shp");
    let run = sigdt(&["reconstruct", arg(&shp), "--crs", "EPSG:27700", "-v"]);
    assert!(run.expect(0).stderr.contains("(its .prj read); in EPSG:27700"), "{run}");
}

#[test]
fn geojson_output_is_longitude_and_latitude_only() {
    // RFC 7946: projected coordinates in GeoJSON are read as degrees by every reader.
    sigdt(&["reconstruct", arg(&gis("sigma_27700.gpkg")), "--format", "geojson"])
        .error(&["is in EPSG:27700, but GeoJSON is longitude/latitude on WGS 84 (RFC 7946)"]);
    let run = sigdt(&["reconstruct", arg(&gis("sigma_4326.gpkg")), "--format", "geojson"]);
    assert!(run.ok().stdout.starts_with(r#"{"type": "Feature", "geometry": {"type": "Polygon""#));
    // The properties say which method made the result and what its status means.
    let method = r#""status": "polygon", "status_message": "one closed polygon through every point not left out", "method": "sig-auto", "points": 245"#;
    assert!(run.stdout.contains(method), "{run}");
}

/// The island `data/real/gshhs_arch_aland_k1.xy` as a 5 km wide group in metres, placed
/// at latitude `lat0` as longitude/latitude (each point's own scale of longitude), with the
/// header `header`.
fn island_csv(lat0: f64, header: &str) -> String {
    const R: f64 = 6_371_008.8;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/real/gshhs_arch_aland_k1.xy");
    let text = fs::read_to_string(path).unwrap();
    let points: Vec<[f64; 2]> = text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let mut f = l.split_whitespace().map(|v| v.parse::<f64>().unwrap());
            [f.next().unwrap(), f.next().unwrap()]
        })
        .collect();
    let lo = |k: usize| points.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
    let hi = |k: usize| points.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
    let scale = 5000.0 / (hi(0) - lo(0)).max(hi(1) - lo(1));
    let mut csv = format!("{header}\n");
    for p in &points {
        let (x, y) = ((p[0] - lo(0)) * scale, (p[1] - lo(1)) * scale);
        let lat = lat0 + (y / R).to_degrees();
        let lon = 10.0 + (x / (R * lat.to_radians().cos())).to_degrees();
        csv += &format!("{lon:?},{lat:?}\n");
    }
    csv
}

#[test]
fn the_same_island_gives_the_same_edges_at_the_equator_and_at_60_north() {
    let dir = tempdir();
    let mut edges = Vec::new();
    for lat0 in [0.0, 60.0] {
        fs::write(dir.path().join("island.csv"), island_csv(lat0, "lon,lat")).unwrap();
        let run = sigdt_in(dir.path(), &["reconstruct", "island.csv"], None);
        edges.push(run.expect(0).stdout.clone());
    }
    assert_eq!(edges[0], edges[1], "longitude/latitude depend on the latitude");
    // Read as plane coordinates (columns not named longitude and latitude), a degree of
    // longitude at 60° N counts twice its length, and the edges change: the test can fail.
    fs::write(dir.path().join("plane.csv"), island_csv(60.0, "a,b")).unwrap();
    let plane = sigdt_in(dir.path(), &["reconstruct", "plane.csv"], None).expect(0).stdout.clone();
    assert_ne!(plane, edges[1], "the island does not tell a plane from a sphere");
}

#[test]
fn damaged_gis_files_are_clean_errors_naming_the_file() {
    let dir = tempdir();
    for name in ["sigma_27700.gpkg", "sigma_27700.fgb", "sigma_27700.shp"] {
        let bytes = fs::read(gis(name)).unwrap();
        for keep in [20, 150, bytes.len() / 2] {
            let cut = dir.path().join(format!("cut_{keep}_{name}"));
            fs::write(&cut, &bytes[..keep]).unwrap();
            let run = sigdt(&["reconstruct", arg(&cut)]);
            let file = cut.file_name().unwrap().to_str().unwrap();
            run.error(&[file]);
        }
    }
    // A GeoPackage is read in place: not from standard input.
    let gpkg = fs::read(gis("sigma_27700.gpkg")).unwrap();
    let text = String::from_utf8_lossy(&gpkg[..16]).into_owned();
    sigdt_in(dir.path(), &["reconstruct", "-"], Some(&text))
        .error(&["<stdin>: a GeoPackage is read in place: give its file name"]);
}

#[test]
fn a_geojson_crs_member_is_carried_like_a_geopackages() {
    // The glyph in metres, as QGIS writes a projected layer: a legacy crs member.
    let glyph = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/inputs/glyph_sigma.xy");
    let text = fs::read_to_string(glyph).unwrap();
    let positions: Vec<String> = text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let f: Vec<f64> = l.split_whitespace().map(|v| v.parse().unwrap()).collect();
            format!("[{:?}, {:?}]", 400_000.0 + f[0], 300_000.0 + f[1])
        })
        .collect();
    let geojson = format!(
        r#"{{"type": "FeatureCollection", "crs": {{"type": "name", "properties": {{"name": "urn:ogc:def:crs:EPSG::27700"}}}}, "features": [{{"type": "Feature", "properties": {{}}, "geometry": {{"type": "MultiPoint", "coordinates": [{}]}}}}]}}"#,
        positions.join(", ")
    );
    let dir = tempdir();
    fs::write(dir.path().join("pts.geojson"), geojson).unwrap();
    let run = sigdt_in(dir.path(), &["reconstruct", "pts.geojson", "-v", "-o", "o.gpkg"], None);
    assert!(run.expect(0).stderr.contains("GeoJSON; in EPSG:27700"), "{run}");
    let back = sigdt_in(dir.path(), &["reconstruct", "o.gpkg", "--layer", "areas", "-v"], None);
    assert!(back.expect(0).stderr.contains("in EPSG:27700"), "{back}");
    sigdt_in(dir.path(), &["reconstruct", "pts.geojson", "--format", "geojson"], None)
        .error(&["is in EPSG:27700, but GeoJSON is longitude/latitude"]);
    // Asked for, the legacy member is written, and read back.
    let args = ["reconstruct", "pts.geojson", "--geojson-legacy-crs", "-o", "out.geojson"];
    sigdt_in(dir.path(), &args, None).ok();
    let text = fs::read_to_string(dir.path().join("out.geojson")).unwrap();
    let member = r#"{"type": "Feature", "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::27700"}}, "geometry": {"type": "Polygon""#;
    assert!(text.starts_with(member), "{text}");
    let back = sigdt_in(dir.path(), &["reconstruct", "out.geojson", "-v"], None);
    assert!(back.expect(0).stderr.contains("GeoJSON; in EPSG:27700"), "{back}");
    // A .prj without an EPSG code has no name for the member.
    let shp = gis("sigma_27700.shp");
    sigdt(&["reconstruct", arg(&shp), "--format", "geojson", "--geojson-legacy-crs"])
        .error(&["the legacy crs member names a system by its EPSG code"]);
}

#[test]
fn commands_in_the_plane_warn_about_degrees() {
    // Only `reconstruct` uses a local plane; the others say that they do not.
    let degrees = gis("sigma_4326.gpkg");
    let run = sigdt(&["graph", arg(&degrees), "--kind", "sigdt"]);
    let warning = "sigdt: warning: EPSG:4326 is longitude/latitude, but `graph` works in the \
                   plane of the coordinates";
    assert!(run.expect(0).stderr.starts_with(warning), "{run}");
    assert_eq!(run.stderr.lines().count(), 1, "{run}");
    // Metres: nothing to say.
    sigdt(&["graph", arg(&gis("sigma_27700.gpkg")), "--kind", "sigdt"]).ok();
}

#[test]
fn sigdts_own_geopackage_reads_back_by_its_layers_not_the_empty_one() {
    // Issue 47, K8: the output read back took the empty `left_out` layer: 0 points, exit 0.
    let dir = tempdir();
    let square = write_points(dir.path(), "square.xy", &circle(24, 10.0));
    sigdt_in(dir.path(), &["reconstruct", arg(&square), "-o", "o.gpkg"], None).ok();
    sigdt_in(dir.path(), &["reconstruct", "o.gpkg"], None)
        .error(&["its only point layer, 'left_out', is empty; choose one of its 4 feature layers"]);
    let run = sigdt_in(dir.path(), &["reconstruct", "o.gpkg", "--layer", "areas", "-v"], None);
    assert!(run.expect(0).stderr.contains("layer 'areas'"), "{run}");
}

#[test]
fn a_layer_whose_system_has_no_row_says_so() {
    // Issue 47, K10: a layer whose srs_id has no row in gpkg_spatial_ref_sys silently had
    // no coordinate system.
    let dir = tempdir();
    let copy = dir.path().join("s.gpkg");
    fs::copy(gis("sigma_27700.gpkg"), &copy).unwrap();
    let db = rusqlite::Connection::open(&copy).unwrap();
    // As a careless tool writes it: the foreign key that forbids it is not enforced.
    db.execute_batch("PRAGMA foreign_keys = OFF").unwrap();
    let rewrite = "UPDATE gpkg_geometry_columns SET srs_id = 99999 WHERE srs_id = 27700";
    assert_eq!(db.execute(rewrite, []).unwrap(), 1);
    drop(db);
    sigdt(&["reconstruct", arg(&copy)])
        .error(&["its srs_id 99999 has no row in gpkg_spatial_ref_sys"]);
}

#[test]
fn a_geopackage_with_other_layers_is_not_replaced() {
    // Issue 47, O1: `-o` onto an existing GeoPackage replaced it whole, deleting the user's
    // other layers, with exit status 0.
    let dir = tempdir();
    let theirs = dir.path().join("theirs.gpkg");
    fs::copy(gis("two_layers.gpkg"), &theirs).unwrap();
    let before = fs::read(&theirs).unwrap();
    let input = gis("sigma_27700.gpkg");
    sigdt(&["reconstruct", arg(&input), "-o", arg(&theirs)])
        .error(&["a GeoPackage holding other tables ('hull', 'points')", "refusing"]);
    assert_eq!(fs::read(&theirs).unwrap(), before);
    // sigdt's own output is replaced, as any output file is.
    let ours = dir.path().join("ours.gpkg");
    sigdt(&["reconstruct", arg(&input), "-o", arg(&ours)]).ok();
    sigdt(&["reconstruct", arg(&input), "-o", arg(&ours), "--method", "emst"]).expect(0);
}

#[test]
fn a_feature_view_is_read() {
    // Issue 47, M3: GeoPackage feature views (allowed by the format; GDAL writes them) were
    // refused: a view has no rowid.
    let dir = tempdir();
    let copy = dir.path().join("v.gpkg");
    fs::copy(gis("sigma_27700.gpkg"), &copy).unwrap();
    let db = rusqlite::Connection::open(&copy).unwrap();
    db.execute_batch(
        "CREATE VIEW half AS SELECT fid, geom FROM points WHERE fid % 2 = 0;
         INSERT INTO gpkg_contents (table_name, data_type, identifier, srs_id)
             VALUES ('half', 'features', 'half', 27700);
         INSERT INTO gpkg_geometry_columns (table_name, column_name, geometry_type_name, srs_id, z, m)
             VALUES ('half', 'geom', 'POINT', 27700, 0, 0);",
    )
    .unwrap();
    let even: i64 = db.query_row("SELECT count(*) FROM half", [], |row| row.get(0)).unwrap();
    drop(db);
    let run = sigdt(&["reconstruct", arg(&copy), "--layer", "half", "-v", "--format", "edges"]);
    let stderr = run.expect(0).stderr.clone();
    assert!(
        stderr.contains(&format!("points:                    {even} (read as layer 'half'")),
        "{stderr}"
    );
    assert!(stderr.contains("in EPSG:27700"), "{stderr}");
}
