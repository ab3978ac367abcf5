//! Readers for point files (plain `x y` and Dey's `.gtn`) and edge files (`i j`).
//!
//! Input is streamed line by line through a reused buffer, so memory stays bounded by the
//! longest line, which is capped at [`MAX_LINE`] bytes. Everywhere, blank lines are skipped,
//! `#` starts a comment that runs to the end of the line, and `\r\n` line endings are
//! accepted. Every problem is an [`Error::Parse`] naming the file and the 1-based line.
//!
//! - **Plain**: one point a line, two numbers separated by spaces or tabs, or by one comma
//!   with optional spaces around it (`1.5 2`, `1.5,2`, `1.5, 2`). The first line may be a
//!   header if none of its fields is a number (`x,y`).
//! - **Gtn** (Dey's CurveRecon): a header `N 2 0 0`, then exactly `N` lines `index x y`
//!   with indices `0, 1, ..., N-1` in order.
//! - **Edges**: one edge a line, two point indices `i j` (ground-truth files).

use std::fs::File;
use std::io::{BufRead, BufReader, ErrorKind};
use std::path::Path;

use crate::{Edge, Error, Point, Result};

/// The longest line a reader accepts, in bytes (1 MiB), not counting the line ending.
pub const MAX_LINE: usize = 1 << 20;

/// A point file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointFormat {
    /// One point a line: `x y`, `x<TAB>y` or `x,y`, with an optional header line.
    Plain,
    /// Dey's CurveRecon format: a header `N 2 0 0`, then `N` lines `index x y`.
    Gtn,
}

impl PointFormat {
    /// The format implied by the file extension (case-insensitive): `.gtn` is
    /// [`Gtn`](Self::Gtn); `.xy`, `.txt`, `.csv`, `.p2d` and `.pts` are [`Plain`](Self::Plain);
    /// anything else is `None`, and readers then detect the format from the content.
    pub fn from_path(path: &Path) -> Option<PointFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "gtn" => Some(PointFormat::Gtn),
            "xy" | "txt" | "csv" | "p2d" | "pts" => Some(PointFormat::Plain),
            _ => None,
        }
    }
}

/// Reads the points of the file at `path`, in the format given by its extension
/// ([`PointFormat::from_path`]) or else detected from its content.
pub fn read_points(path: &Path) -> Result<Vec<Point>> {
    let name = path.display().to_string();
    let file = File::open(path).map_err(|source| Error::Io { path: name.clone(), source })?;
    parse_points(BufReader::with_capacity(1 << 16, file), &name, PointFormat::from_path(path))
}

/// Parses points from `reader` in `format`, or, with `None`, in the format detected from the
/// first line with content: `.gtn` if it has exactly four integers and the second is 2,
/// plain otherwise. `name` is the file name shown in errors (a path or `<stdin>`).
///
/// Empty input gives no points, except in the `.gtn` format, which needs its header.
///
/// ```
/// use sigdt::io::parse_points;
/// let points = parse_points("x,y\n0,0\n1.5, 2 # a comment\n".as_bytes(), "<stdin>", None);
/// assert_eq!(points.unwrap(), vec![[0.0, 0.0], [1.5, 2.0]]);
/// ```
pub fn parse_points<R: BufRead>(
    reader: R,
    name: &str,
    format: Option<PointFormat>,
) -> Result<Vec<Point>> {
    let mut lines = Lines::new(reader, name);
    let format = match format {
        Some(format) => format,
        None => match lines.next_content()? {
            Some(line) if is_gtn_header(line) => PointFormat::Gtn,
            _ => PointFormat::Plain,
        },
    };
    lines.unread();
    match format {
        PointFormat::Plain => plain(&mut lines),
        PointFormat::Gtn => gtn(&mut lines),
    }
}

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

