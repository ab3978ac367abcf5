//! The command line: the subcommands, the global flags and the help texts they share.
//!
//! Everything clap can check is checked here or in the subcommands' argument structs (one
//! per file of [`cmd`](crate::cmd)), so that a bad flag or value is a usage error (exit status
//! 2) reported before any file is touched.

use clap::builder::RangedU64ValueParser;
use clap::{Parser, Subcommand};

use crate::cmd::bench::BenchArgs;
use crate::cmd::bench_worker::WorkerArgs;
use crate::cmd::completions::{CompletionsArgs, ManpagesArgs};
use crate::cmd::eval::EvalArgs;
use crate::cmd::gallery::GalleryArgs;
use crate::cmd::graph::GraphArgs;
use crate::cmd::perturb::PerturbArgs;
use crate::cmd::reconstruct::ReconstructArgs;
use crate::cmd::render::RenderArgs;
use crate::cmd::sample::SampleArgs;
use crate::cmd::sweep::SweepArgs;
use crate::cmd::view::ViewArgs;

/// The input formats, shown in `sigdt --help` and `sigdt <command> --help`.
const INPUT_FORMATS: &str = "\
Input (INPUT is a file, or '-' for standard input):
  plain (.xy .p2d .txt .csv .pts)  one point per line: two numbers separated by spaces,
                                   tabs or a comma ('1.5 2', '1.5,2'); '#' starts a
                                   comment; blank lines are skipped; the first line may
                                   be a header if none of its fields is a number ('x,y')
  .gtn (Dey's CurveRecon)          a header 'N 2 0 0', then N lines 'index x y'
  CSV table (.csv .tsv)            ',' ';' or tab separators, quoted fields, a header row;
                                   x and y from --columns X,Y (names or numbers from 1),
                                   else columns named x/y, lon/lat (lng, long,
                                   longitude / latitude) or easting/northing (e/n) in
                                   any order, else the only two; ';' files may use
                                   decimal commas ('1,5' is 1.5, so '1,000' is 1.0)
  WKT (.wkt)                       POINT, MULTIPOINT, LINESTRING, POLYGON, MULTI*,
                                   GEOMETRYCOLLECTION: every vertex (a ring's closing
                                   vertex once)
  GeoJSON (.geojson .json)         FeatureCollection, Feature, any geometry: every
                                   position; also a JSON array of [x, y] pairs
  NumPy (.npy)                     an (n, 2) array of floats or integers
  GeoPackage (.gpkg)               every vertex of a feature layer: --layer NAME, else the
                                   only layer, else the only point layer; read in place
  FlatGeobuf (.fgb)                every vertex of every feature
  Shapefile (.shp)                 every vertex of every record; the coordinate system
                                   from the .prj beside it
  gzip (.gz)                       any of these compressed, read as it is decompressed
  other extensions and stdin       the format is detected from the content
Points are numbered from 0 in file order; all indices in the output refer to them.
NaN or infinite coordinates, and lines that are not two numbers, are errors.";

/// The result statuses, shown in `sigdt --help` and `sigdt reconstruct --help`.
const STATUSES: &str = "\
Result status (printed with --verbose; also in geojson's properties):
  polygon          one closed simple polygon through every distinct point (sig-auto:
                   but the outliers it leaves out; --verbose counts them)
  polygons         several disjoint closed simple polygons, the same way
  sculpting-stuck  sculpting found no candidate while points were still inside: the loops
                   are simple but miss those points (a warning goes to stderr)
  curves           (sig-auto, graph filters) loops and open paths, not all points on loops
  network          (sig-auto) curves that meet: junctions read as such (--verbose lists
                   them; paths run between junctions and ends)
  branching        (graph-filter methods) some point has 3 or more edges, which the method
                   does not read as a junction (a warning goes to stderr)
  noisy            (sig-auto) the edges zigzag somewhere: the points are too noisy or too
                   sparse for a curve through them there (a warning goes to stderr)
  collinear        all points on one line: the open path through them in line order
  too-few-points   fewer than 3 distinct points: 2 give their edge, 0 or 1 give nothing
Exact duplicate points get no edges: the lowest-index copy stands for all of them.
All of these are results, not errors (exit status 0).";

/// The output formats, shown in `sigdt reconstruct --help`.
const OUTPUT_FORMATS: &str = "\
Output formats (--format; default: from OUT's extension, else edges):
  edges    one edge per line, 'i j' with i < j, sorted      (.edges .txt)
  loops    one closed loop per line, its indices in order; open paths as 'path i j ...'
                                                             (.loops)
  wkt      POLYGON / MULTIPOLYGON / LINESTRING of the loops and paths   (.wkt)
  geojson  one Feature: the geometry, with status and counts as properties; no
           projected system (RFC 7946); longitude/latitude cut at the antimeridian
                                                             (.geojson .json)
  svg      a picture of the points, edges and filled loops   (.svg)
  gpkg     GeoPackage layers of one geometry type each, one feature per group (--by):
           'areas' (multi-polygons), 'paths' (open lines), 'networks' (lines with an end
           at a junction), each with method, status, warning, diagnosis, vertices; and
           'left_out' (points, input row, reason); in the input's coordinate system or
           --crs; longitude/latitude cut at the antimeridian            (.gpkg)
  fgb      FlatGeobuf: the same layers, one file each: areas in OUT, the others in
           STEM.paths.fgb, STEM.networks.fgb and STEM.left_out.fgb beside it  (.fgb)";

/// Exit statuses, shown in `sigdt --help`.
const EXIT_STATUS: &str = "\
Exit status: 0 on success (degenerate input included), 1 on an error (one line
'sigdt: <message>' on stderr), 2 on a usage error. Output files are written to a temporary
file and renamed into place, so a failed run never leaves a partial or truncated OUT.";

