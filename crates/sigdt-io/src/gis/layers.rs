//! Results as GIS layers, one geometry type each (as GIS tools and Shapefiles want them)
//! and one feature per group of points (the whole input is one group without `--by`):
//!
//! - `areas` (MultiPolygon): the group's loops, grouped into polygons with holes;
//! - `paths` (MultiLineString): its open paths neither of whose ends is a junction;
//! - `networks` (MultiLineString): its paths with an end at a junction;
//! - `left_out` (Point): one feature per input point the method left out, with its input
//!   `row` (0-based, as every index sigdt writes) and the `reason`.
//!
//! Every feature of the first three carries the run's `method`, `status`, `warning`,
//! `diagnosis` and `vertices` (the result's points in that geometry, before any cut), after
//! the group's attributes (`left_out` carries them too). A group with nothing in a layer has
//! no feature there, but a group with no curve at all has an `areas` feature with an empty
//! geometry: its status (`too-few-points`) and the status's message as its diagnosis, or,
//! when its reconstruction failed, status `error` and the message. Longitude and latitude
//! are cut at the antimeridian ([`outlines`](super::outlines)). GeoPackage and FlatGeobuf
//! write the same layers.

use sigdt::{Method, Point, Reconstruction};

use super::outlines::outlines;
pub use crate::attributes::{Column, ColumnType, Value};

/// The layers written, in the order they are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layer {
    /// Polygons with holes.
    Areas,
    /// Open paths not ending at a junction.
    Paths,
    /// Paths with an end at a junction.
    Networks,
    /// The points left out.
    LeftOut,
}

impl Layer {
    /// Every layer, in the order they are written.
    pub const ALL: [Layer; 4] = [Layer::Areas, Layer::Paths, Layer::Networks, Layer::LeftOut];

    /// The layer's (table's) name.
    pub fn name(self) -> &'static str {
        match self {
            Layer::Areas => "areas",
            Layer::Paths => "paths",
            Layer::Networks => "networks",
            Layer::LeftOut => "left_out",
        }
    }

    /// Its geometry type, as GeoPackage names it.
    pub fn geometry_type(self) -> &'static str {
        match self {
            Layer::Areas => "MULTIPOLYGON",
            Layer::Paths | Layer::Networks => "MULTILINESTRING",
            Layer::LeftOut => "POINT",
        }
    }
}

/// The names of sigdt's own columns in every layer (with the GeoPackage's `fid` and `geom`):
/// a group attribute of one of these names is written as `input_NAME`.
pub const OWN_COLUMNS: [&str; 9] =
    ["fid", "geom", "method", "status", "warning", "diagnosis", "vertices", "row", "reason"];

/// What every feature of a group says about its run.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// The method's name.
    pub method: String,
    /// The result's status, or `error` when the reconstruction failed.
    pub status: &'static str,
    /// Whether the result warns (it may not be the points' curves), or it failed.
    pub warning: bool,
    /// The sampling check's findings, `; `-separated (empty when there are none), or the
    /// error.
    pub diagnosis: String,
}

/// A group: its attributes (one per column of [`Layers::columns`]) and its run.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// Its attributes.
    pub values: Vec<Value>,
    /// Its run.
    pub run: Run,
}

/// A feature of `areas`: a group's polygons, each a shell and its holes (not closed; shells
/// counter-clockwise, holes clockwise); empty for a group that failed.
#[derive(Debug, Clone, PartialEq)]
pub struct Areas {
    /// The group (an index into [`Layers::groups`]).
    pub group: usize,
    /// The polygons.
    pub polygons: Vec<Vec<Vec<Point>>>,
    /// The result's points on them.
    pub vertices: usize,
}

/// A feature of `paths` or `networks`: a group's lines.
#[derive(Debug, Clone, PartialEq)]
pub struct Lines {
    /// The group (an index into [`Layers::groups`]).
    pub group: usize,
    /// The lines.
    pub lines: Vec<Vec<Point>>,
    /// The result's points on them.
    pub vertices: usize,
}

