//! Tests of the sampling check.
use super::finding::{Significant, Spacings};
use super::*;
use crate::geometry::Point;
use crate::result::Reconstruction;
use std::f64::consts::TAU;

fn circle(n: usize) -> Vec<Point> {
    (0..n).map(|i| TAU * i as f64 / n as f64).map(|a| [a.cos(), a.sin()]).collect()
}

/// The findings of the loops `loops` (input indices) on `points`.
fn findings(points: &[Point], loops: Vec<Vec<usize>>) -> Vec<Finding> {
    let dt = Triangulation::new(points).unwrap();
    diagnose(&dt, &Reconstruction { loops, ..Reconstruction::default() })
}

fn kinds(found: &[Finding]) -> Vec<FindingKind> {
    found.iter().map(|f| f.kind).collect()
}

#[test]
fn a_sampled_circle_has_no_findings() {
    let points = circle(60);
    assert!(findings(&points, vec![(0..60).collect()]).is_empty());
    let rec = crate::reconstruct(&points, &crate::Options::default()).unwrap();
    assert!(rec.diagnosis.is_empty() && !rec.warns());
}

#[test]
fn dense_corners_and_long_sides_are_a_sampled_curve() {
    // A square whose sides have only their end samples and samples close to the
    // corners: every side is many times the spacing at its ends (u far above 2), but
    // its diametral disk is empty.
    let mut points = Vec::new();
    for [x, y, dx, dy] in [
        [0.0, 0.0, 1.0, 0.0],
        [10.0, 0.0, 0.0, 1.0],
        [10.0, 10.0, -1.0, 0.0],
        [0.0, 10.0, 0.0, -1.0],
    ] {
        points.push([x, y]);
        points.push([x + 0.3 * dx, y + 0.3 * dy]);
    }
    // Corner, then the sample beside it, then the long side to the next corner's
    // neighbour... read in order around the square.
    let order = vec![0, 1, 7, 6, 5, 4, 3, 2];
    let order: Vec<usize> = order.into_iter().rev().collect();
    let found = findings(&points, vec![order]);
    assert!(found.iter().all(|f| f.kind != FindingKind::PassesOverSamples), "{found:?}");
}

#[test]
fn outliers_on_the_curve_are_found_and_outliers_off_it_are_not() {
    // A 60-gon read without sample 7 (its neighbours joined), and a point 3 off the
    // circle: both left out as outliers. Sample 7 lies 0.005 from the chord 6-8, a
    // sixtieth of its spacing 0.105; the far point is 2 from every edge.
    use crate::result::{LeftOut, LeftOutReason};
    let mut points = circle(60);
    points.push([3.0, 0.0]);
    let order: Vec<usize> = (0..60).filter(|&i| i != 7).collect();
    let dt = Triangulation::new(&points).unwrap();
    let outlier = |index| LeftOut { index, reason: LeftOutReason::Outlier };
    let rec = |left_out| Reconstruction {
        loops: vec![order.clone()],
        left_out,
        ..Reconstruction::default()
    };
    let found = diagnose(&dt, &rec(vec![outlier(7), outlier(60)]));
    let on_curve: Vec<&Finding> =
        found.iter().filter(|f| f.kind == FindingKind::OutliersOnCurve).collect();
    assert_eq!(on_curve.len(), 1, "{found:?}");
    assert_eq!((on_curve[0].count, on_curve[0].at), (1, 7));
    assert!(on_curve[0].worst < 0.1, "{found:?}");
    assert!(on_curve[0].to_string().contains("1 point(s) left out as outliers lie on or near"));
    let found = diagnose(&dt, &rec(vec![outlier(60)]));
    assert!(found.iter().all(|f| f.kind != FindingKind::OutliersOnCurve), "{found:?}");
}

#[test]
fn outliers_beside_a_long_edge_of_the_reading_are_on_the_curve() {
    // A 60-gon read without samples 7 and 8 (edge 6–9, three spacings), both moved out
    // by 0.6 spacings: 0.75 of their spacing from the edge, but 0.39 of vertex 6's
    // longer edge from it, nearer than any sample can be under u < 2.
    use crate::result::{LeftOut, LeftOutReason};
    let mut points = circle(60);
    for i in [7, 8] {
        points[i] = points[i].map(|c| c * (1.0 + 0.6 * TAU / 60.0));
    }
    let order: Vec<usize> = (0..60).filter(|&i| i != 7 && i != 8).collect();
    let dt = Triangulation::new(&points).unwrap();
    let left_out = [7, 8].map(|index| LeftOut { index, reason: LeftOutReason::Outlier }).to_vec();
    let rec = Reconstruction { loops: vec![order], left_out, ..Reconstruction::default() };
    let found = diagnose(&dt, &rec);
    let on_curve: Vec<&Finding> =
        found.iter().filter(|f| f.kind == FindingKind::OutliersOnCurve).collect();
    assert_eq!(on_curve.len(), 1, "{found:?}");
    assert_eq!(on_curve[0].count, 2, "{found:?}");
    assert!(on_curve[0].worst > 0.3 && on_curve[0].worst < 0.5, "{found:?}");
}

