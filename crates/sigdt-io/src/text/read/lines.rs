//! The line reader and the field splitting shared by the point and edge readers.
//!
//! Input is streamed line by line through a reused buffer, or in blocks of whole lines, so
//! memory stays bounded by the block size plus the longest line, which is capped at
//! [`MAX_LINE`] bytes. Blank lines are skipped, `#` starts a comment that runs to the end of
//! the line, `\r\n` line endings and a UTF-8 byte-order mark are accepted, and every problem
//! is an [`Error::Parse`] naming the file and the 1-based line.

use std::io::{BufRead, ErrorKind};

use sigdt::{Error, Result};

/// The longest line a reader accepts, in bytes (1 MiB), not counting the line ending.
pub const MAX_LINE: usize = 1 << 20;

/// The most lines, blank and comment lines included, an input of at most `max_points`
/// records may have: two a record plus 2²⁰ (comments, a header, blank lines). Without such
/// a bound an endless stream of blank lines (`yes ''`) would never end, since only records
/// count towards `max_points`.
pub fn max_lines(max_points: usize) -> usize {
    max_points.saturating_mul(2).saturating_add(1 << 20)
}

/// Why line `max + 1` is refused by [`max_lines`].
pub fn too_many_lines(max: usize) -> String {
    format!(
        "more than {max} lines, blank and comment lines included (two a point allowed, plus \
         2^20): raise the limit with --max-points"
    )
}

/// Lines of a stream, read into one reused buffer of at most [`MAX_LINE`] bytes.
pub(super) struct Lines<'a, R> {
    reader: R,
    name: &'a str,
    buf: Vec<u8>,
    /// The byte range of the current line's content: comment and outer whitespace removed.
    content: std::ops::Range<usize>,
    /// 1-based number of the current line (0 before the first).
    pub(super) number: usize,
    /// Whether the next call to `next_content` returns the current line again.
    unread: bool,
    /// Whether the reader has reported the end of input: it is not asked again (a terminal
    /// would wait for a second end-of-file).
    eof: bool,
    /// A reading error [`Lines::next_block`] found after whole lines, which it returned
    /// first: it comes at the next call, after any problem on those lines.
    failed: Option<Error>,
    /// The most lines read before line `max_lines + 1` is refused (see [`max_lines`]).
    max_lines: usize,
}

impl<'a, R: BufRead> Lines<'a, R> {
    pub(super) fn new(reader: R, name: &'a str) -> Self {
        let buf = Vec::with_capacity(256);
        Lines {
            reader,
            name,
            buf,
            content: 0..0,
            number: 0,
            unread: false,
            eof: false,
            failed: None,
            max_lines: usize::MAX,
        }
    }

    /// Refuses the input at line `max + 1`, blank and comment lines included.
    pub(super) fn at_most_lines(mut self, max: usize) -> Self {
        self.max_lines = max;
        self
    }

    /// The next line with content, without its comment and outer whitespace; `None` at the
    /// end. Only the content must be valid UTF-8.
    pub(super) fn next_content(&mut self) -> Result<Option<&str>> {
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
        match text(&self.buf[self.content.clone()]) {
            Ok(line) => Ok(Some(line)),
            Err(message) => Err(self.error(message)),
        }
    }

