//! Points from Well-Known Text (OGC Simple Features): every vertex of the geometries, in
//! order, as points.
//!
//! A file holds one or more geometries, separated by white space, new lines or commas:
//! `POINT`, `MULTIPOINT` (with or without parentheses around each point), `LINESTRING`,
//! `POLYGON`, `MULTILINESTRING`, `MULTIPOLYGON` and `GEOMETRYCOLLECTION`, each possibly
//! `EMPTY`, with `Z`, `M` or `ZM` coordinates (only x and y are kept), keywords in any case,
//! and an optional EWKT `SRID=n;` prefix. A polygon ring's closing vertex repeats its first
//! and is dropped, so a ring of `k + 1` coordinates gives `k` points. `#` starts a comment
//! to the end of the line, as in sigdt's plain files, and a UTF-8 byte-order mark may
//! start the file. Only ASCII white space separates, as in plain files: any other
//! character, such as a no-break space (U+00A0), belongs to a token and is refused with it.
//!
//! # Errors
//! The file and the line of the first token that does not fit, saying what was expected;
//! input is shown through [`crate::text::quoted`] (control characters escaped, long tokens
//! cut). Also refused, with the file and line: a token that is not UTF-8 text (comments are
//! not checked), a token longer than [`MAX_LINE`] bytes, `GEOMETRYCOLLECTION`s nested more
//! than [`MAX_DEPTH`] deep, and a failed read. More than `max_points` points stop the
//! reading at the first point over.
//!
//! # Complexity
//! O(length of the text) time. The text is streamed, token by token: memory is the points
//! plus the longest token (at most [`MAX_LINE`] bytes), however long the text or its lines.

use std::io::{BufRead, ErrorKind};

use crate::text::{quoted, wkt_geometry, MAX_LINE, WKT_GEOMETRIES};
use anyhow::{anyhow, Result};
use sigdt::Point;

/// The deepest nesting of `GEOMETRYCOLLECTION`s read, as deep as the GeoJSON reader (and
/// serde_json) goes: the parser recurses once a level, and the stack is finite.
const MAX_DEPTH: usize = 128;

/// The UTF-8 byte-order mark.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Whether `line` starts like WKT: an EWKT `SRID=` prefix, or a geometry as the kernel's
/// reader recognises it ([`crate::text::wkt_geometry`]).
pub fn starts_wkt(line: &str) -> bool {
    let line = line.trim_start();
    line.get(..5).is_some_and(|p| p.eq_ignore_ascii_case("SRID=")) || wkt_geometry(line).is_some()
}

/// The points of the WKT text of `reader`; see the module docs.
pub fn read(reader: impl BufRead, name: &str, max_points: usize) -> Result<Vec<Point>> {
    let tokens = Tokens::new(reader, name)?;
    let mut parser = Parser { tokens, points: Vec::new(), max_points, depth: 0 };
    while parser.peek().is_some() {
        parser.geometry()?;
        parser.eat(",")?;
    }
    Ok(parser.points)
}

/// The error for a failed read on line `line` of `name`.
fn read_error(name: &str, line: usize, e: std::io::Error) -> anyhow::Error {
    anyhow!("{name}:{line}: WKT: cannot read: {e}")
}

/// Whether `byte` ends a word: ASCII white space, a comment or a symbol.
fn ends_word(byte: u8) -> bool {
    byte.is_ascii_whitespace() || byte == b'#' || is_symbol(byte)
}

/// Whether `byte` is a token by itself: `(`, `)`, `,`, or `;`/`=` of an SRID prefix.
fn is_symbol(byte: u8) -> bool {
    matches!(byte, b'(' | b')' | b',' | b';' | b'=')
}

/// The tokens of a WKT text, read from the stream as the parser asks for them: only the
/// current one is held. A token is a word (a keyword or a number) or a symbol.
struct Tokens<'a, R> {
    reader: R,
    name: &'a str,
    /// The current token; empty at the end of the text.
    token: String,
    /// The line of the current token (of the last one at the end).
    line: usize,
    /// The line the reader is on.
    reader_line: usize,
    /// Whether nothing has been read yet: a byte-order mark may come.
    at_start: bool,
    /// Whether the reader has reported the end: it is not asked again (a terminal would wait
    /// for a second end-of-file).
    eof: bool,
}

