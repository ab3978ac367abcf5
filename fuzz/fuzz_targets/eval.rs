//! Small point sets (as in the `reconstruct` target, at most 32 points) and arbitrary edge
//! lists (self loops, repeats, indices out of range) through the metrics:
//! `sigdt_lab::eval::evaluate`, `graph_epsilon` and `overlap`. Errors are fine, panics are not.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt_lab::eval::{evaluate, graph_epsilon, overlap};

fuzz_target!(|data: &[u8]| {
    let Some((points, result, gt)) = sigdt_fuzz::eval_input(data) else { return };
    let _ = evaluate(&points, &result, &gt);
    let _ = graph_epsilon(&points, &gt);
    let _ = overlap(&points, &gt);
});