/// Plain points: two numbers a line; the first line with content may be a header.
fn plain<R: BufRead>(lines: &mut Lines<R>) -> Result<Vec<Point>> {
    let mut points = Vec::new();
    let mut first = true;
    while let Some(line) = lines.next_content()? {
        let point = match xy(line) {
            Ok(p) => Ok(Some(p)),
            Err(_) if first && is_header(line) => Ok(None),
            Err(message) => Err(message),
        };
        first = false;
        points.extend(point.map_err(|message| lines.error(message))?);
    }
    Ok(points)
}

/// Gtn points: the header `N 2 0 0`, then `N` lines `index x y`.
fn gtn<R: BufRead>(lines: &mut Lines<R>) -> Result<Vec<Point>> {
    let Some(header) = lines.next_content()? else {
        return Err(lines.error("missing .gtn header 'N 2 0 0'".to_string()));
    };
    let n = gtn_header(header).map_err(|message| lines.error(message))?;
    // The header is untrusted: reserve at most 1M points up front.
    let mut points = Vec::with_capacity(n.min(1 << 20));
    while let Some(line) = lines.next_content()? {
        if points.len() == n {
            let first_extra = lines.number;
            let m = n + 1 + lines.count_rest()?;
            lines.number = first_extra;
            return Err(lines.error(format!("header says {n} points, file has {m}")));
        }
        points.push(gtn_point(line, points.len()).map_err(|message| lines.error(message))?);
    }
    if points.len() < n {
        return Err(lines.error(format!("header says {n} points, file has {}", points.len())));
    }
    Ok(points)
}

/// Whether `line` looks like a gtn header: exactly four integers, the second being 2.
fn is_gtn_header(line: &str) -> bool {
    line.split_ascii_whitespace().count() == 4 && gtn_header(line).is_ok()
}

/// The point count `N` of a gtn header `N 2 0 0` (trailing tokens must be integers).
fn gtn_header(line: &str) -> Result<usize, String> {
    let (mut n, mut count) = (0, 0);
    for token in line.split_ascii_whitespace() {
        let v: i64 = token
            .parse()
            .map_err(|_| format!("gtn header: '{token}' is not an integer (expected 'N 2 0 0')"))?;
        match count {
            0 => {
                n = usize::try_from(v)
                    .map_err(|_| format!("gtn header: point count '{token}' is negative"))?
            }
            1 if v != 2 => return Err(format!("gtn header: dimension must be 2, found {token}")),
            _ => {}
        }
        count += 1;
    }
    if count < 2 {
        return Err(format!("gtn header: expected 'N 2 0 0', found {count} number(s)"));
    }
    Ok(n)
}

/// A gtn point line `index x y`, whose index must be `expected`.
fn gtn_point(line: &str, expected: usize) -> Result<Point, String> {
    let mut p = [0.0; 2];
    let mut count = 0;
    for token in line.split_ascii_whitespace() {
        match count {
            0 => match token.parse::<usize>() {
                Ok(index) if index == expected => {}
                Ok(index) => return Err(format!("expected point index {expected}, found {index}")),
                Err(_) => return Err(format!("'{token}' is not a point index")),
            },
            1 | 2 => p[count - 1] = coordinate(token)?,
            _ => {}
        }
        count += 1;
    }
    if count != 3 {
        return Err(format!("expected 3 numbers (index x y), found {count}"));
    }
    Ok(p)
}

/// A plain point line: exactly two finite numbers.
fn xy(line: &str) -> Result<Point, String> {
    pair(line, "numbers (x y)", coordinate)
}

/// An edge line: exactly two distinct non-negative integers, returned as `[min, max]`.
fn edge(line: &str) -> Result<Edge, String> {
    let index = |field: &str| {
        let not_index = format!("'{field}' is not a point index (a non-negative integer)");
        field.parse::<usize>().map_err(|_| not_index)
    };
    match pair(line, "indices (i j)", index)? {
        [i, j] if i == j => Err(format!("edge {i} {j} joins a point to itself")),
        [i, j] => Ok([i.min(j), i.max(j)]),
    }
}

