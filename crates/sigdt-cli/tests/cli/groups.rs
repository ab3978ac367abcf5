//! `sigdt reconstruct --by COLUMN` (issue 48, part 6) on every input format that has
//! attributes, the layers of one geometry type each (part 2) and the antimeridian (part 4):
//! one feature per group per layer, with the attributes constant within the group.

use super::*;
use rusqlite::types::Value;

/// `data/gis/NAME` of the repository.
fn gis(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/gis").join(name)
}

/// A feature of a GeoPackage layer: its columns (by name) and its geometry's polygons (or
/// lines, each a polygon of one ring; none for points).
struct Feature {
    values: Vec<(String, Value)>,
    polygons: Vec<Vec<Vec<[f64; 2]>>>,
}

impl Feature {
    fn get(&self, name: &str) -> &Value {
        &self.values.iter().find(|(n, _)| n == name).unwrap_or_else(|| panic!("no {name}")).1
    }
}

/// The features of `layer` of the GeoPackage `path`, in fid order (their geometries parsed).
fn features(path: &Path, layer: &str) -> Vec<Feature> {
    let db = rusqlite::Connection::open(path).unwrap();
    let mut statement = db.prepare(&format!("SELECT * FROM {layer} ORDER BY fid")).unwrap();
    let names: Vec<String> = statement.column_names().map(|n| n.to_string()).collect();
    let rows = statement.query_map([], |row| {
        (0..names.len()).map(|k| row.get::<_, Value>(k)).collect::<rusqlite::Result<Vec<_>>>()
    });
    rows.unwrap()
        .map(|values| {
            let values: Vec<(String, Value)> = names.iter().cloned().zip(values.unwrap()).collect();
            let polygons = match &values.iter().find(|(n, _)| n == "geom").unwrap().1 {
                Value::Blob(blob) if layer != "left_out" => parts(blob),
                _ => Vec::new(),
            };
            Feature { values, polygons }
        })
        .collect()
}

/// The parts of a GeoPackage multi-polygon or multi-line-string blob (sigdt writes no
/// envelope: 8 bytes of header, then little-endian WKB): polygons' rings (closed), or each
/// line as a part of one ring.
fn parts(blob: &[u8]) -> Vec<Vec<Vec<[f64; 2]>>> {
    let int = |at: usize| u32::from_le_bytes(blob[at..at + 4].try_into().unwrap()) as usize;
    let real = |at: usize| f64::from_le_bytes(blob[at..at + 8].try_into().unwrap());
    let kind = int(9);
    assert!(blob[8] == 1 && (kind == 5 || kind == 6), "a little-endian multi-geometry");
    let mut at = 17;
    let mut parts = Vec::new();
    for _ in 0..int(13) {
        assert_eq!((blob[at], int(at + 1)), (1, kind - 3), "a polygon or a line");
        let rings = if kind == 6 { int(at + 5) } else { 1 };
        at += if kind == 6 { 9 } else { 5 };
        let mut part = Vec::new();
        for _ in 0..rings {
            let n = int(at);
            at += 4;
            part.push((0..n).map(|k| [real(at + 16 * k), real(at + 16 * k + 8)]).collect());
            at += 16 * n;
        }
        parts.push(part);
    }
    assert_eq!(at, blob.len(), "nothing after the geometry");
    parts
}

/// The text of a column's value (`None` for NULL), whatever its type.
fn text(value: &Value) -> Option<String> {
    match value {
        Value::Null => None,
        Value::Integer(n) => Some(n.to_string()),
        Value::Real(x) => Some(x.to_string()),
        Value::Text(t) => Some(t.clone()),
        Value::Blob(b) => Some(format!("{} bytes", b.len())),
    }
}

/// The geometry types GeoPackage declares for each layer, by layer name.
fn declared_types(path: &Path) -> Vec<(String, String)> {
    let db = rusqlite::Connection::open(path).unwrap();
    let query = "SELECT table_name, geometry_type_name FROM gpkg_geometry_columns ORDER BY 1";
    let mut statement = db.prepare(query).unwrap();
    let rows = statement.query_map([], |row| Ok((row.get(0)?, row.get(1)?))).unwrap();
    rows.map(Result::unwrap).collect()
}

/// A square of side 1 with its corner at `(x, y)`, counter-clockwise.
fn square_at(x: f64, y: f64) -> [[f64; 2]; 4] {
    [[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]]
}

