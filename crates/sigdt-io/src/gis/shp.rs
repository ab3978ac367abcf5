//! ESRI Shapefile `.shp` (ESRI White Paper J-7855, 1998): the vertices of every record,
//! streamed record by record, and the coordinate system from the `.prj` beside it.
//!
//! Read: null shapes (skipped), points, multipoints, polylines and polygons, with Z or M
//! (their values skipped); a polygon ring's closing vertex is not a point. Every count is
//! checked against the record's declared length before anything is allocated, and every
//! record's length against the bytes that come, so a hostile file costs what it holds.

use std::io::Read;
use std::path::Path;

use anyhow::{anyhow, bail, Result};
use sigdt::Point;

use super::crs::Crs;
pub use super::dbf::Dbf;

/// The file code that opens every `.shp` (big-endian 9994).
pub const MAGIC: &[u8] = &[0x00, 0x00, 0x27, 0x0a];

/// The vertices of the Shapefile stream `reader` (`name` in messages), at most `max`.
pub fn read(reader: impl Read, name: &str, max: usize) -> Result<Vec<Point>> {
    read_each(reader, name, max, |_| Ok(()))
}

/// [`read`], calling `record_read` with the number of points of each record once it is read
/// (a null shape's 0 included), in record order.
pub fn read_each(
    mut reader: impl Read,
    name: &str,
    max: usize,
    mut record_read: impl FnMut(usize) -> Result<()>,
) -> Result<Vec<Point>> {
    let mut header = [0u8; 100];
    reader
        .read_exact(&mut header)
        .map_err(|_| anyhow!("{name}: Shapefile: the file ends inside its 100-byte header"))?;
    if &header[..4] != MAGIC {
        bail!("{name}: not a Shapefile (file code {:02x?}, 9994 expected)", &header[..4]);
    }
    let mut points = Vec::new();
    for number in 1.. {
        let mut head = [0u8; 8];
        match crate::stream::read_full(&mut reader, &mut head) {
            Ok(0) => break,
            Ok(8) => {}
            Ok(_) => bail!("{name}: Shapefile: the file ends inside the header of record {number}"),
            Err(e) => bail!("{name}: cannot read: {e}"),
        }
        // The length counts 16-bit words.
        let bytes = u32::from_be_bytes(head[4..8].try_into().expect("4 bytes")) as u64 * 2;
        // The shape's counts first: a record that will add more points than are left under
        // the limit is refused before its coordinates are buffered (a gzipped record of
        // gigabytes would be read whole otherwise).
        let mut content = Vec::new();
        let counts = bytes.min(COUNTS_BYTES);
        let mut got = (&mut reader)
            .take(counts)
            .read_to_end(&mut content)
            .map_err(|e| anyhow!("{name}: cannot read: {e}"))?;
        // A count the record cannot hold is a lie, which `record` names: only one that fits
        // is refused here.
        let fewest = fewest_points(&content);
        if fewest > max - points.len() && (fewest as u64).saturating_mul(16) <= bytes {
            bail!(
                "{name}: Shapefile record {number}: more than {max} points (raise --max-points \
                 to read more)"
            );
        }
        got += (&mut reader)
            .take(bytes - counts)
            .read_to_end(&mut content)
            .map_err(|e| anyhow!("{name}: cannot read: {e}"))?;
        if (got as u64) < bytes {
            bail!("{name}: Shapefile: the file ends inside record {number}");
        }
        let before = points.len();
        record(&content, &mut points, max)
            .map_err(|why| anyhow!("{name}: Shapefile record {number}: {why}"))?;
        record_read(points.len() - before)?;
    }
    Ok(points)
}

/// The bytes of a record up to its point count: shape type, bounding box, parts and points.
const COUNTS_BYTES: u64 = 44;

/// The fewest points the record beginning with `head` (at most [`COUNTS_BYTES`]) adds: its
/// point count, less one closing repeat a ring for polygons; 0 when the counts are not
/// there (the record is refused when it is read).
fn fewest_points(head: &[u8]) -> usize {
    let int = |at: usize| {
        let b: [u8; 4] = head.get(at..at + 4)?.try_into().ok()?;
        usize::try_from(i32::from_le_bytes(b)).ok()
    };
    match int(0) {
        Some(8 | 18 | 28) => int(36).unwrap_or(0),
        Some(3 | 13 | 23) => int(40).unwrap_or(0),
        Some(5 | 15 | 25) => int(40).unwrap_or(0).saturating_sub(int(36).unwrap_or(0)),
        _ => 0,
    }
}