/// A feature of `left_out`.
#[derive(Debug, Clone, PartialEq)]
pub struct LeftOut {
    /// The group (an index into [`Layers::groups`]).
    pub group: usize,
    /// The point, as given.
    pub point: Point,
    /// Its input row (0-based).
    pub row: usize,
    /// Why it was left out (`outlier`, `inside`).
    pub reason: &'static str,
}

/// The four layers of one or more groups' results.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Layers {
    /// The group attributes' columns, named so as not to clash with [`OWN_COLUMNS`] or one
    /// another.
    pub columns: Vec<Column>,
    /// The groups, in the order added.
    pub groups: Vec<Group>,
    /// The `areas` layer.
    pub areas: Vec<Areas>,
    /// The `paths` layer.
    pub paths: Vec<Lines>,
    /// The `networks` layer.
    pub networks: Vec<Lines>,
    /// The `left_out` layer.
    pub left_out: Vec<LeftOut>,
}

impl Layers {
    /// The layers of the one result `rec`, computed by `method` from `points` (`lon_lat`
    /// when they are longitude and latitude: cut at the antimeridian).
    pub fn new(method: Method, points: &[Point], rec: &Reconstruction, lon_lat: bool) -> Layers {
        let mut layers = Layers::default();
        layers.add(Vec::new(), method, points, rec, lon_lat, None);
        layers
    }

    /// Empty layers whose groups have attributes in `columns`; a name that clashes with
    /// [`OWN_COLUMNS`] or an earlier column (case aside, as SQLite compares them) gets
    /// `input_` in front until it does not.
    pub fn with_columns(columns: Vec<Column>) -> Layers {
        let mut taken: Vec<String> = OWN_COLUMNS.iter().map(|c| c.to_string()).collect();
        let columns = columns
            .into_iter()
            .map(|mut column| {
                while taken.iter().any(|t| t.eq_ignore_ascii_case(&column.name)) {
                    column.name = format!("input_{}", column.name);
                }
                taken.push(column.name.clone());
                column
            })
            .collect();
        Layers { columns, ..Layers::default() }
    }

    /// Adds the group of attributes `values` whose result `rec` was computed by `method` from
    /// `points` (`lon_lat`: longitude and latitude, cut at the antimeridian), which are the
    /// input rows `rows` (`None`: rows 0, 1, ...). A result without curves gets an `areas`
    /// feature without geometry, its status's message as the diagnosis.
    pub fn add(
        &mut self,
        values: Vec<Value>,
        method: Method,
        points: &[Point],
        rec: &Reconstruction,
        lon_lat: bool,
        rows: Option<&[usize]>,
    ) {
        debug_assert_eq!(values.len(), self.columns.len());
        let group = self.groups.len();
        let outlines = outlines(points, rec, lon_lat);
        let nothing = outlines.polygons.is_empty() && outlines.lines.is_empty();
        let mut findings: Vec<String> = rec.diagnosis.iter().map(ToString::to_string).collect();
        if nothing && findings.is_empty() {
            findings.push(rec.status.to_string());
        }
        let run = Run {
            method: method.to_string(),
            status: rec.status.name(),
            warning: rec.warns(),
            diagnosis: findings.join("; "),
        };
        self.groups.push(Group { values, run });
        // A group without a curve is still seen, as an `areas` feature without geometry.
        if !outlines.polygons.is_empty() || nothing {
            let vertices = outlines.loop_vertices;
            self.areas.push(Areas { group, polygons: outlines.polygons, vertices });
        }
        for (at_junction, layer) in [(false, &mut self.paths), (true, &mut self.networks)] {
            let lines = outlines.lines.iter().filter(|l| l.at_junction == at_junction);
            let vertices = lines.clone().map(|l| l.vertices).sum();
            let lines: Vec<Vec<Point>> = lines.flat_map(|l| l.pieces.iter().cloned()).collect();
            if !lines.is_empty() {
                layer.push(Lines { group, lines, vertices });
            }
        }
        self.left_out.extend(rec.left_out.iter().map(|l| LeftOut {
            group,
            point: points[l.index],
            row: rows.map_or(l.index, |rows| rows[l.index]),
            reason: l.reason.name(),
        }));
    }

