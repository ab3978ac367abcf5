//! Regular polygons: `k` points equally spaced on a circle.
use super::{cycle_edges, Sample};
use std::f64::consts::TAU;

/// Regular `k`-gon on a circle of radius `r` (`k` points), centred at the origin, first
/// vertex at angle 0, counter-clockwise.
pub fn regular_polygon(k: usize, r: f64) -> Sample {
    let points = (0..k)
        .map(|i| {
            let t = TAU * i as f64 / k as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    Sample { points, edges: cycle_edges(k) }
}
