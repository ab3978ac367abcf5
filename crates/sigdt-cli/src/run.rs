//! The commands: read the points, call the core crate, write the result.

use std::io::{self, Write};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use crate::format::OutputFormat;
use anyhow::Result;
use sigdt::{GraphKind, Options, Point, Reconstruction, Status};

use crate::args::{Cli, Command, GraphArgs, ReconstructArgs};
use crate::output::{is_dash, Output};

/// Runs the command in `cli`.
pub fn run(cli: Cli) -> Result<()> {
    MAX_POINTS.store(cli.max_points, Ordering::Relaxed);
    match cli.command {
        Command::Reconstruct(args) => reconstruct(&args),
        Command::Graph(args) => graph(&args),
        Command::Bench(args) => crate::bench::bench(&args),
        Command::Eval(args) => crate::bench::evaluate(&args),
        Command::BenchWorker(args) => crate::bench::worker(&args),
        Command::Sample(args) => crate::generate::sample(&args),
        Command::Perturb(args) => crate::generate::perturb(&args),
        Command::Sweep(args) => crate::sweep::sweep(&args),
        Command::Render(args) => crate::picture::render(&args),
        Command::View(args) => crate::picture::view(&args),
    }
}

/// The one-line message for `err`: its own text, then each cause whose text it does not
/// already contain, all on one line.
pub fn message(err: &anyhow::Error) -> String {
    let mut text = err.to_string();
    for cause in err.chain().skip(1) {
        let cause = cause.to_string();
        if !text.contains(&cause) {
            text.push_str(": ");
            text.push_str(&cause);
        }
    }
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// `sigdt reconstruct`.
fn reconstruct(args: &ReconstructArgs) -> Result<()> {
    let output = Output::new(args.output.as_deref(), &args.input)?;
    let format = args
        .format
        .or_else(|| args.output.as_deref().and_then(OutputFormat::from_path))
        .unwrap_or_default();
    let points = read_input(&args.input)?;
    let options = Options { method: args.method, leaf_elimination: !args.no_leaf_elimination };
    let start = Instant::now();
    let rec = sigdt::reconstruct(&points, &options)?;
    let elapsed = start.elapsed().as_secs_f64() * 1e3;
    if args.verbose {
        summary(&options, &rec, elapsed);
    } else if let Status::SculptingStuck { .. } = rec.status {
        note(&format!("sigdt: warning: {}", rec.status));
    }
    output.write(|w| format.write(w, &points, &rec))
}

/// `sigdt graph`.
fn graph(args: &GraphArgs) -> Result<()> {
    let output = Output::new(args.output.as_deref(), &args.input)?;
    let kind = GraphKind::from_name(&args.kind, args.k)?;
    let points = read_input(&args.input)?;
    let edges = sigdt::proximity_graph(&points, kind)?;
    output.write(|w| sigdt::io::write_edges(w, &edges))
}

/// `--max-points` of this run: the one setting every command's input reading shares.
static MAX_POINTS: AtomicUsize = AtomicUsize::new(crate::args::DEFAULT_MAX_POINTS);

/// The points of `input`, a file or `-` for standard input (at most `--max-points`).
pub fn read_input(input: &Path) -> Result<Vec<Point>> {
    let max = MAX_POINTS.load(Ordering::Relaxed);
    if is_dash(input) {
        Ok(sigdt::io::parse_points_at_most(io::stdin().lock(), "<stdin>", None, max)?)
    } else {
        Ok(sigdt::io::read_points_at_most(input, max)?)
    }
}

/// Prints the `--verbose` summary of a run to stderr.
fn summary(options: &Options, rec: &Reconstruction, ms: f64) {
    let s = &rec.stats;
    let method = match options.method {
        // CONNECT2D always adds leaf edges to its BC0; the option applies to SIGDT only.
        sigdt::Method::Connect2d => options.method.to_string(),
        _ => {
            let leaves = if options.leaf_elimination { "on" } else { "off" };
            format!("{} (leaf elimination {leaves})", options.method)
        }
    };
    let lines = [
        format!("method:                    {method}"),
        format!("points:                    {}", s.points),
        format!("distinct points:           {}", s.distinct_points),
        format!("duplicates:                {}", rec.duplicates.len()),
        format!("edges:                     {}", rec.edges.len()),
        format!("loops:                     {}", rec.loops.len()),
        format!("paths:                     {}", rec.paths.len()),
        format!("status:                    {} ({})", rec.status.name(), rec.status),
        format!("time:                      {ms:.3} ms"),
        format!("graph edges:               {}", s.graph_edges),
        format!("leaf edges added:          {}", s.leaf_edges_added),
        format!("non-manifold before:       {}", s.non_manifold_before),
        format!("inflated triangles:        {}", s.inflated_triangles),
        format!("pockets:                   {}", s.pockets),
        format!("interior before sculpting: {}", s.interior_before_sculpting),
        format!("sculpted triangles:        {}", s.sculpted_triangles),
    ];
    note(&lines.join("\n"));
}

/// Writes `text` and a newline to stderr; a closed stderr is ignored.
pub fn note(text: &str) {
    let _ = writeln!(io::stderr().lock(), "{text}");
}
