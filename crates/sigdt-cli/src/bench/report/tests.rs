//! The report on a small synthetic benchmark: 2 methods, 3 categories, a failure, a time-out.
use super::write_report;
use crate::bench::chart::assert_well_formed;
use crate::bench::record::{
    read_results_csv, BenchData, Case, CurveScore, Entry, LeftOut, Outcome, OverlapStat, Run,
};
use sigdt_lab::dataset;
use std::fs;

fn case(name: &str, category: &str, n_points: usize, epsilon: Option<f64>) -> Case {
    let row = dataset::Case { name: name.into(), category: category.into(), n_points, epsilon };
    Case { row, graph_epsilon: None }
}

fn done(exact: bool, time_ms: f64, rmse: Option<f64>) -> Outcome {
    Outcome::Done(Run {
        exact,
        status: "manifold".into(),
        edges: 10,
        missing: usize::from(!exact),
        extra: 0,
        time_ms,
        rmse,
        hausdorff: rmse.map(|r| 2.0 * r),
        symdiff: Some(0.0),
        curve: None,
    })
}

fn sample() -> BenchData {
    let cases = vec![
        case("m1", "manifold", 100, Some(0.5)),
        case("m2", "manifold", 200, Some(0.8)),
        case("m3", "manifold", 300, Some(1.5)),
        case("s1", "sharp", 50, None),
        case("s2", "sharp", 60, None),
        case("o1", "open", 9991, None),
    ];
    let sig = [
        done(true, 1.0, Some(0.0)),
        done(true, 2.0, Some(0.0)),
        done(false, 3.0, Some(0.03)),
        done(true, 0.5, None),
        Outcome::Failed("sculpt | panicked\nat line 3".into()),
        Outcome::TimedOut(10.0),
    ];
    let crust = [
        done(true, 0.5, Some(0.0)),
        done(false, 0.5, Some(0.01)),
        done(false, 0.5, Some(0.01)),
        done(true, 0.25, Some(0.0)),
        done(true, 0.25, Some(0.0)),
        done(false, 39.0, Some(0.1)),
    ];
    let mut entries = Vec::new();
    for (method, outcomes) in [("sig-connect2d", sig), ("crust", crust)] {
        for (case, outcome) in outcomes.into_iter().enumerate() {
            entries.push(Entry { case, method: method.into(), outcome });
        }
    }
    BenchData {
        data_dir: "/data/curves".into(),
        command: "sigdt bench /data/curves --method all --out out".into(),
        machine: "test machine, 2 cores".into(),
        time_limit_s: 10.0,
        methods: vec!["sig-connect2d".into(), "crust".into()],
        cases,
        entries,
        overlap: vec![OverlapStat {
            name: "recon in SIGDT".into(),
            mean_percent: 99.24,
            sets_contained_percent: Some(97.0),
            paper_percent: Some(99.9),
        }],
        eps_threshold: 1.0,
        halves: Vec::new(),
    }
}

fn report(data: &BenchData) -> (String, Vec<String>, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let paths = write_report(data, &out).unwrap();
    let names =
        paths.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
    for p in &paths {
        assert!(p.starts_with(&out) && p.is_file(), "{p:?}");
        if p.extension().is_some_and(|e| e == "svg") {
            let svg = fs::read_to_string(p).unwrap();
            assert_well_formed(&svg);
            assert!(!svg.contains("NaN") && !svg.contains("inf"), "{p:?}");
        }
    }
    (fs::read_to_string(out.join("report.md")).unwrap(), names, dir)
}

fn row<'a>(md: &'a str, start: &str) -> &'a str {
    md.lines().find(|l| l.starts_with(start)).unwrap_or_else(|| panic!("no row {start}\n{md}"))
}

