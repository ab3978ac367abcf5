//! Tests of `bezier` (a file of their own, to keep that one short).
use super::*;

fn parse(text: &str) -> Result<Vec<BezierPath>> {
    parse_svg_paths(text, "t.svg")
}

#[test]
fn reads_absolute_relative_and_elevated_segments() {
    let svg =
        "<svg>\n<!-- <path d=\"M 9 9 L 8 8\"/> -->\n<g transform='scale(2)'>\n<path id='a'\n  \
               style=\"fill:none\"\n  d='m 0,0 l 3,0 q 3,0 3,3 c 0,3 -6,3 -6,0 z'/></g>\n\
               <pathology d='M 1 1'/><path d=\"M 0 0 C 1 1 2 1 3 0\" /></svg>";
    let curves = parse(svg).unwrap();
    assert_eq!(curves.len(), 2);
    let (a, b) = (&curves[0], &curves[1]);
    assert!(a.closed && !b.closed);
    assert_eq!(a.segments.len(), 4);
    assert_eq!(a.segments[0], [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]);
    assert_eq!(a.segments[1], [[3.0, 0.0], [5.0, 0.0], [6.0, 1.0], [6.0, 3.0]]);
    assert_eq!(a.segments[3], line_cubic([0.0, 3.0], [0.0, 0.0]));
    assert_eq!(b.segments, vec![[[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]]]);
    assert_eq!(b.point(0.5), [1.5, 0.75]);
    assert_eq!(b.derivative(0.0), [3.0, 3.0]);
    assert_eq!(a.point(4.0), a.point(0.0));
}

#[test]
fn polylines_follow_the_chain_closed_or_open() {
    let curves = parse("<path d='M0 0 H 2 V 2 Z'/><path d='M 0 0 C 1 1 2 1 3 0'/>").unwrap();
    let closed = curves[0].polyline(4);
    assert_eq!(closed.points.len(), 12);
    assert_eq!(closed.edges.len(), 12);
    assert_eq!(closed.edges[..3], [[0, 1], [0, 11], [1, 2]]);
    assert_eq!(closed.points[4], [2.0, 0.0]);
    let open = curves[1].polyline(4);
    assert_eq!((open.points.len(), open.edges.len()), (5, 4));
    assert_eq!((open.points[0], open.points[4]), ([0.0, 0.0], [3.0, 0.0]));
    assert!(curves[1].polyline(0).points.is_empty());
    assert!(BezierPath::default().polyline(4).edges.is_empty());
}

#[test]
fn subpaths_are_separate_curves_and_closing_lines_are_added() {
    let curves = parse("<path d='M0 0 H 2 V 2 Z M 5 5 L 6 5 L 6 6 L 5 5 M 7 7 L 7 7'/>").unwrap();
    assert_eq!(curves.len(), 2);
    assert!(curves[0].closed && curves[1].closed);
    assert_eq!(curves[0].segments.len(), 3);
    assert_eq!(curves[0].segments[2], line_cubic([2.0, 2.0], [0.0, 0.0]));
    assert_eq!(curves[1].segments.len(), 3);
    assert!(parse("<svg><rect/></svg>").unwrap().is_empty());
}