impl<'a, R: BufRead> Tokens<'a, R> {
    /// The tokens of `reader`, on the first one.
    fn new(reader: R, name: &'a str) -> Result<Self> {
        let token = String::new();
        let mut tokens =
            Tokens { reader, name, token, line: 1, reader_line: 1, at_start: true, eof: false };
        tokens.advance()?;
        Ok(tokens)
    }

    /// The current token; `None` at the end of the text.
    fn current(&self) -> Option<&str> {
        (!self.token.is_empty()).then_some(self.token.as_str())
    }

    /// An error on the current token's line.
    fn error(&self, message: impl std::fmt::Display) -> anyhow::Error {
        anyhow!("{}:{}: WKT: {message}", self.name, self.line)
    }

    /// Moves to the next token.
    fn advance(&mut self) -> Result<()> {
        // The current token's buffer is reused: no allocation a token.
        let mut bytes = std::mem::take(&mut self.token).into_bytes();
        loop {
            bytes.clear();
            self.skip_separators()?;
            let at_start = self.at_start;
            self.read_token(&mut bytes)?;
            if at_start && bytes.starts_with(BOM) {
                bytes.drain(..BOM.len());
            }
            // Empty only at the end, or after a lone byte-order mark.
            if !bytes.is_empty() || self.eof {
                break;
            }
        }
        self.token = String::from_utf8(bytes).map_err(|_| self.error("not UTF-8 text"))?;
        Ok(())
    }

    /// Skips white space and comments, counting lines. More than [`MAX_LINE`] bytes of them
    /// in a row is refused, so that an endless stream of them (`yes ''`) ends.
    fn skip_separators(&mut self) -> Result<()> {
        let mut in_comment = false;
        let mut skipped = 0;
        loop {
            if skipped > MAX_LINE {
                let message = format!("more than {MAX_LINE} bytes of white space and comments");
                return Err(anyhow!("{}:{}: WKT: {message}", self.name, self.reader_line));
            }
            let chunk = self.fill()?;
            let (mut used, mut newlines, mut found) = (0, 0, false);
            for &byte in chunk {
                match byte {
                    b'\n' => (newlines, in_comment) = (newlines + 1, false),
                    b'#' => in_comment = true,
                    _ if in_comment || byte.is_ascii_whitespace() => {}
                    _ => {
                        // A token starts here.
                        (found, self.line) = (true, self.reader_line + newlines);
                        break;
                    }
                }
                used += 1;
            }
            self.consume(used);
            self.reader_line += newlines;
            skipped += used;
            if found || self.eof {
                return Ok(());
            }
        }
    }

    /// Reads the token that starts here into `bytes` (nothing at the end), refusing one
    /// longer than [`MAX_LINE`] before it is held.
    fn read_token(&mut self, bytes: &mut Vec<u8>) -> Result<()> {
        loop {
            let chunk = self.fill()?;
            if chunk.is_empty() {
                return Ok(());
            }
            if bytes.is_empty() && is_symbol(chunk[0]) {
                bytes.push(chunk[0]);
                self.consume(1);
                return Ok(());
            }
            let word = chunk.iter().position(|&b| ends_word(b)).unwrap_or(chunk.len());
            let ended = word < chunk.len();
            if bytes.len() + word > MAX_LINE {
                return Err(self.error(format!("token longer than {MAX_LINE} bytes")));
            }
            bytes.extend_from_slice(&chunk[..word]);
            self.consume(word);
            if ended {
                return Ok(());
            }
        }
    }

    /// The reader's buffered bytes, refilled if empty; empty at the end.
    fn fill(&mut self) -> Result<&[u8]> {
        if self.eof {
            return Ok(&[]);
        }
        loop {
            match self.reader.fill_buf() {
                Ok([]) => {
                    self.eof = true;
                    return Ok(&[]);
                }
                Ok(_) => break,
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                Err(e) => return Err(read_error(self.name, self.reader_line, e)),
            }
        }
        // Again, to return the bytes (the borrow checker refuses returning them from the
        // loop); a non-empty buffer is returned without reading.
        let (name, line) = (self.name, self.reader_line);
        self.reader.fill_buf().map_err(|e| read_error(name, line, e))
    }

    fn consume(&mut self, amount: usize) {
        self.reader.consume(amount);
        self.at_start &= amount == 0;
    }
}

struct Parser<'a, R> {
    tokens: Tokens<'a, R>,
    points: Vec<Point>,
    max_points: usize,
    /// How many `GEOMETRYCOLLECTION`s are open.
    depth: usize,
}

