//! Time per small set: `cargo run --release -p sigdt --example small_sets -- [SETS] [N] [ROUNDS]`
//! reconstructs SETS random blobs of N points (shuffled) one after another on one thread
//! and prints the mean time per set (the Rust side of `reconstruct_many`).
use std::time::Instant;

fn main() {
    let mut args = std::env::args().skip(1);
    let sets: u64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(10_000);
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(260);
    let samples: Vec<_> =
        (0..sets).map(|s| sigdt::samplers::random_closed_curve(s, n).shuffled(s)).collect();
    let options = sigdt::Options { method: sigdt::Method::SigConnect2d, ..Default::default() };
    let rounds: u64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(3);
    for round in 0..rounds {
        let start = Instant::now();
        for s in &samples {
            std::hint::black_box(sigdt::reconstruct(&s.points, &options).unwrap());
        }
        let per = start.elapsed().as_secs_f64() * 1e6 / sets as f64;
        println!("round {round}: {per:.1} µs per set of {n} points");
    }
}
