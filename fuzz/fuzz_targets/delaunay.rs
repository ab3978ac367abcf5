//! Arbitrary points (as in the `reconstruct` target) through `Triangulation::new` and spade's
//! insertion in the same order (`sigdt::internals::spade_reference`): the same error, the
//! same verdict (triangles or none), and for a proper triangulation the same vertex
//! positions, input indices, `triangles` and `halfedges`, bit for bit.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt::internals::{spade_reference, FlatArrays};
use sigdt::Triangulation;

fuzz_target!(|data: &[u8]| {
    let points = sigdt_fuzz::points(data);
    match (Triangulation::new(&points), spade_reference(&points)) {
        (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string()),
        (Ok(dt), Ok(None)) => assert_eq!(dt.num_triangles(), 0),
        (Ok(dt), Ok(Some(reference))) => assert_eq!(FlatArrays::of(&dt), reference),
        (a, b) => panic!("ours ok: {}, spade ok: {}", a.is_ok(), b.is_ok()),
    }
});
