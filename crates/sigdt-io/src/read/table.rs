//! Points from a table: CSV with `,`, `;` or tab separators (or white space), fields
//! optionally in double quotes (`""` inside for a quote), an optional header row, and the x
//! and y columns chosen by name or 1-based number (`--columns x,y`, `--columns 3,4`) or
//! found: a header's `x`/`y`, else `lon`, `lng`, `long` or `longitude` / `lat` or
//! `latitude`, else `easting` or `e` / `northing` or `n` (any case, in any order and
//! position: `lat,lon` is read as y then x), else the only two columns.
//!
//! The separator is the first of `;`, tab and `,` found in the first row, else white space.
//! With `;` separators a number may use a decimal comma (`1,5`), as spreadsheets write it in
//! many locales (so `1,000` is 1.0 there). Blank lines and lines starting with `#` are
//! skipped; a quoted field may hold line breaks (RFC 4180). The first row is a header when
//! the fields of the chosen columns are names (with no columns chosen, or chosen by name:
//! every field that is not empty), by the plain reader's rule, so a headerless first row with
//! a name or `NA` in another column is read as a point; `--verbose` says which.
//!
//! # Errors
//! The file and line of a row that is too short or holds something other than a finite
//! number in a chosen column, and the file with the header's names when a named column is
//! not there or the columns cannot be found.
//!
//! # Complexity
//! O(length of the text), streamed record by record; a record (a line, or lines joined
//! inside quotes) longer than [`MAX_LINE`] bytes is an error, so memory stays bounded by it
//! and the points kept.

use std::io::BufRead;
use std::str::FromStr;

use crate::attributes::{Column as AttributeColumn, ColumnType, Grouping, Value};
use crate::text::{max_lines, quoted, too_many_lines, MAX_LINE};
use anyhow::{anyhow, Result};
use sigdt::Point;

/// The x and y columns of `--columns`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Columns {
    x: Column,
    y: Column,
}

/// A column: a header name or a 1-based number.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Column {
    Name(String),
    Number(usize),
}

impl FromStr for Columns {
    type Err = String;

    fn from_str(text: &str) -> Result<Columns, String> {
        let column = |part: &str| -> Result<Column, String> {
            let part = part.trim();
            match part.parse::<usize>() {
                Ok(0) => Err("column numbers start at 1".to_string()),
                Ok(k) => Ok(Column::Number(k)),
                Err(_) if part.is_empty() => Err("a column is empty".to_string()),
                Err(_) => Ok(Column::Name(part.to_string())),
            }
        };
        match text.split(',').collect::<Vec<_>>().as_slice() {
            [x, y] => Ok(Columns { x: column(x)?, y: column(y)? }),
            _ => Err(format!("'{text}' is not two columns 'X,Y' (names or numbers from 1)")),
        }
    }
}

/// Header names that mean x and y (in any case), by kind in order of preference: plane,
/// geographic, projected.
const XY_NAMES: [(&[&str], &[&str]); 3] = [
    (&["x"], &["y"]),
    (&["lon", "lng", "long", "longitude"], &["lat", "latitude"]),
    (&["easting", "e"], &["northing", "n"]),
];

/// The x and y columns a header names, in any order and position (`lat,lon` is y then x).
fn named_xy(header: &[String]) -> Option<(usize, usize)> {
    let find = |names: &[&str]| {
        header.iter().position(|h| names.iter().any(|n| h.trim().eq_ignore_ascii_case(n)))
    };
    XY_NAMES.iter().find_map(|(x, y)| Some((find(x)?, find(y)?)))
}

/// Whether `first`, the first line of a file the plain reader would read in file order, is
/// a header that the table reader, which reads columns by name, must read: one that names
/// y before x (`lat,lon`, `Y X`, `northing,easting`), or every point would come out with x
/// and y swapped; or longitude and latitude, which are not plane coordinates.
pub fn needs_names(first: &str) -> bool {
    let separator = [';', '\t', ','].into_iter().find(|&c| first.contains(c));
    split_fields(first, separator).is_ok_and(|fields| {
        is_header(&fields, None)
            && named_xy(&fields).is_some_and(|(x, y)| y < x || is_lon_lat(&fields[x], &fields[y]))
    })
}

