//! Tests of `record` (a file of their own, to keep that one short).
use super::*;

/// Two cases, two methods: a success, a failure with an awkward message, a time-out, and
/// a success judged against a true curve.
fn sample() -> BenchData {
    let case = |name: &str, category: &str, n_points, epsilon| Case {
        row: dataset::Case { name: name.into(), category: category.into(), n_points, epsilon },
        graph_epsilon: None,
    };
    let run = Run {
        exact: true,
        status: "manifold".into(),
        edges: 12,
        missing: 0,
        extra: 0,
        time_ms: 0.125,
        rmse: Some(1.5e-7),
        hausdorff: None,
        symdiff: Some(0.0),
        curve: None,
    };
    let curve = CurveScore {
        iou: 0.97,
        topology_right: false,
        hausdorff_over_s: Some(f64::INFINITY),
        hausdorff_bound_over_s: Some(1.5),
        warned: false,
        left_out: Some(LeftOut { outliers: 2, outliers_left_out: 1, curve_points_left_out: 0 }),
    };
    let judged = Run { curve: Some(curve), ..run.clone() };
    let entry = |case, method: &str, outcome| Entry { case, method: method.into(), outcome };
    BenchData {
        methods: vec!["sig-connect2d".into(), "crust".into()],
        cases: vec![case("a,b", "manifold", 12, Some(0.5)), case("c", "open", 30, None)],
        entries: vec![
            entry(0, "sig-connect2d", Outcome::Done(run)),
            entry(0, "crust", Outcome::Failed("panicked: \"x\", then\nexit 101".into())),
            entry(1, "sig-connect2d", Outcome::TimedOut(2.5)),
            entry(1, "crust", Outcome::Done(judged)),
        ],
        time_limit_s: 2.5,
        ..BenchData::default()
    }
}

#[test]
fn csv_round_trip() {
    let data = sample();
    let mut buf = Vec::new();
    write_results_csv(&data, &mut buf).unwrap();
    let text = String::from_utf8(buf).unwrap();
    assert!(text.starts_with("name,category,n_points,"));
    assert!(text.contains("\"a,b\",manifold,12,0.5,,sig-connect2d,ok,1,manifold,12,0,0,"));
    assert!(text.contains("\"panicked: \"\"x\"\", then\nexit 101\""));
    // The curve columns: empty without a true curve; the topology is wrong, so not good.
    assert!(text.contains(",2500,,,,timed out after 2.5 s,,,,,,,,,,,\n"), "{text}");
    assert!(text.contains(",0,,0.97,0,inf,0,0,1,2,1,0,1.5,\n"), "{text}");
    assert_eq!(read_results_csv(text.as_bytes()).unwrap(), data);
    // With halves, each row names its case's.
    let halved = BenchData { halves: vec!["design".into(), "held-out".into()], ..data };
    let mut buf = Vec::new();
    write_results_csv(&halved, &mut buf).unwrap();
    let text = String::from_utf8(buf).unwrap();
    assert!(text.contains(",1,2,1,0,1.5,held-out\n"), "{text}");
    assert!(text.contains(",timed out after 2.5 s,,,,,,,,,,,held-out\n"), "{text}");
    assert_eq!(read_results_csv(text.as_bytes()).unwrap(), halved);
}

/// A result judged against its true curve, topology right, unwarned.
fn judged(iou: f64, h: f64, bound: f64) -> CurveScore {
    CurveScore {
        iou,
        topology_right: true,
        hausdorff_over_s: Some(h),
        hausdorff_bound_over_s: Some(bound),
        warned: false,
        left_out: None,
    }
}

#[test]
fn good_needs_topology_area_and_nearness() {
    // A clean case: the bound is one spacing. Right topology and IoU 0.99, but a spike
    // out to an outlier 2.5 s away: not good, and silently so.
    let spike = judged(0.99, 2.5, 1.0);
    assert!(!spike.good() && spike.silent_wrong());
    assert!(judged(0.99, 0.4, 1.0).good_silent());
    // On noisy data the points stray up to 1.5 s: a result through them is good.
    assert!(judged(0.99, 2.3, 2.5).good());
    // The other conditions still hold, and the bound is inclusive.
    assert!(judged(0.95, 1.0, 1.0).good() && !judged(0.949, 0.1, 1.0).good());
    let wrong = CurveScore { topology_right: false, ..judged(0.99, 0.1, 1.0) };
    assert!(!wrong.good());
    // Without a spacing there is no bound: nothing is good.
    let unknown = CurveScore { hausdorff_bound_over_s: None, ..judged(0.99, 0.1, 1.0) };
    assert!(!unknown.good());
    let warned = CurveScore { warned: true, ..judged(0.99, 0.1, 1.0) };
    assert!(warned.good_warned() && !warned.good_silent() && !warned.silent_wrong());
}

#[test]
fn left_out_counts_against_the_truth() {
    // Points 0-2 a triangle in both; 3 an outlier left out, 4 one wired in; the result
    // skips curve point 5 (a self loop is no edge).
    let truth = [[0, 1], [1, 2], [0, 2], [5, 6], [6, 0]];
    let result = [[0, 1], [1, 2], [0, 2], [4, 6], [6, 0], [5, 5]];
    let count = LeftOut::count(7, &result, &truth);
    assert_eq!(count, LeftOut { outliers: 2, outliers_left_out: 1, curve_points_left_out: 1 });
}

#[test]
fn files_without_the_curve_columns_are_read() {
    let old = format!(
        "{}\nc,open,30,,,crust,ok,1,curves,4,0,0,0.5,0,0,0,\n",
        CSV_HEADER[..OLD_COLUMNS[0]].join(",")
    );
    let data = read_results_csv(old.as_bytes()).unwrap();
    assert!(matches!(&data.entries[0].outcome, Outcome::Done(r) if r.curve.is_none()));
    // Before the Hausdorff bound and the half: read, without a bound, so not good.
    let old = format!(
        "{}\nc,open,30,,,crust,ok,1,curves,4,0,0,0.5,0,0,0,,0.99,1,0.2,0,1,0,0,0,0\n",
        CSV_HEADER[..OLD_COLUMNS[1]].join(",")
    );
    let data = read_results_csv(old.as_bytes()).unwrap();
    let Outcome::Done(Run { curve: Some(c), .. }) = &data.entries[0].outcome else {
        panic!("{data:?}")
    };
    assert!(c.hausdorff_bound_over_s.is_none() && !c.good() && data.halves.is_empty());
}

#[test]
fn read_rejects_bad_input() {
    assert!(read_results_csv("x,y\n".as_bytes()).is_err());
    let bad = format!("{}\nc,open,x,,,m,ok,1,s,1,0,0,1,,,,\n", CSV_HEADER.join(","));
    let err = read_results_csv(bad.as_bytes()).unwrap_err();
    assert!(err.to_string().contains("results.csv, row 2"), "{err}");
}

#[test]
fn empty_data_round_trips() {
    let mut buf = Vec::new();
    write_results_csv(&BenchData::default(), &mut buf).unwrap();
    assert_eq!(read_results_csv(&buf[..]).unwrap(), BenchData::default());
}
