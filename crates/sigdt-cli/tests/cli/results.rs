//! Outputs: every format, the graphs, degenerate input, help texts and a labelled curve.

use super::*;

#[test]
fn square_gives_its_four_sides() {
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    sigdt_in(dir.path(), &["reconstruct", "square.xy"], None).ok().stdout_is(SQUARE_EDGES);
}

#[test]
fn regular_12_gon_gives_the_cycle() {
    let dir = tempdir();
    write_points(dir.path(), "gon.xy", &circle(12, 3.0));
    let expected = edges_text(&cycle_edges(12));
    sigdt_in(dir.path(), &["reconstruct", "gon.xy"], None).ok().stdout_is(&expected);
}

#[test]
fn stdin_input_with_autodetected_format() {
    let dir = tempdir();
    let text = "x,y\n0,0\n1, 0 # comment\n\n1\t1\n0 1\n";
    sigdt_in(dir.path(), &["reconstruct", "-"], Some(text)).ok().stdout_is(SQUARE_EDGES);
    let gtn = "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n";
    sigdt_in(dir.path(), &["reconstruct", "-"], Some(gtn)).ok().stdout_is(SQUARE_EDGES);
}

#[test]
fn gtn_and_p2d_files() {
    let dir = tempdir();
    fs::write(dir.path().join("sq.gtn"), "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n").unwrap();
    fs::write(dir.path().join("sq.p2d"), "0 0\n1 0\n1 1\n0 1\n").unwrap();
    for name in ["sq.gtn", "sq.p2d"] {
        sigdt_in(dir.path(), &["reconstruct", name], None).ok().stdout_is(SQUARE_EDGES);
    }
}