/// Whether a `.csv`/`.tsv` file whose first row is `first` needs the table reader rather
/// than the plain one: `;` or tab separators, quotes, or more than two fields.
pub fn is_table(first: &str) -> bool {
    first.contains([';', '"', '\t']) || first.split(',').count() > 2
}

/// A table's points and how they were read (columns, header), for `--verbose`.
#[derive(Debug)]
pub struct Table {
    pub points: Vec<Point>,
    /// "columns 'lon' and 'lat' (the header row skipped)" or "columns 2 and 3".
    pub how: String,
    /// Whether the columns read are named longitude and latitude (`lon`, `lat`, ...).
    pub lon_lat: bool,
    /// The points grouped by a column (`--by`), each row's other columns its attributes.
    pub grouping: Option<Grouping>,
}

/// Whether header names `x` and `y` are a longitude and a latitude.
fn is_lon_lat(x: &str, y: &str) -> bool {
    let (lon, lat) = XY_NAMES[1];
    let is = |name: &str, names: &[&str]| names.iter().any(|n| name.trim().eq_ignore_ascii_case(n));
    is(x, lon) && is(y, lat)
}

/// The points of the table `reader`, from `columns` or the columns found; see the module docs.
pub fn read(
    reader: impl BufRead,
    name: &str,
    columns: Option<&Columns>,
    max_points: usize,
) -> Result<Table> {
    read_grouped(reader, name, columns, max_points, None)
}

/// [`read`], the points grouped `by` a column of the header (`--by`) when given: every
/// column but x and y is an attribute, its text as written (an empty field: no value).
pub fn read_grouped(
    reader: impl BufRead,
    name: &str,
    columns: Option<&Columns>,
    max_points: usize,
    by: Option<&str>,
) -> Result<Table> {
    let mut records = Records::new(reader, name, max_lines(max_points));
    let Some((first_line, first)) = records.next()? else {
        if by.is_some() {
            return Err(anyhow!("{name}: --by: an empty table has no columns"));
        }
        let how = "an empty table".to_string();
        return Ok(Table { points: Vec::new(), how, lon_lat: false, grouping: None });
    };
    let first = first.to_string();
    let separator = [';', '\t', ','].into_iter().find(|&c| first.contains(c));
    let split = |line: &str| split_fields(line, separator);
    let first_fields = split(&first).map_err(|m| anyhow!("{name}:{first_line}: {m}"))?;
    let is_header = is_header(&first_fields, columns);
    let header = is_header.then(|| first_fields.clone());
    let (cx, cy) = choose(columns, header.as_deref(), first_fields.len())
        .map_err(|m| anyhow!("{name}: {m}"))?;
    let named = |c: usize| match &header {
        Some(h) => quoted(&h[c]),
        None => (c + 1).to_string(),
    };
    let label = |c: usize| format!("column {}", named(c));
    let mut grouping = match (by, &header) {
        (None, _) => None,
        (Some(_), None) => {
            return Err(anyhow!("{name}: --by: the table has no header row to name its columns"))
        }
        (Some(by), Some(header)) => {
            let others = header.iter().enumerate().filter(|&(c, _)| c != cx && c != cy);
            let columns = others
                .map(|(_, h)| AttributeColumn { name: h.clone(), kind: ColumnType::Text })
                .collect();
            Some(Grouping::new(columns, by, name).map_err(|m| anyhow!(m))?)
        }
    };
    let mut points = Vec::new();
    let mut add = |line: usize, text: &str| -> Result<()> {
        let fields = split(text).map_err(|m| anyhow!("{name}:{line}: {m}"))?;
        let value = |c: usize| -> Result<f64> {
            let field = fields.get(c).ok_or_else(|| {
                anyhow!("{name}:{line}: {} fields, {} is missing", fields.len(), label(c))
            })?;
            number(field, separator).map_err(|m| anyhow!("{name}:{line}: {}: {m}", label(c)))
        };
        let point = [value(cx)?, value(cy)?];
        if points.len() >= max_points {
            return Err(super::too_many(name, max_points));
        }
        points.push(point);
        if let Some(grouping) = &mut grouping {
            let values = (0..first_fields.len())
                .filter(|&c| c != cx && c != cy)
                .map(|c| match fields.get(c).filter(|f| !f.is_empty()) {
                    Some(field) => Value::Text(field.clone()),
                    None => Value::Null,
                })
                .collect();
            grouping.add(values, 1);
        }
        Ok(())
    };
    if !is_header {
        add(first_line, &first)?;
    }
    while let Some((line, text)) = records.next()? {
        add(line, text)?;
    }
    let skipped = if is_header { " (the header row skipped)" } else { "" };
    let how = format!("columns {} and {} of a table{skipped}", named(cx), named(cy));
    let lon_lat = header.as_ref().is_some_and(|h| is_lon_lat(&h[cx], &h[cy]));
    Ok(Table { points, how, lon_lat, grouping })
}

