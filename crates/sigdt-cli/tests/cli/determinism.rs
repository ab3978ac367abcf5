//! The binary's output is byte-identical across runs, for every method and output format,
//! on an input full of exact ties (a shuffled grid, with duplicates).
use super::*;

#[test]
fn repeated_runs_give_byte_identical_output() {
    let dir = tempdir();
    let k = 12;
    let mut points: Vec<[f64; 2]> = (0..k * k).map(|i| [(i % k) as f64, (i / k) as f64]).collect();
    points.extend_from_within(..10);
    // A fixed permutation (multiplication by a unit modulo the prime 157 ≥ the length).
    let n = points.len();
    let shuffled: Vec<[f64; 2]> =
        (0..157).map(|i| (i * 37) % 157).filter(|&i| i < n).map(|i| points[i]).collect();
    assert_eq!(shuffled.len(), n);
    write_points(dir.path(), "grid.xy", &shuffled);
    for &method in sigdt::Method::ALL {
        // OPTIMALTRANSPORT's own vertices are written as coordinates only.
        let own = method == sigdt::Method::OptimalTransport;
        for format in if own { ["wkt", "geojson"] } else { ["edges", "geojson"] } {
            let args = ["reconstruct", "grid.xy", "--method", method.name(), "--format", format];
            // Exit 0; stderr may note that sculpting got stuck (the grid), identically.
            let first = sigdt_in(dir.path(), &args, None);
            first.expect(0);
            let second = sigdt_in(dir.path(), &args, None);
            second.expect(0).stdout_is(&first.stdout);
            assert_eq!(second.stderr, first.stderr, "{}", second.what);
        }
    }
}

#[test]
fn every_thread_count_gives_the_same_output() {
    // Large enough for the data-parallel passes to split their work (a noisy closed curve).
    let dir = tempdir();
    let points: Vec<[f64; 2]> = (0..20_000)
        .map(|i| {
            let t = i as f64 * 0.000_314_159_265_358_979_3;
            let r = 1.0 + 0.2 * (5.0 * t).sin() + 1e-4 * ((i * 7919 % 101) as f64 / 101.0);
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    write_points(dir.path(), "curve.xy", &points);
    let default = sigdt_in(dir.path(), &["reconstruct", "curve.xy"], None);
    default.expect(0);
    for threads in ["1", "2", "3"] {
        let run = sigdt_in(dir.path(), &["--threads", threads, "reconstruct", "curve.xy"], None);
        run.expect(0).stdout_is(&default.stdout);
    }
    // A count of 0 is a usage error.
    sigdt_in(dir.path(), &["reconstruct", "curve.xy", "--threads", "0"], None).expect(2);
}

#[test]
fn a_huge_or_bad_thread_count_in_the_environment_is_no_crash() {
    // Issue 30, G14: RAYON_NUM_THREADS=100000 panicked (exit 101) after five seconds.
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    let run = |value: &str| {
        let out = sigdt_command()
            .args(["reconstruct", "square.xy"])
            .current_dir(dir.path())
            .env("RAYON_NUM_THREADS", value)
            .stdin(Stdio::null())
            .output()
            .expect("cannot run sigdt");
        (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
    };
    assert_eq!(run("100000"), (Some(0), String::new()));
    assert_eq!(run("0"), (Some(0), String::new()));
    let (code, stderr) = run("many");
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("RAYON_NUM_THREADS='many': not a thread count"), "{stderr}");
}
