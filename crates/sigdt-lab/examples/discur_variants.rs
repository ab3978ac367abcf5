//! DISCUR's exact-reconstruction rates for each reading of the unknowns of its
//! reconstruction (`docs/algorithms.md` §3.9), against the paper's row of Table 2.
//!
//! ```text
//! cargo run --release -p sigdt-lab --example discur_variants [-- DATA_DIR ...]
//! ```
//!
//! For every labelled folder (default the repository's `data/curves` and `data/real`:
//! `index.csv`, `NAME.xy`, `NAME.gt`) it prints one table: a row per variant (through the
//! hidden `discur_variant`), exact cases and percentage per category, plus the manifold
//! cases with `epsilon < 1`. The switches: `and` tests the criterion at both curve ends
//! instead of either (`or`); `2nn` removes a point's edges once two of them have been
//! processed, `c2` once it is inside a curve; `close-and` closes a curve only when both its
//! ends accept. The row marked `*` is what `Method::Discur` runs. Then, per folder, how many
//! points the default leaves without an edge, by category.
use sigdt::internals::{discur_variant, DiscurVariant};
use sigdt::Triangulation;
use sigdt_lab::dataset::{data_dir, read_index, ExactTally};
use sigdt_lab::eval::is_exact;
use std::collections::BTreeMap;
use std::error::Error;
use std::path::PathBuf;

/// [MOW22] Table 2, DISCUR: manifold, sharp, open, multiple, manifold ε < 1.
const PAPER: [(&str, f64); 5] = [
    ("manifold", 49.0),
    ("sharp", 17.0),
    ("open", 39.1),
    ("multiple", 46.2),
    ("manifold eps<1", 50.7),
];
const COLUMNS: [&str; 8] =
    ["manifold", "sharp", "open", "multiple", "manifold eps<1", "noisy", "outliers", "bezier"];

fn variants() -> Vec<(String, DiscurVariant)> {
    let mut all = Vec::new();
    for both_ends in [false, true] {
        for two_processed in [false, true] {
            for close_both_ends in [false, true] {
                if both_ends && close_both_ends {
                    continue; // the same as without: both ends already decide
                }
                let v = DiscurVariant { both_ends, two_processed, close_both_ends };
                let mark = if v == DiscurVariant::DEFAULT { " *" } else { "" };
                let name = format!(
                    "{} {}{}{mark}",
                    if both_ends { "and" } else { "or" },
                    if two_processed { "2nn" } else { "c2" },
                    if close_both_ends { " close-and" } else { "" }
                );
                all.push((name, v));
            }
        }
    }
    all
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    let dirs = if args.is_empty() { vec![data_dir("curves"), data_dir("real")] } else { args };
    let variants = variants();
    for dir in dirs {
        let mut tally = ExactTally::default();
        // Per category: points, points without an edge (default variant, duplicates aside).
        let mut free: BTreeMap<String, (usize, usize)> = BTreeMap::new();
        for case in read_index(&dir)? {
            let (points, truth) = case.read(&dir)?;
            let dt = Triangulation::new(&points)?;
            let results: Vec<_> = variants.iter().map(|(_, v)| discur_variant(&dt, *v)).collect();
            let exact: Vec<bool> = results.iter().map(|r| is_exact(&r.edges, &truth)).collect();
            tally.add(&case, &exact);
            let default = variants.iter().position(|(_, v)| *v == DiscurVariant::DEFAULT);
            let rec = &results[default.expect("the default is a variant")];
            let mut has_edge = vec![false; points.len()];
            rec.edges.iter().flatten().for_each(|&i| has_edge[i] = true);
            rec.duplicates.iter().for_each(|&[i, _]| has_edge[i] = true);
            let entry = free.entry(case.category.clone()).or_default();
            entry.0 += points.len();
            entry.1 += has_edge.iter().filter(|&&h| !h).count();
        }
        println!("\n{}\n", dir.display());
        let columns: Vec<(&str, usize, &[usize])> = COLUMNS
            .iter()
            .filter_map(|&c| tally.row(c).map(|(cases, exact)| (c, cases, exact)))
            .collect();
        let head: Vec<String> =
            columns.iter().map(|(c, cases, _)| format!("{c} ({cases})")).collect();
        println!("| variant | {} |", head.join(" | "));
        println!("|---|{}", "--:|".repeat(columns.len()));
        for (k, (name, _)) in variants.iter().enumerate() {
            let cells: Vec<String> = columns
                .iter()
                .map(|(_, cases, exact)| {
                    format!("{} ({:.1})", exact[k], 100.0 * exact[k] as f64 / *cases as f64)
                })
                .collect();
            println!("| {name} | {} |", cells.join(" | "));
        }
        let paper: Vec<String> = columns
            .iter()
            .map(|(c, ..)| {
                PAPER.iter().find(|(p, _)| p == c).map_or("–".into(), |p| p.1.to_string())
            })
            .collect();
        println!("| paper (Table 2) | {} |", paper.join(" | "));
        println!("\npoints without an edge (default variant):");
        for (category, (points, without)) in &free {
            println!("  {category:<10} {without:>6} of {points:>7}");
        }
    }
    Ok(())
}