/// Reconstruct curves (polygons and open paths) from unorganised 2D points.
///
/// SIG-CONNECT2D (Marin, Ohrhallinger, Wimmer: "SIGDT: 2D Curve Reconstruction", Pacific
/// Graphics 2022) intersects the spheres-of-influence graph with the Delaunay triangulation,
/// then inflates and sculpts its boundary into polygons that interpolate every point. The
/// default method, SIG-AUTO, reads the same graph per component: open curves stay open,
/// nested curves separate, outliers are left out and noise is read at a coarser scale
/// (`--method sig-connect2d` for the paper's method). Neither has parameters.
#[derive(Debug, Parser)]
#[command(name = "sigdt", version, propagate_version = true)]
#[command(after_help = format!("{INPUT_FORMATS}\n\n{STATUSES}\n\n{EXIT_STATUS}"))]
#[command(arg_required_else_help = true)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
    /// Refuse input with more than N points: reading stops at the first line over the
    /// limit, so a huge file or stream is never read whole.
    #[arg(long, global = true, value_name = "N", default_value_t = DEFAULT_MAX_POINTS,
          value_parser = RangedU64ValueParser::<usize>::new().range(1..))]
    pub max_points: usize,
    /// Read the points from these columns of a CSV table: names from its header row or
    /// numbers from 1, for example `--columns lon,lat` or `--columns 3,4`.
    #[arg(long, global = true, value_name = "X,Y")]
    pub columns: Option<sigdt_io::Columns>,
    /// The GeoPackage layer to read the points from (by default the only layer, or the only
    /// point layer).
    #[arg(long, global = true, value_name = "NAME")]
    pub layer: Option<String>,
    /// The coordinate reference system of input that does not declare one (`EPSG:27700`,
    /// `EPSG:4326`), written to GeoPackage and FlatGeobuf output; a file that declares
    /// another is refused (sigdt does not transform coordinates).
    #[arg(long, global = true, value_name = "EPSG:N", value_parser = parse_crs)]
    pub crs: Option<sigdt_io::Crs>,
    /// Threads for the data-parallel passes (sorting, the triangulation, the SIGDT test, the
    /// boundary's vertex counts, the sampling check, nearest-neighbour queries);
    /// by default every core, or RAYON_NUM_THREADS when it is set; more than the cores count
    /// as the cores. The output is the same, byte for byte, at every thread count.
    #[arg(long, global = true, value_name = "N",
          value_parser = RangedU64ValueParser::<usize>::new().range(1..=1024))]
    pub threads: Option<usize>,
}

/// `--crs` values.
fn parse_crs(text: &str) -> Result<sigdt_io::Crs, String> {
    sigdt_io::Crs::parse(text)
}

/// Default of `--max-points`: 10^8 points (1.6 GB of coordinates).
const DEFAULT_MAX_POINTS: usize = 100_000_000;

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Reconstruct the curve(s) through the points and write the edges (or loops, WKT,
    /// GeoJSON, SVG).
    #[command(after_help = format!("{INPUT_FORMATS}\n\n{STATUSES}\n\n{OUTPUT_FORMATS}"))]
    Reconstruct(ReconstructArgs),
    /// Write a proximity graph of the points, one edge 'i j' per line.
    #[command(after_help = INPUT_FORMATS)]
    Graph(GraphArgs),
    /// Run methods over every case of a labelled folder and write a report (Markdown
    /// table in the layout of the paper's Table 2, CSV, SVG charts).
    Bench(BenchArgs),
    /// Score one reconstruction against ground truth: exact, missing/extra edges, RMSE,
    /// Hausdorff, symmetric area difference, and the sample's graph-based epsilon.
    Eval(EvalArgs),
    /// Sample a cubic Bézier path of an SVG file so that every curve point is within
    /// eps x lfs of a sample (the paper's eps-sampling), optionally with lfs noise.
    Sample(SampleArgs),
    /// Add uniform noise (fraction of the bounding-box diagonal) or outliers to points.
    Perturb(PerturbArgs),
    /// RMSE and exact rate of every method against noise, outliers, lfs noise or eps,
    /// with charts (the paper's Figures 14, 16, 17, 18).
    Sweep(SweepArgs),
    /// Draw the points and chosen layers (Delaunay, SIG circles, SIGDT, SIGDT2, boundary
    /// after inflating, result, ground truth with missing and extra edges) as SVG or PNG.
    Render(RenderArgs),
    /// Draw chosen cases through every method, or each method's failures from a results.csv
    /// of `sigdt bench`, with a Markdown page (the paper's Table 1 and failure figures).
    Gallery(GalleryArgs),
    /// Write a self-contained HTML viewer: pan, zoom, layer toggles, and a slider that
    /// replays inflating and sculpting one triangle at a time.
    View(ViewArgs),
    /// Print a shell completion script (bash, zsh, fish, elvish, powershell).
    Completions(CompletionsArgs),
    /// Internal: write the man pages (`make man`).
    #[command(hide = true)]
    Manpages(ManpagesArgs),
    /// Internal: one method on one case, for `sigdt bench`.
    #[command(hide = true)]
    BenchWorker(WorkerArgs),
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn definitions_are_consistent() {
        Cli::command().debug_assert();
    }
}
