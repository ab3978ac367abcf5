//! The "Exact reconstruction" table in the layout of the paper's Table 2, and Table 2 itself.
use super::summary::{bold_best, inline, mean, ms, table, Summary};
use crate::bench::record::Outcome;

/// The paper's Table 2 (\[MOW22\]; `docs/algorithms.md` §5.1): algorithm; exact rate in % on manifold,
/// sharp, open, multiple and manifold ε < 1; mean manifold runtime and large-set runtime in
/// ms (`None`: no output on the large set).
const PAPER_TABLE_2: [(&str, [f64; 5], f64, Option<f64>); 16] = [
    ("SIG-CONNECT2D", [91.5, 70.2, 0.0, 3.7, 95.8], 0.9, Some(75.0)),
    ("CONNECT2D", [90.3, 65.9, 0.0, 0.0, 95.0], 0.5, Some(99.0)),
    ("HNNCRUST", [64.5, 14.8, 43.4, 53.7, 67.2], 0.6, Some(49.0)),
    ("FITCONNECT", [67.7, 10.6, 8.6, 22.2, 71.0], 237.1, None),
    ("STRETCHDENOISE", [64.7, 11.1, 9.5, 24.0, 68.0], 207.4, None),
    ("DISCUR", [49.0, 17.0, 39.1, 46.2, 50.7], 279.7, None),
    ("VICUR", [46.2, 21.2, 52.1, 46.2, 47.6], 357.5, None),
    ("CRAWL", [75.3, 10.6, 21.7, 40.7, 78.2], 0.4, Some(182.0)),
    ("PEEL", [64.7, 14.8, 43.4, 57.4, 67.3], 2.8, Some(2455.0)),
    ("CRUST", [71.3, 23.4, 43.4, 38.8, 74.3], 0.6, Some(39.0)),
    ("NNCRUST", [39.3, 10.6, 8.6, 12.9, 41.3], 0.1, Some(11.0)),
    ("CCRUST", [53.1, 0.0, 30.4, 22.2, 55.7], 0.8, Some(796.0)),
    ("GATHAN1", [62.4, 44.6, 13.0, 24.0, 65.3], 0.3, Some(18.0)),
    ("GATHANG", [63.2, 80.8, 21.7, 35.1, 65.7], 1.9, Some(293.0)),
    ("LENZ", [2.8, 8.8, 0.0, 0.0, 3.0], 8.2, Some(12672.0)),
    ("OPTIMALTRANSPORT", [0.0, 0.0, 0.0, 0.0, 0.0], 71.2, Some(542.0)),
];

/// The paper's name of one of our methods, if the paper has a row for it.
pub(super) fn paper_name(method: &str) -> Option<&'static str> {
    Some(match method {
        "sig-connect2d" => "SIG-CONNECT2D",
        "connect2d" => "CONNECT2D",
        "crust" => "CRUST",
        "nn-crust" => "NNCRUST",
        "hnn-crust" => "HNNCRUST",
        "gathan1" => "GATHAN1",
        "gathang" => "GATHANG",
        "crawl" => "CRAWL",
        "discur" => "DISCUR",
        "peel" => "PEEL",
        "fit-connect" => "FITCONNECT",
        "stretch-denoise" => "STRETCHDENOISE",
        "optimal-transport" => "OPTIMALTRANSPORT",
        _ => return None,
    })
}

/// The mean size of the paper's manifold sets ([MOW22] §5: about 260 points): the report
/// gives the mean time over manifold cases within a factor of 2 of it.
const PAPER_MEAN_POINTS: usize = 260;

/// The size of the paper's large set (9,991 points): the report gives the time of the case
/// nearest it, beside the largest case.
const PAPER_LARGE_POINTS: usize = 9991;

/// The columns of the exact-rate table and the chart: each category, then the manifold cases
/// with ε below the threshold (from `index.csv`, then ours), as (title, case indices).
pub(super) fn rate_columns(s: &Summary) -> Vec<(String, Vec<usize>)> {
    let mut columns: Vec<(String, Vec<usize>)> =
        s.categories().into_iter().map(|c| (c.clone(), s.in_category(&c))).collect();
    let t = s.data.eps_threshold;
    if let Some(cases) = s.well_sampled(false) {
        columns.push((format!("manifold ε < {t}"), cases));
    }
    if let Some(cases) = s.well_sampled(true) {
        columns.push((format!("manifold ε<sub>ours</sub> < {t}"), cases));
    }
    columns
}