#[test]
fn writes_every_file() {
    let (_, names, dir) = report(&sample());
    let expected = [
        "report.md",
        "results.csv",
        "numbers.json",
        "accuracy.svg",
        "accuracy_eps.svg",
        "runtime.svg",
        "symdiff_open.svg",
    ];
    assert_eq!(names, expected, "the sample has open cases, not multiple or non-manifold ones");
    let md = fs::read_to_string(dir.path().join("out/report.md")).unwrap();
    assert!(md.contains("](symdiff_open.svg)") && !md.contains("symdiff_multiple"));
    assert!(!md.contains("true curve"), "no case has a true curve");
    let symdiff = fs::read_to_string(dir.path().join("out/symdiff_open.svg")).unwrap();
    assert!(symdiff.contains("Symmetric area difference, open"));
    let csv = fs::read(dir.path().join("out/results.csv")).unwrap();
    let back = read_results_csv(&csv[..]).unwrap();
    assert_eq!((back.entries, back.cases), (sample().entries, sample().cases));
    let accuracy = fs::read_to_string(dir.path().join("out/accuracy.svg")).unwrap();
    assert!(accuracy.contains("sig-connect2d") && accuracy.contains("manifold ε &lt; 1"));
}

#[test]
fn exact_table_follows_table_2() {
    let (md, _, _) = report(&sample());
    let header = row(&md, "| Method |");
    for column in
        ["| manifold |", "| sharp |", "| open |", "| manifold ε < 1 |", "`o1` (n = 9991) ms"]
    {
        assert!(header.contains(column), "{column} not in {header}");
    }
    let sig = row(&md, "| `sig-connect2d` |");
    let crust = row(&md, "| `crust` |");
    for cell in ["**66.7 % (2/3)**", "| 50.0 % (1/2) |", "| 0.0 % (0/1) |", "**100.0 % (2/2)**"] {
        assert!(sig.contains(cell), "{cell} not in {sig}");
    }
    assert!(sig.contains("> 10000 (time-out)") && sig.ends_with("| 1 / 1 |"), "{sig}");
    for cell in
        ["| 33.3 % (1/3) |", "**100.0 % (2/2)**", "| 50.0 % (1/2) |", "| 39.0 |", "| 0 / 0 |"]
    {
        assert!(crust.contains(cell), "{cell} not in {crust}");
    }
    // Mean manifold runtime: 2.00 ms against 0.50 ms, the smaller in bold.
    assert!(sig.contains("| 2.00 |") && crust.contains("| **0.50** |"), "{sig}\n{crust}");
    // At the paper's mean size (m2 and m3, within a factor 2 of 260 points): 2.50 against
    // 0.50. The 9,991-point case is both the paper-sized large case and the largest: one
    // column.
    assert!(header.contains("manifold mean ms, n ≈ 260 (2 cases)"), "{header}");
    assert!(sig.contains("| 2.00 | 2.50 |"), "{sig}");
    assert_eq!(header.matches("`o1`").count(), 1, "{header}");
}

#[test]
fn header_paper_table_and_other_sections() {
    let (md, _, _) = report(&sample());
    assert!(md.starts_with("# Benchmark report\n"));
    assert!(md.contains("- Command: `sigdt bench /data/curves --method all --out out`"));
    assert!(md.contains("- Time limit: 10 s per run"));
    assert!(md.contains("| manifold | 3 | 100–300 |") && md.contains("| sharp | 2 | 50–60 |"));
    let paper = row(&md, "| SIG-CONNECT2D |");
    assert!(paper.contains("| 91.5 % |") && paper.ends_with("| `sig-connect2d` |"), "{paper}");
    assert!(row(&md, "| CRUST |").ends_with("| `crust` |"));
    assert!(row(&md, "| LENZ |").ends_with("| 12672 |  |"));
    assert!(row(&md, "| FITCONNECT |").contains("| 237.1 | – |"));
    assert!(md.contains("Paper convention: the paper truncates its percentages"));
    assert!(md.contains("- LENZ: nothing of its rules is known\n"));
    assert_eq!(
        md.lines()
            .filter(|l| l.contains(" % | ")
                && l.starts_with("| ")
                && l.chars().nth(2).unwrap().is_ascii_uppercase())
            .count(),
        16
    );
    let rmse = row(&md, "| manifold | `crust` |");
    assert!(rmse.contains("| 3 | **0.006667** |"), "{rmse}");
    assert!(row(&md, "| sharp | `sig-connect2d` |").contains("| 1 | – |"));
    assert!(md.contains("| recon in SIGDT | 99.2 % | 97.0 % | 99.9 % |"));
    for image in ["(accuracy.svg)", "(accuracy_eps.svg)", "(runtime.svg)"] {
        assert!(md.contains(image), "{image}");
    }
}