/// The vertices of one record's content.
fn record(content: &[u8], out: &mut Vec<Point>, max: usize) -> Result<(), String> {
    let int = |at: usize| -> Result<usize, String> {
        let b = content.get(at..at + 4).ok_or("the record is shorter than its shape")?;
        let v = i32::from_le_bytes(b.try_into().expect("4 bytes"));
        usize::try_from(v).map_err(|_| format!("a negative count {v}"))
    };
    let coordinate = |at: usize| -> Result<f64, String> {
        let b = content.get(at..at + 8).ok_or("the record is shorter than its shape")?;
        Ok(f64::from_le_bytes(b.try_into().expect("8 bytes")))
    };
    let push = |p: Point, out: &mut Vec<Point>| -> Result<(), String> {
        if !p.iter().all(|c| c.is_finite()) {
            return Err(format!("coordinate {:?} {:?} is not finite", p[0], p[1]));
        }
        if out.len() == max {
            return Err(format!("more than {max} points (raise --max-points to read more)"));
        }
        out.push(p);
        Ok(())
    };
    let shape = int(0)?;
    match shape {
        0 => Ok(()),
        1 | 11 | 21 => push([coordinate(4)?, coordinate(12)?], out),
        8 | 18 | 28 => {
            let n = int(36)?;
            check_fits(n, 16, content.len() - 40.min(content.len()))?;
            (0..n).try_for_each(|k| push([coordinate(40 + 16 * k)?, coordinate(48 + 16 * k)?], out))
        }
        3 | 13 | 23 | 5 | 15 | 25 => {
            let (parts, n) = (int(36)?, int(40)?);
            let left = content.len().saturating_sub(44);
            check_fits(parts, 4, left)?;
            check_fits(n, 16, left - 4 * parts)?;
            let at = 44 + 4 * parts;
            let mut starts = (0..parts).map(|k| int(44 + 4 * k)).collect::<Result<Vec<_>, _>>()?;
            starts.push(n);
            let ring = matches!(shape, 5 | 15 | 25);
            for (k, pair) in starts.windows(2).enumerate() {
                let (start, end) = (pair[0], pair[1]);
                // `end` is the next part's start (the point count after the last part): the
                // value to name when the two disagree.
                if end > n {
                    return Err(format!(
                        "part {} starts at point {end}, past the {n} points",
                        k + 1
                    ));
                }
                if start > end {
                    let next = k + 1;
                    return Err(format!(
                        "part {next} starts at point {end}, before part {k} (at {start})"
                    ));
                }
                let first = out.len();
                for k in start..end {
                    push([coordinate(at + 16 * k)?, coordinate(at + 16 * k + 8)?], out)?;
                }
                if ring && out.len() > first + 1 && out.last() == out.get(first) {
                    out.pop();
                }
            }
            Ok(())
        }
        31 => Err("a multipatch (3D surfaces), which holds no points of a curve".into()),
        other => Err(format!("shape type {other} is not a Shapefile shape")),
    }
}

/// Refuses `n` items of `size` bytes when fewer than that many bytes are `left`.
fn check_fits(n: usize, size: usize, left: usize) -> Result<(), String> {
    match n.checked_mul(size) {
        Some(need) if need <= left => Ok(()),
        _ => Err(format!("{n} items, more than the record's {left} bytes hold")),
    }
}

/// The files read beside a Shapefile `path` (`a.shp`, or `a.shp.gz` inside gzip): its
/// `.prj` in either case (the one input sigdt reads) and the `.shx`, `.dbf` and `.cpg` that
/// belong with it, so that no output replaces one. Empty for any other file.
pub fn sidecars(path: &Path) -> Vec<std::path::PathBuf> {
    let name = path.file_name().map(|n| n.to_string_lossy().to_ascii_lowercase());
    let base = match name.as_deref() {
        Some(n) if n.ends_with(".shp") => path.to_path_buf(),
        Some(n) if n.ends_with(".shp.gz") => path.with_extension(""),
        _ => return Vec::new(),
    };
    let extensions = ["prj", "PRJ", "shx", "SHX", "dbf", "DBF", "cpg", "CPG"];
    extensions.into_iter().map(|e| base.with_extension(e)).collect()
}

/// The largest `.prj` read: the longest WKT definitions in the EPSG registry are a few
/// kilobytes.
pub const MAX_PRJ_BYTES: u64 = 64 << 10;

