//! Reading points and writing outlines the way GIS users hold them, for any Rust program:
//! the readers and writers of the `sigdt` command line and Python package.
//!
//! - [`text`]: sigdt's own text formats: plain `x y` point files and `.gtn` read line by
//!   line, edge lists, and results written as edges, loops, WKT and GeoJSON.
//! - [`read`]: any point file, its format found from the bytes and the name: those of
//!   [`text`], CSV and other tables with chosen columns, WKT, GeoJSON, NumPy `.npy`, each
//!   also gzip-compressed, and the GIS formats of [`gis`].
//! - [`gis`]: GeoPackage, FlatGeobuf and Shapefile points in, GeoPackage and FlatGeobuf
//!   layers out, the coordinate system carried from one to the other, and longitude and
//!   latitude reconstructed in a local plane ([`reconstruct_in_plane`]) and cut at the
//!   antimeridian.
//! - [`attributes`]: points grouped by an attribute as they are read (`--by`), from a
//!   GeoPackage layer, a Shapefile's `.dbf`, a FlatGeobuf file or a table.
//!
//! Every reader validates at the entry: it stops at `max_points` before it allocates for
//! more, trusts no size a file announces before its bytes arrive, and names the file (and
//! line, where there is one) in every error.
//!
//! ```
//! use sigdt_io::{read_file, ReadOptions};
//!
//! let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/gis/islands_4326.gpkg");
//! let read = read_file(path.as_ref(), &ReadOptions::at_most(1_000_000))?;
//! assert_eq!(read.crs.as_ref().and_then(|crs| crs.epsg), Some(4326));
//! // Degrees: reconstructed in a local plane, so that lengths are ground lengths.
//! let outlines = read.reconstruct(&sigdt::Options::default())?;
//! assert!(outlines.loops.len() > 1);
//! # Ok::<(), anyhow::Error>(())
//! ```
//!
//! `examples/outlines.rs` writes the outlines of a GeoPackage's points as a GeoPackage in
//! their coordinate system.
pub mod attributes;
pub mod cancel;
pub mod gis;
pub mod read;
mod stream;
pub mod text;

use std::fmt;
use std::io::Read;
use std::path::Path;

pub use gis::local::reconstruct_in_plane;
pub use gis::Crs;
pub use read::{Columns, Points, Reading};
use sigdt::Point;

/// A request that does not fit the file read: `layer` for a format without layers, or
/// `columns` for one without columns. The caller's usage is wrong, not the file (the
/// command line exits with status 2 for it).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Misuse {
    /// What does not fit, naming the option and the file.
    pub message: String,
}

impl fmt::Display for Misuse {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Misuse {}

/// Why reading points failed, so that a caller can tell its user what to change.
#[derive(Debug)]
pub enum Error {
    /// The file cannot be opened or read (`sigdt::Error::Io`).
    Io(sigdt::Error),
    /// The request does not fit the file ([`Misuse`]) or is not understood (bad `columns`).
    Usage(String),
    /// The file's content is not points: the message names the file (and line).
    Data(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Io(err) => err.fmt(f),
            Error::Usage(message) | Error::Data(message) => f.write_str(message),
        }
    }
}

impl std::error::Error for Error {}

impl From<anyhow::Error> for Error {
    fn from(err: anyhow::Error) -> Error {
        if let Some(misuse) = err.downcast_ref::<Misuse>() {
            return Error::Usage(misuse.message.clone());
        }
        match err.downcast::<sigdt::Error>() {
            Ok(io @ sigdt::Error::Io { .. }) => Error::Io(io),
            Ok(other) => Error::Data(other.to_string()),
            Err(err) => Error::Data(one_line(&err)),
        }
    }
}