#[test]
fn a_geopackage_by_a_column_gives_one_feature_per_group_and_its_flatgeobuf_reads_back() {
    let dir = tempdir();
    let islands = gis("islands_4326.gpkg");
    let args = ["reconstruct", islands.to_str().unwrap(), "--by", "archipelago", "-v"];
    let run = sigdt_in(dir.path(), &[&args[..], &["-o", "o.gpkg"]].concat(), None);
    assert!(run.expect(0).stderr.contains("groups:                    4 by 'archipelago'"));
    let layers = declared_types(&dir.path().join("o.gpkg"));
    let expected = [
        ("areas", "MULTIPOLYGON"),
        ("left_out", "POINT"),
        ("networks", "MULTILINESTRING"),
        ("paths", "MULTILINESTRING"),
    ];
    assert_eq!(layers, expected.map(|(a, b)| (a.to_string(), b.to_string())), "{run}");
    let areas = features(&dir.path().join("o.gpkg"), "areas");
    let names: Vec<Option<String>> = areas.iter().map(|f| text(f.get("archipelago"))).collect();
    let expected = ["aland", "dalmatia", "hebrides", "lofoten"].map(|n| Some(n.to_string()));
    let mut sorted = names.clone();
    sorted.sort();
    assert_eq!(sorted, expected, "one feature per archipelago");
    assert!(areas.iter().all(|f| f.polygons.len() > 3), "islands in every archipelago");
    // FlatGeobuf: four files, said under -v; read back by sigdt with their properties.
    let run = sigdt_in(dir.path(), &[&args[..], &["-o", "o.fgb"]].concat(), None);
    for file in ["o.fgb (areas 4", "o.paths.fgb (paths", "o.networks.fgb", "o.left_out.fgb"] {
        assert!(run.expect(0).stderr.contains(file), "{file}: {run}");
    }
    let args = ["reconstruct", "o.fgb", "--by", "archipelago", "-o", "back.gpkg"];
    sigdt_in(dir.path(), &args, None).expect(0);
    let back = features(&dir.path().join("back.gpkg"), "areas");
    let again: Vec<Option<String>> = back.iter().map(|f| text(f.get("archipelago"))).collect();
    assert_eq!(again, names, "the same groups, in the same order");
    // Columns read from sigdt's own `status` come back as `input_status`.
    assert_eq!(text(back[0].get("input_status")), text(areas[0].get("status")));
}

/// A Shapefile of `points` (one point record each) at `dir/name.shp`.
fn point_shapefile(dir: &Path, name: &str, points: &[[f64; 2]]) {
    let mut shp = vec![0u8; 100];
    shp[..4].copy_from_slice(&9994u32.to_be_bytes());
    shp[24..28].copy_from_slice(&((50 + 14 * points.len()) as u32).to_be_bytes());
    shp[28..32].copy_from_slice(&1000u32.to_le_bytes());
    shp[32..36].copy_from_slice(&1u32.to_le_bytes());
    for (k, [x, y]) in points.iter().enumerate() {
        shp.extend_from_slice(&(k as u32 + 1).to_be_bytes());
        shp.extend_from_slice(&10u32.to_be_bytes());
        shp.extend_from_slice(&1u32.to_le_bytes());
        shp.extend_from_slice(&x.to_le_bytes());
        shp.extend_from_slice(&y.to_le_bytes());
    }
    fs::write(dir.join(format!("{name}.shp")), shp).unwrap();
}

/// A dBASE table of the fields `(name, type, length, decimals)` and records at `path`.
fn dbf(path: &Path, fields: &[(&str, u8, u8, u8)], records: &[Vec<&str>]) {
    let record_length: usize = 1 + fields.iter().map(|f| f.2 as usize).sum::<usize>();
    let mut b = vec![3u8, 124, 1, 1];
    b.extend_from_slice(&(records.len() as u32).to_le_bytes());
    b.extend_from_slice(&((33 + 32 * fields.len()) as u16).to_le_bytes());
    b.extend_from_slice(&(record_length as u16).to_le_bytes());
    b.resize(32, 0);
    for &(name, kind, length, decimals) in fields {
        let mut d = [0u8; 32];
        d[..name.len()].copy_from_slice(name.as_bytes());
        (d[11], d[16], d[17]) = (kind, length, decimals);
        b.extend_from_slice(&d);
    }
    b.push(0x0d);
    for record in records {
        b.push(b' ');
        for (value, field) in record.iter().zip(fields) {
            let mut cell = value.as_bytes().to_vec();
            cell.resize(field.2 as usize, b' ');
            b.extend_from_slice(&cell);
        }
    }
    fs::write(path, b).unwrap();
}

