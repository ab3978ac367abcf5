//! `write_report`: the Markdown report, the per-case CSV and the charts of a benchmark run.
use super::summary::{inline, table, Summary};
use super::{charts, curve, exact, numbers, sections};
use crate::bench::record::{write_results_csv, BenchData};
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// Writes the report of `data` into `out_dir` (created if needed) and returns the paths
/// written: `report.md`, `results.csv`, `numbers.json` (the report's counts, for programs),
/// `accuracy.svg`, `accuracy_eps.svg` (only when the
/// manifold cases have an ε in `index.csv`), `runtime.svg` and `symdiff_CATEGORY.svg` for
/// each of the open, multiple and non-manifold categories present.
///
/// The Markdown holds a header (command, data, machine, time limit, cases per category), the
/// exact-reconstruction table in the layout of the paper's Table 2, the results judged
/// against the true curve (when some case has one), the paper's Table 2 for reference, the
/// distances to the ground truth, the proximity-graph statistics, the failures and links to
/// the charts.
pub fn write_report(data: &BenchData, out_dir: &Path) -> io::Result<Vec<PathBuf>> {
    fs::create_dir_all(out_dir)?;
    let s = Summary::new(data);
    let mut written = Vec::new();
    let mut save = |name: &str, contents: &[u8]| -> io::Result<()> {
        let path = out_dir.join(name);
        crate::output::write_file(&path, contents).map_err(io::Error::other)?;
        written.push(path);
        Ok(())
    };

    let eps_chart = charts::accuracy_eps(&s);
    let mut md = header(&s);
    md += "\n";
    md += &exact::exact_section(&s);
    md += "\n![Exact reconstruction rate per method and category](accuracy.svg)\n";
    if eps_chart.is_some() {
        md += "\n![Exact rate of the manifold cases with ε ≤ x](accuracy_eps.svg)\n";
    }
    md += "\n";
    if let Some(section) = curve::curve_section(&s) {
        md += &section;
        md += "\n";
    }
    md += &exact::paper_section(&data.methods);
    md += "\n## Runtime\n\n![Runtime against number of points, log-log](runtime.svg)\n\n";
    md += &sections::distance_section(&s);
    let symdiff_charts: Vec<(String, String)> = charts::SYMDIFF_CATEGORIES
        .iter()
        .filter_map(|&c| Some((c.to_string(), charts::symdiff(&s, c)?)))
        .collect();
    for (category, _) in &symdiff_charts {
        md += &format!(
            "\n![Symmetric area difference per method, {category} cases](symdiff_{category}.svg)\n"
        );
    }
    md += "\n";
    md += &sections::overlap_section(&data.overlap);
    md += "\n";
    md += &sections::failures_section(&s);
    save("report.md", md.as_bytes())?;
    let mut csv = Vec::new();
    write_results_csv(data, &mut csv)?;
    save("results.csv", &csv)?;
    save("numbers.json", numbers::numbers_json(&s).as_bytes())?;
    save("accuracy.svg", charts::accuracy(&s).as_bytes())?;
    if let Some(svg) = eps_chart {
        save("accuracy_eps.svg", svg.as_bytes())?;
    }
    save("runtime.svg", charts::runtime(&s).as_bytes())?;
    for (category, svg) in &symdiff_charts {
        save(&format!("symdiff_{category}.svg"), svg.as_bytes())?;
    }
    Ok(written)
}

/// The title, the run's facts and the number of cases per category.
fn header(s: &Summary) -> String {
    let data = s.data;
    let methods: Vec<String> = data.methods.iter().map(|m| code(m)).collect();
    let mut out = String::from("# Benchmark report\n\n");
    out += &format!("- Command: {}\n", code(&data.command));
    out += &format!("- Data: {}\n", code(&data.data_dir));
    out += &format!("- Machine: {}\n", inline(&data.machine));
    out += &format!("- Time limit: {} s per run\n", data.time_limit_s);
    out += &format!("- Methods: {}\n\n", methods.join(", "));

    let header: Vec<String> = ["Category", "cases", "points (min–max)"].map(String::from).to_vec();
    let mut rows: Vec<Vec<String>> = s
        .categories()
        .into_iter()
        .map(|category| {
            let n: Vec<usize> =
                s.in_category(&category).iter().map(|&i| data.cases[i].row.n_points).collect();
            let (lo, hi) = (n.iter().min().unwrap_or(&0), n.iter().max().unwrap_or(&0));
            vec![inline(&category), n.len().to_string(), format!("{lo}–{hi}")]
        })
        .collect();
    rows.push(vec!["all".into(), data.cases.len().to_string(), String::new()]);
    out + &table(&header, &rows, 1)
}

/// `s` as inline code, whatever backticks it holds.
fn code(s: &str) -> String {
    let s = inline(s);
    if s.contains('`') {
        format!("`` {s} ``")
    } else {
        format!("`{s}`")
    }
}
