//! Writers for reconstructions: edge lists, ordered loops, WKT, GeoJSON and SVG (drawn by
//! [`render_svg`]).
//!
//! Text is built in memory and written with one `write_all`, so a million edges take a few
//! dozen milliseconds and the writer needs no buffering of its own. Coordinates
//! in WKT and GeoJSON are printed with `{:?}`, the shortest text that reads back to the same
//! `f64` (`1.0`, `0.1`, `1e300`). Writers never panic on empty input.

use std::fmt;
use std::io::{self, Write};
use std::path::Path;
use std::str::FromStr;

use crate::render::{render_svg, Layers, RenderOptions};
use crate::{Edge, Point, Reconstruction, Status};

/// An output format. Spelled `edges`, `loops`, `wkt`, `geojson` and `svg`; [`FromStr`] and
/// [`Display`](fmt::Display) map between the two.
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
    /// A standalone SVG picture of the points, edges and filled loops, with a legend.
    Svg,
}

impl OutputFormat {
    /// Every format, in the order they are listed in help texts.
    pub const ALL: &'static [OutputFormat] = &[
        OutputFormat::Edges,
        OutputFormat::Loops,
        OutputFormat::Wkt,
        OutputFormat::GeoJson,
        OutputFormat::Svg,
    ];

    /// The lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            OutputFormat::Edges => "edges",
            OutputFormat::Loops => "loops",
            OutputFormat::Wkt => "wkt",
            OutputFormat::GeoJson => "geojson",
            OutputFormat::Svg => "svg",
        }
    }

    /// The format implied by the file extension (case-insensitive): `.wkt`, `.geojson` or
    /// `.json`, `.svg`, `.loops`, and `.edges` or `.txt` for edges; anything else is `None`.
    pub fn from_path(path: &Path) -> Option<OutputFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "edges" | "txt" => Some(OutputFormat::Edges),
            "loops" => Some(OutputFormat::Loops),
            "wkt" => Some(OutputFormat::Wkt),
            "geojson" | "json" => Some(OutputFormat::GeoJson),
            "svg" => Some(OutputFormat::Svg),
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
    type Err = crate::Error;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        OutputFormat::ALL.iter().copied().find(|f| f.name() == s).ok_or_else(|| {
            let names: Vec<_> = OutputFormat::ALL.iter().map(|f| f.name()).collect();
            crate::Error::InvalidOption(format!(
                "unknown output format '{s}' (expected one of: {})",
                names.join(", ")
            ))
        })
    }
}

