//! Arbitrary SQLite files through the GeoPackage reader (`sigdt_io::read_geopackage_bytes`,
//! name `in.gpkg`, at most 100 points, a small query budget): no panic, no hang (views that
//! never end stop on the budget), and the checks of `read_checks.rs` on the answer. The
//! seeds (`fuzz/seeds/read_gpkg/`, `tools/gpkg-fuzz-seeds.py`) are one file per finding:
//! endless layer lists, layers and systems, sorting views, feature views, write-ahead-log
//! mode, triggers, a missing system.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "read_checks.rs"]
mod read_checks;

fuzz_target!(|data: &[u8]| {
    read_checks::check_result(
        sigdt_io::read_geopackage_bytes(data, "in.gpkg", read_checks::MAX_POINTS),
        "in.gpkg",
        &[],
    );
});
