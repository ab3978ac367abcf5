//! The byte guard in front of serde_json: it bounds the strings read into memory and the
//! nesting, which serde_json leaves unbounded in places.

use std::cell::Cell;
use std::io::{self, Read};

use anyhow::anyhow;

/// Open arrays and objects allowed: serde_json's own limit, kept also where it does not look.
const MAX_DEPTH: usize = 127;
/// The longest string read into memory, in bytes.
const MAX_STRING: usize = 1 << 16;
/// The most white space in a row, in bytes, so that an endless stream of it (`yes ''`) ends.
const MAX_WHITESPACE: usize = 1 << 20;

/// The bytes on their way to serde_json, refused where serde_json would hold unbounded
/// memory: nesting deeper than its limit inside a skipped value (its `IgnoredAny` keeps a
/// byte a level, with no limit), and a long string that is not skipped (serde_json reads a
/// string whole before handing it over). serde_json reads a byte at a time, so `skipping` is
/// up to date when a string's opening quote comes.
pub(super) struct Guard<'a, R> {
    bytes: R,
    skipping: &'a Cell<bool>,
    /// Open arrays and objects.
    depth: usize,
    in_string: bool,
    escaped: bool,
    /// The bytes so far of the string being read, if it is kept.
    kept: Option<usize>,
    /// White space bytes in a row, outside strings.
    whitespace: usize,
    line: usize,
    column: usize,
    refused: Option<&'static str>,
}

impl<'a, R: Read> Guard<'a, R> {
    pub(super) fn new(bytes: R, skipping: &'a Cell<bool>) -> Self {
        Guard {
            bytes,
            skipping,
            depth: 0,
            in_string: false,
            escaped: false,
            kept: None,
            whitespace: 0,
            line: 1,
            column: 0,
            refused: None,
        }
    }

    /// Why and where the guard stopped the reading, if it did.
    pub(super) fn refusal(&self, name: &str) -> Option<anyhow::Error> {
        self.refused.map(|why| anyhow!("{name}:{}:{}: {why}", self.line, self.column))
    }

    fn scan(&mut self, byte: u8) -> Result<(), &'static str> {
        if byte == b'\n' {
            (self.line, self.column) = (self.line + 1, 0);
        } else {
            self.column += 1;
        }
        if !self.in_string {
            return self.outside_strings(byte);
        }
        if self.escaped {
            self.escaped = false;
        } else if byte == b'\\' {
            self.escaped = true;
        } else if byte == b'"' {
            self.in_string = false;
            return Ok(());
        }
        match &mut self.kept {
            Some(MAX_STRING) => {
                Err("a string longer than 65536 bytes outside properties and other skipped members")
            }
            Some(bytes) => {
                *bytes += 1;
                Ok(())
            }
            None => Ok(()),
        }
    }

    fn outside_strings(&mut self, byte: u8) -> Result<(), &'static str> {
        if byte.is_ascii_whitespace() {
            self.whitespace += 1;
            if self.whitespace > MAX_WHITESPACE {
                return Err("more than 1048576 bytes of white space in a row");
            }
            return Ok(());
        }
        self.whitespace = 0;
        match byte {
            b'"' => {
                self.in_string = true;
                self.kept = (!self.skipping.get()).then_some(0);
            }
            b'[' | b'{' if self.depth == MAX_DEPTH => {
                return Err("JSON nested more than 127 arrays and objects deep");
            }
            b'[' | b'{' => self.depth += 1,
            b']' | b'}' => self.depth = self.depth.saturating_sub(1),
            _ => {}
        }
        Ok(())
    }
}

impl<R: Read> Read for Guard<'_, R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let got = self.bytes.read(buf)?;
        for &byte in &buf[..got] {
            if let Err(why) = self.scan(byte) {
                self.refused = Some(why);
                return Err(io::Error::new(io::ErrorKind::InvalidData, why));
            }
        }
        Ok(got)
    }
}
