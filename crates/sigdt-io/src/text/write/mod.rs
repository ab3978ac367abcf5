//! Writers for reconstructions: edge lists, ordered loops, WKT and GeoJSON, one module per
//! format that has more than a few lines. (Pictures are drawn by the `sigdt-lab` crate.)
//!
//! Text is built in memory and written with one `write_all`, so a million edges take a few
//! dozen milliseconds and the writer needs no buffering of its own. Coordinates in WKT and
//! GeoJSON are printed with `{:?}`, the shortest text that reads back to the same `f64`
//! (`1.0`, `0.1`, `1e300`). Writers never panic on empty input.

mod geojson;
mod geometry;
mod wkt;

use std::fmt;
use std::io::{self, Write};
use std::path::Path;
use std::str::FromStr;

use crate::gis::outlines::outlines;
use sigdt::Reconstruction;
use sigdt::{Edge, Point};

/// A text format for results. Spelled `edges`, `loops`, `wkt` and `geojson`; [`FromStr`]
/// and [`Display`](fmt::Display) map between the two.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OutputFormat {
    /// One edge a line, `i j` (0-based input indices).
    #[default]
    Edges,
    /// One closed loop a line, its indices in order; then each open path as `path i j ...`.
    Loops,
    /// Well-known text: `POLYGON`, `MULTIPOLYGON`, `LINESTRING`, ... of the loops and paths.
    Wkt,
    /// One GeoJSON `Feature` with the loops and paths as geometry and counts as properties.
    GeoJson,
}

impl OutputFormat {
    /// Every format, in the order they are listed in help texts.
    pub const ALL: &'static [OutputFormat] =
        &[OutputFormat::Edges, OutputFormat::Loops, OutputFormat::Wkt, OutputFormat::GeoJson];

    /// The lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            OutputFormat::Edges => "edges",
            OutputFormat::Loops => "loops",
            OutputFormat::Wkt => "wkt",
            OutputFormat::GeoJson => "geojson",
        }
    }

    /// The format implied by the file extension (case-insensitive): `.wkt`, `.geojson` or
    /// `.json`, `.loops`, and `.edges` or `.txt` for edges; anything else is `None`.
    pub fn from_path(path: &Path) -> Option<OutputFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "edges" | "txt" => Some(OutputFormat::Edges),
            "loops" => Some(OutputFormat::Loops),
            "wkt" => Some(OutputFormat::Wkt),
            "geojson" | "json" => Some(OutputFormat::GeoJson),
            _ => None,
        }
    }
}

impl fmt::Display for OutputFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for OutputFormat {
    type Err = sigdt::Error;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        sigdt::internals::find_by_name(OutputFormat::ALL, OutputFormat::name, s, "output format")
    }
}

/// Writes `rec`, whose indices refer to `points`, to `w` in `format`. WKT and GeoJSON take
/// the coordinates from [`Reconstruction::vertex_positions`]: the moved or new vertices
/// of a method that has them; edges and loops print indices only.
pub fn write_reconstruction<W: Write>(
    w: W,
    format: OutputFormat,
    points: &[Point],
    rec: &Reconstruction,
) -> io::Result<()> {
    write_reconstruction_with(w, format, points, rec, &WriteOptions::default())
}

/// What a writer says beside the result itself.
#[derive(Debug, Clone, Default)]
pub struct WriteOptions {
    /// The method that made the result: GeoJSON's `method` property (none when `None`).
    pub method: Option<sigdt::Method>,
    /// A coordinate system's name (`urn:ogc:def:crs:EPSG::27700`) for GeoJSON's legacy
    /// `crs` member (GeoJSON 2008), which RFC 7946 removed: only for readers that still
    /// honour it, when the coordinates are not WGS 84 longitude/latitude.
    pub legacy_crs: Option<String>,
}

/// [`write_reconstruction`] with `options`.
pub fn write_reconstruction_with<W: Write>(
    w: W,
    format: OutputFormat,
    points: &[Point],
    rec: &Reconstruction,
    options: &WriteOptions,
) -> io::Result<()> {
    write_text(w, format, points, rec, options, false)
}

/// [`write_reconstruction_with`] for `points` that are longitude and latitude in degrees:
/// the GeoJSON geometry (RFC 7946, §3.1.9) is cut at the antimeridian, its loops grouped in
/// a local plane ([`outlines`]); the other formats are
/// written as by [`write_reconstruction_with`].
pub fn write_reconstruction_lon_lat<W: Write>(
    w: W,
    format: OutputFormat,
    points: &[Point],
    rec: &Reconstruction,
    options: &WriteOptions,
) -> io::Result<()> {
    write_text(w, format, points, rec, options, true)
}

