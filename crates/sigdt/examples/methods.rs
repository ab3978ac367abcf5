//! Speed of every method against SIG-CONNECT2D, at growing sizes, with a time limit.
//!
//! ```text
//! cargo run --release -p sigdt --example methods                    # n = 1e3, 1e4, 1e5
//! cargo run --release -p sigdt --example methods -- --sizes 1e3,1e6 --methods sig-auto
//! cargo run --release -p sigdt --example methods -- --input scatter --methods sig-auto
//! ```
//!
//! Input: [`random_closed_curve`]`(1, n)` shuffled with seed 7 (a smooth blob sampled
//! uniformly, no curve order in the input), or with `--input scatter` `n` points uniform at
//! random in the unit square (seed 7): no curve at all, the worst case SIG-AUTO's outlier
//! rules were found to have (`docs/reliability.md`). For each size the methods run in turn, `R` times
//! (after one warm-up; the calls alternate so machine noise hits all alike; `R` = 5, or 1 for
//! calls over a second), single-threaded. Reported: the median time, and the median over the
//! rounds of the time over SIG-CONNECT2D's time in the same round. A method whose single run takes longer than
//! the limit (`--limit SECONDS`, default 30) is not run at larger sizes: its later cells say
//! `over limit`. `growth` is the time ratio between consecutive sizes divided by the size
//! ratio (1.0 = linear).
use sigdt::samplers::{random_closed_curve, Rng};
use sigdt::{Method, Options};
use std::error::Error;
use std::hint::black_box;
use std::time::Instant;

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| args.iter().position(|a| a == flag).and_then(|i| args.get(i + 1));
    let scatter = match value("--input").map(String::as_str) {
        None | Some("curve") => false,
        Some("scatter") => true,
        Some(other) => return Err(format!("--input: '{other}' is not curve or scatter").into()),
    };
    let sizes: Vec<usize> = match value("--sizes") {
        Some(list) => list
            .split(',')
            .map(|s| s.trim().parse::<f64>().map(|x| x as usize))
            .collect::<Result<_, _>>()
            .map_err(|e| format!("--sizes: {e}"))?,
        None => vec![1_000, 10_000, 100_000],
    };
    let methods: Vec<Method> = match value("--methods") {
        Some(list) => list.split(',').map(str::parse).collect::<Result<_, _>>()?,
        None => Method::ALL.to_vec(),
    };
    let limit: f64 =
        value("--limit").map_or(Ok(30.0), |s| s.parse()).map_err(|e| format!("--limit: {e}"))?;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    println!("| method | n | median ms | / sig-connect2d | growth |");
    println!("|---|--:|--:|--:|--:|");
    let mut stopped = vec![false; methods.len()];
    let mut previous: Vec<Option<(usize, f64)>> = vec![None; methods.len()];
    for &n in &sizes {
        let points = match scatter {
            true => {
                let mut rng = Rng::new(7);
                (0..n).map(|_| [rng.uniform(), rng.uniform()]).collect()
            }
            false => random_closed_curve(1, n).shuffled(7).points,
        };
        let run = |method: Method| -> f64 {
            let options = Options { method, ..Options::default() };
            let start = Instant::now();
            black_box(
                pool.install(|| sigdt::reconstruct(&points, &options)).expect("valid points"),
            );
            start.elapsed().as_secs_f64()
        };
        let reference = Method::SigConnect2d;
        let mut times: Vec<Vec<f64>> = vec![Vec::new(); methods.len()];
        let mut ratios: Vec<Vec<f64>> = vec![Vec::new(); methods.len()];
        let warm = run(reference);
        let rounds = if warm > 1.0 { 1 } else { 5 };
        for k in 0..methods.len() {
            if !stopped[k] && run(methods[k]) > limit {
                stopped[k] = true;
            }
        }
        for _ in 0..rounds {
            let base = run(reference);
            for k in (0..methods.len()).filter(|&k| !stopped[k]) {
                let t = run(methods[k]);
                times[k].push(t);
                ratios[k].push(t / base);
            }
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        for k in 0..methods.len() {
            if times[k].is_empty() {
                println!("| {} | {n} | over limit | | |", methods[k]);
                continue;
            }
            let t = median(&mut times[k]);
            let growth = previous[k]
                .map_or(String::new(), |(m, p)| format!("{:.2}", (t / p) / (n as f64 / m as f64)));
            previous[k] = Some((n, t));
            let ratio = median(&mut ratios[k]);
            println!("| {} | {n} | {:.2} | {ratio:.2} | {growth} |", methods[k], t * 1e3);
        }
    }
    Ok(())
}