#[test]
fn an_outlier_within_an_edge_length_of_its_edge_is_near_the_curve() {
    // A 60-gon and a point 0.7 spacings outside the middle of its edge 7–8: 0.81 of its
    // own spacing from the edge and 0.86 edges from the vertices, so neither half-spacing
    // bound holds, but it is nearer to the edge than the edge is long, where the outlier
    // rule would have kept it.
    use crate::result::{LeftOut, LeftOutReason};
    let mut points = circle(60);
    let (a, b) = (points[7], points[8]);
    let spacing = distance(a, b);
    let middle = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
    let out = 1.0 + 0.7 * spacing / distance(middle, [0.0, 0.0]);
    points.push(middle.map(|c| c * out));
    let dt = Triangulation::new(&points).unwrap();
    let left_out = vec![LeftOut { index: 60, reason: LeftOutReason::Outlier }];
    let rec =
        Reconstruction { loops: vec![(0..60).collect()], left_out, ..Reconstruction::default() };
    let found = diagnose(&dt, &rec);
    let on_curve: Vec<&Finding> =
        found.iter().filter(|f| f.kind == FindingKind::OutliersOnCurve).collect();
    assert_eq!(on_curve.len(), 1, "{found:?}");
    assert!(on_curve[0].worst > 0.5 && on_curve[0].worst < 1.0, "{found:?}");
}

#[test]
fn a_chord_across_the_curve_passes_over_samples() {
    // 40 samples of a circle read without the 11 samples between 0 and 12: the chord
    // 0–12 passes 2.5 spacings deep over them (half-chord 0.81, sagitta 0.41, spacing
    // 0.157 of the radius).
    let points = circle(40);
    let order: Vec<usize> = (12..40).chain([0]).collect();
    let found = findings(&points, vec![order]);
    assert_eq!(kinds(&found), vec![FindingKind::PassesOverSamples], "{found:?}");
    assert_eq!(found[0].count, 1);
    assert!(found[0].worst >= DEPTH_RATIO && found[0].worst < 3.0, "{found:?}");
    assert!([0, 12].contains(&found[0].at));
    // Four skipped samples reach 1.76 spacings deep: not a corner's neighbour, so more
    // than the one spacing allowed for noise.
    let order: Vec<usize> = (5..40).chain([0]).collect();
    let found = findings(&points, vec![order]);
    assert_eq!(kinds(&found), vec![FindingKind::PassesOverSamples], "{found:?}");
    assert!(found[0].worst > STRAY_DEPTH_RATIO && found[0].worst < DEPTH_RATIO, "{found:?}");
    // One skipped sample lies 0.92 spacings deep: within what noise explains.
    let order: Vec<usize> = (2..40).chain([0]).collect();
    assert!(findings(&points, vec![order]).is_empty());
}

#[test]
fn an_outlier_wired_into_the_curve_doubles_back() {
    let mut points = circle(60);
    points.push([3.0, 0.05]);
    let mut order: Vec<usize> = (0..60).collect();
    order.insert(1, 60);
    let found = findings(&points, vec![order]);
    assert!(kinds(&found).contains(&FindingKind::DoublesBack), "{found:?}");
    let back = found.iter().find(|f| f.kind == FindingKind::DoublesBack).unwrap();
    assert_eq!((back.count, back.at), (1, 60));
    assert!(back.worst > 150.0);
}

#[test]
fn an_outlier_wired_in_two_and_a_half_spacings_off_doubles_back() {
    // Its edges are 2.5 spacings long, under twice the bound, but the point is 2.5 times
    // as sparse as both its neighbours, and the reading turns 90° at them to reach it.
    let mut points = circle(60);
    let half = TAU / 120.0;
    points.push([1.26 * half.cos(), 1.26 * half.sin()]);
    let mut order: Vec<usize> = (0..60).collect();
    order.insert(1, 60);
    let found = findings(&points, vec![order]);
    let back = found.iter().find(|f| f.kind == FindingKind::DoublesBack);
    assert_eq!(back.map(|f| (f.count, f.at)), Some((1, 60)), "{found:?}");
}

