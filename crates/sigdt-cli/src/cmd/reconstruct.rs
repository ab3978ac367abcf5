//! `sigdt reconstruct`: the curve(s) through the points, in one of the output formats.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{bail, Result};
use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::Args;
use sigdt::{Expect, Method, Options, Point, Reconstruction, Vertices};
use sigdt_io::attributes::Grouping;
use sigdt_io::text::OutputFormat as TextFormat;
use sigdt_io::Crs;

use crate::format::{Context, OutputFormat};
use crate::gis_output::GisFiles;
use crate::input::Input;
use crate::messages::{note, UsageError};
use crate::output::{is_dash, Output};
use sigdt_io::gis::layers::Layers;
use sigdt_io::gis::local::{reconstruct_in_plane, why_degrees};

/// `sigdt reconstruct`.
#[derive(Debug, Args)]
pub struct ReconstructArgs {
    /// Point file, or '-' for standard input.
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,
    /// Write the result to OUT instead of standard output ('-' is standard output).
    #[arg(short, long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,
    /// Output format [default: from OUT's extension, else edges].
    #[arg(long, value_name = "FORMAT", value_parser = format_parser())]
    pub format: Option<OutputFormat>,
    /// Reconstruction method.
    #[arg(long, value_name = "METHOD", value_parser = crate::methods::parser(),
          default_value_t = Method::default())]
    pub method: Method,
    /// Do not give SIGDT leaves their shortest missing Delaunay edge before inflating
    /// (leaf elimination, SIGDT2, is on by default; with --method sig-connect2d only).
    #[arg(long)]
    pub no_leaf_elimination: bool,
    /// What the points outline, as far as you know: 'curves' (open or closed, as they read)
    /// or 'areas' (every curve is a closed outline: polygon vertices, parcels, islands).
    /// With 'areas', SIG-AUTO closes open readings where a polygon fits as well, and any
    /// open line left is a warning (open-outlines).
    #[arg(long, value_name = "WHAT", default_value_t = Expect::default(),
          value_parser = |s: &str| s.parse::<Expect>().map_err(|e| e.to_string()))]
    pub expect: Expect,
    /// Reconstruct the points in groups, by the value of this attribute column (a
    /// GeoPackage layer's column, a Shapefile's .dbf field, a FlatGeobuf column, or a CSV
    /// table's column), and write one feature per group per layer with the attributes that
    /// are the same on all of a group's points (GeoPackage or FlatGeobuf output only).
    #[arg(long, value_name = "COLUMN")]
    pub by: Option<String>,
    /// GeoJSON output of points in a projected coordinate system: write them with the
    /// legacy 'crs' member of GeoJSON 2008 (which RFC 7946 removed; QGIS and GDAL still read
    /// it) instead of refusing.
    #[arg(long)]
    pub geojson_legacy_crs: bool,
    /// Print a summary (counts, status, time, per-stage statistics) to stderr.
    #[arg(short, long)]
    pub verbose: bool,
}

