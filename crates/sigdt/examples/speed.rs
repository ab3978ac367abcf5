//! Speed benchmark: SIG-CONNECT2D against its own Delaunay step and against CGAL, memory,
//! and scaling to two threads.
//!
//! ```text
//! cargo run --release -p sigdt --example speed                       # n = 1e3 .. 1e6
//! cargo run --release -p sigdt --example speed -- --sizes 1e5,1e6,1e7 --reps 3 \
//!     --cgal target/cgal-delaunay --cli target/release/sigdt
//! ```
//!
//! Inputs: `closed-curve` is [`random_closed_curve`]`(1, n)`, a smooth 12-harmonic blob
//! sampled uniformly; `spiral-band` is [`spiral_band`]`(n)`, a long thin coiled band (the hard
//! case for Delaunay insertion order). Each comes `shuffled` (seed 7: the input order
//! carries no curve order) and in `curve` order. Markdown tables go to stdout, progress to
//! stderr.
//!
//! **In process** (one row per input, order and size):
//! - `Delaunay ms`: median wall time of [`Triangulation::new`] on one thread.
//! - `total ms`: median wall time of [`sigdt::reconstruct`] with SIG-CONNECT2D (which builds
//!   its own triangulation) on one thread; `total/Delaunay` their ratio.
//! - `CGAL ms`: median time of a bare CGAL 2D Delaunay triangulation of the same points
//!   (`Delaunay_triangulation_2`, Epick, range insert with its spatial sort), measured inside
//!   the external tool `tools/cgal-delaunay` (`--cgal PATH`; the column says `n/a` without it);
//!   `total/CGAL` is `total ms` over it.
//! - `ns/point`: `total ms` per point.
//! - `T threads ms`, `speed-up`: `reconstruct` on a pool of `T` threads (`--threads T`,
//!   default: the available parallelism) and the one-thread time over it. Every result is
//!   checked to equal the one-thread result.
//! - `divided ms`: median wall time of the divide-and-conquer triangulation
//!   (`Triangulation::new_divided`, one part a thread, joined by the Guibas–Stolfi merge) on
//!   the pool of `T` threads, as `reconstruct` builds it there; `Delaunay/divided` is the
//!   one-thread insertion over it. Its triangle count is checked.
//! - `default ms`, `default {T} threads ms`: the same for the default method, SIG-AUTO
//!   (`Options::default()`), on one thread and on `T`; `default/CGAL` is the `T`-thread
//!   time over CGAL's one-thread triangulation. The `T`-thread result is checked to equal
//!   the one-thread result.
//! - `peak bytes/point`: heap high-water mark of one one-thread `reconstruct` call beyond
//!   what the process held before it (the input points excluded), counted exactly by a
//!   pass-through allocator; `T threads peak` the same on the pool of `T` threads (where
//!   the triangulation is divided among them).
//! - `exact`: whether the edges equal the ground-truth cycle.
//!
//! Timing: after one warm-up, the calls alternate `R` times (so machine noise hits all of
//! them alike), the CGAL tool running once per round; medians are reported. By default `R`
//! is the smallest count that makes each measurement last at least 0.3 s, clamped to
//! `3..=50`; `--reps R` fixes it.
//!
//! **Whole process** (with `--cli PATH`, the `sigdt` binary, for `n >= 1e5`): the points are
//! written to a temporary file; `sigdt reconstruct FILE --method sig-connect2d -o OUT` with
//! one thread (`RAYON_NUM_THREADS=1`) and with `T`, and `cgal-delaunay FILE` (read and triangulate) run
//! in turn `R` times under `/usr/bin/time`: median wall seconds, and the peak resident memory
//! (`%M`) per point of `sigdt reconstruct`; then `sigdt view FILE -o PAGE` (its median time
//! and the page's size) and `sigdt render FILE -o PICTURE.png`, each with `T` threads; and
//! the default method (`sigdt reconstruct FILE -o OUT`) with `T` threads, its time over
//! CGAL's in `default / CGAL`.
use rayon::{ThreadPool, ThreadPoolBuilder};
use sigdt::samplers::{random_closed_curve, spiral_band, Sample};
use sigdt::{Method, Options, Point, Triangulation};
use std::alloc::{GlobalAlloc, Layout, System};
use std::error::Error;
use std::hint::black_box;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

type Res<T> = Result<T, Box<dyn Error>>;
/// Makes the benchmark input with `n` points.
type Sampler = fn(usize) -> Sample;

/// Each measurement should last at least this long (seconds), within the repetition bounds.
const MIN_SECONDS: f64 = 0.3;
const MIN_REPS: usize = 3;
const MAX_REPS: usize = 50;
const USAGE: &str =
    "usage: speed [--sizes N,N,...] [--reps R] [--threads T] [--cgal PATH] [--cli PATH]";

