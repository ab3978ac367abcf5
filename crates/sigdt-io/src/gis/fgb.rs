//! FlatGeobuf (flatgeobuf.org, version 3): points read from a stream, results written as
//! one layer.
//!
//! Reading streams the file feature by feature (standard input too), with the format's own
//! FlatBuffers verifier from the `flatgeobuf` crate, but our own framing: a feature's size
//! prefix is not trusted (its bytes are read as they come, so a hostile size allocates
//! nothing), and the spatial index is skipped with checked arithmetic.
//!
//! A FlatGeobuf file holds one layer, so a result is written as one: the curves
//! (`kind` `polygon` or `path`, with `method`, `status`, `warning`, `diagnosis` and
//! `vertices`) followed by the left-out points (`kind` `left-out`, with `row` and
//! `reason`), each column empty where it does not apply.

use std::io::{self, Read};

use anyhow::{anyhow, bail, Result};
use flatgeobuf::geozero::error::GeozeroError;
use flatgeobuf::geozero::{ColumnValue, GeomProcessor, GeozeroGeometry, PropertyProcessor};
use flatgeobuf::{
    size_prefixed_root_as_feature, size_prefixed_root_as_header, ColumnType, FgbCrs, FgbWriter,
    FgbWriterOptions, Geometry, GeometryType,
};
use sigdt::Point;

use super::crs::Crs;
use super::layers::{Curve, CurveKind, Layers};

/// The first bytes of a FlatGeobuf file: `fgb`, the major version 3, `fgb`, a patch level.
pub const MAGIC: &[u8] = b"fgb\x03fgb";

/// The largest header read (the `flatgeobuf` crate's own limit).
const MAX_HEADER: usize = 10 << 20;

/// Points of a FlatGeobuf file and its system.
pub struct FgbPoints {
    /// Every vertex of every feature, in the file's order.
    pub points: Vec<Point>,
    /// The system the header declares, if any.
    pub crs: Option<Crs>,
}

/// The vertices of every feature of the FlatGeobuf stream `reader` (`name` in messages),
/// at most `max` of them.
pub fn read(mut reader: impl Read, name: &str, max: usize) -> Result<FgbPoints> {
    let cut = |what: &str| anyhow!("{name}: FlatGeobuf: the file ends inside {what}");
    let mut magic = [0u8; 8];
    reader.read_exact(&mut magic).map_err(|_| cut("its magic bytes"))?;
    if !magic.starts_with(MAGIC) {
        bail!("{name}: not a FlatGeobuf file of version 3 (magic bytes {magic:02x?})");
    }
    let header_bytes = size_prefixed(&mut reader, MAX_HEADER).map_err(|e| match e {
        Framing::End | Framing::Cut => cut("its header"),
        Framing::TooLarge(n) => anyhow!("{name}: FlatGeobuf: a header of {n} bytes"),
        Framing::Io(e) => anyhow!("{name}: cannot read: {e}"),
    })?;
    let header = size_prefixed_root_as_header(&header_bytes)
        .map_err(|e| anyhow!("{name}: FlatGeobuf: the header is not valid: {e}"))?;
    let crs = header.crs().and_then(|c| {
        let mut crs = match c.wkt() {
            Some(wkt) if !wkt.trim().is_empty() => Crs::from_wkt(wkt),
            _ => Crs { epsg: None, wkt: None },
        };
        let org_is_epsg = c.org().is_none_or(|o| o.eq_ignore_ascii_case("EPSG"));
        if org_is_epsg && c.code() > 0 {
            crs.epsg = Some(c.code() as u32);
        }
        (crs.epsg.is_some() || crs.wkt.is_some()).then_some(crs)
    });
    let index = index_size(header.features_count(), header.index_node_size())
        .ok_or_else(|| anyhow!("{name}: FlatGeobuf: a spatial index too large to exist"))?;
    let skipped = io::copy(&mut (&mut reader).take(index), &mut io::sink())
        .map_err(|e| anyhow!("{name}: cannot read: {e}"))?;
    if skipped < index {
        return Err(cut("its spatial index"));
    }
    let header_type = header.geometry_type();
    let mut points = Vec::new();
    for number in 1.. {
        let bytes = match size_prefixed(&mut reader, usize::MAX) {
            Ok(bytes) => bytes,
            Err(Framing::End) => {
                let declared = header.features_count();
                let read = number - 1;
                if declared != 0 && declared > read {
                    bail!(
                        "{name}: FlatGeobuf: the file ends after {read} of its {declared} features"
                    );
                }
                if declared != 0 && declared < read {
                    bail!(
                        "{name}: FlatGeobuf: {read} features, more than the {declared} its \
                         header declares"
                    );
                }
                break;
            }
            Err(Framing::Cut) => return Err(cut(&format!("feature {number}"))),
            Err(Framing::TooLarge(_)) => unreachable!("no limit"),
            Err(Framing::Io(e)) => bail!("{name}: cannot read: {e}"),
        };
        let feature = size_prefixed_root_as_feature(&bytes)
            .map_err(|e| anyhow!("{name}: FlatGeobuf: feature {number} is not valid: {e}"))?;
        if let Some(geometry) = feature.geometry() {
            vertices(&geometry, header_type, &mut points, max, 0)
                .map_err(|why| anyhow!("{name}: FlatGeobuf: feature {number}: {why}"))?;
        }
    }
    Ok(FgbPoints { points, crs })
}

