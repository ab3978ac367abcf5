//! Each step of SIG-CONNECT2D on small hand-made configurations, with exact expectations,
//! including the paper's Figure 6 (inflating a pinched vertex) and Figure 7 (sculpting an
//! isolated interior vertex).
use sigdt::internals::check_reconstruction;
use sigdt::internals::{inflate, sculpt, Boundary, EdgeMask, VertexClass};
use sigdt::Triangulation;
use sigdt::{reconstruct, Method, Options, Point, Stats, Status};

/// The edge mask of the given input-index pairs (each must be a Delaunay edge).
fn mask(dt: &Triangulation, pairs: &[[usize; 2]]) -> EdgeMask {
    let mut g = EdgeMask::new(dt);
    for &[i, j] in pairs {
        let h = dt
            .edge_halfedges()
            .find(|&h| {
                let (a, b) = (dt.input_index(dt.origin(h)), dt.input_index(dt.dest(h)));
                (a, b) == (i, j) || (a, b) == (j, i)
            })
            .unwrap_or_else(|| panic!("[{i}, {j}] is not a Delaunay edge"));
        g.set(dt, h, true);
    }
    g
}

fn class_of(bd: &Boundary<'_>, dt: &Triangulation, input: usize) -> VertexClass {
    let v = (0..dt.num_vertices() as u32).find(|&v| dt.input_index(v) == input).unwrap();
    bd.class[v as usize]
}

fn circle(k: usize, centre: Point, r: f64) -> Vec<Point> {
    let polygon = sigdt::samplers::regular_polygon(k, r).points;
    polygon.into_iter().map(|[x, y]| [centre[0] + x, centre[1] + y]).collect()
}

fn run(points: &[Point]) -> sigdt::Reconstruction {
    // The paper's figures are of SIG-CONNECT2D.
    let rec = reconstruct(points, &Options { method: Method::SigConnect2d, ..Options::default() })
        .unwrap();
    check_reconstruction(points, &rec).unwrap();
    rec
}

#[test]
fn square_boundary_drops_the_diagonal() {
    let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let dt = Triangulation::new(&pts).unwrap();
    let diagonal = dt.edges().into_iter().find(|e| *e == [0, 2] || *e == [1, 3]).unwrap();
    let g = mask(&dt, &[[0, 1], [1, 2], [2, 3], [0, 3], diagonal]);
    let bd = Boundary::from_graph(&dt, &g);
    assert!(bd.inside.iter().all(|&i| i), "both triangles are bounded faces of G");
    assert_eq!(bd.edges.edges(&dt), vec![[0, 1], [0, 3], [1, 2], [2, 3]]);
    assert_eq!((bd.non_manifold, bd.interior), (0, 0));
    let rec = run(&pts);
    assert_eq!(rec.edges, vec![[0, 1], [0, 3], [1, 2], [2, 3]]);
    assert_eq!(rec.loops, vec![vec![0, 1, 2, 3]], "counter-clockwise from the smallest index");
    assert_eq!(rec.status, Status::Polygon);
}

#[test]
fn regular_polygon_needs_no_inflating_or_sculpting() {
    let pts = circle(12, [3.0, -1.0], 2.0);
    let rec = run(&pts);
    let cycle: Vec<[usize; 2]> = {
        let mut c: Vec<_> = (0..12).map(|i| [i.min((i + 1) % 12), i.max((i + 1) % 12)]).collect();
        c.sort();
        c
    };
    assert_eq!(rec.edges, cycle);
    assert_eq!((rec.stats.inflated_triangles, rec.stats.sculpted_triangles), (0, 0));
}

#[test]
fn dangling_path_is_non_manifold_and_inflates_to_the_polygon() {
    // A path (a tree) has exterior on both sides of every edge: all its vertices are
    // non-manifold, and inflating grows triangles until the boundary is a polygon.
    let pts = circle(9, [0.0, 0.0], 1.0);
    let dt = Triangulation::new(&pts).unwrap();
    let path: Vec<[usize; 2]> = (0..8).map(|i| [i, i + 1]).collect();
    let g = mask(&dt, &path);
    let mut bd = Boundary::from_graph(&dt, &g);
    assert!(bd.inside.iter().all(|&i| !i));
    assert_eq!(bd.non_manifold, 9);
    let mut stats = Stats::default();
    inflate(&mut bd, &g, &mut stats);
    assert_eq!(bd.non_manifold, 0);
    // The whole convex 9-gon fills, partly by triangles taken and partly as enclosed pockets.
    assert!(bd.inside.iter().all(|&i| i), "{stats:?}");
    assert!(stats.inflated_triangles >= 1 && stats.inflated_triangles < dt.num_triangles());
    assert!(stats.pockets >= 1, "{stats:?}");
    assert_eq!(
        bd.edges.edges(&dt),
        dt.to_input_edges(
            dt.hull().windows(2).map(|w| [w[0], w[1]]).chain([[dt.hull()[8], dt.hull()[0]]])
        )
    );
}

