//! Arbitrary points (raw f64 bits, or structured degenerate sets; see `sigdt_fuzz`) through
//! `sigdt::reconstruct` with every method, and leaf elimination on and off for
//! SIG-CONNECT2D (the only method that reads it), and SIG-AUTO told to expect areas as
//! well. Either every method fails with the same
//! error, or every result passes `sigdt::internals::check_reconstruction`. The traced run of
//! the inflating methods returns the same reconstruction.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt::internals::check_reconstruction;
use sigdt::{reconstruct, reconstruct_traced, Expect, Method, Options};

fuzz_target!(|data: &[u8]| {
    let points = sigdt_fuzz::points(data);
    for &method in Method::ALL {
        for (leaf_elimination, expect) in
            [(true, Expect::Curves), (false, Expect::Curves), (true, Expect::Areas)]
        {
            if !leaf_elimination && method != Method::SigConnect2d {
                continue;
            }
            if expect == Expect::Areas && method != Method::SigAuto {
                continue;
            }
            let options = Options { method, leaf_elimination, expect };
            let rec = match reconstruct(&points, &options) {
                Ok(rec) => rec,
                Err(e) => {
                    // Validation happens before any method runs.
                    assert_eq!(method, Method::ALL[0], "{method} failed alone: {e}");
                    return;
                }
            };
            if let Err(why) = check_reconstruction(&points, &rec) {
                panic!("{method} (leaf elimination {leaf_elimination}, {expect}): {why}");
            }
            if matches!(method, Method::SigConnect2d | Method::Connect2d) {
                let (traced, _) = reconstruct_traced(&points, &options).expect("validated");
                assert_eq!(traced, rec, "{method}: the traced run differs");
            }
        }
    }
});
