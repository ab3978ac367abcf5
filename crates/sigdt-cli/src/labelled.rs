//! Labelled samples: points with their ground truth (and clean positions when noisy), how
//! `sample` and `sweep` make them from SVG paths, and how they are written as files.
//!
//! Shared by the generating commands; it imports no command.

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use sigdt::samplers::{self, Sample};
use sigdt::{Edge, Point};
use sigdt_lab::curves::{self, BezierPath};

use crate::output::Output;

/// A labelled sample: points, ground truth, and the clean positions when noise was added.
pub struct Labelled {
    /// The (possibly noisy) points.
    pub points: Vec<Point>,
    /// Ground-truth edges.
    pub gt: Vec<Edge>,
    /// Clean positions, same indices, if `points` are noisy.
    pub truth: Option<Vec<Point>>,
    /// The curve the points were sampled from, densely, when known: distances and areas are
    /// then measured against it rather than against the ground-truth polygon.
    pub curve: Option<Sample>,
}

/// Path `k` of `paths`, read from `file`.
pub fn pick<'a>(paths: &'a [BezierPath], k: usize, file: &Path) -> Result<&'a BezierPath> {
    match paths.get(k) {
        Some(p) => Ok(p),
        None if paths.is_empty() => bail!("{}: no <path> with curve data", file.display()),
        None => bail!("{}: --path {k}, but the file has {} path(s)", file.display(), paths.len()),
    }
}

/// An eps-sample of `path` from `offset`, optionally with lfs noise, shuffled if asked.
pub fn eps_sample(
    path: &BezierPath,
    eps: f64,
    offset: f64,
    lfs_noise: Option<f64>,
    seed: u64,
    shuffle: bool,
) -> Result<Labelled> {
    let framed = curves::eps_sample_with_frames(path, eps, offset)?;
    let clean = framed.sample;
    let noisy = match lfs_noise {
        Some(delta) => {
            Some(samplers::lfs_noise(&clean.points, &framed.normals, &framed.lfs, delta, seed)?)
        }
        None => None,
    };
    let order = |s: Sample| if shuffle { s.shuffled(seed) } else { s };
    let edges = clean.edges.clone();
    let truth = order(clean);
    Ok(match noisy {
        None => Labelled { points: truth.points, gt: truth.edges, truth: None, curve: None },
        Some(points) => {
            // The same seed gives the same permutation for the same length.
            let noisy = order(Sample { points, edges });
            Labelled {
                points: noisy.points,
                gt: noisy.edges,
                truth: Some(truth.points),
                curve: None,
            }
        }
    })
}

/// Writes `OUT.xy`, `OUT.gt`, for noisy points `OUT.truth.xy` and, with a known curve,
/// `OUT.curve.xy` and `OUT.curve.gt`, each atomically. All are checked before any is
/// written; none may be `source`, the file read.
pub fn write_labelled(out: &Path, labelled: &Labelled, source: &Path) -> Result<()> {
    let with = |ext: &str| -> PathBuf {
        let stem = out.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        out.with_file_name(format!("{stem}.{ext}"))
    };
    if out.extension().is_none_or(|e| e == "gt") {
        bail!(
            "{}: the output needs an extension such as .xy (the ground truth goes to .gt)",
            out.display()
        );
    }
    let points = Output::new(Some(out), source)?;
    let gt = Output::new(Some(&with("gt")), source)?;
    let truth = match &labelled.truth {
        Some(clean) => Some((Output::new(Some(&with("truth.xy")), source)?, clean)),
        None => None,
    };
    let curve = match &labelled.curve {
        Some(curve) => Some((
            Output::new(Some(&with("curve.xy")), source)?,
            Output::new(Some(&with("curve.gt")), source)?,
            curve,
        )),
        None => None,
    };
    points.write(|w| w.write_all(points_text(&labelled.points).as_bytes()))?;
    gt.write(|w| sigdt_io::text::write_edges(w, &labelled.gt))?;
    if let Some((output, truth)) = truth {
        output.write(|w| w.write_all(points_text(truth).as_bytes()))?;
    }
    if let Some((points, edges, curve)) = curve {
        points.write(|w| w.write_all(points_text(&curve.points).as_bytes()))?;
        edges.write(|w| sigdt_io::text::write_edges(w, &curve.edges))?;
    }
    Ok(())
}

/// `x y` lines, shortest decimals that read back to the same numbers.
pub fn points_text(points: &[Point]) -> String {
    let mut text = String::with_capacity(40 * points.len());
    for [x, y] in points {
        text.push_str(&format!("{x:?} {y:?}\n"));
    }
    text
}
