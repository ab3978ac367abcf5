//! Streaming readers: plain `x y` point files, Dey's `.gtn` files and `i j` edge files.

mod edges;
mod gtn;
pub(in crate::text) mod lines;
mod points;

pub use edges::{parse_edges, parse_edges_of, read_edges, read_edges_of};
pub use lines::{max_lines, quoted, too_many_lines, MAX_LINE};
pub use points::{
    is_header_name, parse_points, parse_points_at_most, read_points, read_points_at_most,
    wkt_geometry, PointFormat, WKT_GEOMETRIES,
};
