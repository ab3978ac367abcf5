//! Point files in the formats people have, beside sigdt's own plain `x y` lines and `.gtn`
//! files (read by [`crate::text`]): WKT, GeoJSON, NumPy `.npy` arrays and CSV tables with
//! chosen columns, each also gzip-compressed (`.gz`, or found by its magic bytes).
//!
//! The format is chosen once, at the entry, in this order:
//! 1. gzip magic bytes: decompressed on the fly, and the name without `.gz` decides the rest;
//! 2. magic bytes: a NumPy array (`npy.rs`), a GeoPackage (SQLite; read in place, so only
//!    from a file), FlatGeobuf or a Shapefile `.shp` (its `.prj` read for the coordinate
//!    system) ([`crate::gis`]);
//! 3. `--columns`: a table (`table.rs`);
//! 4. the extension: `.wkt`, `.geojson` or `.json`, `.csv` or `.tsv` with more than two
//!    fields, `;` separators or quotes;
//! 5. the first character that is not white space: `{` or `[` is GeoJSON, a WKT keyword is
//!    WKT; a plain file whose header names y before x (`lat,lon`) is a table, read by name;
//!    anything else goes to [`crate::text`], which reads plain and `.gtn` files and refuses
//!    what it cannot read with the file and line.
//!
//! Every error names the file (and the line where there is one).

mod geojson;
mod gzip;
mod npy;
mod table;
mod wkt;

use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use crate::text::PointFormat;
use anyhow::{anyhow, bail, Context, Result};
use sigdt::Point;

use crate::attributes::Grouping;
use crate::gis::{fgb, gpkg, shp, Crs};
use crate::Misuse;

pub use table::Columns;

/// How points are to be read: the limit on their number, the columns of a table, the
/// layer of a GeoPackage, and the path of a file (a GeoPackage is read in place, and a
/// Shapefile's `.prj` lies beside it).
#[derive(Debug, Clone, Copy)]
pub struct Reading<'a> {
    /// Reading stops with an error after this many points.
    pub max_points: usize,
    /// `--columns`: the x and y columns of a table.
    pub columns: Option<&'a Columns>,
    /// `--layer`: the layer of a GeoPackage.
    pub layer: Option<&'a str>,
    /// The file read, when it is one (not standard input, not inside gzip).
    pub path: Option<&'a Path>,
    /// `--by`: group the points by this attribute column.
    pub by: Option<&'a str>,
}

impl Reading<'_> {
    /// At most `max_points` points, no columns, no layer, no path, no grouping.
    pub fn at_most(max_points: usize) -> Reading<'static> {
        Reading { max_points, columns: None, layer: None, path: None, by: None }
    }
}

/// Points read from a file, and how: the format and, for a table, the columns; and the
/// coordinate system the file declares, if it does.
#[derive(Debug)]
pub struct Points {
    /// The points, in the file's order.
    pub points: Vec<Point>,
    /// For `--verbose`: "WKT", "columns 'lon' and 'lat' of a table (the header row
    /// skipped)", ...
    pub how: String,
    /// The coordinate system the file declares (or the one given for it).
    pub crs: Option<Crs>,
    /// Whether a table's columns read are named longitude and latitude.
    pub lon_lat: bool,
    /// The points grouped by an attribute (`--by`), when asked.
    pub grouping: Option<Grouping>,
}

/// The points of `reader`, named `name` in errors (a path or `<stdin>`); see the module docs.
pub fn points(reader: impl Read, name: &str, how: Reading<'_>) -> Result<Points> {
    let mut reader = BufReader::with_capacity(1 << 16, reader);
    // The first read fails for a directory: an I/O error, as opening would give it.
    let head =
        reader.fill_buf().map_err(|source| sigdt::Error::Io { path: name.to_string(), source })?;
    if head.starts_with(gzip::MAGIC) {
        let inner = name.strip_suffix(".gz").unwrap_or(name);
        let mut unzipped = BufReader::with_capacity(1 << 16, gzip::Members::new(reader));
        // A corrupt stream fails at its first read, with the file's name.
        let head = unzipped.fill_buf().with_context(|| format!("{name}: not a valid gzip file"))?;
        if head.starts_with(gzip::MAGIC) {
            bail!("{name}: gzip inside gzip: decompress it once (gunzip), then read what remains");
        }
        // Nothing inside gzip is read in place; a Shapefile's `.prj` lies beside the file
        // without `.gz` (`a.shp.gz`: `a.prj`).
        let beside = how.path.map(|path| path.with_extension(""));
        let how = Reading { path: None, ..how };
        let mut read = uncompressed(unzipped, name, inner, how, beside.as_deref())?;
        read.how = format!("{} (gzip)", read.how);
        return Ok(read);
    }
    uncompressed(reader, name, name, how, how.path)
}