/// `sigdt reconstruct`.
pub fn run(args: &ReconstructArgs, input: &Input) -> Result<()> {
    // The output named is checked first: it must not be the input, whatever its format.
    let output = Output::new(args.output.as_deref(), &args.input)?;
    let format = match (args.format, args.output.as_deref().filter(|p| !is_dash(p))) {
        (Some(format), _) => format,
        (None, None) => OutputFormat::default(),
        (None, Some(out)) => match (OutputFormat::from_path(out), out.extension()) {
            (Some(format), _) => format,
            (None, None) => OutputFormat::default(),
            // Edge text in a `.jpg` or `.pdf` would be a silent wrong answer.
            (None, Some(ext)) => {
                return Err(UsageError {
                    command: "reconstruct",
                    kind: clap::error::ErrorKind::InvalidValue,
                    message: format!(
                        "{}: '.{}' names no output format: use .edges, .txt, .loops, .wkt, \
                         .geojson, .json, .svg, .png, .gpkg or .fgb, or give --format",
                        out.display(),
                        ext.to_string_lossy()
                    ),
                }
                .into());
            }
        },
    };
    if args.by.is_some() && !format.is_gis() {
        return Err(UsageError {
            command: "reconstruct",
            kind: clap::error::ErrorKind::ArgumentConflict,
            message: format!(
                "--by: --format {format} holds one result, not one per group: write GIS layers \
                 (-o NAME.gpkg or NAME.fgb, or --format gpkg)"
            ),
        }
        .into());
    }
    // Every file is checked before any work is done.
    let destination = match format.is_gis() {
        true => Destination::Gis(GisFiles::new(format, args.output.as_deref(), &args.input)?),
        false => Destination::One(output),
    };
    if args.no_leaf_elimination && args.method != Method::SigConnect2d {
        // Dropping the flag without a word would hide that another method ran than the one
        // meant (SIG-CONNECT2D was the default before SIG-AUTO).
        return Err(UsageError {
            command: "reconstruct",
            kind: clap::error::ErrorKind::ArgumentConflict,
            message: format!(
                "--no-leaf-elimination applies to sig-connect2d only (give --method \
                 sig-connect2d); {} does not use it",
                args.method
            ),
        }
        .into());
    }
    let read = input.points_grouped(&args.input, args.by.as_deref())?;
    let (mut points, read_as, crs) = (read.points, read.how, read.crs);
    if let (OutputFormat::Text(TextFormat::GeoJson), Some(crs)) = (format, &crs) {
        if args.geojson_legacy_crs && crs.epsg.is_none() {
            bail!(
                "{}: --geojson-legacy-crs: the legacy crs member names a system by its EPSG \
                 code, and {crs}: write .gpkg or .fgb, which keep its definition",
                args.input.display()
            );
        }
        if crs.epsg != Some(4326) && !args.geojson_legacy_crs {
            // RFC 7946: GeoJSON coordinates are WGS 84 longitude and latitude; readers take
            // anything else for degrees.
            bail!(
                "{} is in {crs}, but GeoJSON is longitude/latitude on WGS 84 (RFC 7946) and \
                 sigdt does not transform coordinates: write .gpkg or .fgb, which keep the \
                 coordinate system (or give --geojson-legacy-crs)",
                args.input.display()
            );
        }
    }
    let options = Options {
        method: args.method,
        leaf_elimination: !args.no_leaf_elimination,
        expect: args.expect,
    };
    let degrees = why_degrees(crs.as_ref(), read.lon_lat);
    let read_as = match (&crs, &degrees) {
        (_, Some(why)) => format!(
            "{read_as}; {why}: reconstructed in an azimuthal equidistant plane centred on \
             the points, written in degrees"
        ),
        (Some(crs), None) => format!("{read_as}; in {crs}"),
        (None, None) => read_as,
    };
    if let (Some(grouping), Destination::Gis(files)) = (read.grouping, &destination) {
        return by_groups(args, &options, points, grouping, degrees.as_deref(), &read_as)
            .and_then(|layers| write_layers(files, &layers, crs.as_ref(), args.verbose));
    }
    let name = args.input.display().to_string();
    crate::memory::check(&name, points.len(), crate::memory::Cost::Reconstruct)?;
    let start = Instant::now();
    // Edges and loops are indices: the points can go once triangulated (less peak memory).
    let indices_only = matches!(format, OutputFormat::Text(TextFormat::Edges | TextFormat::Loops));
    let rec = match (indices_only, &degrees) {
        (true, None) => sigdt::reconstruct_owned(std::mem::take(&mut points), &options)?,
        (false, None) => sigdt::reconstruct(&points, &options)?,
        (_, Some(why)) => reconstruct_in_plane(&points, &options, why)?,
    };
    let elapsed = start.elapsed().as_secs_f64() * 1e3;
    if indices_only && matches!(rec.vertices, Vertices::New(_)) {
        // Indices into vertices the user never sees would be a silent wrong answer.
        bail!(
            "{} places vertices of its own, which --format {format} cannot show: \
             use --format wkt, geojson or svg (coordinates)",
            args.method
        );
    }
    if args.verbose {
        summary(&options, &rec, elapsed, &read_as);
    }
    warnings(&rec);
    let lon_lat = degrees.is_some();
    match destination {
        Destination::Gis(files) => {
            let layers = Layers::new(args.method, &points, &rec, lon_lat);
            write_layers(&files, &layers, crs.as_ref(), args.verbose)
        }
        Destination::One(output) => {
            let legacy_crs = crs.as_ref().filter(|_| args.geojson_legacy_crs).and_then(|c| c.epsg);
            let context = Context { method: args.method, legacy_crs, lon_lat };
            output.write(|w| format.write(w, &points, &rec, context))
        }
    }
}

/// Writes `layers` to `files` in the system `crs`, saying which files under `--verbose`.
fn write_layers(files: &GisFiles, layers: &Layers, crs: Option<&Crs>, verbose: bool) -> Result<()> {
    let written = files.write(layers, crs)?;
    if verbose {
        note(&written.join("\n"));
    }
    Ok(())
}

