//! The SVG canvas shared by the charts: layout, palette, markers, axes and legend.
use super::axis::Axis;
use std::fmt::Write;

/// The chart size in pixels.
pub(super) const WIDTH: f64 = 800.0;
pub(super) const HEIGHT: f64 = 450.0;
/// The plot area; the legend sits to its right.
pub(super) const LEFT: f64 = 72.0;
pub(super) const TOP: f64 = 44.0;
pub(super) const RIGHT: f64 = 600.0;
pub(super) const BOTTOM: f64 = 380.0;

/// Okabe–Ito's eight colours, then four of Paul Tol's "muted" scheme.
const PALETTE: [&str; 12] = [
    "#0072B2", "#D55E00", "#009E73", "#E69F00", "#56B4E9", "#CC79A7", "#000000", "#F0E442",
    "#882255", "#44AA99", "#999933", "#332288",
];
/// Dash patterns; with 6 markers every one of the first 12 series has its own pair.
const DASHES: [&str; 4] = ["", "6 3", "2 2", "8 3 2 3"];

/// The longest legend label shown in full.
const LEGEND_CHARS: usize = 22;

/// A marker shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Marker {
    Circle,
    Square,
    TriangleUp,
    Diamond,
    TriangleDown,
    Cross,
}

const MARKERS: [Marker; 6] = [
    Marker::Circle,
    Marker::Square,
    Marker::TriangleUp,
    Marker::Diamond,
    Marker::TriangleDown,
    Marker::Cross,
];

/// How series `i` is drawn.
pub(super) struct Style {
    pub colour: &'static str,
    pub dash: &'static str,
    pub marker: Marker,
    /// Bars of this series are hatched (every other series).
    pub hatched: bool,
}

/// The style of series `i`; colours repeat after 12, shifted against markers and dashes.
pub(super) fn style(i: usize) -> Style {
    Style {
        colour: PALETTE[i % PALETTE.len()],
        dash: DASHES[i % DASHES.len()],
        marker: MARKERS[(i + i / PALETTE.len()) % MARKERS.len()],
        hatched: i % 2 == 1,
    }
}

/// A legend swatch.
pub(super) enum Swatch {
    /// A filled box (bars), with the series' fill.
    Bar(String),
    /// A line sample with a marker (line charts) or only a marker (scatter plots).
    Line { lines: bool },
}

/// An SVG document being written.
pub(super) struct Svg {
    out: String,
}

impl Svg {
    /// The document with its title, background and optional `<defs>`.
    pub fn new(title: &str, defs: &str) -> Svg {
        let mut out = String::new();
        let _ = write!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif" font-size="11" role="img">"#
        );
        let title = escape(title);
        let _ = write!(out, "\n<title>{title}</title>\n");
        if !defs.is_empty() {
            let _ = writeln!(out, "<defs>{defs}</defs>");
        }
        let _ = writeln!(out, r#"<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>"#);
        let x = num((LEFT + RIGHT) / 2.0);
        let _ = writeln!(
            out,
            r#"<text x="{x}" y="24" text-anchor="middle" font-size="15" font-weight="bold">{title}</text>"#
        );
        Svg { out }
    }

    /// Appends raw markup (already escaped).
    pub fn push(&mut self, markup: &str) {
        self.out.push_str(markup);
        self.out.push('\n');
    }