/// The one-line message for `err`: its own text, then each cause whose text it does not
/// already contain, all on one line.
pub fn one_line(err: &anyhow::Error) -> String {
    let mut text = err.to_string();
    for cause in err.chain().skip(1) {
        let cause = cause.to_string();
        if !text.contains(&cause) {
            text.push_str(": ");
            text.push_str(&cause);
        }
    }
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// How to read a point file: the most points to accept, a table's columns, a GeoPackage's
/// layer, and the coordinate system of input that declares none.
#[derive(Debug, Clone)]
pub struct ReadOptions {
    /// Reading stops with an error after this many points.
    pub max_points: usize,
    /// The x and y columns of a table.
    pub columns: Option<Columns>,
    /// The layer of a GeoPackage.
    pub layer: Option<String>,
    /// The coordinate system of input that does not declare one (a declared one that
    /// differs is an error: sigdt does not transform coordinates).
    pub crs: Option<Crs>,
    /// Group the points by this attribute column ([`attributes`]), from a GeoPackage layer,
    /// a Shapefile's `.dbf`, a FlatGeobuf file's columns or a table's other columns.
    pub by: Option<String>,
}

impl ReadOptions {
    /// At most `max_points` points, in the file's own columns, layer and system.
    pub fn at_most(max_points: usize) -> ReadOptions {
        ReadOptions { max_points, columns: None, layer: None, crs: None, by: None }
    }

    fn reading<'a>(&'a self, path: Option<&'a Path>) -> Reading<'a> {
        let (columns, layer) = (self.columns.as_ref(), self.layer.as_deref());
        Reading { max_points: self.max_points, columns, layer, path, by: self.by.as_deref() }
    }
}

impl Points {
    /// The reconstruction of these points with `options`: in their local plane when they
    /// are longitude and latitude (their system says so, or a table's columns are named so;
    /// [`reconstruct_in_plane`]), else in their own coordinates. The indices refer to
    /// [`Points::points`], as always.
    pub fn reconstruct(&self, options: &sigdt::Options) -> anyhow::Result<sigdt::Reconstruction> {
        match gis::local::why_degrees(self.crs.as_ref(), self.lon_lat) {
            Some(why) => reconstruct_in_plane(&self.points, options, &why),
            None => Ok(sigdt::reconstruct(&self.points, options)?),
        }
    }
}

/// The points of the file at `path` in any format of [`read`], how they were read, and
/// their coordinate system.
pub fn read_file(path: &Path, options: &ReadOptions) -> anyhow::Result<Points> {
    let name = path.display().to_string();
    let file = std::fs::File::open(path)
        .map_err(|source| sigdt::Error::Io { path: name.clone(), source })?;
    let read = read::points(file, &name, options.reading(Some(path)))?;
    with_given_crs(read, &name, options.crs.as_ref())
}

/// [`read_file`] of a stream named `name` in errors (`<stdin>`, say): no GeoPackage
/// (SQLite reads a file in place) and no Shapefile `.prj`.
pub fn read_stream(reader: impl Read, name: &str, options: &ReadOptions) -> anyhow::Result<Points> {
    let read = read::points(reader, name, options.reading(None))?;
    with_given_crs(read, name, options.crs.as_ref())
}

/// `read` with the coordinate system `given` where the file declares none or declares one
/// without a code; a different declared code is an error.
fn with_given_crs(mut read: Points, name: &str, given: Option<&Crs>) -> anyhow::Result<Points> {
    match (&read.crs, given) {
        (Some(declared), Some(given)) if declared.epsg.is_some() && declared.epsg != given.epsg => {
            anyhow::bail!(
                "{name} is in {declared}, but --crs says {given}: sigdt does not transform \
                 coordinates (reproject the file, or drop --crs)"
            );
        }
        (None, Some(given)) => read.crs = Some(given.clone()),
        // A definition without a code (an ESRI .prj): the given system names it, unless one
        // is geographic and the other projected.
        (Some(declared), Some(given)) if declared.epsg.is_none() => {
            let kind = |geographic: Option<bool>| match geographic {
                Some(true) => "longitude/latitude",
                Some(false) => "a projected system",
                None => "unknown",
            };
            let (theirs, ours) = (declared.is_geographic(), given.is_geographic());
            if theirs.is_some() && ours.is_some() && theirs != ours {
                anyhow::bail!(
                    "{name} declares {}, but --crs says {given}, which is {}: sigdt does not \
                     transform coordinates (give the file's own code, or drop --crs)",
                    kind(theirs),
                    kind(ours)
                );
            }
            read.crs = Some(Crs { epsg: given.epsg, wkt: declared.wkt.clone() });
        }
        _ => {}
    }
    Ok(read)
}

/// The points of the file at `path` in any format of [`read`] (with `columns` as
/// `--columns` spells them, `layer` of a GeoPackage, and at most `max_points`): the
/// Python package's `read_points`.
pub fn read_points_file(
    path: &Path,
    columns: Option<&str>,
    layer: Option<&str>,
    max_points: usize,
) -> Result<Vec<Point>, Error> {
    let options = ReadOptions {
        columns: parse_columns(columns)?,
        layer: layer.map(str::to_string),
        ..ReadOptions::at_most(max_points)
    };
    Ok(read_file(path, &options)?.points)
}

/// The points of the GeoPackage `bytes` named `name` (written to a temporary file, since
/// SQLite reads files), on a small query budget (10⁷ SQLite steps between rows, 64 MiB):
/// for the fuzz target of the GeoPackage reader.
#[doc(hidden)]
pub fn read_geopackage_bytes(
    bytes: &[u8],
    name: &str,
    max_points: usize,
) -> Result<Vec<Point>, Error> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let k = NEXT.fetch_add(1, Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!("sigdt-fuzz-{}-{k}.gpkg", std::process::id()));
    std::fs::write(&path, bytes).map_err(|e| Error::Data(format!("{name}: {e}")))?;
    let limits = gis::gpkg::Limits { steps_per_row: 10_000_000, memory: 64 << 20 };
    let read = gis::gpkg::read_on_budget(&path, name, None, max_points, None, limits);
    let _ = std::fs::remove_file(&path);
    Ok(read?.points)
}

/// [`read_points_file`] of `bytes` named `name` (whose extension chooses the reader as a
/// file's would): for the fuzz targets of the readers.
#[doc(hidden)]
pub fn read_points_bytes(
    bytes: &[u8],
    name: &str,
    columns: Option<&str>,
    max_points: usize,
) -> Result<Vec<Point>, Error> {
    let columns = parse_columns(columns)?;
    let how = Reading { columns: columns.as_ref(), ..Reading::at_most(max_points) };
    Ok(read::points(bytes, name, how)?.points)
}

/// `columns` as `--columns` spells them.
fn parse_columns(columns: Option<&str>) -> Result<Option<Columns>, Error> {
    columns.map(|text| text.parse().map_err(|m| Error::Usage(format!("columns: {m}")))).transpose()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_projected_prj_is_not_named_longitude_latitude() {
        // Issue 47, K3: a projected .prj with --crs EPSG:4326 was accepted, and metres went
        // out as RFC 7946 GeoJSON labelled WGS 84.
        let shp = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/gis/sigma_27700.shp");
        let given =
            |code| ReadOptions { crs: Some(Crs::epsg(code)), ..ReadOptions::at_most(10_000) };
        let err = read_file(&shp, &given(4326)).unwrap_err().to_string();
        assert!(err.contains("declares a projected system, but --crs says EPSG:4326"), "{err}");
        let read = read_file(&shp, &given(27700)).unwrap();
        assert_eq!(read.crs.map(|c| (c.epsg, c.wkt.is_some())), Some((Some(27700), true)));
    }
}