#[test]
fn every_output_format() {
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    let run = |format: &str| {
        sigdt_in(dir.path(), &["reconstruct", "square.xy", "--format", format], None)
    };
    run("edges").ok().stdout_is(SQUARE_EDGES);
    run("loops").ok().stdout_is("0 1 2 3\n");
    let wkt = run("wkt");
    assert!(wkt.ok().stdout.starts_with("POLYGON (("), "wkt\n{wkt}");
    let json = run("geojson");
    let compact: String = json.ok().stdout.split_whitespace().collect();
    assert!(compact.contains(r#""type":"Feature""#), "geojson\n{json}");
    assert!(compact.contains(r#""status":"polygon""#), "geojson\n{json}");
    let svg = run("svg");
    let text = svg.ok().stdout.trim_start();
    assert!(text.starts_with("<svg") || text.starts_with("<?xml"), "svg\n{svg}");
    assert!(text.trim_end().ends_with("</svg>"), "svg\n{svg}");
}

#[test]
fn verbose_summary_goes_to_stderr() {
    let dir = tempdir();
    write_points(dir.path(), "gon.xy", &circle(12, 1.0));
    let run = sigdt_in(dir.path(), &["reconstruct", "gon.xy", "-v"], None);
    run.expect(0).stdout_is(&edges_text(&cycle_edges(12)));
    for needle in [
        "points:",
        "12",
        "distinct points:",
        "duplicates:",
        "edges:",
        "loops:",
        "status:",
        "polygon",
        "time:",
        " ms",
        "graph edges:",
        "sculpted triangles:",
    ] {
        assert!(run.stderr.contains(needle), "stderr lacks {needle:?}\n{run}");
    }
    let run = sigdt_in(
        dir.path(),
        &[
            "reconstruct",
            "gon.xy",
            "--verbose",
            "--no-leaf-elimination",
            "--method",
            "sig-connect2d",
        ],
        None,
    );
    run.expect(0).stdout_is(&edges_text(&cycle_edges(12)));
    assert!(run.stderr.contains("leaf elimination off"), "{run}");
    // The default method, SIG-AUTO, does not use the option: refused, not dropped.
    let run = sigdt_in(dir.path(), &["reconstruct", "gon.xy", "--no-leaf-elimination"], None);
    run.usage_error();
    assert!(run.stderr.contains("applies to sig-connect2d only"), "{run}");
    let run = sigdt_in(dir.path(), &["reconstruct", "gon.xy", "--verbose"], None);
    assert!(run.expect(0).stderr.contains("method:                    sig-auto\n"), "{run}");
}

#[test]
fn graph_kinds() {
    let dir = tempdir();
    write_points(dir.path(), "tt.xy", &two_triangles());
    write_points(dir.path(), "square.xy", &square());
    let count = |args: &[&str]| -> Vec<[usize; 2]> {
        let run = sigdt_in(dir.path(), args, None);
        run.ok();
        run.stdout
            .lines()
            .map(|l| {
                let v: Vec<usize> = l.split(' ').map(|t| t.parse().expect("index")).collect();
                assert!(v.len() == 2 && v[0] < v[1], "bad edge line {l:?}\n{run}");
                [v[0], v[1]]
            })
            .collect()
    };
    let triangles = vec![[0, 1], [0, 2], [1, 2], [3, 4], [3, 5], [4, 5]];
    // All six points are on the hull: a triangulation has 2n - 3 = 9 edges.
    assert_eq!(count(&["graph", "tt.xy", "--kind", "dt"]).len(), 9);
    // Edges between the triangles are >= 9 > nn(i) + nn(j) <= 2.24: only the triangles stay.
    for kind in ["sig", "sigdt", "sigdt2"] {
        assert_eq!(count(&["graph", "tt.xy", "--kind", kind]), triangles, "--kind {kind}");
    }
    assert_eq!(count(&["graph", "tt.xy", "--kind", "knn", "-k", "2"]), triangles, "knn -k 2");
    let emst = count(&["graph", "tt.xy", "--kind", "emst"]);
    assert_eq!(emst.len(), 5, "EMST of 6 points: {emst:?}");
    for e in [[0, 1], [1, 3], [3, 4]] {
        assert!(emst.contains(&e), "EMST lacks {e:?}: {emst:?}");
    }
    assert_eq!(count(&["graph", "square.xy", "--kind", "dt"]).len(), 5);
    assert_eq!(count(&["graph", "square.xy", "--kind", "emst"]).len(), 3);
    sigdt_in(dir.path(), &["graph", "square.xy", "--kind", "dt", "-o", "g.edges"], None)
        .ok()
        .stdout_is("");
    assert_eq!(fs::read_to_string(dir.path().join("g.edges")).unwrap().lines().count(), 5);
    let run = sigdt_in(
        dir.path(),
        &["graph", "-", "--kind", "knn", "-k", "1"],
        Some("0 0\n1 0\n5 0.5\n"),
    );
    run.ok().stdout_is("0 1\n1 2\n");
}

/// Runs `reconstruct -v` on `text` (stdin) and checks stdout and the status name.
fn degenerate(text: &str, expected_edges: &str, status: &str) -> Run {
    let run = sigdt_in(tempdir().path(), &["reconstruct", "-", "-v"], Some(text));
    run.expect(0).stdout_is(expected_edges);
    assert!(
        run.stderr.contains("status:") && run.stderr.contains(status),
        "expected status {status}\n{run}"
    );
    run
}

#[test]
fn too_few_points() {
    degenerate("", "", "too-few-points");
    degenerate("# only a comment\n", "", "too-few-points");
    degenerate("2.5 3\n", "", "too-few-points");
    degenerate("2.5 3\n-1 0\n", "0 1\n", "too-few-points");
    degenerate("2.5 3\n2.5 3\n2.5 3\n", "", "too-few-points");
}

#[test]
fn collinear_points_give_the_path_in_line_order() {
    // x = 3, 0, 4, 1, 2 on y = 2x + 1: line order is 1, 3, 4, 0, 2.
    let text = "3 7\n0 1\n4 9\n1 3\n2 5\n";
    degenerate(text, "0 2\n0 4\n1 3\n3 4\n", "collinear");
    let run = sigdt_in(tempdir().path(), &["reconstruct", "-", "--format", "loops"], Some(text));
    run.ok().stdout_is("path 1 3 4 0 2\n");
}

#[test]
fn duplicates_get_no_edges() {
    // Points 4 and 5 repeat points 1 and 0.
    let text = "0 0\n1 0\n1 1\n0 1\n1 0\n0 0\n";
    let run = degenerate(text, SQUARE_EDGES, "polygon");
    assert!(run.stderr.contains("duplicates:                2"), "{run}");
}

#[test]
fn help_and_version() {
    let version = sigdt(&["--version"]);
    version.ok();
    assert!(version.stdout.contains(env!("CARGO_PKG_VERSION")), "{version}");
    let top = sigdt(&["--help"]);
    for needle in ["reconstruct", "graph", ".gtn", ".p2d", "header", "comment", "Exit status"] {
        assert!(top.ok().stdout.contains(needle), "sigdt --help lacks {needle:?}\n{top}");
    }
    let help = sigdt(&["reconstruct", "--help"]);
    for needle in [
        "--format",
        "--method",
        "sig-connect2d",
        "--no-leaf-elimination",
        "--verbose",
        ".gtn",
        ".p2d",
        "comma",
        "polygon",
        "polygons",
        "sculpting-stuck",
        "collinear",
        "too-few-points",
        "duplicate",
        "geojson",
    ] {
        assert!(help.ok().stdout.contains(needle), "reconstruct --help lacks {needle:?}\n{help}");
    }
    let help = sigdt(&["graph", "--help"]);
    for needle in ["--kind", "sigdt2", "emst", "knn", "-k"] {
        assert!(help.ok().stdout.contains(needle), "graph --help lacks {needle:?}\n{help}");
    }
}

#[test]
fn labelled_bezier_curve_matches_ground_truth() {
    let dir = labelled_curves();
    let name = "bezier0_eps0.1_off00";
    let input = dir.join(format!("{name}.xy"));
    let expected = fs::read_to_string(dir.join(format!("{name}.gt")))
        .unwrap_or_else(|e| panic!("cannot read {name}.gt in {}: {e}", dir.display()));
    let run = sigdt_in(&dir, &["reconstruct", input.to_str().unwrap()], None);
    run.ok().stdout_is(&expected);
}

#[test]
fn sig_auto_writes_loops_with_holes_and_open_paths() {
    // A ring (radii 3 and 1.5, nested) and a half circle apart from it.
    let dir = tempdir();
    let mut points: Vec<[f64; 2]> = circle(60, 3.0);
    points.extend(circle(30, 1.5));
    points.extend((0..20).map(|i| {
        let a = std::f64::consts::PI * i as f64 / 19.0;
        [10.0 + 2.0 * a.cos(), 2.0 * a.sin()]
    }));
    write_points(dir.path(), "ring.xy", &points);
    let args = ["reconstruct", "ring.xy", "--method", "sig-auto"];
    let loops = sigdt_in(dir.path(), &[&args[..], &["--format", "loops"]].concat(), None);
    let lines: Vec<&str> = loops.ok().stdout.lines().collect();
    let path: Vec<String> = (90..110).map(|i| i.to_string()).collect();
    assert_eq!(lines.len(), 3, "{}", loops.stdout);
    assert_eq!(lines[2], format!("path {}", path.join(" ")));
    let wkt = sigdt_in(dir.path(), &[&args[..], &["--format", "wkt"]].concat(), None);
    let text = &wkt.ok().stdout;
    // One polygon with one hole, and the open line: a geometry collection.
    assert!(text.starts_with("GEOMETRYCOLLECTION (POLYGON ((3.0 0.0, "), "{text}");
    assert_eq!(text.matches("), (").count(), 1, "one hole: {text}");
    assert!(text.contains(", LINESTRING (12.0 0.0, "), "{text}");
    let verbose = sigdt_in(dir.path(), &[&args[..], &["--verbose"]].concat(), None);
    assert!(verbose.expect(0).stderr.contains("curves"), "{}", verbose.stderr);
}

#[test]
fn a_method_with_vertices_of_its_own_writes_coordinates_not_indices() {
    let dir = tempdir();
    write_points(dir.path(), "gon.xy", &circle(40, 3.0));
    let run = |format: &str| {
        let args = ["reconstruct", "gon.xy", "--method", "optimal-transport", "--format", format];
        sigdt_in(dir.path(), &args, None)
    };
    for format in ["edges", "loops"] {
        run(format).error(&["optimal-transport", "vertices of its own", "wkt"]);
    }
    // A quarter of the 40 points are left as vertices, off the input points.
    let wkt = run("wkt");
    let text = &wkt.ok().stdout;
    assert!(text.starts_with("POLYGON") || text.starts_with("LINESTRING"), "{wkt}");
    let input: Vec<String> = circle(40, 3.0).iter().map(|[x, y]| format!("{x:?} {y:?}")).collect();
    assert!(!input.iter().all(|p| text.contains(p.as_str())), "{wkt}");
    assert!(run("svg").ok().stdout.contains("drawn at the method&apos;s 10 vertices"));
}

#[test]
fn completions_and_man_pages_come_from_the_definitions() {
    for (shell, needle) in
        [("bash", "_sigdt()"), ("zsh", "#compdef sigdt"), ("fish", "complete -c sigdt")]
    {
        let run = sigdt(&["completions", shell]);
        run.ok();
        assert!(run.stdout.contains(needle), "{shell}: no {needle:?}\n{run}");
        for word in ["reconstruct", "gallery", "method", "sig-connect2d"] {
            assert!(run.stdout.contains(word), "{shell} completion lacks {word:?}");
        }
    }
    sigdt(&["completions", "tcsh"]).usage_error();
    let dir = tempdir();
    sigdt_in(dir.path(), &["manpages", "--out", "man"], None).expect(0);
    let top = fs::read_to_string(dir.path().join("man/sigdt.1")).unwrap();
    assert!(top.starts_with(".ie \\n(.g .ds Aq") || top.contains(".TH sigdt"), "{top}");
    let page = fs::read_to_string(dir.path().join("man/sigdt-reconstruct.1")).unwrap();
    assert!(page.contains(".TH sigdt-reconstruct") && page.contains("sigdt reconstruct"));
    assert!(page.contains("no\\-leaf\\-elimination"), "{page}");
    assert!(!dir.path().join("man/sigdt-bench-worker.1").exists());
}

/// The bundled glyph with noise of 0.8 % of its box (issue 29's example): SIG-CONNECT2D's
/// polygons zigzag across the strokes, and `reconstruct` says so on stderr (exit 0) and in
/// its GeoJSON.
#[test]
fn a_result_that_breaks_the_sampling_condition_says_so() {
    let dir = tempdir();
    let glyph = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/inputs/glyph_n_tilde.xy");
    let glyph = glyph.to_str().unwrap();
    let args = ["perturb", glyph, "--noise", "0.008", "--seed", "1", "-o", "g.xy"];
    sigdt_in(dir.path(), &args, None).expect(0);
    let run = sigdt_in(dir.path(), &["reconstruct", "g.xy", "-o", "g.edges"], None);
    run.expect(0);
    assert!(run.stderr.starts_with("sigdt: warning: "), "{run}");
    assert!(run.stderr.contains("the result may not be the points' curves"), "{run}");
    let json = sigdt_in(dir.path(), &["reconstruct", "g.xy", "--format", "geojson"], None);
    assert!(json.stdout.contains(r#""warning": true, "diagnosis": [{"kind": "#), "{json}");
    // The clean glyph: no warning, and the GeoJSON says that too.
    let clean = sigdt_in(dir.path(), &["reconstruct", glyph, "--format", "geojson"], None);
    assert!(clean.ok().stdout.contains(r#""warning": false}"#), "{clean}");
}

/// Points left out are counted on stderr without `-v`, one line per reason, and listed in
/// the GeoJSON with their reasons.
#[test]
fn left_out_points_are_reported_without_verbose() {
    let dir = tempdir();
    let mut points = circle(60, 1.0);
    points.push([1.6, 0.05]);
    write_points(dir.path(), "c.xy", &points);
    let run = sigdt_in(dir.path(), &["reconstruct", "c.xy", "--method", "sig-auto"], None);
    run.expect(0);
    assert_eq!(run.stderr, "sigdt: left out 1 point(s): outlier\n", "{run}");
    let args = ["reconstruct", "c.xy", "--method", "sig-auto", "--format", "geojson"];
    let json = sigdt_in(dir.path(), &args, None);
    assert!(json.stdout.contains(r#""left_out": [60], "left_out_reasons": ["outlier"]"#), "{json}");
}

#[test]
fn expect_areas_closes_outlines_or_warns() {
    // Togo and Georgia by their vertices (data/vertices): SIG-AUTO reads both as open lines.
    // Told that they outline areas, Togo closes into its polygon; Georgia stays open, and
    // says so.
    let dir = tempdir();
    let vertices = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/vertices");
    for name in ["ne_togo_raw.xy", "ne_georgia_raw.xy"] {
        fs::copy(vertices.join(name), dir.path().join(name)).unwrap();
    }
    let lines = |args: &[&str]| {
        let run = sigdt_in(dir.path(), args, None);
        let stdout = run.expect(0).stdout.clone();
        // `--format loops` writes a loop as its indices, an open path after the word "path".
        let kind = |l: &str| if l.starts_with("path") { "path" } else { "loop" };
        let kinds: Vec<&str> = stdout.lines().map(kind).collect();
        (kinds, run.stderr.clone())
    };
    let (kinds, _) = lines(&["reconstruct", "ne_togo_raw.xy", "--format", "loops"]);
    assert_eq!(kinds, ["path"]);
    let (kinds, _) =
        lines(&["reconstruct", "ne_togo_raw.xy", "--format", "loops", "--expect", "areas"]);
    assert_eq!(kinds, ["loop"]);
    let (kinds, stderr) =
        lines(&["reconstruct", "ne_georgia_raw.xy", "--format", "loops", "--expect", "areas"]);
    assert_eq!(kinds, ["path"]);
    assert!(stderr.contains("come back open although the points outline areas"), "{stderr}");
    let (_, stderr) = lines(&["reconstruct", "ne_georgia_raw.xy", "--format", "loops"]);
    assert!(!stderr.contains("outline areas"), "{stderr}");
    let run =
        sigdt_in(dir.path(), &["reconstruct", "ne_togo_raw.xy", "--expect", "polygons"], None);
    run.usage_error();
    assert!(run.stderr.contains("curves") && run.stderr.contains("areas"), "{run}");
}
