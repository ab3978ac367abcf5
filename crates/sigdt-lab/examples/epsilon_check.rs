//! Compares [`sigdt_lab::eval::epsilon`] with the `epsilon` column of the data set.
//!
//! ```text
//! cargo run --release -p sigdt-lab --example epsilon_check [-- DATA_DIR] [--timing] [--only=NAME]
//! ```
//!
//! `DATA_DIR` defaults to the repository's `data/curves`. For every case
//! with a finite reference epsilon it computes each variant and prints, per category and
//! overall: the number of cases, Pearson's correlation of the logarithms, the share of
//! cases on the same side of `eps < 1`, and the median ratio ours / reference; then the ten
//! largest disagreements of the default variant. `--timing` also times the distance and
//! area metrics of SIG-CONNECT2D's result on the largest case; `--only=NAME` keeps the cases
//! whose name contains `NAME`.
use sigdt_lab::dataset::{data_dir, read_index};
use sigdt_lab::eval::{area_difference, distance_errors, epsilon, EpsilonVariant};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let timing = args.iter().any(|a| a == "--timing");
    let only = args.iter().find_map(|a| a.strip_prefix("--only="));
    let dir = args
        .iter()
        .find(|a| !a.starts_with("--"))
        .map_or_else(|| data_dir("curves"), PathBuf::from);
    let variants = [
        ("E", EpsilonVariant::Graph),
        ("arcs30", EpsilonVariant::Arcs { corner_turn_deg: 30.0 }),
        ("arcs45", EpsilonVariant::Arcs { corner_turn_deg: 45.0 }),
        ("arcs60", EpsilonVariant::Arcs { corner_turn_deg: 60.0 }),
        ("arcs90", EpsilonVariant::Arcs { corner_turn_deg: 90.0 }),
    ];
    let default = EpsilonVariant::default();
    // (category, name, reference, ours per variant)
    let mut rows: Vec<(String, String, f64, Vec<f64>)> = Vec::new();
    let mut largest: Option<(usize, String)> = None;
    for case in read_index(&dir)? {
        let Some(reference) = case.epsilon else { continue };
        if only.is_some_and(|o| !case.name.contains(o)) {
            continue;
        }
        let (points, gt) = case.read(&dir)?;
        let (name, category) = (case.name, case.category);
        if largest.as_ref().map_or(true, |(n, _)| points.len() > *n) {
            largest = Some((points.len(), name.clone()));
        }
        let t = Instant::now();
        let ours: Vec<f64> =
            variants.iter().map(|&(_, v)| epsilon(&points, &gt, v)).collect::<Result<_, _>>()?;
        if points.len() >= 10_000 {
            eprintln!("{name}: {} points, all variants in {:.2?}", points.len(), t.elapsed());
        }
        rows.push((category, name, reference, ours));
    }
    let mut groups: BTreeMap<String, Vec<usize>> = BTreeMap::new();
    for (k, r) in rows.iter().enumerate() {
        groups.entry(r.0.clone()).or_default().push(k);
        groups.entry("all".into()).or_default().push(k);
    }
    for (v, (label, _)) in variants.iter().enumerate() {
        println!("\n## variant {label}\n");
        println!("| category | cases | corr(log) | same class (eps < 1) | ref < 1 | ours < 1 | median ours/ref |");
        println!("|---|---:|---:|---:|---:|---:|---:|");
        for (cat, ks) in &groups {
            let pairs: Vec<(f64, f64)> = ks.iter().map(|&k| (rows[k].2, rows[k].3[v])).collect();
            let same = pairs.iter().filter(|(r, o)| (*r < 1.0) == (*o < 1.0)).count();
            let below = |f: fn(&(f64, f64)) -> f64| pairs.iter().filter(|p| f(p) < 1.0).count();
            let mut q: Vec<f64> = pairs.iter().map(|(r, o)| o / r).collect();
            q.sort_by(f64::total_cmp);
            println!(
                "| {cat} | {} | {:.3} | {same}/{} | {} | {} | {:.2} |",
                pairs.len(),
                log_correlation(&pairs),
                pairs.len(),
                below(|p| p.0),
                below(|p| p.1),
                q[q.len() / 2]
            );
        }
    }
    let d = variants.iter().position(|&(_, v)| v == default).unwrap_or(0);
    println!("\nLargest disagreements of the default variant ({}):", variants[d].0);
    let mut by: Vec<usize> = (0..rows.len()).collect();
    let gap = |k: usize| (rows[k].3[d] / rows[k].2).ln().abs();
    by.sort_by(|&a, &b| gap(b).total_cmp(&gap(a)));
    for &k in by.iter().take(12) {
        let (cat, name, r, o) = &rows[k];
        println!("  {name} ({cat}): reference {r:.3}, ours {:.3}", o[d]);
    }
    if let (true, Some((_, name))) = (timing, largest) {
        time_metrics(&dir, &name)?;
    }
    Ok(())
}

/// Pearson's correlation of `(ln a, ln b)` over pairs with both positive and finite.
fn log_correlation(pairs: &[(f64, f64)]) -> f64 {
    let xs: Vec<(f64, f64)> = pairs
        .iter()
        .filter(|(a, b)| *a > 0.0 && *b > 0.0 && a.is_finite() && b.is_finite())
        .map(|(a, b)| (a.ln(), b.ln()))
        .collect();
    let n = xs.len() as f64;
    let (ma, mb) =
        (xs.iter().map(|p| p.0).sum::<f64>() / n, xs.iter().map(|p| p.1).sum::<f64>() / n);
    let cov: f64 = xs.iter().map(|p| (p.0 - ma) * (p.1 - mb)).sum();
    let va: f64 = xs.iter().map(|p| (p.0 - ma).powi(2)).sum();
    let vb: f64 = xs.iter().map(|p| (p.1 - mb).powi(2)).sum();
    cov / (va * vb).sqrt()
}

fn time_metrics(dir: &std::path::Path, name: &str) -> Result<(), Box<dyn std::error::Error>> {
    let points = sigdt_io::text::read_points(&dir.join(format!("{name}.xy")))?;
    let gt = sigdt_io::text::read_edges(&dir.join(format!("{name}.gt")))?;
    let options = sigdt::Options { method: sigdt::Method::SigConnect2d, ..Default::default() };
    let rec = sigdt::reconstruct(&points, &options)?;
    let t = Instant::now();
    let d = distance_errors(&points, &rec.edges, &gt)?;
    let td = t.elapsed();
    let t = Instant::now();
    let a = area_difference(&points, &rec.edges, &gt)?;
    let ta = t.elapsed();
    let t = Instant::now();
    let e = sigdt_lab::eval::graph_epsilon(&points, &gt)?;
    let te = t.elapsed();
    println!("\n{name} ({} points, {} result edges):", points.len(), rec.edges.len());
    println!("  distance_errors {td:.2?}: {d:?}");
    println!("  area_difference {ta:.2?}: {a:?}");
    println!("  graph_epsilon   {te:.2?}: {e}");
    Ok(())
}
