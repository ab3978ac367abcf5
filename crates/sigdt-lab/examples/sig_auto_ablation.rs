//! What each of SIG-AUTO's steps buys: exact reconstructions per category with every step,
//! and with one step switched off at a time.
//!
//! ```text
//! cargo run --release -p sigdt-lab --example sig_auto_ablation [-- DATA_DIR ...]
//! ```
//!
//! Runs SIG-AUTO (`internals::sig_auto_with`) on every case of each labelled folder
//! (default the repository's `data/curves` and `data/real`: `index.csv`, `NAME.xy`,
//! `NAME.gt`) once per row of `VARIANTS`, and prints one Markdown table per folder: exact
//! cases per category (plus `manifold eps<1`) for each variant. A column below the `all
//! steps` row says what that step costs when it is gone; `docs/sig-auto.md` keeps the
//! tables.
use sigdt::internals::{sig_auto_with, SigAutoSteps};
use sigdt::Triangulation;
use sigdt_lab::dataset::{data_dir, read_index, ExactTally};
use sigdt_lab::eval::is_exact;
use std::error::Error;
use std::path::PathBuf;

/// One row: its name, and what it switches off.
type Variant = (&'static str, fn(&mut SigAutoSteps));

/// The rows.
const VARIANTS: [Variant; 9] = [
    ("all steps (SIG-AUTO)", |_| {}),
    ("no branch outliers (step 6, tree)", |s| s.branch_outliers = false),
    ("no second reading (step 9)", |s| s.shorter_reading = false),
    ("no paths for zigzag loops (step 8)", |s| s.zigzag_paths = false),
    ("no detour outliers (step 6, reading)", |s| s.detours = false),
    ("no isolated pieces (step 6)", |s| s.isolated = false),
    ("no good continuation (step 7)", |s| s.continuation = false),
    ("outlier rules without tangent rays", |s| s.tangent_rays = false),
    ("outlier rules without own curves", |s| s.own_curves = false),
];

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    let dirs = if args.is_empty() { vec![data_dir("curves"), data_dir("real")] } else { args };
    let variants: Vec<(&str, SigAutoSteps)> = VARIANTS
        .iter()
        .map(|(name, switch)| {
            let mut steps = SigAutoSteps::default();
            switch(&mut steps);
            (*name, steps)
        })
        .collect();
    for dir in dirs {
        let mut tally = ExactTally::default();
        for case in read_index(&dir)? {
            let (points, truth) = case.read(&dir)?;
            let dt = Triangulation::new(&points)?;
            let exact: Vec<bool> = variants
                .iter()
                .map(|(_, s)| is_exact(&sig_auto_with(&dt, s).edges, &truth))
                .collect();
            tally.add(&case, &exact);
        }
        println!("\n{}\n", dir.canonicalize().unwrap_or(dir.clone()).display());
        let heads: Vec<String> =
            tally.rows().map(|(l, cases, _)| format!("{l} ({cases})")).collect();
        println!("| variant | {} |", heads.join(" | "));
        println!("|---|{}", "--:|".repeat(heads.len()));
        for (v, (name, _)) in variants.iter().enumerate() {
            let cells: Vec<String> =
                tally.rows().map(|(_, _, exact)| exact[v].to_string()).collect();
            println!("| {name} | {} |", cells.join(" | "));
        }
    }
    Ok(())
}
