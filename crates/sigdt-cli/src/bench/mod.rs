//! The benchmark machinery behind `sigdt bench` and `sigdt sweep`: every method on every
//! case of a labelled folder, side by side, written up as a Markdown report in the layout
//! of the paper's Table 2 with SVG charts.
//!
//! - `cases`: the cases a run asks for, read by the lab's `index.csv` reader;
//! - `csv`: the CSV of `results.csv` (and of the one `index.csv` column the lab skips);
//! - `suite`: a whole run, from the cases to the report's data;
//! - `runner` and `worker`: one worker process per (case, method), with a time limit;
//! - `overlap`: proximity-graph statistics and the graph-based ε of the labelled sets;
//! - `record`, `report`, `chart`: the results, the report (with `numbers.json`) and its
//!   charts.

pub mod cases;
pub mod chart;
mod csv;
pub mod overlap;
pub mod record;
pub mod report;
pub mod runner;
pub mod suite;
pub mod worker;
