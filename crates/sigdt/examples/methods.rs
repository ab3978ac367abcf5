//! Speed of every method against SIG-CONNECT2D, at growing sizes, with a time limit.
//!
//! ```text
//! cargo run --release -p sigdt --example methods                    # n = 1e3, 1e4, 1e5
//! cargo run --release -p sigdt --example methods -- --sizes 1e3,1e6 --methods sig-auto
//! cargo run --release -p sigdt --example methods -- --input worst --sizes 1e4,2e4,4e4
//! ```
//!
//! Input (`--input`): `curve` (the default), [`random_closed_curve`]`(1, n)` shuffled with
//! seed 7 (a smooth blob sampled uniformly, no curve order in the input); or one of the
//! inputs that are no curve, from [`sigdt::samplers`]: `scatter` (`n` points uniform in the
//! unit square, seed 7), `lattice` (exactly cocircular lattice points), `zigzag` (height
//! 10⁻⁴⁰), `tall-zigzag` (width 10⁻⁴⁰), `line-and-point`; or `worst`, each method on the
//! input that was its slowest (`docs/reliability.md`, "Worst case of each method"). For
//! each size the methods run in turn, each call right after SIG-CONNECT2D on the same input
//! (so machine noise hits both alike), `R` times after one warm-up (`R` = 5, or 1 for calls
//! over a second), single-threaded. Reported: the median time, and the median over the
//! rounds of the time over SIG-CONNECT2D's. A method whose single run takes longer than the
//! limit (`--limit SECONDS`, default 30) is not run at larger sizes: its later cells say
//! `over limit`. `growth` is the time ratio between consecutive sizes divided by the size
//! ratio (1.0 = linear).
use sigdt::samplers::{
    cocircular_lattice, line_and_point, random_closed_curve, tall_zigzag, uniform_square, zigzag,
};
use sigdt::{Method, Options, Point};
use std::error::Error;
use std::hint::black_box;
use std::time::Instant;

/// An input family, built at any size.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Input {
    Curve,
    Scatter,
    Lattice,
    Zigzag,
    TallZigzag,
    LineAndPoint,
}

impl Input {
    const NAMES: [(&'static str, Input); 6] = [
        ("curve", Input::Curve),
        ("scatter", Input::Scatter),
        ("lattice", Input::Lattice),
        ("zigzag", Input::Zigzag),
        ("tall-zigzag", Input::TallZigzag),
        ("line-and-point", Input::LineAndPoint),
    ];

    fn name(self) -> &'static str {
        Self::NAMES.iter().find(|(_, i)| *i == self).expect("every input is named").0
    }

    fn points(self, n: usize) -> Vec<Point> {
        match self {
            Input::Curve => random_closed_curve(1, n).shuffled(7).points,
            Input::Scatter => uniform_square(n, 7),
            Input::Lattice => cocircular_lattice(n),
            Input::Zigzag => zigzag(n, 1e-40),
            Input::TallZigzag => tall_zigzag(n, 1e-40),
            Input::LineAndPoint => line_and_point(n - 1),
        }
    }

    /// The input that was `method`'s slowest (the table in `docs/reliability.md`).
    fn worst_for(method: Method) -> Input {
        match method {
            Method::SigAuto => Input::Scatter,
            Method::Crust => Input::Zigzag,
            Method::HnnCrust => Input::TallZigzag,
            Method::FitConnect | Method::StretchDenoise => Input::LineAndPoint,
            _ => Input::Lattice,
        }
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| args.iter().position(|a| a == flag).and_then(|i| args.get(i + 1));
    let input = match value("--input").map(String::as_str) {
        None => Some(Input::Curve),
        Some("worst") => None,
        Some(name) => match Input::NAMES.iter().find(|(n, _)| *n == name) {
            Some(&(_, input)) => Some(input),
            None => {
                let names: Vec<_> = Input::NAMES.iter().map(|(n, _)| *n).collect();
                let names = names.join(", ");
                return Err(format!("--input: '{name}' is not {names} or worst").into());
            }
        },
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
    let inputs: Vec<Input> =
        methods.iter().map(|&m| input.unwrap_or_else(|| Input::worst_for(m))).collect();
    println!("| method | input | n | median ms | / sig-connect2d | growth |");
    println!("|---|---|--:|--:|--:|--:|");
    let mut stopped = vec![false; methods.len()];
    let mut previous: Vec<Option<(usize, f64)>> = vec![None; methods.len()];
    let reference = Method::SigConnect2d;
    for &n in &sizes {
        let mut built: Vec<(Input, Vec<Point>)> = Vec::new();
        for &input in &inputs {
            if !built.iter().any(|(i, _)| *i == input) {
                built.push((input, input.points(n)));
            }
        }
        let run = |method: Method, input: Input| -> f64 {
            let points = &built.iter().find(|(i, _)| *i == input).expect("built above").1;
            let options = Options { method, ..Options::default() };
            let start = Instant::now();
            black_box(pool.install(|| sigdt::reconstruct(points, &options)).expect("valid points"));
            start.elapsed().as_secs_f64()
        };
        let mut times: Vec<Vec<f64>> = vec![Vec::new(); methods.len()];
        let mut ratios: Vec<Vec<f64>> = vec![Vec::new(); methods.len()];
        let mut rounds = vec![5; methods.len()];
        for k in 0..methods.len() {
            run(reference, inputs[k]);
            if stopped[k] {
                continue;
            }
            let warm = run(methods[k], inputs[k]);
            stopped[k] = warm > limit;
            if warm > 1.0 {
                rounds[k] = 1;
            }
        }
        for round in 0..5 {
            for k in (0..methods.len()).filter(|&k| !stopped[k] && round < rounds[k]) {
                let base = run(reference, inputs[k]);
                let t = run(methods[k], inputs[k]);
                times[k].push(t);
                ratios[k].push(t / base);
            }
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        for k in 0..methods.len() {
            let (method, input) = (methods[k], inputs[k].name());
            if times[k].is_empty() {
                println!("| {method} | {input} | {n} | over limit | | |");
                continue;
            }
            let t = median(&mut times[k]);
            let growth = previous[k]
                .map_or(String::new(), |(m, p)| format!("{:.2}", (t / p) / (n as f64 / m as f64)));
            previous[k] = Some((n, t));
            let ratio = median(&mut ratios[k]);
            println!("| {method} | {input} | {n} | {:.2} | {ratio:.2} | {growth} |", t * 1e3);
        }
    }
    Ok(())
}
