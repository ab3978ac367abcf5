//! Exact-reconstruction counts of the CRUST family on the labelled curves, and their speed.
//!
//! ```text
//! cargo run --release -p sigdt --example baselines_score [DATA_DIR]
//! ```
//!
//! `DATA_DIR` (default `../shared/data/curves`, or `SIGDT_DATA`) holds `index.csv` and
//! `NAME.xy` / `NAME.gt` per case. For every case with a proper triangulation, each method's
//! vertex pairs are mapped to sorted input-index edges and compared with the ground truth
//! (exact = equal sets). Prints `exact / total` per category (plus `manifold eps<1`), then
//! the median time of each method on [`random_closed_curve`]`(1, 100_000)` given its
//! triangulation, and whether that curve came out exact.
use sigdt::baselines::{crust::crust, hnn_crust::hnn_crust, nn_crust::nn_crust};
use sigdt::curves::random_closed_curve;
use sigdt::delaunay::Shape;
use sigdt::io::{read_edges, read_points};
use sigdt::Triangulation;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

type Method = (&'static str, fn(&Triangulation) -> Vec<[u32; 2]>);
const METHODS: [Method; 3] = [("crust", crust), ("nn-crust", nn_crust), ("hnn-crust", hnn_crust)];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args()
        .nth(1)
        .or_else(|| std::env::var("SIGDT_DATA").ok())
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data/curves")
        });
    let index = std::fs::read_to_string(dir.join("index.csv"))?;
    let mut lines = index.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).expect("column");
    let (name_col, category_col, epsilon_col) = (col("name"), col("category"), col("epsilon"));
    // method -> category -> (exact, total)
    let mut table: BTreeMap<&str, BTreeMap<String, (usize, usize)>> = BTreeMap::new();
    let mut skipped = 0;
    for line in lines.filter(|l| !l.trim().is_empty()) {
        let f: Vec<&str> = line.split(',').collect();
        let (name, category) = (f[name_col], f[category_col]);
        let epsilon: Option<f64> = f[epsilon_col].parse().ok();
        let points = read_points(&dir.join(format!("{name}.xy")))?;
        let mut gt: Vec<[usize; 2]> = read_edges(&dir.join(format!("{name}.gt")))?
            .into_iter()
            .map(|[i, j]| [i.min(j), i.max(j)])
            .collect();
        gt.sort_unstable();
        gt.dedup();
        let dt = Triangulation::new(&points)?;
        if dt.shape() != Shape::Proper {
            skipped += 1;
            continue;
        }
        for (method, f) in METHODS {
            let exact = dt.to_input_edges(f(&dt)) == gt;
            let rows = table.entry(method).or_default();
            let mut add = |key: &str| {
                let entry = rows.entry(key.to_string()).or_default();
                entry.0 += usize::from(exact);
                entry.1 += 1;
            };
            add(category);
            add("all");
            if category == "manifold" && epsilon.is_some_and(|e| e < 1.0) {
                add("manifold eps<1");
            }
        }
    }
    println!("exact reconstructions ({skipped} non-proper cases skipped)");
    for (method, rows) in &table {
        println!("{method}:");
        for (category, (exact, total)) in rows {
            let rate = 100.0 * *exact as f64 / *total as f64;
            println!("  {category:<16} {exact:>4} / {total:<4} {rate:>6.1}%");
        }
    }

    let n = 100_000;
    let sample = random_closed_curve(1, n);
    let dt = Triangulation::new(&sample.points)?;
    let mut gt = sample.edges.clone();
    gt.sort_unstable();
    println!("speed on random_closed_curve(1, {n}), given the triangulation:");
    for (method, f) in METHODS {
        let mut times = Vec::new();
        let mut exact = false;
        for _ in 0..5 {
            let start = Instant::now();
            let pairs = f(&dt);
            times.push(start.elapsed().as_secs_f64() * 1e3);
            exact = dt.to_input_edges(pairs) == gt;
        }
        times.sort_by(f64::total_cmp);
        println!("  {method:<10} {:>8.2} ms median, exact: {exact}", times[times.len() / 2]);
    }
    let start = Instant::now();
    let _ = Triangulation::new(&sample.points)?;
    println!("  (Triangulation::new: {:.2} ms)", start.elapsed().as_secs_f64() * 1e3);
    Ok(())
}
