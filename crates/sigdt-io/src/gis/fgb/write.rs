//! FlatGeobuf output: one layer of a result's [`Layers`] a file, declared with the layer's
//! geometry type (MultiPolygon, MultiLineString or Point) and its columns (the groups'
//! attributes, then sigdt's own), written with the `flatgeobuf` crate (no spatial index).

use anyhow::Result;
use flatbuffers::FlatBufferBuilder;
use flatgeobuf::geozero::error::GeozeroError;
use flatgeobuf::geozero::{ColumnValue, GeomProcessor, GeozeroGeometry, PropertyProcessor};
use flatgeobuf::{
    size_prefixed_root_as_feature, ColumnType as FgbColumnType, Feature, FeatureArgs, FgbCrs,
    FgbWriter, FgbWriterOptions, GeometryType,
};
use sigdt::Point;

use crate::gis::crs::Crs;
use crate::gis::layers::{ColumnType, Group, Layer, Layers, Value};

/// The FlatGeobuf file of `layer` of `layers` (see the module docs) in the system `crs`, as
/// bytes: declared with the layer's geometry type, and empty when the layer is.
pub fn write(layers: &Layers, layer: Layer, crs: Option<&Crs>) -> Result<Vec<u8>> {
    let crs = FgbCrs {
        code: crs.and_then(|c| c.epsg).map_or(0, |c| c as i32),
        wkt: crs.and_then(|c| c.wkt.as_deref()),
        ..FgbCrs::default()
    };
    let options = FgbWriterOptions {
        write_index: false,
        detect_type: false,
        promote_to_multi: false,
        crs,
        ..FgbWriterOptions::default()
    };
    let geometry_type = match layer {
        Layer::Areas => GeometryType::MultiPolygon,
        Layer::Paths | Layer::Networks => GeometryType::MultiLineString,
        Layer::LeftOut => GeometryType::Point,
    };
    let mut fgb = FgbWriter::create_with_options(layer.name(), geometry_type, options)?;
    let mut names: Vec<&str> = Vec::new();
    for column in &layers.columns {
        let kind = match column.kind {
            ColumnType::Text => FgbColumnType::String,
            ColumnType::Integer => FgbColumnType::Long,
            ColumnType::Real => FgbColumnType::Double,
            ColumnType::Bool => FgbColumnType::Bool,
        };
        fgb.add_column(&column.name, kind, |_, c| c.nullable = true);
        names.push(&column.name);
    }
    let own: &[(&str, FgbColumnType)] = match layer {
        Layer::LeftOut => &[("row", FgbColumnType::Long), ("reason", FgbColumnType::String)],
        _ => &[
            ("method", FgbColumnType::String),
            ("status", FgbColumnType::String),
            ("warning", FgbColumnType::Bool),
            ("diagnosis", FgbColumnType::String),
            ("vertices", FgbColumnType::Long),
        ],
    };
    for &(name, kind) in own {
        fgb.add_column(name, kind, |_, c| c.nullable = true);
        names.push(name);
    }
    // The group's attributes, then the layer's own values, in column order; no value for
    // a missing attribute.
    let write_properties = |f: &mut dyn PropertyProcessor, group: &Group, own: &[ColumnValue]| {
        for (i, value) in group.values.iter().enumerate() {
            let value = match value {
                Value::Null => continue,
                Value::Text(text) => ColumnValue::String(text),
                Value::Integer(n) => ColumnValue::Long(*n),
                Value::Real(x) => ColumnValue::Double(*x),
                Value::Bool(b) => ColumnValue::Bool(*b),
            };
            f.property(i, names[i], &value).expect("a column of the header");
        }
        let first = group.values.len();
        for (i, value) in own.iter().enumerate() {
            f.property(first + i, names[first + i], value).expect("a column of the header");
        }
    };
    match layer {
        Layer::Areas => {
            for feature in &layers.areas {
                let group = &layers.groups[feature.group];
                fgb.add_feature_geom(MultiPolygon(&feature.polygons), |f| {
                    write_properties(f, group, &run_values(group, feature.vertices))
                })?;
            }
        }
        Layer::Paths | Layer::Networks => {
            let features = if layer == Layer::Paths { &layers.paths } else { &layers.networks };
            for feature in features {
                let group = &layers.groups[feature.group];
                fgb.add_feature_geom(MultiLineString(&feature.lines), |f| {
                    write_properties(f, group, &run_values(group, feature.vertices))
                })?;
            }
        }
        Layer::LeftOut => {
            for left in &layers.left_out {
                let group = &layers.groups[left.group];
                let own = [ColumnValue::Long(left.row as i64), ColumnValue::String(left.reason)];
                fgb.add_feature_geom(LeftOutPoint(left.point), |f| {
                    write_properties(f, group, &own)
                })?;
            }
        }
    }
    let mut out = Vec::new();
    fgb.write(&mut out)?;
    let empty: Vec<bool> = match layer {
        Layer::Areas => layers.areas.iter().map(|a| a.polygons.is_empty()).collect(),
        _ => Vec::new(),
    };
    match empty.contains(&true) {
        true => without_geometry(&out, &empty),
        false => Ok(out),
    }
}

