//! GeoPackage output: a result's four [`Layers`] as tables, each declared with its geometry
//! type (empty ones included) and its columns (the groups' attributes, then sigdt's own),
//! built in memory and handed over as bytes.

use anyhow::Result;
use rusqlite::{Connection, ToSql};

use super::identifier;
use crate::attributes::{ColumnType, Value};
use crate::gis::crs::{Crs, WGS84_WKT};
use crate::gis::layers::{Group, Layer, Layers};
use crate::gis::wkb::Writer;

/// The GeoPackage of `layers` in the system `crs` (undefined when `None`), as bytes: the four
/// tables of [`Layer::ALL`], each declared with its geometry type, empty ones included.
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
    let group_columns: Vec<String> = layers
        .columns
        .iter()
        .map(|c| {
            let kind = match c.kind {
                ColumnType::Text => "TEXT",
                ColumnType::Integer => "INTEGER",
                ColumnType::Real => "REAL",
                ColumnType::Bool => "BOOLEAN",
            };
            format!("{} {kind}", identifier(&c.name))
        })
        .collect();
    for layer in Layer::ALL {
        let own = match layer {
            Layer::LeftOut => "row INTEGER, reason TEXT",
            _ => "method TEXT, status TEXT, warning BOOLEAN, diagnosis TEXT, vertices INTEGER",
        };
        let columns: Vec<&str> = group_columns.iter().map(String::as_str).chain([own]).collect();
        db.execute_batch(&format!(
            "CREATE TABLE {} (fid INTEGER PRIMARY KEY AUTOINCREMENT NOT NULL, geom {}, {});",
            layer.name(),
            layer.geometry_type(),
            columns.join(", ")
        ))?;
        let [x0, y0, x1, y1] = layers.bounds(layer).map_or([None; 4], |b| b.map(Some));
        db.execute(
            "INSERT INTO gpkg_contents (table_name, data_type, identifier, min_x, min_y, max_x, \
             max_y, srs_id) VALUES (?1, 'features', ?1, ?2, ?3, ?4, ?5, ?6)",
            rusqlite::params![layer.name(), x0, y0, x1, y1, srs_id],
        )?;
        db.execute(
            "INSERT INTO gpkg_geometry_columns VALUES (?1, 'geom', ?2, ?3, 0, 0)",
            rusqlite::params![layer.name(), layer.geometry_type(), srs_id],
        )?;
    }
    // Version 0; flags: little-endian, no envelope, and empty for a geometry without points.
    let header = |empty: bool| {
        let mut blob = vec![b'G', b'P', 0, if empty { 0b1_0001 } else { 0b1 }];
        blob.extend_from_slice(&(srs_id as i32).to_le_bytes());
        Writer(blob)
    };
    let names: Vec<String> = layers.columns.iter().map(|c| identifier(&c.name)).collect();
    let insert = |table: &str, own: &[&str]| {
        let columns: Vec<&str> = std::iter::once("geom")
            .chain(names.iter().map(String::as_str))
            .chain(own.iter().copied())
            .collect();
        let marks: Vec<String> = (1..=columns.len()).map(|k| format!("?{k}")).collect();
        format!("INSERT INTO {table} ({}) VALUES ({})", columns.join(", "), marks.join(", "))
    };
    let tx = db.transaction()?;
    {
        let run_columns = ["method", "status", "warning", "diagnosis", "vertices"];
        let mut areas = tx.prepare(&insert("areas", &run_columns))?;
        for feature in &layers.areas {
            let mut w = header(feature.polygons.is_empty());
            w.multi_polygon(&feature.polygons);
            let values = row(w.0, &layers.groups[feature.group], Some(feature.vertices));
            areas.execute(rusqlite::params_from_iter(values))?;
        }
        for (table, features) in [("paths", &layers.paths), ("networks", &layers.networks)] {
            let mut lines = tx.prepare(&insert(table, &run_columns))?;
            for feature in features {
                let mut w = header(feature.lines.is_empty());
                w.multi_line_string(&feature.lines);
                let values = row(w.0, &layers.groups[feature.group], Some(feature.vertices));
                lines.execute(rusqlite::params_from_iter(values))?;
            }
        }
        let mut left_out = tx.prepare(&insert("left_out", &["row", "reason"]))?;
        for left in &layers.left_out {
            let mut w = header(false);
            w.point(left.point);
            let mut values = row(w.0, &layers.groups[left.group], None);
            values.push(Box::new(left.row as i64));
            values.push(Box::new(left.reason));
            left_out.execute(rusqlite::params_from_iter(values))?;
        }
    }
    tx.commit()?;
    let bytes = db.serialize(rusqlite::MAIN_DB)?.to_vec();
    Ok(bytes)
}

/// The values of one feature: its geometry, its group's attributes, and (for `vertices`
/// given) the run's columns.
fn row(geometry: Vec<u8>, group: &Group, vertices: Option<usize>) -> Vec<Box<dyn ToSql>> {
    let mut values: Vec<Box<dyn ToSql>> = vec![Box::new(geometry)];
    for value in &group.values {
        values.push(match value {
            Value::Null => Box::new(rusqlite::types::Null),
            Value::Text(text) => Box::new(text.clone()),
            Value::Integer(n) => Box::new(*n),
            Value::Real(x) => Box::new(*x),
            Value::Bool(b) => Box::new(*b),
        });
    }
    if let Some(vertices) = vertices {
        let run = &group.run;
        values.push(Box::new(run.method.clone()));
        values.push(Box::new(run.status));
        values.push(Box::new(run.warning));
        values.push(Box::new(run.diagnosis.clone()));
        values.push(Box::new(vertices as i64));
    }
    values
}

/// The tables every GeoPackage has (with two of the three systems it must define; WGS 84 is
/// added with [`WGS84_WKT`]); the feature tables of a result are created by [`write()`].
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
"#;
