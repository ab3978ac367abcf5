//! Point files in the formats people have, beside sigdt's own plain `x y` lines and `.gtn`
//! files (read by [`sigdt::io`]): WKT, GeoJSON, NumPy `.npy` arrays and CSV tables with
//! chosen columns, each also gzip-compressed (`.gz`, or found by its magic bytes).
//!
//! The format is chosen once, at the entry, in this order:
//! 1. gzip magic bytes: decompressed on the fly, and the name without `.gz` decides the rest;
//! 2. the `.npy` magic bytes: a NumPy array ([`npy`]);
//! 3. `--columns`: a table ([`table`]);
//! 4. the extension: `.wkt`, `.geojson` or `.json`, `.csv` or `.tsv` with more than two
//!    fields, `;` separators or quotes;
//! 5. the first character that is not white space: `{` or `[` is GeoJSON, a WKT keyword is
//!    WKT; anything else goes to [`sigdt::io`], which reads plain and `.gtn` files and
//!    refuses what it cannot read with the file and line.
//!
//! Every error names the file (and the line where there is one).

mod geojson;
mod npy;
mod table;
mod wkt;

use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use anyhow::{Context, Result};
use sigdt::io::PointFormat;
use sigdt::Point;

pub use table::Columns;

/// The gzip magic bytes.
const GZIP: &[u8] = &[0x1f, 0x8b];

/// How points are to be read: the limit on their number and the columns of a table.
#[derive(Debug, Clone, Copy)]
pub struct Reading<'a> {
    /// Reading stops with an error after this many points.
    pub max_points: usize,
    /// `--columns`: the x and y columns of a table.
    pub columns: Option<&'a Columns>,
}

/// The points of `reader`, named `name` in errors (a path or `<stdin>`); see the module docs.
pub fn points(reader: impl Read, name: &str, how: Reading<'_>) -> Result<Vec<Point>> {
    let mut reader = BufReader::with_capacity(1 << 16, reader);
    let head = reader.fill_buf().with_context(|| format!("{name}: cannot read"))?;
    if head.starts_with(GZIP) {
        let inner = name.strip_suffix(".gz").unwrap_or(name);
        let unzipped = flate2::read::MultiGzDecoder::new(reader);
        let mut unzipped = BufReader::with_capacity(1 << 16, unzipped);
        // A corrupt stream fails at its first read, with the file's name.
        unzipped.fill_buf().with_context(|| format!("{name}: not a valid gzip file"))?;
        return uncompressed(unzipped, name, inner, how);
    }
    uncompressed(reader, name, name, how)
}

/// [`points`] of an uncompressed stream; `shown` names it in errors, `inner` (the name
/// without `.gz`) gives the extension.
fn uncompressed<R: BufRead>(
    mut reader: R,
    shown: &str,
    inner: &str,
    how: Reading<'_>,
) -> Result<Vec<Point>> {
    let head = reader.fill_buf().with_context(|| format!("{shown}: cannot read"))?;
    if head.starts_with(npy::MAGIC) {
        return npy::read(reader, shown, how.max_points);
    }
    if let Some(columns) = how.columns {
        return table::read(reader, shown, Some(columns), how.max_points);
    }
    let extension = Path::new(inner)
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let first = first_content(head);
    match extension.as_str() {
        "wkt" => return wkt::read(reader, shown, how.max_points),
        "geojson" | "json" => return geojson::read(reader, shown, how.max_points),
        "csv" | "tsv" if table::is_table(first) => {
            return table::read(reader, shown, None, how.max_points);
        }
        _ => {}
    }
    if first.starts_with(['{', '[']) {
        return geojson::read(reader, shown, how.max_points);
    }
    if wkt::starts_wkt(first) {
        return wkt::read(reader, shown, how.max_points);
    }
    let format = PointFormat::from_path(Path::new(inner));
    Ok(sigdt::io::parse_points_at_most(reader, shown, format, how.max_points)?)
}

/// The first line of `head` with content: leading white space, a UTF-8 byte-order mark and
/// `#` comment lines skipped (as the plain reader does). Empty when the buffer holds none.
fn first_content(head: &[u8]) -> &str {
    let text = match std::str::from_utf8(head) {
        Ok(text) => text,
        // The buffer may end inside a character: keep the valid prefix.
        Err(e) => std::str::from_utf8(&head[..e.valid_up_to()]).unwrap_or_default(),
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.lines().map(str::trim).find(|l| !l.is_empty() && !l.starts_with('#')).unwrap_or("")
}

/// The error for more than `max` points.
fn too_many(name: &str, max: usize) -> anyhow::Error {
    anyhow::anyhow!("{name}: more than {max} points (raise --max-points to read more)")
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn read(bytes: &[u8], name: &str) -> Result<Vec<Point>> {
        points(bytes, name, Reading { max_points: 100, columns: None })
    }

    #[test]
    fn each_format_is_found_by_content_or_extension() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(read(b"0 0\n1 0\n1 1\n0 1\n", "a.xy").unwrap(), square);
        assert_eq!(read(b"MULTIPOINT (0 0, 1 0, 1 1, 0 1)", "a.txt").unwrap(), square);
        let json = br#"{"type": "MultiPoint", "coordinates": [[0,0],[1,0],[1,1],[0,1]]}"#;
        assert_eq!(read(json, "a").unwrap(), square);
        assert_eq!(read(b"x;y\n0;0\n1;0\n1;1\n0;1\n", "a.csv").unwrap(), square);
        let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        gz.write_all(b"# zipped\nPOINT (0 0)\nPOINT (1 0)\nPOINT (1 1)\nPOINT (0 1)\n").unwrap();
        assert_eq!(read(&gz.finish().unwrap(), "a.wkt.gz").unwrap(), square);
        let err = read(&[0x1f, 0x8b, 0, 1, 2, 3], "b.xy.gz").unwrap_err();
        assert!(format!("{err:#}").contains("b.xy.gz: not a valid gzip file"), "{err:#}");
    }

    #[test]
    fn the_first_content_skips_marks_comments_and_blank_lines() {
        assert_eq!(first_content("\u{feff}\n  # c\n\n {\"a\": 1}\n".as_bytes()), "{\"a\": 1}");
        assert_eq!(first_content(b""), "");
        assert_eq!(first_content(&[b'x', 0xe2, 0x82]), "x");
    }
}
