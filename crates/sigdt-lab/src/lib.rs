//! # sigdt-lab: the evaluation harness around the `sigdt` kernel
//!
//! What a researcher needs beside the reconstruction itself, kept out of the kernel so that
//! users of `sigdt` compile none of it:
//!
//! - [`eval`]: metrics against ground truth (exactness, graph-based ε, RMSE and Hausdorff
//!   distance, symmetric area difference, proximity-graph overlap);
//! - [`curves`]: the research samplers (cubic Bézier paths from SVG files and their
//!   ε-sampling, the sampler of the paper's Bézier experiment);
//! - [`render`]: SVG pictures of points, graphs and results;
//! - [`dataset`]: the labelled folders (`index.csv`, `NAME.xy`, `NAME.gt`) of `data/`.
//!
//! The lab depends on the kernel, never the reverse.

#![forbid(unsafe_code)]

pub mod curves;
pub mod dataset;
pub mod eval;
mod power_of_two;
pub mod render;
