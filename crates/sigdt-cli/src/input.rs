//! Reading what the commands are given: points from a file or standard input (at most
//! `--max-points` of them), ground-truth edges checked against the points, and the title
//! that pictures of the input show.

use std::io;
use std::path::Path;

use anyhow::Result;
use sigdt::{Edge, Point};

use crate::output::is_dash;

/// The settings every command's input reading shares, from the global flags.
#[derive(Debug, Clone, Copy)]
pub struct Input {
    /// `--max-points`: reading stops at the first line over it.
    max_points: usize,
}

impl Input {
    /// Input reading with at most `max_points` points.
    pub fn new(max_points: usize) -> Input {
        Input { max_points }
    }

    /// The points of `input`, a file or `-` for standard input.
    pub fn points(&self, input: &Path) -> Result<Vec<Point>> {
        let max = self.max_points;
        if is_dash(input) {
            Ok(sigdt::io::parse_points_at_most(io::stdin().lock(), "<stdin>", None, max)?)
        } else {
            Ok(sigdt::io::read_points_at_most(input, max)?)
        }
    }
}

/// The ground truth of `--gt`, if given, for `n` points: reading stops at the first index
/// past them or the first line past `3n` edges (an endless file is refused, not read whole).
pub fn ground_truth(path: Option<&Path>, n: usize) -> Result<Option<Vec<Edge>>> {
    let Some(path) = path else { return Ok(None) };
    Ok(Some(sigdt::io::read_edges_of(path, n)?))
}

/// The default title of a picture of `n` points read from `input`: its file stem (or
/// "standard input") and the count.
pub fn picture_title(input: &Path, n: usize) -> String {
    let name = if is_dash(input) {
        "standard input".to_string()
    } else {
        input
            .file_stem()
            .map_or_else(|| input.display().to_string(), |s| s.to_string_lossy().into_owned())
    };
    format!("{name} ({n} points)")
}
