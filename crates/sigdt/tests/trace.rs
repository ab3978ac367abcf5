//! The step trace of inflating and sculpting: its replay ends at the result, inflating ends
//! with a manifold boundary, the steps match the statistics, and tracing changes nothing.
use sigdt::internals::{bc0, inflate, initial_graph, sculpt, Boundary};
use sigdt::samplers::{
    add_outliers, random_closed_curve, regular_polygon, spiral_band, uniform_noise, Blob,
    Modulation, Rng,
};
use sigdt::{reconstruct, reconstruct_traced, Method, Options, Phase, Point, Reconstruction};
use sigdt::{Edge, Stats, Trace, Triangulation};

fn circle(k: usize, centre: Point, r: f64) -> Vec<Point> {
    let polygon = sigdt::samplers::regular_polygon(k, r).points;
    polygon.into_iter().map(|[x, y]| [centre[0] + x, centre[1] + y]).collect()
}

/// Inputs with every kind of run: no work, inflating, pockets, sculpting, stuck sculpting.
fn inputs() -> Vec<(String, Vec<Point>)> {
    let mut inputs = vec![
        ("square".into(), vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
        ("figure 6".into(), vec![[0.0, 0.0], [-2.0, -0.5], [-1.5, 1.0], [2.0, -0.5], [1.5, 1.0]]),
        ("figure 7".into(), {
            let mut pts = circle(12, [0.0, 0.0], 1.0);
            pts.push([0.0, 0.0]);
            pts
        }),
        ("two loops".into(), {
            let mut pts = circle(10, [0.0, 0.0], 1.0);
            pts.extend(circle(8, [5.0, 1.0], 0.7));
            pts
        }),
        ("with duplicate".into(), vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]]),
        ("polygon".into(), regular_polygon(40, 1.0).points),
        ("spiral".into(), spiral_band(600).shuffled(3).points),
    ];
    for seed in 0..6 {
        let blob = random_closed_curve(seed, 150 + 50 * seed as usize);
        inputs.push((format!("blob {seed}"), blob.shuffled(seed).points.clone()));
        let noisy = uniform_noise(&blob.points, 0.004 + 0.003 * seed as f64, seed).unwrap();
        inputs.push((format!("noisy blob {seed}"), noisy));
        inputs.push((format!("outliers {seed}"), add_outliers(&blob.points, 0.1, seed).unwrap()));
        let mut rng = Rng::new(seed);
        let uneven = Blob::random(&mut rng, 6).sample(
            120,
            0.3,
            Modulation { amplitude: 0.6, frequency: 3, phase: 0.0 },
        );
        inputs.push((format!("modulated blob {seed}"), uneven.points));
        let cloud = (0..200).map(|_| [rng.uniform(), rng.uniform()]).collect();
        inputs.push((format!("random cloud {seed}"), cloud));
    }
    inputs
}

fn options() -> Vec<Options> {
    vec![
        sig_connect2d(),
        Options { method: Method::SigConnect2d, leaf_elimination: false, ..Options::default() },
        Options { method: Method::Connect2d, ..Options::default() },
    ]
}

fn traced(points: &[Point], options: &Options) -> (Reconstruction, Trace) {
    let (rec, trace) = reconstruct_traced(points, options).unwrap();
    assert_eq!(rec, reconstruct(points, options).unwrap(), "tracing changed the result");
    (rec, trace.expect("a proper triangulation has a trace"))
}

fn degrees(edges: &[Edge], n: usize) -> Vec<usize> {
    let mut degree = vec![0; n];
    for &[i, j] in edges {
        degree[i] += 1;
        degree[j] += 1;
    }
    degree
}

#[test]
fn replay_ends_at_the_result_and_inflating_ends_manifold() {
    for (name, points) in inputs() {
        for options in options() {
            let (rec, trace) = traced(&points, &options);
            let what = format!("{name}, {}", options.method);
            assert_eq!(trace.boundary_at(trace.steps.len()), rec.edges, "{what}");
            let inflated = trace.boundary_at(trace.inflated_at);
            assert!(
                degrees(&inflated, points.len()).iter().all(|&d| d == 0 || d == 2),
                "{what}: a vertex of the inflated boundary has degree other than 2"
            );
            let initial = trace.boundary_at(0);
            assert!(
                initial.iter().all(|e| trace.graph.binary_search(e).is_ok()),
                "{what}: the initial boundary is part of G"
            );
            assert!(trace.dangling.iter().all(|e| initial.binary_search(e).is_ok()), "{what}");
        }
    }
}

