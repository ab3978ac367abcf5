//! Time per small set: `cargo run --release -p sigdt --example small_sets -- [SETS] [N] [ROUNDS]`
//! reconstructs SETS random blobs of N points (shuffled) one after another on one thread
//! and prints the mean time per set (the Rust side of `reconstruct_many`); then the same sets
//! spread over a pool of all threads (as `reconstruct_many` does), and the speed-up.
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
    let threads = std::thread::available_parallelism().map_or(1, |p| p.get());
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    for round in 0..rounds {
        let time = |pool: &rayon::ThreadPool| {
            let start = Instant::now();
            pool.install(|| {
                use rayon::prelude::*;
                samples.par_iter().for_each(|s| {
                    std::hint::black_box(sigdt::reconstruct(&s.points, &options).unwrap());
                })
            });
            start.elapsed().as_secs_f64()
        };
        let one = time(&rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap());
        let many = time(&pool);
        println!("round {round}: {threads} threads {:.2} times one", one / many);
    }
}
