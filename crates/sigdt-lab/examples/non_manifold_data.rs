//! Writes the `non-manifold` labelled folder ([`non_manifold_cases`]): seeded random drawings
//! with crossings, T-junctions and shared ends, sampled with shared junction vertices.
//!
//! ```text
//! cargo run --release -p sigdt-lab --example non_manifold_data [-- OUT_DIR]
//! ```
//!
//! `OUT_DIR` defaults to the repository's `data/non-manifold` (`make data-non-manifold`). Per
//! case it writes `NAME.svg` (the drawing), `NAME.xy` (the samples, in a seeded random order)
//! and `NAME.gt` (the ground-truth graph), and `index.csv` with the counts of each junction
//! kind. The test `non_manifold_data_is_generated` checks the folder against the generator.
use std::path::PathBuf;

use sigdt_lab::curves::{folder_files, non_manifold_cases, PER_KIND};
use sigdt_lab::dataset::data_dir;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args().nth(1).map_or_else(|| data_dir("non-manifold"), PathBuf::from);
    std::fs::create_dir_all(&out)?;
    let cases = non_manifold_cases(PER_KIND)?;
    for (name, text) in folder_files(&cases) {
        std::fs::write(out.join(name), text)?;
    }
    println!("wrote {} cases to {}", cases.len(), out.display());
    Ok(())
}
