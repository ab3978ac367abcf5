//! Inputs the `eval` fuzz target in `fuzz/` found (docs/fuzzing.md), each fed through the
//! same code path as the target: no panic, and each metric within its time.
use sigdt::{Edge, Point};
use sigdt_lab::eval::{evaluate, graph_epsilon, overlap};

/// What the `eval` fuzz target does: every metric, errors allowed, no panic.
fn evaluate_all(points: &[Point], result: &[Edge], gt: &[Edge]) {
    let _ = evaluate(points, result, gt);
    let _ = graph_epsilon(points, gt);
    let _ = overlap(points, gt);
}

/// The segment grid of the distance metrics overflowed its cell count: with coordinates
/// near 1e301, `w * h` was infinite, the cell size fell back to 1 and `w / 1 + 1` overflowed
/// `i64`. Fuzz input `eval/crash_grid_cell_overflow`; the first set is its minimised form.
#[test]
fn distance_grid_huge_coordinates() {
    evaluate_all(&[[1e300, -1.8000000000000002e301], [0.0, 0.0]], &[[0, 0]], &[[0, 1], [1, 0]]);
    let points = [[0.0, 0.0], [-7e300, -2.4e301], [1e300, 0.0]];
    evaluate_all(&points, &[[0, 0]], &[[0, 1], [2, 0]]);
    evaluate(&points, &[[0, 1]], &[[0, 1], [0, 2]]).unwrap();
    // Extents that overflow f64 themselves: no panic, no endless loop.
    let points = [[-1.7e308, -1.7e308], [1.7e308, 1.7e308], [1.7e308, -1.7e308]];
    evaluate_all(&points, &[[0, 1]], &[[0, 1], [1, 2]]);
}

/// `evaluate` took minutes (fuzzing finding 4). A result edge 1e15 long against a ground
/// truth 52 across was sampled every 52/2000 (capped at 2^24 samples per edge), and each
/// sample far outside the ground truth's segment grid walked O(side²) cells of a grid with
/// up to 4097 cells a side. Fixed: the grid has at most 2√m + 1 cells a side, and an edge
/// set gets at most 2^20 interior samples. Fuzz input
/// `eval/timeout-d9e581de43ff62f8ba700dd6d03f8a38567ced2c`, shortened.
#[test]
fn distance_sampling_far_outside_the_ground_truth() {
    let points = [[0.0, 0.0], [3.184081677783118e-15, 52.0], [1e15, 1e15]];
    evaluate_all(&points, &[[0, 2]], &[[0, 0], [1, 1]]);
}

/// The other shape of finding 4: a ground truth of two zero-length edges at the ends of a
/// 5-unit segment (a flat box: 4097 cells in a row) and a result along it; every sample
/// walked thousands of empty cells.
#[test]
fn distance_grid_with_two_far_apart_points() {
    let points: Vec<[f64; 2]> = (0..7).map(|i| [5.0 * i as f64 / 6.0, 0.0]).collect();
    let path: Vec<[usize; 2]> = (0..6).map(|i| [i, i + 1]).collect();
    evaluate_all(&points, &path, &[[0, 0], [6, 6]]);
}

/// An integer overflow inside `i_overlay` (debug builds; release builds wrapped silently):
/// a ground-truth ring of subnormal coordinates, whose tiny extent made i_overlay's
/// float-to-integer scale enormous. Fixed: `area_difference` scales the rings by a power of
/// two into [1, 2) first. Fuzz input `eval/crash-11926346534a67d2b36ae3fa8bf73c8ac4626585`.
#[test]
fn area_of_subnormal_rings() {
    let points = [
        [10.0, -1.0],
        [0.0, 0.0],
        [1e-310, 0.0],
        [2e-310, 0.0],
        [3e-310, 0.0],
        [4e-310, 0.0],
        [5e-310, 0.0],
        [6e-310, 0.0],
        [0.0, 0.0],
        [0.0, 1e-310],
        [0.0, 2e-310],
        [0.0, 3e-310],
        [0.0, 4e-310],
        [0.0, 5e-310],
        [0.0, 6e-310],
        [0.0, 7e-310],
        [1e-310, 0.0],
        [1e-310, 1e-310],
        [1e-310, 2e-310],
        [1e-310, 3e-310],
        [1e-310, 4e-310],
        [1e-310, 5e-310],
        [1e-310, 6e-310],
        [1e-310, 7e-310],
        [2e-310, 0.0],
        [2e-310, 1e-310],
        [2e-310, 2e-310],
        [2e-310, 3e-310],
        [2e-310, 4e-310],
        [2e-310, 5e-310],
        [2e-310, 6e-310],
        [2e-310, 7e-310],
    ];
    evaluate_all(&points, &[[16, 1], [13, 0]], &[[1, 2], [2, 15]]);
    let area =
        sigdt_lab::eval::area_difference(&points, &[[16, 1], [13, 0]], &[[1, 2], [2, 15]]).unwrap();
    assert!(area.area.is_finite() && area.area >= 0.0, "{area:?}");
}