    /// The next lines, whole, as one [`Block`] of about `size` bytes (more when its last line
    /// runs past them); `None` at the end of input. Lines are not checked here, but for the
    /// last one's length: reading stops as soon as it exceeds [`MAX_LINE`], so memory stays
    /// bounded by `size + MAX_LINE`. A reading error (such a line, or I/O) is returned once
    /// the lines before it are: those may have a problem that comes first.
    pub(super) fn next_block(&mut self, size: usize) -> Result<Option<Block>> {
        if let Some(error) = self.failed.take() {
            return Err(error);
        }
        let mut bytes = Vec::with_capacity(size + 256);
        // Where the last, possibly unfinished, line of `bytes` starts.
        let mut last_start = 0;
        let mut newlines = 0;
        loop {
            if self.eof {
                break;
            }
            let failure = match self.reader.fill_buf() {
                Err(e) if e.kind() == ErrorKind::Interrupted => continue,
                Err(source) => Error::Io { path: self.name.to_string(), source },
                Ok([]) => {
                    self.eof = true;
                    break;
                }
                Ok(chunk) => {
                    let take = if bytes.len() < size {
                        chunk.len().min(size - bytes.len())
                    } else {
                        // Past the size: to the end of the current line.
                        memchr::memchr(b'\n', chunk).map_or(chunk.len(), |i| i + 1)
                    };
                    let start = bytes.len();
                    bytes.extend_from_slice(&chunk[..take]);
                    self.reader.consume(take);
                    let added = &bytes[start..];
                    if let Some(last) = memchr::memrchr(b'\n', added) {
                        newlines += memchr::memchr_iter(b'\n', added).count();
                        last_start = start + last + 1;
                    }
                    if bytes.len() - last_start <= MAX_LINE {
                        if bytes.len() >= size && last_start == bytes.len() {
                            break;
                        }
                        continue;
                    }
                    Error::Parse {
                        path: self.name.to_string(),
                        line: self.number + newlines + 1,
                        message: format!("line longer than {MAX_LINE} bytes"),
                    }
                }
            };
            if last_start == 0 {
                return Err(failure);
            }
            // The whole lines before it first.
            self.failed = Some(failure);
            bytes.truncate(last_start);
            break;
        }
        let lines_read = newlines + usize::from(last_start < bytes.len());
        if self.number + lines_read > self.max_lines {
            // Keep the lines up to the limit: a problem on them comes first.
            let room = self.max_lines - self.number;
            let end = match room.checked_sub(1) {
                Some(last) => memchr::memchr_iter(b'\n', &bytes).nth(last).map_or(0, |i| i + 1),
                None => 0,
            };
            bytes.truncate(end);
            newlines = room;
            last_start = end;
            let failure = self.error_at(self.max_lines + 1, too_many_lines(self.max_lines));
            if bytes.is_empty() {
                return Err(failure);
            }
            self.failed = Some(failure);
        }
        if bytes.is_empty() {
            return Ok(None);
        }
        let first_line = self.number + 1;
        self.number += newlines + usize::from(last_start < bytes.len());
        Ok(Some(Block { bytes, first_line }))
    }

    /// A parse error on line `line` of this input.
    pub(super) fn error_at(&self, line: usize, message: String) -> Error {
        Error::Parse { path: self.name.to_string(), line, message }
    }

    /// Makes the next `next_content` return the current line again (if there is one).
    pub(super) fn unread(&mut self) {
        self.unread = self.number > 0 && !self.content.is_empty();
    }