/// Figure 6: a boundary pinched at `p` is inflated with the exterior triangle at `p` that
/// least increases the boundary length.
#[test]
fn figure_6_inflating_resolves_a_pinched_vertex() {
    // p = 0 with two triangles of G, left (0, 1, 2) and right (0, 3, 4). The upper wedge
    // (0, 2, 4) costs 3 − 2·√3.25 ≈ −0.61, the lower (0, 1, 3) costs 4 − 2·√4.25 ≈ −0.12.
    let pts = [[0.0, 0.0], [-2.0, -0.5], [-1.5, 1.0], [2.0, -0.5], [1.5, 1.0]];
    let dt = Triangulation::new(&pts).unwrap();
    let g = mask(&dt, &[[0, 1], [1, 2], [0, 2], [0, 3], [3, 4], [0, 4]]);
    let mut bd = Boundary::from_graph(&dt, &g);
    assert_eq!(class_of(&bd, &dt, 0), VertexClass::NonManifold, "pinched: four transitions");
    assert_eq!(bd.non_manifold, 1);
    let mut stats = Stats::default();
    inflate(&mut bd, &g, &mut stats);
    assert_eq!(stats.inflated_triangles, 1);
    assert_eq!(class_of(&bd, &dt, 0), VertexClass::Manifold);
    assert_eq!(bd.edges.edges(&dt), vec![[0, 1], [0, 3], [1, 2], [2, 4], [3, 4]]);
}

/// Figure 7: the isolated centre of a regular polygon is exposed by XOR-ing the cheapest
/// interior triangle at it with the boundary.
#[test]
fn figure_7_sculpting_exposes_the_centre() {
    let mut pts = circle(12, [0.0, 0.0], 1.0);
    pts.push([0.0, 0.0]);
    let dt = Triangulation::new(&pts).unwrap();
    // SIGDT here is the fan: 12 sides and 12 spokes (see proximity::sigdt tests).
    let g = sigdt::internals::sigdt_mask(&dt);
    let mut bd = Boundary::from_graph(&dt, &g);
    assert_eq!(class_of(&bd, &dt, 12), VertexClass::Interior);
    let mut stats = Stats::default();
    inflate(&mut bd, &g, &mut stats);
    assert_eq!(stats.inflated_triangles, 0);
    sculpt(&mut bd, &mut stats);
    assert_eq!((stats.interior_before_sculpting, stats.sculpted_triangles), (1, 1));
    assert_eq!(bd.interior, 0);
    let edges = bd.edges.edges(&dt);
    assert_eq!(edges.len(), 13);
    let spokes: Vec<usize> = edges.iter().filter(|e| e[1] == 12).map(|e| e[0]).collect();
    assert_eq!(spokes.len(), 2);
    assert!(spokes[1] - spokes[0] == 1 || spokes == [0, 11], "spokes to the ends of one side");
    let rec = run(&pts);
    assert_eq!(rec.status, Status::Polygon);
    assert_eq!(rec.edges, edges);
}

#[test]
fn two_separate_loops_stay_separate() {
    let mut pts = circle(10, [0.0, 0.0], 1.0);
    pts.extend(circle(8, [5.0, 1.0], 0.7));
    let rec = run(&pts);
    assert_eq!(rec.status, Status::Polygons);
    assert_eq!(rec.loops.len(), 2);
    assert_eq!(rec.loops[0], (0..10).collect::<Vec<_>>());
    assert_eq!(rec.loops[1], (10..18).collect::<Vec<_>>());
}

// Degenerate input (empty, duplicates, collinear, ...) for every method: tests/degenerate.rs.
