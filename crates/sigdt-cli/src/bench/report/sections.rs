//! The report's other sections: distances to the ground truth, proximity graphs, failures.
use super::summary::{bold_best, inline, mean, sci, table, Summary};
use crate::bench::record::{OverlapStat, Run};

/// The "Distance to ground truth" table: per category and method, the mean RMSE, Hausdorff
/// distance and symmetric area difference over the finished runs where each is defined.
pub(super) fn distance_section(s: &Summary) -> String {
    let metrics: [fn(&Run) -> Option<f64>; 3] = [|r| r.rmse, |r| r.hausdorff, |r| r.symdiff];
    let header: Vec<String> =
        ["Category", "Method", "finished runs", "RMSE", "Hausdorff", "sym. area diff."]
            .map(String::from)
            .to_vec();
    let mut rows = Vec::new();
    for category in s.categories() {
        let cases = s.in_category(&category);
        let mut block: Vec<Vec<String>> = Vec::new();
        let mut means: Vec<[Option<f64>; 3]> = Vec::new();
        for m in &s.data.methods {
            let runs: Vec<&Run> = cases.iter().filter_map(|&i| s.run(i, m)).collect();
            let mut row =
                vec![category.clone(), format!("`{}`", inline(m)), runs.len().to_string()];
            let mut row_means = [None; 3];
            for (k, metric) in metrics.iter().enumerate() {
                let values: Vec<f64> =
                    runs.iter().filter_map(|r| metric(r)).filter(|v| v.is_finite()).collect();
                row_means[k] = mean(values.iter().copied());
                row.push(match row_means[k] {
                    None => "–".into(),
                    Some(v) if values.len() == runs.len() => sci(v),
                    Some(v) => format!("{} ({} runs)", sci(v), values.len()),
                });
            }
            block.push(row);
            means.push(row_means);
        }
        for k in 0..3 {
            let mut cells: Vec<String> = block.iter().map(|row| row[3 + k].clone()).collect();
            let values: Vec<Option<f64>> = means.iter().map(|m| m[k]).collect();
            bold_best(&mut cells, &values, true);
            for (row, cell) in block.iter_mut().zip(cells) {
                row[3 + k] = cell;
            }
        }
        rows.extend(block);
    }
    let mut out = String::from("## Distance to ground truth\n\n");
    out += "Means over the finished runs where the measure is defined (the count is given when \
            that is fewer than the finished runs). RMSE (two-sided) and Hausdorff distance are \
            normalised by the ground truth's bounding-box diagonal, the symmetric difference of \
            area by its bounding-box area. The smallest mean of each category is in bold.\n\n";
    out += &table(&header, &rows, 2);
    out
}

/// The "Proximity graphs" table of the overlap statistics (`docs/algorithms.md` §4.10).
pub(super) fn overlap_section(overlap: &[OverlapStat]) -> String {
    let mut out = String::from("## Proximity graphs\n\n");
    if overlap.is_empty() {
        return out + "Not computed.\n";
    }
    out += "Per manifold case, then averaged over the cases; \"sets fully contained\" is the \
            percentage of cases where the first set lies entirely in the second.\n\n";
    let pct = |v: Option<f64>| v.map_or("–".into(), |v| format!("{v:.1} %"));
    let header: Vec<String> =
        ["Statistic", "ours", "sets fully contained", "paper"].map(String::from).to_vec();
    let rows: Vec<Vec<String>> = overlap
        .iter()
        .map(|o| {
            let ours = pct(Some(o.mean_percent).filter(|v| v.is_finite()));
            vec![inline(&o.name), ours, pct(o.sets_contained_percent), pct(o.paper_percent)]
        })
        .collect();
    out + &table(&header, &rows, 1)
}

/// The "Failures" section: the failed and timed-out runs of each method with their message,
/// then the non-exact cases per method and category, collapsed.
pub(super) fn failures_section(s: &Summary) -> String {
    use crate::bench::record::Outcome;
    let cases = &s.data.cases;
    let mut out = String::from("## Failures\n\n");
    for m in &s.data.methods {
        out += &format!("### `{}`\n\n", inline(m));
        let mut any = false;
        for (i, case) in cases.iter().enumerate() {
            let what = match s.outcome(i, m) {
                Some(Outcome::Failed(message)) => format!("failed: {}", inline(message)),
                Some(Outcome::TimedOut(limit)) => format!("timed out after {limit} s"),
                _ => continue,
            };
            any = true;
            let name = inline(&case.row.name);
            out += &format!(
                "- `{name}` ({}, n = {}): {what}\n",
                inline(&case.row.category),
                case.row.n_points
            );
        }
        out += if any { "\n" } else { "None.\n\n" };
    }

    out += "<details>\n<summary>Cases not reconstructed exactly, per method and category</summary>\n\n";
    for m in &s.data.methods {
        for category in s.categories() {
            let all = s.in_category(&category);
            let missed: Vec<String> = all
                .iter()
                .filter(|&&i| !s.run(i, m).is_some_and(|r| r.exact))
                .map(|&i| format!("`{}`", inline(&cases[i].row.name)))
                .collect();
            if !missed.is_empty() {
                out += &format!(
                    "- `{}`, {} ({} of {}): {}\n",
                    inline(m),
                    inline(&category),
                    missed.len(),
                    all.len(),
                    missed.join(", ")
                );
            }
        }
    }
    out + "\n</details>\n"
}
