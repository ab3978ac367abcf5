//! Tests of [`render_svg`] on hand-made inputs: layers, comparison with ground truth,
//! density, and well-formed output.

use super::{render_svg, Layers, RenderOptions};
use sigdt::{Edge, Point, Reconstruction, Status};

const SQUARE: [Point; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
const SQUARE_EDGES: [Edge; 4] = [[0, 1], [0, 3], [1, 2], [2, 3]];

fn square() -> Reconstruction {
    Reconstruction {
        edges: SQUARE_EDGES.to_vec(),
        loops: vec![vec![0, 1, 2, 3]],
        ..Reconstruction::default()
    }
}

/// `n` points on the unit circle, the polygon through them, as a reconstruction.
fn circle(n: usize) -> (Vec<Point>, Reconstruction) {
    let points = (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            [t.cos(), t.sin()]
        })
        .collect();
    let mut edges: Vec<Edge> =
        (0..n).map(|k| [k, (k + 1) % n]).map(|[i, j]| [i.min(j), i.max(j)]).collect();
    edges.sort_unstable();
    let rec = Reconstruction { edges, loops: vec![(0..n).collect()], ..Reconstruction::default() };
    (points, rec)
}

fn render(points: &[Point], layers: &Layers) -> String {
    let svg = render_svg(points, layers, &RenderOptions::default());
    check_well_formed(&svg);
    svg
}

/// Tags balance, attribute values are quoted, `&` only starts an entity, every number in
/// the path data is finite and the output is the same on a second run.
fn check_well_formed(svg: &str) {
    assert!(
        svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\"") && svg.ends_with("</svg>\n")
    );
    assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
    let mut open = Vec::new();
    for tag in svg.split('<').skip(1) {
        let tag = &tag[..tag.find('>').expect("tag closed")];
        assert_eq!(tag.matches('"').count() % 2, 0, "<{tag}>");
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(open.pop(), Some(name), "</{name}>");
        } else if !tag.ends_with('/') {
            open.push(tag.split(' ').next().unwrap());
        }
    }
    assert!(open.is_empty(), "unclosed {open:?}");
    for (k, _) in svg.match_indices('&') {
        let entity = &svg[k..svg[k..].find(';').map_or(svg.len(), |e| k + e + 1)];
        assert!(["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"].contains(&entity), "{entity}");
    }
    for d in svg.split(" d=\"").skip(1) {
        let d = &d[..d.find('"').unwrap()];
        let numbers = d.replace(|c: char| c.is_ascii_alphabetic(), " ").replace('-', " -");
        for number in numbers.split_whitespace() {
            assert!(number.parse::<f64>().is_ok_and(f64::is_finite), "{number} in {d}");
        }
    }
}

#[test]
fn layers_present_and_absent() {
    let rec = square();
    let svg = render(&SQUARE, &Layers { points: true, ..Layers::default() });
    assert!(svg.contains("points 4") && svg.contains("h0"), "{svg}");
    for absent in ["Delaunay", "SIG", "result", "missing", "#dce8f4", "#009e73"] {
        assert!(!svg.contains(absent), "{absent} in\n{svg}");
    }
    let dt: Vec<Edge> = [SQUARE_EDGES.as_slice(), &[[0, 2]]].concat();
    let radii = [1.0; 4];
    let all = Layers {
        points: true,
        dt: Some(&dt),
        sig: Some(&radii),
        sigdt: Some(&SQUARE_EDGES),
        sigdt2: Some(&SQUARE_EDGES),
        boundary: Some(&SQUARE_EDGES),
        result: Some(&rec),
        gt: None,
    };
    let svg = render(&SQUARE, &all);
    for present in [
        "points 4",
        "Delaunay 5",
        "SIG circles 4",
        "SIGDT 4",
        "SIGDT2 4",
        "boundary 4",
        "result 4 edges, 1 loop (polygon)",
        "fill=\"#dce8f4\"",
    ] {
        assert!(svg.contains(present), "{present} not in\n{svg}");
    }
    // One <path> per layer: fill, 6 edge or circle layers, dots, plus the legend's lines.
    assert_eq!(svg.matches("<path fill=").count(), 1 + 6 + 1, "{svg}");
    assert!(!svg.contains("not on result") && !svg.contains("missing"));
    let bare =
        render_svg(&SQUARE, &all, &RenderOptions { legend: false, ..RenderOptions::default() });
    assert!(!bare.contains("<text") && bare.len() < svg.len());
}

