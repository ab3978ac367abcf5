//! The legend: one entry per drawn layer (a small sample of its stroke and a label with its
//! count), in rows below the drawing, and the escaping of text.

use std::fmt::Write as _;

use super::frame::MARGIN;
use super::path::pixels;

/// Font size of the legend, in pixels.
const FONT: f64 = 12.0;
/// Height of one legend row, in pixels.
const ROW: f64 = 19.0;
/// Width of a swatch and the gap before its label, in pixels.
const SWATCH: f64 = 20.0;
const GAP: f64 = 6.0;
/// Space between two entries of a row, in pixels.
const SPREAD: f64 = 18.0;
/// Estimated advance of one character at [`FONT`] in a sans-serif face (DejaVu Sans is among
/// the widest), so entries do not overlap whichever font draws them.
const CHAR: f64 = 0.6 * FONT;

/// How a legend entry shows its layer.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Swatch {
    /// A line segment: colour, width in pixels, dashed.
    Line(&'static str, f64, bool),
    /// A filled dot.
    Dot(&'static str),
    /// A ring (circle outline) of the given radius.
    Ring(&'static str, f64),
    /// A filled box with an outline: fill, outline.
    Fill(&'static str, &'static str),
}

/// One line of the legend.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Entry {
    pub swatch: Swatch,
    pub label: String,
}

impl Entry {
    fn width(&self) -> f64 {
        SWATCH + GAP + CHAR * self.label.chars().count() as f64
    }
}

/// The height of the legend band for `entries` on a picture `width` pixels wide; 0 without
/// entries.
pub(crate) fn height(entries: &[Entry], width: f64) -> f64 {
    let rows = layout(entries, width).last().map_or(0, |&(row, _)| row + 1);
    if rows == 0 {
        0.0
    } else {
        rows as f64 * ROW + MARGIN / 2.0
    }
}

/// Draws the legend with its first row's top at `top`.
pub(crate) fn draw(out: &mut String, entries: &[Entry], width: f64, top: f64) {
    if entries.is_empty() {
        return;
    }
    let _ = writeln!(out, "<g font-family=\"sans-serif\" font-size=\"{}\" fill=\"#222\">", FONT);
    for (entry, (row, x)) in entries.iter().zip(layout(entries, width)) {
        let y = top + row as f64 * ROW + ROW / 2.0;
        let (x0, x1, cx) = (pixels(x), pixels(x + SWATCH), pixels(x + SWATCH / 2.0));
        let cy = pixels(y);
        match entry.swatch {
            Swatch::Line(colour, w, dashed) => {
                let w = w.clamp(1.5, 4.0);
                let dash = if dashed {
                    format!(" stroke-dasharray=\"{}\"", pixels(2.0 * w))
                } else {
                    String::new()
                };
                let _ = writeln!(
                    out,
                    "<path d=\"M{x0} {cy}H{x1}\" stroke=\"{colour}\" stroke-width=\"{}\"{dash}/>",
                    pixels(w)
                );
            }
            Swatch::Dot(colour) => {
                let _ =
                    writeln!(out, "<circle cx=\"{cx}\" cy=\"{cy}\" r=\"3\" fill=\"{colour}\"/>");
            }
            Swatch::Ring(colour, r) => {
                let _ = writeln!(
                    out,
                    "<circle cx=\"{cx}\" cy=\"{cy}\" r=\"{}\" fill=\"none\" stroke=\"{colour}\" \
                     stroke-width=\"1.2\"/>",
                    pixels(r.clamp(3.0, 7.0))
                );
            }
            Swatch::Fill(fill, edge) => {
                let _ = writeln!(
                    out,
                    "<rect x=\"{x0}\" y=\"{}\" width=\"{SWATCH}\" height=\"10\" fill=\"{fill}\" \
                     stroke=\"{edge}\"/>",
                    pixels(y - 5.0)
                );
            }
        }
        let tx = pixels(x + SWATCH + GAP);
        let ty = pixels(y + 0.35 * FONT);
        let _ = writeln!(out, "<text x=\"{tx}\" y=\"{ty}\">{}</text>", escape(&entry.label));
    }
    out.push_str("</g>\n");
}

/// `(row, x)` of every entry: entries fill a row left to right, then wrap.
fn layout(entries: &[Entry], width: f64) -> Vec<(usize, f64)> {
    let (mut row, mut x) = (0, MARGIN);
    let mut out = Vec::with_capacity(entries.len());
    for entry in entries {
        let w = entry.width();
        if x > MARGIN && x + w > width - MARGIN {
            (row, x) = (row + 1, MARGIN);
        }
        out.push((row, x));
        x += w + SPREAD;
    }
    out
}

/// `text` with the five XML special characters escaped and control characters dropped
/// (tabs and newlines become spaces), for SVG text and attributes.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' => out.push(' '),
            c if c.is_control() => {}
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(label: &str) -> Entry {
        Entry { swatch: Swatch::Dot("#000"), label: label.to_string() }
    }

    #[test]
    fn entries_wrap_into_rows() {
        let entries: Vec<Entry> = (0..6).map(|k| entry(&format!("layer {k} 1234"))).collect();
        let rows = layout(&entries, 400.0);
        assert_eq!(rows[0], (0, MARGIN));
        assert!(rows.iter().all(|&(_, x)| x + entries[0].width() <= 400.0 - MARGIN));
        assert_eq!(rows.last().unwrap().0, 2);
        assert_eq!(height(&entries, 400.0), 3.0 * ROW + MARGIN / 2.0);
        assert_eq!(height(&[], 400.0), 0.0);
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(
            escape("a<b & \"c\"\u{7}\n'd'>"),
            "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;"
        );
        let mut out = String::new();
        draw(&mut out, &[entry("x < y")], 800.0, 10.0);
        assert!(out.contains(">x &lt; y</text>"), "{out}");
    }
}
