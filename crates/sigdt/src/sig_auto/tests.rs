use super::*;
use crate::geometry::Point;
use crate::internals::check_reconstruction;
use crate::proximity::emst::minimum_spanning_forest;
use crate::sig_connect2d::sig_connect2d_on;
use std::f64::consts::TAU;

fn arc(n: usize, radius: f64, centre: Point, from: f64, to: f64) -> Vec<Point> {
    (0..n)
        .map(|i| {
            let a = from + (to - from) * i as f64 / (n - 1) as f64;
            [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
        })
        .collect()
}

fn circle(n: usize, radius: f64, centre: Point) -> Vec<Point> {
    (0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
        })
        .collect()
}

fn run(points: &[Point]) -> Reconstruction {
    let rec = sig_auto_on(&Triangulation::new(points).unwrap());
    check_reconstruction(points, &rec).unwrap();
    rec
}

#[test]
fn a_circle_is_one_polygon() {
    let rec = run(&circle(60, 1.0, [0.0, 0.0]));
    assert_eq!(rec.status, Status::Polygon);
    assert_eq!(rec.loops, vec![(0..60).collect::<Vec<_>>()]);
}

#[test]
fn an_open_arc_is_one_path_in_order() {
    // Three quarters of a circle: SIG-CONNECT2D must close it, SIG-AUTO keeps it open.
    let points = arc(40, 1.0, [0.0, 0.0], 0.0, 0.75 * TAU);
    let rec = run(&points);
    assert_eq!(rec.status, Status::Curves);
    assert!(rec.loops.is_empty());
    assert_eq!(rec.paths, vec![(0..40).collect::<Vec<_>>()]);
    let dt = Triangulation::new(&points).unwrap();
    assert!(sig_connect2d_on(&dt, true).status.is_manifold());
}

#[test]
fn a_gap_closes_only_within_twice_the_spacing() {
    // 30 samples at spacing s on a circle of 32 (gap 3s, not closed) or 31 slots (gap 2s).
    for (slots, closed) in [(31, true), (32, false), (34, false)] {
        let points: Vec<Point> = circle(slots, 1.0, [0.0, 0.0]).into_iter().take(30).collect();
        let rec = run(&points);
        assert_eq!(rec.loops.len() == 1, closed, "{slots} slots: {:?}", rec.status);
        assert_eq!(rec.paths.len() == 1, !closed, "{slots} slots");
    }
}

#[test]
fn the_join_ratio_moves_the_bound() {
    // The 3s gap of 30 samples on 32 slots closes only once the ratio exceeds 3; the 2s
    // gap on 31 slots needs more than 2. `sig_auto_on` is the ratio 2.
    let sample =
        |slots| -> Vec<Point> { circle(slots, 1.0, [0.0, 0.0]).into_iter().take(30).collect() };
    for (slots, ratio, closed) in
        [(32, 3.5, true), (32, 2.5, false), (31, 2.0, true), (31, 1.5, false)]
    {
        let points = sample(slots);
        let dt = Triangulation::new(&points).unwrap();
        let rec = sig_auto_with(&dt, &Steps { join_ratio: ratio, ..Steps::default() });
        check_reconstruction(&points, &rec).unwrap();
        assert_eq!(rec.loops.len() == 1, closed, "{slots} slots, ratio {ratio}");
    }
    let dt = Triangulation::new(&sample(31)).unwrap();
    let ratio_2 = Steps { join_ratio: JOIN_RATIO, ..Steps::default() };
    assert_eq!(sig_auto_on(&dt), sig_auto_with(&dt, &ratio_2));
}

#[test]
fn nested_circles_are_two_loops() {
    // SIG-CONNECT2D swallows the inner circle into the outer disk's interior.
    let mut points = circle(80, 2.0, [0.0, 0.0]);
    points.extend(circle(40, 1.0, [0.1, 0.0]));
    let rec = run(&points);
    assert_eq!(rec.status, Status::Polygons);
    assert_eq!(rec.loops.len(), 2);
    assert_eq!(rec.loops[1], (80..120).collect::<Vec<_>>());
    let dt = Triangulation::new(&points).unwrap();
    assert_ne!(sig_connect2d_on(&dt, true).loops.len(), 2);
}

#[test]
fn loops_and_paths_together() {
    let mut points = circle(50, 1.0, [0.0, 0.0]);
    points.extend(arc(20, 1.0, [5.0, 0.0], 0.0, 2.0));
    points.extend(arc(15, 1.0, [0.0, 5.0], 1.0, 3.0));
    let rec = run(&points);
    assert_eq!(rec.status, Status::Curves);
    assert_eq!(rec.loops, vec![(0..50).collect::<Vec<_>>()]);
    assert_eq!(rec.paths, vec![(50..70).collect::<Vec<_>>(), (70..85).collect::<Vec<_>>()]);
}

