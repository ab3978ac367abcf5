//! `sigdt sample` on arbitrary path data: the first byte picks ε in (0, 1], the second the
//! start offset, the rest is the `d` attribute of one `<path>`. The ε-sampler returns a
//! sample or an error, never a panic; a sample has finite points and its ground truth is
//! the path through them (closed: the cycle). Paths of more than 8 segments are skipped, and
//! the third byte picks the dense evaluation's density, 4 to 259 parameters a segment
//! (`sigdt sample` uses 1000): the same walk and medial axis at a rate that reaches 10⁷
//! runs.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt_lab::curves::{eps_sample_at_density, parse_svg_paths};

fuzz_target!(|data: &[u8]| {
    let [e, o, density, rest @ ..] = data else { return };
    let eps = (1 + *e as usize) as f64 / 256.0;
    let offset = *o as f64 / 256.0;
    let d = String::from_utf8_lossy(rest).replace(['"', '<', '>'], " ");
    let Ok(curves) = parse_svg_paths(&format!("<path d=\"{d}\"/>"), "fuzz.svg") else { return };
    let Some(curve) = curves.first().filter(|c| c.segments.len() <= 8) else { return };
    let density = 4 + *density as usize;
    if let Ok(framed) = eps_sample_at_density(curve, eps, offset, density) {
        let sample = framed.sample;
        let n = sample.points.len();
        assert!(sample.points.iter().flatten().all(|v| v.is_finite()), "non-finite sample");
        assert!(sample.edges.iter().all(|&[i, j]| i < j && j < n), "edge out of range");
        let expected = if curve.closed && n >= 3 { n } else { n.saturating_sub(1) };
        assert!(sample.edges.len() <= expected.max(n), "{} edges on {n} samples", sample.edges.len());
    }
});
