//! The FlatGeobuf magic bytes (`fgb\x03fgb\x00`) and then arbitrary bytes through the command line's reader
//! (`sigdt_io::read_points_bytes`, name `in.fgb`, at most 100 points): no panic, no
//! allocation a size field asks for before its bytes arrive; `Ok` gives at most 100 finite
//! points; an error is one line that names the file, holds no control character and is at
//! most 1000 characters (see `read_checks.rs`). Bytes that already start with the magic,
//! such as the seeds (whole files), are read as they are.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "read_checks.rs"]
mod read_checks;

/// Messages of known findings (see `read_checks.rs`): none.
const KNOWN: &[&str] = &[];

const MAGIC: &[u8] = b"fgb\x03fgb\x00";

fuzz_target!(|data: &[u8]| {
    let bytes = if data.starts_with(MAGIC) { data.to_vec() } else { [MAGIC, data].concat() };
    read_checks::check(&bytes, "in.fgb", None, KNOWN);
});
