//! Geographic information systems' formats and coordinate systems: GeoPackage, FlatGeobuf
//! and Shapefile points in, GeoPackage and FlatGeobuf layers out, and the coordinate
//! reference system carried from one to the other.

pub mod antimeridian;
pub mod crs;
pub mod dbf;
pub mod fgb;
mod geographic_codes;
pub mod gpkg;
pub mod layers;
pub mod local;
pub mod outlines;
pub mod seam;
pub mod shp;
pub mod wkb;

pub use crs::Crs;
