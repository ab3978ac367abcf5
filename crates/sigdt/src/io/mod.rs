//! Reading point files and writing reconstructions (formats in `docs/formats.md`).
//!
//! - [`points`]: readers for plain `x y` point files, Dey's `.gtn` files and `i j` edge files.
//!   They stream line by line with bounded memory and report every problem as
//!   [`Error::Parse`](crate::Error::Parse) naming the file and the 1-based line. The line
//!   reader lives in `lines`, the `.gtn` format in `gtn` and the edge reader in `edges`.
//! - [`write`](mod@write): writers for edge lists, ordered loops, WKT, GeoJSON and SVG; the
//!   SVG picture is drawn by [`render_svg`](crate::render::render_svg).

mod edges;
mod gtn;
mod lines;
pub mod points;
pub mod write;

pub use points::{
    parse_edges, parse_points, parse_points_at_most, read_edges, read_points, read_points_at_most,
    PointFormat, MAX_LINE,
};
pub use write::{write_edges, write_reconstruction, OutputFormat};