enum Framing {
    /// The stream ended where a size would start.
    End,
    /// The stream ended inside the size or the bytes it announces.
    Cut,
    TooLarge(usize),
    Io(io::Error),
}

/// A little-endian `u32` size and that many bytes, returned with the size prefix (as the
/// verifier wants them). The bytes are read as they arrive: the size allocates nothing.
fn size_prefixed(reader: &mut impl Read, max: usize) -> Result<Vec<u8>, Framing> {
    let mut size = [0u8; 4];
    match crate::stream::read_full(reader, &mut size).map_err(Framing::Io)? {
        0 => return Err(Framing::End),
        4 => {}
        _ => return Err(Framing::Cut),
    }
    let n = u32::from_le_bytes(size) as usize;
    if n > max {
        return Err(Framing::TooLarge(n));
    }
    let mut bytes = size.to_vec();
    let got = reader.take(n as u64).read_to_end(&mut bytes).map_err(Framing::Io)?;
    if got < n {
        return Err(Framing::Cut);
    }
    Ok(bytes)
}

/// The packed R-tree's size in bytes for `count` features and nodes of `node_size` items
/// (0: no index), or `None` if it overflows.
fn index_size(count: u64, node_size: u16) -> Option<u64> {
    if node_size == 0 || count == 0 {
        return Some(0);
    }
    let node_size = u64::from(node_size.max(2));
    let (mut level, mut nodes) = (count, count);
    while level > 1 {
        level = level.div_ceil(node_size);
        nodes = nodes.checked_add(level)?;
    }
    if count == 1 {
        nodes += 1; // the root above the single leaf, as the format counts it
    }
    nodes.checked_mul(40) // four f64 bounds and a u64 offset a node
}

/// The vertices of `geometry`, of type `parent` when it does not say; polygon rings without
/// their closing repeat.
fn vertices(
    geometry: &Geometry<'_>,
    parent: GeometryType,
    out: &mut Vec<Point>,
    max: usize,
    depth: usize,
) -> Result<(), String> {
    if depth > 128 {
        return Err("geometries nested more than 128 deep".into());
    }
    let kind = match geometry.type_() {
        GeometryType::Unknown => parent,
        kind => kind,
    };
    if let Some(parts) = geometry.parts() {
        for part in parts {
            vertices(&part, kind, out, max, depth + 1)?;
        }
        return Ok(());
    }
    let Some(xy) = geometry.xy() else { return Ok(()) };
    if xy.len() % 2 != 0 {
        return Err(format!("{} coordinates, not pairs", xy.len()));
    }
    let n = xy.len() / 2;
    let rings = matches!(kind, GeometryType::Polygon | GeometryType::MultiPolygon);
    let ends: Vec<usize> = match geometry.ends() {
        Some(ends) if rings => ends.iter().map(|e| e as usize).collect(),
        _ => vec![n],
    };
    let mut start = 0;
    for end in ends {
        if end < start || end > n {
            return Err(format!("ring end {end} outside the {n} points"));
        }
        let first = out.len();
        for k in start..end {
            let p = [xy.get(2 * k), xy.get(2 * k + 1)];
            if p[0].is_nan() && p[1].is_nan() && kind == GeometryType::Point {
                continue; // an empty point
            }
            if !p.iter().all(|c| c.is_finite()) {
                return Err(format!("coordinate {:?} {:?} is not finite", p[0], p[1]));
            }
            if out.len() == max {
                return Err(format!("more than {max} points (raise --max-points to read more)"));
            }
            out.push(p);
        }
        if rings && out.len() > first + 1 && out.last() == out.get(first) {
            out.pop();
        }
        start = end;
    }
    Ok(())
}

