//! Speed benchmark: the Delaunay step against the whole SIG-CONNECT2D pipeline, plus memory.
//!
//! ```text
//! cargo run --release -p sigdt --example speed                       # n = 1e3, 1e4, 1e5, 1e6
//! cargo run --release -p sigdt --example speed -- --sizes 1000,1e4 --reps 5
//! ```
//!
//! Inputs: `closed-curve` is [`random_closed_curve`]`(1, n)`, a smooth 12-harmonic blob
//! sampled uniformly; `spiral-band` is [`spiral_band`]`(n)`, a long thin coiled band (the hard
//! case for Delaunay insertion order). Both are shuffled with seed 7, so the input order
//! carries no curve order. A Markdown table goes to stdout, progress to stderr. Columns:
//!
//! - `input`, `n`: the input and its number of points.
//! - `Delaunay ms`: median wall time of [`Triangulation::new`] (validation, deduplication,
//!   insertion order, triangulation).
//! - `total ms`: median wall time of [`sigdt::reconstruct`] with default options, which
//!   builds its own triangulation.
//! - `total/Delaunay`: ratio of the two medians: how much the pipeline adds to the Delaunay step.
//! - `ns/point (total)`: `total ms` per input point.
//! - `peak MiB`, `peak bytes/point`: peak memory of one `reconstruct` call beyond what the
//!   process held just before it (so the input points are excluded).
//! - `exact`: whether the reconstructed edges equal the ground-truth cycle.
//!
//! Timing: after one warm-up run of each, the two calls alternate `R` times (so machine noise
//! hits both alike) and the medians are reported. By default `R` is the smallest count that
//! makes each measurement last at least 0.3 s, clamped to `3..=50`; `--reps R` fixes it. Every
//! run is single-threaded.
//!
//! Memory: exact heap bytes, counted by a pass-through `#[global_allocator]`: the peak
//! during one `reconstruct` call minus what was allocated just before it (the result
//! returned by the call is included).
use sigdt::samplers::{random_closed_curve, spiral_band, Sample};
use sigdt::{Options, Point, Triangulation};
use std::alloc::{GlobalAlloc, Layout, System};
use std::error::Error;
use std::hint::black_box;
use std::io::Write;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

type Res<T> = Result<T, Box<dyn Error>>;
/// Makes the benchmark input with `n` points.
type Sampler = fn(usize) -> Sample;

/// Each measurement should last at least this long (seconds), within the repetition bounds.
const MIN_SECONDS: f64 = 0.3;
const MIN_REPS: usize = 3;
const MAX_REPS: usize = 50;
const USAGE: &str = "usage: speed [--sizes N,N,...] [--reps R]";

fn main() -> Res<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (sizes, reps) = parse_args(&args)?;
    let threads = std::thread::available_parallelism().map_or(1, |p| p.get());
    let (arch, os) = (std::env::consts::ARCH, std::env::consts::OS);
    println!(
        "Machine: {arch}-{os}, available parallelism {threads}; every run is single-threaded."
    );
    println!();
    println!(
        "| input | n | Delaunay ms | total ms | total/Delaunay | ns/point (total) | peak MiB \
         | peak bytes/point | exact |"
    );
    println!("|---|--:|--:|--:|--:|--:|--:|--:|:-:|");
    let inputs: [(&str, Sampler); 2] =
        [("closed-curve", |n| random_closed_curve(1, n)), ("spiral-band", spiral_band)];
    for (name, make) in inputs {
        for &n in &sizes {
            eprint!("{name} n={n}: sampling… ");
            let sample = make(n).shuffled(7);
            eprint!("timing… ");
            let timing = measure(&sample, reps)?;
            eprint!("{} repetitions; memory… ", timing.reps);
            let peak = peak_memory(&sample.points)?;
            eprintln!("done");
            let (dt, total) = (timing.delaunay * 1e3, timing.total * 1e3);
            let (mib, per_point) = match peak {
                Some(bytes) => {
                    let bytes = bytes as f64;
                    (format!("{:.1}", bytes / 1048576.0), format!("{:.0}", bytes / n as f64))
                }
                None => ("n/a".to_string(), "n/a".to_string()),
            };
            println!(
                "| {name} | {n} | {dt:.2} | {total:.2} | {:.2} | {:.0} | {mib} | {per_point} | {} |",
                total / dt,
                total * 1e6 / n as f64,
                if timing.exact { "yes" } else { "no" },
            );
            std::io::stdout().flush()?;
        }
    }
    Ok(())
}