/// The formats of [`uncompressed`], found before reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    GeoPackage,
    FlatGeobuf,
    Shapefile,
    Npy,
    Wkt,
    GeoJson,
    Table,
    /// Plain lines or `.gtn`, read by [`crate::text`].
    Kernel(PointFormat),
}

/// [`points`] of an uncompressed stream; `shown` names it in errors, `inner` (the name
/// without `.gz`) gives the extension, and a Shapefile's `.prj` is looked for beside
/// `beside`.
fn uncompressed<R: BufRead>(
    mut reader: R,
    shown: &str,
    inner: &str,
    how: Reading<'_>,
    beside: Option<&Path>,
) -> Result<Points> {
    let head = reader.fill_buf().with_context(|| format!("{shown}: cannot read"))?;
    let format = detect(head, inner);
    let max = how.max_points;
    let done = |points: Vec<Point>, how: &str| Points {
        points,
        how: how.to_string(),
        crs: None,
        lon_lat: false,
        grouping: None,
    };
    let kind = match format {
        Format::Table | Format::Kernel(PointFormat::Plain) => "a table",
        Format::Kernel(PointFormat::Gtn) => "a .gtn file",
        Format::Npy => "a NumPy array",
        Format::Wkt => "WKT",
        Format::GeoJson => "GeoJSON",
        Format::GeoPackage => "a GeoPackage",
        Format::FlatGeobuf => "FlatGeobuf",
        Format::Shapefile => "a Shapefile",
    };
    let conflict = |message: String| -> anyhow::Error { Misuse { message }.into() };
    if how.layer.is_some() && format != Format::GeoPackage {
        return Err(conflict(format!("--layer: {shown} is {kind}, which has no layers to choose")));
    }
    let with_attributes = matches!(
        format,
        Format::GeoPackage
            | Format::FlatGeobuf
            | Format::Shapefile
            | Format::Table
            | Format::Kernel(PointFormat::Plain)
    );
    if how.by.is_some() && !with_attributes {
        return Err(conflict(format!(
            "--by: {shown} is {kind}, which has no attributes to group by (GeoPackage, \
             Shapefile, FlatGeobuf and CSV tables have)"
        )));
    }
    let as_table = matches!(format, Format::Table | Format::Kernel(PointFormat::Plain));
    if how.columns.is_some() || (how.by.is_some() && as_table) {
        if !as_table {
            return Err(conflict(format!(
                "--columns: {shown} is {kind}, which has no columns to choose"
            )));
        }
        let table = table::read_grouped(reader, shown, how.columns, max, how.by)?;
        return Ok(Points {
            points: table.points,
            how: table.how,
            crs: None,
            lon_lat: table.lon_lat,
            grouping: table.grouping,
        });
    }
    Ok(match format {
        Format::GeoPackage => {
            let Some(path) = how.path else {
                bail!(
                    "{shown}: a GeoPackage is read in place: give its file name (not standard \
                     input, not gzip-compressed)"
                );
            };
            let read = gpkg::read_grouped(path, shown, how.layer, max, how.by)?;
            let how = format!("layer {} of a GeoPackage", crate::text::quoted(&read.layer));
            Points {
                points: read.points,
                how,
                crs: read.crs,
                lon_lat: false,
                grouping: read.grouping,
            }
        }
        Format::FlatGeobuf => {
            let read = fgb::read_grouped(reader, shown, max, how.by)?;
            let how = "FlatGeobuf".to_string();
            Points {
                points: read.points,
                how,
                crs: read.crs,
                lon_lat: false,
                grouping: read.grouping,
            }
        }
        Format::Shapefile => {
            let (points, grouping) = match how.by {
                None => (shp::read(reader, shown, max)?, None),
                Some(by) => shapefile_grouped(reader, shown, max, beside, by)?,
            };
            let crs = match beside {
                Some(path) => shp::projection(path)?,
                None => None,
            };
            let how = match &crs {
                Some(_) => "a Shapefile (its .prj read)",
                None => "a Shapefile (no .prj beside it: coordinate system unknown)",
            };
            Points { points, how: how.into(), crs, lon_lat: false, grouping }
        }
        Format::Npy => done(npy::read(reader, shown, max)?, "a NumPy array"),
        Format::Wkt => done(wkt::read(reader, shown, max)?, "WKT"),
        Format::GeoJson => {
            let (points, crs) = geojson::read_with_crs(reader, shown, max)?;
            // A name sigdt cannot read is an error: dropped, the points would be written
            // out in a system they are not in.
            let crs = crs
                .map(|name| {
                    Crs::parse(&name).map_err(|_| {
                        anyhow::anyhow!(
                            "{shown}: GeoJSON: the \"crs\" member names {}, a coordinate system \
                             sigdt cannot read (it reads EPSG codes and CRS84, as names, OGC URNs \
                             or http URIs): write it as urn:ogc:def:crs:EPSG::NNNN",
                            crate::text::quoted(&name)
                        )
                    })
                })
                .transpose()?;
            Points { points, how: "GeoJSON".into(), crs, lon_lat: false, grouping: None }
        }
        Format::Table => {
            let table = table::read(reader, shown, None, max)?;
            let (how, lon_lat) = (table.how, table.lon_lat);
            Points { points: table.points, how, crs: None, lon_lat, grouping: None }
        }
        Format::Kernel(format) => {
            let points = crate::text::parse_points_at_most(reader, shown, Some(format), max)?;
            let how = if format == PointFormat::Gtn { ".gtn" } else { "plain lines" };
            done(points, how)
        }
    })
}