#[test]
fn huge_arcs_and_paths_are_refused_before_they_are_expanded() {
    let refused = |d: &str| parse(&format!("<path d='{d}'/>")).unwrap_err().to_string();
    // Arcs as large as the drawing are read at a fixed size: a few cubics at any scale
    // (issue 30, G17: a circle of radius 1e18 took 20 s).
    for d in [
        "M 1e18 0 A 1e18 1e18 0 1 0 -1e18 0 A 1e18 1e18 0 1 0 1e18 0",
        "M 1e-300 0 A 1e-300 1e-300 0 1 0 -1e-300 0 A 1e-300 1e-300 0 1 0 1e-300 0",
    ] {
        let curves = parse(&format!("<path d='{d}'/>")).unwrap();
        assert!((1..=16).contains(&curves[0].segments.len()), "{d}: {curves:?}");
    }
    // A radius far smaller than the drawing, which the converter would draw as a line at
    // the fixed size and as a huge excursion at the file's (fuzz finds: a radius of 44
    // beside 4.4e33, or radii of 14 and 16 in a drawing 5e73 across).
    for d in [
        "M 2 1 A 44 4.4e33 14 1 0 0 80",
        "m 1 1 a 44 4.4e12 14 1 0 44 4.4e59",
        "M 50,5e73 A 14,16 0,1 0 50,10 Z",
        "M 51,555555555555555555555 A 9169610316303040510 14,16 1 0 50,10",
    ] {
        let err = refused(d);
        assert!(err.contains("too small against the size of the drawing"), "{d}: {err}");
    }
    // A thin ellipse across a long chord grows by the chord over its small radius, here
    // to 10²³ times the drawing (fuzz find: svgtypes made millions of cubics, handed out
    // quadratically).
    let err = refused("M 0 0 A 1e-20 1000 0 1 0 1000 0");
    assert!(err.contains("elliptical arc of radius 5.0e25"), "{err}");
    assert!(arc_radius([0.0, 0.0], [2.0, 0.0], 1.0, 1.0, 0.0) == 1.0);
    assert!(arc_radius([0.0, 0.0], [4.0, 0.0], 1.0, 1.0, 90.0) == 2.0);
    assert!(arc_radius([0.0, 0.0], [4.0, 0.0], 0.0, 1.0, 0.0) == 0.0);
    // Ordinary arcs are read as cubics.
    let arc = parse("<path d='M 0 0 A 1 1 0 0 1 2 0'/>").unwrap();
    assert!((1..=8).contains(&arc[0].segments.len()));
    let long: String = (0..=MAX_SEGMENTS).map(|k| format!(" L {k} {}", k % 2)).collect();
    let err = refused(&format!("M 0 5{long}"));
    assert!(err.contains("more than 4096 cubic segments"), "{err}");
}

#[test]
fn a_close_that_misses_the_start_by_rounding_snaps_onto_it() {
    // A closed arc whose last point lands 1e-14 from the start, as decimal text of a
    // circle does: no 1e-14 closing line (its noisy corners made eps-sampling stall).
    let near =
        parse("<path d='M 100 0 C 100 50 50 100 0 100 C -100 100 -100 -1e-14 100 -1e-14 Z'/>");
    let near = near.unwrap();
    assert_eq!(near[0].segments.len(), 2);
    assert!(near[0].closed && near[0].segments[1][3] == [100.0, 0.0]);
    // A real gap, however small against the drawing's size, still gets its line.
    let gap = parse("<path d='M 100 0 C 100 50 50 100 0 100 L 100 -1e-6 Z'/>").unwrap();
    assert_eq!(gap[0].segments.len(), 3);
}

#[test]
fn errors_name_file_and_line() {
    let message = |text: &str| parse(text).unwrap_err().to_string();
    assert_eq!(
        message("<svg>\n\n<path d='M 0 0 L 1 x'/>"),
        "t.svg:3: bad path data: ".to_string() + &bad("M 0 0 L 1 x")
    );
    assert!(message("<svg>\n<path d='M 0 0").starts_with("t.svg:2: unterminated value"));
    assert!(message("<path d=M/>").starts_with("t.svg:1: attribute 'd' of <path> has no quoted"));
    assert!(message("\n<path d='M 0 0'").starts_with("t.svg:2: unterminated <path> tag"));
    assert!(message("<!-- <path").starts_with("t.svg:1: unterminated comment"));
    let m = message("<path d='M 1e308 0 l 1e308 0'/>");
    assert!(m.contains("non-finite"), "{m}");
    let missing = read_svg_paths(Path::new("/nonexistent/x.svg")).unwrap_err();
    assert!(missing.to_string().starts_with("/nonexistent/x.svg: "));
}

fn bad(d: &str) -> String {
    SimplifyingPathParser::from(d).find_map(|s| s.err()).unwrap().to_string()
}

#[test]
fn reads_the_bundled_drawings() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/svg");
    let simple = read_svg_paths(&dir.join("simple.svg")).unwrap();
    assert_eq!(simple.len(), 1);
    assert!(simple[0].closed && simple[0].segments.len() == 5);
    let corner = read_svg_paths(&dir.join("corner.svg")).unwrap();
    assert_eq!(corner.len(), 2);
    assert!(corner[0].closed && !corner[1].closed);
}
