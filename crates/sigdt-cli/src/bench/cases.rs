//! The cases of a labelled folder that a run asks for: the rows of its `index.csv`, read by
//! the lab's one reader ([`sigdt_lab::dataset`]), filtered by `--categories` and `--names`;
//! and their sample spacing and half, columns that reader does not keep.

use std::collections::HashMap;
use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use sigdt_lab::dataset;

use super::csv::parse_csv;
use super::record::Case;

/// The cases of the folder `dir`, in `index.csv` order, of `categories` (empty: all) and
/// whose name contains `names`.
pub fn select(dir: &Path, categories: &[String], names: Option<&str>) -> Result<Vec<Case>> {
    let rows = dataset::read_index(dir).map_err(|err| match err {
        sigdt::Error::Io { path, source } => {
            anyhow!("{path}: cannot read the case index: {source}")
        }
        err => err.into(),
    })?;
    let wanted = |row: &dataset::Case| {
        (categories.is_empty() || categories.contains(&row.category))
            && names.is_none_or(|pattern| row.name.contains(pattern))
    };
    let cases: Vec<Case> =
        rows.into_iter().filter(wanted).map(|row| Case { row, graph_epsilon: None }).collect();
    for case in &cases {
        let files = case.row.files(dir);
        let curve = files.curve.iter().flat_map(|(points, edges)| [points, edges]);
        for path in [&files.points, &files.gt].into_iter().chain(&files.truth).chain(curve) {
            // Parts of a run read case files in-process, outside the workers' time limit: a
            // named pipe there would block it forever. A missing file fails its case only.
            if path.exists() && !path.is_file() {
                bail!(
                    "{}: not a regular file (a case file cannot be a pipe or device)",
                    path.display()
                );
            }
        }
    }
    spacings(dir)?; // A malformed spacing fails the run now, not after the first workers.
    Ok(cases)
}

/// The `spacing` column of `index.csv` in `dir` (the spacing `s` the cases were sampled at),
/// by case name; empty when there is no such column, and without the cases whose field is
/// empty or `-` (unknown; a `nan` is an error, as for `epsilon`).
///
/// [`dataset::Case`] keeps only the columns every labelled folder has, so the column is read
/// here, from the file that [`select`] has already checked.
pub fn spacings(dir: &Path) -> Result<HashMap<String, f64>> {
    let path = dir.join("index.csv");
    let mut out = HashMap::new();
    for (line, case, text) in column(dir, "spacing")? {
        match text.as_str() {
            "" | "-" => {}
            text => match text.parse::<f64>() {
                Ok(s) if s.is_finite() && s > 0.0 => {
                    out.insert(case, s);
                }
                _ => bail!(
                    "{}:{line}: spacing '{text}' is not a number > 0 (write nothing or - if \
                     unknown)",
                    path.display()
                ),
            },
        }
    }
    Ok(out)
}

/// The `half` column of `index.csv` in `dir` (for example `design` and `held-out`: the half
/// of the cases a method was tuned on, and the half kept for checking it), by case name;
/// empty when there is no such column, and without the cases whose field is empty.
pub fn halves(dir: &Path) -> Result<HashMap<String, String>> {
    let fields = column(dir, "half")?;
    Ok(fields.into_iter().filter(|(_, _, half)| !half.is_empty()).map(|(_, c, h)| (c, h)).collect())
}

/// The column `name` of `index.csv` in `dir` as (line, case name, field), both trimmed, in
/// file order; nothing when there is no such column.
fn column(dir: &Path, name: &str) -> Result<Vec<(usize, String, String)>> {
    let path = dir.join("index.csv");
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("{}: cannot read the case index", path.display()))?;
    let records = parse_csv(text.strip_prefix('\u{feff}').unwrap_or(&text));
    let mut rows =
        records.iter().enumerate().filter(|(_, r)| r.iter().any(|f| !f.trim().is_empty()));
    let Some((_, header)) = rows.next() else { return Ok(Vec::new()) };
    let position = |column: &str| header.iter().position(|h| h.trim() == column);
    let (Some(case), Some(field)) = (position("name"), position(name)) else {
        return Ok(Vec::new());
    };
    let fields = rows
        .filter_map(|(k, row)| {
            let (case, text) = (row.get(case)?, row.get(field)?);
            Some((k + 1, case.trim().to_string(), text.trim().to_string()))
        })
        .collect();
    Ok(fields)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filters_by_category_and_name() {
        let dir = tempfile::tempdir().unwrap();
        let index = "name,category,n_points,epsilon\nab,manifold,10,0.5\nb,open,12,\nc,open,3,\n";
        std::fs::write(dir.path().join("index.csv"), index).unwrap();
        let names = |categories: &[&str], names: Option<&str>| -> Vec<String> {
            let categories: Vec<String> = categories.iter().map(|c| c.to_string()).collect();
            let cases = select(dir.path(), &categories, names).unwrap();
            cases.into_iter().map(|c| c.row.name).collect()
        };
        assert_eq!(names(&[], None), ["ab", "b", "c"]);
        assert_eq!(names(&["open"], None), ["b", "c"]);
        assert_eq!(names(&["open", "manifold"], Some("b")), ["ab", "b"]);
        let err = select(&dir.path().join("missing"), &[], None).unwrap_err().to_string();
        assert!(err.contains("index.csv: cannot read the case index"), "{err}");
        assert!(spacings(dir.path()).unwrap().is_empty());
    }

    #[test]
    fn reads_the_spacing_column() {
        let dir = tempfile::tempdir().unwrap();
        let index =
            "\u{feff}name,category,spacing,source\na,outline-clean,0.5,\"x, y\"\nb,open,,\n";
        std::fs::write(dir.path().join("index.csv"), index).unwrap();
        let s = spacings(dir.path()).unwrap();
        assert_eq!((s.len(), s.get("a")), (1, Some(&0.5)));
        std::fs::write(dir.path().join("index.csv"), "name,category,spacing\na,open,-1\n").unwrap();
        let err = select(dir.path(), &[], None).unwrap_err().to_string();
        assert!(err.contains("index.csv:2: spacing '-1'"), "{err}");
    }

    #[test]
    fn reads_the_half_column() {
        let dir = tempfile::tempdir().unwrap();
        let index = "name,half,category\na, design ,open\nb,held-out,open\nc,,open\n";
        std::fs::write(dir.path().join("index.csv"), index).unwrap();
        let halves = halves(dir.path()).unwrap();
        assert_eq!(halves.len(), 2);
        assert_eq!((halves["a"].as_str(), halves["b"].as_str()), ("design", "held-out"));
        std::fs::write(dir.path().join("index.csv"), "name,category\na,open\n").unwrap();
        assert!(super::halves(dir.path()).unwrap().is_empty());
    }
}
