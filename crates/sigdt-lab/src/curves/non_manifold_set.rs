//! The `non-manifold` labelled set (`data/non-manifold`): seeded random drawings of every
//! [`DrawingKind`] sampled with shared junctions, a pure function of the seeds.
//!
//! Drawing `i` of kind `k` (both from 0) starts from seed `1000 (k + 1) + i` and moves on in
//! steps of 100 until the drawing has a junction (two blobs can miss each other). Its spacing
//! is drawn from 1.5 % to 4 % of the diagonal, and its points are shuffled with the seed.
//!
//! # Complexity
//! O(cases) drawings of O(1) segments each.
use std::fmt::Write as _;

use sigdt::samplers::Rng;
use sigdt::Result;

use super::{
    random_drawing, sample_with_junctions, to_svg, BezierPath, DrawingKind, JunctionSample,
};

/// Drawings per kind in `data/non-manifold`.
pub const PER_KIND: usize = 8;

/// One generated case.
#[derive(Debug, Clone, PartialEq)]
pub struct NonManifoldCase {
    /// `nm_KIND_II`.
    pub name: String,
    /// The drawing's kind.
    pub kind: DrawingKind,
    /// The seed of the drawing, its spacing and its point order.
    pub seed: u64,
    /// The spacing of the samples, a fraction of the drawing's diagonal.
    pub spacing: f64,
    /// The drawing.
    pub drawing: Vec<BezierPath>,
    /// The sample (points shuffled) and its junction counts.
    pub junctions: JunctionSample,
}

/// `per_kind` cases of every kind, kinds in [`DrawingKind::ALL`] order.
///
/// # Errors
/// None in practice: the drawings are valid by construction; an error of
/// [`sample_with_junctions`] is passed on.
pub fn non_manifold_cases(per_kind: usize) -> Result<Vec<NonManifoldCase>> {
    let mut cases = Vec::new();
    for (k, kind) in DrawingKind::ALL.into_iter().enumerate() {
        for i in 0..per_kind {
            let mut seed = 1_000 * (k as u64 + 1) + i as u64;
            loop {
                let spacing = 0.015 + 0.025 * Rng::new(seed ^ 0x5A5A).uniform();
                let drawing = random_drawing(kind, seed);
                let mut junctions = sample_with_junctions(&drawing, spacing)?;
                if junctions.crossings + junctions.tees + junctions.shared_ends > 0 {
                    junctions.sample = junctions.sample.shuffled(seed);
                    let name = format!("nm_{}_{i:02}", kind.name());
                    cases.push(NonManifoldCase { name, kind, seed, spacing, drawing, junctions });
                    break;
                }
                seed += 100;
            }
        }
    }
    Ok(cases)
}

/// Every file of the folder of `cases`: name and contents. `NAME.svg` the drawing, `NAME.xy`
/// the points, `NAME.gt` the ground truth and `index.csv` with the junction counts.
pub fn folder_files(cases: &[NonManifoldCase]) -> Vec<(String, String)> {
    let mut index = String::from(
        "name,category,n_points,n_edges,epsilon,spacing,crossings,tees,shared_ends,source\n",
    );
    let mut files = Vec::new();
    for case in cases {
        let (name, kind, seed) = (&case.name, case.kind.name(), case.seed);
        let comment = format!(
            "sigdt random non-manifold drawing: kind {kind}, seed {seed} (the project's own, \
             MIT OR Apache-2.0)"
        );
        files.push((format!("{name}.svg"), to_svg(&case.drawing, &comment)));
        let sample = &case.junctions.sample;
        let mut xy = String::new();
        for [x, y] in &sample.points {
            writeln!(xy, "{x:?} {y:?}").expect("writing to a String");
        }
        files.push((format!("{name}.xy"), xy));
        let mut gt = String::new();
        for [a, b] in &sample.edges {
            writeln!(gt, "{a} {b}").expect("writing to a String");
        }
        files.push((format!("{name}.gt"), gt));
        let j = &case.junctions;
        writeln!(
            index,
            "{name},non-manifold,{},{},,{:.4},{},{},{},random:{kind}:{seed}",
            sample.points.len(),
            sample.edges.len(),
            case.spacing,
            j.crossings,
            j.tees,
            j.shared_ends,
        )
        .expect("writing to a String");
    }
    files.push(("index.csv".to_string(), index));
    files
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_case_has_a_junction_and_vertices_of_degree_three_or_more() {
        let cases = non_manifold_cases(2).unwrap();
        assert_eq!(cases.len(), 2 * DrawingKind::ALL.len());
        for case in &cases {
            let s = &case.junctions.sample;
            let mut degree = vec![0; s.points.len()];
            for &[i, j] in &s.edges {
                degree[i] += 1;
                degree[j] += 1;
            }
            assert!(degree.iter().any(|&d| d >= 3), "{}", case.name);
            assert!(degree.iter().all(|&d| (1..=4).contains(&d)), "{}", case.name);
        }
        assert_eq!(non_manifold_cases(2).unwrap(), cases, "a pure function of the seeds");
    }
}