    /// Reads the next line into `buf`, without its `\n`; false at the end of input. Stops
    /// with an error, before buffering it, as soon as a line exceeds [`MAX_LINE`] bytes.
    fn read_line(&mut self) -> Result<bool> {
        self.buf.clear();
        let mut any = false;
        loop {
            if self.eof {
                break;
            }
            let chunk = match self.reader.fill_buf() {
                Ok(chunk) => chunk,
                Err(e) if e.kind() == ErrorKind::Interrupted => continue,
                Err(source) => return Err(Error::Io { path: self.name.to_string(), source }),
            };
            if chunk.is_empty() {
                self.eof = true;
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
        if self.number > self.max_lines {
            return Err(self.error(too_many_lines(self.max_lines)));
        }
        Ok(any)
    }

    /// A parse error on the current line (line 1 if nothing was read).
    pub(super) fn error(&self, message: String) -> Error {
        Error::Parse { path: self.name.to_string(), line: self.number.max(1), message }
    }
}

/// Whole lines of an input read at once (by [`Lines::next_block`]), so that they can be
/// parsed apart from the reader, in parallel.
pub(super) struct Block {
    bytes: Vec<u8>,
    /// The 1-based number of the first line.
    pub first_line: usize,
}

impl Block {
    /// `(line number, content)` of every line with content, in order, or the number and
    /// message of the first line that is too long or whose content is not UTF-8 text
    /// (checked as each line is reached, as [`Lines::next_content`] does).
    pub(super) fn contents(
        &self,
    ) -> impl Iterator<Item = Result<(usize, &str), (usize, String)>> + '_ {
        let body = self.bytes.strip_suffix(b"\n").unwrap_or(&self.bytes);
        let mut next_start = 0;
        let lines = memchr::memchr_iter(b'\n', body).chain([body.len()]).map(move |end| {
            let start = std::mem::replace(&mut next_start, end + 1);
            start..end
        });
        // One check of the whole block costs less than one a line; a block that fails it
        // (the fault may be in a comment, which is allowed) is checked line by line.
        let checked = memchr::memchr(0, body).is_none().then(|| std::str::from_utf8(body).ok());
        let checked = checked.flatten();
        lines.zip(self.first_line..).filter_map(move |(line, number)| {
            if line.len() > MAX_LINE {
                return Some(Err((number, format!("line longer than {MAX_LINE} bytes"))));
            }
            let range = content(&body[line.clone()], false);
            let range = line.start + range.start..line.start + range.end;
            let text = match checked {
                _ if range.is_empty() => return None,
                Some(all) => Ok(&all[range]),
                None => text(&body[range]),
            };
            Some(text.map(|text| (number, text)).map_err(|message| (number, message)))
        })
    }
}

/// A line's content as text: refused if it has NUL bytes or is not UTF-8.
fn text(bytes: &[u8]) -> Result<&str, String> {
    if bytes.contains(&0) {
        // UTF-16 text without a byte-order mark (or a binary file) reads as NUL bytes
        // between characters; showing them would say nothing.
        return Err("line has NUL bytes: UTF-16 or binary data? Save it as UTF-8 text".into());
    }
    std::str::from_utf8(bytes).map_err(|_| "line is not valid UTF-8".to_string())
}

/// The range of `line` without its `#` comment, outer ASCII whitespace (including `\r`) and,
/// on the first line, a UTF-8 byte-order mark. Both ends fall on character boundaries.
fn content(line: &[u8], first: bool) -> std::ops::Range<usize> {
    let start = if first && line.starts_with(b"\xEF\xBB\xBF") { 3 } else { 0 };
    let end = memchr::memchr(b'#', line).unwrap_or(line.len()).max(start);
    let body = &line[start..end];
    let lead = body.iter().take_while(|b| b.is_ascii_whitespace()).count();
    let trail = body[lead..].iter().rev().take_while(|b| b.is_ascii_whitespace()).count();
    start + lead..end - trail
}

/// Exactly two fields of `line`, each read by `read`; `what` names them in errors.
pub(super) fn pair<T: Copy + Default>(
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
pub(super) fn coordinate(field: &str) -> Result<f64, String> {
    match field.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!("coordinate {} is not finite", quoted(field))),
        Err(_) if field.is_empty() => Err("empty field between commas".to_string()),
        Err(_) => Err(not_a_number(field)),
    }
}

/// Why `field` is not a number, naming an unsupported separator inside it if it has one.
pub(super) fn not_a_number(field: &str) -> String {
    if field.contains([' ', '\t']) {
        // Spaces and tabs are separators, except in a line that also has a comma.
        return format!(
            "{} is not a number: a line is two numbers separated by spaces, tabs or one comma",
            quoted(field)
        );
    }
    let separator = field.chars().find(|&c| c.is_whitespace() || matches!(c, ';' | '|'));
    match separator {
        Some(c) => format!(
            "{} is not a number: unsupported separator {} (use spaces, tabs or one comma)",
            quoted(field),
            c.escape_unicode()
        ),
        None => format!("{} is not a number", quoted(field)),
    }
}

