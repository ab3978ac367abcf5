//! GeoPackage (OGC 12-128r18): points read from a feature layer, results written as the
//! [`Layers`] `curves` and `left_out`. SQLite is compiled in (rusqlite's bundled build), so
//! nothing is needed on the machine; a file is read in place, and a result is built in
//! memory and handed over as bytes, so it is written atomically like every output.
//!
//! A geometry blob is the GeoPackage header (`GP`, version, flags, SRS id, optional
//! envelope) and well-known binary ([`wkb`](super::wkb)).

use std::path::Path;

use crate::text::quoted;
use anyhow::{anyhow, bail, Context, Result};
use rusqlite::{Connection, OpenFlags, OptionalExtension};
use sigdt::Point;

use super::crs::{Crs, WGS84_WKT};
use super::layers::Layers;
use super::wkb::read_vertices;

/// The first bytes of every SQLite database, so of every GeoPackage.
pub const MAGIC: &[u8] = b"SQLite format 3\0";

/// Points of a GeoPackage: which layer, its system, how they were read.
pub struct Read {
    /// Every vertex of every feature of the layer, in row order.
    pub points: Vec<Point>,
    /// The layer's system, if it has one.
    pub crs: Option<Crs>,
    /// The layer read.
    pub layer: String,
}

/// The points of the GeoPackage at `path` (`name` in messages): every vertex of every
/// feature of `layer`, or of the only feature layer, or of the only point layer, in
/// feature order; at most `max` of them.
pub fn read(path: &Path, name: &str, layer: Option<&str>, max: usize) -> Result<Read> {
    let flags = OpenFlags::SQLITE_OPEN_READ_ONLY | OpenFlags::SQLITE_OPEN_NO_MUTEX;
    let db = Connection::open_with_flags(path, flags)
        .with_context(|| format!("{name}: cannot open as a GeoPackage"))?;
    let sql_error = |e: rusqlite::Error| anyhow!("{name}: not a readable GeoPackage: {e}");
    let layers = feature_layers(&db).map_err(sql_error)?;
    let names = || layers.iter().map(|l| quoted(&l.table)).collect::<Vec<_>>().join(", ");
    let chosen = match layer {
        Some(wanted) => layers.iter().find(|l| l.table == wanted).ok_or_else(|| {
            anyhow!(
                "{name}: --layer: no feature layer {} (the layers: {})",
                quoted(wanted),
                names()
            )
        })?,
        None => {
            let points: Vec<_> = layers.iter().filter(|l| l.is_points()).collect();
            // An empty point layer beside others (sigdt's own `left_out` when nothing was left
            // out) is not what the user means to read.
            let has_rows = |l: &Layer| -> rusqlite::Result<bool> {
                let query = format!("SELECT EXISTS (SELECT 1 FROM {})", identifier(&l.table));
                db.query_row(&query, [], |row| row.get(0))
            };
            match (layers.as_slice(), points.as_slice()) {
                ([], _) => bail!("{name}: a GeoPackage without feature layers"),
                ([only], _) => only,
                (_, [only]) if has_rows(only).map_err(sql_error)? => *only,
                (_, [only]) => bail!(
                    "{name}: its only point layer, {}, is empty; choose one of its {} feature \
                     layers ({}) with --layer NAME",
                    quoted(&only.table),
                    layers.len(),
                    names()
                ),
                _ => bail!(
                    "{name}: a GeoPackage of {} feature layers ({}): choose one with --layer NAME",
                    layers.len(),
                    names()
                ),
            }
        }
    };
    let crs = match system(&db, chosen.srs_id) {
        Err(rusqlite::Error::QueryReturnedNoRows) => bail!(
            "{name}: layer {}: its srs_id {} has no row in gpkg_spatial_ref_sys, so its \
             coordinate system is unknown (add the row, or write the layer again with its system)",
            quoted(&chosen.table),
            chosen.srs_id
        ),
        found => found.map_err(sql_error)?,
    };
    // A feature view (the format allows them; GDAL writes them) has no rowid: its features
    // are numbered from 1 in the order the view gives them.
    let is_view: bool = db
        .query_row(
            "SELECT EXISTS (SELECT 1 FROM sqlite_master WHERE type = 'view' AND name = ?1)",
            [&chosen.table],
            |row| row.get(0),
        )
        .map_err(sql_error)?;
    let fid = if is_view { "NULL".to_string() } else { identifier("rowid") };
    let query =
        format!("SELECT {fid}, {} FROM {}", identifier(&chosen.column), identifier(&chosen.table));
    let mut statement = db.prepare(&query).map_err(sql_error)?;
    let mut rows = statement.query([]).map_err(sql_error)?;
    let mut points = Vec::new();
    let table = quoted(&chosen.table);
    let mut position = 0i64;
    while let Some(row) = rows.next().map_err(sql_error)? {
        position += 1;
        let fid: i64 = row.get::<_, Option<i64>>(0).map_err(sql_error)?.unwrap_or(position);
        let blob: Option<Vec<u8>> = row.get(1).map_err(|e| {
            anyhow!("{name}: layer {table}, feature {fid}: the geometry is not a blob ({e})")
        })?;
        let Some(blob) = blob else { continue };
        geometry_vertices(&blob, &mut points, max)
            .map_err(|why| anyhow!("{name}: layer {table}, feature {fid}: {why}"))?;
    }
    Ok(Read { points, crs, layer: chosen.table.clone() })
}

