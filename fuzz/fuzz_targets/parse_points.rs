//! Arbitrary bytes through the point-file reader, with every format hint: `Ok` or `Err`,
//! never a panic. `Ok` points are finite. Reading through a 1..8-byte buffer (lines split
//! across many `fill_buf` chunks) gives the same answer as reading the slice at once.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt_io::text::{parse_points, PointFormat};
use std::io::BufReader;

fuzz_target!(|data: &[u8]| {
    let capacity = 1 + data.first().map_or(0, |&b| b as usize % 8);
    for format in [None, Some(PointFormat::Plain), Some(PointFormat::Gtn)] {
        let whole = parse_points(data, "fuzz", format);
        if let Ok(points) = &whole {
            assert!(points.iter().flatten().all(|c| c.is_finite()), "non-finite point parsed");
        }
        let chunked = parse_points(BufReader::with_capacity(capacity, data), "fuzz", format);
        match (&whole, &chunked) {
            (Ok(a), Ok(b)) => assert_eq!(a, b, "{format:?}: chunked read differs"),
            (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{format:?}"),
            _ => panic!("{format:?}: chunked read differs: {whole:?} vs {chunked:?}"),
        }
    }
});
