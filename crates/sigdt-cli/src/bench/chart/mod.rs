//! Self-contained SVG charts for the benchmark report: no scripts, no external fonts.
//!
//! Every chart is 800 × 450 with a title, labelled axes with ticks, and a legend on the right.
//! Series are told apart by colour (a colour-blind-friendly palette of 12) and also by marker
//! shape and dash pattern (lines) or hatching (bars); box plots label each box, so they survive greyscale printing.

mod axis;
mod bars;
mod boxes;
mod svg;
mod xy;

pub use bars::grouped_bars;
pub use boxes::box_plots;
pub use xy::{line_chart, log_log_scatter};

#[cfg(test)]
pub(crate) use svg::assert_well_formed;
