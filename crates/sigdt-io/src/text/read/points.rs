//! Readers for point files (plain `x y` and Dey's `.gtn`) and edge files (`i j`).
//!
//! Input is streamed: the edge and `.gtn` readers go line by line through a reused buffer,
//! the plain reader in batches of blocks of whole lines (parsed in parallel), so memory stays
//! bounded by a few MiB plus the longest line, which is capped at [`MAX_LINE`](super::lines::MAX_LINE) bytes.
//! Everywhere, blank lines are skipped, `#` starts a comment that runs to the end of the
//! line, and `\r\n` line endings are accepted. Every problem is an [`Error::Parse`] naming
//! the file and the 1-based line.
//!
//! - **Plain**: one point a line, two numbers separated by spaces or tabs, or by one comma
//!   with optional spaces around it (`1.5 2`, `1.5,2`, `1.5, 2`). The first line may be a
//!   header: a line of names (`x,y`), each with a letter and none starting like a number.
//! - **Gtn** (Dey's CurveRecon): a header `N 2 0 0`, then exactly `N` lines `index x y`
//!   with indices `0, 1, ..., N-1` in order.
//! - **Edges**: one edge a line, two point indices `i j` (ground-truth files).

use std::fs::File;
use std::io::{BufRead, BufReader};
use std::path::Path;

use super::gtn::{gtn, is_gtn_header};
use super::lines::{coordinate, fields, max_lines, pair, too_many, Block, Lines};
use rayon::prelude::*;
use sigdt::Point;
use sigdt::{Error, Result};

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

    /// The format of the file at `path` whose first line with content is `first_line`: by
    /// extension ([`PointFormat::from_path`]), else `.gtn` when that line is a gtn header
    /// (`N 2 0 0`), else plain, as [`parse_points`] decides it.
    ///
    /// ```
    /// use sigdt_io::text::PointFormat;
    /// use std::path::Path;
    /// assert_eq!(PointFormat::detect(Path::new("a"), "3 2 0 0"), PointFormat::Gtn);
    /// assert_eq!(PointFormat::detect(Path::new("a.xy"), "3 2 0 0"), PointFormat::Plain);
    /// assert_eq!(PointFormat::detect(Path::new("-"), "x,y"), PointFormat::Plain);
    /// ```
    pub fn detect(path: &Path, first_line: &str) -> PointFormat {
        match PointFormat::from_path(path) {
            Some(format) => format,
            None if is_gtn_header(first_line.trim()) => PointFormat::Gtn,
            None => PointFormat::Plain,
        }
    }
}

/// Reads the points of the file at `path`, in the format given by its extension
/// ([`PointFormat::from_path`]) or else detected from its content.
pub fn read_points(path: &Path) -> Result<Vec<Point>> {
    read_points_at_most(path, usize::MAX)
}

/// [`read_points`], refusing files with more than `max_points` points (see
/// [`parse_points_at_most`]).
pub fn read_points_at_most(path: &Path, max_points: usize) -> Result<Vec<Point>> {
    let name = path.display().to_string();
    let file = File::open(path).map_err(|source| Error::Io { path: name.clone(), source })?;
    let reader = BufReader::with_capacity(1 << 16, file);
    parse_points_at_most(reader, &name, PointFormat::from_path(path), max_points)
}

/// Parses points from `reader` in `format`, or, with `None`, in the format detected from the
/// first line with content: `.gtn` if it has exactly four integers and the second is 2,
/// plain otherwise. `name` is the file name shown in errors (a path or `<stdin>`).
///
/// Empty input gives no points, except in the `.gtn` format, which needs its header.
///
/// ```
/// use sigdt_io::text::parse_points;
/// let points = parse_points("x,y\n0,0\n1.5, 2 # a comment\n".as_bytes(), "<stdin>", None);
/// assert_eq!(points.unwrap(), vec![[0.0, 0.0], [1.5, 2.0]]);
/// ```
pub fn parse_points<R: BufRead>(
    reader: R,
    name: &str,
    format: Option<PointFormat>,
) -> Result<Vec<Point>> {
    parse_points_at_most(reader, name, format, usize::MAX)
}

