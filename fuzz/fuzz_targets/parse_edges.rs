//! Arbitrary bytes through the edge-file reader: `Ok` or `Err`, never a panic. `Ok` edges
//! are `[i, j]` with `i < j`. Reading through a 1..8-byte buffer gives the same answer.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt_io::text::{parse_edges, parse_edges_of};
use std::io::BufReader;

fuzz_target!(|data: &[u8]| {
    let capacity = 1 + data.first().map_or(0, |&b| b as usize % 8);
    let whole = parse_edges(data, "fuzz");
    if let Ok(edges) = &whole {
        assert!(edges.iter().all(|&[i, j]| i < j), "edge not [min, max]");
    }
    // For a graph on `n` points (from the second byte): indices below `n`, at most `3n`
    // edges, and otherwise the same edges as the unbounded reader.
    let n = data.get(1).map_or(0, |&b| b as usize);
    match parse_edges_of(data, "fuzz", n) {
        Ok(bounded) => {
            assert!(bounded.iter().all(|&[_, j]| j < n) && bounded.len() <= 3 * n);
            assert_eq!(Some(&bounded), whole.as_ref().ok(), "bounded read differs");
        }
        Err(e) => assert!(whole.is_err() || e.to_string().contains("fuzz:")),
    }
    let chunked = parse_edges(BufReader::with_capacity(capacity, data), "fuzz");
    match (&whole, &chunked) {
        (Ok(a), Ok(b)) => assert_eq!(a, b, "chunked read differs"),
        (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string()),
        _ => panic!("chunked read differs: {whole:?} vs {chunked:?}"),
    }
});