#[test]
fn failures_are_listed() {
    let (md, _, _) = report(&sample());
    let failures = &md[md.find("## Failures").unwrap()..];
    assert!(failures.contains("- `s2` (sharp, n = 60): failed: sculpt \\| panicked at line 3\n"));
    assert!(failures.contains("- `o1` (open, n = 9991): timed out after 10 s\n"));
    assert!(failures.contains("### `crust`\n\nNone.\n"));
    let details = &failures[failures.find("<details>").unwrap()..];
    assert!(details.contains("- `sig-connect2d`, manifold (1 of 3): `m3`\n"));
    assert!(details.contains("- `sig-connect2d`, sharp (1 of 2): `s2`\n"));
    assert!(details.contains("- `crust`, manifold (2 of 3): `m2`, `m3`\n"));
    assert!(details.trim_end().ends_with("</details>"));
}

#[test]
fn empty_data_gives_a_report() {
    let (md, names, _) = report(&BenchData::default());
    assert!(md.contains("## Exact reconstruction") && md.contains("Not computed."));
    assert_eq!(names, ["report.md", "results.csv", "numbers.json", "accuracy.svg", "runtime.svg"]);
}

#[test]
fn runtime_columns_at_the_papers_large_size_and_the_largest() {
    // A 100,000-point case beside the 9,991-point one: both get a column, 10⁴ first.
    let mut data = sample();
    data.cases.push(case("big", "open", 100_000, None));
    let (md, _, _) = report(&data);
    let header = row(&md, "| Method |");
    let (near, large) = (header.find("`o1` (n = 9991) ms"), header.find("`big` (n = 100000) ms"));
    assert!(near.is_some() && large.is_some() && near < large, "{header}");
}

/// A run judged against a true curve.
fn judged(iou: f64, topology_right: bool, h: f64, warned: bool) -> Outcome {
    let Outcome::Done(run) = done(false, 1.0, Some(0.01)) else { unreachable!() };
    let left_out = Some(LeftOut { outliers: 4, outliers_left_out: 3, curve_points_left_out: 1 });
    let curve = CurveScore {
        iou,
        topology_right,
        hausdorff_over_s: Some(h),
        hausdorff_bound_over_s: Some(1.0),
        warned,
        left_out,
    };
    Outcome::Done(Run { curve: Some(curve), ..run })
}

/// The sample and three outline cases, two methods and an import, judged against their true
/// curves (clean data: the Hausdorff bound is one spacing). sig-connect2d is good on two,
/// wrong with a warning on one; crust good but warned on one, wrong silently on two (one an
/// extra loop at IoU 0.99); the import good on one, a spike out to an outlier on another
/// (topology right, IoU 0.99, H = 2.5 s: silently wrong), and fails on the third.
fn judged_sample() -> BenchData {
    let mut data = sample();
    data.methods.push("hull".into());
    for (name, category) in [("a", "outline-clean"), ("b", "outline-clean"), ("c", "outline-noise")]
    {
        data.cases.push(case(name, category, 100, None));
    }
    let outcomes = [
        (
            "sig-connect2d",
            [(0.99, true, 0.3, false), (0.998, true, 0.2, false), (0.5, true, 9.0, true)],
        ),
        (
            "crust",
            [(0.98, true, 0.3, true), (0.99, false, 0.4, false), (0.2, true, f64::INFINITY, false)],
        ),
        (
            "hull",
            [(0.97, true, 0.8, false), (0.99, true, 2.5, false), (f64::NAN, false, 0.0, false)],
        ),
    ];
    for (method, runs) in outcomes {
        for (k, (iou, right, h, warned)) in runs.into_iter().enumerate() {
            let outcome = if iou.is_nan() {
                Outcome::Failed("no result file".into())
            } else {
                judged(iou, right, h, warned)
            };
            data.entries.push(Entry { case: 6 + k, method: method.into(), outcome });
        }
    }
    data
}