/// [`parse_points`], stopping with an error naming the line as soon as the input has more
/// than `max_points` points (for `.gtn`, as soon as the header announces more), so that a
/// huge input is refused after reading at most `max_points` lines of it.
pub fn parse_points_at_most<R: BufRead>(
    reader: R,
    name: &str,
    format: Option<PointFormat>,
    max_points: usize,
) -> Result<Vec<Point>> {
    let mut lines = Lines::new(reader, name).at_most_lines(max_lines(max_points));
    let format = match format {
        Some(format) => format,
        None => match lines.next_content()? {
            Some(line) if is_gtn_header(line) => PointFormat::Gtn,
            _ => PointFormat::Plain,
        },
    };
    lines.unread();
    match format {
        PointFormat::Plain => plain(&mut lines, max_points),
        PointFormat::Gtn => gtn(&mut lines, max_points),
    }
}

/// Bytes of input per block of lines, and blocks read before they are parsed, in parallel.
const BLOCK: usize = 1 << 18;
const BATCH: usize = 16;

/// Plain points: two numbers a line; the first line with content may be a header. The
/// first line is read on its own; the rest in batches of [`BLOCK`]-byte blocks of whole
/// lines, each block parsed on its own (in parallel when the pool has several threads) and
/// the results joined in order, so points, errors and their line numbers are the same as
/// reading line by line.
fn plain<R: BufRead>(lines: &mut Lines<R>, max_points: usize) -> Result<Vec<Point>> {
    plain_in_blocks(lines, max_points, BLOCK, BATCH)
}

/// [`plain`] with blocks of `block` bytes, `batch` at a time.
fn plain_in_blocks<R: BufRead>(
    lines: &mut Lines<R>,
    max_points: usize,
    block: usize,
    batch: usize,
) -> Result<Vec<Point>> {
    let mut points = Vec::new();
    if let Some(line) = lines.next_content()? {
        match xy(line) {
            Ok(point) => points.push(point),
            Err(message) => match foreign_format(line) {
                Some(format) => {
                    return Err(lines.error(format!(
                        "this is {format}, not a point file: write one point per line ('x y' \
                         or 'x,y')"
                    )))
                }
                None if is_header(line) => {}
                None => return Err(lines.error(message)),
            },
        }
        if points.len() > max_points {
            return Err(lines.error(too_many(max_points)));
        }
    }
    loop {
        let mut blocks = Vec::with_capacity(batch);
        // A reading error comes after any problem on the lines read before it.
        let mut failed = None;
        while blocks.len() < batch {
            match lines.next_block(block) {
                Ok(Some(block)) => blocks.push(block),
                Ok(None) => break,
                Err(error) => {
                    failed = Some(error);
                    break;
                }
            }
        }
        if blocks.is_empty() {
            return failed.map_or(Ok(points), Err);
        }
        let room = max_points - points.len();
        // Each block a task of its own, on the current rayon pool (the same points at every
        // thread count).
        let parsed: Vec<_> =
            blocks.par_iter().with_max_len(1).map(|block| plain_block(block, room)).collect();
        for (block, (mut found, mut problem)) in blocks.iter().zip(parsed) {
            let room = max_points - points.len();
            if found.len() > room {
                // Earlier blocks left less room than this one was parsed with.
                (found, problem) = plain_block(block, room);
            }
            points.append(&mut found);
            if let Some((line, message)) = problem {
                let message = message.unwrap_or_else(|| too_many(max_points));
                return Err(lines.error_at(line, message));
            }
        }
        if let Some(error) = failed {
            return Err(error);
        }
    }
}

