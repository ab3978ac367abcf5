//! Per-stage timing: `cargo run --release -p sigdt --example stages -- N REPS` times each stage
//! of SIG-CONNECT2D on the
//! spiral band (median over REPS).
use sigdt::internals::{
    eliminate_leaves, inflate, loop_edges, loops, sculpt, sigdt_mask, Boundary,
};
use std::time::Instant;

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let reps: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(20);
    let s = sigdt::samplers::spiral_band(n).shuffled(7);
    let mut times = vec![Vec::new(); 6];
    for _ in 0..reps {
        let mut t = Instant::now();
        let mut lap = |k: usize, times: &mut Vec<Vec<f64>>| {
            times[k].push(t.elapsed().as_secs_f64() * 1e6);
            t = Instant::now();
        };
        let dt = sigdt::Triangulation::new(&s.points).unwrap();
        lap(0, &mut times);
        let mut g = sigdt_mask(&dt);
        eliminate_leaves(&dt, &mut g);
        lap(1, &mut times);
        let mut bd = Boundary::from_graph(&dt, &g);
        lap(2, &mut times);
        let mut stats = sigdt::Stats::default();
        inflate(&mut bd, &g, &mut stats);
        sculpt(&mut bd, &mut stats);
        lap(3, &mut times);
        let loops = loops(&bd);
        lap(4, &mut times);
        let e = loop_edges(&loops, n);
        lap(5, &mut times);
        std::hint::black_box(e);
    }
    for (name, mut t) in
        ["delaunay", "sigdt+leaves", "boundary", "inflate+sculpt", "loops", "edges"]
            .into_iter()
            .zip(times)
    {
        t.sort_by(f64::total_cmp);
        println!("{name:>15}: {:8.1} µs", t[t.len() / 2]);
    }
}
