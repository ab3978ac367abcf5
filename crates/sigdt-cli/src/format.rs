//! The output formats of `sigdt reconstruct`: the kernel's text formats, the SVG picture,
//! and GIS layers (GeoPackage, FlatGeobuf; written by [`gis_output`](crate::gis_output)).

use std::fmt;
use std::io::{self, Write};
use std::path::Path;
use std::str::FromStr;

use sigdt::{Method, Point, Reconstruction};
use sigdt_io::text::{
    write_reconstruction_lon_lat, write_reconstruction_with, OutputFormat as Text, WriteOptions,
};

use sigdt_lab::render::{render_svg, Layers, RenderOptions};

/// An output format. Spelled `edges`, `loops`, `wkt`, `geojson`, `svg`, `png`, `gpkg` and
/// `fgb`;
/// [`FromStr`] and [`Display`](fmt::Display) map between the two.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutputFormat {
    /// A text format of the kernel ([`sigdt_io::text::OutputFormat`]).
    Text(Text),
    /// A standalone SVG picture of the points, edges and filled loops, with a legend.
    Svg,
    /// The same picture as a PNG image.
    Png,
    /// GeoPackage layers `areas`, `paths`, `networks` and `left_out`
    /// ([`sigdt_io::gis::layers`]).
    GeoPackage,
    /// FlatGeobuf: the same layers, one file each.
    FlatGeobuf,
}

/// What the text formats say beside a result's geometry, and how they write it.
#[derive(Debug, Clone, Copy)]
pub struct Context {
    /// The method that made the result (GeoJSON's `method`).
    pub method: Method,
    /// The EPSG code for GeoJSON's legacy `crs` member, when asked for.
    pub legacy_crs: Option<u32>,
    /// Whether the points are longitude and latitude (GeoJSON is cut at the antimeridian).
    pub lon_lat: bool,
}

impl OutputFormat {
    /// Every format, in the order they are listed in help texts.
    pub const ALL: &'static [OutputFormat] = &[
        OutputFormat::Text(Text::Edges),
        OutputFormat::Text(Text::Loops),
        OutputFormat::Text(Text::Wkt),
        OutputFormat::Text(Text::GeoJson),
        OutputFormat::Svg,
        OutputFormat::Png,
        OutputFormat::GeoPackage,
        OutputFormat::FlatGeobuf,
    ];

    /// The lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            OutputFormat::Text(text) => text.name(),
            OutputFormat::Svg => "svg",
            OutputFormat::Png => "png",
            OutputFormat::GeoPackage => "gpkg",
            OutputFormat::FlatGeobuf => "fgb",
        }
    }

    /// Whether it is a GIS format, whose layers [`gis_output`](crate::gis_output) writes.
    pub fn is_gis(self) -> bool {
        matches!(self, OutputFormat::GeoPackage | OutputFormat::FlatGeobuf)
    }

    /// The format implied by the file extension (case-insensitive): the kernel's text
    /// extensions, `.svg`, `.png`, `.gpkg` and `.fgb`; anything else is `None`.
    pub fn from_path(path: &Path) -> Option<OutputFormat> {
        let is = |ext: &str| path.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext));
        if is("svg") {
            Some(OutputFormat::Svg)
        } else if is("png") {
            Some(OutputFormat::Png)
        } else if is("gpkg") {
            Some(OutputFormat::GeoPackage)
        } else if is("fgb") {
            Some(OutputFormat::FlatGeobuf)
        } else {
            Text::from_path(path).map(OutputFormat::Text)
        }
    }

    /// Writes `rec`, whose indices refer to `points`, to `w` in this format; the GIS formats
    /// are layers, written by [`gis_output`](crate::gis_output), not to one stream.
    pub fn write(
        self,
        w: &mut dyn Write,
        points: &[Point],
        rec: &Reconstruction,
        context: Context,
    ) -> io::Result<()> {
        match self {
            OutputFormat::Text(text) => {
                let legacy_crs = context.legacy_crs.map(|c| format!("urn:ogc:def:crs:EPSG::{c}"));
                let options = WriteOptions { method: Some(context.method), legacy_crs };
                match context.lon_lat {
                    true => write_reconstruction_lon_lat(w, text, points, rec, &options),
                    false => write_reconstruction_with(w, text, points, rec, &options),
                }
            }
            OutputFormat::Svg => w.write_all(picture(points, rec).as_bytes()),
            OutputFormat::Png => {
                let bytes =
                    crate::png::svg_to_png(&picture(points, rec)).map_err(io::Error::other)?;
                w.write_all(&bytes)
            }
            OutputFormat::GeoPackage | OutputFormat::FlatGeobuf => {
                Err(io::Error::other(format!("{self}: layers, written by gis_output")))
            }
        }
    }
}

