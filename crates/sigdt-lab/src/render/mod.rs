//! Pictures of point sets, proximity graphs and reconstructions, as standalone SVG.
//!
//! - `svg`: [`render_svg`] draws the chosen [`Layers`] with [`RenderOptions`].
//! - `frame`: the page layout, and line widths and dot sizes from the point spacing;
//!   [`place`] gives its positions to pictures drawn elsewhere.
//! - `path`: compact path data (one `<path>` per layer) and edge chaining.
//! - `legend`: the legend and text escaping.
//! - [`palette`]: the colours, shared with the viewer and Python.

mod frame;
mod legend;
pub mod palette;
mod path;
mod svg;
#[cfg(test)]
mod tests;

pub use frame::place;
pub use legend::escape as escape_xml;
pub use svg::{render_svg, Layers, RenderOptions};