#[test]
fn a_spur_is_put_into_the_path() {
    // A sample 0.6 off a line of unit spacing hangs off the spanning tree (its nearest
    // point is 0.6 away, its other neighbours 1.17): the tree branches, and the result is
    // still one path through every point, with the spur next to its anchor.
    let mut points: Vec<Point> = (0..21).map(|i| [i as f64, 0.0]).collect();
    points.push([10.0, 0.6]);
    let rec = run(&points);
    let dt = Triangulation::new(&points).unwrap();
    let forest = minimum_spanning_forest(&dt, |_| true);
    assert!(forest.degrees(&dt).iter().any(|&d| d > 2), "the test needs a branching tree");
    assert!(rec.loops.is_empty(), "{:?}", rec.status);
    assert_eq!(rec.paths.len(), 1);
    assert_eq!(rec.paths[0].len(), points.len());
    let at = rec.paths[0].iter().position(|&v| v == 21).unwrap();
    assert!([at - 1, at + 1].iter().any(|&k| rec.paths[0][k] == 10));
}

#[test]
fn two_islands_closer_than_their_spacing_come_apart() {
    // Two circles sampled at spacing 0.157, 0.1 apart: the graph joins them, good
    // continuation splits the merged loop where it turns sharply at all four bridge ends.
    let mut points = circle(40, 1.0, [0.0, 0.0]);
    points.extend(circle(40, 1.0, [2.1, 0.0]));
    let rec = run(&points);
    assert_eq!(rec.status, Status::Polygons);
    assert_eq!(rec.loops.len(), 2, "{:?}", rec.loops);
}

/// The points and true edges of a case of `data/`, read at compile time.
fn labelled(xy: &str, gt: &str) -> (Vec<Point>, Vec<(usize, usize)>) {
    let numbers = |text: &str| -> Vec<Vec<f64>> {
        let row = |line: &str| line.split_whitespace().map(|x| x.parse().unwrap()).collect();
        text.lines().filter(|l| !l.trim().is_empty()).map(row).collect()
    };
    let points = numbers(xy).iter().map(|p| [p[0], p[1]]).collect();
    let edge = |e: &Vec<f64>| (e[0].min(e[1]) as usize, e[0].max(e[1]) as usize);
    let mut truth: Vec<_> = numbers(gt).iter().map(edge).collect();
    truth.sort_unstable();
    (points, truth)
}

/// SIG-AUTO on a labelled case, checked to leave out exactly its outliers (the points
/// on none of its true edges); the result and the true edges.
fn with_outliers_left_out(xy: &str, gt: &str) -> (Reconstruction, Vec<(usize, usize)>) {
    let (points, truth) = labelled(xy, gt);
    let rec = run(&points);
    assert_eq!(left_out(&rec), outliers(points.len(), &truth));
    (rec, truth)
}

/// The outliers of a labelled case: the points on none of its true edges.
fn outliers(n: usize, truth: &[(usize, usize)]) -> Vec<usize> {
    let on_curve: std::collections::HashSet<usize> =
        truth.iter().flat_map(|&(a, b)| [a, b]).collect();
    (0..n).filter(|i| !on_curve.contains(i)).collect()
}

/// The input indices `rec` left out.
fn left_out(rec: &Reconstruction) -> Vec<usize> {
    rec.left_out.iter().map(|l| l.index).collect()
}

fn sorted_edges(rec: &Reconstruction) -> Vec<(usize, usize)> {
    let mut found: Vec<_> = rec.edges.iter().map(|&[a, b]| (a.min(b), a.max(b))).collect();
    found.sort_unstable();
    found
}

#[test]
fn outliers_scattered_between_small_islands_are_all_left_out() {
    // Thirteen islands of 7 to 186 points and 36 outliers in the sea between them. The
    // outliers link into pieces by their own spacing: a cloud of 13 beside eight islands
    // (a twentieth of their points together, not of any one), and pieces of two beside
    // nothing but the cloud. Before, they were wired into polygons across the sea.
    let (rec, truth) = with_outliers_left_out(
        include_str!("../../../../data/outlines/gshhs_arch_dalmatia_smooth_outliers.xy"),
        include_str!("../../../../data/outlines/gshhs_arch_dalmatia_smooth_outliers.gt"),
    );
    assert_eq!(sorted_edges(&rec), truth);
    assert!(!rec.warns(), "{:?}", rec.diagnosis);
}

#[test]
fn an_outlier_hanging_off_a_second_loop_is_left_out() {
    // An elephant of two loops with 30 outliers. One outlier lies 18 spacings from the
    // small loop, and the spanning tree hangs it there, in a branch that holds the whole
    // small loop and so lies near the large one. Before branches were read again inside,
    // it stayed, was sculpted into a bridge between the loops, and a curve sample was cut.
    let (rec, truth) = with_outliers_left_out(
        include_str!("../../../../data/outlines/mp7_elephant11_uni050_outliers.xy"),
        include_str!("../../../../data/outlines/mp7_elephant11_uni050_outliers.gt"),
    );
    assert_eq!(sorted_edges(&rec), truth);
    assert_eq!(rec.status, Status::Polygons);
}

