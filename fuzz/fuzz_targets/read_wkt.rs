//! Arbitrary bytes as a `.wkt` file through the command line's reader
//! (`sigdt_io::read_points_bytes`, name `in.wkt`, at most 100 points): no panic; `Ok` gives
//! at most 100 finite points; an error is one line that names the file, holds no control
//! character and is at most 1000 characters (see `read_checks.rs` for the bound). Bytes that
//! start with the gzip magic are decompressed first.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "read_checks.rs"]
mod read_checks;

/// Messages of known findings (see `read_checks.rs`): none.
const KNOWN: &[&str] = &[];

fuzz_target!(|data: &[u8]| {
    read_checks::check(data, "in.wkt", None, KNOWN);
});
