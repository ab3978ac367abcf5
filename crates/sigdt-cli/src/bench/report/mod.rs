//! The benchmark report: Markdown tables after the paper's Table 2, a CSV file and SVG charts.

mod charts;
mod curve;
mod exact;
mod sections;
mod summary;
#[cfg(test)]
mod tests;
mod write;

pub use write::write_report;
