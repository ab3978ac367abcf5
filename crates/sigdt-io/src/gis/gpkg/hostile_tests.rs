//! Hostile GeoPackages (issue 47, M1, M2, M4): views that never end, and files whose reading
//! would write beside them. Each stops within its budget with an error naming the table.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use rusqlite::Connection;

use super::budget::{Budgeted, Limits, Stop};
use super::{read, system};

/// A minimal GeoPackage in `dir` with `sql` run after its two required tables are made;
/// `points` is an ordinary point layer of one point.
fn geopackage(dir: &Path, sql: &str) -> PathBuf {
    let path = dir.join("hostile.gpkg");
    let db = Connection::open(&path).unwrap();
    db.execute_batch(
        "CREATE TABLE gpkg_spatial_ref_sys (srs_name TEXT, srs_id INTEGER PRIMARY KEY, \
           organization TEXT, organization_coordsys_id INTEGER, definition TEXT);
         INSERT INTO gpkg_spatial_ref_sys VALUES ('u', 0, 'NONE', 0, 'undefined');
         CREATE TABLE points (fid INTEGER PRIMARY KEY, geom BLOB);
         INSERT INTO points VALUES (1, X'47500001000000000101000000000000000000F03F0000000000000040');",
    )
    .unwrap();
    db.execute_batch(sql).unwrap();
    path
}

const COLUMNS: &str = "CREATE TABLE gpkg_geometry_columns (table_name TEXT, column_name TEXT, \
                       geometry_type_name TEXT, srs_id INTEGER, z INTEGER, m INTEGER);";

fn quick<T>(run: impl FnOnce() -> T) -> T {
    let started = Instant::now();
    let out = run();
    assert!(started.elapsed() < Duration::from_secs(60), "took {:?}", started.elapsed());
    out
}

#[test]
fn an_endless_layer_list_is_refused_naming_it() {
    // M1: gpkg_geometry_columns a view over an endless recursive query.
    let dir = tempfile::tempdir().unwrap();
    let path = geopackage(
        dir.path(),
        "CREATE VIEW gpkg_geometry_columns AS WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL \
         SELECT i + 1 FROM n) SELECT 'points' AS table_name, 'geom' AS column_name, \
         'POINT' AS geometry_type_name, 0 AS srs_id, 0 AS z, 0 AS m FROM n;",
    );
    let err = quick(|| read(&path, "h.gpkg", None, 1000)).err().unwrap().to_string();
    // sigdt sorts the list, so the budget stops the sort (were it not sorted, the count of
    // layers would: "lists more than 100000 layers").
    assert!(err.starts_with("h.gpkg: reading 'gpkg_geometry_columns': stopped"), "{err}");
}

#[test]
fn an_endless_layer_without_points_counts_its_rows() {
    // M2: the layer an endless view whose rows carry no geometry; --max-points never
    // triggered.
    let dir = tempfile::tempdir().unwrap();
    let path = geopackage(
        dir.path(),
        &format!(
            "{COLUMNS} INSERT INTO gpkg_geometry_columns VALUES ('endless', 'geom', 'POINT', 0, 0, 0);
             CREATE VIEW endless AS WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 \
             FROM n) SELECT i AS fid, NULL AS geom FROM n;"
        ),
    );
    let err = quick(|| read(&path, "h.gpkg", Some("endless"), 1000)).err().unwrap().to_string();
    assert!(err.contains("layer 'endless': more than 1000 points and rows without one"), "{err}");
}

#[test]
fn a_view_of_systems_is_stopped_by_the_memory_and_time_budgets() {
    // M2: gpkg_spatial_ref_sys an endless view; the system asked for is never in it.
    let dir = tempfile::tempdir().unwrap();
    let path = geopackage(
        dir.path(),
        "ALTER TABLE gpkg_spatial_ref_sys RENAME TO srs_table;
         CREATE VIEW gpkg_spatial_ref_sys AS WITH RECURSIVE n(i) AS (SELECT 2 UNION ALL \
         SELECT i + 2 FROM n) SELECT 'x' AS srs_name, i AS srs_id, 'EPSG' AS organization, \
         i AS organization_coordsys_id, '' AS definition FROM n;",
    );
    let limits = Limits { steps_per_row: 20_000_000, memory: 1 << 40 };
    let budget = Budgeted::open_with(&path, limits).unwrap();
    let error = quick(|| system(&budget.db, 4327)).unwrap_err();
    assert_eq!(budget.stopped(&error), Some(Stop::Time), "{error}");
    // Sorted, it holds every row it has made: the memory budget.
    let limits = Limits { steps_per_row: u64::MAX, memory: 64 << 20 };
    let budget = Budgeted::open_with(&path, limits).unwrap();
    let sorted = "SELECT srs_id FROM gpkg_spatial_ref_sys ORDER BY srs_id DESC";
    let error = quick(|| budget.db.query_row(sorted, [], |r| r.get::<_, i64>(0))).unwrap_err();
    assert_eq!(budget.stopped(&error), Some(Stop::Memory), "{error}");
}

#[test]
fn a_cancelled_reading_stops() {
    let dir = tempfile::tempdir().unwrap();
    let path = geopackage(
        dir.path(),
        &format!(
            "{COLUMNS} INSERT INTO gpkg_geometry_columns VALUES ('endless', 'geom', 'POINT', 0, 0, 0);
             CREATE VIEW endless AS WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 \
             FROM n) SELECT i AS fid, NULL AS geom FROM n WHERE i < 0;"
        ),
    );
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(true));
    let err = quick(|| {
        crate::cancel::cancellable(flag, || read(&path, "h.gpkg", Some("endless"), usize::MAX))
    });
    let err = err.err().unwrap().to_string();
    assert!(err.contains("reading cancelled"), "{err}");
}

#[test]
fn a_write_ahead_log_geopackage_is_read_without_writing_beside_it() {
    // M4: QGIS leaves GeoPackages in WAL mode; reading one created `-wal` and `-shm` files.
    let dir = tempfile::tempdir().unwrap();
    let path = geopackage(
        dir.path(),
        &format!(
            "{COLUMNS} INSERT INTO gpkg_geometry_columns VALUES ('points', 'geom', 'POINT', 0, 0, 0);
             PRAGMA journal_mode = WAL;"
        ),
    );
    let beside = |suffix: &str| dir.path().join(format!("hostile.gpkg{suffix}"));
    assert!(!beside("-wal").exists() && !beside("-shm").exists());
    let read = read(&path, "h.gpkg", None, 1000).unwrap();
    assert_eq!(read.points, vec![[1.0, 2.0]]);
    assert!(!beside("-wal").exists() && !beside("-shm").exists());
}