/// Exactly two fields of `line`, each read by `read`; `what` names them in errors.
fn pair<T: Copy + Default>(
    line: &str,
    what: &str,
    read: impl Fn(&str) -> Result<T, String>,
) -> Result<[T; 2], String> {
    let (mut pair, mut count) = ([T::default(); 2], 0);
    for field in fields(line) {
        let v = read(field)?;
        if let Some(slot) = pair.get_mut(count) {
            *slot = v;
        }
        count += 1;
    }
    if count != 2 {
        return Err(format!("expected 2 {what}, found {count}"));
    }
    Ok(pair)
}

/// A finite coordinate. Rust's parser accepts `nan` and `inf`, which are rejected here.
fn coordinate(field: &str) -> Result<f64, String> {
    match field.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!("coordinate '{field}' is not finite")),
        Err(_) if field.is_empty() => Err("empty field between commas".to_string()),
        Err(_) => Err(format!("'{field}' is not a number")),
    }
}

/// Whether a plain line is a header: none of its fields is a number.
fn is_header(line: &str) -> bool {
    fields(line).all(|field| field.parse::<f64>().is_err())
}

/// The fields of a plain line: comma-separated (each trimmed) if it has a comma, else
/// separated by runs of spaces and tabs.
fn fields(line: &str) -> impl Iterator<Item = &str> {
    let comma = line.contains(',');
    let by_comma = comma.then(|| line.split(',').map(str::trim_ascii));
    let by_space = (!comma).then(|| line.split_ascii_whitespace());
    by_comma.into_iter().flatten().chain(by_space.into_iter().flatten())
}

/// Lines of a stream, read into one reused buffer of at most [`MAX_LINE`] bytes.
struct Lines<'a, R> {
    reader: R,
    name: &'a str,
    buf: Vec<u8>,
    /// The byte range of the current line's content: comment and outer whitespace removed.
    content: std::ops::Range<usize>,
    /// 1-based number of the current line (0 before the first).
    number: usize,
    /// Whether the next call to `next_content` returns the current line again.
    unread: bool,
}

impl<'a, R: BufRead> Lines<'a, R> {
    fn new(reader: R, name: &'a str) -> Self {
        let buf = Vec::with_capacity(256);
        Lines { reader, name, buf, content: 0..0, number: 0, unread: false }
    }

    /// The next line with content, without its comment and outer whitespace; `None` at the
    /// end. Only the content must be valid UTF-8.
    fn next_content(&mut self) -> Result<Option<&str>> {
        if !self.unread {
            loop {
                if !self.read_line()? {
                    return Ok(None);
                }
                self.content = content(&self.buf, self.number == 1);
                if !self.content.is_empty() {
                    break;
                }
            }
        }
        self.unread = false;
        match std::str::from_utf8(&self.buf[self.content.clone()]) {
            Ok(line) => Ok(Some(line)),
            Err(_) => Err(self.error("line is not valid UTF-8".to_string())),
        }
    }

    /// Makes the next `next_content` return the current line again (if there is one).
    fn unread(&mut self) {
        self.unread = self.number > 0 && !self.content.is_empty();
    }

    /// The number of lines with content left, without checking them.
    fn count_rest(&mut self) -> Result<usize> {
        let mut count = 0;
        while self.read_line()? {
            count += usize::from(!content(&self.buf, false).is_empty());
        }
        Ok(count)
    }