/// The points of a Shapefile grouped `by` a field of the `.dbf` beside `beside` (the `.shp`
/// without `.gz`): record `k` of the one gives the attributes of the points of record `k`
/// of the other.
fn shapefile_grouped(
    reader: impl BufRead,
    shown: &str,
    max: usize,
    beside: Option<&Path>,
    by: &str,
) -> Result<(Vec<Point>, Option<Grouping>)> {
    let table = beside.map(shp::Dbf::beside).transpose()?.flatten();
    let Some(mut table) = table else {
        bail!("{shown}: --by: no .dbf beside the Shapefile, so its records have no attributes");
    };
    let mut grouping = Grouping::new(table.columns(), by, table.name()).map_err(|m| anyhow!(m))?;
    let points = shp::read_each(reader, shown, max, |n| {
        grouping.add(table.next_record()?, n);
        Ok(())
    })?;
    Ok((points, Some(grouping)))
}

/// The format of a stream that starts with `head`, named `inner` (without `.gz`); see the
/// module docs.
fn detect(head: &[u8], inner: &str) -> Format {
    if head.starts_with(npy::MAGIC) {
        return Format::Npy;
    }
    if head.starts_with(gpkg::MAGIC) {
        return Format::GeoPackage;
    }
    if head.starts_with(fgb::MAGIC) {
        return Format::FlatGeobuf;
    }
    if head.starts_with(shp::MAGIC) {
        return Format::Shapefile;
    }
    let extension = Path::new(inner)
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let first = first_content(head);
    match extension.as_str() {
        "wkt" => return Format::Wkt,
        "geojson" | "json" => return Format::GeoJson,
        "csv" | "tsv" if table::is_table(first) => return Format::Table,
        _ => {}
    }
    if first.starts_with(['{', '[']) {
        return Format::GeoJson;
    }
    if wkt::starts_wkt(first) {
        return Format::Wkt;
    }
    match PointFormat::detect(Path::new(inner), first) {
        PointFormat::Plain if table::needs_names(first) => Format::Table,
        format => Format::Kernel(format),
    }
}

