//! Drawing points, edges and loops as a standalone SVG picture.
//!
//! The picture is built in memory as one `String`. Coordinates are printed with as many
//! decimals as about 1% of the point spacing needs, so large pictures stay small.

use std::fmt::Write as _;

use crate::{Edge, Point};

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

    #[test]
    fn svg_square_and_degenerate_boxes() {
        let picture = svg(&SQUARE, &[[0, 1], [0, 3], [1, 2], [2, 3]], &[vec![0, 1, 2, 3]]);
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