/// The most characters of an input token an error message shows.
const SHOWN_CHARS: usize = 40;

/// `token` as an error message shows it: in single quotes, control and other invisible
/// characters escaped (a crafted file cannot drive the terminal), cut after
/// 40 characters. Every reader's messages quote input through it.
///
/// ```
/// assert_eq!(sigdt_io::text::quoted("a\x1b[2J"), r"'a\u{1b}[2J'");
/// ```
pub fn quoted(token: &str) -> String {
    let mut shown = String::from("'");
    for (k, c) in token.chars().enumerate() {
        if k == SHOWN_CHARS {
            shown.push_str(&format!("...' ({} characters)", token.chars().count()));
            return shown;
        }
        match c {
            c if c.is_control() || c.is_whitespace() && c != ' ' => {
                shown.extend(c.escape_unicode())
            }
            '\'' | '\\' => shown.extend(c.escape_default()),
            c => shown.push(c),
        }
    }
    shown.push('\'');
    shown
}

/// The fields of a plain line: comma-separated (each trimmed) if it has a comma, else
/// separated by runs of spaces and tabs.
pub(super) fn fields(line: &str) -> impl Iterator<Item = &str> {
    let comma = line.contains(',');
    let by_comma = comma.then(|| line.split(',').map(str::trim_ascii));
    let by_space = (!comma).then(|| line.split_ascii_whitespace());
    by_comma.into_iter().flatten().chain(by_space.into_iter().flatten())
}

/// The message for input with more than `max` points.
pub(super) fn too_many(max: usize) -> String {
    format!("more than the {max} points allowed (raise the limit with --max-points)")
}

#[cfg(test)]
pub(super) mod tests {
    use crate::text::{parse_edges, parse_points};
    use sigdt::{Error, Result};
    use std::io::{BufReader, Read};

    use super::MAX_LINE;

    /// The `line: message` of a parse error in the file `t.xy`.
    pub(in crate::text) fn error(result: Result<impl std::fmt::Debug>) -> String {
        match result.unwrap_err() {
            Error::Parse { path, line, message } if path == "t.xy" => format!("{line}: {message}"),
            e => panic!("not a parse error: {e}"),
        }
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

    /// A reader that counts the reads that found the end of input.
    struct EndCounting<R>(R, usize);
    impl<R: Read> Read for EndCounting<R> {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            let n = self.0.read(buf)?;
            self.1 += usize::from(n == 0 && !buf.is_empty());
            Ok(n)
        }
    }

    #[test]
    fn the_end_of_input_is_read_once() {
        // A terminal answers every read after Ctrl-D with a new wait: read past the end once.
        for text in ["", "x y\n", "1 2\n3 4", "# c\n1 2\n\n"] {
            let mut input = EndCounting(text.as_bytes(), 0);
            parse_points(BufReader::new(&mut input), "t.xy", None).unwrap();
            assert_eq!(input.1, 1, "{text:?}");
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
        // The same after the first line, which the plain reader reads apart from the rest.
        let mut endless = Counting(b"0 0\n1 1\n".chain(std::io::repeat(b'1')), 0);
        let result = parse_points(BufReader::new(&mut endless), "t.xy", None);
        assert_eq!(error(result), "3: line longer than 1048576 bytes");
        assert!(endless.1 <= MAX_LINE + (1 << 18) + (64 << 10), "read {}", endless.1);
        // Exactly at the limit is fine.
        let mut line = vec![b' '; MAX_LINE - 3];
        line.extend_from_slice(b"1 2\n3 4");
        assert_eq!(parse_points(&line[..], "t.xy", None).unwrap(), vec![[1.0, 2.0], [3.0, 4.0]]);
    }
}
