//! OPTIMALTRANSPORT's RMSE on the uniform-noise sweep, for several stopping rules, and the
//! RMSE of outside results (CGAL's, from `tools/cgal-otr/`) on the same noisy sets.
//!
//! ```text
//! cargo run --release -p sigdt-lab --example ot_noise_sweep -- \
//!     [--stop v/4,v/8,steps/2,tol/0.002] [--levels 1e-4,1e-3] [--limit N] \
//!     [--write DIR] [--score NAME=DIR ...] [--csv FILE]
//! ```
//!
//! The sets are the `manifold` cases of `data/curves` (or `SIGDT_DATA`), each moved by
//! `sigdt::samplers::uniform_noise` at every level (a fraction of the bounding-box diagonal;
//! default 1e-4, 3e-4, 1e-3, 3e-3, 1e-2) with the seeds of `sigdt sweep` (`1000·(k + 1) + i`
//! for level `k` and case `i`). RMSE is against the clean ground truth, as a fraction of its
//! diagonal (`reconstruction_distance_errors`). The table gives its mean and median over the
//! cases with at least one edge, and the number of runs without one. `--csv` writes every
//! run.
//!
//! Stopping rules (`none` runs none): `v/D` keeps `ceil(m / D)` of the `m` distinct points
//! as vertices (`v/4` is the default), `steps/D` performs `floor(m / D)` collapses, `tol/X`
//! stops at a transport tolerance of `X` times the diagonal of the points' bounding box.
//!
//! `--write DIR` also writes each noisy set to `DIR/LEVEL/NAME.xy` with `DIR/LEVEL/NAME.n`
//! (its number of distinct points), for an outside program; `--score NAME=DIR` reads its
//! segments from `DIR/LEVEL/NAME.segments` (`x0 y0 x1 y1` per line) and scores them too.
use sigdt::internals::{optimal_transport_with, Stop};
use sigdt::samplers::uniform_noise;
use sigdt::{Edge, Point, Reconstruction, Triangulation, Vertices};
use sigdt_lab::dataset::{data_dir, read_index};
use sigdt_lab::eval::reconstruction_distance_errors;
use std::collections::BTreeMap;
use std::error::Error;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

const LEVELS: [f64; 5] = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2];

/// A stopping rule relative to the input.
#[derive(Clone)]
enum Rule {
    Keep(f64),
    Steps(f64),
    Tolerance(f64),
}

impl Rule {
    fn parse(text: &str) -> Result<Rule, String> {
        let (kind, value) = text.split_once('/').ok_or(format!("{text:?}: want KIND/NUMBER"))?;
        let x: f64 = value.parse().map_err(|_| format!("{text:?}: {value:?} is no number"))?;
        match kind {
            "v" if x >= 1.0 => Ok(Rule::Keep(x)),
            "steps" if x >= 1.0 => Ok(Rule::Steps(x)),
            "tol" if x >= 0.0 => Ok(Rule::Tolerance(x)),
            _ => Err(format!("{text:?}: want v/D or steps/D (D >= 1) or tol/X (X >= 0)")),
        }
    }

    fn stop(&self, distinct: usize, diag: f64) -> Stop {
        match *self {
            Rule::Keep(d) => Stop::Vertices((distinct as f64 / d).ceil() as usize),
            Rule::Steps(d) => Stop::Steps((distinct as f64 / d).floor() as usize),
            Rule::Tolerance(x) => Stop::Tolerance(x * diag),
        }
    }
}

