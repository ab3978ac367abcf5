//! Seeded random non-manifold drawings: closed blobs and open strokes that cross, end on one
//! another or meet at a common end, the generator of the `non-manifold` labelled category
//! (`data/non-manifold`, \[MOW22\] Fig. 19), sampled by
//! [`sample_with_junctions`](super::sample_with_junctions).
//!
//! Blobs are closed C1 Catmull–Rom curves through 5 to 7 nodes at jittered angles and radii;
//! strokes are single cubics with their inner controls pushed sideways (a bend). A T-junction
//! is built by starting a stroke at a point evaluated on its host curve, so it lies on the
//! host up to rounding; crossings happen where the geometry puts them.
//!
//! # Complexity
//! O(1) per drawing (a handful of segments).
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
use std::f64::consts::{PI, TAU};
use std::fmt::Write as _;

use sigdt::samplers::Rng;
use sigdt::Point;

use super::BezierPath;

/// The kinds of junction a drawing shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DrawingKind {
    /// A blob with a chord ending on it at both ends: two T-junctions.
    Theta,
    /// Two strokes crossing: one X-junction.
    Cross,
    /// A blob pierced by a stroke that sticks out on both sides: two X-junctions.
    Pierced,
    /// A stroke with two strokes ending on it, one on each side: two T-junctions.
    Tee,
    /// Three or four strokes from one common end: a Y- or X-shaped vertex of degree 3 or 4.
    Star,
    /// Two overlapping blobs: two X-junctions.
    Overlap,
    /// Two roughly parallel strokes crossed by two others, like `#`: four X-junctions.
    Hash,
}

impl DrawingKind {
    /// Every kind, in a fixed order.
    pub const ALL: [DrawingKind; 7] = [
        DrawingKind::Theta,
        DrawingKind::Cross,
        DrawingKind::Pierced,
        DrawingKind::Tee,
        DrawingKind::Star,
        DrawingKind::Overlap,
        DrawingKind::Hash,
    ];

    /// The kind's name, as used in case names.
    pub fn name(self) -> &'static str {
        match self {
            DrawingKind::Theta => "theta",
            DrawingKind::Cross => "cross",
            DrawingKind::Pierced => "pierced",
            DrawingKind::Tee => "tee",
            DrawingKind::Star => "star",
            DrawingKind::Overlap => "overlap",
            DrawingKind::Hash => "hash",
        }
    }
}

/// A random drawing of `kind`, fixed by `seed`, in about the box [-1, 1]².
pub fn random_drawing(kind: DrawingKind, seed: u64) -> Vec<BezierPath> {
    let mut rng = Rng::new(seed);
    let rng = &mut rng;
    let turn = rng.uniform() * TAU;
    match kind {
        DrawingKind::Theta => {
            let blob = blob(rng, [0.0, 0.0], 1.0);
            let m = blob.segments.len() as f64;
            let ua = rng.uniform() * m;
            let ub = ua + m * (0.4 + 0.2 * rng.uniform());
            let chord = stroke(rng, blob.point(ua), blob.point(ub), 0.15);
            vec![blob, chord]
        }
        DrawingKind::Cross => {
            let a = across(rng, turn, 1.0, 0.2);
            let second = turn + PI * (0.3 + 0.4 * rng.uniform());
            let b = across(rng, second, 1.0, 0.2);
            vec![a, b]
        }
        DrawingKind::Pierced => {
            let blob = blob(rng, [0.0, 0.0], 0.75);
            let through = across(rng, turn, 1.2, 0.1);
            vec![blob, through]
        }
        DrawingKind::Tee => {
            let base = across(rng, turn, 1.0, 0.15);
            let mut paths = vec![base];
            for (side, u) in
                [(1.0, 0.3 + 0.15 * rng.uniform()), (-1.0, 0.55 + 0.15 * rng.uniform())]
            {
                let start = paths[0].point(u);
                let d = paths[0].derivative(u);
                let len = d[0].hypot(d[1]).max(f64::MIN_POSITIVE);
                let normal = [-d[1] / len * side, d[0] / len * side];
                let reach = 0.6 + 0.4 * rng.uniform();
                let lean = 0.4 * (rng.uniform() - 0.5);
                let end = [
                    start[0] + reach * (normal[0] + lean * d[0] / len),
                    start[1] + reach * (normal[1] + lean * d[1] / len),
                ];
                paths.push(stroke(rng, start, end, 0.15));
            }
            paths
        }
        DrawingKind::Star => {
            let arms = 3 + rng.below(2);
            let centre = [0.2 * (rng.uniform() - 0.5), 0.2 * (rng.uniform() - 0.5)];
            (0..arms)
                .map(|k| {
                    let angle = turn + TAU * (k as f64 + 0.3 * (rng.uniform() - 0.5)) / arms as f64;
                    let reach = 0.7 + 0.3 * rng.uniform();
                    let end = [centre[0] + reach * angle.cos(), centre[1] + reach * angle.sin()];
                    stroke(rng, centre, end, 0.15)
                })
                .collect()
        }
        DrawingKind::Overlap => {
            let offset = 0.3 + 0.15 * rng.uniform();
            let (dx, dy) = (offset * turn.cos(), offset * turn.sin());
            vec![blob(rng, [-dx, -dy], 0.7), blob(rng, [dx, dy], 0.7)]
        }
        DrawingKind::Hash => {
            let mut paths = Vec::new();
            for direction in [turn, turn + PI * (0.35 + 0.3 * rng.uniform())] {
                let gap = 0.35 + 0.2 * rng.uniform();
                for shift in [-gap, gap] {
                    let mut line = across(rng, direction, 1.0, 0.1);
                    let (sx, sy) = (-shift * direction.sin(), shift * direction.cos());
                    for segment in &mut line.segments {
                        for p in segment.iter_mut() {
                            *p = [p[0] + sx, p[1] + sy];
                        }
                    }
                    paths.push(line);
                }
            }
            paths
        }
    }
}