#[test]
fn outliers_that_read_as_a_loop_when_thinned_stay_outliers() {
    // A device outline with 18 outliers. Its first reading leaves them all out but cuts
    // three curve samples as detours and gets sculpting stuck, so the points are read
    // again at a coarser scale. Thinning keeps every outlier and spaces the curve like
    // them, and three outliers could then read as a small loop, which failed every
    // level: the three samples stayed cut (`coarse_reading`'s unit test
    // `small_coarse_loops_of_known_outliers_are_dropped` pins the rule itself). Since
    // the coarse reading thins along the Hilbert curve, one outlier, 2.8 spacings off the
    // curve, was wired in as a spike the sampling check let pass; the check now finds a
    // point twice as sparse as both its neighbours, reached by a turn no sampled curve
    // makes, doubling back (`doubling_back`), and the spike is cut: every outlier is out.
    // A known miss remains, shown in docs/sig-auto.md: three curve samples are cut with
    // them (the outline is still good: IoU 0.99, within a spacing of the truth).
    let xy = include_str!("../../../../data/outlines/mp7_device713_lfs030_outliers.xy");
    let gt = include_str!("../../../../data/outlines/mp7_device713_lfs030_outliers.gt");
    let (points, truth) = labelled(xy, gt);
    let rec = run(&points);
    assert_eq!(rec.loops.len(), 1);
    let (left_out, outliers) = (left_out(&rec), outliers(points.len(), &truth));
    let cut: Vec<usize> = left_out.iter().copied().filter(|i| !outliers.contains(i)).collect();
    assert!(outliers.iter().all(|i| left_out.contains(i)), "an outlier stays in");
    assert_eq!(cut, [200, 297, 1279], "the curve samples cut changed");
}

#[test]
fn outliers_strung_onto_the_end_of_a_closed_curve_are_left_out() {
    // An apple with 13 outliers. After the first two rounds, two outliers are left, and
    // the spanning tree strings them onto one end of the apple's path, so the component
    // is a chain that cannot close: it came back as an open path with a tail into the
    // apple, status `curves`, and no warning.
    let (rec, truth) = with_outliers_left_out(
        include_str!("../../../../data/real/mp7_apple11_lfs030_out07.xy"),
        include_str!("../../../../data/real/mp7_apple11_lfs030_out07.gt"),
    );
    assert_eq!(sorted_edges(&rec), truth);
    assert_eq!(rec.status, Status::Polygon);
}

/// The lines of a `cells` x `cells` grid, sampled 8 times a cell side with every
/// crossing a sample of both lines, bent into smooth curves; and its edges.
fn warped_grid(cells: usize) -> (Vec<Point>, Vec<(usize, usize)>) {
    let per_side = 8;
    let steps = cells * per_side;
    let warp = |u: f64, v: f64| [u + 0.2 * (0.9 * v).sin(), v + 0.2 * (0.8 * u).sin()];
    let mut index = std::collections::HashMap::new();
    let mut points = Vec::new();
    let mut truth = Vec::new();
    let mut at = |k: usize, line: usize, along_rows: bool| {
        let key = if along_rows { (k, line * per_side) } else { (line * per_side, k) };
        *index.entry(key).or_insert_with(|| {
            points.push(warp(key.0 as f64 / per_side as f64, key.1 as f64 / per_side as f64));
            points.len() - 1
        })
    };
    for line in 0..=cells {
        for along_rows in [true, false] {
            for k in 0..steps {
                let (a, b) = (at(k, line, along_rows), at(k + 1, line, along_rows));
                truth.push((a.min(b), a.max(b)));
            }
        }
    }
    truth.sort_unstable();
    (points, truth)
}

#[test]
fn a_grid_of_crossing_curves_is_one_network() {
    // Every point lies on curves that cross or end on one another: the branches of its
    // spanning tree are curves, not outliers, and the pair graph is the reading. (It was
    // read as polygons, stuck, with whole stretches of the lines left out as outliers,
    // over 16 rounds of outlier removal.)
    for cells in [3, 8] {
        let (points, truth) = warped_grid(cells);
        let rec = run(&points);
        assert_eq!(rec.status, Status::Network, "{cells} cells");
        assert_eq!(sorted_edges(&rec), truth);
        // A crossing inside, a T where each inner line ends on the frame.
        assert_eq!(rec.junctions().len(), (cells - 1) * (cells - 1) + 4 * (cells - 1));
        assert!(rec.diagnosis.is_empty() && !rec.warns());
    }
}

#[test]
fn a_neck_a_spacing_wide_is_not_cut() {
    // A noisy glyph (ψ) whose arm meets the stem at a neck about one spacing wide: cutting
    // across it would make two loops that each keep a corner at the cut, for a gain smaller
    // than one sampled turn. SIG-CONNECT2D reads it right, and so must SIG-AUTO.
    let (points, truth) = labelled(
        include_str!("../../../../data/curves/noisy_DejaVuSans-Oblique_U03C8_c0.xy"),
        include_str!("../../../../data/curves/noisy_DejaVuSans-Oblique_U03C8_c0.gt"),
    );
    let rec = run(&points);
    assert_eq!(rec.loops.len(), 1, "{:?}", rec.loops);
    assert_eq!(sorted_edges(&rec), truth);
}
