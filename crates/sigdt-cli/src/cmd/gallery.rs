//! `sigdt gallery`: pictures of results beside their ground truth, with a Markdown page.
//!
//! Two galleries of the paper's evaluation: chosen cases through every method (its Table 1,
//! and with noisy sets its Fig. 15), and each method's failures on a labelled folder, read
//! from the `results.csv` of `sigdt bench` (its Fig. 22, for every method). Pictures are
//! drawn in-process, so a method is run again on each drawn case; failures are drawn only
//! for runs that finished (crashes and time-outs are listed by name), smallest case of each
//! category first.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use clap::builder::RangedU64ValueParser;
use clap::{ArgGroup, Args};
use sigdt::{Method, Options};
use sigdt_lab::dataset::{self, Case};
use sigdt_lab::render::{render_svg, Layers, RenderOptions};

use crate::bench::record::{read_results_csv, Outcome};
use crate::messages::note;

/// `sigdt gallery`.
#[derive(Debug, Args)]
#[command(group(ArgGroup::new("what").required(true).args(["cases", "failures"])))]
pub struct GalleryArgs {
    /// A labelled folder (index.csv, NAME.xy, NAME.gt).
    #[arg(value_name = "DATA")]
    pub data: PathBuf,
    /// Folder for the pictures and gallery.md.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Draw these cases of DATA through every method.
    #[arg(long, value_name = "C1,C2,...", value_delimiter = ',')]
    pub cases: Vec<String>,
    /// Draw each method's failures, from this results.csv of `sigdt bench` on DATA.
    #[arg(long, value_name = "RESULTS.csv")]
    pub failures: Option<PathBuf>,
    /// Methods, comma-separated, or 'all' [default: all; with --failures, the methods of
    /// the results].
    #[arg(long, value_name = "M1,M2,...|all", value_parser = crate::methods::list_parser())]
    pub method: Option<String>,
    /// With --failures: pictures per method.
    #[arg(long, value_name = "N", default_value_t = 6)]
    pub per_method: usize,
    /// With --failures: draw only cases of at most N points (larger ones are listed).
    #[arg(long, value_name = "N", default_value_t = 2000)]
    pub largest: usize,
    /// Width of each picture in pixels.
    #[arg(long, value_name = "PX", default_value_t = 260,
          value_parser = RangedU64ValueParser::<u32>::new().range(64..=4096))]
    pub width: u32,
}

/// Pictures per row of the Markdown tables (the paper's Table 1 is four wide).
const COLUMNS: usize = 4;

/// `sigdt gallery`.
pub fn run(args: &GalleryArgs) -> Result<()> {
    let index = dataset::read_index(&args.data)
        .with_context(|| format!("{}: not a labelled folder", args.data.display()))?;
    if std::fs::canonicalize(&args.out).ok() == std::fs::canonicalize(&args.data).ok()
        && args.out.exists()
    {
        bail!("--out {} is the data folder: choose another folder", args.out.display());
    }
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("{}: cannot create the folder", args.out.display()))?;
    let page = match &args.failures {
        Some(results) => failures(args, &index, results)?,
        None => cases(args, &index)?,
    };
    let path = args.out.join("gallery.md");
    crate::output::write_file(&path, page.as_bytes())?;
    note(&format!("wrote {}", path.display()));
    Ok(())
}

/// The methods of `--method`, or `default`.
fn methods(args: &GalleryArgs, default: Vec<Method>) -> Result<Vec<Method>> {
    match &args.method {
        Some(text) => Ok(crate::methods::list(text)?),
        None => Ok(default),
    }
}

