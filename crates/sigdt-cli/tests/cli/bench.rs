//! `sigdt bench` and `sigdt eval`: a small labelled folder made here, with one case that
//! cannot be read, so that a failing case is recorded and the run still succeeds.

use super::*;

/// A labelled folder: a 12-gon (manifold, its points gzipped as any input may be), a square
/// (sharp) and a broken case.
fn labelled_folder() -> TempDir {
    let dir = tempdir();
    let d = dir.path();
    let text: String = circle(12, 1.0).iter().map(|p| format!("{} {}\n", p[0], p[1])).collect();
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    std::io::Write::write_all(&mut gz, text.as_bytes()).unwrap();
    fs::write(d.join("gon.xy"), gz.finish().unwrap()).unwrap();
    fs::write(d.join("gon.gt"), edges_text(&cycle_edges(12))).unwrap();
    write_points(d, "square.xy", &square());
    fs::write(d.join("square.gt"), SQUARE_EDGES).unwrap();
    fs::write(d.join("broken.xy"), "0 0\n1 zero\n").unwrap();
    fs::write(d.join("broken.gt"), "0 1\n").unwrap();
    fs::write(
        d.join("index.csv"),
        "name,category,n_points,epsilon\ngon,manifold,12,0.27\nsquare,sharp,4,0.7\n\
         broken,manifold,2,0.5\n",
    )
    .unwrap();
    dir
}

