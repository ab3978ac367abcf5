//! The benchmark report: Markdown tables after the paper's Table 2, a CSV file, the counts as
//! JSON and SVG charts.

mod charts;
mod curve;
mod exact;
mod numbers;
mod sections;
mod summary;
#[cfg(test)]
mod tests;
mod write;

pub use write::write_report;