/// Median times in seconds, the number of repetitions, and whether the output was exact.
struct Timing {
    delaunay: f64,
    total: f64,
    reps: usize,
    exact: bool,
}

/// Times `Triangulation::new` and `reconstruct` on the sample's points, interleaved.
fn measure(sample: &Sample, reps: Option<usize>) -> Res<Timing> {
    let points = &sample.points[..];
    let options = Options::default();
    // Warm-up: also checks the output and sizes the number of repetitions.
    let (first_dt, dt) = time(|| Triangulation::new(points))?;
    drop(dt);
    let (first_total, rec) = time(|| sigdt::reconstruct(points, &options))?;
    let exact = rec.edges == sample.edges;
    drop(rec);
    let reps = reps.unwrap_or_else(|| {
        let needed = (MIN_SECONDS / first_dt.min(first_total)).ceil();
        (needed.min(MAX_REPS as f64) as usize).max(MIN_REPS)
    });
    let (mut dts, mut totals) = (Vec::with_capacity(reps), Vec::with_capacity(reps));
    for _ in 0..reps {
        let (t, dt) = time(|| Triangulation::new(points))?;
        dts.push(t);
        drop(dt); // dropped outside the timed region
        let (t, rec) = time(|| sigdt::reconstruct(points, &options))?;
        totals.push(t);
        drop(rec);
    }
    Ok(Timing { delaunay: median(&mut dts), total: median(&mut totals), reps, exact })
}

/// Wall time of `f` in seconds, and its result (to be dropped by the caller, untimed).
fn time<T>(f: impl FnOnce() -> sigdt::Result<T>) -> sigdt::Result<(f64, T)> {
    let start = Instant::now();
    let out = black_box(f()?);
    Ok((start.elapsed().as_secs_f64(), out))
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let mid = values.len() / 2;
    if values.len() % 2 == 1 {
        values[mid]
    } else {
        0.5 * (values[mid - 1] + values[mid])
    }
}

/// Peak heap bytes of one `reconstruct` run on `points`, beyond what was allocated before
/// the call (the input points are excluded; the returned result is included).
fn peak_memory(points: &[Point]) -> Res<Option<u64>> {
    let options = Options::default();
    let baseline = CURRENT.load(Ordering::SeqCst);
    PEAK.store(baseline, Ordering::SeqCst);
    let rec = black_box(sigdt::reconstruct(points, &options)?);
    let peak = PEAK.load(Ordering::SeqCst);
    drop(rec);
    Ok(Some((peak - baseline) as u64))
}

/// Heap bytes allocated now, and the most since the last reset.
static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

/// The system allocator, counting bytes in [`CURRENT`] and [`PEAK`].
struct Counting;

// The only unsafe code in the workspace: a pass-through allocator for this benchmark.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grow(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        CURRENT.fetch_sub(layout.size(), Ordering::SeqCst);
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            CURRENT.fetch_sub(layout.size(), Ordering::SeqCst);
            grow(new_size);
        }
        p
    }
}

fn grow(bytes: usize) {
    let now = CURRENT.fetch_add(bytes, Ordering::SeqCst) + bytes;
    PEAK.fetch_max(now, Ordering::SeqCst);
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

fn parse_args(args: &[String]) -> Res<(Vec<usize>, Option<usize>)> {
    let mut sizes = vec![1_000, 10_000, 100_000, 1_000_000];
    let mut reps = None;
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        if arg != "--sizes" && arg != "--reps" {
            return Err(format!("unknown argument {arg:?}; {USAGE}").into());
        }
        let value = it.next().ok_or_else(|| format!("{arg} needs a value; {USAGE}"))?;
        if arg == "--sizes" {
            sizes = value.split(',').map(parse_count).collect::<Res<_>>()?;
        } else {
            reps = Some(parse_count(value)?.max(1));
        }
    }
    Ok((sizes, reps))
}

/// A non-negative integer, written plainly (`10000`) or in exponent form (`1e4`).
fn parse_count(text: &str) -> Res<usize> {
    let text = text.trim();
    if let Ok(n) = text.parse() {
        return Ok(n);
    }
    match text.parse::<f64>() {
        Ok(x) if x >= 0.0 && x.fract() == 0.0 && x <= 1e15 => Ok(x as usize),
        _ => Err(format!("not a count: {text:?}; {USAGE}").into()),
    }
}