/// The FlatGeobuf file `bytes` (no spatial index) with the features `empty[k]` written
/// without a geometry, as GDAL writes an empty one: the `flatgeobuf` crate writes an empty
/// multi-polygon as a geometry of no parts, which GDAL refuses ("Fatal error parsing
/// feature").
fn without_geometry(bytes: &[u8], empty: &[bool]) -> Result<Vec<u8>> {
    let size = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().expect("4 bytes"));
    let mut at = 8 + 4 + size(8) as usize;
    let mut out = bytes[..at].to_vec();
    for &empty in empty {
        let end = at + 4 + size(at) as usize;
        if empty {
            let feature = size_prefixed_root_as_feature(&bytes[at..end])?;
            let mut fbb = FlatBufferBuilder::new();
            let properties = feature.properties().map(|p| fbb.create_vector(p.bytes()));
            let args = FeatureArgs { properties, ..FeatureArgs::default() };
            let feature = Feature::create(&mut fbb, &args);
            fbb.finish_size_prefixed(feature, None);
            out.extend_from_slice(fbb.finished_data());
        } else {
            out.extend_from_slice(&bytes[at..end]);
        }
        at = end;
    }
    debug_assert_eq!(at, bytes.len());
    Ok(out)
}

/// The values of the run's columns for a feature of `group` with `vertices`.
fn run_values(group: &Group, vertices: usize) -> [ColumnValue<'_>; 5] {
    let run = &group.run;
    [
        ColumnValue::String(&run.method),
        ColumnValue::String(run.status),
        ColumnValue::Bool(run.warning),
        ColumnValue::String(&run.diagnosis),
        ColumnValue::Long(vertices as i64),
    ]
}

/// The `k`th line of a multi-line string or ring of a polygon for geozero: `points`, a
/// `ring` closed (its first point repeated, as the format wants it).
fn line<P: GeomProcessor>(
    p: &mut P,
    points: &[Point],
    ring: bool,
    k: usize,
) -> Result<(), GeozeroError> {
    let closing = if ring { points.first().copied() } else { None };
    let all: Vec<_> = points.iter().copied().chain(closing).collect();
    p.linestring_begin(false, all.len(), k)?;
    for (i, [x, y]) in all.into_iter().enumerate() {
        p.xy(x, y, i)?;
    }
    p.linestring_end(false, k)
}

/// A group's polygons for geozero (rings closed, as the format wants them).
struct MultiPolygon<'a>(&'a [Vec<Vec<Point>>]);

impl GeozeroGeometry for MultiPolygon<'_> {
    fn process_geom<P: GeomProcessor>(&self, p: &mut P) -> Result<(), GeozeroError> {
        p.multipolygon_begin(self.0.len(), 0)?;
        for (k, rings) in self.0.iter().enumerate() {
            p.polygon_begin(false, rings.len(), k)?;
            for (r, ring) in rings.iter().enumerate() {
                line(p, ring, true, r)?;
            }
            p.polygon_end(false, k)?;
        }
        p.multipolygon_end(0)
    }
}

/// A group's lines for geozero.
struct MultiLineString<'a>(&'a [Vec<Point>]);

impl GeozeroGeometry for MultiLineString<'_> {
    fn process_geom<P: GeomProcessor>(&self, p: &mut P) -> Result<(), GeozeroError> {
        p.multilinestring_begin(self.0.len(), 0)?;
        for (k, points) in self.0.iter().enumerate() {
            line(p, points, false, k)?;
        }
        p.multilinestring_end(0)
    }
}

/// A left-out point's geometry for geozero.
struct LeftOutPoint(Point);

impl GeozeroGeometry for LeftOutPoint {
    fn process_geom<P: GeomProcessor>(&self, p: &mut P) -> Result<(), GeozeroError> {
        p.point_begin(0)?;
        p.xy(self.0[0], self.0[1], 0)?;
        p.point_end(0)
    }
}
