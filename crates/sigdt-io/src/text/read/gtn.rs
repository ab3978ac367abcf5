//! The `.gtn` point format of Dey's CurveRecon: a header `N 2 0 0`, then exactly `N` lines
//! `index x y` with indices `0, 1, ..., N-1` in order.

use std::io::BufRead;

use super::lines::{coordinate, quoted, too_many, Lines};
use sigdt::Point;
use sigdt::Result;

/// Gtn points: the header `N 2 0 0`, then `N` lines `index x y`.
pub(super) fn gtn<R: BufRead>(lines: &mut Lines<R>, max_points: usize) -> Result<Vec<Point>> {
    let Some(header) = lines.next_content()? else {
        return Err(lines.error("missing .gtn header 'N 2 0 0'".to_string()));
    };
    let n = gtn_header(header).map_err(|message| lines.error(message))?;
    if n > max_points {
        return Err(lines.error(too_many(max_points)));
    }
    // The header is untrusted: reserve at most 1M points up front.
    let mut points = Vec::with_capacity(n.min(1 << 20));
    while let Some(line) = lines.next_content()? {
        if points.len() == n {
            // Stop here: counting the rest would read an endless stream forever.
            let message = format!("header says {n} points, but the file goes on past them");
            return Err(lines.error(message));
        }
        points.push(gtn_point(line, points.len()).map_err(|message| lines.error(message))?);
    }
    if points.len() < n {
        return Err(lines.error(format!("header says {n} points, file has {}", points.len())));
    }
    Ok(points)
}

/// Whether `line` looks like a gtn header: exactly four integers, the second being 2.
pub(super) fn is_gtn_header(line: &str) -> bool {
    line.split_ascii_whitespace().count() == 4 && gtn_header(line).is_ok()
}

/// The point count `N` of a gtn header `N 2 0 0` (trailing tokens must be integers).
fn gtn_header(line: &str) -> Result<usize, String> {
    let (mut n, mut count) = (0, 0);
    for token in line.split_ascii_whitespace() {
        let v: i64 = token.parse().map_err(|_| {
            format!("gtn header: {} is not an integer (expected 'N 2 0 0')", quoted(token))
        })?;
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
                Err(_) => return Err(format!("{} is not a point index", quoted(token))),
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

#[cfg(test)]
mod tests {
    use crate::text::read::lines::tests::error;
    use crate::text::{parse_points, PointFormat};
    use sigdt::Point;
    use sigdt::Result;

    fn parse(text: &str, format: Option<PointFormat>) -> Result<Vec<Point>> {
        parse_points(text.as_bytes(), "t.xy", format)
    }

    #[test]
    fn gtn_errors_name_line_and_token() {
        use PointFormat::Gtn;
        let header = "gtn header: expected 'N 2 0 0', found 1 number(s)";
        let cases = [
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
            (
                "1 2 0 0\n0 0 0\n1 1 1\n\n2 2 2\n",
                None,
                "3: header says 1 points, but the file goes on past them",
            ),
        ];
        for (text, format, expected) in cases {
            assert_eq!(error(parse(text, format)), expected, "{text:?}");
        }
    }

    #[test]
    fn gtn_padded_header_and_tabs() {
        let text = "     3 2 0 0\n0\t41.636364 3.636364\n     1\t41.7 3.6\r\n2 -1 1e2\n\n";
        let expected = vec![[41.636364, 3.636364], [41.7, 3.6], [-1.0, 100.0]];
        assert_eq!(parse(text, Some(PointFormat::Gtn)).unwrap(), expected);
        assert_eq!(parse(text, None).unwrap(), expected);
        assert!(parse("0 2 0 0\n", None).unwrap().is_empty());
    }
}