#[test]
fn a_shapefile_is_grouped_by_a_field_of_its_dbf() {
    let dir = tempdir();
    let points = [square_at(0.0, 0.0), square_at(5.0, 0.0)].concat();
    point_shapefile(dir.path(), "pts", &points);
    let fields = [("island", b'C', 6, 0), ("kind", b'C', 6, 0), ("area", b'N', 4, 0)];
    let fields = [&fields[..], &[("ok", b'L', 1, 0), ("day", b'D', 8, 0)]].concat();
    let record = |island, kind| vec![island, kind, "  12", "T", "20240131"];
    let records: Vec<Vec<&str>> = (0..8)
        .map(|k| match k {
            0..4 => record("a", "rock"),
            _ => record("b", if k == 7 { "sand" } else { "rock" }),
        })
        .collect();
    dbf(&dir.path().join("pts.dbf"), &fields, &records);
    sigdt_in(dir.path(), &["reconstruct", "pts.shp", "--by", "island", "-o", "o.gpkg"], None)
        .expect(0);
    let areas = features(&dir.path().join("o.gpkg"), "areas");
    assert_eq!(areas.len(), 2);
    let row = |f: &Feature| ["island", "kind", "area", "ok", "day"].map(|c| text(f.get(c)));
    let some = |s: &str| Some(s.to_string());
    assert_eq!(
        row(&areas[0]),
        [some("a"), some("rock"), some("12"), some("1"), some("2024-01-31")]
    );
    assert_eq!(row(&areas[1])[1], None, "`kind` differs within b");
    assert_eq!(*areas[0].get("area"), Value::Integer(12), "N with no decimals is a number");
    // Without a .dbf there are no attributes to group by.
    fs::remove_file(dir.path().join("pts.dbf")).unwrap();
    sigdt_in(dir.path(), &["reconstruct", "pts.shp", "--by", "island", "-o", "o.gpkg"], None)
        .error(&["pts.shp: --by: no .dbf beside the Shapefile"]);
}

#[test]
fn a_table_keeps_the_attributes_constant_within_each_group() {
    let dir = tempdir();
    let mut csv = String::from("island,kind,id,x,y\n");
    let rows = [("a", square_at(0.0, 0.0)), ("b", square_at(5.0, 0.0)), ("", square_at(0.0, 5.0))];
    let mut id = 0;
    for (island, square) in rows {
        for (k, [x, y]) in square.iter().enumerate() {
            let kind = if island == "b" && k == 3 { "sand" } else { "rock" };
            id += 1;
            csv += &format!("{island},{kind},{id},{x},{y}\n");
        }
    }
    csv += "c,rock,99,9,9\n";
    fs::write(dir.path().join("t.csv"), csv).unwrap();
    let run =
        sigdt_in(dir.path(), &["reconstruct", "t.csv", "--by", "island", "-o", "o.gpkg"], None);
    let warning = "sigdt: warning: 1 of 4 groups gave no curve (their areas features, without \
                   geometry, say why): 'c' (too-few-points: fewer than three distinct points)";
    assert_eq!(run.expect(0).stderr.trim(), warning, "{run}");
    let areas = features(&dir.path().join("o.gpkg"), "areas");
    let rows: Vec<[Option<String>; 4]> =
        areas.iter().map(|f| ["island", "kind", "id", "status"].map(|c| text(f.get(c)))).collect();
    let s = |t: &str| Some(t.to_string());
    assert_eq!(
        rows,
        [
            [s("a"), s("rock"), None, s("polygon")],
            [s("b"), None, None, s("polygon")],
            [None, s("rock"), None, s("polygon")],
            [s("c"), s("rock"), s("99"), s("too-few-points")],
        ],
        "the missing value is a group of its own; `id` is kept where it is constant"
    );
    assert!(areas[3].polygons.is_empty(), "no geometry for a group without a curve");
    assert_eq!(
        areas[0].polygons,
        vec![vec![[square_at(0.0, 0.0).to_vec(), vec![[0.0, 0.0]]].concat()]]
    );
}