    /// Text at (x, y); `attrs` are extra attributes (already escaped).
    pub fn text(&mut self, x: f64, y: f64, attrs: &str, content: &str) {
        let (x, y, content) = (num(x), num(y), escape(content));
        self.push(&format!(r#"<text x="{x}" y="{y}" {attrs}>{content}</text>"#));
    }

    /// A thin line.
    pub fn line(&mut self, (x1, y1): (f64, f64), (x2, y2): (f64, f64), stroke: &str) {
        let (x1, y1, x2, y2) = (num(x1), num(y1), num(x2), num(y2));
        self.push(&format!(
            r#"<line x1="{x1}" y1="{y1}" x2="{x2}" y2="{y2}" stroke="{stroke}" stroke-width="1"/>"#
        ));
    }

    /// "no data" in the middle of the plot area.
    pub fn no_data(&mut self) {
        let (x, y) = ((LEFT + RIGHT) / 2.0, (TOP + BOTTOM) / 2.0);
        self.text(x, y, r##"text-anchor="middle" fill="#666" font-size="14""##, "no data");
    }

    /// The vertical axis: grid lines, ticks, tick labels and the rotated label.
    pub fn y_axis(&mut self, axis: &Axis, label: &str) {
        for &t in &axis.minor {
            let y = BOTTOM - axis.tick_frac(t) * (BOTTOM - TOP);
            self.line((LEFT - 3.0, y), (LEFT, y), "#444");
        }
        for (t, text) in &axis.ticks {
            let y = BOTTOM - axis.tick_frac(*t) * (BOTTOM - TOP);
            self.line((LEFT, y), (RIGHT, y), "#e4e4e4");
            self.line((LEFT - 5.0, y), (LEFT, y), "#444");
            self.text(LEFT - 8.0, y + 4.0, r#"text-anchor="end""#, text);
        }
        let (x, y) = (num(18.0), num((TOP + BOTTOM) / 2.0));
        let attrs =
            format!(r#"text-anchor="middle" font-size="12" transform="rotate(-90 {x} {y})""#);
        self.text(18.0, (TOP + BOTTOM) / 2.0, &attrs, label);
    }

    /// The horizontal axis of a numeric chart: grid lines, ticks, tick labels and label.
    pub fn x_axis(&mut self, axis: &Axis, label: &str) {
        for &t in &axis.minor {
            let x = LEFT + axis.tick_frac(t) * (RIGHT - LEFT);
            self.line((x, BOTTOM), (x, BOTTOM + 3.0), "#444");
        }
        for (t, text) in &axis.ticks {
            let x = LEFT + axis.tick_frac(*t) * (RIGHT - LEFT);
            self.line((x, TOP), (x, BOTTOM), "#e4e4e4");
            self.line((x, BOTTOM), (x, BOTTOM + 5.0), "#444");
            self.text(x, BOTTOM + 18.0, r#"text-anchor="middle""#, text);
        }
        self.x_label(label);
    }

    /// The label under the horizontal axis.
    pub fn x_label(&mut self, label: &str) {
        let x = (LEFT + RIGHT) / 2.0;
        self.text(x, BOTTOM + 40.0, r#"text-anchor="middle" font-size="12""#, label);
    }

    /// The frame around the plot area.
    pub fn frame(&mut self) {
        let (x, y, w, h) = (num(LEFT), num(TOP), num(RIGHT - LEFT), num(BOTTOM - TOP));
        self.push(&format!(
            r##"<rect x="{x}" y="{y}" width="{w}" height="{h}" fill="none" stroke="#444"/>"##
        ));
    }

    /// The legend, one row per series, right of the plot area.
    pub fn legend(&mut self, names: &[&str], swatch: impl Fn(usize) -> Swatch) {
        let x = RIGHT + 16.0;
        for (i, name) in names.iter().enumerate() {
            let y = TOP + 8.0 + 18.0 * i as f64;
            let s = style(i);
            match swatch(i) {
                Swatch::Bar(fill) => {
                    let (bx, by) = (num(x), num(y - 6.0));
                    self.push(&format!(
                        r##"<rect x="{bx}" y="{by}" width="22" height="11" fill="{fill}" stroke="#333" stroke-width="0.5"/>"##
                    ));
                }
                Swatch::Line { lines } => {
                    if lines {
                        self.push(&polyline(&[(x, y), (x + 22.0, y)], &s));
                    }
                    self.push(&marker(s.marker, x + 11.0, y, s.colour));
                }
            }
            let shown: String = if name.chars().count() > LEGEND_CHARS {
                name.chars().take(LEGEND_CHARS - 1).chain(['…']).collect()
            } else {
                name.to_string()
            };
            let (tx, ty, full, shown) = (num(x + 28.0), num(y + 4.0), escape(name), escape(&shown));
            self.push(&format!(r#"<text x="{tx}" y="{ty}">{shown}<title>{full}</title></text>"#));
        }
    }

    /// The finished document.
    pub fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// A polyline through `points` in the series' colour and dash pattern.
pub(super) fn polyline(points: &[(f64, f64)], s: &Style) -> String {
    let coords: Vec<String> =
        points.iter().map(|&(x, y)| format!("{},{}", num(x), num(y))).collect();
    let dash = if s.dash.is_empty() {
        String::new()
    } else {
        format!(r#" stroke-dasharray="{}""#, s.dash)
    };
    format!(
        r#"<polyline points="{}" fill="none" stroke="{}" stroke-width="1.8"{dash}/>"#,
        coords.join(" "),
        s.colour
    )
}

/// A marker centred at (x, y).
pub(super) fn marker(m: Marker, x: f64, y: f64, colour: &str) -> String {
    let r = 3.5;
    let p = |pts: &[(f64, f64)]| {
        let d: Vec<String> =
            pts.iter().map(|&(dx, dy)| format!("{},{}", num(x + dx), num(y + dy))).collect();
        format!(
            r#"<path d="M{}Z" fill="{colour}" fill-opacity="0.75" stroke="{colour}"/>"#,
            d.join("L")
        )
    };
    match m {
        Marker::Circle => format!(
            r#"<circle cx="{}" cy="{}" r="{r}" fill="{colour}" fill-opacity="0.75" stroke="{colour}"/>"#,
            num(x),
            num(y)
        ),
        Marker::Square => p(&[(-r, -r), (r, -r), (r, r), (-r, r)]),
        Marker::TriangleUp => p(&[(0.0, -1.2 * r), (r, 0.8 * r), (-r, 0.8 * r)]),
        Marker::Diamond => p(&[(0.0, -1.3 * r), (r, 0.0), (0.0, 1.3 * r), (-r, 0.0)]),
        Marker::TriangleDown => p(&[(0.0, 1.2 * r), (r, -0.8 * r), (-r, -0.8 * r)]),
        Marker::Cross => {
            let (a, b, c, d) = (num(x - r), num(x + r), num(y - r), num(y + r));
            format!(
                r#"<path d="M{a},{c}L{b},{d}M{a},{d}L{b},{c}" stroke="{colour}" stroke-width="1.8"/>"#
            )
        }
    }
}

/// A coordinate with one decimal; a non-finite value (a bug) becomes 0 rather than `NaN`.
pub(super) fn num(v: f64) -> String {
    debug_assert!(v.is_finite(), "non-finite coordinate");
    format!("{:.1}", if v.is_finite() { v } else { 0.0 })
}

pub(super) use sigdt_lab::render::escape_xml as escape;

/// Asserts a chart is well formed and has no NaN or infinite coordinate (test helper).
#[cfg(test)]
pub(crate) fn assert_clean(svg: &str) {
    assert_well_formed(svg);
    for bad in ["NaN", "inf"] {
        assert!(!svg.contains(bad), "{bad} in\n{svg}");
    }
}

/// Panics unless `xml` is well formed: balanced tags, quoted attributes, escaped text.
#[cfg(test)]
pub(crate) fn assert_well_formed(xml: &str) {
    fn text_ok(t: &str) {
        for (i, _) in t.match_indices('&') {
            let entity = &t[i..t[i..].find(';').map_or(t.len(), |e| i + e + 1)];
            let ok = ["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"].contains(&entity)
                || (entity.starts_with("&#") && entity.len() > 3);
            assert!(ok, "bad entity in {t:?}");
        }
        assert!(!t.contains('<') && !t.contains('>'), "unescaped markup in {t:?}");
    }
    let mut stack: Vec<&str> = Vec::new();
    let mut rest = xml.trim();
    assert!(rest.starts_with("<svg"), "no <svg> root");
    while let Some(open) = rest.find('<') {
        text_ok(&rest[..open]);
        let close = open + rest[open..].find('>').expect("unclosed tag");
        let tag = &rest[open + 1..close];
        rest = &rest[close + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop(), Some(name), "mismatched </{name}>");
            assert!(!stack.is_empty() || rest.trim().is_empty(), "content after the root");
            continue;
        }
        let self_closing = tag.ends_with('/');
        let body = tag.trim_end_matches('/');
        let (name, mut attrs) = body.split_once(' ').unwrap_or((body, ""));
        assert!(!name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '-'));
        while !attrs.trim().is_empty() {
            let (key, after) = attrs.trim_start().split_once("=\"").expect("attribute");
            assert!(key.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == ':'));
            let (value, after) = after.split_once('"').expect("unterminated attribute");
            text_ok(value);
            attrs = after;
        }
        if !self_closing {
            stack.push(name);
        }
    }
    text_ok(rest);
    assert!(stack.is_empty(), "unclosed {stack:?}");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escape_and_checker() {
        assert_eq!(escape(r#"a<b & "c's">"#), "a&lt;b &amp; &quot;c&apos;s&quot;&gt;");
        assert_well_formed(r#"<svg a="1"><g><text x="1">a &amp; b</text><rect/></g></svg>"#);
        for bad in ["<svg><g></svg>", "<svg>a & b</svg>", r#"<svg a="1></svg>"#, "<svg></svg><x/>"]
        {
            assert!(std::panic::catch_unwind(|| assert_well_formed(bad)).is_err(), "{bad}");
        }
    }

    #[test]
    fn styles_differ() {
        let pairs: Vec<(&str, usize)> = (0..12)
            .map(|i| (style(i).dash, MARKERS.iter().position(|&m| m == style(i).marker).unwrap()))
            .collect();
        for i in 0..12 {
            assert!(!pairs[..i].contains(&pairs[i]), "series {i} looks like an earlier one");
        }
        assert_eq!(num(f64::from(1u8) / 3.0), "0.3");
    }
}
