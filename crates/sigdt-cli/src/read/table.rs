//! Points from a table: CSV with `,`, `;` or tab separators (or white space), fields
//! optionally in double quotes (`""` inside for a quote), an optional header row, and the x
//! and y columns chosen by name or 1-based number (`--columns x,y`, `--columns 3,4`) or
//! found: the only two columns, or a header's `x`/`y` (`lon`/`lat`, `lng`/`lat`,
//! `longitude`/`latitude`, `easting`/`northing`), in any case.
//!
//! The separator is the first of `;`, tab and `,` found in the first row, else white space.
//! With `;` separators a number may use a decimal comma (`1,5`), as spreadsheets write it in
//! many locales. Blank lines and lines starting with `#` are skipped.
//!
//! # Errors
//! The file and line of a row that is too short or holds something other than a finite
//! number in a chosen column, and the file with the header's names when a named column is
//! not there or the columns cannot be found.
//!
//! # Complexity
//! O(length of the text), streamed line by line.

use std::io::BufRead;
use std::str::FromStr;

use anyhow::{anyhow, Context, Result};
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

/// Header names that mean x and y, in order of preference.
const XY_NAMES: [(&str, &str); 5] = [
    ("x", "y"),
    ("lon", "lat"),
    ("lng", "lat"),
    ("longitude", "latitude"),
    ("easting", "northing"),
];

/// Whether a `.csv`/`.tsv` file whose first row is `first` needs the table reader rather
/// than the plain one: `;` or tab separators, quotes, or more than two fields.
pub fn is_table(first: &str) -> bool {
    first.contains([';', '"', '\t']) || first.split(',').count() > 2
}

/// The points of the table `reader`, from `columns` or the columns found; see the module docs.
pub fn read(
    reader: impl BufRead,
    name: &str,
    columns: Option<&Columns>,
    max_points: usize,
) -> Result<Vec<Point>> {
    let mut rows = reader.lines().enumerate().filter_map(|(k, line)| match line {
        Ok(line) => {
            let line = line.trim_start_matches('\u{feff}').trim().to_string();
            (!line.is_empty() && !line.starts_with('#')).then_some(Ok((k + 1, line)))
        }
        Err(e) => Some(Err(e)),
    });
    let Some(first) = rows.next() else { return Ok(Vec::new()) };
    let (first_line, first) = first.with_context(|| format!("{name}: cannot read"))?;
    let separator = [';', '\t', ','].into_iter().find(|&c| first.contains(c));
    let split = |line: &str| split_fields(line, separator);
    let first_fields = split(&first).map_err(|m| anyhow!("{name}:{first_line}: {m}"))?;
    let is_header = first_fields.iter().any(|f| number(f, separator).is_err());
    let header = is_header.then(|| first_fields.clone());
    let (cx, cy) = choose(columns, header.as_deref(), first_fields.len())
        .map_err(|m| anyhow!("{name}: {m}"))?;
    let label = |c: usize| match &header {
        Some(h) => format!("column '{}'", h[c]),
        None => format!("column {}", c + 1),
    };
    let mut points = Vec::new();
    let data = (!is_header).then_some(Ok((first_line, first))).into_iter().chain(rows);
    for row in data {
        let (line, text) = row.with_context(|| format!("{name}: cannot read"))?;
        let fields = split(&text).map_err(|m| anyhow!("{name}:{line}: {m}"))?;
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
    }
    Ok(points)
}

/// The 0-based x and y columns.
fn choose(
    columns: Option<&Columns>,
    header: Option<&[String]>,
    width: usize,
) -> Result<(usize, usize), String> {
    let names = || header.map(|h| h.join(", ")).unwrap_or_default();
    let find = |wanted: &str| {
        header.and_then(|h| h.iter().position(|n| n.trim().eq_ignore_ascii_case(wanted)))
    };
    let Some(columns) = columns else {
        if width == 2 {
            return Ok((0, 1));
        }
        if let Some(pair) = XY_NAMES.iter().find_map(|(x, y)| Some((find(x)?, find(y)?))) {
            return Ok(pair);
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
        Ok(_) => Err(format!("'{text}' is not finite")),
        Err(_) if text.is_empty() => Err("empty".to_string()),
        Err(_) => Err(format!("'{text}' is not a number")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str, columns: Option<&str>) -> Result<Vec<Point>> {
        let columns: Option<Columns> = columns.map(|c| c.parse().unwrap());
        read(text.as_bytes(), "t.csv", columns.as_ref(), 1000)
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
        assert_eq!(err, "t.csv: a table of 3 columns (a, b, c): choose x and y with --columns X,Y");
        let err = parse("a,b,c\n1,2,3\n", Some("a,q")).unwrap_err().to_string();
        assert_eq!(err, "t.csv: --columns: no column 'q' (the columns: a, b, c)");
        let err = parse("1,2,3\n", Some("x,y")).unwrap_err().to_string();
        assert!(err.contains("no header row"), "{err}");
        assert!(parse("1,2,3\n", Some("1,5")).unwrap_err().to_string().contains("column 5"));
        assert!(parse("\"a,b\n", None).unwrap_err().to_string().contains("not closed"));
        assert!(parse("x;y\n1;inf\n", None).unwrap_err().to_string().contains("not finite"));
        assert!("1".parse::<Columns>().is_err() && "0,1".parse::<Columns>().is_err());
        let many = read("x,y\n1,2\n3,4\n".as_bytes(), "t.csv", None, 1).unwrap_err();
        assert!(many.to_string().contains("more than 1 points"));
    }

    #[test]
    fn tables_are_told_from_plain_files() {
        assert!(
            is_table("x;y") && is_table("a,b,c") && is_table("\"x\",\"y\"") && is_table("x\ty")
        );
        assert!(!is_table("x,y") && !is_table("1.5, 2"));
    }
}