#[test]
fn a_group_that_fails_is_a_feature_and_a_warning_not_a_failed_run() {
    let dir = tempdir();
    let mut csv = String::from("name,lon,lat\n");
    for [x, y] in square_at(10.0, 10.0) {
        csv += &format!("near,{},{}\n", x * 0.01 + 10.0, y * 0.01 + 10.0);
    }
    csv += "far,-170,0\nfar,-10,0\nfar,90,0\nfar,90,1\n";
    fs::write(dir.path().join("t.csv"), csv).unwrap();
    let run = sigdt_in(dir.path(), &["reconstruct", "t.csv", "--by", "name", "-o", "o.gpkg"], None);
    assert!(run.expect(0).stderr.contains("1 of 2 groups gave no curve"), "{run}");
    assert!(
        run.stderr.contains(
            "'far' (the columns are longitude and latitude, and point 0 lies more than 10,000 km"
        ),
        "{run}"
    );
    let areas = features(&dir.path().join("o.gpkg"), "areas");
    assert_eq!(areas.len(), 2);
    let far = &areas[1];
    assert_eq!(
        (text(far.get("name")), text(far.get("status"))),
        (Some("far".into()), Some("error".into()))
    );
    assert!(text(far.get("diagnosis")).unwrap().contains("split the data by region"));
    assert!(far.polygons.is_empty());
}

#[test]
fn by_is_refused_where_it_cannot_be_written_or_found() {
    let dir = tempdir();
    fs::write(dir.path().join("t.csv"), "island,x,y\na,0,0\na,1,0\na,1,1\n").unwrap();
    let run = |args: &[&str]| sigdt_in(dir.path(), &[&["reconstruct"][..], args].concat(), None);
    run(&["t.csv", "--by", "island"]).usage_error();
    run(&["t.csv", "--by", "island", "-o", "o.wkt"]).usage_error();
    run(&["t.csv", "--by", "isle", "-o", "o.gpkg"])
        .error(&["t.csv: --by: no column 'isle' (the columns: 'island')"]);
    fs::write(dir.path().join("p.wkt"), "MULTIPOINT (0 0, 1 0, 1 1)").unwrap();
    run(&["p.wkt", "--by", "island", "-o", "o.gpkg"]).usage_error();
    // FlatGeobuf holds one layer a file: not one stream, and none of its files the input.
    run(&["t.csv", "--format", "fgb"]).usage_error();
    fs::copy(dir.path().join("t.csv"), dir.path().join("o.paths.fgb")).unwrap();
    run(&["o.paths.fgb", "-o", "o.fgb", "--columns", "x,y"])
        .error(&["o.paths.fgb: output is the input file; refusing to overwrite it"]);
    assert!(!dir.path().join("o.fgb").exists(), "nothing written");
    // A file of another kind where a layer file goes is the user's: not replaced.
    run(&["t.csv", "--by", "island", "-o", "o.fgb"]).error(&[
        "o.paths.fgb: sigdt writes the paths layer there, beside -o, but it holds something \
         other than a FlatGeobuf file",
    ]);
    assert_eq!(
        fs::read(dir.path().join("o.paths.fgb")).unwrap(),
        fs::read(dir.path().join("t.csv")).unwrap()
    );
    assert!(!dir.path().join("o.fgb").exists(), "nothing written");
    // An earlier run's layer files are replaced.
    fs::remove_file(dir.path().join("o.paths.fgb")).unwrap();
    run(&["t.csv", "--by", "island", "-o", "o.fgb"]).expect(0);
    run(&["t.csv", "--by", "island", "-o", "o.fgb"]).expect(0);
}

/// `[lon, lat]` with the longitude brought into [-180, 180], as GIS files store it.
fn wrapped([lon, lat]: [f64; 2]) -> [f64; 2] {
    [if lon > 180.0 { lon - 360.0 } else { lon }, lat]
}

/// Twice the signed area of `ring` (closed: its last point is its first).
fn twice_area(ring: &[[f64; 2]]) -> f64 {
    ring.windows(2).map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1]).sum()
}

/// Whether two edges of `ring` (closed) that are not neighbours cross or touch.
fn self_intersects(ring: &[[f64; 2]]) -> bool {
    let n = ring.len() - 1;
    let orient = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).signum()
    };
    (0..n).any(|i| {
        (i + 2..n).filter(|&j| !(i == 0 && j == n - 1)).any(|j| {
            let (a, b, c, d) = (ring[i], ring[i + 1], ring[j], ring[j + 1]);
            orient(a, b, c) != orient(a, b, d) && orient(c, d, a) != orient(c, d, b)
        })
    })
}

