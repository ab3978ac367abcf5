//! Scatter plots and line charts on linear or logarithmic axes.
use super::axis::Axis;
use super::svg::{marker, polyline, style, Svg, Swatch, BOTTOM, LEFT, RIGHT, TOP};

/// A log-log scatter plot (for example runtime against number of points) as an SVG document.
///
/// Points with a non-positive or non-finite coordinate are skipped. Ticks are at decades.
pub fn log_log_scatter(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[(String, Vec<(f64, f64)>)],
) -> String {
    xy_chart(title, x_label, y_label, (true, true), false, series)
}

/// A line chart with markers, each series sorted by x (for example RMSE against noise level).
///
/// On a log axis, points with a non-positive coordinate are skipped; non-finite ones always are.
pub fn line_chart(
    title: &str,
    x_label: &str,
    y_label: &str,
    log_x: bool,
    log_y: bool,
    series: &[(String, Vec<(f64, f64)>)],
) -> String {
    xy_chart(title, x_label, y_label, (log_x, log_y), true, series)
}

fn xy_chart(
    title: &str,
    x_label: &str,
    y_label: &str,
    (log_x, log_y): (bool, bool),
    lines: bool,
    series: &[(String, Vec<(f64, f64)>)],
) -> String {
    let shown = |v: f64, log: bool| v.is_finite() && (!log || v > 0.0);
    let kept: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|(_, pts)| {
            let mut pts: Vec<(f64, f64)> =
                pts.iter().copied().filter(|&(x, y)| shown(x, log_x) && shown(y, log_y)).collect();
            if lines {
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            }
            pts
        })
        .collect();
    let axis = |log: bool, values: Vec<f64>| {
        if log {
            Axis::log(values)
        } else {
            Axis::linear(values, false)
        }
    };
    let x = axis(log_x, kept.iter().flatten().map(|p| p.0).collect());
    let y = axis(log_y, kept.iter().flatten().map(|p| p.1).collect());

    let mut svg = Svg::new(title, "");
    svg.y_axis(&y, y_label);
    svg.x_axis(&x, x_label);
    for (i, pts) in kept.iter().enumerate() {
        let s = style(i);
        let screen: Vec<(f64, f64)> = pts
            .iter()
            .filter_map(|&(px, py)| {
                let (fx, fy) = (x.frac(px)?, y.frac(py)?);
                Some((LEFT + fx * (RIGHT - LEFT), BOTTOM - fy * (BOTTOM - TOP)))
            })
            .collect();
        if lines && screen.len() > 1 {
            svg.push(&polyline(&screen, &s));
        }
        // On a line, at most about 25 markers, staggered between series so they overlap less.
        let every = if lines { screen.len().div_ceil(25).max(1) } else { 1 };
        let last = screen.len().saturating_sub(1);
        for (k, &(sx, sy)) in screen.iter().enumerate() {
            if (k + i) % every == 0 || k == last {
                svg.push(&marker(s.marker, sx, sy, s.colour));
            }
        }
    }
    if kept.iter().all(Vec::is_empty) {
        svg.no_data();
    }
    svg.frame();
    let names: Vec<&str> = series.iter().map(|(n, _)| n.as_str()).collect();
    svg.legend(&names, |_| Swatch::Line { lines });
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::super::svg::assert_clean as clean;
    use super::*;

    fn series() -> Vec<(String, Vec<(f64, f64)>)> {
        vec![
            ("sig-connect2d".into(), vec![(100.0, 0.5), (1000.0, 4.0), (9991.0, 75.0)]),
            ("crust".into(), vec![(0.0, 1.0), (-3.0, 2.0), (f64::NAN, 1.0), (260.0, 0.6)]),
            ("empty".into(), vec![]),
        ]
    }

    #[test]
    fn scatter_has_decades_and_every_series() {
        let svg = log_log_scatter("Runtime", "points", "time (ms)", &series());
        clean(&svg);
        for name in ["sig-connect2d<", "crust<", "empty<", ">10000<", ">0.1<", ">100<"] {
            assert!(svg.contains(name), "{name} missing");
        }
        assert!(!svg.contains("<polyline") && !svg.contains("no data"));
    }

    #[test]
    fn line_chart_on_any_axes() {
        for (log_x, log_y) in [(false, false), (true, false), (false, true), (true, true)] {
            let svg = line_chart("RMSE", "noise", "rmse", log_x, log_y, &series());
            clean(&svg);
            assert!(svg.contains("<polyline") && svg.contains("empty<"));
        }
        let flat = vec![("one point".to_string(), vec![(0.01, 0.0)])];
        clean(&line_chart("flat", "x", "y", true, false, &flat));
    }

    #[test]
    fn nothing_to_show() {
        let none = vec![("a".to_string(), vec![(0.0, 0.0), (f64::INFINITY, 1.0)])];
        for svg in [
            log_log_scatter("t", "x", "y", &none),
            line_chart("t", "x", "y", false, false, &[]),
            log_log_scatter("t", "x", "y", &[]),
        ] {
            clean(&svg);
            assert!(svg.contains("no data"));
        }
    }
}