impl<R: BufRead> Parser<'_, R> {
    fn peek(&self) -> Option<&str> {
        self.tokens.current()
    }

    fn error(&self, expected: &str) -> anyhow::Error {
        match self.peek() {
            Some(t) => self.tokens.error(format!("expected {expected}, found {}", quoted(t))),
            None => self.tokens.error(format!("expected {expected}, found the end")),
        }
    }

    fn expect(&mut self, symbol: &str) -> Result<()> {
        if self.peek() == Some(symbol) {
            self.tokens.advance()
        } else {
            Err(self.error(&format!("'{symbol}'")))
        }
    }

    /// Consumes `symbol` (in any case) if it is next.
    fn eat(&mut self, symbol: &str) -> Result<bool> {
        let next = self.peek().is_some_and(|t| t.eq_ignore_ascii_case(symbol));
        if next {
            self.tokens.advance()?;
        }
        Ok(next)
    }

    /// `[SRID=n;] KEYWORD [Z|M|ZM] (EMPTY | body)`.
    fn geometry(&mut self) -> Result<()> {
        if self.eat("SRID")? {
            self.expect("=")?;
            if self.peek().is_none_or(|t| t.parse::<u32>().is_err()) {
                return Err(self.error("an SRID number"));
            }
            self.tokens.advance()?;
            self.expect(";")?;
        }
        let keyword = self
            .peek()
            .and_then(|t| WKT_GEOMETRIES.iter().find(|k| t.eq_ignore_ascii_case(k)).copied());
        let Some(keyword) = keyword else {
            return Err(self.error("a WKT geometry (POINT, MULTIPOINT, LINESTRING, POLYGON, ...)"));
        };
        self.tokens.advance()?;
        for dimension in ["ZM", "Z", "M"] {
            if self.eat(dimension)? {
                break;
            }
        }
        if self.eat("EMPTY")? {
            return Ok(());
        }
        match keyword {
            "POINT" => self.parenthesised(Self::coordinate),
            "MULTIPOINT" => self.list(|p| {
                if p.peek() == Some("(") {
                    p.parenthesised(Self::coordinate)
                } else {
                    p.coordinate()
                }
            }),
            "LINESTRING" => self.list(Self::coordinate),
            "POLYGON" => self.list(Self::ring),
            "MULTILINESTRING" => self.list(|p| p.list(Self::coordinate)),
            "MULTIPOLYGON" => self.list(|p| p.list(Self::ring)),
            _ => self.collection(),
        }
    }

    /// The body of a `GEOMETRYCOLLECTION`: `( geometry {, geometry} )`, at most
    /// [`MAX_DEPTH`] deep.
    fn collection(&mut self) -> Result<()> {
        if self.depth == MAX_DEPTH {
            let message = format!("GEOMETRYCOLLECTION nested more than {MAX_DEPTH} deep");
            return Err(self.tokens.error(message));
        }
        self.depth += 1;
        self.list(Self::geometry)?;
        self.depth -= 1;
        Ok(())
    }

    /// `( item )`.
    fn parenthesised(&mut self, item: fn(&mut Self) -> Result<()>) -> Result<()> {
        self.expect("(")?;
        item(self)?;
        self.expect(")")
    }

    /// `( item {, item} )`; an item may also be `EMPTY`.
    fn list(&mut self, mut item: impl FnMut(&mut Self) -> Result<()>) -> Result<()> {
        self.expect("(")?;
        loop {
            if !self.eat("EMPTY")? {
                item(self)?;
            }
            if !self.eat(",")? {
                return self.expect(")");
            }
        }
    }

    /// A polygon ring: its coordinates, without the closing repeat of the first.
    fn ring(&mut self) -> Result<()> {
        let first = self.points.len();
        self.list(Self::coordinate)?;
        if self.points.len() > first + 1 && self.points.last() == self.points.get(first) {
            self.points.pop();
        }
        Ok(())
    }

    /// `x y [z [m]]`: x and y kept.
    fn coordinate(&mut self) -> Result<()> {
        let (mut values, mut count) = ([0.0; 4], 0);
        while count < 4 {
            let Some(token) = self.peek() else { break };
            let Ok(v) = token.parse::<f64>() else { break };
            if !v.is_finite() {
                let message = format!("coordinate {} is not finite", quoted(token));
                return Err(self.tokens.error(message));
            }
            values[count] = v;
            count += 1;
            self.tokens.advance()?;
        }
        if count < 2 {
            return Err(self.error("a coordinate 'x y'"));
        }
        if self.points.len() >= self.max_points {
            return Err(super::too_many(self.tokens.name, self.max_points));
        }
        self.points.push([values[0], values[1]]);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{BufReader, Read};

    fn parse(text: &str) -> Result<Vec<Point>> {
        read(text.as_bytes(), "t.wkt", 1000)
    }

    #[test]
    fn every_geometry_gives_its_vertices() {
        let text = "SRID=4326;MULTIPOINT ((0 0), (1 0))\npoint z (2 0 7)\n\
                    LINESTRING (3 0, 4 0) # a comment\n\
                    POLYGON ((0 1, 1 1, 1 2, 0 1), (5 5, 6 5, 6 6, 5 5))\n\
                    MULTIPOLYGON (((9 9, 8 9, 8 8, 9 9)), EMPTY)\n\
                    GEOMETRYCOLLECTION (POINT (7 7), MULTILINESTRING ((1 3, 2 3)))\n\
                    POINT EMPTY, MULTIPOINT (10 10, 11 11)";
        let points = parse(text).unwrap();
        assert_eq!(points.len(), 2 + 1 + 2 + 3 + 3 + 3 + 1 + 2 + 2);
        assert_eq!(points[..3], [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]);
        assert_eq!(
            points[5..8],
            [[0.0, 1.0], [1.0, 1.0], [1.0, 2.0]],
            "the ring's closing vertex dropped"
        );
        assert_eq!(points[points.len() - 1], [11.0, 11.0]);
    }

    #[test]
    fn errors_name_the_line_and_what_was_expected() {
        let err = parse("POINT (1 2)\nLINESTRING (1 2, 3)\n").unwrap_err().to_string();
        assert_eq!(err, "t.wkt:2: WKT: expected a coordinate 'x y', found ')'");
        let err = parse("POINT (1 2\n\n# the end\n").unwrap_err().to_string();
        assert_eq!(err, "t.wkt:1: WKT: expected ')', found the end", "the last token's line");
        let err = parse("CIRCLE (1 2)").unwrap_err().to_string();
        assert!(err.starts_with("t.wkt:1: WKT: expected a WKT geometry"), "{err}");
        assert!(parse("POINT (1e400 0)").unwrap_err().to_string().contains("not finite"));
        let many = read("MULTIPOINT (0 0, 1 1, 2 2)".as_bytes(), "t.wkt", 2).unwrap_err();
        assert!(many.to_string().contains("more than 2 points"), "{many}");
    }

    #[test]
    fn tokens_may_span_reads() {
        let text = "\u{feff}SRID=4326;MULTIPOINT ((0 0), (1 0)) # caf\u{e9}\r\n\
                    POLYGON ((0 1, 1 1, 1 2, 0 1)), point zm (12345.5 -6e2 7 8)\n";
        let byte_by_byte =
            |text: &str| read(BufReader::with_capacity(1, text.as_bytes()), "t.wkt", 9);
        assert_eq!(byte_by_byte(text).unwrap(), parse(text).unwrap());
        assert_eq!(parse(text).unwrap().len(), 6);
        let err = byte_by_byte("POINT (0 0)\n\n  POINT (1 \u{e9})").unwrap_err().to_string();
        assert_eq!(err, "t.wkt:3: WKT: expected a coordinate 'x y', found '\u{e9}'");
    }

    #[test]
    fn wkt_is_told_from_headers() {
        assert!(starts_wkt("MultiPoint ((1 2))") && starts_wkt("POINT ZM (1 2 3 4)"));
        assert!(starts_wkt("srid=3857;POINT(1 2)") && starts_wkt("POLYGON EMPTY"));
        assert!(!starts_wkt("point x") && !starts_wkt("x,y") && !starts_wkt("1 2"));
    }

    /// `depth` GEOMETRYCOLLECTIONs around one point.
    fn nested(depth: usize) -> String {
        let open = "GEOMETRYCOLLECTION (".repeat(depth);
        format!("{open}POINT (0 0){}", ")".repeat(depth))
    }

    #[test]
    fn collections_nest_at_most_128_deep() {
        assert_eq!(parse(&nested(128)).unwrap(), [[0.0, 0.0]]);
        let err = parse(&nested(129)).unwrap_err().to_string();
        assert_eq!(err, "t.wkt:1: WKT: GEOMETRYCOLLECTION nested more than 128 deep");
        // Without the limit, this overflowed the stack.
        assert!(parse(&nested(400_000)).unwrap_err().to_string().contains("nested more than"));
    }

    /// `MULTIPOINT (` and then `1 1,` for ever, as `yes` gives it.
    struct Endless {
        served: usize,
    }

    impl Read for Endless {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            // Only a reader that does not stop gets here; fail rather than fill the memory.
            assert!(self.served < 16 << 20, "read past 16 MiB: reading must stop at point 6");
            const HEAD: &[u8] = b"MULTIPOINT (";
            for byte in buf.iter_mut() {
                *byte = match HEAD.get(self.served) {
                    Some(&b) => b,
                    None => b"1 1,"[(self.served - HEAD.len()) % 4],
                };
                self.served += 1;
            }
            Ok(buf.len())
        }
    }

    #[test]
    fn an_endless_text_stops_at_the_point_over_the_limit() {
        let mut endless = Endless { served: 0 };
        let err = read(BufReader::new(&mut endless), "t.wkt", 5).unwrap_err();
        assert_eq!(err.to_string(), "t.wkt: more than 5 points (raise --max-points to read more)");
        assert!(endless.served <= 1 << 16, "read {} bytes", endless.served);
    }

    #[test]
    fn reading_errors_name_the_file_and_line() {
        let text = b"POINT (1 2)\n# caf\xe9: a comment may hold anything\nPOINT (\xff 1)\n";
        let err = read(&text[..], "t.wkt", 10).unwrap_err().to_string();
        assert_eq!(err, "t.wkt:3: WKT: not UTF-8 text");
        let ok = read(&text[..text.len() - 13], "t.wkt", 10).unwrap();
        assert_eq!(ok, [[1.0, 2.0]], "a comment is not checked");

        struct Failing;
        impl Read for Failing {
            fn read(&mut self, _: &mut [u8]) -> std::io::Result<usize> {
                Err(std::io::Error::other("disk on fire"))
            }
        }
        let err = read(BufReader::new(Failing), "t.wkt", 10).unwrap_err();
        assert_eq!(err.to_string(), "t.wkt:1: WKT: cannot read: disk on fire");
    }

    #[test]
    fn a_token_longer_than_a_mebibyte_is_refused() {
        let text = format!("POINT ({} 0)", "1".repeat(crate::text::MAX_LINE + 1));
        let err = parse(&text).unwrap_err().to_string();
        assert_eq!(err, "t.wkt:1: WKT: token longer than 1048576 bytes");
    }

    #[test]
    fn endless_white_space_or_comments_end() {
        // `(echo 'MULTIPOINT ((0 0)'; yes '') | sigdt reconstruct -` ended never (G4). (Twice
        // the limit stands in for endless.)
        for filler in [&b"\n"[..], b"# c\n", b" "] {
            let mut text = b"MULTIPOINT ((0 0)".to_vec();
            text.extend(filler.repeat((2 << 20) / filler.len()));
            let err = read(&text[..], "t.wkt", 9).unwrap_err().to_string();
            let want = "WKT: more than 1048576 bytes of white space and comments";
            assert!(err.starts_with("t.wkt:") && err.ends_with(want), "{err}");
        }
    }

    #[test]
    fn input_in_messages_is_quoted() {
        let err = parse("POINT (1 \x1b[2J)").unwrap_err().to_string();
        assert_eq!(err, r"t.wkt:1: WKT: expected a coordinate 'x y', found '\u{1b}[2J'");
        let err = parse(&format!("CIRCLE{}", "x".repeat(50_000))).unwrap_err().to_string();
        assert!(err.len() < 200 && err.ends_with("(50006 characters)"), "{err}");
        let err = parse("POINT (1e400 0)").unwrap_err().to_string();
        assert_eq!(err, "t.wkt:1: WKT: coordinate '1e400' is not finite");
    }

    #[test]
    fn a_byte_order_mark_is_skipped() {
        let points = parse("\u{feff}MULTIPOINT ((0 0),(1 0),(1 1))").unwrap();
        assert_eq!(points, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
        assert!(parse("POINT (0 0)\n\u{feff}POINT (1 1)").is_err(), "only at the start");
    }

    #[test]
    fn only_ascii_white_space_separates() {
        let err = parse("MULTIPOINT (0 0,\n1\u{a0}1)").unwrap_err().to_string();
        assert_eq!(err, r"t.wkt:2: WKT: expected a coordinate 'x y', found '1\u{a0}1'");
        assert_eq!(parse("POINT\t(1\r\n2)\x0c").unwrap(), [[1.0, 2.0]]);
    }
}