/// Every asked case through every method, one table per case.
fn cases(args: &GalleryArgs, index: &[Case]) -> Result<String> {
    let methods = methods(args, Method::ALL.to_vec())?;
    let mut page = String::from("# Gallery\n\n");
    let _ = writeln!(
        page,
        "Every method on the same input (`{}`): the result in black, the ground truth in \
         green, missing edges dashed vermillion, extra edges blue. Written by `sigdt gallery`.\n",
        args.data.display()
    );
    for name in &args.cases {
        let Some(case) = index.iter().find(|c| &c.name == name) else {
            bail!("{}: no case '{name}' in index.csv", args.data.display());
        };
        let mut cells = Vec::new();
        for &method in &methods {
            let (file, verdict) = picture(args, case, method, Path::new("."))?;
            cells.push(format!("![{method} on {name}]({file})<br>`{method}`: {verdict}"));
        }
        let _ = writeln!(page, "## `{name}` ({} points, {})\n", case.n_points, case.category);
        page += &grid(&cells);
        page += "\n";
    }
    Ok(page)
}

/// Each method's failures from `results`, drawn smallest first per category.
fn failures(args: &GalleryArgs, index: &[Case], results: &Path) -> Result<String> {
    let file = std::fs::File::open(results)
        .with_context(|| format!("{}: cannot read the results", results.display()))?;
    let data = read_results_csv(std::io::BufReader::new(file))
        .with_context(|| format!("{}: not a results.csv of sigdt bench", results.display()))?;
    let default: Vec<Method> = data.methods.iter().filter_map(|m| m.parse().ok()).collect();
    let methods = methods(args, default)?;
    let mut page = String::from("# Failures per method\n\n");
    let _ = writeln!(
        page,
        "Cases of `{}` that each method does not reconstruct exactly, from `{}`. Up to {} \
         pictures per method, the smallest failing case of each category in turn; every \
         failing name is listed. The result in black, the ground truth in green, missing \
         edges dashed vermillion, extra edges blue. Written by `sigdt gallery --failures`.\n",
        args.data.display(),
        results.display(),
        args.per_method
    );
    for method in methods {
        let name = method.to_string();
        let mut failing: Vec<(&Case, String)> = Vec::new();
        for entry in data.entries.iter().filter(|e| e.method == name) {
            let row = &data.cases[entry.case].row;
            let why = match &entry.outcome {
                Outcome::Done(run) if run.exact => continue,
                Outcome::Done(run) => format!("{} missing, {} extra", run.missing, run.extra),
                Outcome::Failed(_) => "failed".to_string(),
                Outcome::TimedOut(s) => format!("timed out at {s} s"),
            };
            let Some(case) = index.iter().find(|c| c.name == row.name) else {
                bail!(
                    "{}: case '{}' is not in {}",
                    results.display(),
                    row.name,
                    args.data.display()
                );
            };
            failing.push((case, why));
        }
        let total = data.entries.iter().filter(|e| e.method == name).count();
        let _ = writeln!(page, "## `{name}`: {} of {total} cases not exact\n", failing.len());
        if failing.is_empty() {
            continue;
        }
        let drawable: Vec<&Case> = failing
            .iter()
            .filter(|(c, why)| c.n_points <= args.largest && why.contains("missing"))
            .map(|(c, _)| *c)
            .collect();
        let dir = PathBuf::from(&name);
        std::fs::create_dir_all(args.out.join(&dir))?;
        let mut cells = Vec::new();
        for case in pick(&drawable, args.per_method) {
            let (file, verdict) = picture(args, case, method, &dir)?;
            cells.push(format!("![{name} on {}]({file})<br>`{}`: {verdict}", case.name, case.name));
        }
        page += &grid(&cells);
        let names: Vec<String> =
            failing.iter().map(|(c, why)| format!("`{}` ({why})", c.name)).collect();
        let _ = writeln!(
            page,
            "\n<details><summary>All {} failing cases</summary>\n\n{}\n\n</details>\n",
            failing.len(),
            names.join(", ")
        );
    }
    Ok(page)
}

