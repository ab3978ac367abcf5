//! How SIG-AUTO's exact-reconstruction counts change with the ratio of its join bound.
//!
//! ```text
//! cargo run --release -p sigdt-lab --example join_ratio_sweep \
//!     [-- DATA_DIR] [--ratios 1.5,2,3] [--list CATEGORY]
//! ```
//!
//! SIG-AUTO closes a gap only when it is at most [`JOIN_RATIO`] (2, the `u < 2` of the
//! paper's Theorem 1) times the longest sample spacing next to it; the same ratio decides
//! where a loop is cut open. This example replaces that ratio (in all three places, through
//! `sig_auto_with`) and counts exact reconstructions per category of the
//! labelled folder `DATA_DIR` (default the repository's `data/curves`: `index.csv`,
//! `NAME.xy`, `NAME.gt`), plus a `manifold eps<1` row. A smaller ratio keeps more open curves
//! open and closes fewer closed ones; the table shows how much of each a ratio buys. With
//! `--list CATEGORY`, the cases of that category that no ratio reconstructs go to stderr.
use sigdt::internals::{sig_auto_with, SigAutoSteps, JOIN_RATIO};
use sigdt::Triangulation;
use sigdt_lab::dataset::{data_dir, read_index, ExactTally};
use sigdt_lab::eval::is_exact;
use std::error::Error;
use std::path::PathBuf;

const DEFAULT_RATIOS: [f64; 9] = [1.25, 1.5, 1.75, 1.9, 2.0, 2.25, 2.5, 3.0, 3.5];

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut dir = data_dir("curves");
    let mut ratios = DEFAULT_RATIOS.to_vec();
    let mut list: Option<String> = None;
    let mut k = 0;
    while k < args.len() {
        match args[k].as_str() {
            "--ratios" => {
                let text = args.get(k + 1).ok_or("--ratios needs a list such as 1.5,2,3")?;
                ratios = text
                    .split(',')
                    .map(|r| {
                        r.trim().parse().map_err(|_| format!("--ratios: {r:?} is not a number"))
                    })
                    .collect::<Result<_, _>>()?;
                if ratios.iter().any(|r: &f64| !(r.is_finite() && *r > 0.0)) {
                    return Err(
                        format!("--ratios: every ratio must be positive, got {text}").into()
                    );
                }
                k += 2;
            }
            "--list" => {
                list = Some(args.get(k + 1).ok_or("--list needs a category")?.clone());
                k += 2;
            }
            other => {
                dir = PathBuf::from(other);
                k += 1;
            }
        }
    }
    let mut tally = ExactTally::default();
    for case in read_index(&dir)? {
        let (name, category) = (case.name.as_str(), case.category.as_str());
        let eps = case.epsilon.unwrap_or(f64::INFINITY);
        let (points, truth) = case.read(&dir)?;
        let dt = Triangulation::new(&points)?;
        let exact: Vec<bool> = ratios
            .iter()
            .map(|&r| {
                let steps = SigAutoSteps { join_ratio: r, ..SigAutoSteps::default() };
                is_exact(&sig_auto_with(&dt, &steps).edges, &truth)
            })
            .collect();
        tally.add(&case, &exact);
        if list.as_deref() == Some(category) && !exact.contains(&true) {
            eprintln!("no ratio: {name} (n = {}, eps = {eps})", points.len());
        }
    }
    let marks: Vec<String> = ratios
        .iter()
        .map(|&r| if r == JOIN_RATIO { format!("**{r}**") } else { r.to_string() })
        .collect();
    println!("| category | cases | {} |", marks.join(" | "));
    println!("|---|--:|{}", "--:|".repeat(ratios.len()));
    for (label, cases, exact) in tally.rows() {
        let cells: Vec<String> = exact.iter().map(|e| e.to_string()).collect();
        println!("| {label} | {cases} | {} |", cells.join(" | "));
    }
    Ok(())
}
