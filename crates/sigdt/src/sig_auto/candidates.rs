//! Candidate readings judged by one measure: SIG-AUTO's own reading, and where the sampling
//! check finds it broken or it leaves curves open, the polygons of SIG-CONNECT2D ([MOW22])
//! and CONNECT2D ([OM13]) through every point; the one with the least [`Misfit`] is kept.
//!
//! Digitised polygon vertices (GIS data) are dense on detail and sparse on straight runs:
//! they break `u < 2` of [MOW22] Theorem 1 everywhere, and SIG-AUTO's reading, built on that
//! bound, leaves such outlines open or splits them where a polygon through every point
//! reads them right.
//!
//! **The measure**, compared in order:
//! 1. *breaks*: the places where a reading breaks the sampling it assumes, as the sampling
//!    check counts them (edges passing over samples, points where it doubles back, small
//!    loops, open ends that stop beside other points, points left out beside the curves)
//!    and the points left inside where sculpting got stuck. Two findings are not counted:
//!    a loop that zigzags (digitised borders are jagged at their spacing, like noise) and
//!    ends that could meet (an open curve and a closed one with a long side read the same);
//! 2. *length*, open paths closed by their chords: of two readings through the same points
//!    that break the sampling as often, the shorter. For dense samples the shortest closed
//!    tour is the curve's polygon ([Gie99]), and a path closed by its chord pays for its gap.
//!
//! **When a polygon may replace the reading**: it has no open path, as many loops as the
//! reading at least and no more than the reading has (or one), and no vertex of an edge the
//! reading does not have is less uniform (longer over shorter edge) than `u < 2` allows, or
//! than the reading's own samples already are: sparse straight runs beside dense detail are
//! read as polygon sides only where the points show such runs elsewhere, so that the open
//! curves of evenly spaced samples stay open.
//!
//! **When the caller says the points outline areas** (`Expect::Areas`): a reading with open
//! paths is replaced by a polygon that breaks the sampling no more often, whatever its
//! length and the uniformity of its new sides, and with up to one loop per open path more
//! than the reading has; an open path that stays is reported (`open-outlines`).
//!
//! # Complexity
//! O(1) when the reading passes the check with no open path; otherwise two more readings
//! (O(n log n) each) and their checks.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
//! [OM13]: https://doi.org/10.1111/cgf.12227
//! [Gie99]: https://doi.org/10.1145/304893.304971
use crate::baselines::connect2d::connect2d_on;
use crate::delaunay::{Shape, Triangulation};
use crate::geometry::{distance, Point};
use crate::result::{FindingKind, LeftOutReason, Reconstruction, Status, Vertices};
use crate::sampling_check::LONG_EDGE_RATIO;
use crate::sig_connect2d::sig_connect2d_on;
use std::collections::HashSet;

use super::{finish, outlier_vertices, Facts, Kind};

/// How far a reading is from the sampling it assumes (module docs); less is better.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Misfit {
    /// Places where the reading breaks the sampling condition.
    pub breaks: usize,
    /// Total edge length, open paths closed by their chords.
    pub length: f64,
}

impl Misfit {
    /// The misfit of `rec`, whose sampling check has run.
    /// `at` gives the point of an input index of the result.
    pub(crate) fn of(at: impl Fn(usize) -> Point, rec: &Reconstruction) -> Misfit {
        let edge = |&[a, b]: &[usize; 2]| distance(at(a), at(b));
        let chords = rec.paths.iter().map(|p| distance(at(p[0]), at(p[p.len() - 1])));
        let length = rec.edges.iter().map(edge).sum::<f64>() + chords.sum::<f64>();
        Misfit { breaks: breaks(rec), length }
    }

    /// Fewer breaks, or as many and shorter by more than rounding.
    fn better_than(&self, other: &Misfit) -> bool {
        self.breaks < other.breaks
            || (self.breaks == other.breaks && self.length < other.length * (1.0 - 1e-9))
    }
}

/// The places where `rec` breaks the sampling condition (module docs, measure 1).
fn breaks(rec: &Reconstruction) -> usize {
    let counted =
        |kind: FindingKind| !matches!(kind, FindingKind::NoisyArea | FindingKind::EndsMeet);
    let findings: usize = rec.diagnosis.iter().filter(|f| counted(f.kind)).map(|f| f.count).sum();
    findings + rec.left_out.iter().filter(|l| l.reason == LeftOutReason::Inside).count()
}

