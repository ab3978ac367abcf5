//! GeoPackage (OGC 12-128r18): points read from a feature layer (with its attributes for
//! `--by`), results written as the [`Layers`](super::layers::Layers) `areas`, `paths`,
//! `networks` and `left_out` ([`write()`]). SQLite is compiled in (rusqlite's bundled build),
//! so nothing is needed on the machine; a file is read in place, and a result is built in
//! memory and handed over as bytes, so it is written atomically like every output.
//!
//! A geometry blob is the GeoPackage header (`GP`, version, flags, SRS id, optional
//! envelope) and well-known binary ([`wkb`](super::wkb)).

use std::path::Path;

use crate::text::quoted;
use anyhow::{anyhow, bail, Context, Result};
use rusqlite::types::ValueRef;
use rusqlite::{Connection, OptionalExtension};
use sigdt::Point;

use super::crs::Crs;
use super::layers::Layer;
use super::wkb::read_vertices;
use crate::attributes::{Column, ColumnType, Grouping, Value};

pub mod budget;
#[cfg(test)]
mod hostile_tests;
mod write;

use budget::Budgeted;
pub use budget::Limits;

pub use write::write;

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
    /// The points grouped by a column of the layer (`--by`), each feature's other columns
    /// its attributes.
    pub grouping: Option<Grouping>,
}

/// The points of the GeoPackage at `path` (`name` in messages): every vertex of every
/// feature of `layer`, or of the only feature layer, or of the only point layer, in
/// feature order; at most `max` of them.
pub fn read(path: &Path, name: &str, layer: Option<&str>, max: usize) -> Result<Read> {
    read_grouped(path, name, layer, max, None)
}

/// [`read`], the points grouped `by` a column of the layer when given: its other columns
/// (but the feature id and BLOBs) are the attributes.
pub fn read_grouped(
    path: &Path,
    name: &str,
    layer: Option<&str>,
    max: usize,
    by: Option<&str>,
) -> Result<Read> {
    read_on_budget(path, name, layer, max, by, Limits::default())
}

