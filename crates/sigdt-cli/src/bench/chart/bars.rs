//! Grouped bar charts of percentages: one group per category, one bar per method.
use super::axis::Axis;
use super::svg::{escape, num, style, Svg, Swatch, BOTTOM, LEFT, RIGHT, TOP};

/// A grouped bar chart of percentages (0..100) as an SVG document.
///
/// `series` holds, per method, one value per group; `None` leaves a gap. Values are clamped
/// to 0..100 and a zero is drawn as a hairline so it differs from a gap. Every bar carries a
/// tooltip with its value.
pub fn grouped_bars(
    title: &str,
    y_label: &str,
    groups: &[String],
    series: &[(String, Vec<Option<f64>>)],
) -> String {
    let defs: String = (0..series.len())
        .filter(|&i| style(i).hatched)
        .map(|i| {
            let colour = style(i).colour;
            format!(
                r#"<pattern id="hatch{i}" patternUnits="userSpaceOnUse" width="5" height="5" patternTransform="rotate(45)"><rect width="5" height="5" fill="{colour}"/><line x1="0" y1="0" x2="0" y2="5" stroke="white" stroke-width="1.6"/></pattern>"#
            )
        })
        .collect();
    let fill = |i: usize| {
        let s = style(i);
        if s.hatched {
            format!("url(#hatch{i})")
        } else {
            s.colour.to_string()
        }
    };
    let mut svg = Svg::new(title, &defs);
    let y = Axis::fixed(0.0, 100.0, 20.0);
    svg.y_axis(&y, y_label);

    let slot = (RIGHT - LEFT) / groups.len().max(1) as f64;
    let bar = slot * 0.8 / series.len().max(1) as f64;
    let mut any = false;
    for (g, group) in groups.iter().enumerate() {
        let x0 = LEFT + slot * g as f64 + slot * 0.1;
        for (i, (name, values)) in series.iter().enumerate() {
            let Some(v) = values.get(g).copied().flatten().filter(|v| v.is_finite()) else {
                continue;
            };
            any = true;
            let height = (v.clamp(0.0, 100.0) / 100.0 * (BOTTOM - TOP)).max(1.0);
            let (bx, by, bw, bh) = (x0 + bar * i as f64, BOTTOM - height, bar, height);
            let tip = escape(&format!("{name}, {group}: {v:.1} %"));
            svg.push(&format!(
                r##"<rect x="{}" y="{}" width="{}" height="{}" fill="{}" stroke="#333" stroke-width="0.5"><title>{tip}</title></rect>"##,
                num(bx),
                num(by),
                num(bw),
                num(bh),
                fill(i)
            ));
        }
    }
    if !any {
        svg.no_data();
    }

    // Group labels, slanted when they would not fit side by side.
    let widest = groups.iter().map(|g| g.chars().count()).max().unwrap_or(0);
    let slanted = widest as f64 * 6.5 > slot;
    for (g, group) in groups.iter().enumerate() {
        let x = LEFT + slot * (g as f64 + 0.5);
        let y = BOTTOM + 16.0;
        let attrs = if slanted {
            format!(r#"text-anchor="end" transform="rotate(-25 {} {})""#, num(x), num(y))
        } else {
            r#"text-anchor="middle""#.to_string()
        };
        svg.text(x, y, &attrs, group);
    }
    svg.frame();
    let names: Vec<&str> = series.iter().map(|(n, _)| n.as_str()).collect();
    svg.legend(&names, |i| Swatch::Bar(fill(i)));
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::super::svg::assert_clean as clean;
    use super::*;

    #[test]
    fn bars_show_every_series() {
        let groups: Vec<String> = ["manifold", "sharp", "open"].map(String::from).to_vec();
        let series = vec![
            ("sig-connect2d".to_string(), vec![Some(95.5), Some(70.0), Some(0.0)]),
            ("crust & <friends>".to_string(), vec![None, Some(f64::NAN), Some(150.0)]),
        ];
        let svg = grouped_bars("Exact \"rate\"", "exact (%)", &groups, &series);
        clean(&svg);
        assert!(svg.contains("sig-connect2d") && svg.contains("crust &amp; &lt;friends&gt;"));
        assert!(svg.contains("sig-connect2d, manifold: 95.5 %"));
        assert!(svg.contains("url(#hatch1)") && svg.contains(r#"id="hatch1""#));
        assert!(svg.contains(">manifold</text>") && !svg.contains("no data"));
        assert_eq!(svg.matches("<rect x=").count(), 4 + 1 + 2, "4 bars, frame, 2 swatches");
    }

    #[test]
    fn bars_survive_empty_input() {
        clean(&grouped_bars("empty", "y", &[], &[]));
        let groups = vec!["a-very-long-category-name".to_string(); 9];
        let series: Vec<_> = (0..14).map(|i| (format!("method {i}"), vec![None; 9])).collect();
        let svg = grouped_bars("all none", "y", &groups, &series);
        clean(&svg);
        assert!(svg.contains("no data") && svg.contains("rotate(-25"));
        assert!((0..14).all(|i| svg.contains(&format!("method {i}<"))));
    }
}
