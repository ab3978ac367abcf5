//! Input formats people have: WKT, GeoJSON, NumPy `.npy`, CSV tables with `--columns`, and
//! gzip-compressed files, from files and from standard input.

use std::io::Write;

use super::*;

/// The unit square's edges, as `sigdt reconstruct` prints them.
const SQUARE: &str = "0 1\n0 3\n1 2\n2 3\n";

#[test]
fn wkt_and_geojson_files_give_their_vertices() {
    let dir = tempdir();
    let d = dir.path();
    let files = [
        ("a.wkt", "MULTIPOINT ((0 0), (1 0), (1 1), (0 1))".to_string()),
        ("b.txt", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\n".to_string()),
        ("c.geojson", r#"{"type":"MultiPoint","coordinates":[[0,0],[1,0],[1,1],[0,1]]}"#.into()),
        (
            "d.json",
            r#"{"type":"FeatureCollection","features":[{"type":"Feature","properties":{},
               "geometry":{"type":"LineString","coordinates":[[0,0],[1,0],[1,1],[0,1]]}}]}"#
                .into(),
        ),
        ("e", "[[0, 0], [1, 0], [1, 1], [0, 1]]".to_string()),
    ];
    for (name, text) in &files {
        fs::write(d.join(name), text).unwrap();
        sigdt_in(d, &["reconstruct", name], None).ok().stdout_is(SQUARE);
    }
    let wkt = "POINT (0 0)\nPOINT (1 0)\nPOINT (1 1)\nPOINT (0 1)\n";
    sigdt_in(d, &["reconstruct", "-"], Some(wkt)).ok().stdout_is(SQUARE);
    fs::write(d.join("bad.geojson"), r#"{"type": "Circle", "radius": 1}"#).unwrap();
    sigdt_in(d, &["reconstruct", "bad.geojson"], None)
        .error(&["bad.geojson", "unknown GeoJSON type 'Circle'"]);
    fs::write(d.join("bad.wkt"), "POINT (0 0)\nLINESTRING (1 0, 2)\n").unwrap();
    sigdt_in(d, &["reconstruct", "bad.wkt"], None).error(&["bad.wkt:2: WKT: expected"]);
}

#[test]
fn npy_arrays_and_gzip_files() {
    let dir = tempdir();
    let d = dir.path();
    let values: Vec<u8> =
        [0.0f64, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0].iter().flat_map(|v| v.to_le_bytes()).collect();
    let mut header = b"{'descr': '<f8', 'fortran_order': False, 'shape': (4, 2), }".to_vec();
    while !(10 + header.len() + 1).is_multiple_of(64) {
        header.push(b' ');
    }
    header.push(b'\n');
    let mut npy = b"\x93NUMPY\x01\x00".to_vec();
    npy.extend((header.len() as u16).to_le_bytes());
    npy.extend(&header);
    npy.extend(&values);
    fs::write(d.join("square.npy"), &npy).unwrap();
    sigdt_in(d, &["reconstruct", "square.npy"], None).ok().stdout_is(SQUARE);
    let mut three = npy.clone();
    let at = three.windows(6).position(|w| w == b"(4, 2)").unwrap();
    three[at..at + 6].copy_from_slice(b"(2, 4)");
    fs::write(d.join("wide.npy"), &three).unwrap();
    sigdt_in(d, &["reconstruct", "wide.npy"], None).error(&["wide.npy", "shape '(2, 4)'"]);

    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(b"x,y\n0,0\n1,0\n1,1\n0,1\n").unwrap();
    let gz = gz.finish().unwrap();
    fs::write(d.join("square.csv.gz"), &gz).unwrap();
    sigdt_in(d, &["reconstruct", "square.csv.gz"], None).ok().stdout_is(SQUARE);
    // Empty input reconstructs to nothing, and says so (issue 31: an empty export fed to a
    // pipeline passed unnoticed).
    let empty = sigdt_in(d, &["reconstruct", "-", "--format", "geojson"], None);
    empty.expect(0);
    assert_eq!(empty.stderr, "sigdt: warning: fewer than three distinct points\n");
    assert!(empty.stdout.contains(r#""warning": true"#), "{}", empty.stdout);
    fs::write(d.join("broken.xy.gz"), &gz[..gz.len() / 2]).unwrap();
    sigdt_in(d, &["reconstruct", "broken.xy.gz"], None).error(&["broken.xy.gz"]);
}

#[test]
fn csv_tables_with_chosen_columns() {
    let dir = tempdir();
    let d = dir.path();
    let table = "id;name;lon;lat\n1;\"a; b\";0;0\n2;c;1;0\n3;d;1;1\n4;e;0;1\n";
    fs::write(d.join("t.csv"), table).unwrap();
    sigdt_in(d, &["reconstruct", "t.csv"], None).ok().stdout_is(SQUARE);
    sigdt_in(d, &["reconstruct", "t.csv", "--columns", "lon,lat"], None).ok().stdout_is(SQUARE);
    sigdt_in(d, &["--columns", "3,4", "reconstruct", "t.csv"], None).ok().stdout_is(SQUARE);
    sigdt_in(d, &["reconstruct", "t.csv", "--columns", "x,y"], None).error(&[
        "t.csv",
        "no column 'x'",
        "'id', 'name', 'lon', 'lat'",
    ]);
    sigdt_in(d, &["reconstruct", "t.csv", "--columns", "3"], None).usage_error();
    fs::write(d.join("w.csv"), "a,b,c\n0,0,5\n").unwrap();
    sigdt_in(d, &["reconstruct", "w.csv"], None).error(&["w.csv", "--columns"]);
    // Decimal commas with ';' separators, and a table on standard input with --columns.
    let comma = "x;y\n0,0;0\n1,0;0\n1,0;1,0\n0;1,0\n";
    sigdt_in(d, &["reconstruct", "-", "--columns", "x,y"], Some(comma)).ok().stdout_is(SQUARE);
}