/// Writes `rec`, whose indices refer to `points`, to `w` in `format`.
pub fn write_reconstruction<W: Write>(
    mut w: W,
    format: OutputFormat,
    points: &[Point],
    rec: &Reconstruction,
) -> io::Result<()> {
    let mut out = Vec::new();
    match format {
        OutputFormat::Edges => return write_edges(w, &rec.edges),
        OutputFormat::Loops => {
            for (prefix, lists) in [("", &rec.loops), ("path ", &rec.paths)] {
                for indices in lists {
                    out.extend_from_slice(prefix.as_bytes());
                    for (k, &i) in indices.iter().enumerate() {
                        write!(out, "{}{i}", if k == 0 { "" } else { " " })?;
                    }
                    out.push(b'\n');
                }
            }
        }
        OutputFormat::Wkt => {
            geometry(&mut out, points, &rec.loops, &rec.paths, false)?;
            out.push(b'\n');
        }
        OutputFormat::GeoJson => {
            out.extend_from_slice(br#"{"type": "Feature", "geometry": "#);
            geometry(&mut out, points, &rec.loops, &rec.paths, true)?;
            let (n, m, d) = (points.len(), rec.edges.len(), rec.duplicates.len());
            let (k, p, status) = (rec.loops.len(), rec.paths.len(), rec.status.name());
            write!(
                out,
                r#", "properties": {{"status": "{status}", "points": {n}, "edges": {m}, "#
            )?;
            write!(out, r#""loops": {k}, "paths": {p}, "duplicates": {d}"#)?;
            if let Status::SculptingStuck { left_out } = &rec.status {
                let left_out: Vec<_> = left_out.iter().map(usize::to_string).collect();
                write!(out, r#", "left_out": [{}]"#, left_out.join(", "))?;
            }
            out.extend_from_slice(b"}}\n");
        }
        OutputFormat::Svg => out = picture(points, rec).into_bytes(),
    }
    w.write_all(&out)?;
    w.flush()
}

/// The SVG output: the points and the result, with the default [`RenderOptions`].
fn picture(points: &[Point], rec: &Reconstruction) -> String {
    let layers = Layers { points: true, result: Some(rec), ..Layers::default() };
    render_svg(points, &layers, &RenderOptions::default())
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

/// The geometry of the loops and paths, as WKT or as a GeoJSON geometry object.
fn geometry(
    out: &mut Vec<u8>,
    points: &[Point],
    loops: &[Vec<usize>],
    paths: &[Vec<usize>],
    json: bool,
) -> io::Result<()> {
    match (loops.is_empty(), paths.is_empty()) {
        (true, true) => {
            out.extend_from_slice(if json { b"null" } else { b"GEOMETRYCOLLECTION EMPTY" })
        }
        (false, true) => polygons(out, points, loops, json)?,
        (true, false) => shape(out, points, paths, false, json)?,
        (false, false) => {
            out.extend_from_slice(if json {
                br#"{"type": "GeometryCollection", "geometries": ["#
            } else {
                b"GEOMETRYCOLLECTION ("
            });
            polygons(out, points, loops, json)?;
            out.extend_from_slice(b", ");
            shape(out, points, paths, false, json)?;
            out.extend_from_slice(if json { b"]}" } else { b")" });
        }
    }
    Ok(())
}

/// The loops as polygons with holes ([`nest_loops`]): a `POLYGON` / `Polygon` when there is
/// one shell, else a multi-polygon. Holes run clockwise, shells counter-clockwise.
fn polygons(
    out: &mut Vec<u8>,
    points: &[Point],
    loops: &[Vec<usize>],
    json: bool,
) -> io::Result<()> {
    let nested = nest_loops(points, loops);
    if nested.len() == 1 && nested[0].len() == 1 {
        return shape(out, points, loops, true, json);
    }
    let rings = |polygon: &Vec<usize>| -> Vec<Vec<usize>> {
        polygon
            .iter()
            .enumerate()
            .map(|(k, &l)| {
                let mut ring = loops[l].clone();
                if k > 0 {
                    ring.reverse();
                }
                ring
            })
            .collect()
    };
    let (open, close) = if json { ("[", "]") } else { ("(", ")") };
    let multi = nested.len() > 1;
    match (json, multi) {
        (true, true) => out.extend_from_slice(br#"{"type": "MultiPolygon", "coordinates": ["#),
        (true, false) => out.extend_from_slice(br#"{"type": "Polygon", "coordinates": "#),
        (false, true) => out.extend_from_slice(b"MULTIPOLYGON ("),
        (false, false) => out.extend_from_slice(b"POLYGON "),
    }
    for (k, polygon) in nested.iter().enumerate() {
        write!(out, "{}{open}", if k == 0 { "" } else { ", " })?;
        for (r, ring) in rings(polygon).iter().enumerate() {
            write!(out, "{}{open}", if r == 0 { "" } else { ", " })?;
            coordinates(out, points, ring.iter().chain(ring.first()), json)?;
            out.extend_from_slice(close.as_bytes());
        }
        out.extend_from_slice(close.as_bytes());
    }
    if multi {
        out.extend_from_slice(close.as_bytes());
    }
    if json {
        out.push(b'}');
    }
    Ok(())
}

/// Groups vertex-disjoint, non-crossing loops into polygons with holes: each group is a
/// shell's loop number followed by its holes'. A loop inside an even number of others is a
/// shell; the loops directly inside it (one level deeper) are its holes. Shells are in loop
/// order, holes in loop order.
pub fn nest_loops(points: &[Point], loops: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let boxes: Vec<[f64; 4]> = loops
        .iter()
        .map(|l| {
            l.iter().fold(
                [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY],
                |b, &i| {
                    let [x, y] = points[i];
                    [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)]
                },
            )
        })
        .collect();
    // Loop `i` is inside loop `j` when a vertex of `i` that is not on `j` is (the first
    // vertex, for the vertex-disjoint loops of a reconstruction).
    let inside = |i: usize, j: usize| {
        let b = boxes[j];
        let in_box = |[x, y]: Point| x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3];
        if i == j || !in_box(points[loops[i][0]]) {
            return false;
        }
        let Some(&v) = loops[i].iter().find(|v| !loops[j].contains(v)) else {
            return false;
        };
        point_in_ring(points, &loops[j], points[v])
    };
    let containers: Vec<Vec<usize>> =
        (0..loops.len()).map(|i| (0..loops.len()).filter(|&j| inside(i, j)).collect()).collect();
    let depth: Vec<usize> = containers.iter().map(Vec::len).collect();
    (0..loops.len())
        .filter(|&i| depth[i] % 2 == 0)
        .map(|shell| {
            let holes = (0..loops.len())
                .filter(|&h| depth[h] == depth[shell] + 1 && containers[h].contains(&shell));
            std::iter::once(shell).chain(holes).collect()
        })
        .collect()
}

/// Whether `p` lies inside the closed ring through `ring` (even-odd rule).
fn point_in_ring(points: &[Point], ring: &[usize], p: Point) -> bool {
    let mut inside = false;
    for k in 0..ring.len() {
        let (a, b) = (points[ring[k]], points[ring[(k + 1) % ring.len()]]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// The coordinates of `indices`, comma-separated: `x y` in WKT, `[x, y]` in JSON (`null`
/// for non-finite coordinates).
fn coordinates<'a>(
    out: &mut Vec<u8>,
    points: &[Point],
    indices: impl Iterator<Item = &'a usize>,
    json: bool,
) -> io::Result<()> {
    for (k, &i) in indices.enumerate() {
        let ([x, y], sep) = (points[i], if k == 0 { "" } else { ", " });
        match json {
            false => write!(out, "{sep}{x:?} {y:?}")?,
            true if x.is_finite() && y.is_finite() => write!(out, "{sep}[{x:?}, {y:?}]")?,
            true => write!(out, "{sep}[null, null]")?,
        }
    }
    Ok(())
}

/// One polygon per ring (rings repeat their first point), or one line string per path; a
/// multi-geometry when there are several. Non-finite coordinates are `null` in JSON.
fn shape(
    out: &mut Vec<u8>,
    points: &[Point],
    lists: &[Vec<usize>],
    ring: bool,
    json: bool,
) -> io::Result<()> {
    let multi = lists.len() > 1;
    let [wkt, geojson] = match (ring, multi) {
        (true, false) => ["POLYGON ", "Polygon"],
        (true, true) => ["MULTIPOLYGON ", "MultiPolygon"],
        (false, false) => ["LINESTRING ", "LineString"],
        (false, true) => ["MULTILINESTRING ", "MultiLineString"],
    };
    let (open, close) = if json { ("[", "]") } else { ("(", ")") };
    if json {
        write!(out, r#"{{"type": "{geojson}", "coordinates": "#)?;
    } else {
        out.extend_from_slice(wkt.as_bytes());
    }
    let (open_ring, close_ring) = if ring { (open, close) } else { ("", "") };
    write!(out, "{}", if multi { open } else { "" })?;
    for (k, indices) in lists.iter().enumerate() {
        write!(out, "{}{open_ring}{open}", if k == 0 { "" } else { ", " })?;
        let closing = indices.first().filter(|_| ring);
        coordinates(out, points, indices.iter().chain(closing), json)?;
        write!(out, "{close}{close_ring}")?;
    }
    write!(out, "{}{}", if multi { close } else { "" }, if json { "}" } else { "" })
}

#[cfg(test)]
mod tests {
    use super::*;

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
        assert!(err.contains("'png'") && err.contains("edges, loops, wkt, geojson, svg"), "{err}");
        let format = |name: &str| OutputFormat::from_path(Path::new(name));
        assert_eq!(format("a.JSON"), Some(OutputFormat::GeoJson));
        assert_eq!(format("a.txt"), Some(OutputFormat::Edges));
        assert_eq!(format("a.loops"), Some(OutputFormat::Loops));
        assert_eq!(format("a.png"), None);
    }

    #[test]
    fn nested_loops_are_polygons_with_holes() {
        // Squares of sides 6, 4 and 2 around the origin, and one apart.
        let square = |r: f64, dx: f64| [[dx - r, -r], [dx + r, -r], [dx + r, r], [dx - r, r]];
        let points: Vec<Point> =
            [square(3.0, 0.0), square(2.0, 0.0), square(1.0, 0.0), square(1.0, 9.0)].concat();
        let loops: Vec<Vec<usize>> = (0..4).map(|k| (4 * k..4 * k + 4).collect()).collect();
        assert_eq!(nest_loops(&points, &loops), vec![vec![0, 1], vec![2], vec![3]]);
        let rec = Reconstruction { loops, status: Status::Polygons, ..Reconstruction::default() };
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
        let properties = r#""properties": {"status": "polygon", "points": 4, "edges": 4, "loops": 1, "paths": 0, "duplicates": 0}}"#;
        assert_eq!(square, format!("{geometry}{properties}\n"));
        let path = text(GeoJson, &SQUARE, &path());
        let lines = r#"{"type": "MultiLineString", "coordinates": [[[0.0, 0.0], [1.0, 1.0]], [[1.0, 0.0], [0.0, 1.0]]]}"#;
        assert!(path.contains(lines) && path.contains(r#""status": "collinear""#), "{path}");
        let stuck =
            Reconstruction { status: Status::SculptingStuck { left_out: vec![2, 5] }, ..empty() };
        let stuck = text(GeoJson, &[], &stuck);
        assert!(stuck.contains(r#""geometry": null"#), "{stuck}");
        assert!(stuck.ends_with("\"duplicates\": 0, \"left_out\": [2, 5]}}\n"), "{stuck}");
    }

    #[test]
    fn svg_is_the_picture() {
        let svg = text(OutputFormat::Svg, &SQUARE, &square());
        assert_eq!(svg, picture(&SQUARE, &square()));
        assert!(svg.starts_with("<svg ") && svg.ends_with("</svg>\n"), "{svg}");
        assert!(svg.contains("points 4") && svg.contains("result 4 edges, 1 loop"), "{svg}");
        let empty = text(OutputFormat::Svg, &[], &empty());
        assert!(empty.ends_with("</svg>\n") && !empty.contains("NaN"), "{empty}");
    }
}