/// The FlatGeobuf file of `layers` (see the module docs) in the system `crs`, as bytes.
pub fn write(layers: &Layers, crs: Option<&Crs>) -> Result<Vec<u8>> {
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
    let mut fgb = FgbWriter::create_with_options("curves", GeometryType::Unknown, options)?;
    let columns = [
        ("kind", ColumnType::String),
        ("method", ColumnType::String),
        ("status", ColumnType::String),
        ("warning", ColumnType::Bool),
        ("diagnosis", ColumnType::String),
        ("vertices", ColumnType::Long),
        ("row", ColumnType::Long),
        ("reason", ColumnType::String),
    ];
    for (name, kind) in columns {
        fgb.add_column(name, kind, |_, column| column.nullable = true);
    }
    let run = &layers.run;
    for curve in &layers.curves {
        fgb.add_feature_geom(curve, |f| {
            let values = [
                (0, "kind", ColumnValue::String(curve.kind.name())),
                (1, "method", ColumnValue::String(&run.method)),
                (2, "status", ColumnValue::String(run.status)),
                (3, "warning", ColumnValue::Bool(run.warning)),
                (4, "diagnosis", ColumnValue::String(&run.diagnosis)),
                (5, "vertices", ColumnValue::Long(curve.vertices as i64)),
            ];
            for (i, name, value) in &values {
                f.property(*i, name, value).expect("a column of the header");
            }
        })?;
    }
    for left in &layers.left_out {
        fgb.add_feature_geom(LeftOutPoint(left.point), |f| {
            let values = [
                (0, "kind", ColumnValue::String("left-out")),
                (6, "row", ColumnValue::Long(left.row as i64)),
                (7, "reason", ColumnValue::String(left.reason)),
            ];
            for (i, name, value) in &values {
                f.property(*i, name, value).expect("a column of the header");
            }
        })?;
    }
    let mut out = Vec::new();
    fgb.write(&mut out)?;
    Ok(out)
}

/// A curve's geometry for geozero: a polygon's rings closed (their first point repeated, as
/// the format wants), or a line string.
impl GeozeroGeometry for &Curve {
    fn process_geom<P: GeomProcessor>(&self, p: &mut P) -> Result<(), GeozeroError> {
        let line = |p: &mut P, points: &[Point], tagged: bool, k: usize| {
            let closing = (!tagged).then(|| points[0]);
            let all: Vec<_> = points.iter().copied().chain(closing).collect();
            p.linestring_begin(tagged, all.len(), k)?;
            for (i, [x, y]) in all.into_iter().enumerate() {
                p.xy(x, y, i)?;
            }
            p.linestring_end(tagged, k)
        };
        match self.kind {
            CurveKind::Path => line(p, &self.rings[0], true, 0),
            CurveKind::Polygon => {
                p.polygon_begin(true, self.rings.len(), 0)?;
                for (k, ring) in self.rings.iter().enumerate() {
                    line(p, ring, false, k)?;
                }
                p.polygon_end(true, 0)
            }
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use sigdt::{Method, Options};

    /// A FlatGeobuf file of the outline of a square and, after it, its last feature again.
    fn one_feature_too_many() -> Vec<u8> {
        let points = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let rec = sigdt::reconstruct(&points, &Options::default()).unwrap();
        let mut bytes = write(&Layers::new(Method::SigAuto, &points, &rec), None).unwrap();
        let prefix = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        // The magic bytes, the size-prefixed header, then size-prefixed features (no index).
        let mut at = 8 + 4 + prefix(8);
        let mut last = at;
        while at < bytes.len() {
            last = at;
            at += 4 + prefix(at);
        }
        let copy = bytes[last..].to_vec();
        bytes.extend(copy);
        bytes
    }

    #[test]
    fn more_features_than_the_header_declares_is_said_the_right_way_round() {
        // Issue 47, B3: the message said the file ended after 2 of its 1 features.
        let bytes = one_feature_too_many();
        let Err(err) = read(&bytes[..], "a.fgb", 100) else { panic!("read") };
        let err = err.to_string();
        assert!(err.contains("features, more than the"), "{err}");
        assert!(err.contains("its header declares"), "{err}");
    }
}
