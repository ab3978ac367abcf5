use super::*;
use crate::geometry::Point;
use crate::internals::check_reconstruction;
use crate::result::LeftOutReason;

fn circle(n: usize, r: f64) -> Vec<Point> {
    crate::samplers::regular_polygon(n, r).points
}

fn run(points: &[Point]) -> Reconstruction {
    let rec = fit_connect_on(&Triangulation::new(points).unwrap());
    check_reconstruction(points, &rec).unwrap();
    rec
}

#[test]
fn a_dense_circle_is_one_loop() {
    let pts = circle(40, 1.0);
    let rec = run(&pts);
    assert_eq!(rec.status, Status::Polygon, "{rec:?}");
    assert_eq!(rec.edges.len() + rec.left_out.len(), 40);
}

fn arc(n: usize, radius: f64, sweep: f64) -> Vec<Point> {
    (0..n)
        .map(|i| {
            let a = sweep * i as f64 / (n - 1) as f64;
            [radius * a.cos(), radius * a.sin()]
        })
        .collect()
}

#[test]
fn an_open_arc_is_one_path_between_two_leaves() {
    let pts = arc(30, 1.0, 2.0);
    let rec = run(&pts);
    assert_eq!(rec.status, Status::Curves, "{rec:?}");
    assert_eq!(rec.paths, vec![(0..30).collect::<Vec<_>>()], "{rec:?}");
    assert!(rec.left_out.is_empty());
}

#[test]
fn two_far_circles_are_two_loops() {
    let mut pts = circle(30, 1.0);
    pts.extend(circle(30, 1.0).iter().map(|p| [p[0] + 10.0, p[1]]));
    let rec = run(&pts);
    assert_eq!((rec.status.clone(), rec.loops.len()), (Status::Polygons, 2), "{rec:?}");
}

#[test]
fn noise_is_thinned_into_one_loop() {
    // 300 points on a unit circle with uniform radial noise of ±0.03, about the spacing:
    // FITCONNECT eliminates points between linked ones and keeps one loop through the rest
    // (15 points eliminated today).
    let mut seed: u64 = 12345;
    let pts: Vec<Point> = (0..300)
        .map(|i| {
            seed = (seed * 1103515245 + 12345) % (1 << 31);
            let a = i as f64 * std::f64::consts::TAU / 300.0;
            let r = 1.0 + 0.03 * (seed as f64 / (1u64 << 31) as f64 * 2.0 - 1.0);
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    let rec = run(&pts);
    assert_eq!((rec.status.clone(), rec.loops.len()), (Status::Polygon, 1));
    assert!(!rec.left_out.is_empty());
    assert!(rec.left_out.iter().all(|l| l.reason == LeftOutReason::Eliminated));
    assert_eq!(rec.loops[0].len() + rec.left_out.len(), 300);
}

#[test]
fn the_pass_limit_leaves_the_undecided_points_out() {
    // The ends of an open arc only become leaves once their neighbourhoods hold every
    // point, after about n passes.
    let pts = arc(30, 1.0, 2.0);
    let dt = Triangulation::new(&pts).unwrap();
    let rec = fit_connect_with_limit(&dt, 2);
    check_reconstruction(&pts, &rec).unwrap();
    assert_eq!(rec.status, Status::Unfinished);
    assert!(rec.left_out.iter().any(|l| l.reason == LeftOutReason::Unresolved));
    assert_eq!(fit_connect_on(&dt).status, Status::Curves);
}

#[test]
fn a_grid_stops_at_the_work_limit() {
    // On a grid most points never conform, so their neighbourhoods would grow to every
    // point (n³ work): the work limit ends the run.
    let pts: Vec<Point> = (0..900).map(|i| [(i % 30) as f64, (i / 30) as f64]).collect();
    let rec = run(&pts);
    assert_eq!(rec.status, Status::Unfinished, "{:?}", rec.status);
}

#[test]
fn results_repeat_and_do_not_depend_on_scale_or_offset() {
    let pts: Vec<Point> = (0..120)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / 120.0;
            let r = 1.0 + 0.3 * (3.0 * a).sin() + 0.01 * ((i * 31 % 7) as f64 - 3.0);
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    let first = run(&pts);
    assert_eq!(run(&pts), first);
    // Power-of-two scaling and an exactly representable offset change no decision.
    let moved: Vec<Point> = pts.iter().map(|p| [p[0] * 8.0 + 1024.0, p[1] * 8.0 - 512.0]).collect();
    let second = run(&moved);
    assert_eq!((second.edges, second.left_out), (first.edges, first.left_out));
}