    /// Reads the next line into `buf`, without its `\n`; false at the end of input. Stops
    /// with an error, before buffering it, as soon as a line exceeds [`MAX_LINE`] bytes.
    fn read_line(&mut self) -> Result<bool> {
        self.buf.clear();
        let mut any = false;
        loop {
            let chunk = match self.reader.fill_buf() {
                Ok(chunk) => chunk,
                Err(e) if e.kind() == ErrorKind::Interrupted => continue,
                Err(source) => return Err(Error::Io { path: self.name.to_string(), source }),
            };
            if chunk.is_empty() {
                break;
            }
            any = true;
            let (len, newline) = match chunk.iter().position(|&b| b == b'\n') {
                Some(len) => (len, true),
                None => (chunk.len(), false),
            };
            if self.buf.len() + len > MAX_LINE {
                self.number += 1;
                return Err(self.error(format!("line longer than {MAX_LINE} bytes")));
            }
            self.buf.extend_from_slice(&chunk[..len]);
            self.reader.consume(len + usize::from(newline));
            if newline {
                break;
            }
        }
        self.number += usize::from(any);
        Ok(any)
    }

    /// A parse error on the current line (line 1 if nothing was read).
    fn error(&self, message: String) -> Error {
        Error::Parse { path: self.name.to_string(), line: self.number.max(1), message }
    }
}

