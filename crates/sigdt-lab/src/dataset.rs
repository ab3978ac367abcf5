//! Labelled folders in the layout of `data/curves` and `data/real`: `index.csv` with one row
//! per case (`name,category,n_points,...,epsilon,...`), and beside it `NAME.xy` points with
//! `NAME.gt` ground-truth edges. An optional `NAME.truth.xy` holds the clean positions of
//! noisy points (same indices), to measure distances against the clean curve; an optional
//! `NAME.curve.xy` with `NAME.curve.gt` holds the curve the points were sampled from, densely
//! (a polyline of its own points), to measure distances and areas against the curve itself.
//!
//! This is the one reader of such folders: the benchmark, the golden tests and the examples
//! all go through it. `index.csv` is read as CSV: a UTF-8 byte-order mark is skipped, fields
//! may be quoted (`"a,b"`, with `""` for a quote), blank lines are skipped, and every problem
//! is an error naming the file and line, as is a case listed twice.
use std::collections::{BTreeMap, HashSet};
use std::path::{Path, PathBuf};

use sigdt::{Edge, Error, Point, Result};

/// One labelled point set of a folder: a row of its `index.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// File stem: the points are `NAME.xy`, the ground truth `NAME.gt`.
    pub name: String,
    /// Category: manifold, sharp, open, multiple, noisy, outliers, bezier or large.
    pub category: String,
    /// Number of input points (0 when the column is missing or empty).
    pub n_points: usize,
    /// The sampling ε of the ground truth, from the `epsilon` column (empty: unknown).
    pub epsilon: Option<f64>,
}

/// The files of one case.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CaseFiles {
    /// `NAME.xy`.
    pub points: PathBuf,
    /// `NAME.gt`.
    pub gt: PathBuf,
    /// `NAME.truth.xy`, when it exists.
    pub truth: Option<PathBuf>,
    /// `NAME.curve.xy` and `NAME.curve.gt`, when the first exists (the second must then
    /// exist too: reading it fails otherwise).
    pub curve: Option<(PathBuf, PathBuf)>,
}

/// The cases of the folder `dir`, in `index.csv` order.
///
/// # Errors
/// [`Error::Io`] when `index.csv` cannot be read, [`Error::Parse`] (file and line) for a
/// missing `name` or `category` column, a row with too few fields, a name that is not a
/// file stem (empty, with a path separator, starting with `.`, or with a control character
/// such as NUL, which would be written into the report), a category with a control
/// character, a number that is not a number ≥ 0, or a name listed twice. A number given as
/// nothing, `-`, `nan` or `NaN` is unknown (`None`).
pub fn read_index(dir: &Path) -> Result<Vec<Case>> {
    let path = dir.join("index.csv");
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(&path)
        .map_err(|source| Error::Io { path: shown.clone(), source })?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let error = |line: usize, message: String| Error::Parse { path: shown.clone(), line, message };
    let mut rows = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let Some((_, header)) = rows.next() else {
        return Err(error(1, "empty index, expected a header".into()));
    };
    let header = fields(header).map_err(|m| error(1, m))?;
    let column = |name: &str| header.iter().position(|h| h == name);
    let (Some(name_col), Some(category_col)) = (column("name"), column("category")) else {
        return Err(error(1, "the header must name the columns 'name' and 'category'".into()));
    };
    let (points_col, epsilon_col) = (column("n_points"), column("epsilon"));
    let mut cases = Vec::new();
    let mut seen = HashSet::new();
    for (k, row) in rows {
        let line = k + 1;
        let fields = fields(row).map_err(|m| error(line, m))?;
        if fields.len() < header.len() {
            let message = format!("{} fields, the header has {}", fields.len(), header.len());
            return Err(error(line, message));
        }
        let name = fields[name_col].clone();
        let control = |text: &str| text.chars().any(char::is_control);
        if name.is_empty() || name.contains(['/', '\\']) || name.starts_with('.') || control(&name)
        {
            let shown = sigdt_io::text::quoted(&name);
            return Err(error(line, format!("{shown} is not a case name (a file stem)")));
        }
        if control(&fields[category_col]) {
            let shown = sigdt_io::text::quoted(&fields[category_col]);
            return Err(error(line, format!("{shown} is not a category (a control character)")));
        }
        if !seen.insert(name.clone()) {
            return Err(error(line, format!("case '{name}' is listed twice")));
        }
        let number = |col: Option<usize>, what: &str| -> Result<Option<f64>> {
            // Unknown is written as nothing or `-`; a NaN is more often a computation gone
            // wrong than a choice (issue 47), so it is refused with the rest.
            match col.map(|c| fields[c].as_str()) {
                None | Some("" | "-") => Ok(None),
                Some(text) => match text.parse::<f64>() {
                    Ok(v) if v.is_finite() && v >= 0.0 => Ok(Some(v)),
                    _ => Err(error(
                        line,
                        format!(
                            "{what} '{text}' is not a number >= 0 (write nothing or - if unknown)"
                        ),
                    )),
                },
            }
        };
        cases.push(Case {
            n_points: number(points_col, "n_points")?.unwrap_or(0.0) as usize,
            epsilon: number(epsilon_col, "epsilon")?,
            category: fields[category_col].clone(),
            name,
        });
    }
    Ok(cases)
}