/// The table under `### TITLE` in `section`.
fn table_of(section: &str, title: &str) -> String {
    let start = section.find(&format!("### {title}\n")).unwrap_or_else(|| panic!("{title}"));
    section[start..].split("\n\n").nth(1).unwrap().to_string()
}

#[test]
fn results_judged_against_true_curves() {
    let data = judged_sample();
    let (md, _, dir) = report(&data);
    let (exact, section, paper) = (
        md.find("## Exact reconstruction").unwrap(),
        md.find("## Judged against the true curve").unwrap(),
        md.find("## The paper's Table 2").unwrap(),
    );
    assert!(exact < section && section < paper, "the exact table first, then this");
    let section = &md[section..paper];
    assert!(section.contains("The 3 cases that carry their true curve"), "{section}");
    assert!(section.contains("and H ≤ s + d<sub>max</sub>"), "{section}");
    assert!(!section.contains("half"), "no halves: {section}");
    let table = |title: &str| table_of(section, title);
    let good = table("Good");
    assert!(good.starts_with("| Method | outline-clean | outline-noise |"), "{good}");
    assert!(good.contains("| `sig-connect2d` | **100.0 % (2/2)** | 0.0 % (0/1) |"), "{good}");
    assert!(good.contains("| `crust` | 50.0 % (1/2) | 0.0 % (0/1) |"), "{good}");
    assert!(good.contains("| `hull` | 50.0 % (1/2) | 0.0 % (0/1) |"), "the spike: {good}");
    let quiet = table("Good, no warning");
    assert!(quiet.contains("| `sig-connect2d` | **100.0 % (2/2)** | 0.0 % (0/1) |"), "{quiet}");
    assert!(quiet.contains("| `crust` | 0.0 % (0/2) |"), "{quiet}");
    assert!(quiet.contains("| `hull` | 50.0 % (1/2) |"), "{quiet}");
    let alarms = table("Good but warned");
    assert!(alarms.contains("| `crust` | 50.0 % (1/2) | 0.0 % (0/1) |"), "{alarms}");
    assert!(alarms.contains("| `hull` | **0.0 % (0/2)** | 0.0 % (0/1) |"), "{alarms}");
    let silent = table("Silent wrong");
    assert!(silent.contains("| `crust` | 50.0 % (1/2) | 100.0 % (1/1) |"), "{silent}");
    assert!(silent.contains("| `hull` | 50.0 % (1/2) | **0.0 % (0/1)** |"), "{silent}");
    let iou = table("Median IoU");
    assert!(iou.contains("| `sig-connect2d` | **0.994** | **0.500** |"), "{iou}");
    assert!(iou.contains("| `hull` | 0.980 | – |"), "{iou}");
    let h = table("Median H/s");
    assert!(h.contains("| `crust` | 0.35 | ∞ |"), "{h}");
    let list = &section[section.find("### Silent wrong cases").unwrap()..];
    assert!(list.contains("- `crust` (2): `b` (IoU 0.990, topology wrong, manifold), `c` (IoU"));
    assert!(list.contains("- `hull` (1): `b` (IoU 0.990, topology right, manifold)"), "{list}");
    assert!(!list.contains("`sig-connect2d` ("), "{list}");
    // The columns in results.csv: filled for the judged runs only, read back the same.
    let csv = fs::read_to_string(dir.path().join("out/results.csv")).unwrap();
    assert!(csv.lines().next().unwrap().ends_with(
        ",good,silent_wrong,outliers,outliers_left_out,curve_points_left_out,\
         hausdorff_bound_over_s,half"
    ));
    assert!(csv.contains("\nb,outline-clean,100,,,crust,ok,0,manifold,"), "{csv}");
    assert!(csv.contains(",0.99,0,0.4,0,0,1,4,3,1,1,\n"), "{csv}");
    assert!(csv.contains(",0.2,1,inf,0,0,1,4,3,1,1,\n"), "{csv}");
    assert!(csv.contains(",0.99,1,2.5,0,0,1,4,3,1,1,\n"), "the spike: {csv}");
    assert!(csv.lines().filter(|l| l.ends_with(",,,,,,,,,,,")).count() == 12 + 1, "{csv}");
    // Every judged run left out 3 of its 4 outliers and 1 curve point.
    let outliers = table("Outliers left out");
    assert!(outliers.contains("| `crust` | 75.0 % (6/8) | 75.0 % (3/4) |"), "{outliers}");
    let curve_points = table("Curve points left out");
    assert!(curve_points.contains("| `hull` | 2 in 2 case(s) | – |"), "{curve_points}");
    assert_eq!(read_results_csv(csv.as_bytes()).unwrap().entries, data.entries);
}