#[test]
fn replay_matches_the_live_boundary_at_the_start_after_inflating_and_at_the_end() {
    for (name, points) in inputs() {
        let dt = Triangulation::new(&points).unwrap();
        for (graph, _) in [initial_graph(&dt, true), initial_graph(&dt, false), bc0(&dt)] {
            let mut bd = Boundary::from_graph(&dt, &graph);
            let mut trace = bd.start_trace(&graph);
            assert_eq!(trace.boundary_at(0), bd.edges.edges(&dt), "{name}: start");
            let mut stats = Stats::default();
            inflate(&mut bd, &graph, &mut stats);
            trace.steps = bd.trace.clone().unwrap_or_default();
            assert_eq!(trace.boundary_at(trace.steps.len()), bd.edges.edges(&dt), "{name}");
            sculpt(&mut bd, &mut stats);
            trace.steps = bd.trace.take().unwrap_or_default();
            assert_eq!(trace.boundary_at(trace.steps.len()), bd.edges.edges(&dt), "{name}");
            assert_eq!(trace.inside_at(trace.steps.len()), bd.inside, "{name}");
        }
    }
}

#[test]
fn steps_match_the_statistics_and_change_a_label_each() {
    for (name, points) in inputs() {
        for options in options() {
            let (rec, trace) = traced(&points, &options);
            let what = format!("{name}, {}", options.method);
            let count = |phase| trace.steps.iter().filter(|s| s.phase == phase).count();
            let pocket_triangles = count(Phase::Pocket);
            assert_eq!(count(Phase::Inflate), rec.stats.inflated_triangles, "{what}");
            assert_eq!(count(Phase::Sculpt), rec.stats.sculpted_triangles, "{what}");
            assert_eq!(
                trace.steps.len(),
                rec.stats.inflated_triangles + pocket_triangles + rec.stats.sculpted_triangles,
                "{what}"
            );
            // Each pocket is a run of pocket steps right after the inflate step closing it.
            let runs = trace
                .steps
                .windows(2)
                .filter(|w| w[0].phase == Phase::Inflate && w[1].phase == Phase::Pocket)
                .count();
            assert_eq!(runs, rec.stats.pockets, "{what}");
            // Inflating only adds, sculpting only removes, and sculpting comes last.
            for (k, s) in trace.steps.iter().enumerate() {
                assert_eq!(s.inside, s.phase != Phase::Sculpt, "{what}: step {k}");
                assert_eq!(k >= trace.inflated_at, s.phase == Phase::Sculpt, "{what}: step {k}");
            }
            let mut inside = trace.initial_inside.clone();
            for (k, s) in trace.steps.iter().enumerate() {
                assert_ne!(inside[s.triangle], s.inside, "{what}: step {k} changes nothing");
                inside[s.triangle] = s.inside;
            }
            assert_eq!(inside, trace.inside_at(trace.steps.len()), "{what}");
        }
    }
}

#[test]
fn some_inputs_exercise_every_phase() {
    let mut seen = [false; 3];
    for (_, points) in inputs() {
        let (_, trace) = traced(&points, &sig_connect2d());
        for s in &trace.steps {
            seen[Phase::ALL.iter().position(|&p| p == s.phase).unwrap()] = true;
        }
    }
    assert_eq!(seen, [true; 3], "inflate, pocket, sculpt");
}

#[test]
fn graph_filters_and_degenerate_input_have_no_trace() {
    let points = circle(12, [0.0, 0.0], 1.0);
    for &method in Method::ALL {
        let options = Options { method, ..Options::default() };
        let (rec, trace) = reconstruct_traced(&points, &options).unwrap();
        assert_eq!(rec, reconstruct(&points, &options).unwrap());
        let inflates = matches!(method, Method::SigConnect2d | Method::Connect2d);
        assert_eq!(trace.is_some(), inflates, "{method}");
    }
    for points in [vec![], vec![[0.0, 0.0], [1.0, 1.0]], vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]] {
        let (rec, trace) = reconstruct_traced(&points, &sig_connect2d()).unwrap();
        assert_eq!(rec, reconstruct(&points, &sig_connect2d()).unwrap());
        assert!(trace.is_none());
    }
    assert!(reconstruct_traced(&[[f64::NAN, 0.0]], &sig_connect2d()).is_err());
}

#[test]
fn trace_fixed_part_describes_the_start() {
    let points = circle(12, [0.0, 0.0], 1.0);
    let (rec, trace) = traced(&points, &sig_connect2d());
    assert_eq!(trace.triangles.len(), 10, "a convex 12-gon has 10 triangles");
    assert!(trace.initial_inside.iter().all(|&i| i), "SIGDT is the 12-gon: all interior");
    assert!(rec.edges.iter().all(|e| trace.graph.binary_search(e).is_ok()), "G ⊇ the polygon");
    assert_eq!(trace.steps.len(), 0);
    assert_eq!(trace.boundary_at(0), rec.edges);
}

/// SIG-CONNECT2D, the method whose steps a trace records (the default, SIG-AUTO, has none).
fn sig_connect2d() -> Options {
    Options { method: Method::SigConnect2d, ..Options::default() }
}