/// The layers of the GeoPackage at `path` that sigdt would not write itself (every table
/// but `curves`, `left_out` and the GeoPackage's own `gpkg_*` and `rtree_*` tables), so that
/// writing over it does not delete a user's layers; empty when `path` is not a readable
/// SQLite file (a file of another kind is the caller's to refuse or replace).
pub fn foreign_tables(path: &Path) -> Vec<String> {
    let flags = OpenFlags::SQLITE_OPEN_READ_ONLY | OpenFlags::SQLITE_OPEN_NO_MUTEX;
    let Ok(db) = Connection::open_with_flags(path, flags) else { return Vec::new() };
    let query = "SELECT name FROM sqlite_master WHERE type IN ('table', 'view') ORDER BY name";
    let names = db.prepare(query).and_then(|mut statement| {
        statement
            .query_map([], |row| row.get::<_, String>(0))?
            .collect::<rusqlite::Result<Vec<_>>>()
    });
    let ours = |name: &str| {
        matches!(name, "curves" | "left_out")
            || name.starts_with("gpkg_")
            || name.starts_with("rtree_")
            || name.starts_with("sqlite_")
    };
    names.unwrap_or_default().into_iter().filter(|name| !ours(name)).collect()
}

/// A feature layer of a GeoPackage.
struct Layer {
    table: String,
    column: String,
    geometry_type: String,
    srs_id: i64,
}

impl Layer {
    fn is_points(&self) -> bool {
        matches!(self.geometry_type.to_ascii_uppercase().as_str(), "POINT" | "MULTIPOINT")
    }
}

fn feature_layers(db: &Connection) -> rusqlite::Result<Vec<Layer>> {
    let mut statement = db.prepare(
        "SELECT table_name, column_name, geometry_type_name, srs_id FROM gpkg_geometry_columns \
         ORDER BY table_name",
    )?;
    let layers = statement.query_map([], |row| {
        Ok(Layer {
            table: row.get(0)?,
            column: row.get(1)?,
            geometry_type: row.get(2)?,
            srs_id: row.get(3)?,
        })
    })?;
    layers.collect()
}

