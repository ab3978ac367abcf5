//! FlatGeobuf (flatgeobuf.org, version 3): points read from a stream (with the features'
//! properties for `--by`), results written one layer a file ([`write()`]).
//!
//! Reading streams the file feature by feature (standard input too), with the format's own
//! FlatBuffers verifier from the `flatgeobuf` crate, but our own framing: a feature's size
//! prefix is not trusted (its bytes are read as they come, so a hostile size allocates
//! nothing), and the spatial index is skipped with checked arithmetic.

use std::io::{self, Read};

use anyhow::{anyhow, bail, Result};
use flatgeobuf::{
    size_prefixed_root_as_feature, size_prefixed_root_as_header, Geometry, GeometryType,
};
use sigdt::Point;

use super::crs::Crs;
use crate::attributes::Grouping;

mod properties;
mod write;

pub use write::write;

/// The first bytes of a FlatGeobuf file: `fgb`, the major version 3, `fgb`, a patch level.
pub const MAGIC: &[u8] = b"fgb\x03fgb";

/// The largest header read (the `flatgeobuf` crate's own limit).
const MAX_HEADER: usize = 10 << 20;

/// The most bytes a feature may hold besides its coordinates (attributes, lengths, the
/// FlatBuffers tables).
const MAX_ATTRIBUTES: usize = 16 << 20;

/// Points of a FlatGeobuf file and its system.
pub struct FgbPoints {
    /// Every vertex of every feature, in the file's order.
    pub points: Vec<Point>,
    /// The system the header declares, if any.
    pub crs: Option<Crs>,
    /// The points grouped by a column (`--by`), each feature's properties its attributes.
    pub grouping: Option<Grouping>,
}

/// The vertices of every feature of the FlatGeobuf stream `reader` (`name` in messages),
/// at most `max` of them.
pub fn read(reader: impl Read, name: &str, max: usize) -> Result<FgbPoints> {
    read_grouped(reader, name, max, None)
}

/// [`read`], the points grouped `by` a column of the header when given: the features'
/// properties are the attributes.
pub fn read_grouped(
    mut reader: impl Read,
    name: &str,
    max: usize,
    by: Option<&str>,
) -> Result<FgbPoints> {
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
    let columns = by.map(|_| properties::Columns::of(&header));
    let mut grouping = match (by, &columns) {
        (Some(by), Some(columns)) => {
            Some(Grouping::new(columns.columns.clone(), by, name).map_err(|m| anyhow!(m))?)
        }
        _ => None,
    };
    let mut points = Vec::new();
    for number in 1.. {
        // Counted before the bytes are buffered (issue 47, B2: a 2 MB .fgb.gz announcing one
        // 2 GB feature was buffered whole under --max-points 1000): a feature can need at
        // most 32 bytes a point (x, y, z, m) for the points still allowed, and some room for
        // its attributes.
        let room =
            max.saturating_sub(points.len()).saturating_mul(32).saturating_add(MAX_ATTRIBUTES);
        let bytes = match size_prefixed(&mut reader, room) {
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
            Err(Framing::TooLarge(size)) => bail!(
                "{name}: FlatGeobuf: feature {number} announces {size} bytes, more than \
                 {} points (the --max-points {max} left, 32 bytes each) and {} MiB of \
                 attributes can need",
                max - points.len().min(max),
                MAX_ATTRIBUTES >> 20
            ),
            Err(Framing::Io(e)) => bail!("{name}: cannot read: {e}"),
        };
        let feature = size_prefixed_root_as_feature(&bytes)
            .map_err(|e| anyhow!("{name}: FlatGeobuf: feature {number} is not valid: {e}"))?;
        let before = points.len();
        if let Some(geometry) = feature.geometry() {
            vertices(&geometry, header_type, &mut points, max, 0)
                .map_err(|why| anyhow!("{name}: FlatGeobuf: feature {number}: {why}"))?;
        }
        if let (Some(grouping), Some(columns)) = (&mut grouping, &columns) {
            let bytes = feature.properties().map_or(&[][..], |p| p.bytes());
            let values = columns
                .values(bytes)
                .map_err(|why| anyhow!("{name}: FlatGeobuf: feature {number}: {why}"))?;
            grouping.add(values, points.len() - before);
        }
    }
    Ok(FgbPoints { points, crs, grouping })
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gis::layers::{Layer, Layers};
    use sigdt::{Method, Options};

    /// A FlatGeobuf file of the outline of a square and, after it, its last feature again.
    fn one_feature_too_many() -> Vec<u8> {
        let points = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let rec = sigdt::reconstruct(&points, &Options::default()).unwrap();
        let layers = Layers::new(Method::SigAuto, &points, &rec, false);
        let mut bytes = write(&layers, Layer::Areas, None).unwrap();
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
    fn every_layer_is_written_with_its_type_and_reads_back() {
        // A square and a failed group (an empty multi-polygon): the square's four vertices.
        let points = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let rec = sigdt::reconstruct(&points, &Options::default()).unwrap();
        let mut layers = Layers::new(Method::SigAuto, &points, &rec, false);
        layers.add_failed(Vec::new(), Method::SigAuto, "too few points".into());
        for layer in Layer::ALL {
            let bytes = write(&layers, layer, None).unwrap();
            let header = size_prefixed_root_as_header(&bytes[8..]).unwrap();
            let expected = match layer {
                Layer::Areas => GeometryType::MultiPolygon,
                Layer::Paths | Layer::Networks => GeometryType::MultiLineString,
                Layer::LeftOut => GeometryType::Point,
            };
            assert_eq!((header.name(), header.geometry_type()), (Some(layer.name()), expected));
            assert_eq!(header.features_count(), layers.len(layer) as u64);
            let read = read(&bytes[..], "a.fgb", 100).unwrap();
            let vertices = if layer == Layer::Areas { points.len() } else { 0 };
            assert_eq!(read.points.len(), vertices, "{layer:?}");
        }
        // The failed group's feature has no geometry (GDAL refuses one without parts), and
        // keeps its properties.
        let bytes = write(&layers, Layer::Areas, None).unwrap();
        let prefix = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        let first = 8 + 4 + prefix(8);
        let second = first + 4 + prefix(first);
        let feature = |at: usize| size_prefixed_root_as_feature(&bytes[at..]).unwrap();
        assert!(feature(first).geometry().is_some());
        assert!(feature(second).geometry().is_none());
        let properties = feature(second).properties().unwrap().bytes().to_vec();
        assert!(String::from_utf8_lossy(&properties).contains("too few points"));
        assert_eq!(second + 4 + prefix(second), bytes.len());
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

    #[test]
    fn a_feature_past_the_limit_is_refused_before_its_bytes_are_read() {
        // Issue 47, B2: a 2 MB .fgb.gz announcing one 2 GB feature was buffered whole before
        // a point was counted. A feature announcing 3 GB, of which no byte arrives: refused
        // on its size, not by the end of the stream.
        let mut bytes = one_feature_too_many();
        let prefix = |b: &[u8], at: usize| u32::from_le_bytes(b[at..at + 4].try_into().unwrap());
        let first = 8 + 4 + prefix(&bytes, 8) as usize;
        bytes.truncate(first);
        bytes.extend(3_000_000_000u32.to_le_bytes());
        let Err(err) = read(&bytes[..], "a.fgb", 1000) else { panic!("read") };
        assert_eq!(
            err.to_string(),
            "a.fgb: FlatGeobuf: feature 1 announces 3000000000 bytes, more than 1000 points (the \
             --max-points 1000 left, 32 bytes each) and 16 MiB of attributes can need"
        );
    }
}