impl Case {
    /// The files of this case in `dir`.
    pub fn files(&self, dir: &Path) -> CaseFiles {
        let truth = dir.join(format!("{}.truth.xy", self.name));
        let curve = dir.join(format!("{}.curve.xy", self.name));
        CaseFiles {
            points: dir.join(format!("{}.xy", self.name)),
            gt: dir.join(format!("{}.gt", self.name)),
            truth: truth.is_file().then_some(truth),
            curve: curve.is_file().then(|| (curve, dir.join(format!("{}.curve.gt", self.name)))),
        }
    }

    /// The points and the ground-truth edges (as `[i, j]` with `i < j`, sorted) of this
    /// case in `dir`.
    ///
    /// # Errors
    /// As [`sigdt_io::text::read_points`] and [`sigdt_io::text::read_edges`]; an edge index past the
    /// points is [`Error::Parse`] naming the ground-truth file.
    pub fn read(&self, dir: &Path) -> Result<(Vec<Point>, Vec<Edge>)> {
        let files = self.files(dir);
        let points = sigdt_io::text::read_points(&files.points)?;
        let mut gt: Vec<Edge> = sigdt_io::text::read_edges(&files.gt)?
            .into_iter()
            .map(|[i, j]| [i.min(j), i.max(j)])
            .collect();
        gt.sort_unstable();
        if let Some(&[i, j]) = gt.iter().find(|e| e[1] >= points.len()) {
            return Err(Error::Parse {
                path: files.gt.display().to_string(),
                line: 0,
                message: format!("edge [{i}, {j}] refers past the {} points", points.len()),
            });
        }
        Ok((points, gt))
    }
}

/// The labelled folder `folder` of the repository's `data/` (`curves`, `real`), or the folder
/// named by the environment variable `SIGDT_DATA` when it is set.
pub fn data_dir(folder: &str) -> PathBuf {
    std::env::var_os("SIGDT_DATA")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data").join(folder))
}

/// The fields of one CSV row: separated by commas, trimmed, optionally quoted.
fn fields(row: &str) -> std::result::Result<Vec<String>, String> {
    let mut out = Vec::new();
    let mut chars = row.chars().peekable();
    loop {
        let mut field = String::new();
        while chars.peek().is_some_and(|c| *c == ' ' || *c == '\t') {
            chars.next();
        }
        if chars.peek() == Some(&'"') {
            chars.next();
            loop {
                match chars.next() {
                    Some('"') if chars.peek() == Some(&'"') => {
                        chars.next();
                        field.push('"');
                    }
                    Some('"') => break,
                    Some(c) => field.push(c),
                    None => return Err("a quoted field is not closed".into()),
                }
            }
            while chars.peek().is_some_and(|c| *c != ',') {
                if !chars.next().is_some_and(char::is_whitespace) {
                    return Err("text after a quoted field".into());
                }
            }
        } else {
            while let Some(&c) = chars.peek().filter(|c| **c != ',') {
                field.push(c);
                chars.next();
            }
            field = field.trim().to_string();
        }
        out.push(field);
        if chars.next().is_none() {
            return Ok(out);
        }
    }
}

/// The row label of the manifold cases sampled with ε < 1 (the paper's Fig. 12).
pub const EPS_BELOW_1: &str = "manifold eps<1";

/// Exact reconstructions per row for several variants of a method (ratios, switched-off
/// steps, readings of a paper): a row per category, plus [`EPS_BELOW_1`]. The research
/// examples print it as their table.
#[derive(Debug, Clone, Default)]
pub struct ExactTally {
    /// Per row label: the number of cases, and the exact count of each variant.
    rows: BTreeMap<String, (usize, Vec<usize>)>,
}

