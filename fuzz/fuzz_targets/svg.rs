//! Arbitrary bytes (as text) through the SVG path reader of `sigdt sample`: `Ok` or an
//! `Err` naming a line of the input, never a panic; every curve read has finite control
//! points and at least one segment, and a closed curve ends where it starts.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt_lab::curves::parse_svg_paths;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match parse_svg_paths(&text, "fuzz.svg") {
        Ok(curves) => {
            for curve in &curves {
                assert!(!curve.segments.is_empty(), "a curve without segments");
                let all = curve.segments.iter().flatten().flatten();
                assert!(all.clone().all(|v| v.is_finite()), "a non-finite control point");
                for pair in curve.segments.windows(2) {
                    assert_eq!(pair[0][3], pair[1][0], "segments do not join");
                }
                if curve.closed {
                    let (first, last) = (curve.segments[0][0], curve.segments.last().unwrap()[3]);
                    assert_eq!(first, last, "a closed curve that does not close");
                }
            }
        }
        Err(sigdt::Error::Parse { line, .. }) => {
            assert!(line >= 1 && line <= 1 + text.matches('\n').count(), "line {line} is not in the input");
        }
        Err(e) => panic!("not a parse error: {e}"),
    }
});