/// [`read`] on the query budget `limits` ([`budget`]): for the fuzz target, whose files
/// must fail fast.
#[doc(hidden)]
pub fn read_on_budget(
    path: &Path,
    name: &str,
    layer: Option<&str>,
    max: usize,
    by: Option<&str>,
    limits: Limits,
) -> Result<Read> {
    let budget = Budgeted::open_with(path, limits)
        .with_context(|| format!("{name}: cannot open as a GeoPackage"))?;
    let db = &budget.db;
    // A query the budget stopped says which table and which budget; others are SQLite's.
    let failed = |table: &str| query_error(&budget, name, table);
    let sql_error = failed("gpkg_geometry_columns");
    budget.row();
    let layers = feature_layers(db).map_err(|e| match e {
        rusqlite::Error::InvalidQuery => anyhow!(
            "{name}: gpkg_geometry_columns lists more than {MAX_LAYERS} layers (an endless view?)"
        ),
        e => sql_error(e),
    })?;
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
            let has_rows = |l: &FeatureTable| -> Result<bool> {
                let query = format!("SELECT EXISTS (SELECT 1 FROM {})", identifier(&l.table));
                budget.row();
                db.query_row(&query, [], |row| row.get(0)).map_err(failed(&l.table))
            };
            match (layers.as_slice(), points.as_slice()) {
                ([], _) => bail!("{name}: a GeoPackage without feature layers"),
                ([only], _) => only,
                (_, [only]) if has_rows(only)? => *only,
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
    budget.row();
    let crs = match system(db, chosen.srs_id) {
        Err(rusqlite::Error::QueryReturnedNoRows) => bail!(
            "{name}: layer {}: its srs_id {} has no row in gpkg_spatial_ref_sys, so its \
             coordinate system is unknown (add the row, or write the layer again with its system)",
            quoted(&chosen.table),
            chosen.srs_id
        ),
        found => found.map_err(failed("gpkg_spatial_ref_sys"))?,
    };
    let sql_error = failed(&chosen.table);
    // A feature view (the format allows them; GDAL writes them) has no rowid: its features
    // are numbered from 1 in the order the view gives them.
    let is_view: bool = db
        .query_row(
            "SELECT EXISTS (SELECT 1 FROM sqlite_master WHERE type = 'view' AND name = ?1)",
            [&chosen.table],
            |row| row.get(0),
        )
        .map_err(&sql_error)?;
    let fid = if is_view { "NULL".to_string() } else { identifier("rowid") };
    let table = quoted(&chosen.table);
    let mut grouping = match by {
        None => None,
        Some(by) => {
            let columns = attribute_columns(db, chosen).map_err(&sql_error)?;
            let shown = format!("{name}: layer {table}");
            Some(Grouping::new(columns, by, &shown).map_err(|m| anyhow!(m))?)
        }
    };
    let attributes: Vec<String> = grouping
        .iter()
        .flat_map(|g| g.columns.iter().map(|c| format!(", {}", identifier(&c.name))))
        .collect();
    let query = format!(
        "SELECT {fid}, {}{} FROM {}",
        identifier(&chosen.column),
        attributes.concat(),
        identifier(&chosen.table)
    );
    let mut statement = db.prepare(&query).map_err(&sql_error)?;
    budget.row();
    let mut rows = statement.query([]).map_err(&sql_error)?;
    let mut points = Vec::new();
    let mut position = 0i64;
    // Rows without a point count against --max-points too, so that an endless view of rows
    // without geometry stops (M2).
    let mut empty_rows = 0usize;
    while let Some(row) = rows.next().map_err(&sql_error)? {
        budget.row();
        position += 1;
        let fid: i64 = row.get::<_, Option<i64>>(0).map_err(&sql_error)?.unwrap_or(position);
        let blob: Option<Vec<u8>> = row.get(1).map_err(|e| {
            // rusqlite names the column as the file spells it: escaped like any reason.
            anyhow!(
                "{name}: layer {table}, feature {fid}: the geometry is not a blob ({})",
                reason(&e)
            )
        })?;
        let before = points.len();
        if let Some(blob) = &blob {
            geometry_vertices(blob, &mut points, max.saturating_sub(empty_rows))
                .map_err(|why| anyhow!("{name}: layer {table}, feature {fid}: {why}"))?;
        }
        if points.len() == before {
            empty_rows += 1;
            if points.len() + empty_rows > max {
                bail!(
                    "{name}: layer {table}: more than {max} points and rows without one \
                     (--max-points {max}); is the layer an endless view?"
                );
            }
            if blob.is_none() {
                continue;
            }
        }
        if let Some(grouping) = &mut grouping {
            let values = (0..grouping.columns.len())
                .map(|c| value(row.get_ref(2 + c)?, grouping.columns[c].kind))
                .collect::<rusqlite::Result<Vec<Value>>>()
                .map_err(&sql_error)?;
            grouping.add(values, points.len() - before);
        }
    }
    Ok(Read { points, crs, layer: chosen.table.clone(), grouping })
}

/// What a failed query on `table` says: the budget that stopped it, or SQLite's error.
fn query_error<'a>(
    budget: &'a Budgeted,
    name: &'a str,
    table: &str,
) -> impl Fn(rusqlite::Error) -> anyhow::Error + 'a {
    let table = quoted(table);
    move |e: rusqlite::Error| match budget.stopped(&e) {
        Some(stop) => anyhow!("{name}: reading {table}: {}", stop.explain(&budget.limits)),
        None => anyhow!("{name}: not a readable GeoPackage: {}", reason(&e)),
    }
}

/// The most characters of SQLite's reason a message shows.
const REASON_CHARS: usize = 200;

