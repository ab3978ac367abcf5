//! Time to read a point file: `cargo run --release -p sigdt --example read_speed -- FILE [REPS]`
//! reads FILE with [`sigdt_io::text::read_points`] on a pool of one thread and on one of two,
//! alternately, and prints the median time of each (the reader parses blocks of lines in
//! parallel; the points are the same).
use std::path::Path;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let file = args.next().ok_or("usage: read_speed FILE [REPS]")?;
    let reps: usize = args.next().map(|s| s.parse()).transpose()?.unwrap_or(7);
    let pools = [1, 2].map(|t| rayon::ThreadPoolBuilder::new().num_threads(t).build());
    let mut times = [Vec::new(), Vec::new()];
    let mut first: Option<Vec<[f64; 2]>> = None;
    for _ in 0..reps {
        for (pool, times) in pools.iter().zip(&mut times) {
            let pool = pool.as_ref().map_err(|e| e.to_string())?;
            let start = Instant::now();
            let points = pool.install(|| sigdt_io::text::read_points(Path::new(&file)))?;
            times.push(start.elapsed().as_secs_f64() * 1e3);
            assert_eq!(*first.get_or_insert_with(|| points.clone()), points);
        }
    }
    for (threads, mut t) in [1, 2].into_iter().zip(times) {
        t.sort_by(f64::total_cmp);
        println!("{threads} thread(s): {:.1} ms (median of {reps})", t[t.len() / 2]);
    }
    Ok(())
}