/// `rec`, SIG-AUTO's checked reading of `dt`, or the candidate polygon with the least misfit
/// (module docs).
pub(crate) fn best_reading(facts: &Facts, rec: Reconstruction) -> Reconstruction {
    let dt = facts.dt;
    let settled = breaks(&rec) == 0 && rec.paths.is_empty();
    // Told that the points outline areas, a reading with open paths is closed if it can be.
    let closing = facts.areas && !rec.paths.is_empty();
    if settled
        || dt.shape() != Shape::Proper
        || rec.vertices != Vertices::Input
        || rec.status == Status::Network
    {
        return rec;
    }
    // A result indexes only points with a vertex (a duplicate's representative stands for
    // it), so every index it holds has one.
    let vertex_of = dt.vertex_of_inputs();
    let at = |i: usize| dt.point(vertex_of[i]);
    let mut best_misfit = Misfit::of(at, &rec);
    let own_uniformity = worst_uniformity(at, &rec.loops, &rec.paths, None);
    let own_edges: HashSet<[usize; 2]> =
        rec.edges.iter().map(|&[a, b]| [a.min(b), a.max(b)]).collect();
    // Each open path may close into an area of its own when the caller expects areas.
    let max_loops = match closing {
        true => rec.loops.len() + rec.paths.len(),
        false => rec.loops.len().max(1),
    };
    let min_loops = rec.loops.len();
    let mut best = rec;
    for candidate in polygons_through_kept(facts, &best, &vertex_of) {
        if !candidate.paths.is_empty()
            || candidate.loops.len() < min_loops
            || candidate.loops.len() > max_loops
        {
            continue;
        }
        // The gate keeps evenly sampled open curves open; areas are closed by the caller's word.
        let new_uniformity = worst_uniformity(at, &candidate.loops, &[], Some(&own_edges));
        if !closing && new_uniformity > own_uniformity.max(LONG_EDGE_RATIO) {
            continue;
        }
        let misfit = Misfit::of(at, &candidate);
        // Expecting areas, a polygon that closes the open paths wins unless it breaks the
        // sampling more often (its length no longer decides against it).
        let closes = closing && !best.paths.is_empty() && misfit.breaks <= best_misfit.breaks;
        if closes || misfit.better_than(&best_misfit) {
            (best, best_misfit) = (candidate, misfit);
        }
    }
    best
}

/// The polygons of SIG-CONNECT2D and CONNECT2D through the points that `rec` keeps (the
/// outliers it left out stay out), as checked results on `facts.dt` (`vertex_of`: its
/// vertex of each input index).
fn polygons_through_kept(
    facts: &Facts,
    rec: &Reconstruction,
    vertex_of: &[u32],
) -> Vec<Reconstruction> {
    let dt = facts.dt;
    let outliers = outlier_vertices(rec, vertex_of);
    if outliers.is_empty() {
        let on_dt = |polygon: Reconstruction| {
            let pairs = polygon.edges.iter().map(|&[i, j]| [vertex_of[i], vertex_of[j]]).collect();
            let inside = polygon.left_out.iter().map(|l| l.index).collect();
            finish(facts, pairs, inside, &[], polygon.stats, Kind::Curves)
        };
        return vec![on_dt(sig_connect2d_on(dt, true)), on_dt(connect2d_on(dt))];
    }
    let mut gone = vec![false; dt.num_vertices()];
    outliers.iter().for_each(|&v| gone[v as usize] = true);
    let kept: Vec<u32> = (0..dt.num_vertices() as u32).filter(|&v| !gone[v as usize]).collect();
    let points: Vec<Point> = kept.iter().map(|&v| dt.point(v)).collect();
    let Ok(sub) = Triangulation::new(&points) else { return Vec::new() };
    let on_dt = |polygon: Reconstruction| {
        let pairs = polygon.edges.iter().map(|&[i, j]| [kept[i], kept[j]]).collect();
        let inside = polygon.left_out.iter().map(|l| dt.input_index(kept[l.index])).collect();
        finish(facts, pairs, inside, &outliers, polygon.stats, Kind::Curves)
    };
    vec![on_dt(sig_connect2d_on(&sub, true)), on_dt(connect2d_on(&sub))]
}

