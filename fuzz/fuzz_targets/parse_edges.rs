//! Arbitrary bytes through the edge-file reader: `Ok` or `Err`, never a panic. `Ok` edges
//! are `[i, j]` with `i < j`. Reading through a 1..8-byte buffer gives the same answer.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt::io::parse_edges;
use std::io::BufReader;

fuzz_target!(|data: &[u8]| {
    let capacity = 1 + data.first().map_or(0, |&b| b as usize % 8);
    let whole = parse_edges(data, "fuzz");
    if let Ok(edges) = &whole {
        assert!(edges.iter().all(|&[i, j]| i < j), "edge not [min, max]");
    }
    let chunked = parse_edges(BufReader::with_capacity(capacity, data), "fuzz");
    match (&whole, &chunked) {
        (Ok(a), Ok(b)) => assert_eq!(a, b, "chunked read differs"),
        (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string()),
        _ => panic!("chunked read differs: {whole:?} vs {chunked:?}"),
    }
});