/// The range of `line` without its `#` comment, outer ASCII whitespace (including `\r`) and,
/// on the first line, a UTF-8 byte-order mark. Both ends fall on character boundaries.
fn content(line: &[u8], first: bool) -> std::ops::Range<usize> {
    let start = if first && line.starts_with(b"\xEF\xBB\xBF") { 3 } else { 0 };
    let end = line.iter().position(|&b| b == b'#').unwrap_or(line.len()).max(start);
    let body = &line[start..end];
    let lead = body.iter().take_while(|b| b.is_ascii_whitespace()).count();
    let trail = body[lead..].iter().rev().take_while(|b| b.is_ascii_whitespace()).count();
    start + lead..end - trail
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read;

    fn parse(text: &str, format: Option<PointFormat>) -> Result<Vec<Point>> {
        parse_points(text.as_bytes(), "t.xy", format)
    }

    /// The `line: message` of a parse error.
    fn error(result: Result<impl std::fmt::Debug>) -> String {
        match result.unwrap_err() {
            Error::Parse { path, line, message } if path == "t.xy" => format!("{line}: {message}"),
            e => panic!("not a parse error: {e}"),
        }
    }

    #[test]
    fn plain_separators_comments_header_crlf() {
        let text =
            "\u{feff}# made by hand\r\nx, y\r\n\r\n1.5 2\r\n-3\t4e1 # trailing\n5,6\n 7 , -0.0 \n";
        let expected = vec![[1.5, 2.0], [-3.0, 40.0], [5.0, 6.0], [7.0, -0.0]];
        assert_eq!(parse(text, None).unwrap(), expected);
        assert_eq!(parse(text, Some(PointFormat::Plain)).unwrap(), expected);
        assert!(parse("x y\n", None).unwrap().is_empty());
        assert!(parse("", None).unwrap().is_empty());
        assert!(parse("\n  \n# only a comment\n", None).unwrap().is_empty());
    }

    #[test]
    fn errors_name_line_and_token() {
        use PointFormat::Gtn;
        let header = "gtn header: expected 'N 2 0 0', found 1 number(s)";
        let cases = [
            ("0 0\nx y\n", None, "2: 'x' is not a number"),
            ("x 1\n", None, "1: 'x' is not a number"),
            ("\n1 abc\n", None, "2: 'abc' is not a number"),
            ("1 2 3\n", None, "1: expected 2 numbers (x y), found 3"),
            ("3 2 0\n", None, "1: expected 2 numbers (x y), found 3"),
            ("1\n", None, "1: expected 2 numbers (x y), found 1"),
            ("1,,2\n", None, "1: empty field between commas"),
            ("1 2\nnan 0\n", None, "2: coordinate 'nan' is not finite"),
            ("0 -inf\n", None, "1: coordinate '-inf' is not finite"),
            ("", Some(Gtn), "1: missing .gtn header 'N 2 0 0'"),
            ("2 3 0 0\n", Some(Gtn), "1: gtn header: dimension must be 2, found 3"),
            ("-1 2 0 0\n", Some(Gtn), "1: gtn header: point count '-1' is negative"),
            ("2 2 x 0\n", Some(Gtn), "1: gtn header: 'x' is not an integer (expected 'N 2 0 0')"),
            ("7\n", Some(Gtn), &format!("1: {header}")),
            ("2 2 0 0\n0 0 0\n2 1 1\n", None, "3: expected point index 1, found 2"),
            ("1 2 0 0\nx 0 0\n", Some(Gtn), "2: 'x' is not a point index"),
            ("1 2 0 0\n0 0\n", None, "2: expected 3 numbers (index x y), found 2"),
            ("1 2 0 0\n0 0 inf\n", None, "2: coordinate 'inf' is not finite"),
            ("3 2 0 0\n0 0 0\n1 1 1\n\n", None, "4: header says 3 points, file has 2"),
            ("1 2 0 0\n0 0 0\n1 1 1\n\n2 2 2\n", None, "3: header says 1 points, file has 3"),
        ];
        for (text, format, expected) in cases {
            assert_eq!(error(parse(text, format)), expected, "{text:?}");
        }
        let latin1 = parse_points(&b"0 0\n1 \xE9\n"[..], "t.xy", None);
        assert_eq!(error(latin1), "2: line is not valid UTF-8");
        let comment = parse_points(&b"0 0 # caf\xE9\n"[..], "t.xy", None);
        assert_eq!(comment.unwrap(), vec![[0.0, 0.0]]);
    }

    #[test]
    fn gtn_padded_header_and_tabs() {
        let text = "     3 2 0 0\n0\t41.636364 3.636364\n     1\t41.7 3.6\r\n2 -1 1e2\n\n";
        let expected = vec![[41.636364, 3.636364], [41.7, 3.6], [-1.0, 100.0]];
        assert_eq!(parse(text, Some(PointFormat::Gtn)).unwrap(), expected);
        assert_eq!(parse(text, None).unwrap(), expected);
        assert!(parse("0 2 0 0\n", None).unwrap().is_empty());
    }

    #[test]
    fn formats_from_extensions() {
        let format = |name: &str| PointFormat::from_path(Path::new(name));
        assert_eq!(format("a/b.GTN"), Some(PointFormat::Gtn));
        for name in ["a.xy", "a.txt", "a.CSV", "a.p2d", "a.pts"] {
            assert_eq!(format(name), Some(PointFormat::Plain));
        }
        assert_eq!(format("a.dat"), None);
        assert_eq!(format("xy"), None);
    }

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

    /// A reader that counts the bytes taken from it.
    struct Counting<R>(R, usize);
    impl<R: Read> Read for Counting<R> {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            let n = self.0.read(buf)?;
            self.1 += n;
            Ok(n)
        }
    }

    #[test]
    fn long_lines_are_rejected_with_bounded_memory() {
        let two_mib = std::io::repeat(b'1').take(2 << 20);
        let reader = BufReader::new(two_mib);
        assert_eq!(error(parse_points(reader, "t.xy", None)), "1: line longer than 1048576 bytes");
        // An endless line: the reader stops right after the limit.
        let mut endless = Counting(std::io::repeat(b'1'), 0);
        let result = parse_edges(BufReader::new(&mut endless), "t.xy");
        assert_eq!(error(result), "1: line longer than 1048576 bytes");
        assert!(endless.1 <= MAX_LINE + (64 << 10));
        // Exactly at the limit is fine.
        let mut line = vec![b' '; MAX_LINE - 3];
        line.extend_from_slice(b"1 2\n3 4");
        assert_eq!(parse_points(&line[..], "t.xy", None).unwrap(), vec![[1.0, 2.0], [3.0, 4.0]]);
    }

    #[test]
    fn read_points_names_missing_files() {
        let err = read_points(Path::new("/nonexistent/p.xy")).unwrap_err();
        assert!(matches!(err, Error::Io { ref path, .. } if path == "/nonexistent/p.xy"));
    }
}