/// Per (level, column): RMSEs, failures, seconds.
type Tally = BTreeMap<(usize, usize), (Vec<f64>, usize, f64)>;

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut stops = vec!["v/4".to_string()];
    let mut levels = LEVELS.to_vec();
    let (mut limit, mut write, mut csv) = (usize::MAX, None::<PathBuf>, None::<PathBuf>);
    let mut outside: Vec<(String, PathBuf)> = Vec::new();
    let mut k = 0;
    while k < args.len() {
        let value = args.get(k + 1).ok_or(format!("{} needs a value", args[k]))?;
        match args[k].as_str() {
            "--stop" => stops = value.split(',').map(str::to_string).collect(),
            "--levels" => {
                levels = value.split(',').map(str::parse).collect::<Result<_, _>>()?;
            }
            "--limit" => limit = value.parse()?,
            "--write" => write = Some(PathBuf::from(value)),
            "--csv" => csv = Some(PathBuf::from(value)),
            "--score" => {
                let (name, dir) = value.split_once('=').ok_or("--score wants NAME=DIR")?;
                outside.push((name.to_string(), PathBuf::from(dir)));
            }
            other => return Err(format!("unknown argument {other:?}").into()),
        }
        k += 2;
    }
    stops.retain(|s| s != "none");
    let rules: Vec<Rule> = stops.iter().map(|s| Rule::parse(s)).collect::<Result<_, _>>()?;
    let dir = data_dir("curves");
    let cases: Vec<_> =
        read_index(&dir)?.into_iter().filter(|c| c.category == "manifold").take(limit).collect();
    let columns: Vec<String> =
        stops.iter().cloned().chain(outside.iter().map(|(n, _)| n.clone())).collect();
    let mut tally: Tally = BTreeMap::new();
    let mut rows = String::from("level,case,n,column,rmse,seconds\n");
    for (l, &level) in levels.iter().enumerate() {
        for (i, case) in cases.iter().enumerate() {
            let (clean, gt) = case.read(&dir)?;
            let points = uniform_noise(&clean, level, 1000 * (l as u64 + 1) + i as u64)?;
            let dt = Triangulation::new(&points)?;
            if let Some(out) = &write {
                let folder = out.join(format!("{level}"));
                std::fs::create_dir_all(&folder)?;
                let text: String =
                    points.iter().map(|p| format!("{:?} {:?}\n", p[0], p[1])).collect();
                std::fs::write(folder.join(format!("{}.xy", case.name)), text)?;
                std::fs::write(
                    folder.join(format!("{}.n", case.name)),
                    format!("{}\n", dt.num_vertices()),
                )?;
            }
            let diag = diagonal(&points);
            let mut score =
                |column: usize, rec: &Reconstruction, seconds: f64| -> Result<(), Box<dyn Error>> {
                    let e = reconstruction_distance_errors(&points, rec, &clean, &gt)?;
                    let entry = tally.entry((l, column)).or_default();
                    entry.2 += seconds;
                    let rmse = e.map(|e| e.rmse);
                    match rmse {
                        Some(r) => entry.0.push(r),
                        None => entry.1 += 1,
                    }
                    let rmse = rmse.map_or(String::new(), |r| format!("{r:e}"));
                    writeln!(
                        rows,
                        "{level},{},{},{},{rmse},{seconds}",
                        case.name,
                        points.len(),
                        columns[column]
                    )?;
                    Ok(())
                };
            for (c, rule) in rules.iter().enumerate() {
                let start = Instant::now();
                let rec = optimal_transport_with(&dt, rule.stop(dt.num_vertices(), diag))?;
                score(c, &rec, start.elapsed().as_secs_f64())?;
            }
            for (j, (_, out)) in outside.iter().enumerate() {
                let path = out.join(format!("{level}")).join(format!("{}.segments", case.name));
                let rec = read_segments(&path)?;
                score(rules.len() + j, &rec, 0.0)?;
            }
        }
    }
    if let Some(path) = csv {
        std::fs::write(path, rows)?;
    }
    println!(
        "RMSE as a fraction of the diagonal over {} manifold cases: mean and median of the \
         runs with edges, runs without, seconds",
        cases.len()
    );
    print!("| level |");
    columns.iter().for_each(|c| print!(" {c} |"));
    println!("\n|---|{}", "---|".repeat(columns.len()));
    for (l, level) in levels.iter().enumerate() {
        print!("| {level} |");
        for c in 0..columns.len() {
            let (mut rmse, failed, seconds) = tally.get(&(l, c)).cloned().unwrap_or_default();
            rmse.sort_by(f64::total_cmp);
            let mean = rmse.iter().sum::<f64>() / rmse.len().max(1) as f64;
            let median = rmse.get(rmse.len() / 2).copied().unwrap_or(f64::NAN);
            print!(" {mean:.2e} / {median:.2e}, {failed}, {seconds:.1} s |");
        }
        println!();
    }
    Ok(())
}

/// The diagonal of the bounding box of `points`.
fn diagonal(points: &[Point]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

/// Segments `x0 y0 x1 y1`, one per line, as a result over vertices of its own (endpoints
/// with equal coordinates are one vertex).
fn read_segments(path: &std::path::Path) -> Result<Reconstruction, Box<dyn Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut vertices: Vec<Point> = Vec::new();
    let mut index: BTreeMap<(u64, u64), usize> = BTreeMap::new();
    let mut edges: Vec<Edge> = Vec::new();
    for line in text.lines().filter(|l| !l.trim().is_empty()) {
        let v: Vec<f64> = line.split_whitespace().map(str::parse).collect::<Result<_, _>>()?;
        let [x0, y0, x1, y1] = v[..] else {
            return Err(format!("{}: {line:?}", path.display()).into());
        };
        let mut id = |p: Point| {
            *index.entry((p[0].to_bits(), p[1].to_bits())).or_insert_with(|| {
                vertices.push(p);
                vertices.len() - 1
            })
        };
        let (a, b) = (id([x0, y0]), id([x1, y1]));
        if a != b {
            edges.push([a.min(b), a.max(b)]);
        }
    }
    edges.sort_unstable();
    edges.dedup();
    Ok(Reconstruction { edges, vertices: Vertices::New(vertices), ..Reconstruction::default() })
}