#[test]
fn bench_writes_a_report_and_records_failures() {
    let data = labelled_folder();
    let out = tempdir();
    let report = out.path().join("rep");
    let d = data.path().to_str().unwrap();
    let r = report.to_str().unwrap();
    let run = sigdt(&["bench", d, "--method", "sig-connect2d,connect2d", "--out", r, "-j", "2"]);
    run.expect(0);
    let md = fs::read_to_string(report.join("report.md")).unwrap();
    assert!(md.contains("sig-connect2d") && md.contains("connect2d"), "{md}");
    assert!(md.contains("broken") && md.contains("is not a number"), "failure not reported:\n{md}");
    let csv = fs::read_to_string(report.join("results.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 3 * 2, "{csv}");
    assert!(csv.lines().any(|l| l.starts_with("gon,") && l.contains(",sig-connect2d,ok,1,")));
    for chart in ["accuracy.svg", "runtime.svg"] {
        assert!(fs::read_to_string(report.join(chart)).unwrap().starts_with("<svg"), "{chart}");
    }
}

#[test]
fn bench_imports_results_of_other_tools() {
    let data = labelled_folder();
    let other = tempdir();
    fs::write(other.path().join("gon.edges"), edges_text(&cycle_edges(12))).unwrap();
    fs::write(other.path().join("square.edges"), "0 1\n").unwrap();
    fs::write(other.path().join("times.csv"), "name,time_ms\ngon,1.5\n").unwrap();
    let out = tempdir();
    let import = format!("mine={}", other.path().display());
    let d = data.path().to_str().unwrap();
    let o = out.path().to_str().unwrap();
    sigdt(&["bench", d, "--method", "connect2d", "--out", o, "--import", &import]).expect(0);
    let csv = fs::read_to_string(out.path().join("results.csv")).unwrap();
    assert!(csv.lines().any(|l| l.starts_with("gon,") && l.contains(",mine,ok,1,")), "{csv}");
    assert!(csv.lines().any(|l| l.starts_with("square,") && l.contains(",mine,ok,0,")), "{csv}");
}

/// Writes a case of `rings` (each `(samples, radius)`, concentric circles) sampled from
/// its true curve, the same circles as 400-gons in `NAME.curve.xy` / `NAME.curve.gt`.
fn write_circles(d: &Path, name: &str, rings: &[(usize, f64)]) {
    let (mut points, mut gt, mut curve, mut curve_gt) = (vec![], vec![], vec![], vec![]);
    for &(n, r) in rings {
        let shift =
            |e: Vec<[usize; 2]>, by: usize| e.into_iter().map(move |[i, j]| [i + by, j + by]);
        gt.extend(shift(cycle_edges(n), points.len()));
        points.extend(circle(n, r));
        curve_gt.extend(shift(cycle_edges(400), curve.len()));
        curve.extend(circle(400, r));
    }
    write_points(d, &format!("{name}.xy"), &points);
    fs::write(d.join(format!("{name}.gt")), edges_text(&gt)).unwrap();
    write_points(d, &format!("{name}.curve.xy"), &curve);
    fs::write(d.join(format!("{name}.curve.gt")), edges_text(&curve_gt)).unwrap();
}

#[test]
fn bench_judges_results_against_true_curves() {
    // A circle and an annulus with their true curves (the circle's spacing in the index, the
    // annulus's the median edge length), beside the labelled folder's cases without one; the
    // cases in two halves.
    let data = labelled_folder();
    let d = data.path();
    write_circles(d, "disc", &[(40, 1.0)]);
    write_circles(d, "annulus", &[(48, 2.0), (24, 1.0)]);
    let index = "name,category,n_points,epsilon,spacing,half\ngon,manifold,12,0.27,,design\n\
                 disc,outline-clean,40,,0.157,design\nannulus,outline-clean,72,,,held-out\n";
    fs::write(d.join("index.csv"), index).unwrap();
    let hull = tempdir();
    fs::write(hull.path().join("disc.edges"), edges_text(&cycle_edges(40))).unwrap();
    fs::write(hull.path().join("annulus.edges"), edges_text(&cycle_edges(48))).unwrap();
    let import = format!("hull={}", hull.path().display());
    let out = tempdir();
    let (ds, o) = (d.to_str().unwrap(), out.path().to_str().unwrap());
    sigdt(&["bench", ds, "--method", "sig-auto", "--out", o, "--import", &import]).expect(0);
    let csv = fs::read_to_string(out.path().join("results.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let row = |name: &str, method: &str| -> Vec<String> {
        let line = csv.lines().find(|l| l.starts_with(&format!("{name},")) && l.contains(method));
        line.unwrap_or_else(|| panic!("no {name} {method}\n{csv}"))
            .split(',')
            .map(String::from)
            .collect()
    };
    let field = |row: &[String], column: &str| {
        row[header.iter().position(|h| *h == column).unwrap()].clone()
    };
    // Cases without a true curve: the curve columns are empty; the half is given.
    let gon = row("gon", ",sig-auto,");
    let iou = header.iter().position(|h| *h == "iou").unwrap();
    assert!(gon.len() == header.len() && header[header.len() - 1] == "half", "{csv}");
    assert!(gon[iou..header.len() - 1].iter().all(|f| f.is_empty()), "{csv}");
    assert_eq!(field(&gon, "half"), "design");
    // SIG-AUTO returns the circle and the annulus with its hole: good, and quiet about it.
    for name in ["disc", "annulus"] {
        let r = row(name, ",sig-auto,");
        let iou: f64 = field(&r, "iou").parse().unwrap();
        let h: f64 = field(&r, "hausdorff_over_s").parse().unwrap();
        assert!(iou > 0.98 && h < 0.1, "{name}: {csv}");
        assert_eq!(field(&r, "topology_right") + &field(&r, "good") + &field(&r, "warned"), "110");
        // Sampled on the curve: the bound is one spacing (up to the 400-gon's sagitta).
        let bound: f64 = field(&r, "hausdorff_bound_over_s").parse().unwrap();
        assert!((1.0..1.01).contains(&bound), "{name}: {csv}");
    }
    // The import never warns: the disc is good, the annulus without its hole silently wrong.
    let disc = row("disc", ",hull,");
    assert_eq!([field(&disc, "good"), field(&disc, "warned")], ["1", "0"], "{csv}");
    let annulus = row("annulus", ",hull,");
    assert_eq!(field(&annulus, "topology_right") + &field(&annulus, "silent_wrong"), "01");
    let md = fs::read_to_string(out.path().join("report.md")).unwrap();
    assert!(md.contains("## Judged against the true curve"), "{md}");
    assert!(md.contains("- `hull` (1): `annulus` (IoU 0.74"), "{md}");
    assert!(md.contains("| Method | outline-clean · design | outline-clean · held-out |"), "{md}");
    // numbers.json: the counts per method, category and half.
    let json = fs::read_to_string(out.path().join("numbers.json")).unwrap();
    let json: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(json["folder"], ds);
    let rows = json["rows"].as_array().unwrap();
    let groups = "2 methods x (2 categories, manifold eps<1, all) x (all, 2 halves)";
    assert_eq!(rows.len(), 2 * 4 * 3, "{groups}");
    let find = |method: &str, category: &str, half: &str| {
        let key = |r: &&serde_json::Value| {
            r["method"] == method && r["category"] == category && r["half"] == half
        };
        rows.iter().find(key).unwrap_or_else(|| panic!("{method} {category} {half}: {json}"))
    };
    let hull = find("hull", "outline-clean", "held-out");
    assert_eq!(
        (&hull["cases"], &hull["good"], &hull["silent_wrong"]),
        (&1.into(), &0.into(), &1.into())
    );
    let sig = find("sig-auto", "all", "all");
    assert_eq!(
        (&sig["cases"], &sig["judged"], &sig["good_silent"]),
        (&3.into(), &2.into(), &2.into())
    );
    assert!(find("sig-auto", "manifold", "design")["good"].is_null());
}

#[test]
fn imported_results_are_scored_under_the_time_limit_and_pipes_are_refused() {
    let data = tempdir();
    let d = data.path();
    let n = 3000;
    let mut rng = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        rng
    };
    let points: Vec<[f64; 2]> =
        (0..n).map(|_| [(next() % 1_000_000) as f64, (next() % 1_000_000) as f64]).collect();
    write_points(d, "cloud.xy", &points);
    fs::write(d.join("cloud.gt"), edges_text(&cycle_edges(n))).unwrap();
    fs::write(d.join("index.csv"), format!("name,category,n_points\ncloud,manifold,{n}\n"))
        .unwrap();
    // A wild result: 9000 random chords, crossing everywhere, slow for the area metric.
    let other = tempdir();
    let wild: Vec<[usize; 2]> = (0..3 * n)
        .map(|_| (next() as usize % n, next() as usize % n))
        .filter(|(i, j)| i != j)
        .map(|(i, j)| [i.min(j), i.max(j)])
        .collect();
    fs::write(other.path().join("cloud.edges"), edges_text(&wild)).unwrap();
    let import = format!("wild={}", other.path().display());
    let out = tempdir();
    let (ds, o) = (d.to_str().unwrap(), out.path().to_str().unwrap());
    let args = ["bench", ds, "--method", "emst", "--out", o, "--import", &import];
    sigdt(&[&args[..], &["--time-limit", "0.3"]].concat()).expect(0);
    let csv = fs::read_to_string(out.path().join("results.csv")).unwrap();
    assert!(csv.lines().any(|l| l.contains(",wild,timeout,")), "{csv}");
    // A named pipe as a case file is refused at once instead of blocking the run.
    fs::remove_file(d.join("cloud.xy")).unwrap();
    let status = std::process::Command::new("mkfifo").arg(d.join("cloud.xy")).status().unwrap();
    assert!(status.success());
    sigdt(&["bench", ds, "--out", o]).error(&["cloud.xy: not a regular file"]);
}

#[test]
fn bench_errors_are_clear() {
    let data = labelled_folder();
    let d = data.path().to_str().unwrap();
    let nope = sigdt(&["bench", d, "--method", "crust,nope"]);
    assert!(nope.usage_error().stderr.contains("unknown method 'nope'"), "{nope}");
    sigdt(&["sweep", "noise", d, "--method", ","]).usage_error();
    sigdt(&["bench", d, "--categories", "open"]).error(&["no case matches"]);
    let empty = tempdir();
    sigdt(&["bench", empty.path().to_str().unwrap()]).error(&["index.csv"]);
    sigdt(&["bench", d, "--time-limit", "0"]).usage_error();
    sigdt(&["bench", d, "--import", "nolabel"]).usage_error();
}

#[test]
fn a_hanging_or_crashing_method_is_recorded_not_fatal() {
    // A case too large to finish in the limit: a time-out, and the other case still runs.
    // 20 000 points take about 30 ms in a release build (far more in a debug one), 30 times
    // the 1 ms limit; the case's epsilon, computed whatever the method does, stays quick.
    let data = labelled_folder();
    let big: Vec<[f64; 2]> = circle(20_000, 1.0);
    write_points(data.path(), "big.xy", &big);
    fs::write(data.path().join("big.gt"), edges_text(&cycle_edges(20_000))).unwrap();
    let index = fs::read_to_string(data.path().join("index.csv")).unwrap();
    fs::write(data.path().join("index.csv"), format!("{index}big,large,20000,\n")).unwrap();
    let out = tempdir();
    let (d, o) = (data.path().to_str().unwrap(), out.path().to_str().unwrap());
    let run = sigdt(&[
        "bench",
        d,
        "--method",
        "sig-connect2d",
        "--out",
        o,
        "--time-limit",
        "0.001",
        "--names",
        "g",
    ]);
    run.expect(0);
    let csv = fs::read_to_string(out.path().join("results.csv")).unwrap();
    assert!(csv.lines().any(|l| l.starts_with("big,") && l.contains(",timeout,")), "{csv}");
}

#[test]
fn eval_scores_a_method_and_an_edge_file() {
    let dir = tempdir();
    let pts = write_points(dir.path(), "gon.xy", &circle(12, 1.0));
    fs::write(dir.path().join("gon.gt"), edges_text(&cycle_edges(12))).unwrap();
    let (p, gt) = (pts.to_str().unwrap(), dir.path().join("gon.gt"));
    let run = sigdt(&["eval", p, "--gt", gt.to_str().unwrap()]);
    run.expect(0);
    assert!(run.stdout.contains("exact:") && run.stdout.contains("yes"), "{run}");
    assert!(run.stdout.contains("epsilon:"), "{run}");
    fs::write(dir.path().join("bad.edges"), "0 1\n1 99\n").unwrap();
    let bad = dir.path().join("bad.edges");
    let run = sigdt(&["eval", p, "--gt", gt.to_str().unwrap(), "--edges", bad.to_str().unwrap()]);
    run.error(&["--edges", "refers to point 99"]);
}

fn simple_svg() -> String {
    let svg = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/svg/simple.svg");
    svg.to_str().unwrap().to_string()
}

#[test]
fn sample_writes_points_and_ground_truth_that_reconstruct_exactly() {
    let dir = tempdir();
    let d = dir.path();
    sigdt_in(d, &["sample", &simple_svg(), "--eps", "0.3", "--offset", "0.35", "-o", "s.xy"], None)
        .ok();
    let gt = fs::read_to_string(d.join("s.gt")).unwrap();
    let points = fs::read_to_string(d.join("s.xy")).unwrap();
    assert_eq!(gt.lines().count(), points.lines().count(), "a closed curve: n edges");
    sigdt_in(d, &["reconstruct", "s.xy"], None).ok().stdout_is(&gt);
    // lfs noise writes the clean positions too; same seed, same file.
    let noisy = ["sample", &simple_svg(), "--eps", "0.3", "--lfs-noise", "0.1", "-o", "n.xy"];
    sigdt_in(d, &noisy, None).ok();
    let first = fs::read_to_string(d.join("n.xy")).unwrap();
    assert!(d.join("n.truth.xy").is_file() && first != points);
    sigdt_in(d, &noisy, None).ok();
    assert_eq!(fs::read_to_string(d.join("n.xy")).unwrap(), first);
    sigdt_in(d, &["sample", &simple_svg(), "--eps", "0", "-o", "z.xy"], None).error(&["eps"]);
    sigdt_in(d, &["sample", &simple_svg(), "--eps", "0.3", "--path", "9", "-o", "z.xy"], None)
        .error(&["--path 9"]);
    assert!(!d.join("z.xy").exists());
}

#[test]
fn perturb_adds_noise_and_outliers_deterministically() {
    let dir = tempdir();
    write_points(dir.path(), "gon.xy", &circle(50, 1.0));
    let noisy = sigdt_in(dir.path(), &["perturb", "gon.xy", "--noise", "0.01"], None);
    noisy.ok();
    assert_eq!(noisy.stdout.lines().count(), 50);
    let again = sigdt_in(dir.path(), &["perturb", "gon.xy", "--noise", "0.01"], None);
    assert_eq!(again.stdout, noisy.stdout);
    let more = sigdt_in(dir.path(), &["perturb", "gon.xy", "--outliers", "0.1"], None);
    assert_eq!(more.ok().stdout.lines().count(), 55);
    sigdt_in(dir.path(), &["perturb", "gon.xy", "--noise=-1"], None).error(&["-1"]);
}

#[test]
fn sweep_writes_a_table_and_charts() {
    let dir = tempdir();
    let args = [
        "sweep",
        "eps",
        &simple_svg(),
        "--levels",
        "0.3,0.5",
        "--method",
        "sig-connect2d,crust",
        "--out",
        "sw",
    ];
    sigdt_in(dir.path(), &args, None).expect(0);
    let csv = fs::read_to_string(dir.path().join("sw/sweep.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 2 * 2, "{csv}");
    assert!(csv.contains("eps,0.3,sig-connect2d,20,20,20,"), "{csv}");
    for chart in ["rmse.svg", "exact.svg"] {
        assert!(fs::read_to_string(dir.path().join("sw").join(chart)).unwrap().contains("<svg"));
    }
    // RMSE is measured against the Bézier curve itself: exact results are off the curve by
    // the chords' sagittas, more at the sparser eps.
    let rmse = |level: &str| -> f64 {
        let row =
            csv.lines().find(|l| l.starts_with(&format!("eps,{level},sig-connect2d"))).unwrap();
        row.rsplit(',').next().unwrap().parse().unwrap()
    };
    assert!(rmse("0.3") > 1e-4 && rmse("0.5") > rmse("0.3"), "{csv}");
    assert!(dir.path().join("sw/data/eps_0.3/off00.curve.xy").is_file());
    let sets = fs::read_to_string(dir.path().join("sw/sets.csv")).unwrap();
    assert_eq!(sets.lines().count(), 1 + 2 * 20, "{sets}");
    assert!(sets.starts_with("kind,level,set,n_points,gt_in_sigdt\neps,0.3,off00,"), "{sets}");
    assert!(sets.lines().skip(1).all(|l| l.ends_with(",1")), "SIGDT contains every GT: {sets}");
}

#[test]
fn sample_with_junctions_shares_each_junction() {
    let dir = tempdir();
    let d = dir.path();
    let svg = "<svg><path d='M -1,0 L 1,0'/><path d='M 0,-1 L 0,1'/><path d='M 1,0 C 1,1 2,1 2,2'/></svg>";
    fs::write(d.join("x.svg"), svg).unwrap();
    let run =
        sigdt_in(d, &["sample", "x.svg", "--junctions", "--spacing", "0.05", "-o", "x.xy"], None);
    run.expect(0);
    assert!(run.stderr.contains("1 crossings, 0 T-junctions, 1 shared ends"), "{}", run.stderr);
    let points = fs::read_to_string(d.join("x.xy")).unwrap();
    let gt = fs::read_to_string(d.join("x.gt")).unwrap();
    let mut degree = vec![0; points.lines().count()];
    for line in gt.lines() {
        for v in line.split_whitespace() {
            degree[v.parse::<usize>().unwrap()] += 1;
        }
    }
    assert_eq!(degree.iter().filter(|&&k| k == 4).count(), 1, "the crossing");
    assert_eq!(degree.iter().filter(|&&k| k == 1).count(), 4, "the free ends");
    sigdt_in(d, &["sample", "x.svg", "--junctions", "--eps", "0.2", "-o", "y.xy"], None)
        .usage_error();
    sigdt_in(d, &["sample", "x.svg", "--junctions", "--spacing", "0", "-o", "y.xy"], None)
        .error(&["spacing 0"]);
    assert!(!d.join("y.xy").exists());
}

#[test]
fn outputs_never_replace_the_inputs() {
    let data = labelled_folder();
    let d = data.path().to_str().unwrap();
    sigdt(&["bench", d, "--out", d]).error(&["--out is the data folder"]);
    let imported = format!("connect2d={d}");
    sigdt(&["bench", d, "--method", "connect2d", "--import", &imported])
        .error(&["already names a method"]);
    let dir = tempdir();
    let svg = dir.path().join("c.svg");
    fs::copy(simple_svg(), &svg).unwrap();
    let before = fs::read(&svg).unwrap();
    let s = svg.to_str().unwrap();
    sigdt(&["sample", s, "--eps", "0.3", "-o", s]).error(&["refusing to overwrite"]);
    assert_eq!(fs::read(&svg).unwrap(), before);
    assert!(!dir.path().join("c.gt").exists(), "nothing written when one output is refused");
}

#[test]
fn a_sweep_never_writes_into_its_own_input() {
    let data = labelled_folder();
    let index = fs::read(data.path().join("index.csv")).unwrap();
    let d = data.path().to_str().unwrap();
    let parent = data.path().parent().unwrap().to_str().unwrap();
    for out in [d, parent] {
        sigdt(&["sweep", "noise", d, "--levels", "0.01", "--out", out]).usage_error();
    }
    assert_eq!(fs::read(data.path().join("index.csv")).unwrap(), index);
    assert!(!data.path().join("data").exists() && !data.path().join("sweep.csv").exists());
}

#[test]
fn gallery_draws_cases_and_each_methods_failures() {
    let data = labelled_folder();
    let out = tempdir();
    let (d, o) = (data.path().to_str().unwrap(), out.path());
    let rep = o.join("rep");
    sigdt(&["bench", d, "--method", "sig-connect2d,emst", "--out", rep.to_str().unwrap()])
        .expect(0);
    let results = rep.join("results.csv");
    let failures = o.join("failures");
    let args = ["gallery", d, "--failures", results.to_str().unwrap(), "--out"];
    sigdt(&[&args[..], &[failures.to_str().unwrap()]].concat()).expect(0);
    let page = fs::read_to_string(failures.join("gallery.md")).unwrap();
    assert!(page.contains("## `emst`: 3 of 3 cases not exact"), "{page}");
    assert!(page.contains("## `sig-connect2d`: 1 of 3 cases not exact"), "{page}");
    assert!(page.contains("`broken` (failed)"), "{page}");
    assert!(page.contains("](emst/gon.emst.svg)"), "{page}");
    let svg = fs::read_to_string(failures.join("emst/square.emst.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("emst: "), "{svg}");

    let table = o.join("table");
    let args = ["gallery", d, "--cases", "gon", "--method", "sig-connect2d,emst", "--out"];
    sigdt(&[&args[..], &[table.to_str().unwrap()]].concat()).expect(0);
    let page = fs::read_to_string(table.join("gallery.md")).unwrap();
    assert!(page.contains("`sig-connect2d`: exact (polygon)"), "{page}");
    assert!(table.join("gon.emst.svg").is_file());

    let nope = ["gallery", d, "--cases", "nope", "--out", table.to_str().unwrap()];
    sigdt(&nope).error(&["no case 'nope'"]);
    sigdt(&["gallery", d, "--out", table.to_str().unwrap()]).usage_error();
    sigdt(&["gallery", d, "--cases", "gon", "--out", d]).error(&["is the data folder"]);
}

#[test]
fn sample_is_the_same_at_every_scale_and_refuses_a_curve_that_crosses_itself() {
    // Issue 30, G17: a circle of radius 1e18 drawn as two arcs took 20 s (svgtypes' absolute
    // arc tolerance); at 1e200 sampling overflowed. Now each is read at a fixed size.
    let dir = tempdir();
    let counts: Vec<usize> = ["1", "1e18", "1e200", "1e-200"]
        .iter()
        .map(|r| {
            let d = format!("M {r} 0 A {r} {r} 0 1 0 -{r} 0 A {r} {r} 0 1 0 {r} 0");
            let svg = format!("<svg xmlns='http://www.w3.org/2000/svg'><path d='{d}'/></svg>");
            fs::write(dir.path().join("c.svg"), svg).unwrap();
            sigdt_in(dir.path(), &["sample", "c.svg", "--eps", "0.3", "-o", "c.xy"], None)
                .expect(0);
            fs::read_to_string(dir.path().join("c.xy")).unwrap().lines().count()
        })
        .collect();
    assert!(counts.iter().all(|&c| c >= 8 && c.abs_diff(counts[0]) <= 2), "{counts:?}");
    // G18: a figure eight through one point twice gave a ground truth that crosses itself.
    let eight = "M 0 0 C 50 50 100 50 100 0 C 100 -50 50 -50 0 0 C -50 50 -100 50 -100 0 \
                 C -100 -50 -50 -50 0 0 Z";
    let svg = format!("<svg xmlns='http://www.w3.org/2000/svg'><path d='{eight}'/></svg>");
    fs::write(dir.path().join("eight.svg"), svg).unwrap();
    sigdt_in(dir.path(), &["sample", "eight.svg", "--eps", "0.3", "-o", "e.xy"], None)
        .error(&["eight.svg: path 0 crosses itself", "--junctions"]);
    assert!(!dir.path().join("e.xy").exists());
}
