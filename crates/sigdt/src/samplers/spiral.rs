//! The spiral band: a long thin coiled closed curve, the hard case for Delaunay insertion
//! order.
use super::arc_length::Cumulative;
use super::{cycle_edges, Sample};
use std::f64::consts::PI;

/// A "spiral band": a closed curve that winds out along an Archimedean spiral and back along
/// a parallel spiral just outside it, closed by two semicircular caps, like a coiled ribbon.
///
/// In units of the band width `w`: the inner edge is `r = 2 + θ/π` for `θ ∈ [0, 2π·T]`
/// (pitch 2, so the gap between neighbouring windings is ≈ `w`), the outer edge is 1 further
/// out, and the caps have radius 1/2. The number of turns `T` (real, → `sqrt(n / 16π)` for
/// large `n`: 3.4 for `n = 1000`, 12.9 for `10⁴`, 140 for `10⁶`) is chosen so that the `n`
/// samples, equally spaced in arc length, are `w/4` apart (within 0.6%); then `ρ ≤ 1/2`
/// everywhere (the local feature size is ≈ `w/2`). For `n < 13` there are no turns: the
/// sample is a circle of diameter `w`. The result is scaled into the unit disk. This is the
/// hard case for Delaunay insertion order: many long thin, nearly cocircular triangles.
pub fn spiral_band(n: usize) -> Sample {
    const R0: f64 = 2.0;
    // r grows by C per radian: pitch 2π·C = 2 band widths.
    const C: f64 = 1.0 / PI;
    // Length n/4 ≈ ∫ (r_in + r_out) dθ + π = B·end + C·end² + π with B = 2·R0 + 1: solve.
    let (b, excess) = (2.0 * R0 + 1.0, (n as f64 / 4.0 - PI).max(0.0));
    let end = ((b * b + 4.0 * C * excess).sqrt() - b) / (2.0 * C); // θ at the far cap
    let inner = Cumulative::new(|t: f64| (R0 + C * t).hypot(C), 0.0, end);
    let outer = Cumulative::new(|t: f64| (R0 + 1.0 + C * t).hypot(C), 0.0, end);
    let (len_in, len_out, len_cap) = (inner.total(), outer.total(), 0.5 * PI);
    let length = len_in + len_out + 2.0 * len_cap;
    let polar = |r: f64, t: f64| [r * t.cos(), r * t.sin()];
    // A cap from the inner to the outer edge at angle t, bulging along `side` (±1 = ±tangent).
    let cap = |t: f64, alpha: f64, side: f64| {
        let (radial, tangent) = ([t.cos(), t.sin()], [-side * t.sin(), side * t.cos()]);
        let (c, s) = (-0.5 * alpha.cos(), 0.5 * alpha.sin());
        let centre = R0 + 0.5 + C * t;
        [0, 1].map(|d| centre * radial[d] + c * radial[d] + s * tangent[d])
    };
    let scale = 1.0 / (R0 + 1.5 + C * end);
    let points = (0..n)
        .map(|i| {
            let s = length * i as f64 / n as f64;
            let p = if s < len_in {
                let t = inner.inverse(s);
                polar(R0 + C * t, t)
            } else if s < len_in + len_cap {
                cap(end, 2.0 * (s - len_in), 1.0)
            } else if s < len_in + len_cap + len_out {
                let t = outer.inverse(len_out - (s - len_in - len_cap));
                polar(R0 + 1.0 + C * t, t)
            } else {
                cap(0.0, PI - 2.0 * (s - len_in - len_cap - len_out), -1.0)
            };
            p.map(|x| x * scale)
        })
        .collect();
    Sample { points, edges: cycle_edges(n) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{distance, segments_cross};
    use crate::samplers::tests::{gaps, max_ratio};

    #[test]
    fn spiral_band_is_simple_and_well_sampled() {
        let sample = spiral_band(1000);
        let (p, n, g) = (&sample.points, 1000, gaps(&sample));
        let spacing = g.iter().sum::<f64>() / n as f64;
        assert!(max_ratio(&g) < 1.02);
        for (a, &[i, j]) in sample.edges.iter().enumerate() {
            for &[k, l] in &sample.edges[a + 1..] {
                let disjoint = i != k && i != l && j != k && j != l;
                assert!(!disjoint || !segments_cross(p[i], p[j], p[k], p[l]), "{i}-{j} x {k}-{l}");
            }
            for k in (0..n).filter(|&k| (2..n - 1).contains(&((i + n - k) % n))) {
                assert!(distance(p[i], p[k]) > 1.5 * spacing, "{i} {k}");
            }
        }
    }
}