/// Whether the first row, split into `fields`, is a header, by the plain reader's rule for
/// names: with columns chosen by number, when the fields of those columns are names;
/// otherwise when every field that is not empty is. So a headerless table whose first row
/// has a name, `NA` or nothing in a column not read loses no point.
fn is_header(fields: &[String], columns: Option<&Columns>) -> bool {
    let is_name = |field: &str| crate::text::is_header_name(field);
    match columns {
        Some(Columns { x: Column::Number(x), y: Column::Number(y) }) => {
            [x, y].iter().all(|&&k| fields.get(k - 1).is_some_and(|f| is_name(f)))
        }
        _ => {
            let mut filled = fields.iter().filter(|f| !f.is_empty()).peekable();
            filled.peek().is_some() && filled.all(|f| is_name(f))
        }
    }
}

/// The records of a table: lines with content (blank lines and `#` comment lines skipped, a
/// UTF-8 byte-order mark dropped), a record running on over line breaks inside a quoted
/// field (RFC 4180). A record may hold at most [`MAX_LINE`] bytes, so memory stays bounded
/// whatever the input.
struct Records<'a, R> {
    reader: R,
    name: &'a str,
    buf: Vec<u8>,
    /// 1-based number of the last line read.
    line: usize,
    /// Line `max_lines + 1` is refused, blank and comment lines included, so that an endless
    /// stream of them ends (see [`max_lines`]).
    max_lines: usize,
}

impl<'a, R: BufRead> Records<'a, R> {
    fn new(reader: R, name: &'a str, max_lines: usize) -> Self {
        Records { reader, name, buf: Vec::new(), line: 0, max_lines }
    }

    /// The next record with content and the number of its first line; `None` at the end.
    fn next(&mut self) -> Result<Option<(usize, &str)>> {
        loop {
            self.buf.clear();
            let first_line = self.line + 1;
            // One more line while a quote is open: an odd count of `"` so far.
            let mut quotes = 0;
            let mut counted = 0;
            while self.read_line()? {
                quotes += bytecount(&self.buf[counted..], b'"');
                counted = self.buf.len();
                if quotes % 2 == 0 {
                    break;
                }
            }
            if self.buf.is_empty() {
                return Ok(None);
            }
            let name = self.name;
            let text = std::str::from_utf8(&self.buf)
                .map_err(|_| anyhow!("{name}:{first_line}: not UTF-8 text"))?;
            let text = if first_line == 1 { text.trim_start_matches('\u{feff}') } else { text };
            let text = text.trim();
            if !text.is_empty() && !text.starts_with('#') {
                // Re-borrow for the caller: the same bytes, trimmed.
                let start = text.as_ptr() as usize - self.buf.as_ptr() as usize;
                let range = start..start + text.len();
                let text = std::str::from_utf8(&self.buf[range]).expect("checked above");
                return Ok(Some((first_line, text)));
            }
        }
    }

    /// Appends the next line, without its line ending, to the buffer; `false` at the end of
    /// input. A line past [`MAX_LINE`] bytes is an error, found before it is held whole.
    fn read_line(&mut self) -> Result<bool> {
        let name = self.name;
        let mut read_any = false;
        loop {
            let chunk = match self.reader.fill_buf() {
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(anyhow!("{name}: cannot read: {e}")),
                Ok(chunk) => chunk,
            };
            if chunk.is_empty() {
                if read_any {
                    self.line += 1;
                }
                return Ok(read_any);
            }
            read_any = true;
            let (take, ends) = match chunk.iter().position(|&b| b == b'\n') {
                Some(i) => (i + 1, true),
                None => (chunk.len(), false),
            };
            if self.buf.len() + take > MAX_LINE + 1 {
                return Err(anyhow!("{name}:{}: line longer than {MAX_LINE} bytes", self.line + 1));
            }
            self.buf.extend_from_slice(&chunk[..take]);
            self.reader.consume(take);
            if ends {
                self.line += 1;
                if self.line > self.max_lines {
                    let message = too_many_lines(self.max_lines);
                    return Err(anyhow!("{name}:{}: {message}", self.line));
                }
                return Ok(true);
            }
        }
    }
}

