//! How the sampling check (`Reconstruction::diagnosis`) separates right results from wrong
//! ones: per category, exact results with and without a warning, and wrong results with and
//! without one (a wrong result without a warning is a *silent wrong* answer).
//!
//! ```text
//! cargo run --release -p sigdt-lab --example sampling_check [-- DATA_DIR ...]
//! ```
//!
//! Runs SIG-CONNECT2D and SIG-AUTO on every case of each labelled folder (default the
//! repository's `data/curves` and `data/real`) and prints one table per folder and method,
//! then the cases that are exact but warned (false alarms) with their findings.
use sigdt::{reconstruct_on, Method, Options, Triangulation};
use sigdt_lab::dataset::{data_dir, read_index};
use sigdt_lab::eval::is_exact;
use std::collections::BTreeMap;
use std::error::Error;
use std::path::PathBuf;

/// Counts of one category: exact and warned, exact and quiet, wrong and warned, wrong and
/// quiet.
#[derive(Default)]
struct Counts([usize; 4]);

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    let dirs = if args.is_empty() { vec![data_dir("curves"), data_dir("real")] } else { args };
    for dir in dirs {
        let cases = read_index(&dir)?;
        for method in [Method::SigConnect2d, Method::SigAuto] {
            let options = Options { method, ..Options::default() };
            let mut by_category: BTreeMap<String, Counts> = BTreeMap::new();
            let mut false_alarms = Vec::new();
            for case in &cases {
                let (points, truth) = case.read(&dir)?;
                let dt = Triangulation::new(&points)?;
                let rec = reconstruct_on(&dt, &options);
                let exact = is_exact(&rec.edges, &truth);
                let slot = 2 * usize::from(!exact) + usize::from(!rec.warns());
                by_category.entry(case.category.clone()).or_default().0[slot] += 1;
                if exact && rec.warns() {
                    let found: Vec<String> = rec.diagnosis.iter().map(|f| f.to_string()).collect();
                    false_alarms.push(format!(
                        "{} [{}]: {}",
                        case.name,
                        rec.status.name(),
                        found.join("; ")
                    ));
                }
            }
            println!("\n{} — {method}\n", dir.display());
            println!("| category | exact, warned | exact, quiet | wrong, warned | wrong, silent |");
            println!("|---|--:|--:|--:|--:|");
            for (category, Counts(c)) in &by_category {
                println!("| {category} | {} | {} | {} | {} |", c[0], c[1], c[2], c[3]);
            }
            for line in false_alarms {
                println!("  false alarm: {line}");
            }
        }
    }
    Ok(())
}