#[test]
fn an_island_across_the_antimeridian_is_written_valid_in_degrees() {
    // 40 points round (180° E, 16° S), 0.3° of arc across, stored as GIS files store them:
    // longitudes in [-180, 180], the two crossing points at both +180 and -180.
    let cos = 16f64.to_radians().cos();
    let unwrapped: Vec<[f64; 2]> = (0..40)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 40.0;
            [180.0 + 0.3 * a.cos() / cos, -16.0 + 0.3 * a.sin()]
        })
        .collect();
    let mut csv = String::from("name,lon,lat\n");
    for &p in &unwrapped {
        let [lon, lat] = wrapped(p);
        csv += &format!("island,{lon:?},{lat:?}\n");
        if lon == 180.0 {
            csv += &format!("island,-180.0,{lat:?}\n");
        }
    }
    assert_eq!(csv.matches(",-180.0,").count(), 2, "both crossing points twice");
    // And an open arc across it, westwards.
    for k in 0..=30 {
        let a = std::f64::consts::PI * k as f64 / 30.0;
        let [lon, lat] = wrapped([180.5 - a / 3.0, -14.0 + 0.5 * a.sin()]);
        csv += &format!("reef,{lon:?},{lat:?}\n");
    }
    let dir = tempdir();
    fs::write(dir.path().join("t.csv"), csv).unwrap();
    let args = ["reconstruct", "t.csv", "--by", "name", "-o", "o.gpkg", "--expect", "curves"];
    sigdt_in(dir.path(), &args, None).expect(0);
    let areas = features(&dir.path().join("o.gpkg"), "areas");
    assert_eq!(areas.len(), 1, "the island");
    let parts = &areas[0].polygons;
    assert_eq!(parts.len(), 2, "cut in two at the antimeridian: {parts:?}");
    let mut area = 0.0;
    for part in parts {
        let lons = part.iter().flatten().map(|p| p[0]);
        let (west, east) =
            lons.fold((f64::INFINITY, f64::NEG_INFINITY), |(w, e), x| (w.min(x), e.max(x)));
        assert!(-180.0 <= west && east <= 180.0 && east - west < 1.0, "{part:?}");
        assert_eq!(part.len(), 1, "no holes");
        assert!(!self_intersects(&part[0]) && twice_area(&part[0]) > 0.0, "{part:?}");
        area += twice_area(&part[0]) / 2.0;
    }
    let closed: Vec<[f64; 2]> = unwrapped.iter().chain(&unwrapped[..1]).copied().collect();
    let whole = twice_area(&closed) / 2.0;
    assert!((area - whole).abs() < 1e-9 * whole, "{area} {whole}");
    // The reef: one feature of paths, cut where it crosses, its pieces ending on ±180.
    let db = rusqlite::Connection::open(dir.path().join("o.gpkg")).unwrap();
    let lines: i64 =
        db.query_row("SELECT count(*) FROM paths WHERE name = 'reef'", [], |r| r.get(0)).unwrap();
    assert_eq!(lines, 1);
    // GeoJSON of the island alone: one Feature, its geometry cut the same way.
    fs::write(
        dir.path().join("island.csv"),
        fs::read_to_string(dir.path().join("t.csv"))
            .unwrap()
            .lines()
            .filter(|l| !l.starts_with("reef"))
            .map(|l| format!("{l}\n"))
            .collect::<String>(),
    )
    .unwrap();
    let run = sigdt_in(dir.path(), &["reconstruct", "island.csv", "--format", "geojson"], None);
    let json: serde_json::Value = serde_json::from_str(&run.expect(0).stdout).unwrap();
    assert_eq!(json["geometry"]["type"], "MultiPolygon", "{run}");
    let polygons = json["geometry"]["coordinates"].as_array().unwrap();
    assert_eq!(polygons.len(), 2);
    for lon in
        polygons.iter().flat_map(|p| p[0].as_array().unwrap()).map(|q| q[0].as_f64().unwrap())
    {
        assert!(lon.abs() <= 180.0 && (lon.abs() >= 179.5), "{lon}");
    }
}
