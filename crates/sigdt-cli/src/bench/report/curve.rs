//! The "Judged against the true curve" section: for the cases that carry their true curve,
//! how often each method gives the right outline (with or without a warning), how often it
//! is wrong without a warning, and how close it comes (`docs/evaluation.md`, "Judged as a
//! user would"). With halves (`index.csv`'s `half` column) each category is shown once per
//! half.
use super::summary::{bold_best, inline, table, Summary};
use crate::bench::record::{CurveScore, LeftOut};

/// Silent-wrong cases listed by name per method, at most.
const LISTED: usize = 20;

/// The section, or `None` when no case has a true curve. Rows are methods, columns the
/// categories with true curves (each once per half, when the cases have halves); a case
/// counts when some method was judged on it, and a run that failed or timed out is neither
/// good nor silent.
pub(super) fn curve_section(s: &Summary) -> Option<String> {
    let columns: Vec<(String, Vec<usize>)> = s
        .categories()
        .into_iter()
        .map(|c| {
            let judged: Vec<usize> =
                s.in_category(&c).into_iter().filter(|&i| s.has_curve(i)).collect();
            (c, judged)
        })
        .filter(|(_, cases)| !cases.is_empty())
        .collect();
    if columns.is_empty() {
        return None;
    }
    let n: usize = columns.iter().map(|(_, cases)| cases.len()).sum();
    let mut out = String::from("## Judged against the true curve\n\n");
    out += &format!(
        "The {n} cases that carry their true curve (`NAME.curve.xy`, `NAME.curve.gt`), judged \
         as a user would; per method and category:\n\n"
    );
    out += "- **good**: as many polygons, holes and open paths as the truth, IoU ≥ 0.95 (area \
            of the intersection over area of the union of the two regions, read even-odd, an \
            open path closed by its chord), and H ≤ s + d<sub>max</sub>: the symmetric \
            Hausdorff distance H to the true curve at most one spacing s more than the \
            farthest a labelled point (one on a ground-truth edge) lies from it, \
            d<sub>max</sub> (0 on clean data, the noise on noisy data; a spike out to an \
            outlier is not good); failures and time-outs are not good;\n\
            - **good, no warning**: good, and the result did not warn (its status or its \
            sampling check; imported results never warn): the answer a user can take as is; \
            **good but warned**: false alarms;\n\
            - **silent wrong**: finished, not good, and no warning;\n\
            - **outliers left out**: of the points without ground-truth edges (outliers), the \
            share the result passes through no edge of, over all cases of the category (– \
            without outliers); **curve points left out**: the points of the true curve the \
            result leaves without edges, in all, and in how many cases (– for methods that \
            place vertices of their own);\n\
            - **median IoU**, **median H/s**: over the finished runs; H/s is H over the \
            case's spacing (`spacing` in `index.csv`, else the median ground-truth edge \
            length), ∞ for an empty result.\n\n";
    let halves = s.halves();
    if !halves.is_empty() {
        out += &format!(
            "Each category is shown once per half of its cases (the `half` column of \
             `index.csv`), side by side: {}.\n\n",
            halves
                .iter()
                .map(|h| format!("`CATEGORY · {}`", inline(h)))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    let split = s.by_half(columns.clone());
    let tables: [(&str, Metric, bool); 8] = [
        ("Good", good, false),
        ("Good, no warning", good_silent, false),
        ("Good but warned", good_warned, true),
        ("Silent wrong", silent_wrong, true),
        ("Outliers left out", outliers_left_out, false),
        ("Curve points left out", curve_points_left_out, true),
        ("Median IoU", median_iou, false),
        ("Median H/s", median_hausdorff, true),
    ];
    for (title, metric, lower_is_better) in tables {
        out += &format!("### {title}\n\n");
        out += &metric_table(s, &split, metric, lower_is_better);
        out += "\n";
    }
    out += &silent_list(s, &columns);
    Some(out)
}

/// A cell and the value that decides the bolding, of one method on some cases.
type Metric = fn(&[Option<&CurveScore>]) -> (String, Option<f64>);

fn metric_table(
    s: &Summary,
    columns: &[(String, Vec<usize>)],
    metric: Metric,
    lower_is_better: bool,
) -> String {
    let methods = &s.data.methods;
    let mut header = vec!["Method".to_string()];
    header.extend(columns.iter().map(|(c, _)| inline(c)));
    let mut rows: Vec<Vec<String>> =
        methods.iter().map(|m| vec![format!("`{}`", inline(m))]).collect();
    for (_, cases) in columns {
        let (mut cells, values): (Vec<String>, Vec<Option<f64>>) =
            methods.iter().map(|m| metric(&scores(s, cases, m))).unzip();
        bold_best(&mut cells, &values, lower_is_better);
        for (row, cell) in rows.iter_mut().zip(cells) {
            row.push(cell);
        }
    }
    table(&header, &rows, 1)
}

/// The silent-wrong cases of each method by name, with IoU, topology and status.
fn silent_list(s: &Summary, columns: &[(String, Vec<usize>)]) -> String {
    let mut out = String::from("### Silent wrong cases\n\n");
    let mut any = false;
    for m in &s.data.methods {
        let silent: Vec<String> = columns
            .iter()
            .flat_map(|(_, cases)| cases)
            .filter_map(|&i| {
                let run = s.run(i, m)?;
                let c = run.curve.filter(CurveScore::silent_wrong)?;
                let topology = if c.topology_right { "topology right" } else { "topology wrong" };
                let name = inline(&s.data.cases[i].row.name);
                let status = inline(&run.status);
                Some(format!("`{name}` (IoU {:.3}, {topology}, {status})", c.iou))
            })
            .collect();
        if silent.is_empty() {
            continue;
        }
        any = true;
        let more = silent.len().saturating_sub(LISTED);
        let shown = silent[..silent.len().min(LISTED)].join(", ");
        let more = if more > 0 { format!(", and {more} more") } else { String::new() };
        out += &format!("- `{}` ({}): {shown}{more}\n", inline(m), silent.len());
    }
    out + if any { "" } else { "None.\n" }
}

/// The curve scores of `method` on `cases`; `None` where it did not finish.
fn scores<'a>(s: &Summary<'a>, cases: &[usize], method: &str) -> Vec<Option<&'a CurveScore>> {
    cases.iter().map(|&i| s.run(i, method).and_then(|r| r.curve.as_ref())).collect()
}

