//! The cases of a labelled folder that a run asks for: the rows of its `index.csv`, read by
//! the lab's one reader ([`sigdt_lab::dataset`]), filtered by `--categories` and `--names`.

use std::path::Path;

use anyhow::{anyhow, bail, Result};
use sigdt_lab::dataset;

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
            && names.map_or(true, |pattern| row.name.contains(pattern))
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
    Ok(cases)
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
    }
}