/// SQLite's reason for `e` as a message may show it: SQLite quotes the file's schema
/// ("malformed database schema (T) - unrecognized token: ..."), so control and other
/// invisible characters are escaped, as every reader escapes input, and it is cut after
/// [`REASON_CHARS`] characters (a fuzzed schema put a control character on the terminal).
fn reason(e: &rusqlite::Error) -> String {
    let text = e.to_string();
    let mut shown = String::new();
    for (k, c) in text.chars().enumerate() {
        if k == REASON_CHARS {
            shown.push_str("...");
            break;
        }
        match c {
            c if c.is_control() || c.is_whitespace() && c != ' ' => {
                shown.extend(c.escape_unicode())
            }
            c => shown.push(c),
        }
    }
    shown
}

/// The layers of the GeoPackage at `path` that sigdt would not write itself (every table
/// but those of [`Layer::ALL`], `curves` (which sigdt wrote before them) and the
/// GeoPackage's own `gpkg_*` and `rtree_*` tables), so that writing over it does not delete
/// a user's layers; empty when `path` is not a readable SQLite file (a file of another kind
/// is the caller's to refuse or replace).
pub fn foreign_tables(path: &Path) -> Vec<String> {
    let Ok(budget) = Budgeted::open(path) else { return Vec::new() };
    let db = &budget.db;
    let query = "SELECT name FROM sqlite_master WHERE type IN ('table', 'view') ORDER BY name";
    let names = db.prepare(query).and_then(|mut statement| {
        statement
            .query_map([], |row| row.get::<_, String>(0))?
            .collect::<rusqlite::Result<Vec<_>>>()
    });
    let ours = |name: &str| {
        name == "curves"
            || Layer::ALL.iter().any(|layer| layer.name() == name)
            || name.starts_with("gpkg_")
            || name.starts_with("rtree_")
            || name.starts_with("sqlite_")
    };
    names.unwrap_or_default().into_iter().filter(|name| !ours(name)).collect()
}

/// A feature layer of a GeoPackage.
struct FeatureTable {
    table: String,
    column: String,
    geometry_type: String,
    srs_id: i64,
}

impl FeatureTable {
    fn is_points(&self) -> bool {
        matches!(self.geometry_type.to_ascii_uppercase().as_str(), "POINT" | "MULTIPOINT")
    }
}

/// The most feature layers a GeoPackage may list: its list may be a view of any length.
const MAX_LAYERS: usize = 100_000;

fn feature_layers(db: &Connection) -> rusqlite::Result<Vec<FeatureTable>> {
    let mut statement = db.prepare(
        "SELECT table_name, column_name, geometry_type_name, srs_id FROM gpkg_geometry_columns \
         ORDER BY table_name",
    )?;
    let layers = statement.query_map([], |row| {
        Ok(FeatureTable {
            table: row.get(0)?,
            column: row.get(1)?,
            geometry_type: row.get(2)?,
            srs_id: row.get(3)?,
        })
    })?;
    let mut out = Vec::new();
    for layer in layers {
        if out.len() == MAX_LAYERS {
            return Err(rusqlite::Error::InvalidQuery); // read as "too many layers" below
        }
        out.push(layer?);
    }
    Ok(out)
}

/// The attribute columns of `layer`: every column but the geometry, the feature id (an
/// `INTEGER PRIMARY KEY`) and BLOBs, typed by their declared type (SQLite's affinity rules).
fn attribute_columns(db: &Connection, layer: &FeatureTable) -> rusqlite::Result<Vec<Column>> {
    let query = format!("PRAGMA table_info({})", identifier(&layer.table));
    let mut statement = db.prepare(&query)?;
    let columns = statement.query_map([], |row| {
        Ok((row.get::<_, String>(1)?, row.get::<_, String>(2)?, row.get::<_, i64>(5)?))
    })?;
    let mut kept = Vec::new();
    for column in columns {
        let (name, declared, pk) = column?;
        let declared = declared.to_ascii_uppercase();
        let is_id = pk > 0 && declared == "INTEGER";
        if name.eq_ignore_ascii_case(&layer.column) || is_id || declared.contains("BLOB") {
            continue;
        }
        let kind = if declared.contains("BOOL") {
            ColumnType::Bool
        } else if declared.contains("INT") {
            ColumnType::Integer
        } else if ["REAL", "FLOA", "DOUB"].iter().any(|t| declared.contains(t)) {
            ColumnType::Real
        } else {
            ColumnType::Text
        };
        kept.push(Column { name, kind });
    }
    Ok(kept)
}