/// Up to `k` cases: the smallest of each category in turn (categories in order of first
/// appearance), ties by name.
fn pick<'a>(cases: &[&'a Case], k: usize) -> Vec<&'a Case> {
    let mut categories: Vec<(&str, Vec<&'a Case>)> = Vec::new();
    for &case in cases {
        match categories.iter_mut().find(|(c, _)| *c == case.category) {
            Some((_, list)) => list.push(case),
            None => categories.push((&case.category, vec![case])),
        }
    }
    for (_, list) in &mut categories {
        list.sort_by(|a, b| a.n_points.cmp(&b.n_points).then(a.name.cmp(&b.name)));
        list.reverse(); // popped from the end
    }
    let mut chosen = Vec::new();
    while chosen.len() < k && categories.iter().any(|(_, l)| !l.is_empty()) {
        for (_, list) in &mut categories {
            if chosen.len() < k {
                chosen.extend(list.pop());
            }
        }
    }
    chosen
}

/// Draws `method` on `case` into `OUT/dir/CASE.METHOD.svg`; returns the picture's path
/// relative to OUT and the verdict (exact, or missing and extra edges, and the status).
fn picture(
    args: &GalleryArgs,
    case: &Case,
    method: Method,
    dir: &Path,
) -> Result<(String, String)> {
    let files = case.files(&args.data);
    let points = crate::input::points_of_file(&files.points)?;
    let gt = sigdt_io::text::read_edges_of(&files.gt, points.len())?;
    let rec = sigdt::reconstruct(&points, &Options { method, ..Options::default() })
        .with_context(|| format!("{method} on {}", case.name))?;
    let diff = sigdt_lab::eval::edge_diff(&rec.edges, &gt);
    let own_vertices = matches!(rec.vertices, sigdt::Vertices::New(_));
    let verdict = if own_vertices {
        format!("{} vertices of its own", rec.vertex_positions(&points).len())
    } else if diff.missing.is_empty() && diff.extra.is_empty() {
        "exact".to_string()
    } else {
        format!("{} missing, {} extra", diff.missing.len(), diff.extra.len())
    };
    let verdict = format!("{verdict} ({})", rec.status.name());
    let layers = Layers { points: true, result: Some(&rec), gt: Some(&gt), ..Layers::default() };
    let options = RenderOptions {
        width_px: args.width,
        title: Some(format!("{method}: {verdict}")),
        legend: false,
    };
    let file = dir.join(format!("{}.{method}.svg", case.name));
    let path = args.out.join(&file);
    crate::output::write_file(&path, render_svg(&points, &layers, &options).as_bytes())?;
    Ok((file.to_string_lossy().trim_start_matches("./").to_string(), verdict))
}

/// `cells` as a Markdown table of [`COLUMNS`] columns without a header row's text.
fn grid(cells: &[String]) -> String {
    if cells.is_empty() {
        return String::new();
    }
    let width = COLUMNS.min(cells.len());
    let mut out = format!("|{}\n|{}\n", " |".repeat(width), " :-: |".repeat(width));
    for row in cells.chunks(width) {
        let mut line = String::from("|");
        for k in 0..width {
            let _ = write!(line, " {} |", row.get(k).map_or("", String::as_str));
        }
        out += &line;
        out += "\n";
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(name: &str, category: &str, n_points: usize) -> Case {
        Case { name: name.into(), category: category.into(), n_points, epsilon: None }
    }

    #[test]
    fn picks_the_smallest_of_each_category_in_turn() {
        let all = [
            case("a", "open", 50),
            case("b", "open", 10),
            case("c", "sharp", 30),
            case("d", "open", 10),
            case("e", "sharp", 20),
        ];
        let refs: Vec<&Case> = all.iter().collect();
        let names = |k| pick(&refs, k).iter().map(|c| c.name.clone()).collect::<Vec<_>>();
        assert_eq!(names(3), ["b", "e", "d"]);
        assert_eq!(names(9), ["b", "e", "d", "c", "a"]);
        assert!(names(0).is_empty());
    }

    #[test]
    fn grids_fill_rows_of_four() {
        let cells: Vec<String> = (0..5).map(|k| k.to_string()).collect();
        let g = grid(&cells);
        assert_eq!(g.lines().count(), 4);
        assert!(g.lines().nth(2).unwrap().starts_with("| 0 | 1 | 2 | 3 |"));
        assert_eq!(g.lines().nth(3).unwrap(), "| 4 |  |  |  |");
        assert_eq!(grid(&[]), "");
    }
}
