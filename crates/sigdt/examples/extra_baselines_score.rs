//! Exact-reconstruction counts of the CRAWL and PEEL baselines on the labelled curves.
//!
//! ```text
//! cargo run --release -p sigdt --example extra_baselines_score [-- DATA_DIR] [--time N] [--list]
//! ```
//!
//! `DATA_DIR` (default `../shared/data/curves` seen from the workspace root, i.e.
//! `/work/shared/data/curves`) holds `index.csv` (`name,category,...,epsilon,...`),
//! `NAME.xy` points and `NAME.gt` sorted 0-based ground-truth edges. A case counts as exact
//! when the method's input-index edge set equals the ground truth. Inputs whose triangulation
//! is not proper (collinear, fewer than three distinct points) are skipped and counted.
//! Prints one row per category, plus a `manifold eps<1` row. With `--time N`, also times each method
//! (median of 5, triangulation excluded) on `random_closed_curve(1, N)` shuffled with seed 7.
//! With `--list`, every inexact case and the methods that missed it go to stderr.
//! GATHAN has no implementation (see `sigdt::baselines::gathan`).
use sigdt::baselines::{crawl::crawl, peel::peel};
use sigdt::delaunay::Shape;
use sigdt::io::{read_edges, read_points};
use sigdt::{Edge, Triangulation};
use std::collections::BTreeMap;
use std::error::Error;
use std::path::PathBuf;
use std::time::Instant;

type Method = fn(&Triangulation) -> Vec<[u32; 2]>;
const METHODS: [(&str, Method); 2] = [("CRAWL", crawl), ("PEEL", peel)];

/// Per category: cases, skipped, exact count per method.
#[derive(Default)]
struct Tally {
    cases: usize,
    skipped: usize,
    exact: [usize; METHODS.len()],
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut dir = PathBuf::from("/work/shared/data/curves");
    let mut time_n = None;
    let mut list = false;
    let mut k = 0;
    while k < args.len() {
        if args[k] == "--list" {
            list = true;
            k += 1;
        } else if args[k] == "--time" {
            time_n = Some(args.get(k + 1).ok_or("--time needs N")?.parse::<f64>()? as usize);
            k += 2;
        } else {
            dir = PathBuf::from(&args[k]);
            k += 1;
        }
    }
    let index = std::fs::read_to_string(dir.join("index.csv"))?;
    let mut rows = index.lines();
    let header: Vec<&str> = rows.next().ok_or("empty index.csv")?.split(',').collect();
    let col = |name: &str| header.iter().position(|&h| h == name).ok_or(format!("no {name}"));
    let (c_name, c_cat, c_eps) = (col("name")?, col("category")?, col("epsilon")?);
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    for row in rows.filter(|r| !r.trim().is_empty()) {
        let f: Vec<&str> = row.split(',').collect();
        let (name, category) = (f[c_name], f[c_cat]);
        let eps: f64 = f[c_eps].parse().unwrap_or(f64::INFINITY);
        let points = read_points(&dir.join(format!("{name}.xy")))?;
        let truth: Vec<Edge> = read_edges(&dir.join(format!("{name}.gt")))?;
        let dt = Triangulation::new(&points)?;
        let mut keys = vec![category.to_string()];
        if category == "manifold" && eps < 1.0 {
            keys.push("manifold eps<1".to_string());
        }
        let proper = dt.shape() == Shape::Proper;
        let exact = METHODS.map(|(_, m)| proper && dt.to_input_edges(m(&dt)) == truth);
        if list {
            let failed: Vec<&str> =
                METHODS.iter().zip(&exact).filter(|(_, &ok)| !ok).map(|((n, _), _)| *n).collect();
            if !failed.is_empty() {
                eprintln!("{category} {name} eps={eps} n={}: {}", points.len(), failed.join(" "));
            }
        }
        for key in keys {
            let t = tallies.entry(key).or_default();
            t.cases += 1;
            t.skipped += usize::from(!proper);
            for (e, &ok) in t.exact.iter_mut().zip(&exact) {
                *e += usize::from(ok);
            }
        }
    }
    print!("| category | cases | skipped |");
    for (name, _) in METHODS {
        print!(" {name} |");
    }
    println!();
    println!("|---|---|---|{}", "---|".repeat(METHODS.len()));
    for (category, t) in &tallies {
        print!("| {category} | {} | {} |", t.cases, t.skipped);
        for e in t.exact {
            print!(" {e} ({:.1}%) |", 100.0 * e as f64 / t.cases.max(1) as f64);
        }
        println!();
    }
    if let Some(n) = time_n {
        let points = sigdt::curves::random_closed_curve(1, n).shuffled(7).points;
        let dt = Triangulation::new(&points)?;
        for (name, m) in METHODS {
            let mut ms: Vec<f64> = (0..5)
                .map(|_| {
                    let t = Instant::now();
                    std::hint::black_box(m(&dt));
                    t.elapsed().as_secs_f64() * 1e3
                })
                .collect();
            ms.sort_by(f64::total_cmp);
            let ok = dt.to_input_edges(m(&dt))
                == sigdt::curves::random_closed_curve(1, n).shuffled(7).edges;
            println!("{name}: n = {n}, median {:.1} ms (exact: {ok})", ms[2]);
        }
    }
    Ok(())
}