fn good(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    share(scores.iter().flatten().filter(|c| c.good()).count(), scores.len())
}

fn silent_wrong(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    share(scores.iter().flatten().filter(|c| c.silent_wrong()).count(), scores.len())
}

fn good_silent(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    share(scores.iter().flatten().filter(|c| c.good_silent()).count(), scores.len())
}

fn good_warned(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    share(scores.iter().flatten().filter(|c| c.good_warned()).count(), scores.len())
}

fn outliers_left_out(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    let counts: Vec<LeftOut> = scores.iter().flatten().filter_map(|c| c.left_out).collect();
    let outliers = counts.iter().map(|l| l.outliers).sum();
    share(counts.iter().map(|l| l.outliers_left_out).sum(), outliers)
}

fn curve_points_left_out(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    let counts: Vec<usize> = scores
        .iter()
        .flatten()
        .filter_map(|c| c.left_out)
        .map(|l| l.curve_points_left_out)
        .collect();
    if counts.is_empty() {
        return ("–".into(), None);
    }
    let (points, cases) = (counts.iter().sum::<usize>(), counts.iter().filter(|&&k| k > 0).count());
    (format!("{points} in {cases} case(s)"), Some(points as f64))
}

fn median_iou(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    let value = median(scores.iter().flatten().map(|c| c.iou));
    (value.map_or("–".into(), |v| format!("{v:.3}")), value)
}

fn median_hausdorff(scores: &[Option<&CurveScore>]) -> (String, Option<f64>) {
    let value = median(scores.iter().flatten().filter_map(|c| c.hausdorff_over_s));
    let cell = match value {
        None => "–".into(),
        Some(v) if v.is_infinite() => "∞".into(),
        Some(v) => format!("{v:.2}"),
    };
    (cell, value)
}

/// `part` of `whole` as `96.0 % (72/75)`, and the percentage; `–` for none.
fn share(part: usize, whole: usize) -> (String, Option<f64>) {
    if whole == 0 {
        return ("–".into(), None);
    }
    let percent = 100.0 * part as f64 / whole as f64;
    (format!("{percent:.1} % ({part}/{whole})"), Some(percent))
}

/// The median (the mean of the middle two for an even count), `None` without values.
fn median(values: impl Iterator<Item = f64>) -> Option<f64> {
    let mut v: Vec<f64> = values.collect();
    v.sort_by(f64::total_cmp);
    let k = v.len() / 2;
    match v.len() {
        0 => None,
        n if n % 2 == 1 => Some(v[k]),
        _ => Some((v[k - 1] + v[k]) / 2.0),
    }
}
