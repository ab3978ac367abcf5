//! Writers for reconstructions: edge lists, ordered loops, WKT, GeoJSON and SVG.
//!
//! Text is built in memory and written with one `write_all`, so a million edges take a few
//! dozen milliseconds and the writer needs no buffering of its own. Coordinates
//! in WKT and GeoJSON are printed with `{:?}`, the shortest text that reads back to the same
//! `f64` (`1.0`, `0.1`, `1e300`). Writers never panic on empty input.

use std::fmt::{self, Write as _};
use std::io::{self, Write};
use std::path::Path;
use std::str::FromStr;

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
    /// A standalone SVG picture of the points, edges and filled loops.
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
        OutputFormat::Svg => out = svg(points, &rec.edges, &rec.loops).into_bytes(),
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

/// A standalone SVG document showing `points` (red dots), `edges` (blue lines) and `loops`
/// (filled light blue, even-odd).
///
/// The picture fits the points' bounding box with a 5% margin, y pointing up, its longer
/// side 1000 units. Line width and dot size follow the point spacing `s` (the median edge
/// length, or without edges the box diagonal over `√n`): 0.12·s and 0.22·s, so a small
/// glyph and a dense contour both read well when zoomed in. Coordinates are printed to
/// about 1% of `s`, which keeps large pictures small.
pub fn svg(points: &[Point], edges: &[Edge], loops: &[Vec<usize>]) -> String {
    let f = Frame::new(points, edges);
    let mut out = String::with_capacity(512 + 40 * (points.len() + edges.len()));
    let number = |v: f64, decimals: usize| {
        let mut s = String::new();
        push_fixed(&mut s, v, decimals);
        s
    };
    let xy = |out: &mut String, i: usize| {
        let [x, y] = f.map(points[i]);
        push_fixed(out, x, f.decimals);
        out.push(' ');
        push_fixed(out, y, f.decimals);
    };
    let (w, h) = (number(f.width, 2), number(f.height, 2));
    let (n, m, k) = (points.len(), edges.len(), loops.len());
    let _ = write!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
         viewBox=\"0 0 {w} {h}\">\n<title>{n} points, {m} edges, {k} loops</title>\n\
         <rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
    );
    if !loops.is_empty() {
        out.push_str("<path fill=\"#dbe9f6\" fill-rule=\"evenodd\" stroke=\"none\" d=\"");
        for indices in loops {
            for (k, &i) in indices.iter().enumerate() {
                out.push_str(if k == 0 { "M " } else { " L " });
                xy(&mut out, i);
            }
            out.push_str(" Z ");
        }
        out.pop();
        out.push_str("\"/>\n");
    }
    if !edges.is_empty() {
        let width = number(0.12 * f.spacing, f.decimals + 1);
        let _ = write!(
            out,
            "<path fill=\"none\" stroke=\"#1f4e79\" stroke-width=\"{width}\" \
             stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\""
        );
        for &[i, j] in edges {
            out.push_str("M ");
            xy(&mut out, i);
            out.push_str(" L ");
            xy(&mut out, j);
            out.push(' ');
        }
        out.pop();
        out.push_str("\"/>\n");
    }
    if !points.is_empty() {
        let r = number(0.22 * f.spacing, f.decimals + 1);
        out.push_str("<g fill=\"#c0392b\">\n");
        for &p in points {
            let [x, y] = f.map(p);
            out.push_str("<circle cx=\"");
            push_fixed(&mut out, x, f.decimals);
            out.push_str("\" cy=\"");
            push_fixed(&mut out, y, f.decimals);
            let _ = writeln!(out, "\" r=\"{r}\"/>");
        }
        out.push_str("</g>\n");
    }
    out.push_str("</svg>\n");
    out
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
        (false, true) => shape(out, points, loops, true, json)?,
        (true, false) => shape(out, points, paths, false, json)?,
        (false, false) => {
            out.extend_from_slice(if json {
                br#"{"type": "GeometryCollection", "geometries": ["#
            } else {
                b"GEOMETRYCOLLECTION ("
            });
            shape(out, points, loops, true, json)?;
            out.extend_from_slice(b", ");
            shape(out, points, paths, false, json)?;
            out.extend_from_slice(if json { b"]}" } else { b")" });
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
        for (k, &i) in indices.iter().chain(closing).enumerate() {
            let ([x, y], sep) = (points[i], if k == 0 { "" } else { ", " });
            match json {
                false => write!(out, "{sep}{x:?} {y:?}")?,
                true if x.is_finite() && y.is_finite() => write!(out, "{sep}[{x:?}, {y:?}]")?,
                true => write!(out, "{sep}[null, null]")?,
            }
        }
        write!(out, "{close}{close_ring}")?;
    }
    write!(out, "{}{}", if multi { close } else { "" }, if json { "}" } else { "" })
}