/// Reconstructs the `points` of each group of `grouping` (`--by`) and returns their layers,
/// with a warning line for the groups without a curve and for those that warn, and the
/// `--verbose` summary (`read_as` saying how the points were read).
fn by_groups(
    args: &ReconstructArgs,
    options: &Options,
    points: Vec<Point>,
    grouping: Grouping,
    degrees: Option<&str>,
    read_as: &str,
) -> Result<Layers> {
    let start = Instant::now();
    let count = grouping.groups.len();
    let by = grouping.columns[grouping.by].name.clone();
    let groups = crate::groups::reconstruct(&points, grouping, options, degrees);
    let elapsed = start.elapsed().as_secs_f64() * 1e3;
    if args.verbose {
        let statuses: Vec<String> =
            groups.statuses.iter().map(|(s, k)| format!("{s} {k}")).collect();
        let left_out: usize = groups.left_out.values().sum();
        let lines = [
            format!("method:                    {}", options.method),
            format!("points:                    {} (read as {read_as})", points.len()),
            format!("groups:                    {count} by {}", sigdt_io::text::quoted(&by)),
            format!("statuses:                  {}", statuses.join(", ")),
            format!("without curves:            {}", groups.without_curves.len()),
            format!("left out:                  {left_out}"),
            format!("time:                      {elapsed:.3} ms"),
        ];
        note(&lines.join("\n"));
    }
    if !groups.without_curves.is_empty() {
        let named = groups.without_curves.iter().map(|(name, why)| format!("{name} ({why})"));
        note(&format!(
            "sigdt: warning: {} of {count} groups gave no curve (their areas features, without \
             geometry, say why): {}",
            groups.without_curves.len(),
            crate::groups::listed(named)
        ));
    }
    if !groups.warned.is_empty() {
        note(&format!(
            "sigdt: warning: {} of {count} groups may not be their points' curves (see their \
             warning and diagnosis): {}",
            groups.warned.len(),
            crate::groups::listed(groups.warned.iter().cloned())
        ));
    }
    for (reason, k) in &groups.left_out {
        note(&format!("sigdt: left out {k} point(s): {reason}"));
    }
    Ok(groups.layers)
}

/// Where a result goes: one stream or file, or the files of GIS layers.
enum Destination {
    One(Output),
    Gis(GisFiles),
}

/// `--format` values, listed in the help and checked by clap.
fn format_parser() -> impl TypedValueParser<Value = OutputFormat> {
    let names = OutputFormat::ALL.iter().map(|f| f.name());
    PossibleValuesParser::new(names).try_map(|s| s.parse::<OutputFormat>())
}

/// One stderr line for each thing a user cannot see in the output but must know: that the
/// result may not be the points' curves (its status, each finding of the sampling check),
/// and how many points were left out, per reason.
fn warnings(rec: &Reconstruction) {
    if rec.status.is_warning() {
        note(&format!("sigdt: warning: {}", rec.status));
    }
    for finding in &rec.diagnosis {
        note(&format!("sigdt: warning: the result may not be the points' curves: {finding}"));
    }
    for (reason, count) in left_out_by_reason(rec) {
        note(&format!("sigdt: left out {count} point(s): {reason}"));
    }
}

/// The number of points left out, per reason name, in name order.
fn left_out_by_reason(rec: &Reconstruction) -> std::collections::BTreeMap<&'static str, usize> {
    let mut by_reason = std::collections::BTreeMap::new();
    for l in &rec.left_out {
        *by_reason.entry(l.reason.name()).or_default() += 1;
    }
    by_reason
}

/// How many points the result leaves out, by reason: `0`, or `3 (outlier 2, inside 1)`.
fn left_out_summary(rec: &Reconstruction) -> String {
    let reasons: Vec<String> =
        left_out_by_reason(rec).iter().map(|(r, k)| format!("{r} {k}")).collect();
    match reasons.is_empty() {
        true => "0".to_string(),
        false => format!("{} ({})", rec.left_out.len(), reasons.join(", ")),
    }
}

/// Prints the `--verbose` summary of a run to stderr.
fn summary(options: &Options, rec: &Reconstruction, ms: f64, read_as: &str) {
    let s = &rec.stats;
    let method = match options.method {
        // The option applies to SIG-CONNECT2D only.
        Method::SigConnect2d => {
            let leaves = if options.leaf_elimination { "on" } else { "off" };
            format!("{} (leaf elimination {leaves})", options.method)
        }
        _ => options.method.to_string(),
    };
    let lines = [
        format!("method:                    {method}"),
        format!("points:                    {} (read as {read_as})", s.points),
        format!("distinct points:           {}", s.distinct_points),
        format!("duplicates:                {}", rec.duplicates.len()),
        format!("edges:                     {}", rec.edges.len()),
        format!("loops:                     {}", rec.loops.len()),
        format!("paths:                     {}", rec.paths.len()),
        format!("junctions:                 {}", rec.junctions().len()),
        format!("left out:                  {}", left_out_summary(rec)),
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