/// The largest ratio of the longer to the shorter edge at a vertex of `loops` and inside
/// `paths`; with `skip`, only at vertices with an edge not in `skip` (1 without any).
fn worst_uniformity(
    at: impl Fn(usize) -> Point,
    loops: &[Vec<usize>],
    paths: &[Vec<usize>],
    skip: Option<&HashSet<[usize; 2]>>,
) -> f64 {
    let new = |a: usize, b: usize| !skip.is_some_and(|s| s.contains(&[a.min(b), a.max(b)]));
    let mut worst = 1.0f64;
    let mut visit = |a: usize, b: usize, c: usize| {
        if new(a, b) || new(b, c) {
            let (x, y) = (distance(at(a), at(b)), distance(at(b), at(c)));
            if x.min(y) > 0.0 {
                worst = worst.max(x.max(y) / x.min(y));
            }
        }
    };
    for ring in loops.iter().filter(|l| l.len() >= 3) {
        let n = ring.len();
        (0..n).for_each(|k| visit(ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]));
    }
    for path in paths {
        path.windows(3).for_each(|w| visit(w[0], w[1], w[2]));
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::super::{sig_auto_on, sig_auto_with, Steps};
    use crate::delaunay::Triangulation;
    use crate::geometry::Point;
    use crate::internals::check_reconstruction;
    use crate::result::Status;

    fn read(xy: &str) -> Vec<Point> {
        let row = |l: &str| -> Point {
            let mut x = l.split_whitespace().map(|v| v.parse::<f64>().unwrap());
            [x.next().unwrap(), x.next().unwrap()]
        };
        xy.lines().filter(|l| !l.trim().is_empty()).map(row).collect()
    }

    fn edges(gt: &str) -> Vec<[usize; 2]> {
        let row = |l: &str| -> [usize; 2] {
            let mut x = l.split_whitespace().map(|v| v.parse::<usize>().unwrap());
            [x.next().unwrap(), x.next().unwrap()]
        };
        gt.lines().filter(|l| !l.trim().is_empty()).map(row).collect()
    }

    #[test]
    fn digitised_vertices_read_open_come_back_as_their_polygon() {
        // Taiwan by its eight vertices (Natural Earth 1:110m): one side is more than twice
        // every other, so the chain does not close and the reading is an open path, with no
        // finding. The polygons through every point are shorter with the path's chord, and
        // their sides are no less uniform than the check's long-edge bound: the polygon wins.
        let points = read(include_str!("../../../../data/vertices/ne_taiwan_raw.xy"));
        let truth = edges(include_str!("../../../../data/vertices/ne_taiwan_raw.gt"));
        let dt = Triangulation::new(&points).unwrap();
        let own = sig_auto_with(&dt, &Steps { candidates: false, ..Steps::default() });
        assert_eq!((own.loops.len(), own.paths.len()), (0, 1));
        let rec = sig_auto_on(&dt);
        check_reconstruction(&points, &rec).unwrap();
        assert_eq!(rec.status, Status::Polygon);
        assert_eq!(rec.edges, truth);
    }

    #[test]
    fn told_that_the_points_outline_areas_an_open_reading_closes() {
        // Togo by its vertices (Natural Earth 1:110m): read as one open path, the polygon's
        // new side is eight times the sides beside it, so the gate keeps it open. Told that
        // the points outline an area, the polygon through them fits as well and closes it:
        // the true outline.
        use crate::{reconstruct, Expect, FindingKind, Options};
        let points = read(include_str!("../../../../data/vertices/ne_togo_raw.xy"));
        let truth = edges(include_str!("../../../../data/vertices/ne_togo_raw.gt"));
        let curves = reconstruct(&points, &Options::default()).unwrap();
        assert_eq!((curves.loops.len(), curves.paths.len()), (0, 1));
        let areas = Options { expect: Expect::Areas, ..Options::default() };
        let rec = reconstruct(&points, &areas).unwrap();
        check_reconstruction(&points, &rec).unwrap();
        assert_eq!((rec.status, &rec.edges), (Status::Polygon, &truth));
        // Georgia's vertices stay open even so: the polygons through the points it keeps
        // break the sampling where its open reading does not. The open line is then a
        // finding, `open-outlines`, at its end of smaller index, and a warning; without the
        // word, no such finding.
        let points = read(include_str!("../../../../data/vertices/ne_georgia_raw.xy"));
        let rec = reconstruct(&points, &areas).unwrap();
        assert_eq!(rec.paths.len(), 1);
        let open = rec.diagnosis.iter().find(|f| f.kind == FindingKind::OpenOutlines);
        let open = open.expect("an open outline where areas were expected is a finding");
        assert_eq!((open.count, open.at), (1, 15));
        assert_eq!(open.point, points[15]);
        assert!(rec.warns() && open.to_string().contains("densify"), "{open}");
        let quiet = reconstruct(&points, &Options::default()).unwrap();
        assert!(!quiet.diagnosis.iter().any(|f| f.kind == FindingKind::OpenOutlines));
    }

    #[test]
    fn duplicate_points_are_read_through_their_representatives() {
        // Found by the Python property test: a duplicate has no vertex of its own, and the
        // candidates looked its point up by vertex (index u32::MAX).
        for points in [
            vec![[2.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 1.0]],
            vec![[0.0, 0.0], [3.0, 0.0], [3.0, 0.1], [0.0, 0.0], [1.0, 2.0], [3.0, 0.0]],
        ] {
            let rec = sig_auto_on(&Triangulation::new(&points).unwrap());
            check_reconstruction(&points, &rec).unwrap();
        }
    }

    #[test]
    fn an_evenly_sampled_open_stroke_stays_open() {
        // A glyph's open stroke (б), evenly sampled: CONNECT2D's polygon through its points
        // is shorter than the stroke closed by its chord, but it needs sides more than
        // four times the samples beside them, where the stroke's own spacing varies by less
        // than three: the stroke stays an open path.
        let points = read(include_str!(
            "../../../../data/curves/glyphopen_DejaVuSerifCondensed-BoldItalic_U0431.xy"
        ));
        let truth = edges(include_str!(
            "../../../../data/curves/glyphopen_DejaVuSerifCondensed-BoldItalic_U0431.gt"
        ));
        let rec = sig_auto_on(&Triangulation::new(&points).unwrap());
        assert_eq!((rec.loops.len(), rec.paths.len()), (0, 1));
        assert_eq!(rec.edges, truth);
    }
}