#[test]
fn a_sparse_sharp_tip_between_straight_sides_does_not_double_back() {
    // A triangle with a 20° tip three times as sparse as its sides: the reading turns
    // 160° there, between edges of three spacings, but runs on straight at both
    // neighbours: a corner of the curve.
    let side = |angle: f64| -> Vec<Point> {
        (0..28).map(|k| 0.3 + 0.1 * k as f64).map(|t| [t * angle.cos(), t * angle.sin()]).collect()
    };
    let (upper, lower) = (side(10f64.to_radians()), side(-10f64.to_radians()));
    let (top, bottom) = (upper[27], lower[27]);
    let base: Vec<Point> = (1..10)
        .map(|k| k as f64 / 10.0)
        .map(|t| [top[0], top[1] + t * (bottom[1] - top[1])])
        .collect();
    let mut points = vec![[0.0, 0.0]];
    points.extend(&upper);
    points.extend(&base);
    points.extend(lower.iter().rev());
    let found = findings(&points, vec![(0..points.len()).collect()]);
    assert!(!kinds(&found).contains(&FindingKind::DoublesBack), "{found:?}");
}

/// `n` points on a small circle far from a circle of 40, read as the two loops.
fn knot_beside_a_circle(n: usize) -> Vec<Finding> {
    let mut points = circle(40);
    points.extend(circle(n).iter().map(|p| [5.0 + 0.1 * p[0], 0.1 * p[1]]));
    findings(&points, vec![(0..40).collect(), (40..40 + n).collect()])
}

#[test]
fn loops_of_fewer_than_seven_points_beside_a_curve_are_small() {
    for n in [3, 4, 6] {
        let found = knot_beside_a_circle(n);
        assert_eq!(kinds(&found), vec![FindingKind::SmallLoops], "{n} points");
        assert_eq!((found[0].worst, found[0].at), (n as f64, 40));
        // Alone, they are what was given.
        assert!(findings(&circle(n), vec![(0..n).collect()]).is_empty(), "{n} alone");
    }
    assert!(knot_beside_a_circle(7).is_empty());
}

#[test]
fn an_open_end_next_to_other_points() {
    // 40 samples of a circle read as one path that stops at sample 30, while 31 to 39
    // are read as their own loop beside it: sample 30's nearest point is 31, at one
    // spacing; its last edge is one spacing too, so that end is fine. Read as a path
    // with its last edge across to 35 instead, the end 35... keeps 34 and 36 at one
    // spacing against a last edge of five: an open end next to other points.
    let points = circle(40);
    let path: Vec<usize> = (0..=30).chain([35]).collect();
    let found = {
        let dt = Triangulation::new(&points).unwrap();
        let rec = Reconstruction { paths: vec![path], ..Reconstruction::default() };
        diagnose(&dt, &rec)
    };
    let end = found.iter().find(|f| f.kind == FindingKind::OpenEnds).expect("open end");
    assert_eq!((end.count, end.at), (1, 35));
    assert!(end.worst > 4.0 && end.worst < 5.0, "{end:?}");
}

#[test]
fn the_message_says_where_how_much_and_what_to_do() {
    // Point 40 of the knot is 5 + 0.1 · (cos 0, sin 0) = (5.1, 0): its coordinates, as
    // given, are in the finding and the message.
    let found = knot_beside_a_circle(5);
    assert_eq!((found[0].at, found[0].point), (40, [5.1, 0.0]));
    let text = found[0].to_string();
    assert!(text.contains("fewer than 7 points") && text.contains("near (5.1, 0)"), "{text}");
    assert!(text.contains("densify the source lines there"), "{text}");
}

#[test]
fn numbers_in_messages_stay_readable() {
    let shown = |x: f64| Significant(x).to_string();
    assert_eq!(shown(136.125_41), "136.125");
    assert_eq!(shown(-17.464_318), "-17.4643");
    assert_eq!(shown(523_456.789), "523457");
    assert_eq!(shown(0.000_123_456_7), "0.000123457");
    assert_eq!(shown(2.5e-7), "2.50000e-7");
    assert_eq!(shown(0.0), "0");
    assert_eq!(Spacings(1.5e15).to_string(), "more than 1000");
    assert_eq!(Spacings(10.71).to_string(), "10.7");
}