/// The SVG output: the points and the result, with the default [`RenderOptions`]. A method
/// with vertices of its own is drawn on them (the title says so).
fn picture(points: &[Point], rec: &Reconstruction) -> String {
    let layers = Layers { points: true, result: Some(rec), ..Layers::default() };
    let vertices = rec.vertex_positions(points);
    let mut options = RenderOptions::default();
    if !std::ptr::eq(vertices, points) {
        options.title = Some(format!(
            "sigdt: {} points, drawn at the method's {} vertices",
            points.len(),
            vertices.len()
        ));
    }
    render_svg(vertices, &layers, &options)
}

impl Default for OutputFormat {
    fn default() -> Self {
        OutputFormat::Text(Text::Edges)
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

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: [Point; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];

    fn text(format: OutputFormat, points: &[Point], rec: &Reconstruction) -> String {
        let mut out = Vec::new();
        let context = Context { method: Method::SigConnect2d, legacy_crs: None, lon_lat: false };
        format.write(&mut out, points, rec, context).unwrap();
        String::from_utf8(out).unwrap()
    }

    fn square() -> Reconstruction {
        Reconstruction {
            edges: vec![[0, 1], [0, 3], [1, 2], [2, 3]],
            loops: vec![vec![0, 1, 2, 3]],
            ..Reconstruction::default()
        }
    }

    #[test]
    fn names_round_trip() {
        for &f in OutputFormat::ALL {
            assert_eq!(f.to_string().parse::<OutputFormat>().unwrap(), f);
        }
        let err = "jpg".parse::<OutputFormat>().unwrap_err().to_string();
        let names = "edges, loops, wkt, geojson, svg, png, gpkg, fgb";
        assert!(err.contains("'jpg'") && err.contains(names), "{err}");
        let format = |name: &str| OutputFormat::from_path(Path::new(name));
        assert_eq!(format("a.JSON"), Some(OutputFormat::Text(Text::GeoJson)));
        assert_eq!(format("a.txt"), Some(OutputFormat::Text(Text::Edges)));
        assert_eq!(format("a.loops"), Some(OutputFormat::Text(Text::Loops)));
        assert_eq!(format("a.SVG"), Some(OutputFormat::Svg));
        assert_eq!(format("a.PNG"), Some(OutputFormat::Png));
        assert_eq!(format("a.jpg"), None);
    }

    #[test]
    fn svg_is_the_picture() {
        let svg = text(OutputFormat::Svg, &SQUARE, &square());
        assert_eq!(svg, picture(&SQUARE, &square()));
        assert!(svg.starts_with("<svg ") && svg.ends_with("</svg>\n"), "{svg}");
        assert!(svg.contains("points 4") && svg.contains("result 4 edges, 1 loop"), "{svg}");
        let empty = Reconstruction { status: sigdt::Status::TooFewPoints, ..Default::default() };
        let empty = text(OutputFormat::Svg, &[], &empty);
        assert!(empty.ends_with("</svg>\n") && !empty.contains("NaN"), "{empty}");
    }
}
