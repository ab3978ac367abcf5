//! Points from Well-Known Text (OGC Simple Features): every vertex of the geometries, in
//! order, as points.
//!
//! A file holds one or more geometries, separated by white space, new lines or commas:
//! `POINT`, `MULTIPOINT` (with or without parentheses around each point), `LINESTRING`,
//! `POLYGON`, `MULTILINESTRING`, `MULTIPOLYGON` and `GEOMETRYCOLLECTION`, each possibly
//! `EMPTY`, with `Z`, `M` or `ZM` coordinates (only x and y are kept), keywords in any case,
//! and an optional EWKT `SRID=n;` prefix. A polygon ring's closing vertex repeats its first
//! and is dropped, so a ring of `k + 1` coordinates gives `k` points. `#` starts a comment
//! to the end of the line, as in sigdt's plain files.
//!
//! # Errors
//! The file and the line of the first token that does not fit, saying what was expected.
//!
//! # Complexity
//! O(length of the text); the text is read whole.

use std::io::Read;

use anyhow::{bail, Result};
use sigdt::io::{wkt_geometry, WKT_GEOMETRIES};
use sigdt::Point;

/// Whether `line` starts like WKT: an EWKT `SRID=` prefix, or a geometry as the kernel's
/// reader recognises it ([`sigdt::io::wkt_geometry`]).
pub fn starts_wkt(line: &str) -> bool {
    let line = line.trim_start();
    line.get(..5).is_some_and(|p| p.eq_ignore_ascii_case("SRID=")) || wkt_geometry(line).is_some()
}

/// The points of the WKT text of `reader`; see the module docs.
pub fn read(mut reader: impl Read, name: &str, max_points: usize) -> Result<Vec<Point>> {
    let mut text = String::new();
    if reader.read_to_string(&mut text).is_err() {
        bail!("{name}: not UTF-8 text (WKT is text)");
    }
    let mut parser = Parser { tokens: tokens(&text), at: 0, name, points: Vec::new(), max_points };
    while parser.peek().is_some() {
        parser.geometry()?;
        if parser.peek().map(|t| t.text) == Some(",") {
            parser.at += 1;
        }
    }
    Ok(parser.points)
}

/// A token: a word, a number, `(`, `)`, `,` or `;`/`=` of an SRID prefix, with its line.
#[derive(Debug, Clone, Copy)]
struct Token<'a> {
    text: &'a str,
    line: usize,
}

/// The tokens of `text`, comments removed.
fn tokens(text: &str) -> Vec<Token<'_>> {
    let mut out = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let line_text = line.split('#').next().unwrap_or("");
        let mut rest = line_text;
        while let Some(start) = rest.find(|c: char| !c.is_whitespace()) {
            rest = &rest[start..];
            let len = if rest.starts_with(['(', ')', ',', ';', '=']) {
                1
            } else {
                rest.find(|c: char| c.is_whitespace() || "(),;=".contains(c)).unwrap_or(rest.len())
            };
            out.push(Token { text: &rest[..len], line: k + 1 });
            rest = &rest[len..];
        }
    }
    out
}

struct Parser<'a> {
    tokens: Vec<Token<'a>>,
    at: usize,
    name: &'a str,
    points: Vec<Point>,
    max_points: usize,
}