struct Args {
    sizes: Vec<usize>,
    reps: Option<usize>,
    threads: usize,
    cgal: Option<PathBuf>,
    cli: Option<PathBuf>,
}

fn main() -> Res<()> {
    let args = parse_args(&std::env::args().skip(1).collect::<Vec<_>>())?;
    let (arch, os) = (std::env::consts::ARCH, std::env::consts::OS);
    let cores = std::thread::available_parallelism().map_or(1, |p| p.get());
    println!("Machine: {arch}-{os}, available parallelism {cores}.");
    println!();
    let t = args.threads;
    println!(
        "| input | order | n | Delaunay ms | total ms | total/Delaunay | CGAL ms | total/CGAL \
         | ns/point | {t} threads ms | speed-up | divided ms | Delaunay/divided \
         | default ms | default {t} threads ms | default/CGAL \
         | peak bytes/point | {t} threads peak | exact |"
    );
    println!("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|:-:|");
    let one = ThreadPoolBuilder::new().num_threads(1).build()?;
    let many = ThreadPoolBuilder::new().num_threads(t).build()?;
    let dir = std::env::temp_dir().join(format!("sigdt-speed-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let mut process_rows = Vec::new();
    let inputs: [(&str, Sampler); 2] =
        [("closed-curve", |n| random_closed_curve(1, n)), ("spiral-band", spiral_band)];
    for (name, make) in inputs {
        for &n in &args.sizes {
            eprint!("{name} n={n}: sampling… ");
            let curve = make(n);
            for (order, sample) in [("shuffled", curve.shuffled(7)), ("curve", curve.clone())] {
                let file = dir.join(format!("{name}-{order}-{n}.xy"));
                let needs_file = args.cgal.is_some() || (args.cli.is_some() && n >= 100_000);
                if needs_file {
                    write_points(&file, &sample.points)?;
                }
                eprint!("{order}: timing… ");
                let cgal = args.cgal.as_deref().filter(|_| needs_file).map(|c| (c, file.as_path()));
                let m = measure(&sample, args.reps, &one, &many, cgal)?;
                eprint!("{} repetitions; memory… ", m.reps);
                let peak = one.install(|| peak_memory(&sample.points))?;
                let peak_many = many.install(|| peak_memory(&sample.points))?;
                let (dt, total, total_t) = (m.delaunay * 1e3, m.total * 1e3, m.total_many * 1e3);
                let divided = m.divided * 1e3;
                let (auto, auto_t) = (m.default * 1e3, m.default_many * 1e3);
                let cgal_ms = m.cgal.map(|c| c * 1e3);
                println!(
                    "| {name} | {order} | {n} | {dt:.2} | {total:.2} | {:.2} | {} | {} | {:.0} \
                     | {total_t:.2} | {:.2} | {divided:.2} | {:.2} | {auto:.2} | {auto_t:.2} | {} \
                     | {:.0} | {:.0} | {} |",
                    total / dt,
                    cgal_ms.map_or("n/a".into(), |c| format!("{c:.2}")),
                    cgal_ms.map_or("n/a".into(), |c| format!("{:.2}", total / c)),
                    total * 1e6 / n as f64,
                    total / total_t,
                    dt / divided,
                    cgal_ms.map_or("n/a".into(), |c| format!("{:.2}", auto_t / c)),
                    peak as f64 / n as f64,
                    peak_many as f64 / n as f64,
                    if m.exact { "yes" } else { "no" },
                );
                std::io::stdout().flush()?;
                if let Some(cli) = args.cli.as_deref().filter(|_| n >= 100_000) {
                    eprint!("whole process… ");
                    let row = whole_process(cli, args.cgal.as_deref(), &file, n, t, &args, &dir)?;
                    process_rows.push(format!("| {name} | {order} | {n} | {row}"));
                }
                if needs_file {
                    std::fs::remove_file(&file)?;
                }
                eprintln!("done");
            }
        }
    }
    if !process_rows.is_empty() {
        println!();
        println!(
            "| input | order | n | `sigdt reconstruct` s, 1 thread | {t} threads s | speed-up \
             | `cgal-delaunay` s | sigdt (1 thread) / CGAL | default, {t} threads s \
             | default / CGAL | peak RSS bytes/point | `sigdt view` s | its page MB \
             | `sigdt render` (PNG) s |"
        );
        println!("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|");
        for row in process_rows {
            println!("{row}");
        }
    }
    std::fs::remove_dir_all(&dir)?;
    Ok(())
}

/// Median times in seconds, the number of repetitions, and whether the output was exact.
struct Measured {
    delaunay: f64,
    total: f64,
    total_many: f64,
    divided: f64,
    /// The default method (SIG-AUTO) on one thread and on the pool.
    default: f64,
    default_many: f64,
    cgal: Option<f64>,
    reps: usize,
    exact: bool,
}

/// Times `Triangulation::new` and `reconstruct` (one thread and many) on the sample's
/// points, and the CGAL tool on their file, interleaved.
fn measure(
    sample: &Sample,
    reps: Option<usize>,
    one: &ThreadPool,
    many: &ThreadPool,
    cgal: Option<(&Path, &Path)>,
) -> Res<Measured> {
    let points = &sample.points[..];
    let options = Options { method: Method::SigConnect2d, ..Options::default() };
    let delaunay = || one.install(|| time(|| Triangulation::new(points)));
    let halvings = many.current_num_threads().next_power_of_two().trailing_zeros();
    let divided = || many.install(|| time(|| Triangulation::new_divided(points, halvings)));
    let total = |pool: &ThreadPool| pool.install(|| time(|| sigdt::reconstruct(points, &options)));
    let default = Options::default();
    let auto = |pool: &ThreadPool| pool.install(|| time(|| sigdt::reconstruct(points, &default)));
    // Warm-up: also checks the output and sizes the number of repetitions.
    let (first_dt, dt) = delaunay()?;
    drop(dt);
    let (first_total, rec) = total(one)?;
    let exact = rec.edges == sample.edges;
    let (_, auto_rec) = auto(one)?;
    let reps = reps.unwrap_or_else(|| {
        let needed = (MIN_SECONDS / first_dt.min(first_total)).ceil();
        (needed.min(MAX_REPS as f64) as usize).max(MIN_REPS)
    });
    let (mut dts, mut totals, mut manys, mut cgals) = (vec![], vec![], vec![], vec![]);
    let (mut divideds, mut autos, mut autos_many) = (vec![], vec![], vec![]);
    for _ in 0..reps {
        let (t, dt) = delaunay()?;
        dts.push(t);
        let (t, parts) = divided()?;
        divideds.push(t);
        if parts.num_triangles() != dt.num_triangles() {
            return Err("the divided triangulation has another triangle count".into());
        }
        drop((dt, parts)); // dropped outside the timed region
        let (t, r) = total(one)?;
        totals.push(t);
        drop(r);
        let (t, r) = total(many)?;
        manys.push(t);
        if r != rec {
            return Err("the result on several threads differs from the one-thread result".into());
        }
        drop(r);
        let (t, r) = auto(one)?;
        autos.push(t);
        drop(r);
        let (t, r) = auto(many)?;
        autos_many.push(t);
        if r != auto_rec {
            return Err("the default's result on several threads differs from one thread's".into());
        }
        drop(r);
        if let Some((tool, file)) = cgal {
            cgals.push(cgal_time(tool, file)?);
        }
    }
    Ok(Measured {
        delaunay: median(&mut dts),
        total: median(&mut totals),
        total_many: median(&mut manys),
        divided: median(&mut divideds),
        default: median(&mut autos),
        default_many: median(&mut autos_many),
        cgal: (!cgals.is_empty()).then(|| median(&mut cgals)),
        reps,
        exact,
    })
}

/// The triangulation time (seconds) that `cgal-delaunay FILE` reports.
fn cgal_time(tool: &Path, file: &Path) -> Res<f64> {
    let out = Command::new(tool).arg(file).output()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let ms = text
        .split_whitespace()
        .find_map(|w| w.strip_prefix("ms="))
        .ok_or_else(|| format!("{}: unexpected output {text:?}", tool.display()))?;
    Ok(ms.parse::<f64>()? / 1e3)
}

/// `sigdt view` and `sigdt render` refuse more points than this (their pages and pictures
/// would not be usable); their columns say `n/a` above it.
const MAX_PICTURE_POINTS: usize = 2_000_000;

/// One row of the whole-process table: `sigdt reconstruct` on one and `t` threads,
/// `cgal-delaunay`, and `sigdt view` and `sigdt render` (a PNG) on `t` threads, in turn,
/// under `/usr/bin/time`.
fn whole_process(
    cli: &Path,
    cgal: Option<&Path>,
    file: &Path,
    n: usize,
    t: usize,
    args: &Args,
    dir: &Path,
) -> Res<String> {
    let (out, page, picture) = (dir.join("out.edges"), dir.join("view.html"), dir.join("p.png"));
    let run = |program: &Path, threads: usize, arguments: &[&Path]| -> Res<(f64, f64)> {
        let mut cmd = Command::new("/usr/bin/time");
        cmd.args(["-f", "%e %M"]).arg(program).env("RAYON_NUM_THREADS", threads.to_string());
        cmd.args(arguments);
        let o = cmd.output()?;
        let text = String::from_utf8_lossy(&o.stderr);
        let last = text.lines().last().unwrap_or_default();
        let mut it = last.split_whitespace().map(str::parse::<f64>);
        match (it.next(), it.next()) {
            (Some(Ok(s)), Some(Ok(kb))) if o.status.success() => Ok((s, kb * 1024.0)),
            _ => Err(format!("{}: failed: {text}", program.display()).into()),
        }
    };
    let o = Path::new("-o");
    // SIG-CONNECT2D, as in the in-process table; the default (SIG-AUTO) has its own column.
    let (method, name) = (Path::new("--method"), Path::new("sig-connect2d"));
    let reconstruct = [Path::new("reconstruct"), file, method, name, o, &out];
    let default = [Path::new("reconstruct"), file, o, &out];
    let view = [Path::new("view"), file, o, &page];
    let render = [Path::new("render"), file, o, &picture];
    let reps = args.reps.unwrap_or(MIN_REPS);
    let (mut ones, mut manys, mut cgals, mut rss) = (vec![], vec![], vec![], vec![]);
    let (mut views, mut renders, mut defaults) = (vec![], vec![], vec![]);
    for _ in 0..reps {
        let (s, bytes) = run(cli, 1, &reconstruct)?;
        ones.push(s);
        rss.push(bytes);
        manys.push(run(cli, t, &reconstruct)?.0);
        defaults.push(run(cli, t, &default)?.0);
        if let Some(c) = cgal {
            cgals.push(run(c, 1, &[file])?.0);
        }
        if n <= MAX_PICTURE_POINTS {
            views.push(run(cli, t, &view)?.0);
            renders.push(run(cli, t, &render)?.0);
        }
    }
    let (one, many, peak) = (median(&mut ones), median(&mut manys), median(&mut rss));
    let auto = median(&mut defaults);
    let cgal = (!cgals.is_empty()).then(|| median(&mut cgals));
    let cell = |x: Option<f64>| x.map_or("n/a".into(), |x| format!("{x:.2}"));
    // A page of an earlier, smaller size may still lie there.
    let page_mb = match views.is_empty() {
        true => None,
        false => Some(std::fs::metadata(&page)?.len() as f64 / 1e6),
    };
    Ok(format!(
        "{one:.2} | {many:.2} | {:.2} | {} | {} | {auto:.2} | {} | {:.0} | {} | {} | {} |",
        one / many,
        cell(cgal),
        cell(cgal.map(|c| one / c)),
        cell(cgal.map(|c| auto / c)),
        peak / n as f64,
        cell((!views.is_empty()).then(|| median(&mut views))),
        page_mb.map_or("n/a".into(), |mb| format!("{mb:.1}")),
        cell((!renders.is_empty()).then(|| median(&mut renders))),
    ))
}

/// Writes `points` as `x y` lines (shortest round-trip decimal form).
fn write_points(path: &Path, points: &[Point]) -> Res<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    for p in points {
        writeln!(w, "{} {}", p[0], p[1])?;
    }
    w.flush()?;
    Ok(())
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
fn peak_memory(points: &[Point]) -> sigdt::Result<usize> {
    let options = Options { method: Method::SigConnect2d, ..Options::default() };
    let baseline = CURRENT.load(Ordering::SeqCst);
    PEAK.store(baseline, Ordering::SeqCst);
    let rec = black_box(sigdt::reconstruct(points, &options)?);
    let peak = PEAK.load(Ordering::SeqCst);
    drop(rec);
    Ok(peak - baseline)
}

/// Heap bytes allocated now, and the most since the last reset.
static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

/// The system allocator, counting bytes in [`CURRENT`] and [`PEAK`].
struct Counting;

// Unsafe code, as in the CLI's allocator (`sigdt-cli/src/allocation_failure.rs`): a
// pass-through allocator for this benchmark.
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

fn parse_args(args: &[String]) -> Res<Args> {
    let threads = std::thread::available_parallelism().map_or(1, |p| p.get()).max(2);
    let mut out = Args {
        sizes: vec![1_000, 10_000, 100_000, 1_000_000],
        reps: None,
        threads,
        cgal: None,
        cli: None,
    };
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let value = it.next().ok_or_else(|| format!("{arg} needs a value; {USAGE}"))?;
        match arg.as_str() {
            "--sizes" => out.sizes = value.split(',').map(parse_count).collect::<Res<_>>()?,
            "--reps" => out.reps = Some(parse_count(value)?.max(1)),
            "--threads" => out.threads = parse_count(value)?.max(1),
            "--cgal" => out.cgal = Some(PathBuf::from(value)).filter(|p| p.exists()),
            "--cli" => out.cli = Some(PathBuf::from(value)).filter(|p| p.exists()),
            _ => return Err(format!("unknown argument {arg:?}; {USAGE}").into()),
        }
    }
    Ok(out)
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
