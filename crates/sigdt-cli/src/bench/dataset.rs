//! A labelled data folder in the `../shared/data` layout: `index.csv` with one row per case
//! (`name,category,n_points,...,epsilon,...`), and `NAME.xy` points with `NAME.gt`
//! ground-truth edges beside it. An optional `NAME.truth.xy` holds the clean positions of
//! noisy points (same indices); distances are then measured against the clean curve.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use super::record::Case;

/// The cases of the folder `dir`, in `index.csv` order, filtered by `categories` (empty:
/// all) and by a substring of the name.
pub fn read_index(dir: &Path, categories: &[String], names: Option<&str>) -> Result<Vec<Case>> {
    let path = dir.join("index.csv");
    let shown = path.display();
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("{shown}: cannot read the case index"))?;
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let Some((_, header)) = lines.next() else {
        bail!("{shown}:1: empty index, expected a header")
    };
    let header: Vec<&str> = header.split(',').map(str::trim).collect();
    let column = |name: &str| header.iter().position(|h| *h == name);
    let (Some(name_col), Some(category_col)) = (column("name"), column("category")) else {
        bail!("{shown}:1: the header must name the columns 'name' and 'category'");
    };
    let (points_col, epsilon_col) = (column("n_points"), column("epsilon"));
    let mut cases = Vec::new();
    for (k, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() < header.len() {
            bail!("{shown}:{}: {} fields, the header has {}", k + 1, fields.len(), header.len());
        }
        let name = fields[name_col].to_string();
        if name.is_empty() || name.contains(['/', '\\']) || name.starts_with('.') {
            bail!("{shown}:{}: '{name}' is not a case name (a file stem)", k + 1);
        }
        let number = |col: Option<usize>, what: &str| -> Result<Option<f64>> {
            match col.map(|c| fields[c]) {
                None | Some("" | "-" | "nan" | "NaN") => Ok(None),
                Some(text) => match text.parse::<f64>() {
                    Ok(v) if v.is_finite() && v >= 0.0 => Ok(Some(v)),
                    _ => bail!("{shown}:{}: {what} '{text}' is not a number >= 0", k + 1),
                },
            }
        };
        let case = Case {
            name,
            category: fields[category_col].to_string(),
            n_points: number(points_col, "n_points")?.unwrap_or(0.0) as usize,
            epsilon: number(epsilon_col, "epsilon")?,
            graph_epsilon: None,
        };
        let wanted = categories.is_empty() || categories.contains(&case.category);
        if wanted && names.map_or(true, |pattern| case.name.contains(pattern)) {
            cases.push(case);
        }
    }
    Ok(cases)
}

/// The files of case `name` in `dir`: points, ground truth and optional clean positions.
pub fn case_files(dir: &Path, name: &str) -> (PathBuf, PathBuf, Option<PathBuf>) {
    let truth = dir.join(format!("{name}.truth.xy"));
    (
        dir.join(format!("{name}.xy")),
        dir.join(format!("{name}.gt")),
        truth.is_file().then_some(truth),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn index(text: &str) -> Result<Vec<Case>> {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("index.csv"), text).unwrap();
        read_index(dir.path(), &[], None)
    }

    #[test]
    fn reads_rows_and_filters() {
        let cases =
            index("name,category,n_points,epsilon\na,manifold,10,0.5\nb,open,12,\n").unwrap();
        assert_eq!(cases.len(), 2);
        assert_eq!((cases[0].n_points, cases[0].epsilon), (10, Some(0.5)));
        assert_eq!(cases[1].epsilon, None);
    }

    #[test]
    fn errors_name_file_and_line() {
        let err = index("name,category,epsilon\na,manifold,x\n").unwrap_err().to_string();
        assert!(err.contains("index.csv:2:") && err.contains("'x'"), "{err}");
        let err = index("name,kind\n").unwrap_err().to_string();
        assert!(err.contains("index.csv:1:"), "{err}");
        let err = index("name,category\n../x,open\n").unwrap_err().to_string();
        assert!(err.contains("not a case name"), "{err}");
    }
}