/// The points of one block, at most `room` of them, and the first problem: the line and
/// its message, or no message for a point past `room` (the error names the limit).
fn plain_block(block: &Block, room: usize) -> (Vec<Point>, Option<(usize, Option<String>)>) {
    let mut points = Vec::new();
    for line in block.contents() {
        let (number, text) = match line {
            Ok(line) => line,
            Err((number, message)) => return (points, Some((number, Some(message)))),
        };
        match xy(text) {
            Err(message) => return (points, Some((number, Some(message)))),
            Ok(_) if points.len() == room => return (points, Some((number, None))),
            Ok(point) => points.push(point),
        }
    }
    (points, None)
}

/// A plain point line: exactly two finite numbers.
fn xy(line: &str) -> Result<Point, String> {
    two_numbers(line).ok_or(()).or_else(|()| pair(line, "numbers (x y)", coordinate))
}

/// The common line, two finite numbers separated by spaces or tabs, read without splitting
/// it into fields; `None` for anything else, which [`pair`] then reads (or explains). What
/// this accepts, `pair` reads the same: a number has no white space, so the line is exactly
/// these two fields.
fn two_numbers(line: &str) -> Option<Point> {
    let gap = line.find([' ', '\t'])?;
    let (x, y) = (&line[..gap], line[gap..].trim_start_matches([' ', '\t']));
    let (x, y) = (x.parse::<f64>().ok()?, y.parse::<f64>().ok()?);
    (x.is_finite() && y.is_finite() && !line.contains(',')).then_some([x, y])
}

/// The geometry format a first line is written in, when it is one sigdt does not read:
/// GeoJSON (or other JSON) starts with `{` or `[`, WKT with a geometry keyword. Named in the
/// error, so that such a file is neither read as a header nor reported as a bad number.
fn foreign_format(line: &str) -> Option<String> {
    if line.starts_with(['{', '[']) {
        return Some("GeoJSON or other JSON".to_string());
    }
    wkt_geometry(line).map(|keyword| format!("WKT ({keyword})"))
}

/// The WKT geometry keywords, longest first (so that a prefix never matches early).
pub const WKT_GEOMETRIES: [&str; 7] = [
    "GEOMETRYCOLLECTION",
    "MULTIPOLYGON",
    "MULTILINESTRING",
    "MULTIPOINT",
    "POLYGON",
    "LINESTRING",
    "POINT",
];

/// The geometry keyword (upper case) of a line that starts a WKT geometry: a keyword of
/// [`WKT_GEOMETRIES`] in any case, an optional `Z`, `M` or `ZM`, then `(` or `EMPTY`; `None`
/// otherwise, so that a header such as `point x` is not taken for WKT. The plain reader
/// refuses such a file by name; the command line reads it.
///
/// ```
/// use sigdt_io::text::wkt_geometry;
/// assert_eq!(wkt_geometry("MultiPoint Z ((1 2 3))"), Some("MULTIPOINT"));
/// assert_eq!(wkt_geometry("point x"), None);
/// ```
pub fn wkt_geometry(line: &str) -> Option<&'static str> {
    let line = line.trim_start();
    let word: String = line.chars().take_while(char::is_ascii_alphabetic).collect();
    let keyword = WKT_GEOMETRIES.iter().find(|k| word.eq_ignore_ascii_case(k))?;
    let rest = line[word.len()..].trim_start().to_ascii_uppercase();
    let rest = ["ZM", "Z", "M"].iter().find_map(|d| rest.strip_prefix(d)).unwrap_or(&rest);
    let rest = rest.trim_start();
    (rest.starts_with('(') || rest.starts_with("EMPTY")).then_some(*keyword)
}

/// Whether a plain line is a header: a line of names. Every field has a letter and none
/// starts like a number (a digit of any script, or a sign or point before one), so that
/// `0x1p3`, `1_000` or full-width digits are errors, not a header that silently drops a
/// point.
fn is_header(line: &str) -> bool {
    fields(line).all(is_header_name)
}