/// The "Exact reconstruction" section: one row per method, the best value of each column
/// in bold; with halves, each rate column once per half.
pub(super) fn exact_section(s: &Summary) -> String {
    let methods = &s.data.methods;
    let rates = s.by_half(rate_columns(s));
    let manifold = s.in_category("manifold");
    // The paper's mean set size (about 260 points) and its large set (9,991 points).
    let paper_sized = s.sized_about("manifold", PAPER_MEAN_POINTS);
    let largest = s.largest();
    let mut sized: Vec<usize> = s.nearest_size(PAPER_LARGE_POINTS).into_iter().collect();
    sized.extend(largest.filter(|l| !sized.contains(l)));

    let mut header = vec!["Method".to_string()];
    header.extend(rates.iter().map(|(title, _)| title.clone()));
    header.push("manifold mean ms".into());
    if !paper_sized.is_empty() {
        header.push(format!(
            "manifold mean ms, n ≈ {PAPER_MEAN_POINTS} ({} cases)",
            paper_sized.len()
        ));
    }
    for &i in &sized {
        let case = &s.data.cases[i];
        header.push(format!("`{}` (n = {}) ms", inline(&case.row.name), case.row.n_points));
    }
    header.push("failed / timed out".into());

    // Columns of cells and of the values that decide the bolding.
    let mut columns: Vec<(Vec<String>, Vec<Option<f64>>, bool)> = Vec::new();
    for (_, cases) in &rates {
        let r: Vec<_> = methods.iter().map(|m| s.rate(m, cases)).collect();
        columns.push((
            r.iter().map(|r| r.cell()).collect(),
            r.iter().map(|r| r.percent()).collect(),
            false,
        ));
    }
    let mean_over = |cases: &[usize]| -> Vec<Option<f64>> {
        let time = |m: &str| mean(cases.iter().filter_map(|&i| s.run(i, m)).map(|r| r.time_ms));
        methods.iter().map(|m| time(m)).collect()
    };
    let mut means = vec![mean_over(&manifold)];
    if !paper_sized.is_empty() {
        means.push(mean_over(&paper_sized));
    }
    for mean_ms in means {
        columns.push((mean_ms.iter().map(|v| v.map_or("–".into(), ms)).collect(), mean_ms, true));
    }
    for &i in &sized {
        let time: Vec<Option<f64>> =
            methods.iter().map(|m| s.run(i, m).map(|r| r.time_ms)).collect();
        let cells = methods
            .iter()
            .map(|m| match s.outcome(i, m) {
                Some(Outcome::Done(r)) => ms(r.time_ms),
                Some(Outcome::Failed(_)) => "failed".into(),
                Some(Outcome::TimedOut(limit)) => format!("> {} (time-out)", ms(limit * 1000.0)),
                None => "–".into(),
            })
            .collect();
        columns.push((cells, time, true));
    }
    for (cells, values, lower) in &mut columns {
        bold_best(cells, values, *lower);
    }

    let rows: Vec<Vec<String>> = methods
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let mut row = vec![format!("`{}`", inline(m))];
            row.extend(columns.iter().map(|(cells, _, _)| cells[k].clone()));
            let (mut failed, mut timed_out) = (0, 0);
            for entry in s.data.entries.iter().filter(|e| &e.method == m) {
                match entry.outcome {
                    Outcome::Failed(_) => failed += 1,
                    Outcome::TimedOut(_) => timed_out += 1,
                    Outcome::Done(_) => {}
                }
            }
            row.push(format!("{failed} / {timed_out}"));
            row
        })
        .collect();

    let mut out = String::from("## Exact reconstruction\n\n");
    out += "Percentage of cases whose output equals the ground truth (no missing, no extra edge), \
            over all cases of the column; failures and time-outs count as not exact. \
            Percentages are rounded to one decimal (the paper truncates). \
            Runtimes are wall-clock milliseconds of completed runs. \
            The best value of each column is in bold.\n\n";
    let halves = s.halves();
    if !halves.is_empty() {
        let titles: Vec<String> = halves.iter().map(|h| format!("`· {}`", inline(h))).collect();
        out += &format!(
            "Each rate column is shown once per half of its cases (the `half` column of \
             `index.csv`), side by side: {}.\n\n",
            titles.join(", ")
        );
    }
    out += &table(&header, &rows, 1);
    out
}

/// The paper's Table 2, with the rows we implement marked.
pub(super) fn paper_section(methods: &[String]) -> String {
    let header: Vec<String> = [
        "Algorithm",
        "manifold",
        "sharp",
        "open",
        "multiple",
        "ε < 1",
        "manifold ms",
        "large set (9991 points) ms",
        "here",
    ]
    .map(String::from)
    .to_vec();
    let rows: Vec<Vec<String>> = PAPER_TABLE_2
        .iter()
        .map(|&(name, rates, manifold_ms, large_ms)| {
            let ours: Vec<String> = methods
                .iter()
                .filter(|m| paper_name(m) == Some(name))
                .map(|m| format!("`{}`", inline(m)))
                .collect();
            let mut row = vec![name.to_string()];
            row.extend(rates.iter().map(|r| format!("{r:.1} %")));
            row.push(format!("{manifold_ms:.1}"));
            row.push(large_ms.map_or("–".into(), |v| format!("{v:.0}")));
            row.push(ours.join(", "));
            row
        })
        .collect();
    let mut out = String::from("## The paper's Table 2\n\n");
    out += "For reference: exact-reconstruction rates and runtimes reported by Marin, \
            Ohrhallinger and Wimmer (2022) on 1257 manifold, 47 sharp, about 23 open and 54 \
            multiple-curve sets of the 2D curve reconstruction benchmark (Intel Core i7-7700HQ). \
            \"here\" names the method of this benchmark that implements the row; \
            \"–\": no output on the large set.\n\n";
    out += &table(&header, &rows, 1);
    out += "\nPaper convention: the paper truncates its percentages and, for some rows, leaves \
            runs without output out of the denominator (STRETCHDENOISE's sharp 11.1 % is 5 of \
            45 cases where FITCONNECT's 10.6 % is 5 of 47); the tables of this report round \
            to one decimal and count failures and time-outs as not exact, over every case \
            of the column.\n\n";
    out += "Rows without a method here (`docs/evaluation.md`, \"Methods without an \
            implementation\"):\n\n";
    for (name, why) in NOT_IMPLEMENTED {
        out += &format!("- {name}: {why}\n");
    }
    out
}

/// The rows of Table 2 that no method implements, and why, one line each.
const NOT_IMPLEMENTED: [(&str, &str); 4] = [
    (
        "GATHAN1, GATHANG",
        "neither paper's text nor the authors' program is available: the angle and \
         length-ratio tests, their thresholds and what separates the two are unknown",
    ),
    ("CCRUST", "only the idea (edges justified by empty circles) is known, not its predicate"),
    ("LENZ", "nothing of its rules is known"),
    (
        "VICUR",
        "DISCUR with vision-inspired proximity and continuation rules whose weights and \
         thresholds are unknown",
    ),
];
