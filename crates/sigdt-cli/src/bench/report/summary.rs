//! What the report's sections share: lookups, rates, number formats and Markdown tables.
use crate::bench::record::{BenchData, Outcome, Run};
use std::collections::HashMap;

/// The categories of the data folder, in the order of the paper's tables.
const CATEGORY_ORDER: [&str; 8] =
    ["manifold", "sharp", "open", "multiple", "noisy", "outliers", "bezier", "large"];

/// The halves of a data folder (`index.csv`'s `half` column) in the order they are shown:
/// the cases a method was designed on, then those held out to check it.
const HALF_ORDER: [&str; 2] = ["design", "held-out"];

/// The benchmark data with its entries indexed by (case, method).
pub(super) struct Summary<'a> {
    pub data: &'a BenchData,
    outcomes: HashMap<(usize, &'a str), &'a Outcome>,
}

impl<'a> Summary<'a> {
    pub fn new(data: &'a BenchData) -> Self {
        let outcomes = data.entries.iter().map(|e| ((e.case, e.method.as_str()), &e.outcome));
        Summary { data, outcomes: outcomes.collect() }
    }

    /// The outcome of `method` on case `case`, if it was run.
    pub fn outcome(&self, case: usize, method: &str) -> Option<&'a Outcome> {
        self.outcomes.get(&(case, method)).copied()
    }

    /// The run of `method` on case `case`, if it finished.
    pub fn run(&self, case: usize, method: &str) -> Option<&'a Run> {
        match self.outcome(case, method)? {
            Outcome::Done(run) => Some(run),
            _ => None,
        }
    }

    /// The categories present: the paper's order first, then any others alphabetically.
    pub fn categories(&self) -> Vec<String> {
        let mut present: Vec<&str> =
            self.data.cases.iter().map(|c| c.row.category.as_str()).collect();
        present.sort_by_key(|c| (CATEGORY_ORDER.iter().position(|o| o == c), *c));
        present.dedup();
        let (mut known, others): (Vec<&str>, Vec<&str>) =
            present.into_iter().partition(|c| CATEGORY_ORDER.contains(c));
        known.extend(others);
        known.into_iter().map(String::from).collect()
    }

    /// The halves of the cases (`index.csv`'s `half` column): `design`, `held-out`, then any
    /// others alphabetically; empty without the column.
    pub fn halves(&self) -> Vec<String> {
        let mut present: Vec<&str> = (0..self.data.cases.len())
            .map(|i| self.data.half(i))
            .filter(|h| !h.is_empty())
            .collect();
        present.sort_by_key(|h| {
            (HALF_ORDER.iter().position(|o| o == h).unwrap_or(HALF_ORDER.len()), *h)
        });
        present.dedup();
        present.into_iter().map(String::from).collect()
    }

    /// `columns` (title, cases) with each column shown once per half, side by side: `TITLE ·
    /// HALF` with the column's cases of that half, `design` first. Unchanged without halves;
    /// a case without a half is then in no column.
    pub fn by_half(&self, columns: Vec<(String, Vec<usize>)>) -> Vec<(String, Vec<usize>)> {
        let halves = self.halves();
        if halves.is_empty() {
            return columns;
        }
        let mut out = Vec::new();
        for (title, cases) in columns {
            for half in &halves {
                let of_half = cases.iter().copied().filter(|&i| self.data.half(i) == half);
                out.push((format!("{title} · {half}"), of_half.collect()));
            }
        }
        out
    }

    /// Whether some method was judged against a true curve on case `case`: the case has one.
    pub fn has_curve(&self, case: usize) -> bool {
        self.data.methods.iter().any(|m| self.run(case, m).is_some_and(|r| r.curve.is_some()))
    }

    /// The indices of the cases of `category`.
    pub fn in_category(&self, category: &str) -> Vec<usize> {
        (0..self.data.cases.len())
            .filter(|&i| self.data.cases[i].row.category == category)
            .collect()
    }

    /// The manifold cases with `epsilon` below the threshold (`ours` picks `graph_epsilon`);
    /// `None` when no manifold case has that epsilon.
    pub fn well_sampled(&self, ours: bool) -> Option<Vec<usize>> {
        let manifold = self.in_category("manifold");
        let eps = |i: usize| {
            let case = &self.data.cases[i];
            if ours {
                case.graph_epsilon
            } else {
                case.row.epsilon
            }
        };
        manifold.iter().any(|&i| eps(i).is_some()).then(|| {
            let below = |&i: &usize| eps(i).is_some_and(|e| e < self.data.eps_threshold);
            manifold.into_iter().filter(below).collect()
        })
    }

    /// How many of `cases` `method` reconstructed exactly; failures and missing runs count
    /// as not exact (`docs/algorithms.md` §4.2).
    pub fn rate(&self, method: &str, cases: &[usize]) -> Rate {
        let exact = cases.iter().filter(|&&i| self.run(i, method).is_some_and(|r| r.exact)).count();
        Rate { exact, total: cases.len() }
    }

    /// The index of the largest case (most points, first on ties).
    pub fn largest(&self) -> Option<usize> {
        let cases = &self.data.cases;
        (0..cases.len()).rev().max_by_key(|&i| cases[i].row.n_points)
    }

    /// The case whose size is nearest `target` points by ratio, among those within a factor
    /// of 2 of it (first on ties).
    pub fn nearest_size(&self, target: usize) -> Option<usize> {
        let cases = &self.data.cases;
        let ratio = |i: usize| (cases[i].row.n_points as f64 / target as f64).ln().abs();
        (0..cases.len())
            .filter(|&i| ratio(i) <= std::f64::consts::LN_2)
            .min_by(|&a, &b| ratio(a).total_cmp(&ratio(b)))
    }

    /// The cases of `category` within a factor of 2 of `target` points.
    pub fn sized_about(&self, category: &str, target: usize) -> Vec<usize> {
        let within = |n: usize| n * 2 >= target && n <= 2 * target;
        let cases = self.in_category(category);
        cases.into_iter().filter(|&i| within(self.data.cases[i].row.n_points)).collect()
    }
}

