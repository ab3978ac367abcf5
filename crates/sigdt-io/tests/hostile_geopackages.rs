//! The seeds of the fuzz target `read_gpkg` (`fuzz/seeds/read_gpkg/`, written by
//! `tools/gpkg-fuzz-seeds.py`), one GeoPackage per finding of the reader (issue 47: M1 and
//! M2 endless views, M3 feature views, M4 write-ahead-log files, K10 a missing system), each
//! read as the fuzz target reads it and checked for the answer it must give, promptly.

use std::path::PathBuf;
use std::time::{Duration, Instant};

fn seed(name: &str) -> Vec<u8> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fuzz/seeds/read_gpkg");
    std::fs::read(dir.join(format!("{name}.gpkg"))).unwrap()
}

/// The seed `name` read as the fuzz target does (at most 100 points, a small budget): its
/// points, or its one-line message naming the file.
fn read(name: &str) -> Result<usize, String> {
    let started = Instant::now();
    let out = sigdt_io::read_geopackage_bytes(&seed(name), "in.gpkg", 100);
    assert!(started.elapsed() < Duration::from_secs(60), "{name}: {:?}", started.elapsed());
    out.map(|points| points.len()).map_err(|e| {
        let message = e.to_string();
        assert!(message.starts_with("in.gpkg: ") && !message.contains('\n'), "{message}");
        message
    })
}

#[test]
fn ordinary_views_and_triggers_read() {
    for name in ["square", "m3-feature-view", "m4-wal", "trigger"] {
        assert_eq!(read(name), Ok(4), "{name}");
    }
}

#[test]
fn endless_views_stop_on_their_budget_naming_the_table() {
    let err = read("m1-endless-layer-list").unwrap_err();
    assert!(err.contains("reading 'gpkg_geometry_columns': stopped"), "{err}");
    let err = read("m1-endless-sort").unwrap_err();
    assert!(err.contains("reading 'sorted': stopped"), "{err}");
    let err = read("m2-endless-systems").unwrap_err();
    assert!(err.contains("reading 'gpkg_spatial_ref_sys': stopped after"), "{err}");
    let err = read("m2-endless-layer").unwrap_err();
    assert!(err.contains("layer 'endless': more than 100 points and rows without one"), "{err}");
}

#[test]
fn a_layer_without_its_system_says_so() {
    let err = read("k10-missing-system").unwrap_err();
    assert!(err.contains("its srs_id 999 has no row in gpkg_spatial_ref_sys"), "{err}");
}

#[test]
fn a_write_ahead_log_file_is_read_without_files_beside_it() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("wal.gpkg");
    std::fs::write(&path, seed("m4-wal")).unwrap();
    let points = sigdt_io::read_points_file(&path, None, None, 100).unwrap();
    assert_eq!(points.len(), 4);
    let beside: Vec<_> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(beside, ["wal.gpkg"]);
}

#[test]
fn sqlite_quoting_the_schema_puts_no_control_character_in_the_message() {
    // Found by the fuzz target: a damaged schema made SQLite's reason quote a control
    // character ("unrecognized token: \"\u{1}\"").
    let err = read("crash-control-character-in-sqlite-reason").unwrap_err();
    assert!(err.contains("not a readable GeoPackage"), "{err}");
    assert!(!err.chars().any(char::is_control), "{err}");
}

#[test]
fn a_geometry_column_named_with_a_control_character_is_escaped_in_the_message() {
    // Found by the fuzz target (1.8 million runs in): a geometry column named "ge\u{19}m"
    // holding text; rusqlite's reason names the column as the file spells it.
    let err = read("crash-control-character-in-column-name").unwrap_err();
    assert!(err.contains("the geometry is not a blob"), "{err}");
    assert!(!err.chars().any(char::is_control), "{err}");
}
