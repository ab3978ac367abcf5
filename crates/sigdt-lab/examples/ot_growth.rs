//! How OPTIMALTRANSPORT's time grows with the number of points, at its default stopping
//! rule (a quarter of the points left as vertices).
//!
//! ```text
//! cargo run --release -p sigdt-lab --example ot_growth [-- --limit SECONDS]
//! ```
//!
//! Inputs at 10³, 10⁴ and 10⁵ points: a random smooth closed curve
//! (`sigdt::samplers::random_closed_curve`, seed 1), the same curve with uniform noise of
//! 0.3 % of its diagonal, and points on a straight line with one point off it (the case
//! where one edge would collect every sample). A size is skipped once the previous size of
//! the same input took more than a tenth of `--limit` (default 120 s), since the next is ten
//! times larger. Prints one row per run: input, points, seconds, output edges.
use sigdt::internals::{default_stop, optimal_transport_with};
use sigdt::samplers::{random_closed_curve, uniform_noise};
use sigdt::{Point, Triangulation};
use std::error::Error;
use std::time::Instant;

/// A named input of any size.
type Input = (&'static str, fn(usize) -> Vec<Point>);

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let limit = match args.as_slice() {
        [] => 120.0,
        [flag, value] if flag == "--limit" => value.parse()?,
        _ => return Err("usage: ot_growth [--limit SECONDS]".into()),
    };
    let inputs: [Input; 3] = [
        ("curve", |n| random_closed_curve(1, n).points),
        ("noisy curve", |n| uniform_noise(&random_closed_curve(1, n).points, 0.003, 1).unwrap()),
        ("line + point off", |n| {
            let mut points: Vec<Point> = (0..n - 1).map(|i| [i as f64, 0.0]).collect();
            points.push([n as f64 / 2.0 + 0.5, 1.0]);
            points
        }),
    ];
    println!("| input | points | seconds | edges |\n|---|---|---|---|");
    for (name, make) in inputs {
        let mut previous = 0.0;
        for n in [1_000, 10_000, 100_000] {
            if previous > limit / 10.0 {
                println!("| {name} | {n} | skipped (over {limit} s expected) | |");
                continue;
            }
            let points = make(n);
            let start = Instant::now();
            let dt = Triangulation::new(&points)?;
            let rec = optimal_transport_with(&dt, default_stop(dt.num_vertices()))?;
            previous = start.elapsed().as_secs_f64();
            println!("| {name} | {n} | {previous:.2} | {} |", rec.edges.len());
        }
    }
    Ok(())
}
