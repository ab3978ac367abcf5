//! The edge file reader: one edge a line, two point indices `i j` (ground-truth files).

use std::fs::File;
use std::io::{BufRead, BufReader};
use std::path::Path;

use super::lines::{max_lines, pair, quoted, Lines};
use sigdt::Edge;
use sigdt::{Error, Result};

/// Reads the edges of the file at `path`; see [`parse_edges`].
pub fn read_edges(path: &Path) -> Result<Vec<Edge>> {
    read_edges_of(path, usize::MAX)
}

/// [`read_edges`] of a graph on `points` points; see [`parse_edges_of`].
pub fn read_edges_of(path: &Path, points: usize) -> Result<Vec<Edge>> {
    let name = path.display().to_string();
    let file = File::open(path).map_err(|source| Error::Io { path: name.clone(), source })?;
    parse_edges_of(BufReader::with_capacity(1 << 16, file), &name, points)
}

/// Parses edges `i j`, one a line (separated like plain points), as `[min, max]` pairs in
/// file order. Indices are non-negative integers; an edge from a point to itself is an error.
pub fn parse_edges<R: BufRead>(reader: R, name: &str) -> Result<Vec<Edge>> {
    parse_edges_of(reader, name, usize::MAX)
}

/// [`parse_edges`] of a graph on `points` points: an index of `points` or more is an error
/// naming its line, and so is a line past the `3 · points` edges that a graph without
/// crossings (a ground truth, a reconstruction) can have at most, so an endless stream is
/// refused after that many lines.
///
/// ```
/// use sigdt_io::text::parse_edges_of;
/// assert_eq!(parse_edges_of("0 1\n2 1\n".as_bytes(), "t.gt", 3).unwrap(), [[0, 1], [1, 2]]);
/// let err = parse_edges_of("0 1\n1 3\n".as_bytes(), "t.gt", 3).unwrap_err();
/// assert_eq!(err.to_string(), "t.gt:2: edge 1 3 refers to point 3, but there are 3 points");
/// ```
pub fn parse_edges_of<R: BufRead>(reader: R, name: &str, points: usize) -> Result<Vec<Edge>> {
    let most = points.saturating_mul(3);
    let mut lines = Lines::new(reader, name).at_most_lines(max_lines(most));
    let mut edges = Vec::new();
    while let Some(line) = lines.next_content()? {
        let [i, j] = edge(line).map_err(|message| lines.error(message))?;
        if j >= points {
            let message =
                format!("edge {i} {j} refers to point {j}, but there are {points} points");
            return Err(lines.error(message));
        }
        if edges.len() == most {
            let message = format!(
                "more than the {most} edges a graph without crossings on {points} points can have"
            );
            return Err(lines.error(message));
        }
        edges.push([i, j]);
    }
    Ok(edges)
}

/// An edge line: exactly two distinct non-negative integers, returned as `[min, max]`.
fn edge(line: &str) -> Result<Edge, String> {
    let index = |field: &str| {
        let not_index = format!("{} is not a point index (a non-negative integer)", quoted(field));
        field.parse::<usize>().map_err(|_| not_index)
    };
    match pair(line, "indices (i j)", index)? {
        [i, j] if i == j => Err(format!("edge {i} {j} joins a point to itself")),
        [i, j] => Ok([i.min(j), i.max(j)]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::read::lines::tests::error;

    #[test]
    fn edges_and_their_errors() {
        let edges = |text: &str| parse_edges(text.as_bytes(), "t.xy");
        assert_eq!(edges("# gt\n0 1\r\n3\t2\n\n5,4\n").unwrap(), vec![[0, 1], [2, 3], [4, 5]]);
        assert!(edges("").unwrap().is_empty());
        let msg = "is not a point index (a non-negative integer)";
        assert_eq!(error(edges("0 1\n-1 2\n")), format!("2: '-1' {msg}"));
        assert_eq!(error(edges("1.0 2\n")), format!("1: '1.0' {msg}"));
        assert_eq!(error(edges("0 1 2\n")), "1: expected 2 indices (i j), found 3");
        assert_eq!(error(edges("4 4\n")), "1: edge 4 4 joins a point to itself");
    }

    /// An endless stream of the line `0 1`.
    struct Endless(usize);
    impl std::io::Read for Endless {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            for b in buf.iter_mut() {
                *b = b"0 1\n"[self.0 % 4];
                self.0 += 1;
            }
            Ok(buf.len())
        }
    }

    #[test]
    fn a_graph_on_n_points_has_bounded_indices_and_length() {
        let of = |text: &str, n| parse_edges_of(text.as_bytes(), "t.xy", n);
        assert_eq!(of("0 1\n1 2\n0 2\n", 3).unwrap(), vec![[0, 1], [1, 2], [0, 2]]);
        let far = "2: edge 0 5 refers to point 5, but there are 5 points";
        assert_eq!(error(of("0 1\n5 0\n", 5)), far);
        let six = "7: more than the 6 edges a graph without crossings on 2 points can have";
        assert_eq!(error(of(&"0 1\n".repeat(7), 2)), six);
        // An endless stream stops at the first line past 3n edges.
        let endless = parse_edges_of(std::io::BufReader::new(Endless(0)), "t.xy", 1000);
        assert!(error(endless).starts_with("3001: more than the 3000 edges"));
    }
}