/// How many times `byte` occurs in `bytes`.
fn bytecount(bytes: &[u8], byte: u8) -> usize {
    bytes.iter().filter(|&&b| b == byte).count()
}

/// The 0-based x and y columns.
fn choose(
    columns: Option<&Columns>,
    header: Option<&[String]>,
    width: usize,
) -> Result<(usize, usize), String> {
    // The first few names, at most eight and about 300 characters: a header of hundreds,
    // or of long names full of escaped control characters, would make a message no one
    // reads.
    const SHOWN: usize = 8;
    const CHARACTERS: usize = 300;
    let names = || {
        let Some(header) = header else { return String::new() };
        let mut shown: Vec<String> = Vec::new();
        let mut length = 0;
        for name in header.iter().take(SHOWN) {
            let name = quoted(name);
            if !shown.is_empty() && length + name.len() > CHARACTERS {
                break;
            }
            length += name.len() + 2;
            shown.push(name);
        }
        match header.len() - shown.len() {
            0 => shown.join(", "),
            more => format!("{}, and {more} more", shown.join(", ")),
        }
    };
    let find = |wanted: &str| {
        header.and_then(|h| h.iter().position(|n| n.trim().eq_ignore_ascii_case(wanted)))
    };
    let Some(columns) = columns else {
        if let Some(pair) = header.and_then(named_xy) {
            return Ok(pair);
        }
        if width == 2 {
            return Ok((0, 1));
        }
        return Err(match header {
            Some(_) => format!(
                "a table of {width} columns ({}): choose x and y with --columns X,Y",
                names()
            ),
            None => format!("a table of {width} columns: choose x and y with --columns 1,2"),
        });
    };
    let index = |c: &Column| -> Result<usize, String> {
        match c {
            Column::Number(k) if *k <= width => Ok(k - 1),
            Column::Number(k) => Err(format!("--columns: column {k}, but the table has {width}")),
            Column::Name(n) if header.is_none() => Err(format!(
                "--columns: '{n}' names a column, but the table has no header row: give numbers \
                 (--columns 1,2)"
            )),
            Column::Name(n) => find(n)
                .ok_or_else(|| format!("--columns: no column '{n}' (the columns: {})", names())),
        }
    };
    Ok((index(&columns.x)?, index(&columns.y)?))
}

/// The fields of `line`, split at `separator` (white space when `None`), quotes removed.
fn split_fields(line: &str, separator: Option<char>) -> Result<Vec<String>, String> {
    let Some(separator) = separator else {
        return Ok(line.split_whitespace().map(str::to_string).collect());
    };
    let mut fields = Vec::new();
    let mut field = String::new();
    let mut chars = line.chars().peekable();
    let mut quoted = false;
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            '"' if quoted => quoted = false,
            '"' if field.trim().is_empty() => {
                field.clear();
                quoted = true;
            }
            c if c == separator && !quoted => fields.push(std::mem::take(&mut field)),
            c => field.push(c),
        }
    }
    if quoted {
        return Err("a quoted field is not closed".to_string());
    }
    fields.push(field);
    Ok(fields.into_iter().map(|f| f.trim().to_string()).collect())
}