impl ExactTally {
    /// Counts `case`, where `exact[k]` says whether variant `k` reconstructed it exactly.
    pub fn add(&mut self, case: &Case, exact: &[bool]) {
        let mut labels = vec![case.category.as_str()];
        if case.category == "manifold" && case.epsilon.is_some_and(|e| e < 1.0) {
            labels.push(EPS_BELOW_1);
        }
        for label in labels {
            let entry =
                self.rows.entry(label.to_string()).or_insert_with(|| (0, vec![0; exact.len()]));
            entry.0 += 1;
            for (count, &ok) in entry.1.iter_mut().zip(exact) {
                *count += usize::from(ok);
            }
        }
    }

    /// The rows in label order: label, number of cases, exact count per variant.
    pub fn rows(&self) -> impl Iterator<Item = (&str, usize, &[usize])> {
        self.rows.iter().map(|(label, (cases, exact))| (label.as_str(), *cases, &exact[..]))
    }

    /// The row of `label`, if any case had it.
    pub fn row(&self, label: &str) -> Option<(usize, &[usize])> {
        self.rows.get(label).map(|(cases, exact)| (*cases, &exact[..]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn index(text: &str) -> Result<Vec<Case>> {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("index.csv"), text).unwrap();
        read_index(dir.path())
    }

    #[test]
    fn reads_rows() {
        let cases =
            index("name,category,n_points,epsilon\na,manifold,10,0.5\nb,open,12,\n").unwrap();
        assert_eq!(cases.len(), 2);
        assert_eq!((cases[0].n_points, cases[0].epsilon), (10, Some(0.5)));
        assert_eq!(cases[1].epsilon, None);
    }

    #[test]
    fn a_bom_and_quoted_fields_are_read() {
        let cases =
            index("\u{feff}name,category,source\n\"a\",manifold,\"font:x, \"\"y\"\"\"\n").unwrap();
        assert_eq!((cases[0].name.as_str(), cases[0].category.as_str()), ("a", "manifold"));
        assert_eq!(fields(r#"a, "b,c" ,"d""e""#).unwrap(), ["a", "b,c", "d\"e"]);
        assert!(fields(r#"a,"b"#).unwrap_err().contains("not closed"));
    }

    #[test]
    fn errors_name_file_and_line() {
        let err = index("name,category,epsilon\na,manifold,x\n").unwrap_err().to_string();
        assert!(err.contains("index.csv:2:") && err.contains("'x'"), "{err}");
        // Issue 47: a NaN is refused, not read as unknown.
        let err = index("name,category,epsilon\na,open,\nb,manifold,nan\n").unwrap_err();
        let err = err.to_string();
        assert!(err.contains("index.csv:3:") && err.contains("epsilon 'nan'"), "{err}");
        let err = index("name,kind\n").unwrap_err().to_string();
        assert!(err.contains("index.csv:1:"), "{err}");
        let err = index("name,category\n../x,open\n").unwrap_err().to_string();
        assert!(err.contains("not a case name"), "{err}");
        // Issue 30, G19: a NUL was written into results.csv and report.md.
        let err = index("name,category\na\u{0}b,open\n").unwrap_err().to_string();
        assert!(err.ends_with(":2: 'a\\u{0}b' is not a case name (a file stem)"), "{err}");
        let err = index("name,category\nab,op\u{1b}en\n").unwrap_err().to_string();
        assert!(err.contains("is not a category"), "{err}");
        let err = index("name,category\na,open\n\na,sharp\n").unwrap_err().to_string();
        assert!(err.contains("index.csv:4:") && err.contains("listed twice"), "{err}");
    }

    #[test]
    fn a_tally_counts_each_variant_per_category_and_eps_below_1() {
        let cases = index("name,category,epsilon\na,manifold,0.5\nb,manifold,1.5\nc,open,\n");
        let cases = cases.unwrap();
        let mut tally = ExactTally::default();
        for (case, exact) in cases.iter().zip([[true, false], [true, true], [false, true]]) {
            tally.add(case, &exact);
        }
        let rows: Vec<(&str, usize, Vec<usize>)> =
            tally.rows().map(|(l, n, e)| (l, n, e.to_vec())).collect();
        assert_eq!(
            rows,
            [("manifold", 2, vec![2, 1]), (EPS_BELOW_1, 1, vec![1, 0]), ("open", 1, vec![0, 1])]
        );
        assert_eq!(tally.row("sharp"), None);
    }
}