/// `paths` as an SVG document, one `<path>` each, coordinates written so they read back
/// exactly; `comment` goes into an XML comment.
pub fn to_svg(paths: &[BezierPath], comment: &str) -> String {
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let comment = comment.replace("--", "- -");
    let _ = writeln!(out, "<!-- {comment} -->");
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-1.6 -1.6 3.2 3.2\">\n";
    for path in paths {
        let Some(first) = path.segments.first() else { continue };
        let mut d = format!("M {:?},{:?}", first[0][0], first[0][1]);
        for [_, c1, c2, end] in &path.segments {
            let _ = write!(
                d,
                " C {:?},{:?} {:?},{:?} {:?},{:?}",
                c1[0], c1[1], c2[0], c2[1], end[0], end[1]
            );
        }
        if path.closed {
            d += " Z";
        }
        let _ =
            writeln!(out, "  <path style=\"fill:none;stroke:#000;stroke-width:0.01\" d=\"{d}\"/>");
    }
    out + "</svg>\n"
}

/// A closed Catmull–Rom blob around `centre` of about `radius`.
fn blob(rng: &mut Rng, centre: Point, radius: f64) -> BezierPath {
    let n = 5 + rng.below(3);
    let start = rng.uniform() * TAU;
    let nodes: Vec<Point> = (0..n)
        .map(|k| {
            let angle = start + TAU * (k as f64 + 0.35 * (rng.uniform() - 0.5)) / n as f64;
            let r = radius * (0.75 + 0.5 * rng.uniform());
            [centre[0] + r * angle.cos(), centre[1] + r * angle.sin()]
        })
        .collect();
    let tangent = |k: usize| {
        let (prev, next) = (nodes[(k + n - 1) % n], nodes[(k + 1) % n]);
        [(next[0] - prev[0]) / 6.0, (next[1] - prev[1]) / 6.0]
    };
    let segments = (0..n)
        .map(|k| {
            let (p, q) = (nodes[k], nodes[(k + 1) % n]);
            let (tp, tq) = (tangent(k), tangent((k + 1) % n));
            [p, [p[0] + tp[0], p[1] + tp[1]], [q[0] - tq[0], q[1] - tq[1]], q]
        })
        .collect();
    BezierPath { segments, closed: true }
}

/// An open cubic from `a` to `b`, its inner controls pushed sideways by up to `bend` × its
/// length.
fn stroke(rng: &mut Rng, a: Point, b: Point, bend: f64) -> BezierPath {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let mut control = |t: f64| {
        let push = bend * (2.0 * rng.uniform() - 1.0);
        [a[0] + t * dx - push * dy, a[1] + t * dy + push * dx]
    };
    let (c1, c2) = (control(1.0 / 3.0), control(2.0 / 3.0));
    BezierPath { segments: vec![[a, c1, c2, b]], closed: false }
}

/// A stroke through about the origin in direction `angle`, `reach` long on each side.
fn across(rng: &mut Rng, angle: f64, reach: f64, bend: f64) -> BezierPath {
    let (c, s) = (angle.cos(), angle.sin());
    let r1 = reach * (0.85 + 0.3 * rng.uniform());
    let r2 = reach * (0.85 + 0.3 * rng.uniform());
    stroke(rng, [-r1 * c, -r1 * s], [r2 * c, r2 * s], bend)
}