impl<'a> Parser<'a> {
    fn peek(&self) -> Option<Token<'a>> {
        self.tokens.get(self.at).copied()
    }

    fn error(&self, expected: &str) -> anyhow::Error {
        match self.peek() {
            Some(t) => anyhow::anyhow!(
                "{}:{}: WKT: expected {expected}, found '{}'",
                self.name,
                t.line,
                t.text
            ),
            None => anyhow::anyhow!("{}: WKT: expected {expected}, found the end", self.name),
        }
    }

    fn expect(&mut self, symbol: &str) -> Result<()> {
        if self.peek().map(|t| t.text) == Some(symbol) {
            self.at += 1;
            Ok(())
        } else {
            Err(self.error(&format!("'{symbol}'")))
        }
    }

    /// Consumes `symbol` if it is next.
    fn eat(&mut self, symbol: &str) -> bool {
        let next = self.peek().is_some_and(|t| t.text.eq_ignore_ascii_case(symbol));
        self.at += usize::from(next);
        next
    }

    /// `[SRID=n;] KEYWORD [Z|M|ZM] (EMPTY | body)`.
    fn geometry(&mut self) -> Result<()> {
        if self.peek().is_some_and(|t| t.text.eq_ignore_ascii_case("SRID")) {
            self.at += 1;
            self.expect("=")?;
            if !self.peek().is_some_and(|t| t.text.parse::<u32>().is_ok()) {
                return Err(self.error("an SRID number"));
            }
            self.at += 1;
            self.expect(";")?;
        }
        let keyword = match self.peek() {
            Some(t) => WKT_GEOMETRIES.iter().find(|k| t.text.eq_ignore_ascii_case(k)).copied(),
            None => None,
        };
        let Some(keyword) = keyword else {
            return Err(self.error("a WKT geometry (POINT, MULTIPOINT, LINESTRING, POLYGON, ...)"));
        };
        self.at += 1;
        for dimension in ["ZM", "Z", "M"] {
            if self.eat(dimension) {
                break;
            }
        }
        if self.eat("EMPTY") {
            return Ok(());
        }
        match keyword {
            "POINT" => self.parenthesised(Self::coordinate),
            "MULTIPOINT" => self.list(|p| {
                if p.peek().map(|t| t.text) == Some("(") {
                    p.parenthesised(Self::coordinate)
                } else {
                    p.coordinate()
                }
            }),
            "LINESTRING" => self.list(Self::coordinate),
            "POLYGON" => self.list(Self::ring),
            "MULTILINESTRING" => self.list(|p| p.list(Self::coordinate)),
            "MULTIPOLYGON" => self.list(|p| p.list(Self::ring)),
            _ => self.list(Self::geometry),
        }
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
            if !self.eat("EMPTY") {
                item(self)?;
            }
            if self.peek().map(|t| t.text) == Some(",") {
                self.at += 1;
            } else {
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
        let mut values = Vec::with_capacity(4);
        while let Some(t) = self.peek() {
            match t.text.parse::<f64>() {
                Ok(v) if values.len() < 4 => {
                    if !v.is_finite() {
                        bail!(
                            "{}:{}: WKT: coordinate '{}' is not finite",
                            self.name,
                            t.line,
                            t.text
                        );
                    }
                    values.push(v);
                    self.at += 1;
                }
                _ => break,
            }
        }
        if values.len() < 2 {
            return Err(self.error("a coordinate 'x y'"));
        }
        if self.points.len() >= self.max_points {
            return Err(super::too_many(self.name, self.max_points));
        }
        self.points.push([values[0], values[1]]);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let err = parse("POINT (1 2").unwrap_err().to_string();
        assert_eq!(err, "t.wkt: WKT: expected ')', found the end");
        let err = parse("CIRCLE (1 2)").unwrap_err().to_string();
        assert!(err.starts_with("t.wkt:1: WKT: expected a WKT geometry"), "{err}");
        assert!(parse("POINT (1e400 0)").unwrap_err().to_string().contains("not finite"));
        let many = read("MULTIPOINT (0 0, 1 1, 2 2)".as_bytes(), "t.wkt", 2).unwrap_err();
        assert!(many.to_string().contains("more than 2 points"), "{many}");
    }

    #[test]
    fn wkt_is_told_from_headers() {
        assert!(starts_wkt("MultiPoint ((1 2))") && starts_wkt("POINT ZM (1 2 3 4)"));
        assert!(starts_wkt("srid=3857;POINT(1 2)") && starts_wkt("POLYGON EMPTY"));
        assert!(!starts_wkt("point x") && !starts_wkt("x,y") && !starts_wkt("1 2"));
    }
}