/// Whether a field of a first line is a column name rather than a value: it has a letter and
/// does not start like a number (a digit of any script, or a sign or point before one). The
/// rule of the plain reader's header, shared with the CLI's tables.
///
/// ```
/// use sigdt_io::text::is_header_name;
/// assert!(is_header_name("lon") && is_header_name("X coordinate"));
/// assert!(!is_header_name("1.5") && !is_header_name("0x1p3") && !is_header_name("NaN"));
/// ```
pub fn is_header_name(field: &str) -> bool {
    let unsigned = field.trim_start_matches(['+', '-']).trim_start_matches('.');
    let numeric_start = unsigned.chars().next().is_some_and(char::is_numeric);
    field.chars().any(char::is_alphabetic) && !numeric_start && field.parse::<f64>().is_err()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::read::lines::tests::error;
    use crate::text::read::lines::MAX_LINE;

    fn parse(text: &str, format: Option<PointFormat>) -> Result<Vec<Point>> {
        parse_points(text.as_bytes(), "t.xy", format)
    }

    /// The plain reader one line at a time, as it was before blocks: the reference.
    fn plain_by_line(text: &[u8], max_points: usize, max_lines: usize) -> Result<Vec<Point>> {
        let mut lines = Lines::new(text, "t.xy").at_most_lines(max_lines);
        let mut points = Vec::new();
        let mut first = true;
        while let Some(line) = lines.next_content()? {
            let point = match xy(line) {
                Ok(p) => Ok(Some(p)),
                Err(message) if first => match foreign_format(line) {
                    Some(format) => Err(format!("this is {format}")),
                    None if is_header(line) => Ok(None),
                    None => Err(message),
                },
                Err(message) => Err(message),
            };
            first = false;
            points.extend(point.map_err(|message| lines.error(message))?);
            if points.len() > max_points {
                return Err(lines.error(too_many(max_points)));
            }
        }
        Ok(points)
    }

    #[test]
    fn blocks_read_what_lines_read() {
        // Random files of valid and broken lines, read in blocks of a few bytes (lines and
        // `\r\n` cut across blocks, several batches) with random point limits: the same
        // points, or the same error on the same line, as reading line by line.
        let pieces: [&[u8]; 12] = [
            b"1 2\n",
            b"-3.5,4e2\r\n",
            b"\n",
            b"  # note\n",
            b"5\t6 # x\n",
            b"7 8",
            b"9 x\n",
            b"1 2 3\n",
            b"0 nan\n",
            b"1 \xE9\n",
            b"1\x002\n",
            b"x y\n",
        ];
        let mut rng = sigdt::samplers::Rng::new(11);
        for case in 0..3000 {
            let lines = 1 + rng.below(40);
            let broken = rng.below(4) == 0;
            let mut text = Vec::new();
            for _ in 0..lines {
                // Mostly good lines; broken pieces in a quarter of the files.
                let k = if broken { rng.below(pieces.len()) } else { rng.below(6) };
                text.extend_from_slice(pieces[k]);
                if k == 5 {
                    text.push(b'\n'); // "7 8" then a line ending, unless last
                }
            }
            if rng.below(2) == 0 && text.last() == Some(&b'\n') {
                text.pop();
            }
            let max_points = if rng.below(3) == 0 { rng.below(lines + 1) } else { usize::MAX };
            let max_lines = if rng.below(3) == 0 { rng.below(lines + 2) } else { usize::MAX };
            let (block, batch) = (1 + rng.below(24), 1 + rng.below(4));
            let mut reader = Lines::new(&text[..], "t.xy").at_most_lines(max_lines);
            let got = plain_in_blocks(&mut reader, max_points, block, batch);
            let want = plain_by_line(&text, max_points, max_lines);
            let shown = |r: &Result<Vec<Point>>| match r {
                Ok(points) => format!("{points:?}"),
                Err(e) => e.to_string().split(": this is").next().unwrap().to_string(),
            };
            let text = String::from_utf8_lossy(&text);
            assert_eq!(shown(&got), shown(&want), "case {case}, {block}x{batch}: {text:?}");
        }
    }

    #[test]
    fn an_endless_stream_of_blank_lines_is_refused_after_the_line_limit() {
        // `yes ''` and `yes '#'`: no point ever counts towards the point limit. (A stream
        // a little longer than the limit stands in for an endless one.)
        let limit = max_lines(3);
        for line in [&b"\n"[..], b"#\n", b" \r\n"] {
            let long = line.repeat(limit + 10);
            let err = parse_points_at_most(&long[..], "yes", None, 3).unwrap_err();
            let want = format!("yes:{}: {}", limit + 1, super::super::lines::too_many_lines(limit));
            assert_eq!(err.to_string(), want);
        }
    }

    #[test]
    fn a_long_line_after_the_first_is_refused_with_bounded_reading() {
        let mut text = b"0 0\n1 1\n".to_vec();
        text.extend(std::iter::repeat_n(b'1', MAX_LINE + 1));
        text.extend_from_slice(b" 2\n3 3\n");
        assert_eq!(
            error(parse(std::str::from_utf8(&text).unwrap(), None)),
            "3: line longer than 1048576 bytes"
        );
        // At the limit it is a (bad) point, read whole.
        let mut text = b"0 0\n".to_vec();
        text.extend(std::iter::repeat_n(b'1', MAX_LINE - 2));
        text.extend_from_slice(b" 2\n");
        let e = error(parse(std::str::from_utf8(&text).unwrap(), None));
        assert!(e.starts_with("2: coordinate"), "{e}");
    }

    #[test]
    fn the_common_line_reads_as_the_general_one() {
        // Lines of random tokens and separators: where the short path answers, the general
        // one gives the same point.
        let tokens = ["1", "-2.5", "3e2", "nan", "inf", "1e999", ".5", "x", "", "0x1", "1,5"];
        let gaps = [" ", "\t", "  ", " \t ", ",", " , ", "\u{c}", "\u{a0}", ""];
        let mut rng = sigdt::samplers::Rng::new(2);
        let (mut short, mut cases) = (0, 0);
        for _ in 0..20_000 {
            let mut line = String::new();
            for k in 0..1 + rng.below(3) {
                if k > 0 {
                    line.push_str(gaps[rng.below(gaps.len())]);
                }
                line.push_str(tokens[rng.below(tokens.len())]);
            }
            let line = line.trim_ascii();
            cases += 1;
            if let Some(point) = two_numbers(line) {
                short += 1;
                assert_eq!(pair(line, "numbers (x y)", coordinate), Ok(point), "{line:?}");
            }
        }
        assert!(short > cases / 100, "the short path answered {short} of {cases}");
    }

    #[test]
    fn a_problem_before_a_long_line_comes_first() {
        let long = "1".repeat(MAX_LINE + 1);
        for (text, max, expected) in [
            (format!("0 0\n1 x\n{long}\n"), usize::MAX, "2: 'x' is not a number"),
            (format!("0 0\n1 1\n2 2\n{long}\n"), 2, format!("3: {}", too_many(2)).leak()),
            (format!("0 0\n1 1\n{long}\n1 x\n"), usize::MAX, "3: line longer than 1048576 bytes"),
        ] {
            let result = parse_points_at_most(text.as_bytes(), "t.xy", None, max);
            assert_eq!(error(result), expected);
        }
    }

    #[test]
    fn point_limit_names_the_first_line_over_it() {
        let text = "x y\n0 0\n1 0\n\n2 0\n3 0\n";
        assert_eq!(parse_points_at_most(text.as_bytes(), "t.xy", None, 4).unwrap().len(), 4);
        let err = parse_points_at_most(text.as_bytes(), "t.xy", None, 2).unwrap_err();
        assert_eq!(err.to_string(), format!("t.xy:5: {}", too_many(2)));
        let gtn = "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n";
        let err = parse_points_at_most(gtn.as_bytes(), "t.gtn", None, 2).unwrap_err();
        assert_eq!(err.to_string(), format!("t.gtn:1: {}", too_many(2)));
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
        ];
        for (text, format, expected) in cases {
            assert_eq!(error(parse(text, format)), expected, "{text:?}");
        }
        let latin1 = parse_points(&b"0 0\n1 \xE9\n"[..], "t.xy", None);
        let utf16 = parse_points(&b"0\x00 \x000\x00\n\x00"[..], "t.xy", None);
        assert!(error(utf16).starts_with("1: line has NUL bytes: UTF-16"));
        assert_eq!(error(latin1), "2: line is not valid UTF-8");
        let comment = parse_points(&b"0 0 # caf\xE9\n"[..], "t.xy", None);
        assert_eq!(comment.unwrap(), vec![[0.0, 0.0]]);
    }

    #[test]
    fn a_first_line_that_starts_like_a_number_is_an_error_not_a_header() {
        // Each would drop the first point silently if taken for a header.
        let cases = [
            ("0x1p3 2\n0 0\n", "1: '0x1p3' is not a number"),
            ("1_000 2_000\n0 0\n", "1: '1_000' is not a number"),
            ("\u{ff11} \u{ff12}\n0 0\n", "1: '\u{ff11}' is not a number"),
            ("-.5e 1\n0 0\n", "1: '-.5e' is not a number"),
            (
                "1.5;2.5\n0 0\n",
                "1: '1.5;2.5' is not a number: unsupported separator \\u{3b} \
                 (use spaces, tabs or one comma)",
            ),
        ];
        for (text, expected) in cases {
            assert_eq!(error(parse(text, None)), expected, "{text:?}");
        }
        for header in ["x y", "lon,lat", "X coordinate, Y coordinate", "x1 y1", "\u{3b1} \u{3b2}"] {
            let text = format!("{header}\n0 0\n");
            assert_eq!(parse(&text, None).unwrap(), vec![[0.0, 0.0]], "{header}");
        }
    }

    #[test]
    fn wkt_and_geojson_are_named_not_read_as_a_header_or_a_bad_number() {
        for (text, format) in [
            ("MULTIPOINT ((1 2), (3 4), (5 7))\n", "WKT (MULTIPOINT)"),
            ("point(1 2)\n", "WKT (POINT)"),
            ("POLYGON((0 0, 1 0, 1 1, 0 0))\n", "WKT (POLYGON)"),
            ("{\"type\":\"MultiPoint\",\"coordinates\":[[1,2],[3,4]]}\n", "GeoJSON or other JSON"),
            ("[[1, 2], [3, 4]]\n", "GeoJSON or other JSON"),
        ] {
            let e = error(parse(text, None));
            assert!(e.starts_with(&format!("1: this is {format}, not a point file")), "{e}");
        }
        // Headers that start with a WKT word stay headers.
        for header in ["points x", "point x", "Point,Y"] {
            assert_eq!(parse(&format!("{header}\n1 2\n"), None).unwrap(), vec![[1.0, 2.0]]);
        }
        let e = error(parse("POINT Z (1 2 3)\n", None));
        assert!(e.starts_with("1: this is WKT (POINT)"), "{e}");
    }

    #[test]
    fn messages_escape_what_the_input_could_use_against_a_terminal() {
        let nbsp = error(parse("1\u{a0}2\n", None));
        assert_eq!(
            nbsp,
            "1: '1\\u{a0}2' is not a number: unsupported separator \\u{a0} \
             (use spaces, tabs or one comma)"
        );
        let vt = error(parse("0 0\n1\u{b}2\n", None));
        assert!(vt.starts_with("2: '1\\u{b}2' is not a number: unsupported separator"), "{vt}");
        let escape = error(parse("0 0\n\u{1b}[2J\u{7} 1\n", None));
        assert_eq!(escape, "2: '\\u{1b}[2J\\u{7}' is not a number");
        assert!(!escape.contains('\u{1b}'));
        let long = error(parse(&format!("0 {}\n", "9".repeat(400) + "x"), None));
        assert_eq!(long, format!("1: '{}...' (401 characters) is not a number", "9".repeat(40)));
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
    fn read_points_names_missing_files() {
        let err = read_points(Path::new("/nonexistent/p.xy")).unwrap_err();
        assert!(matches!(err, Error::Io { ref path, .. } if path == "/nonexistent/p.xy"));
    }
}
