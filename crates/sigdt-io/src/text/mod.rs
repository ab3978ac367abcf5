//! Reading point and edge files, and writing results as text.
//!
//! - Readers stream line by line with bounded memory and report every problem as
//!   [`Error::Parse`](sigdt::Error::Parse) naming the file and the 1-based line.
//! - Writers give edge lists, ordered loops, WKT and GeoJSON ([`OutputFormat`]).

mod read;
mod write;

pub use read::{
    is_header_name, max_lines, parse_edges, parse_edges_of, parse_points, parse_points_at_most,
    quoted, read_edges, read_edges_of, read_points, read_points_at_most, too_many_lines,
    wkt_geometry, PointFormat, MAX_LINE, WKT_GEOMETRIES,
};
pub use write::{
    write_edges, write_reconstruction, write_reconstruction_lon_lat, write_reconstruction_with,
    OutputFormat, WriteOptions,
};
