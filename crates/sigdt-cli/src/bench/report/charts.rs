//! The report's charts, built from the benchmark data.
use super::exact::rate_columns;
use super::summary::Summary;
use crate::bench::chart::{box_plots, grouped_bars, line_chart, log_log_scatter};

/// `accuracy.svg`: the exact rate per method in each column of the exact-rate table.
pub(super) fn accuracy(s: &Summary) -> String {
    let columns = rate_columns(s);
    let groups: Vec<String> =
        columns.iter().map(|(title, _)| title.replace("<sub>ours</sub>", " ours")).collect();
    let series: Vec<(String, Vec<Option<f64>>)> = s
        .data
        .methods
        .iter()
        .map(|m| (m.clone(), columns.iter().map(|(_, cases)| s.rate(m, cases).percent()).collect()))
        .collect();
    grouped_bars("Exact reconstruction rate", "exact (%)", &groups, &series)
}

/// `accuracy_eps.svg`: for each ε of a manifold case (from `index.csv`), the exact rate over
/// the manifold cases sampled at least that densely; `None` without any ε.
pub(super) fn accuracy_eps(s: &Summary) -> Option<String> {
    let cases = &s.data.cases;
    let mut by_eps: Vec<(f64, usize)> = s
        .in_category("manifold")
        .into_iter()
        .filter_map(|i| Some((cases[i].row.epsilon.filter(|e| e.is_finite())?, i)))
        .collect();
    if by_eps.is_empty() {
        return None;
    }
    by_eps.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let series: Vec<(String, Vec<(f64, f64)>)> = s
        .data
        .methods
        .iter()
        .map(|m| {
            let mut exact = 0;
            let mut points: Vec<(f64, f64)> = Vec::new();
            for (k, &(eps, i)) in by_eps.iter().enumerate() {
                exact += usize::from(s.run(i, m).is_some_and(|r| r.exact));
                let rate = 100.0 * exact as f64 / (k + 1) as f64;
                // One point per distinct ε: the last case with that ε has the full count.
                if !matches!(by_eps.get(k + 1), Some(next) if next.0 == eps) {
                    points.push((eps, rate));
                }
            }
            (m.clone(), points)
        })
        .collect();
    let title = "Exact rate of manifold cases with ε ≤ x";
    Some(line_chart(title, "ε (index.csv)", "exact (%)", true, false, &series))
}

/// `runtime.svg`: the runtime of every finished run against its number of points.
pub(super) fn runtime(s: &Summary) -> String {
    let series: Vec<(String, Vec<(f64, f64)>)> = s
        .data
        .methods
        .iter()
        .map(|m| {
            let points = (0..s.data.cases.len())
                .filter_map(|i| Some((s.data.cases[i].row.n_points as f64, s.run(i, m)?.time_ms)))
                .collect();
            (m.clone(), points)
        })
        .collect();
    log_log_scatter("Runtime", "number of points", "time (ms)", &series)
}

/// The categories whose symmetric area difference gets a chart of its own: those where exact
/// rates say little ([MOW22] Figs. 10, 11 and 19).
pub(super) const SYMDIFF_CATEGORIES: [&str; 3] = ["open", "multiple", "non-manifold"];

/// `symdiff_CATEGORY.svg`: per method, the distribution of the symmetric area difference over
/// the category's cases where the method finished and the measure is defined; `None` when the
/// data has no case of `category`.
pub(super) fn symdiff(s: &Summary, category: &str) -> Option<String> {
    let cases = s.in_category(category);
    if cases.is_empty() {
        return None;
    }
    let series: Vec<(String, Vec<f64>)> = s
        .data
        .methods
        .iter()
        .map(|m| (m.clone(), cases.iter().filter_map(|&i| s.run(i, m)?.symdiff).collect()))
        .collect();
    let title = format!("Symmetric area difference, {category} ({} cases)", cases.len());
    Some(box_plots(&title, "area difference / ground-truth box area", &series))
}
