//! Determinism: the same input gives the same result, bit for bit, on every run and
//! whichever thread computes it. Inputs include exact ties (a grid, exactly cocircular
//! points, duplicates), where the answer depends only on tie-breaking by index.
use sigdt::samplers::{random_closed_curve, spiral_band, Rng};
use sigdt::{
    reconstruct, reconstruct_on, reconstruct_owned, Method, Options, Point, Reconstruction,
    Triangulation,
};

/// Smaller inputs in debug builds, to keep `cargo test` quick.
fn scale(release: usize, debug: usize) -> usize {
    if cfg!(debug_assertions) {
        debug
    } else {
        release
    }
}

/// The inputs: smooth curves, a band, and inputs full of exact ties.
fn inputs() -> Vec<(String, Vec<Point>)> {
    let mut sets = Vec::new();
    for seed in 0..3 {
        sets.push((
            format!("curve {seed}"),
            random_closed_curve(seed, scale(3000, 400)).shuffled(seed).points,
        ));
    }
    sets.push(("spiral band".into(), spiral_band(scale(3000, 400)).shuffled(9).points));
    let k = scale(40, 12);
    let mut grid: Vec<Point> = (0..k * k).map(|i| [(i % k) as f64, (i / k) as f64]).collect();
    Rng::new(1).shuffle(&mut grid);
    sets.push(("grid".into(), grid));
    // Exactly cocircular: the 8 symmetric copies of the integer points on x² + y² = 65².
    let mut cocircular: Vec<Point> = [[16.0, 63.0], [33.0, 56.0], [39.0, 52.0], [25.0, 60.0]]
        .iter()
        .flat_map(|&[x, y]| {
            [[x, y], [y, x], [-x, y], [-y, x], [x, -y], [y, -x], [-x, -y], [-y, -x]]
        })
        .chain([[65.0, 0.0], [0.0, 65.0], [-65.0, 0.0], [0.0, -65.0]])
        .collect();
    Rng::new(2).shuffle(&mut cocircular);
    sets.push(("cocircular".into(), cocircular));
    let mut duplicated = random_closed_curve(5, scale(1000, 200)).points;
    duplicated.extend_from_within(..duplicated.len() / 2);
    Rng::new(3).shuffle(&mut duplicated);
    sets.push(("duplicates".into(), duplicated));
    sets
}

/// Every (input, method) pair.
fn jobs() -> Vec<(String, Vec<Point>, Method)> {
    inputs()
        .into_iter()
        .flat_map(|(name, points)| {
            Method::ALL.iter().map(move |&m| (name.clone(), points.clone(), m))
        })
        .collect()
}

/// The full result as bytes: every field, including the statistics.
fn bytes(points: &[Point], method: Method) -> Vec<u8> {
    let rec: Reconstruction = reconstruct(points, &Options { method, ..Options::default() })
        .unwrap_or_else(|e| panic!("{method}: {e}"));
    format!("{rec:?}").into_bytes()
}

#[test]
fn repeated_runs_are_byte_identical() {
    for (name, points, method) in jobs() {
        let first = bytes(&points, method);
        for _ in 0..2 {
            assert!(bytes(&points, method) == first, "{name}, {method}: a rerun differs");
        }
    }
}

#[test]
fn owned_points_and_a_shared_triangulation_give_the_same_result() {
    // `reconstruct` frees its triangulation before building SIG-CONNECT2D's result,
    // `reconstruct_owned` frees the points too, `reconstruct_on` does neither.
    for (name, points, method) in jobs() {
        for leaf_elimination in [true, false] {
            let options = Options { method, leaf_elimination, ..Options::default() };
            let borrowed = format!("{:?}", reconstruct(&points, &options).unwrap());
            let owned = format!("{:?}", reconstruct_owned(points.clone(), &options).unwrap());
            let dt = Triangulation::new(&points).unwrap();
            let shared = format!("{:?}", reconstruct_on(&dt, &options));
            assert!(owned == borrowed, "{name}, {method}: reconstruct_owned differs");
            assert!(shared == borrowed, "{name}, {method}: reconstruct_on differs");
        }
    }
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let jobs = jobs();
    let one: Vec<Vec<u8>> = jobs.iter().map(|(_, p, m)| bytes(p, *m)).collect();
    let threads = 4;
    let mut four: Vec<Vec<u8>> = vec![Vec::new(); jobs.len()];
    std::thread::scope(|s| {
        // Thread t takes jobs t, t + 4, ...: neighbouring jobs run concurrently.
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let jobs = &jobs;
                s.spawn(move || {
                    (t..jobs.len())
                        .step_by(threads)
                        .map(|k| (k, bytes(&jobs[k].1, jobs[k].2)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        for h in handles {
            for (k, b) in h.join().expect("a worker panicked") {
                four[k] = b;
            }
        }
    });
    for (k, (name, _, method)) in jobs.iter().enumerate() {
        assert!(one[k] == four[k], "{name}, {method}: 1 and 4 threads differ");
    }
}

#[test]
fn one_large_set_is_the_same_on_every_pool_size() {
    // Above the size where the kernel's loops go parallel (2^14), on rayon pools of 1, 2
    // and (release) 3 threads: the same result, every method, bit for bit.
    // Debug builds (`make test`) take the curve only: the spiral doubles the test's minute.
    let n = scale(60_000, 20_000);
    let mut sets = vec![random_closed_curve(5, n).shuffled(1).points];
    if !cfg!(debug_assertions) {
        sets.push(spiral_band(n).shuffled(2).points);
    }
    for points in &sets {
        for &method in Method::ALL {
            let on = |threads: usize| {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
                pool.install(|| bytes(points, method))
            };
            let one = on(1);
            // Debug builds compare with two threads only (a third pool adds a third of the
            // test's half minute); release builds with two and three.
            for &threads in if cfg!(debug_assertions) { &[2][..] } else { &[2, 3][..] } {
                assert!(on(threads) == one, "{method}: 1 and {threads} threads differ");
            }
        }
    }
}

#[test]
fn proximity_graphs_are_the_same_on_every_pool_size() {
    // Above the size where the per-point loops go parallel (2^14): the kNN graph and the
    // SIG (k-d tree queries), the EMST (a parallel sort) on pools of 1 and 2 threads.
    use sigdt::{proximity_graph, GraphKind};
    let points = random_closed_curve(3, 20_000).shuffled(4).points;
    let mut grid: Vec<Point> = (0..20_164).map(|i| [(i % 142) as f64, (i / 142) as f64]).collect();
    Rng::new(5).shuffle(&mut grid);
    for points in [&points, &grid] {
        for kind in [GraphKind::Knn { k: 4 }, GraphKind::Sig, GraphKind::Emst] {
            let on = |threads: usize| {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
                pool.install(|| proximity_graph(points, kind).unwrap())
            };
            assert_eq!(on(1), on(2), "{kind:?}: 1 and 2 threads differ");
        }
    }
}