/// The rows of `numbers.json` in `dir`, after checking that it is JSON of the data folder.
fn numbers(dir: &tempfile::TempDir) -> Vec<serde_json::Value> {
    let text = fs::read_to_string(dir.path().join("out/numbers.json")).unwrap();
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(json["folder"], "/data/curves");
    assert!(!text.contains('%') && !text.contains("time"), "counts only: {text}");
    json["rows"].as_array().unwrap().clone()
}

/// The row of `numbers` for (method, category, half).
fn numbers_row<'a>(
    rows: &'a [serde_json::Value],
    method: &str,
    category: &str,
    half: &str,
) -> &'a serde_json::Value {
    let key = |r: &&serde_json::Value| {
        r["method"] == method && r["category"] == category && r["half"] == half
    };
    rows.iter().find(key).unwrap_or_else(|| panic!("no row {method} {category} {half}"))
}

#[test]
fn numbers_json_holds_the_counts() {
    let (_, _, dir) = report(&judged_sample());
    let rows = numbers(&dir);
    // 3 methods × (5 categories + manifold eps<1 + all) × the half "all".
    assert_eq!(rows.len(), 3 * 7);
    let first: Vec<&str> = rows[..7].iter().map(|r| r["category"].as_str().unwrap()).collect();
    let categories = ["manifold", "sharp", "open", "outline-clean", "outline-noise"];
    assert_eq!(first, [&categories[..], &["manifold eps<1", "all"]].concat());
    // m1 and m2 (ε 0.5 and 0.8, both exact), not m3 (ε 1.5).
    let well_sampled = numbers_row(&rows, "sig-connect2d", "manifold eps<1", "all");
    assert_eq!(
        (well_sampled["cases"].as_u64(), well_sampled["exact"].as_u64()),
        (Some(2), Some(2))
    );
    let fields: Vec<&String> = rows[0].as_object().unwrap().keys().collect();
    assert_eq!(fields.len(), 15, "{fields:?}");
    let sig = numbers_row(&rows, "sig-connect2d", "outline-clean", "all");
    let expected = serde_json::json!({
        "method": "sig-connect2d", "category": "outline-clean", "half": "all", "cases": 2,
        "exact": 0, "judged": 2, "good": 2, "good_silent": 2, "good_warned": 0,
        "silent_wrong": 0, "warned": 0, "outliers": 8, "outliers_left_out": 6,
        "clean_points_left_out": 2, "cases_with_clean_points_left_out": 2
    });
    assert_eq!(sig, &expected);
    // The failed import: two runs counted, none good (one a spike), one silent.
    let hull = numbers_row(&rows, "hull", "all", "all");
    assert_eq!((hull["cases"].as_u64(), hull["judged"].as_u64()), (Some(9), Some(3)));
    assert_eq!((hull["good"].as_u64(), hull["silent_wrong"].as_u64()), (Some(1), Some(1)));
    assert_eq!(hull["outliers"].as_u64(), Some(8));
    // Without a true curve: only cases and exact.
    let crust = numbers_row(&rows, "crust", "manifold", "all");
    assert_eq!((crust["cases"].as_u64(), crust["exact"].as_u64()), (Some(3), Some(1)));
    assert!(crust["judged"] == 0 && crust["good"].is_null() && crust["outliers"].is_null());
}