/// The first line of `head` with content: leading white space, a UTF-8 byte-order mark and
/// `#` comment lines skipped (as the plain reader does). Empty when the buffer holds none.
fn first_content(head: &[u8]) -> &str {
    let text = match std::str::from_utf8(head) {
        Ok(text) => text,
        // The buffer may end inside a character: keep the valid prefix.
        Err(e) => std::str::from_utf8(&head[..e.valid_up_to()]).unwrap_or_default(),
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.lines().map(str::trim).find(|l| !l.is_empty() && !l.starts_with('#')).unwrap_or("")
}

/// The error for more than `max` points.
fn too_many(name: &str, max: usize) -> anyhow::Error {
    anyhow::anyhow!("{name}: more than {max} points (raise --max-points to read more)")
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn read(bytes: &[u8], name: &str) -> Result<Vec<Point>> {
        points(bytes, name, Reading::at_most(100)).map(|p| p.points)
    }

    #[test]
    fn a_header_naming_y_before_x_is_read_by_name() {
        let read = |text: &str| points(text.as_bytes(), "a.csv", Reading::at_most(9)).unwrap();
        let latlon = read("lat,lon\n10,20\n11,21\n");
        assert_eq!(latlon.points, vec![[20.0, 10.0], [21.0, 11.0]]);
        assert_eq!(latlon.how, "columns 'lon' and 'lat' of a table (the header row skipped)");
        assert_eq!(read("x,y\n10,20\n").how, "plain lines", "the fast reader where it is right");
    }

    #[test]
    fn columns_are_refused_for_formats_without_columns() {
        // Issue 30, G8: WKT and GeoJSON gave no points, a .gtn header became a point.
        let columns: Columns = "1,2".parse().unwrap();
        let with_columns = |bytes: &[u8], name: &str| {
            points(bytes, name, Reading { columns: Some(&columns), ..Reading::at_most(100) })
        };
        for (bytes, name, kind) in [
            (&b"MULTIPOINT (0 0, 1 0, 1 1)"[..], "a.wkt", "WKT"),
            (&b"{\"type\": \"MultiPoint\", \"coordinates\": [[0,0]]}"[..], "a", "GeoJSON"),
            (&b"3 2 0 0\n0 0 0\n1 1 0\n2 1 1\n"[..], "a", "a .gtn file"),
            (&b"\x93NUMPY"[..], "a.npy", "a NumPy array"),
        ] {
            let err = with_columns(bytes, name).unwrap_err();
            let usage = err.downcast_ref::<Misuse>().expect("a usage error (exit 2)");
            assert_eq!(
                usage.message,
                format!("--columns: {name} is {kind}, which has no columns to choose")
            );
        }
        let read = with_columns(b"0 0\n1 0\n1 1\n", "a.xy").unwrap();
        assert_eq!((read.points.len(), read.how.as_str()), (3, "columns 1 and 2 of a table"));
    }

    #[test]
    fn each_format_is_found_by_content_or_extension() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(read(b"0 0\n1 0\n1 1\n0 1\n", "a.xy").unwrap(), square);
        assert_eq!(read(b"MULTIPOINT (0 0, 1 0, 1 1, 0 1)", "a.txt").unwrap(), square);
        let json = br#"{"type": "MultiPoint", "coordinates": [[0,0],[1,0],[1,1],[0,1]]}"#;
        assert_eq!(read(json, "a").unwrap(), square);
        assert_eq!(read(b"x;y\n0;0\n1;0\n1;1\n0;1\n", "a.csv").unwrap(), square);
        let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        gz.write_all(b"# zipped\nPOINT (0 0)\nPOINT (1 0)\nPOINT (1 1)\nPOINT (0 1)\n").unwrap();
        assert_eq!(read(&gz.finish().unwrap(), "a.wkt.gz").unwrap(), square);
        let err = read(&[0x1f, 0x8b, 0, 1, 2, 3], "b.xy.gz").unwrap_err();
        assert!(format!("{err:#}").contains("b.xy.gz: not a valid gzip file"), "{err:#}");
        let mut twice = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        let mut once = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        once.write_all(b"0 0\n").unwrap();
        twice.write_all(&once.finish().unwrap()).unwrap();
        let err = read(&twice.finish().unwrap(), "c.xy.gz").unwrap_err().to_string();
        assert!(err.starts_with("c.xy.gz: gzip inside gzip"), "{err}");
    }

    #[test]
    fn the_first_content_skips_marks_comments_and_blank_lines() {
        assert_eq!(first_content("\u{feff}\n  # c\n\n {\"a\": 1}\n".as_bytes()), "{\"a\": 1}");
        assert_eq!(first_content(b""), "");
        assert_eq!(first_content(&[b'x', 0xe2, 0x82]), "x");
    }

    #[test]
    fn a_gzipped_shapefile_finds_its_prj_beside_it() {
        // Issue 47, K5: `a.shp.gz` did not find `a.prj`, and `-v` said there was none.
        use std::io::Write;
        let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/gis");
        let dir = tempfile::tempdir().unwrap();
        let shp = std::fs::read(data.join("sigma_27700.shp")).unwrap();
        let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        gz.write_all(&shp).unwrap();
        std::fs::write(dir.path().join("a.shp.gz"), gz.finish().unwrap()).unwrap();
        std::fs::copy(data.join("sigma_27700.prj"), dir.path().join("a.prj")).unwrap();
        let path = dir.path().join("a.shp.gz");
        let read = crate::read_file(&path, &crate::ReadOptions::at_most(1000)).unwrap();
        assert!(read.crs.is_some_and(|c| c.wkt.is_some()), "{}", read.how);
        assert_eq!(read.how, "a Shapefile (its .prj read) (gzip)");
    }

    #[test]
    fn a_geojson_crs_that_cannot_be_read_is_an_error_not_dropped() {
        // Issue 47, K1: British-grid metres named by a versioned URN went out as RFC 7946.
        let named = |name: &str| {
            format!(
                r#"{{"type": "MultiPoint", "crs": {{"type": "name", "properties": {{"name": "{name}"}}}}, "coordinates": [[0, 0], [1, 0], [1, 1]]}}"#
            )
        };
        let read = |text: String| points(text.as_bytes(), "a.geojson", Reading::at_most(10));
        let crs = read(named("urn:ogc:def:crs:EPSG:6.6:27700")).unwrap().crs;
        assert_eq!(crs.and_then(|c| c.epsg), Some(27700));
        let err = read(named("ESRI:102100")).unwrap_err().to_string();
        assert!(
            err.starts_with("a.geojson: GeoJSON: the \"crs\" member names 'ESRI:102100'"),
            "{err}"
        );
    }
}