    /// Adds the group of attributes `values` whose reconstruction by `method` failed with
    /// `error`: an `areas` feature without geometry, status `error`.
    pub fn add_failed(&mut self, values: Vec<Value>, method: Method, error: String) {
        debug_assert_eq!(values.len(), self.columns.len());
        let group = self.groups.len();
        let run =
            Run { method: method.to_string(), status: "error", warning: true, diagnosis: error };
        self.groups.push(Group { values, run });
        self.areas.push(Areas { group, polygons: Vec::new(), vertices: 0 });
    }

    /// The number of features of `layer`.
    pub fn len(&self, layer: Layer) -> usize {
        match layer {
            Layer::Areas => self.areas.len(),
            Layer::Paths => self.paths.len(),
            Layer::Networks => self.networks.len(),
            Layer::LeftOut => self.left_out.len(),
        }
    }

    /// Whether every layer is empty.
    pub fn is_empty(&self) -> bool {
        Layer::ALL.iter().all(|&layer| self.len(layer) == 0)
    }

    /// The bounding box `[min x, min y, max x, max y]` of `layer`'s geometries; `None` when
    /// it has none.
    pub fn bounds(&self, layer: Layer) -> Option<[f64; 4]> {
        let points: Box<dyn Iterator<Item = &Point>> = match layer {
            Layer::Areas => {
                Box::new(self.areas.iter().flat_map(|a| a.polygons.iter().flatten().flatten()))
            }
            Layer::Paths => Box::new(self.paths.iter().flat_map(|l| l.lines.iter().flatten())),
            Layer::Networks => {
                Box::new(self.networks.iter().flat_map(|l| l.lines.iter().flatten()))
            }
            Layer::LeftOut => Box::new(self.left_out.iter().map(|l| &l.point)),
        };
        points.fold(None, |b: Option<[f64; 4]>, p| {
            let [x, y] = *p;
            Some(b.map_or([x, y, x, y], |b| [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)]))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sigdt::{LeftOutReason, Status};

    #[test]
    fn each_layer_gets_one_feature_per_group_of_its_own_kind() {
        // A square (a loop), a T (three paths at a junction), a lone segment and an outlier.
        let points = [
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [5.0, 0.0],
            [6.0, 0.0],
            [7.0, 0.0],
            [6.0, 1.0],
            [9.0, 9.0],
            [9.0, 10.0],
            [50.0, 50.0],
        ];
        let rec = Reconstruction {
            edges: vec![[0, 1], [0, 3], [1, 2], [2, 3], [4, 5], [5, 6], [5, 7], [8, 9]],
            loops: vec![vec![0, 1, 2, 3]],
            paths: vec![vec![4, 5], vec![5, 6], vec![5, 7], vec![8, 9]],
            left_out: vec![sigdt::LeftOut { index: 10, reason: LeftOutReason::Outlier }],
            status: Status::Network,
            ..Reconstruction::default()
        };
        let mut layers =
            Layers::with_columns(vec![Column { name: "Status".into(), kind: ColumnType::Text }]);
        let rows: Vec<usize> = (100..111).collect();
        let island = vec![Value::Text("a".into())];
        layers.add(island, Method::SigAuto, &points, &rec, false, Some(&rows));
        layers.add_failed(vec![Value::Null], Method::SigAuto, "too few points".into());
        assert_eq!(layers.columns[0].name, "input_Status", "sigdt's own names come first");
        assert_eq!(Layer::ALL.map(|l| layers.len(l)), [2, 1, 1, 1]);
        assert_eq!(layers.areas[0].vertices, 4);
        assert_eq!((layers.paths[0].lines.len(), layers.paths[0].vertices), (1, 2));
        assert_eq!((layers.networks[0].lines.len(), layers.networks[0].vertices), (3, 6));
        assert_eq!((layers.left_out[0].row, layers.left_out[0].reason), (110, "outlier"));
        assert!(layers.areas[1].polygons.is_empty());
        assert_eq!(layers.groups[1].run.status, "error");
        assert_eq!(layers.bounds(Layer::Areas), Some([0.0, 0.0, 1.0, 1.0]));
        assert_eq!(layers.bounds(Layer::LeftOut), Some([50.0, 50.0, 50.0, 50.0]));
    }
}