/// The system of `srs_id`: none for the undefined ones (-1, 0); `QueryReturnedNoRows` when
/// `gpkg_spatial_ref_sys` has no row for it.
fn system(db: &Connection, srs_id: i64) -> rusqlite::Result<Option<Crs>> {
    if srs_id <= 0 {
        return Ok(None);
    }
    let row: Option<(String, i64, String)> = db
        .query_row(
            "SELECT organization, organization_coordsys_id, definition FROM gpkg_spatial_ref_sys \
             WHERE srs_id = ?1",
            [srs_id],
            |row| Ok((row.get(0)?, row.get(1)?, row.get(2)?)),
        )
        .optional()?;
    let Some(row) = row else {
        return Err(rusqlite::Error::QueryReturnedNoRows);
    };
    Ok(Some(row).map(|(organization, code, definition)| {
        let mut crs = match definition.trim() {
            "" | "undefined" => Crs { epsg: None, wkt: None },
            wkt => Crs::from_wkt(wkt),
        };
        if organization.eq_ignore_ascii_case("EPSG") {
            crs.epsg = u32::try_from(code).ok().filter(|&c| c > 0).or(crs.epsg);
        }
        crs
    }))
}

/// The vertices of a GeoPackage geometry blob (header, then WKB).
fn geometry_vertices(blob: &[u8], out: &mut Vec<Point>, max: usize) -> Result<(), String> {
    let [b'G', b'P', _version, flags, ..] = *blob else {
        return Err("the geometry is not a GeoPackage geometry (no 'GP' header)".into());
    };
    if flags & 0b0010_0000 != 0 {
        return Err("an extended GeoPackage geometry type, which sigdt does not read".into());
    }
    let envelope = match (flags >> 1) & 0b111 {
        0 => 0,
        1 => 32,
        2 | 3 => 48,
        4 => 64,
        e => return Err(format!("envelope code {e} in the geometry header (0 to 4 expected)")),
    };
    let start = 8 + envelope;
    let wkb = blob.get(start..).ok_or("the geometry ends inside its header")?;
    if flags & 0b1_0000 != 0 && wkb.is_empty() {
        return Ok(()); // An empty geometry.
    }
    read_vertices(wkb, out, max)
}

/// `name` as an SQL identifier.
fn identifier(name: &str) -> String {
    format!("\"{}\"", name.replace('"', "\"\""))
}

/// The GeoPackage of `layers` in the system `crs` (undefined when `None`), as bytes.
pub fn write(layers: &Layers, crs: Option<&Crs>) -> Result<Vec<u8>> {
    let mut db = Connection::open_in_memory()?;
    let (srs_id, organization, code, definition) = match crs {
        Some(Crs { epsg: Some(code), wkt }) => {
            let known = (*code == 4326).then_some(WGS84_WKT);
            let definition = wkt.as_deref().or(known).unwrap_or("undefined");
            (i64::from(*code), "EPSG", i64::from(*code), definition.to_string())
        }
        Some(Crs { epsg: None, wkt: Some(wkt) }) => (100_000, "NONE", 100_000, wkt.clone()),
        _ => (-1, "NONE", -1, "undefined".to_string()),
    };
    db.execute_batch(SCHEMA)?;
    db.execute(
        "INSERT INTO gpkg_spatial_ref_sys VALUES ('WGS 84 geodetic', 4326, 'EPSG', 4326, ?1, \
         'longitude/latitude coordinates in decimal degrees on the WGS 84 spheroid')",
        [WGS84_WKT],
    )?;
    if srs_id > 0 && srs_id != 4326 {
        db.execute(
            "INSERT INTO gpkg_spatial_ref_sys VALUES (?1, ?2, ?3, ?4, ?5, NULL)",
            rusqlite::params![crs.map(ToString::to_string), srs_id, organization, code, definition],
        )?;
    }
    let bounds =
        layers.curves.iter().map(|c| c.bounds).chain(
            layers.left_out.iter().map(|l| [l.point[0], l.point[1], l.point[0], l.point[1]]),
        );
    let all = bounds.fold(None, |acc: Option<[f64; 4]>, b| {
        Some(acc.map_or(b, |a| [a[0].min(b[0]), a[1].min(b[1]), a[2].max(b[2]), a[3].max(b[3])]))
    });
    for (table, kind) in [("curves", "GEOMETRY"), ("left_out", "POINT")] {
        let [x0, y0, x1, y1] = all.map_or([None; 4], |b| b.map(Some));
        db.execute(
            "INSERT INTO gpkg_contents (table_name, data_type, identifier, min_x, min_y, max_x, \
             max_y, srs_id) VALUES (?1, 'features', ?1, ?2, ?3, ?4, ?5, ?6)",
            rusqlite::params![table, x0, y0, x1, y1, srs_id],
        )?;
        db.execute(
            "INSERT INTO gpkg_geometry_columns VALUES (?1, 'geom', ?2, ?3, 0, 0)",
            rusqlite::params![table, kind, srs_id],
        )?;
    }
    let header = |srs: i64| {
        let mut blob = b"GP\0\x01".to_vec(); // version 0; flags: little-endian, no envelope
        blob.extend_from_slice(&(srs as i32).to_le_bytes());
        blob
    };
    {
        let run = &layers.run;
        let mut insert = db.prepare(
            "INSERT INTO curves (geom, kind, method, status, warning, diagnosis, vertices) \
             VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)",
        )?;
        for curve in &layers.curves {
            insert.execute(rusqlite::params![
                curve.wkb(header(srs_id)),
                curve.kind.name(),
                run.method,
                run.status,
                run.warning,
                run.diagnosis,
                curve.vertices as i64
            ])?;
        }
        let mut insert =
            db.prepare("INSERT INTO left_out (geom, row, reason) VALUES (?1, ?2, ?3)")?;
        for left in &layers.left_out {
            let mut w = super::wkb::Writer(header(srs_id));
            w.point(left.point);
            insert.execute(rusqlite::params![w.0, left.row as i64, left.reason])?;
        }
    }
    let bytes = db.serialize(rusqlite::MAIN_DB)?.to_vec();
    Ok(bytes)
}

