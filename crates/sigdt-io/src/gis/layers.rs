//! A result as GIS layers: `curves`, one feature a polygon (a loop with the loops directly
//! inside it as holes, grouped by [`Reconstruction::polygons`]) or a path (a line string),
//! each with the run's method, status, warning and diagnosis; and `left_out`, one point a
//! left-out input point with its input row (0-based, as every index sigdt writes) and the
//! reason. GeoPackage and FlatGeobuf write the same layers.

use sigdt::{Method, Point, Reconstruction};

use super::wkb::Writer;

/// One feature of the `curves` layer.
pub struct Curve {
    /// A polygon or a path.
    pub kind: CurveKind,
    /// A polygon's rings (the shell, then its holes; not closed), or a path's one line.
    pub rings: Vec<Vec<Point>>,
    /// Points on it (a polygon's rings together).
    pub vertices: usize,
    /// The bounding box `[min x, min y, max x, max y]`.
    pub bounds: [f64; 4],
}

/// What a curve is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveKind {
    /// A loop, with the loops directly inside it as holes.
    Polygon,
    /// An open path.
    Path,
}

impl CurveKind {
    /// The `kind` attribute.
    pub fn name(self) -> &'static str {
        match self {
            CurveKind::Polygon => "polygon",
            CurveKind::Path => "path",
        }
    }
}

impl Curve {
    /// The geometry as well-known binary, after `prefix` (GeoPackage's header).
    pub fn wkb(&self, prefix: Vec<u8>) -> Vec<u8> {
        let mut w = Writer(prefix);
        match self.kind {
            CurveKind::Polygon => w.polygon(&self.rings),
            CurveKind::Path => w.line_string(&self.rings[0]),
        }
        w.0
    }
}

/// What every curve says about the run.
pub struct Run {
    /// The method's name.
    pub method: String,
    /// The result's status.
    pub status: &'static str,
    /// Whether the result warns (it may not be the points' curves).
    pub warning: bool,
    /// The sampling check's findings, `; `-separated; empty when there are none.
    pub diagnosis: String,
}

/// One feature of the `left_out` layer.
pub struct LeftOut {
    /// The point, as given.
    pub point: Point,
    /// The input index.
    pub row: usize,
    /// Why it was left out (`outlier`, `inside`).
    pub reason: &'static str,
}

/// The layers of `rec`, computed by `method` from the input `points`.
pub struct Layers {
    /// What every curve says about the run.
    pub run: Run,
    /// The `curves` layer.
    pub curves: Vec<Curve>,
    /// The `left_out` layer.
    pub left_out: Vec<LeftOut>,
}

impl Layers {
    /// The layers of `rec`, computed by `method` from the input `points`.
    pub fn new(method: Method, points: &[Point], rec: &Reconstruction) -> Layers {
        let vertices = rec.vertex_positions(points);
        let ring = |l: &Vec<usize>| l.iter().map(|&i| vertices[i]).collect::<Vec<Point>>();
        let mut curves = Vec::new();
        for polygon in rec.polygons(vertices) {
            let rings: Vec<Vec<Point>> = std::iter::once(polygon.shell)
                .chain(polygon.holes.iter().copied())
                .map(|k| ring(&rec.loops[k]))
                .collect();
            curves.push(Curve::new(CurveKind::Polygon, rings));
        }
        for path in &rec.paths {
            curves.push(Curve::new(CurveKind::Path, vec![ring(path)]));
        }
        let findings: Vec<String> = rec.diagnosis.iter().map(ToString::to_string).collect();
        let run = Run {
            method: method.to_string(),
            status: rec.status.name(),
            warning: rec.warns(),
            diagnosis: findings.join("; "),
        };
        let left_out = rec
            .left_out
            .iter()
            .map(|l| LeftOut { point: points[l.index], row: l.index, reason: l.reason.name() })
            .collect();
        Layers { run, curves, left_out }
    }
}

impl Curve {
    fn new(kind: CurveKind, rings: Vec<Vec<Point>>) -> Curve {
        let vertices = rings.iter().map(Vec::len).sum();
        let bounds = bounds(&rings[0]);
        Curve { kind, rings, vertices, bounds }
    }
}

/// The bounding box of `points` (not empty).
fn bounds(points: &[Point]) -> [f64; 4] {
    points
        .iter()
        .fold([f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY], |b, p| {
            [b[0].min(p[0]), b[1].min(p[1]), b[2].max(p[0]), b[3].max(p[1])]
        })
}