/// The system of the `.prj` beside the `.shp` at `path`, if there is one. Its text goes into
/// every GIS output as the system's definition, so it is refused when it is not a WKT
/// coordinate system, larger than [`MAX_PRJ_BYTES`], or a symbolic link out of its folder.
pub fn projection(path: &Path) -> Result<Option<Crs>> {
    let prj = path.with_extension("prj");
    let upper = path.with_extension("PRJ");
    let Some(found) = [prj, upper].into_iter().find(|p| p.is_file()) else {
        return Ok(None);
    };
    let shown = found.display();
    // The folder of a bare file name (`s.prj`) is the current one.
    let folder = |p: &Path| {
        let dir = p.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
        std::fs::canonicalize(dir).ok()
    };
    let target = std::fs::canonicalize(&found).map_err(|e| anyhow!("{shown}: cannot read: {e}"))?;
    if folder(&target) != folder(&found) {
        bail!(
            "{shown}: a link to '{}', outside the Shapefile's folder: refused (copy the \
             definition beside it)",
            target.display()
        );
    }
    let mut bytes = Vec::new();
    std::fs::File::open(&found)
        .and_then(|f| f.take(MAX_PRJ_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| anyhow!("{shown}: cannot read: {e}"))?;
    if bytes.len() as u64 > MAX_PRJ_BYTES {
        bail!("{shown}: larger than {MAX_PRJ_BYTES} bytes, which no coordinate system needs");
    }
    let text = String::from_utf8_lossy(&bytes);
    let crs = Crs::from_wkt(&text);
    if crs.wkt.is_none() {
        return Ok(None);
    }
    if !crs.is_wkt_definition() {
        bail!(
            "{shown}: not a coordinate system definition (WKT such as PROJCS[...] or \
             GEOGCS[...]): correct or remove it"
        );
    }
    Ok(Some(crs))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shp(records: &[Vec<u8>]) -> Vec<u8> {
        let mut bytes = MAGIC.to_vec();
        bytes.resize(100, 0);
        for (k, content) in records.iter().enumerate() {
            bytes.extend_from_slice(&(k as u32 + 1).to_be_bytes());
            bytes.extend_from_slice(&(content.len() as u32 / 2).to_be_bytes());
            bytes.extend_from_slice(content);
        }
        bytes
    }

    fn point(x: f64, y: f64) -> Vec<u8> {
        let mut c = 1i32.to_le_bytes().to_vec();
        c.extend_from_slice(&x.to_le_bytes());
        c.extend_from_slice(&y.to_le_bytes());
        c
    }

    fn polygon(ring: &[Point]) -> Vec<u8> {
        let mut c = 5i32.to_le_bytes().to_vec();
        c.extend_from_slice(&[0; 32]);
        c.extend_from_slice(&1i32.to_le_bytes());
        c.extend_from_slice(&(ring.len() as i32).to_le_bytes());
        c.extend_from_slice(&0i32.to_le_bytes());
        for p in ring {
            c.extend_from_slice(&p[0].to_le_bytes());
            c.extend_from_slice(&p[1].to_le_bytes());
        }
        c
    }

    #[test]
    fn points_and_rings_read_without_the_closing_repeat() {
        let ring = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.0]];
        let bytes = shp(&[point(5.0, 6.0), vec![0, 0, 0, 0], polygon(&ring)]);
        let points = read(&bytes[..], "t.shp", 10).unwrap();
        assert_eq!(points, vec![[5.0, 6.0], [0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
    }

    #[test]
    fn hostile_records_are_refused_naming_the_record() {
        // A polygon claiming 2^31-1 points in a short record: refused, nothing allocated.
        let mut c = polygon(&[[0.0, 0.0]]);
        c[40..44].copy_from_slice(&i32::MAX.to_le_bytes());
        let err = read(&shp(&[point(0.0, 0.0), c])[..], "t.shp", 10).unwrap_err().to_string();
        assert!(err.starts_with("t.shp: Shapefile record 2: 2147483647 items"), "{err}");
        // A record longer than the file.
        let mut bytes = shp(&[point(0.0, 0.0)]);
        bytes[104..108].copy_from_slice(&u32::MAX.to_be_bytes());
        let err = read(&bytes[..], "t.shp", 10).unwrap_err().to_string();
        assert_eq!(err, "t.shp: Shapefile: the file ends inside record 1");
        let err = read(&b"not a shapefile"[..], "t.shp", 10).unwrap_err().to_string();
        assert!(err.contains("ends inside its 100-byte header"), "{err}");
        let err = read(&shp(&[point(f64::NAN, 0.0)])[..], "t.shp", 10).unwrap_err().to_string();
        assert!(err.contains("record 1: coordinate NaN 0.0 is not finite"), "{err}");
        // Parts whose starts disagree with the points: the message names the start that
        // is wrong (it named the first part's, which was right).
        let two_parts = |second: i32| {
            let mut c = polygon(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
            c[36..40].copy_from_slice(&2i32.to_le_bytes());
            c.splice(48..48, second.to_le_bytes());
            read(&shp(&[c])[..], "t.shp", 10).unwrap_err().to_string()
        };
        let err = two_parts(5);
        assert!(err.ends_with("record 1: part 1 starts at point 5, past the 3 points"), "{err}");
        let err = two_parts(-1);
        assert!(err.contains("record 1: "), "{err}");
        let mut c = polygon(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
        c[36..40].copy_from_slice(&2i32.to_le_bytes());
        c[44..48].copy_from_slice(&2i32.to_le_bytes());
        c.splice(48..48, 1i32.to_le_bytes());
        let err = read(&shp(&[c])[..], "t.shp", 10).unwrap_err().to_string();
        assert!(err.ends_with("part 1 starts at point 1, before part 0 (at 2)"), "{err}");
        let many: Vec<_> = (0..11).map(|k| point(k as f64, 0.0)).collect();
        let err = read(&shp(&many)[..], "t.shp", 10).unwrap_err().to_string();
        assert!(err.contains("record 11: more than 10 points"), "{err}");
    }

    #[test]
    fn a_record_past_the_limit_is_refused_before_its_coordinates_are_read() {
        // Issue 47, B1: a gzipped record of gigabytes was buffered whole before a point was
        // counted (2.1 GB with --max-points 1000). A polygon announcing a million points in a
        // record of that length, of which only the counts arrive: refused on its counts,
        // not by the end of the file.
        let mut c = polygon(&[[0.0, 0.0]]);
        c[40..44].copy_from_slice(&1_000_000i32.to_le_bytes());
        let mut bytes = shp(&[c]);
        let words = ((44 + 4 + 16 * 1_000_000) / 2) as u32;
        bytes[104..108].copy_from_slice(&words.to_be_bytes());
        let err = read(&bytes[..], "t.shp", 10).unwrap_err().to_string();
        assert_eq!(
            err,
            "t.shp: Shapefile record 1: more than 10 points (raise --max-points to read more)"
        );
        // A record within the limit is read as before.
        let ring = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.0]];
        assert_eq!(read(&shp(&[polygon(&ring)])[..], "t.shp", 4).unwrap().len(), 3);
    }

    #[test]
    fn a_prj_that_is_no_coordinate_system_or_lies_elsewhere_is_refused() {
        // Issue 47, K7: a .prj was followed through symbolic links, and any text up to
        // 1 MiB went into the outputs as the system's definition.
        let dir = tempfile::tempdir().unwrap();
        let shp_path = dir.path().join("a.shp");
        let prj = dir.path().join("a.prj");
        std::fs::write(&prj, "password=hunter2\n").unwrap();
        let err = projection(&shp_path).unwrap_err().to_string();
        assert!(err.ends_with("not a coordinate system definition (WKT such as PROJCS[...] or GEOGCS[...]): correct or remove it"), "{err}");
        std::fs::write(&prj, format!("GEOGCS[\"{}\"]", "x".repeat(70_000))).unwrap();
        let err = projection(&shp_path).unwrap_err().to_string();
        assert!(err.contains("larger than 65536 bytes"), "{err}");
        std::fs::write(&prj, format!("\u{feff}{}", super::super::crs::WGS84_WKT)).unwrap();
        assert_eq!(projection(&shp_path).unwrap().and_then(|c| c.epsg), Some(4326));
        #[cfg(unix)]
        links(&dir, &prj, &shp_path);
    }

    /// A link to a file in another folder is refused; one beside it is read.
    #[cfg(unix)]
    fn links(dir: &tempfile::TempDir, prj: &Path, shp_path: &Path) {
        let elsewhere = tempfile::tempdir().unwrap();
        let secret = elsewhere.path().join("secret.prj");
        std::fs::write(&secret, super::super::crs::WGS84_WKT).unwrap();
        std::fs::remove_file(prj).unwrap();
        std::os::unix::fs::symlink(&secret, prj).unwrap();
        let err = projection(shp_path).unwrap_err().to_string();
        assert!(err.contains("outside the Shapefile's folder"), "{err}");
        std::fs::remove_file(prj).unwrap();
        let beside = dir.path().join("b.prj");
        std::fs::write(&beside, super::super::crs::WGS84_WKT).unwrap();
        std::os::unix::fs::symlink(&beside, prj).unwrap();
        assert_eq!(projection(shp_path).unwrap().and_then(|c| c.epsg), Some(4326));
    }
}