/// The tables every GeoPackage has (with two of the three systems it must define; WGS 84 is
/// added with [`WGS84_WKT`]), and the two feature tables of a result.
const SCHEMA: &str = r#"
PRAGMA application_id = 1196444487;
PRAGMA user_version = 10400;
CREATE TABLE gpkg_spatial_ref_sys (
  srs_name TEXT NOT NULL, srs_id INTEGER PRIMARY KEY, organization TEXT NOT NULL,
  organization_coordsys_id INTEGER NOT NULL, definition TEXT NOT NULL, description TEXT);
INSERT INTO gpkg_spatial_ref_sys VALUES
  ('Undefined cartesian SRS', -1, 'NONE', -1, 'undefined', 'undefined cartesian coordinate reference system'),
  ('Undefined geographic SRS', 0, 'NONE', 0, 'undefined', 'undefined geographic coordinate reference system');
CREATE TABLE gpkg_contents (
  table_name TEXT NOT NULL PRIMARY KEY, data_type TEXT NOT NULL, identifier TEXT UNIQUE,
  description TEXT DEFAULT '',
  last_change DATETIME NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now')),
  min_x DOUBLE, min_y DOUBLE, max_x DOUBLE, max_y DOUBLE, srs_id INTEGER,
  CONSTRAINT fk_gc_r_srs_id FOREIGN KEY (srs_id) REFERENCES gpkg_spatial_ref_sys(srs_id));
CREATE TABLE gpkg_geometry_columns (
  table_name TEXT NOT NULL, column_name TEXT NOT NULL, geometry_type_name TEXT NOT NULL,
  srs_id INTEGER NOT NULL, z TINYINT NOT NULL, m TINYINT NOT NULL,
  CONSTRAINT pk_geom_cols PRIMARY KEY (table_name, column_name),
  CONSTRAINT fk_gc_tn FOREIGN KEY (table_name) REFERENCES gpkg_contents(table_name),
  CONSTRAINT fk_gc_srs FOREIGN KEY (srs_id) REFERENCES gpkg_spatial_ref_sys (srs_id));
CREATE TABLE curves (
  fid INTEGER PRIMARY KEY AUTOINCREMENT NOT NULL, geom GEOMETRY, kind TEXT, method TEXT,
  status TEXT, warning BOOLEAN, diagnosis TEXT, vertices INTEGER);
CREATE TABLE left_out (
  fid INTEGER PRIMARY KEY AUTOINCREMENT NOT NULL, geom POINT, row INTEGER, reason TEXT);
"#;