/// A finite number; with `;` separators a decimal comma is read as a point.
fn number(field: &str, separator: Option<char>) -> Result<f64, String> {
    let text = field.trim();
    let decimal_comma =
        separator == Some(';') && text.matches(',').count() == 1 && !text.contains('.');
    let parsed = if decimal_comma { text.replace(',', ".").parse() } else { text.parse::<f64>() };
    match parsed {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!("{} is not finite", quoted(text))),
        Err(_) if text.is_empty() => Err("empty".to_string()),
        Err(_) => Err(format!("{} is not a number", quoted(text))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str, columns: Option<&str>) -> Result<Vec<Point>> {
        let columns: Option<Columns> = columns.map(|c| c.parse().unwrap());
        read(text.as_bytes(), "t.csv", columns.as_ref(), 1000).map(|t| t.points)
    }

    #[test]
    fn columns_by_name_number_or_found() {
        let text = "id;\"name\";x;y\n1;\"a; b\";1,5;2\n# skipped\n2;\"c \"\"d\"\"\";3;-4,25\n";
        let expected = vec![[1.5, 2.0], [3.0, -4.25]];
        assert_eq!(parse(text, None).unwrap(), expected, "x and y found in the header");
        assert_eq!(parse(text, Some("X, Y")).unwrap(), expected);
        assert_eq!(parse(text, Some("3,4")).unwrap(), expected);
        assert_eq!(parse(text, Some("4,3")).unwrap(), vec![[2.0, 1.5], [-4.25, 3.0]]);
        let wide = "lat,lon,z\n10,20,0\n11,21,0\n";
        assert_eq!(parse(wide, None).unwrap(), vec![[20.0, 10.0], [21.0, 11.0]]);
        assert_eq!(parse("1\t2\t9\n3\t4\t9\n", Some("1,2")).unwrap(), vec![[1.0, 2.0], [3.0, 4.0]]);
        assert_eq!(parse("a b\n1 2\n", None).unwrap(), vec![[1.0, 2.0]]);
    }

    #[test]
    fn errors_name_the_line_and_the_columns() {
        let text = "id,x,y\n1,0,0\n2,1\n";
        assert_eq!(
            parse(text, None).unwrap_err().to_string(),
            "t.csv:3: 2 fields, column 'y' is missing"
        );
        let text = "id,x,y\n1,0,zero\n";
        assert_eq!(
            parse(text, None).unwrap_err().to_string(),
            "t.csv:2: column 'y': 'zero' is not a number"
        );
        let err = parse("a,b,c\n1,2,3\n", None).unwrap_err().to_string();
        assert_eq!(
            err,
            "t.csv: a table of 3 columns ('a', 'b', 'c'): choose x and y with --columns X,Y"
        );
        // Fuzz finding 13: header names reached the terminal raw and whole.
        let err = parse("a\u{1b}[2J,b,c\n1,2,3\n", None).unwrap_err().to_string();
        assert!(err.contains(r"('a\u{1b}[2J', 'b', 'c')"), "{err}");
        let err = parse("a,b,c\n1,2,3\n", Some("a,q")).unwrap_err().to_string();
        assert_eq!(err, "t.csv: --columns: no column 'q' (the columns: 'a', 'b', 'c')");
        // Fuzz finding 14: a header of hundreds of names made a message of thousands of
        // characters; the first eight are shown.
        let wide: Vec<String> = (0..300).map(|i| format!("c{i}")).collect();
        let text = format!("{}\n{}\n", wide.join(","), vec!["1"; 300].join(","));
        let err = parse(&text, None).unwrap_err().to_string();
        let want = "'c0', 'c1', 'c2', 'c3', 'c4', 'c5', 'c6', 'c7', and 292 more)";
        assert!(err.contains(want) && err.len() < 200, "{err}");
        // Fuzz finding 16: eight names of control characters, each escaped six times its
        // length, still made a message of 1,020 characters.
        let odd: Vec<String> = (0..15).map(|i| format!("Y{}{i}", "\u{c}".repeat(40))).collect();
        let text = format!("{}\n{}\n", odd.join(","), vec!["1"; 15].join(","));
        let err = parse(&text, Some("x,y")).unwrap_err().to_string();
        assert!(err.len() < 500 && err.ends_with(" more)"), "{} characters: {err}", err.len());
        let err = parse("1,2,3\n", Some("x,y")).unwrap_err().to_string();
        assert!(err.contains("no header row"), "{err}");
        assert!(parse("1,2,3\n", Some("1,5")).unwrap_err().to_string().contains("column 5"));
        assert!(parse("\"a,b\n", None).unwrap_err().to_string().contains("not closed"));
        assert!(parse("x;y\n1;inf\n", None).unwrap_err().to_string().contains("not finite"));
        assert!("1".parse::<Columns>().is_err() && "0,1".parse::<Columns>().is_err());
        let many = parse_at_most("x,y\n1,2\n3,4\n", 1).unwrap_err();
        assert!(many.to_string().contains("more than 1 points"));
    }

    fn parse_at_most(text: &str, max_points: usize) -> Result<Vec<Point>> {
        read(text.as_bytes(), "t.csv", None, max_points).map(|t| t.points)
    }

    #[test]
    fn a_first_row_is_a_header_only_when_the_chosen_fields_are_names() {
        // A name column, `NA` or an empty field in a column not read: no header (issue 30, G7).
        let text = "p1,0,0\np2,1,0\np3,1,1\np4,0,1\n";
        assert_eq!(parse(text, Some("2,3")).unwrap().len(), 4);
        assert_eq!(parse("NA,0,0\n,1,0\n", Some("2,3")).unwrap().len(), 2);
        let table = read("id,x,y\n1,0,0\n".as_bytes(), "t.csv", Some(&"2,3".parse().unwrap()), 9);
        let table = table.unwrap();
        assert_eq!(
            (table.points.len(), table.how.as_str()),
            (1, "columns 'x' and 'y' of a table (the header row skipped)")
        );
        // Pandas writes an empty name above its index column.
        assert_eq!(parse(",x,y\n0,1.5,2\n", None).unwrap(), vec![[1.5, 2.0]]);
        // A first row with a number in a chosen column and a word in the other is an error.
        let err = parse("x,5\n1,2\n", Some("1,2")).unwrap_err().to_string();
        assert_eq!(err, "t.csv:1: column 1: 'x' is not a number");
    }

    #[test]
    fn lines_are_bounded_and_quoted_fields_may_hold_line_breaks() {
        // One endless line (`/dev/zero --columns 1,2`): an error before it is held whole (G4).
        struct Zeros;
        impl std::io::Read for Zeros {
            fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
                buf.fill(0);
                Ok(buf.len())
            }
        }
        let columns: Columns = "1,2".parse().unwrap();
        let reader = std::io::BufReader::new(Zeros);
        let err = read(reader, "z", Some(&columns), 9).unwrap_err().to_string();
        assert_eq!(err, format!("z:1: line longer than {MAX_LINE} bytes"));
        // Endless blank lines (`yes '' | sigdt reconstruct - --columns 1,2`) end (G4).
        let reader = std::io::BufReader::new(std::io::repeat(b'\n'));
        let err = read(reader, "y", Some(&columns), 9).unwrap_err().to_string();
        let limit = max_lines(9);
        assert_eq!(err, format!("y:{}: {}", limit + 1, too_many_lines(limit)));
        // RFC 4180: a line break inside quotes, in a column not read (G21).
        let text = "name,x,y\n\"two\nlines\",1,2\n\"c\",3,4\n";
        let table = read(text.as_bytes(), "t.csv", None, 9).unwrap();
        assert_eq!(table.points, vec![[1.0, 2.0], [3.0, 4.0]]);
        let err = parse("x,y,z\n1,2,3\n\"a,2,3\n", Some("2,3")).unwrap_err().to_string();
        assert_eq!(err, "t.csv:3: a quoted field is not closed");
        // Control characters in a field are escaped in messages (G11).
        let err = parse("x,y\n1,\u{1b}[2J\n", None).unwrap_err().to_string();
        assert_eq!(err, "t.csv:2: column 'y': '\\u{1b}[2J' is not a number");
    }

    #[test]
    fn named_columns_are_read_in_any_order() {
        // Issue 31: a two-column `lat,lon` file was read in file order, x and y swapped.
        assert_eq!(parse("lat,lon\n10,20\n", None).unwrap(), vec![[20.0, 10.0]]);
        assert_eq!(parse("Y X\n1 2\n", None).unwrap(), vec![[2.0, 1.0]]);
        assert_eq!(parse("N;E\n1;2\n", None).unwrap(), vec![[2.0, 1.0]]);
        let gis = "id,name,Latitude,Longitude,elev_m\n1,a,60.5,5.25,10\n";
        assert_eq!(parse(gis, None).unwrap(), vec![[5.25, 60.5]]);
        assert_eq!(parse("a,b\n1,2\n", None).unwrap(), vec![[1.0, 2.0]], "two unnamed columns");
        assert!(needs_names("lat,lon") && needs_names("northing easting"));
        assert!(needs_names("lon,lat"), "longitude and latitude are not plane coordinates");
        assert!(!needs_names("x,y") && !needs_names("1,2") && !needs_names("a b"));
        assert!(!needs_names("e,n"), "easting and northing are");
    }

    #[test]
    fn tables_are_told_from_plain_files() {
        assert!(
            is_table("x;y") && is_table("a,b,c") && is_table("\"x\",\"y\"") && is_table("x\ty")
        );
        assert!(!is_table("x,y") && !is_table("1.5, 2"));
    }
}