#[test]
fn missing_and_extra_edges_have_their_colours_and_counts() {
    // The result closes the square through its diagonal 0-2 instead of 2-3 and 0-3.
    let rec = Reconstruction {
        edges: vec![[0, 1], [0, 2], [1, 2]],
        loops: vec![vec![0, 1, 2]],
        status: Status::SculptingStuck { left_out: vec![3] },
        ..Reconstruction::default()
    };
    let layers =
        Layers { points: true, result: Some(&rec), gt: Some(&SQUARE_EDGES), ..Layers::default() };
    let svg = render(&SQUARE, &layers);
    for present in
        ["in both 2, 1 loop (sculpting-stuck)", "missing 2", "extra 1", "not on result 1"]
    {
        assert!(svg.contains(present), "{present} not in\n{svg}");
    }
    let line = |colour: &str| {
        svg.lines().find(|l| l.starts_with("<path") && l.contains(colour)).unwrap().to_string()
    };
    assert!(line("stroke=\"#d55e00\"").contains("stroke-dasharray"), "missing edges are dashed");
    assert!(!line("stroke=\"#0072b2\"").contains("stroke-dasharray"), "extra edges are solid");
    let perfect =
        render(&SQUARE, &Layers { result: Some(&square()), gt: Some(&SQUARE_EDGES), ..layers });
    assert!(
        perfect.contains("in both 4")
            && perfect.contains("missing 0")
            && perfect.contains("extra 0")
    );
    assert!(!perfect.contains("d=\"\""), "empty layers are left out");
    // Ground truth alone is drawn dashed, in grey.
    let truth = render(&SQUARE, &Layers { gt: Some(&SQUARE_EDGES), ..Layers::default() });
    assert!(truth.contains("ground truth 4") && truth.contains("stroke=\"#6b6b6b\""), "{truth}");
}

#[test]
fn dense_points_are_hidden_next_to_other_layers() {
    let (points, rec) = circle(20_000);
    let layers = Layers { points: true, result: Some(&rec), ..Layers::default() };
    let svg = render(&points, &layers);
    assert!(svg.contains("points 20000 (too dense to draw)") && !svg.contains("h0"));
    // One chained polyline, closed: 20,000 short relative steps, a few bytes each.
    assert_eq!(svg.matches('M').count(), 1, "one path fills and outlines the loop");
    assert!(svg.len() < 400_000, "{} bytes", svg.len());
    let alone = render(&points, &Layers { points: true, ..Layers::default() });
    assert!(alone.contains("h0") && !alone.contains("too dense"));
    let (sparse, rec) = circle(50);
    let svg = render(&sparse, &Layers { result: Some(&rec), ..layers });
    assert!(svg.contains("points 50<") && svg.contains("h0"));
}

#[test]
fn stroke_widths_follow_the_spacing() {
    let width = |n| {
        let (points, rec) = circle(n);
        let svg = render(&points, &Layers { result: Some(&rec), ..Layers::default() });
        let line = svg.lines().find(|l| l.contains("stroke=\"#1a1a1a\"")).unwrap().to_string();
        let w = line.split("stroke-width=\"").nth(1).unwrap();
        w[..w.find('"').unwrap()].parse::<f64>().unwrap()
    };
    assert_eq!(width(20), 2.2);
    assert_eq!(width(2000), 0.8);
    assert!((0.8..2.2).contains(&width(200)));
}

#[test]
fn odd_input_gives_a_valid_picture() {
    let rec = Reconstruction {
        edges: vec![[0, 9], [1, 1], [0, 2]],
        loops: vec![vec![0, 1, 7]],
        ..Reconstruction::default()
    };
    let points = [[0.0, 0.0], [f64::NAN, 1.0], [1e300, -1e300]];
    let radii = [f64::INFINITY, -1.0, 2.0, 4.0];
    let layers = Layers {
        points: true,
        sig: Some(&radii),
        result: Some(&rec),
        gt: Some(&[[2, 0], [0, 2]]),
        ..Layers::default()
    };
    let title = RenderOptions { title: Some("<a & b>".into()), width_px: 0, legend: true };
    let svg = render_svg(&points, &layers, &title);
    check_well_formed(&svg);
    assert!(svg.contains(">&lt;a &amp; b&gt;</text>") && svg.contains("in both 1"), "{svg}");
    for points in
        [&[][..], &[[2.0, 2.0]], &[[0.0, 1.0], [0.0, 1.0]], &[[0.0, 0.0], [5.0, 0.0], [9.0, 0.0]]]
    {
        check_well_formed(&render(
            points,
            &Layers { points: true, dt: Some(&[[0, 1]]), ..Layers::default() },
        ));
    }
    assert_eq!(render_svg(&points, &layers, &title), svg, "deterministic");
}