/// [`write_reconstruction_with`]; the GeoJSON geometry cut at the antimeridian when
/// `lon_lat`.
fn write_text<W: Write>(
    mut w: W,
    format: OutputFormat,
    points: &[Point],
    rec: &Reconstruction,
    options: &WriteOptions,
    lon_lat: bool,
) -> io::Result<()> {
    let mut out = Vec::new();
    let vertices = rec.vertex_positions(points);
    match format {
        OutputFormat::Edges => return write_edges(w, &rec.edges),
        OutputFormat::Loops => loops(&mut out, rec)?,
        OutputFormat::Wkt => wkt::wkt(&mut out, &outlines(points, rec, false))?,
        OutputFormat::GeoJson => {
            let outlines = outlines(points, rec, lon_lat);
            geojson::geojson(&mut out, points.len(), vertices, &outlines, rec, options)?
        }
    }
    w.write_all(&out)?;
    w.flush()
}

/// Writes `edges` to `w`, one `i j` a line, in the order given.
pub fn write_edges<W: Write>(mut w: W, edges: &[Edge]) -> io::Result<()> {
    let mut out = Vec::with_capacity(16 * edges.len());
    for &[i, j] in edges {
        writeln!(out, "{i} {j}")?;
    }
    w.write_all(&out)?;
    w.flush()
}