/// Maps input coordinates to the SVG picture, whose longer side is [`Self::SIDE`] units.
struct Frame {
    /// Input coordinates of the picture's top-left corner.
    origin: Point,
    /// Picture units per input unit.
    scale: f64,
    width: f64,
    height: f64,
    /// The point spacing, in picture units.
    spacing: f64,
    /// Decimals printed for coordinates: about 1% of the spacing.
    decimals: usize,
}

impl Frame {
    const SIDE: f64 = 1000.0;

    fn new(points: &[Point], edges: &[Edge]) -> Frame {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points {
            lo = [lo[0].min(p[0]), lo[1].min(p[1])];
            hi = [hi[0].max(p[0]), hi[1].max(p[1])];
        }
        if points.is_empty() {
            (lo, hi) = ([0.0; 2], [0.0; 2]);
        }
        let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
        let side = w.max(h);
        let mut spacing = if edges.is_empty() {
            w.hypot(h) / (points.len() as f64).sqrt()
        } else {
            let length =
                |&[i, j]: &Edge| (points[i][0] - points[j][0]).hypot(points[i][1] - points[j][1]);
            let mut lengths: Vec<f64> = edges.iter().map(length).collect();
            let mid = lengths.len() / 2;
            *lengths.select_nth_unstable_by(mid, f64::total_cmp).1
        };
        if !(spacing > 0.0 && spacing.is_finite()) {
            spacing = if side > 0.0 { side / 10.0 } else { 1.0 };
        }
        // A 5% margin, but room for the dots when there are only a few points, and a box
        // around a lone point.
        let pad = if side > 0.0 { (0.05 * side).max(0.3 * spacing) } else { 2.0 * spacing };
        let scale = Self::SIDE / (side + 2.0 * pad);
        let decimals = (-(spacing * scale / 100.0).log10()).ceil() as i64;
        Frame {
            origin: [lo[0] - pad, hi[1] + pad],
            scale,
            width: (w + 2.0 * pad) * scale,
            height: (h + 2.0 * pad) * scale,
            spacing: spacing * scale,
            decimals: decimals.clamp(1, 9) as usize,
        }
    }

    /// `p` in picture coordinates, y pointing down.
    fn map(&self, p: Point) -> Point {
        [(p[0] - self.origin[0]) * self.scale, (self.origin[1] - p[1]) * self.scale]
    }
}

/// Appends `v` with `decimals` decimals, trailing zeros removed (`12.50` → `12.5`,
/// `-0.00` → `0`).
fn push_fixed(out: &mut String, v: f64, decimals: usize) {
    let start = out.len();
    let _ = write!(out, "{v:.decimals$}");
    if out[start..].contains('.') {
        out.truncate(out.trim_end_matches('0').trim_end_matches('.').len());
    }
    if &out[start..] == "-0" {
        out.remove(start);
    }
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
    fn svg_square_and_degenerate_boxes() {
        let picture = text(OutputFormat::Svg, &SQUARE, &square());
        assert_eq!(picture, svg(&SQUARE, &square().edges, &square().loops));
        // Spacing 1 → margin 0.3, 625 picture units per input unit, y flipped.
        for part in [
            r#"viewBox="0 0 1000 1000""#,
            "<title>4 points, 4 edges, 1 loops</title>",
            r##"<path fill="#dbe9f6" fill-rule="evenodd" stroke="none" d="M 187.5 812.5 L 812.5 812.5 L 812.5 187.5 L 187.5 187.5 Z"/>"##,
            r#"stroke-width="75""#,
            "M 187.5 812.5 L 812.5 812.5 M 187.5 812.5 L 187.5 187.5 ",
            r#"<circle cx="187.5" cy="812.5" r="137.5"/>"#,
        ] {
            assert!(picture.contains(part), "{part} not in\n{picture}");
        }
        assert!(picture.starts_with("<svg ") && picture.ends_with("</svg>\n"));
        let single = svg(&[[5.0, 5.0]], &[], &[]);
        assert!(
            single.contains(r#"viewBox="0 0 1000 1000""#)
                && single.contains(r#"cx="500" cy="500""#)
        );
        let line = svg(&[[0.0, 3.0], [1.0, 3.0], [2.0, 3.0]], &[[0, 1], [1, 2]], &[]);
        assert!(line.contains(r#"viewBox="0 0 1000 230.77""#), "{line}");
        let nothing = svg(&[], &[], &[]);
        assert!(
            nothing.contains("<title>0 points, 0 edges, 0 loops</title>")
                && !nothing.contains("NaN")
        );
    }

    #[test]
    fn numbers_are_compact() {
        let fixed = |v, decimals| {
            let mut s = "x ".to_string();
            push_fixed(&mut s, v, decimals);
            s
        };
        assert_eq!(fixed(12.5, 3), "x 12.5");
        assert_eq!(fixed(-0.0001, 2), "x 0");
        assert_eq!(fixed(30.0, 2), "x 30");
        assert_eq!(fixed(0.0123456, 3), "x 0.012");
    }
}