/// An exact-reconstruction count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Rate {
    pub exact: usize,
    pub total: usize,
}

impl Rate {
    /// The percentage, `None` for an empty set.
    pub fn percent(self) -> Option<f64> {
        (self.total > 0).then(|| 100.0 * self.exact as f64 / self.total as f64)
    }

    /// `95.5 % (105/110)`, rounded to one decimal; `–` for an empty set.
    pub fn cell(self) -> String {
        match self.percent() {
            Some(p) => format!("{p:.1} % ({}/{})", self.exact, self.total),
            None => "–".into(),
        }
    }
}

/// Bolds the cells holding the best value (largest, or smallest with `lower_is_better`), ties
/// included. Nothing is bolded with fewer than two values, when they are all equal, or when
/// the best rate is zero.
pub(super) fn bold_best(cells: &mut [String], values: &[Option<f64>], lower_is_better: bool) {
    let present: Vec<f64> = values.iter().flatten().copied().filter(|v| v.is_finite()).collect();
    if present.len() < 2 {
        return;
    }
    let best = if lower_is_better {
        present.iter().copied().fold(f64::INFINITY, f64::min)
    } else {
        present.iter().copied().fold(f64::NEG_INFINITY, f64::max)
    };
    if present.iter().all(|&v| v == best) || (!lower_is_better && best <= 0.0) {
        return;
    }
    for (cell, value) in cells.iter_mut().zip(values) {
        if *value == Some(best) {
            *cell = format!("**{cell}**");
        }
    }
}

/// A runtime in milliseconds with 2, 1 or 0 decimals as it grows.
pub(super) fn ms(v: f64) -> String {
    match v {
        v if v < 10.0 => format!("{v:.2}"),
        v if v < 100.0 => format!("{v:.1}"),
        v => format!("{v:.0}"),
    }
}

/// A small non-negative quantity with 4 significant digits, in scientific notation outside
/// 0.001..10000.
pub(super) fn sci(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&v.abs()) {
        let decimals = (3 - v.abs().log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.3e}")
    }
}

/// The mean of the values, `None` without any.
pub(super) fn mean(values: impl IntoIterator<Item = f64>) -> Option<f64> {
    let (sum, n) = values.into_iter().fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    (n > 0).then(|| sum / n as f64)
}

/// Text made safe for one Markdown table cell or list item: one line, no `|`, no HTML.
pub(super) fn inline(s: &str) -> String {
    let one_line = s.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut out = one_line.replace('|', "\\|").replace('<', "&lt;");
    if out.chars().count() > 300 {
        out = out.chars().take(299).chain(['…']).collect();
    }
    out
}

/// A Markdown table; the first `left` columns are left-aligned, the others right-aligned.
pub(super) fn table(header: &[String], rows: &[Vec<String>], left: usize) -> String {
    let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
    let rule: Vec<String> =
        (0..header.len()).map(|i| if i < left { ":--" } else { "--:" }.to_string()).collect();
    let mut out = line(header) + &line(&rule);
    for row in rows {
        out += &line(row);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats() {
        assert_eq!(Rate { exact: 105, total: 110 }.cell(), "95.5 % (105/110)");
        assert_eq!(Rate { exact: 0, total: 0 }.cell(), "–");
        assert_eq!(
            (ms(0.123), ms(75.04), ms(2455.4)),
            ("0.12".into(), "75.0".into(), "2455".into())
        );
        assert_eq!(
            (sci(0.0), sci(0.01234567), sci(2.5e-6)),
            ("0".into(), "0.01235".into(), "2.500e-6".into())
        );
        assert_eq!(inline("a|b\n<c>"), "a\\|b &lt;c>");
        assert_eq!(mean([1.0, 2.0]), Some(1.5));
    }

    #[test]
    fn bolding() {
        let mut cells = vec!["1".to_string(), "3".into(), "3".into(), "-".into()];
        bold_best(&mut cells, &[Some(1.0), Some(3.0), Some(3.0), None], false);
        assert_eq!(cells, ["1", "**3**", "**3**", "-"]);
        let mut cells = vec!["0".to_string(), "0".into()];
        bold_best(&mut cells, &[Some(0.0), Some(0.0)], false);
        bold_best(&mut cells, &[Some(1.0), Some(1.0)], true);
        assert_eq!(cells, ["0", "0"]);
        bold_best(&mut cells, &[Some(0.0), Some(1.0)], true);
        assert_eq!(cells, ["**0**", "0"]);
    }
}
