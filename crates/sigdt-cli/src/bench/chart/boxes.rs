//! Box plots of a measure's distribution: one box per method, side by side.
use super::axis::Axis;
use super::svg::{escape, marker, num, style, Marker, Svg, Swatch, BOTTOM, LEFT, RIGHT, TOP};

/// Box plots of non-negative values (for example the symmetric area difference per case) as
/// an SVG document: one box per series, from the lower to the upper quartile with the median
/// drawn across it, whiskers to the 5th and 95th percentiles and the mean as a diamond.
/// Non-finite values are ignored; a series without values leaves a gap. Each box's tooltip
/// gives its quartiles, mean and count.
pub fn box_plots(title: &str, y_label: &str, series: &[(String, Vec<f64>)]) -> String {
    let mut svg = Svg::new(title, "");
    let summaries: Vec<Option<BoxSummary>> =
        series.iter().map(|(_, values)| BoxSummary::of(values)).collect();
    let y = Axis::linear(summaries.iter().flatten().flat_map(|b| [b.p95, b.mean]), true);
    svg.y_axis(&y, y_label);
    let to_y = |v: f64| BOTTOM - y.frac(v).unwrap_or(0.0) * (BOTTOM - TOP);
    let slot = (RIGHT - LEFT) / series.len().max(1) as f64;
    for (i, ((name, _), summary)) in series.iter().zip(&summaries).enumerate() {
        let Some(b) = summary else { continue };
        let colour = style(i).colour;
        let centre = LEFT + slot * (i as f64 + 0.5);
        let half = (slot * 0.3).min(18.0);
        svg.line((centre, to_y(b.p05)), (centre, to_y(b.q1)), "#333");
        svg.line((centre, to_y(b.q3)), (centre, to_y(b.p95)), "#333");
        for whisker in [b.p05, b.p95] {
            svg.line(
                (centre - half / 2.0, to_y(whisker)),
                (centre + half / 2.0, to_y(whisker)),
                "#333",
            );
        }
        let tip = escape(&format!(
            "{name}: median {}, quartiles {} to {}, mean {}, {} values",
            short(b.median),
            short(b.q1),
            short(b.q3),
            short(b.mean),
            b.count
        ));
        let (top, bottom) = (to_y(b.q3), to_y(b.q1));
        svg.push(&format!(
            r##"<rect x="{}" y="{}" width="{}" height="{}" fill="{colour}" fill-opacity="0.45" stroke="#333" stroke-width="0.8"><title>{tip}</title></rect>"##,
            num(centre - half),
            num(top),
            num(2.0 * half),
            num((bottom - top).max(1.0)),
        ));
        svg.line((centre - half, to_y(b.median)), (centre + half, to_y(b.median)), "#000");
        svg.push(&marker(Marker::Diamond, centre, to_y(b.mean), colour));
    }
    if summaries.iter().all(Option::is_none) {
        svg.no_data();
    }
    for (i, (name, _)) in series.iter().enumerate() {
        let x = LEFT + slot * (i as f64 + 0.5);
        let y = BOTTOM + 14.0;
        let attrs = format!(r#"text-anchor="end" transform="rotate(-35 {} {})""#, num(x), num(y));
        svg.text(x, y, &attrs, name);
    }
    svg.frame();
    let names: Vec<&str> = series.iter().map(|(n, _)| n.as_str()).collect();
    svg.legend(&names, |i| Swatch::Bar(style(i).colour.to_string()));
    svg.finish()
}

/// The five numbers of a box and the mean.
#[derive(Debug, Clone, Copy, PartialEq)]
struct BoxSummary {
    p05: f64,
    q1: f64,
    median: f64,
    q3: f64,
    p95: f64,
    mean: f64,
    count: usize,
}

impl BoxSummary {
    /// The summary of the finite `values`; `None` without any.
    fn of(values: &[f64]) -> Option<BoxSummary> {
        let mut v: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        // Linear interpolation between the closest ranks.
        let at = |q: f64| {
            let pos = q * (v.len() - 1) as f64;
            let (k, f) = (pos.floor() as usize, pos.fract());
            v[k] + f * (v[(k + 1).min(v.len() - 1)] - v[k])
        };
        Some(BoxSummary {
            p05: at(0.05),
            q1: at(0.25),
            median: at(0.5),
            q3: at(0.75),
            p95: at(0.95),
            mean: v.iter().sum::<f64>() / v.len() as f64,
            count: v.len(),
        })
    }
}

/// Three significant digits.
fn short(v: f64) -> String {
    format!("{v:.2e}")
}

#[cfg(test)]
mod tests {
    use super::super::svg::assert_clean as clean;
    use super::*;

    #[test]
    fn quantiles_interpolate_between_ranks() {
        let b = BoxSummary::of(&[4.0, 0.0, 2.0, 1.0, 3.0, f64::NAN]).unwrap();
        assert_eq!((b.q1, b.median, b.q3, b.count), (1.0, 2.0, 3.0, 5));
        assert!((b.p05 - 0.2).abs() < 1e-12 && (b.p95 - 3.8).abs() < 1e-12);
        assert_eq!(b.mean, 2.0);
        assert_eq!(BoxSummary::of(&[f64::NAN]), None);
        assert_eq!(BoxSummary::of(&[7.0]).unwrap().p95, 7.0);
    }

    #[test]
    fn boxes_show_every_series_and_survive_gaps() {
        let series = vec![
            ("sig-auto".to_string(), vec![0.0, 0.01, 0.02, 0.5]),
            ("a & <b>".to_string(), vec![]),
            ("crust".to_string(), vec![0.1; 3]),
        ];
        let svg = box_plots("Symmetric \"area\" difference", "area / box", &series);
        clean(&svg);
        assert!(svg.contains("sig-auto: median 1.50e-2") && svg.contains("a &amp; &lt;b&gt;"));
        assert_eq!(svg.matches("fill-opacity=\"0.45\"").count(), 2, "two boxes, one gap");
        assert!(!svg.contains("no data"));
        let empty = box_plots("none", "y", &[("m".to_string(), vec![f64::NAN])]);
        clean(&empty);
        assert!(empty.contains("no data"));
    }
}
