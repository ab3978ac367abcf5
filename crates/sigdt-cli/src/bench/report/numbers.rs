//! `numbers.json`: the report's figures for programs, as flat rows of counts. No times and no
//! percentages (a reader computes them from the counts), so the file changes only when the
//! results do.
//!
//! ```json
//! {"folder": "data/outlines", "rows": [
//!   {"method": "sig-auto", "category": "outline-clean", "half": "all", "cases": 75,
//!    "exact": 71, "judged": 75, "good": 72, "good_silent": 70, "good_warned": 2,
//!    "silent_wrong": 0, "warned": 5, "outliers": 0, "outliers_left_out": 0,
//!    "clean_points_left_out": 3, "cases_with_clean_points_left_out": 1},
//!   ...]}
//! ```
//!
//! One row per method × category × half, in the report's order: the methods, then per
//! method the categories, `manifold eps<1` (the manifold cases whose `epsilon` in
//! `index.csv` is below the threshold, when the folder gives it: the paper's ε < 1 column)
//! and `all`, then per category the half `all` and, when `index.csv` has a `half` column,
//! each half (`design`, `held-out`).
use serde_json::Value;

use super::summary::Summary;
use crate::bench::record::CurveScore;

/// The text of `numbers.json`, one row a line.
pub(super) fn numbers_json(s: &Summary) -> String {
    let mut groups: Vec<(String, Vec<usize>)> =
        s.categories().into_iter().map(|c| (c.clone(), s.in_category(&c))).collect();
    if let Some(cases) = s.well_sampled(false) {
        groups.push(("manifold eps<1".into(), cases));
    }
    groups.push(("all".into(), (0..s.data.cases.len()).collect()));
    let halves: Vec<String> = ["all".to_string()].into_iter().chain(s.halves()).collect();
    let mut rows = Vec::new();
    for method in &s.data.methods {
        for (category, cases) in &groups {
            for half in &halves {
                let in_half = |&&i: &&usize| half == "all" || s.data.half(i) == half;
                let cases: Vec<usize> = cases.iter().filter(in_half).copied().collect();
                rows.push(row(s, method, category, half, &cases));
            }
        }
    }
    let folder = Value::String(s.data.data_dir.clone());
    format!("{{\n  \"folder\": {folder},\n  \"rows\": [\n{}\n  ]\n}}\n", rows.join(",\n"))
}

/// The row of `method` on `cases`, as one line of JSON.
fn row(s: &Summary, method: &str, category: &str, half: &str, cases: &[usize]) -> String {
    let text = |v: &str| Value::String(v.to_string()).to_string();
    let count = |n: Option<usize>| n.map_or("null".to_string(), |n| n.to_string());
    let exact = cases.iter().filter(|&&i| s.run(i, method).is_some_and(|r| r.exact)).count();
    let judged: Vec<usize> = cases.iter().copied().filter(|&i| s.has_curve(i)).collect();
    let scores: Vec<&CurveScore> =
        judged.iter().filter_map(|&i| s.run(i, method)?.curve.as_ref()).collect();
    let curve = |f: fn(&CurveScore) -> bool| {
        (!judged.is_empty()).then(|| scores.iter().filter(|c| f(c)).count())
    };
    let left_out: Vec<_> = scores.iter().filter_map(|c| c.left_out).collect();
    let sum = |f: fn(&crate::bench::record::LeftOut) -> usize| {
        (!left_out.is_empty()).then(|| left_out.iter().map(f).sum::<usize>())
    };
    let fields = [
        ("method", text(method)),
        ("category", text(category)),
        ("half", text(half)),
        ("cases", cases.len().to_string()),
        ("exact", exact.to_string()),
        ("judged", judged.len().to_string()),
        ("good", count(curve(CurveScore::good))),
        ("good_silent", count(curve(CurveScore::good_silent))),
        ("good_warned", count(curve(CurveScore::good_warned))),
        ("silent_wrong", count(curve(CurveScore::silent_wrong))),
        ("warned", count(curve(|c| c.warned))),
        ("outliers", count(sum(|l| l.outliers))),
        ("outliers_left_out", count(sum(|l| l.outliers_left_out))),
        ("clean_points_left_out", count(sum(|l| l.curve_points_left_out))),
        (
            "cases_with_clean_points_left_out",
            count(sum(|l| usize::from(l.curve_points_left_out > 0))),
        ),
    ];
    let fields: Vec<String> = fields.iter().map(|(k, v)| format!("\"{k}\": {v}")).collect();
    format!("    {{{}}}", fields.join(", "))
}