/// Each loop on a line, its indices in order; then each path as `path i j ...`.
fn loops(out: &mut Vec<u8>, rec: &Reconstruction) -> io::Result<()> {
    for (prefix, lists) in [("", &rec.loops), ("path ", &rec.paths)] {
        for indices in lists {
            out.extend_from_slice(prefix.as_bytes());
            for (k, &i) in indices.iter().enumerate() {
                write!(out, "{}{i}", if k == 0 { "" } else { " " })?;
            }
            out.push(b'\n');
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use sigdt::Status;

    const SQUARE: [Point; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];

    fn square() -> Reconstruction {
        Reconstruction {
            edges: vec![[0, 1], [0, 3], [1, 2], [2, 3]],
            loops: vec![vec![0, 1, 2, 3]],
            ..Reconstruction::default()
        }
    }

    fn path() -> Reconstruction {
        Reconstruction {
            edges: vec![[0, 2], [1, 3]],
            paths: vec![vec![0, 2], vec![1, 3]],
            status: Status::Collinear,
            ..Reconstruction::default()
        }
    }

    fn empty() -> Reconstruction {
        Reconstruction { status: Status::TooFewPoints, ..Reconstruction::default() }
    }

    fn text(format: OutputFormat, points: &[Point], rec: &Reconstruction) -> String {
        let mut out = Vec::new();
        write_reconstruction(&mut out, format, points, rec).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn names_round_trip() {
        for &f in OutputFormat::ALL {
            assert_eq!(f.to_string().parse::<OutputFormat>().unwrap(), f);
        }
        let err = "png".parse::<OutputFormat>().unwrap_err().to_string();
        assert!(err.contains("'png'") && err.contains("edges, loops, wkt, geojson"), "{err}");
        let format = |name: &str| OutputFormat::from_path(Path::new(name));
        assert_eq!(format("a.JSON"), Some(OutputFormat::GeoJson));
        assert_eq!(format("a.txt"), Some(OutputFormat::Edges));
        assert_eq!(format("a.loops"), Some(OutputFormat::Loops));
        assert_eq!(format("a.png"), None);
        assert_eq!(format("a.svg"), None);
    }

    #[test]
    fn nested_loops_are_polygons_with_holes() {
        // Squares of sides 6, 4 and 2 around the origin, and one apart.
        let square = |r: f64, dx: f64| [[dx - r, -r], [dx + r, -r], [dx + r, r], [dx - r, r]];
        let points: Vec<Point> =
            [square(3.0, 0.0), square(2.0, 0.0), square(1.0, 0.0), square(1.0, 9.0)].concat();
        let loops: Vec<Vec<usize>> = (0..4).map(|k| (4 * k..4 * k + 4).collect()).collect();
        let rec = Reconstruction { loops, status: Status::Polygons, ..Reconstruction::default() };
        let nested: Vec<Vec<usize>> = rec
            .polygons(&points)
            .into_iter()
            .map(|p| std::iter::once(p.shell).chain(p.holes).collect())
            .collect();
        assert_eq!(nested, vec![vec![0, 1], vec![2], vec![3]]);
        let wkt = text(OutputFormat::Wkt, &points, &rec);
        assert!(wkt.starts_with("MULTIPOLYGON (((-3.0 -3.0, 3.0 -3.0, 3.0 3.0, -3.0 3.0, -3.0 -3.0), (-2.0 2.0, 2.0 2.0, 2.0 -2.0, -2.0 -2.0, -2.0 2.0)), ((-1.0"), "{wkt}");
        let json = text(OutputFormat::GeoJson, &points, &rec);
        assert!(
            json.contains(r#"{"type": "MultiPolygon", "coordinates": [[[[-3.0, -3.0], "#),
            "{json}"
        );
        assert!(json.contains("[-3.0, -3.0]], [[-2.0, 2.0], [2.0, 2.0]"), "{json}");
    }

    #[test]
    fn edges_and_loops() {
        use OutputFormat::{Edges, Loops};
        assert_eq!(text(Edges, &SQUARE, &square()), "0 1\n0 3\n1 2\n2 3\n");
        assert_eq!(text(Edges, &[], &empty()), "");
        let mut out = Vec::new();
        write_edges(&mut out, &[[10, 9], [0, 12345678901]]).unwrap();
        assert_eq!(out, b"10 9\n0 12345678901\n");
        assert_eq!(text(Loops, &SQUARE, &square()), "0 1 2 3\n");
        assert_eq!(text(Loops, &SQUARE, &path()), "path 0 2\npath 1 3\n");
        assert_eq!(text(Loops, &[], &empty()), "");
    }

    #[test]
    fn wkt() {
        use OutputFormat::Wkt;
        let polygon = "POLYGON ((0.0 0.0, 1.0 0.0, 1.0 1.0, 0.0 1.0, 0.0 0.0))\n";
        assert_eq!(text(Wkt, &SQUARE, &square()), polygon);
        let lines = "MULTILINESTRING ((0.0 0.0, 1.0 1.0), (1.0 0.0, 0.0 1.0))\n";
        assert_eq!(text(Wkt, &SQUARE, &path()), lines);
        let one = Reconstruction { paths: vec![vec![1, 0]], ..empty() };
        assert_eq!(
            text(Wkt, &[[1e300, -0.5], [2.5, 1e-7]], &one),
            "LINESTRING (2.5 1e-7, 1e300 -0.5)\n"
        );
        let two = Reconstruction { loops: vec![vec![0, 1, 2], vec![0, 2, 3]], ..square() };
        let multi = "MULTIPOLYGON (((0.0 0.0, 1.0 0.0, 1.0 1.0, 0.0 0.0)), \
                     ((0.0 0.0, 1.0 1.0, 0.0 1.0, 0.0 0.0)))\n";
        assert_eq!(text(Wkt, &SQUARE, &two), multi);
        let both =
            Reconstruction { loops: vec![vec![0, 1, 2]], paths: vec![vec![3, 0]], ..square() };
        let collection = "GEOMETRYCOLLECTION (POLYGON ((0.0 0.0, 1.0 0.0, 1.0 1.0, 0.0 0.0)), \
                          LINESTRING (0.0 1.0, 0.0 0.0))\n";
        assert_eq!(text(Wkt, &SQUARE, &both), collection);
        assert_eq!(text(Wkt, &[], &empty()), "GEOMETRYCOLLECTION EMPTY\n");
    }

    #[test]
    fn geojson() {
        use OutputFormat::GeoJson;
        let square = text(GeoJson, &SQUARE, &square());
        let geometry = r#"{"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]]]}, "#;
        let properties = r#""properties": {"status": "polygon", "status_message": "one closed polygon through every point not left out", "points": 4, "edges": 4, "loops": 1, "paths": 0, "duplicates": 0, "warning": false}}"#;
        assert_eq!(square, format!("{geometry}{properties}\n"));
        let path = text(GeoJson, &SQUARE, &path());
        let lines = r#"{"type": "MultiLineString", "coordinates": [[[0.0, 0.0], [1.0, 1.0]], [[1.0, 0.0], [0.0, 1.0]]]}"#;
        assert!(path.contains(lines) && path.contains(r#""status": "collinear""#), "{path}");
        // Vertices of the method's own: `points` counts the input, `vertices` the positions.
        let own = Reconstruction {
            edges: vec![[0, 1]],
            paths: vec![vec![0, 1]],
            vertices: sigdt::Vertices::New(vec![[0.5, 0.0], [0.5, 1.0]]),
            ..self::path()
        };
        let own = text(GeoJson, &SQUARE, &own);
        let counts = r#""points": 4, "vertices": 2, "edges": 1, "loops": 0, "paths": 1"#;
        assert!(own.contains(counts) && own.contains("[[0.5, 0.0], [0.5, 1.0]]"), "{own}");
        let stuck = Reconstruction {
            status: Status::SculptingStuck { left_out: vec![2, 5] },
            left_out: [2, 5]
                .map(|index| sigdt::LeftOut { index, reason: sigdt::LeftOutReason::Inside })
                .to_vec(),
            ..empty()
        };
        let stuck = text(GeoJson, &[], &stuck);
        assert!(stuck.contains(r#""geometry": null"#), "{stuck}");
        let end = r#""duplicates": 0, "left_out": [2, 5], "left_out_reasons": ["inside", "inside"], "warning": true}}"#;
        assert!(stuck.ends_with(&format!("{end}\n")), "{stuck}");
        let finding = sigdt::Finding {
            kind: sigdt::FindingKind::SmallLoops,
            count: 1,
            worst: 3.0,
            at: 0,
            point: [0.0, 0.0],
        };
        let flagged = Reconstruction { diagnosis: vec![finding], ..self::square() };
        let flagged = text(GeoJson, &SQUARE, &flagged);
        let diagnosis = r#""warning": true, "diagnosis": [{"kind": "small-loops", "count": 1, "worst": 3.0, "at": 0, "point": [0.0, 0.0], "message": "1 loop(s) of fewer than 7 points"#;
        assert!(flagged.contains(diagnosis), "{flagged}");
    }
}
