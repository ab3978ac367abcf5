//! Reading what the commands are given: points from a file or standard input (at most
//! `--max-points` of them), ground-truth edges checked against the points, and the title
//! that pictures of the input show.

use std::io;
use std::path::Path;

use anyhow::Result;
use sigdt::{Edge, Point};

use sigdt_io::gis::local::why_degrees;
use sigdt_io::{Columns, Crs, Points, ReadOptions};

use crate::output::is_dash;

/// The settings every command's input reading shares, from the global flags.
#[derive(Debug, Clone)]
pub struct Input {
    /// `--max-points`: reading stops at the first line over it.
    max_points: usize,
    /// `--columns`: the x and y columns of a table.
    columns: Option<Columns>,
    /// `--layer`: the layer of a GeoPackage.
    layer: Option<String>,
    /// `--crs`: the coordinate system of input that does not declare one.
    crs: Option<Crs>,
}

impl Input {
    /// Input reading with at most `max_points` points, from `columns` of a table if given.
    pub fn new(max_points: usize, columns: Option<Columns>) -> Input {
        Input { max_points, columns, layer: None, crs: None }
    }

    /// Reading `layer` of a GeoPackage, and input in `crs` unless it says otherwise.
    pub fn with_gis(self, layer: Option<String>, crs: Option<Crs>) -> Input {
        Input { layer, crs, ..self }
    }

    /// The points of `input`, a file or `-` for standard input, in any format of
    /// [`sigdt_io::read`].
    pub fn points(&self, input: &Path) -> Result<Vec<Point>> {
        Ok(self.points_and_how(input)?.points)
    }

    /// [`Input::points`] for a command that works in the plane of the coordinates, with a
    /// warning on stderr when they are longitude and latitude (only `reconstruct` uses a
    /// local plane for those).
    pub fn plane_points(&self, input: &Path, command: &str) -> Result<Vec<Point>> {
        let read = self.points_and_how(input)?;
        if let Some(why) = why_degrees(read.crs.as_ref(), read.lon_lat) {
            crate::messages::note(&format!(
                "sigdt: warning: {why}, but `{command}` works in the plane of the \
                 coordinates: its lengths depend on the latitude (`reconstruct` uses a local \
                 plane)"
            ));
        }
        Ok(read.points)
    }

    /// [`Input::points`], and how they were read (the format; a table's columns).
    pub fn points_and_how(&self, input: &Path) -> Result<Points> {
        self.points_grouped(input, None)
    }

    /// [`Input::points_and_how`], grouped `by` an attribute column when given (`--by`).
    pub fn points_grouped(&self, input: &Path, by: Option<&str>) -> Result<Points> {
        let options = ReadOptions {
            max_points: self.max_points,
            columns: self.columns.clone(),
            layer: self.layer.clone(),
            crs: self.crs.clone(),
            by: by.map(str::to_string),
        };
        match is_dash(input) {
            true => sigdt_io::read_stream(io::stdin().lock(), "<stdin>", &options),
            false => sigdt_io::read_file(input, &options),
        }
    }
}

/// The points of the file at `path`, in any format the commands read, without a limit: how
/// `bench`, `gallery` and `sweep` read case files, so that a case may be gzipped or WKT like
/// any input.
pub fn points_of_file(path: &Path) -> Result<Vec<Point>> {
    Input::new(usize::MAX, None).points(path)
}

/// The ground truth of `--gt`, if given, for `n` points (see [`edges_of`]).
pub fn ground_truth(path: Option<&Path>, n: usize) -> Result<Option<Vec<Edge>>> {
    path.map(|path| edges_of(path, n, "--gt")).transpose()
}

/// The edges of the file `path` given as `flag`, for `n` points: reading stops at the first
/// index past them or the first line past `3n` edges (an endless file is refused, not read
/// whole). An index past the points is bad data in that file (exit status 1), named with the
/// flag, the file and the line.
pub fn edges_of(path: &Path, n: usize, flag: &str) -> Result<Vec<Edge>> {
    sigdt_io::text::read_edges_of(path, n).map_err(|err| match &err {
        sigdt::Error::Parse { message, .. } if is_index_past_the_points(message) => {
            anyhow::anyhow!("{flag} {err}: it is not a graph on the {n} input points")
        }
        _ => err.into(),
    })
}

/// Whether a parse message of [`sigdt_io::text::read_edges_of`] is about an index past the points.
fn is_index_past_the_points(message: &str) -> bool {
    message.starts_with("edge ") && message.contains(" refers to point ")
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_index_past_the_points_is_bad_data_named_with_the_flag() {
        // Issue 30: a file whose content is wrong is bad data (exit 1), not bad usage.
        let dir = tempfile::tempdir().unwrap();
        let gt = dir.path().join("t.gt");
        std::fs::write(&gt, "0 1\n1 7\n").unwrap();
        let message = edges_of(&gt, 3, "--gt").unwrap_err().to_string();
        assert!(message.starts_with("--gt "), "{message}");
        assert!(message.contains("t.gt:2: edge 1 7 refers to point 7, but there are 3 points"));
    }
}