/// `evaluate` took more than 10 s (fuzzing finding 6): ground-truth edges between subnormal
/// points next to an ordinary one. The points were scaled by their overall largest
/// coordinate (1), the edges' diagonal stayed subnormal, the sample spacing `diag / 2000`
/// underflowed to 0 and every edge got 2^24 samples of slow subnormal arithmetic. Fixed:
/// the scale comes from the edges' own ends. Fuzz input
/// `eval/timeout-a22e4856758eb76271baaa88bf2c22f83a27308b`.
#[test]
fn metrics_of_subnormal_edges_next_to_ordinary_points() {
    let t = -5e-324;
    let points = [
        [0.0, 0.0],
        [t, t],
        [0.0, t],
        [t, t],
        [0.0, 0.0],
        [0.0, 0.0],
        [t, t],
        [t, t],
        [-1.0, -1.0],
        [t, t],
    ];
    evaluate_all(&points, &[[4, 2], [1, 1]], &[[2, 3], [0, 3]]);
    let errors = sigdt_lab::eval::distance_errors(&points, &[[4, 2]], &[[2, 3], [0, 3]]);
    assert!(errors.unwrap().is_some_and(|e| e.hausdorff.is_finite()));
}

/// Finding 6 again, by another way in: a self loop on an ordinary point in the result kept
/// the scale at 1, the ground truth's subnormal diagonal made the spacing 0, and every edge
/// got 2^24 samples (8 s). Fixed: the sample budget is counted in samples, not derived from
/// a spacing. Fuzz input `eval/slow-unit-0e8a400b26882218b66464b46a48a39b3e42309c`.
#[test]
fn metrics_of_subnormal_edges_with_a_self_loop_far_away() {
    let points = [
        [0.0, 0.0],
        [-1.0, -1.0],
        [0.0, -5e-324],
        [-5e-324, -5e-324],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [-5e-324, -5e-324],
        [-5e-324, -5e-324],
        [-5e-324, -5e-324],
        [-5e-324, -5e-324],
        [-5e-324, -5e-324],
        [-5e-324, -5e-324],
    ];
    evaluate_all(&points, &[[16, 2], [1, 1]], &[[2, 3], [0, 8]]);
}

/// The `svg` fuzz target's findings 7 to 10 (docs/fuzzing.md): an elliptical arc of
/// radius 4.4e33, one of radius 4.4e12 whose end 4.4e59 away grows its radius, one that
/// starts 5e73 away, and a thin one (radii 9.2e18 and 14) across a chord of 5.6e20, which
/// SVG grows to 1.7e38, made the SVG parser expand millions of cubics (over 10 s, then over
/// 2 GB). All are refused at once, naming the line of their `<path`.
#[test]
fn svg_arcs_that_would_expand_without_bound_are_refused() {
    let findings = [
        ("finding-7-huge-arc", 1),
        ("finding-8-far-arc-end", 4),
        ("finding-9-far-arc-start", 10),
        ("finding-10-thin-arc-long-chord", 5),
    ];
    for (seed, line) in findings {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz/seeds/svg");
        let bytes = std::fs::read(path.join(seed)).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        match sigdt_lab::curves::parse_svg_paths(&text, "fuzz.svg") {
            Err(sigdt::Error::Parse { line: at, message, .. }) => {
                assert!(message.contains("elliptical arc"), "{seed}: {message}");
                assert_eq!(at, line, "{seed}");
            }
            other => panic!("{seed}: {other:?}"),
        }
    }
}