#[test]
fn halves_are_shown_side_by_side() {
    let mut data = judged_sample();
    // m1 m2 m3 s1 s2 o1 a b c: a case of each category in each half, but the noisy one.
    let halves = ["design", "held-out", "design", "held-out", "design", "held-out"];
    data.halves =
        halves.iter().chain(&["held-out", "design", "design"]).map(|h| h.to_string()).collect();
    let (md, _, dir) = report(&data);
    let header = row(&md, "| Method | manifold · design | manifold · held-out | sharp · design |");
    assert!(header.contains("| manifold ε < 1 · design | manifold ε < 1 · held-out |"), "{header}");
    // Manifold: sig-connect2d exact on m1 (design) and m2 (held-out), not m3 (design);
    // crust on m1 only.
    let sig = row(&md, "| `sig-connect2d` |");
    assert!(sig.starts_with("| `sig-connect2d` | **50.0 % (1/2)** | **100.0 % (1/1)** |"), "{sig}");
    assert!(row(&md, "| `crust` |").starts_with("| `crust` | **50.0 % (1/2)** | 0.0 % (0/1) |"));
    assert!(md.contains("side by side: `· design`, `· held-out`."), "{md}");
    let section = &md[md.find("## Judged against the true curve").unwrap()..];
    let good = table_of(section, "Good");
    assert!(
        good.starts_with(
            "| Method | outline-clean · design | outline-clean · held-out | \
             outline-noise · design | outline-noise · held-out |"
        ),
        "{good}"
    );
    // a is held-out, b design: the spike of the import is in the design half.
    assert!(good.contains("| `hull` | 0.0 % (0/1) | 100.0 % (1/1) | 0.0 % (0/1) | – |"), "{good}");
    assert!(section.contains("`CATEGORY · design`, `CATEGORY · held-out`"), "{section}");
    // results.csv names the half of each row; numbers.json has a row per half.
    let csv = fs::read_to_string(dir.path().join("out/results.csv")).unwrap();
    assert!(csv.lines().any(|l| l.starts_with("a,outline-clean,") && l.ends_with(",held-out")));
    assert_eq!(read_results_csv(csv.as_bytes()).unwrap().halves, data.halves);
    let rows = numbers(&dir);
    assert_eq!(rows.len(), 3 * 7 * 3);
    let halves: Vec<&str> = rows[..3].iter().map(|r| r["half"].as_str().unwrap()).collect();
    assert_eq!(halves, ["all", "design", "held-out"]);
    let design = numbers_row(&rows, "hull", "outline-clean", "design");
    assert_eq!((design["cases"].as_u64(), design["good"].as_u64()), (Some(1), Some(0)));
    assert_eq!(design["silent_wrong"].as_u64(), Some(1));
    let held_out = numbers_row(&rows, "hull", "outline-noise", "held-out");
    assert!(held_out["cases"] == 0 && held_out["good"].is_null());
}
