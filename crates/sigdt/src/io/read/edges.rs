//! The edge file reader: one edge a line, two point indices `i j` (ground-truth files).

use std::fs::File;
use std::io::{BufRead, BufReader};
use std::path::Path;

use super::lines::{pair, quoted, Lines};
use crate::error::{Error, Result};
use crate::geometry::Edge;

/// Reads the edges of the file at `path`; see [`parse_edges`].
pub fn read_edges(path: &Path) -> Result<Vec<Edge>> {
    let name = path.display().to_string();
    let file = File::open(path).map_err(|source| Error::Io { path: name.clone(), source })?;
    parse_edges(BufReader::with_capacity(1 << 16, file), &name)
}

/// Parses edges `i j`, one a line (separated like plain points), as `[min, max]` pairs in
/// file order. Indices are non-negative integers; an edge from a point to itself is an error.
pub fn parse_edges<R: BufRead>(reader: R, name: &str) -> Result<Vec<Edge>> {
    let mut lines = Lines::new(reader, name);
    let mut edges = Vec::new();
    while let Some(line) = lines.next_content()? {
        edges.push(edge(line).map_err(|message| lines.error(message))?);
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
    use crate::io::read::lines::tests::error;

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
}