/// An SQLite value of a column of type `kind` as an attribute (a BLOB as no value).
fn value(v: ValueRef<'_>, kind: ColumnType) -> rusqlite::Result<Value> {
    Ok(match v {
        ValueRef::Null | ValueRef::Blob(_) => Value::Null,
        ValueRef::Integer(n) if kind == ColumnType::Bool => Value::Bool(n != 0),
        ValueRef::Integer(n) => Value::Integer(n),
        ValueRef::Real(x) => Value::Real(x),
        ValueRef::Text(bytes) => Value::Text(String::from_utf8_lossy(bytes).into_owned()),
    })
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gis::layers::Layers;
    use sigdt::{Method, Options};

    #[test]
    fn four_tables_each_of_one_geometry_type_with_the_group_attributes() {
        let points = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let rec = sigdt::reconstruct(&points, &Options::default()).unwrap();
        let column = |name: &str, kind| Column { name: name.into(), kind };
        let mut layers = Layers::with_columns(vec![
            column("island", ColumnType::Text),
            column("status", ColumnType::Integer),
        ]);
        let values = vec![Value::Text("a".into()), Value::Integer(7)];
        layers.add(values, Method::SigAuto, &points, &rec, false, None);
        layers.add_failed(vec![Value::Null, Value::Null], Method::SigAuto, "no points".into());
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("o.gpkg");
        std::fs::write(&path, write(&layers, None).unwrap()).unwrap();
        let db = Connection::open(&path).unwrap();
        let mut types =
            db.prepare("SELECT table_name, geometry_type_name FROM gpkg_geometry_columns").unwrap();
        let types: Vec<(String, String)> = types
            .query_map([], |row| Ok((row.get(0)?, row.get(1)?)))
            .unwrap()
            .collect::<rusqlite::Result<_>>()
            .unwrap();
        let expected = [
            ("areas", "MULTIPOLYGON"),
            ("left_out", "POINT"),
            ("networks", "MULTILINESTRING"),
            ("paths", "MULTILINESTRING"),
        ];
        let mut types = types;
        types.sort();
        assert_eq!(types, expected.map(|(a, b)| (a.to_string(), b.to_string())));
        let query = "SELECT island, input_status, status, diagnosis, vertices, length(geom) \
                     FROM areas ORDER BY fid";
        let mut rows = db.prepare(query).unwrap();
        let rows: Vec<Vec<rusqlite::types::Value>> = rows
            .query_map([], |r| (0..6).map(|k| r.get(k)).collect())
            .unwrap()
            .collect::<rusqlite::Result<_>>()
            .unwrap();
        use rusqlite::types::Value as V;
        let text = |s: &str| V::Text(s.to_string());
        let island = [text("a"), V::Integer(7), text("polygon"), text(""), V::Integer(4)];
        assert_eq!(rows[0][..5], island);
        // The failed group: an empty multi-polygon (header and 9 bytes), the error.
        let failed = [V::Null, V::Null, text("error"), text("no points"), V::Integer(0)];
        assert_eq!((&rows[1][..5], &rows[1][5]), (&failed[..], &V::Integer(17)));
        // Read back: the square's vertices; the empty geometry has none.
        let read = read(&path, "o.gpkg", Some("areas"), 100).unwrap();
        assert_eq!(read.points.len(), 4);
    }
}
