//! Every method gives the same result, bit for bit, whatever order the triangulation's
//! triangles are stored in and whichever corner each starts at
//! (`Triangulation::with_triangles_shuffled`). The canonical triangulation fixes the
//! triangles; this fixes that nothing after it depends on where they lie in the arrays, so
//! that another construction (in parallel: issue 48) needs no pass that lays them out the
//! way one insertion sequence does. Ties are where a stage could lean on the layout, so the
//! inputs are full of them: a grid, cocircular points, duplicates, noise and outliers.
use sigdt::samplers::{random_closed_curve, spiral_band, Rng};
use sigdt::{reconstruct_on, Method, Options, Point, Triangulation};

/// Curves (clean, noisy, with outliers), a band, and inputs full of exact ties.
fn inputs() -> Vec<(String, Vec<Point>)> {
    // Smaller in debug builds, to keep `cargo test` quick.
    let scale = |release: usize, debug: usize| if cfg!(debug_assertions) { debug } else { release };
    let mut sets = Vec::new();
    for seed in 0..2 {
        let n = scale(2000, 300);
        sets.push((format!("curve {seed}"), random_closed_curve(seed, n).shuffled(seed).points));
        let mut rng = Rng::new(seed + 10);
        let mut noisy = random_closed_curve(seed + 3, n).points;
        let spacing = 6.0 / n as f64;
        for p in &mut noisy {
            p[0] += 0.3 * spacing * (rng.uniform() - 0.5);
            p[1] += 0.3 * spacing * (rng.uniform() - 0.5);
        }
        let outliers = (0..n / 50).map(|_| [4.0 * rng.uniform() - 2.0, 4.0 * rng.uniform() - 2.0]);
        noisy.extend(outliers.collect::<Vec<_>>());
        rng.shuffle(&mut noisy);
        sets.push((format!("noisy curve with outliers {seed}"), noisy));
    }
    sets.push(("spiral band".into(), spiral_band(scale(2000, 300)).shuffled(9).points));
    let k = scale(30, 12);
    let mut grid: Vec<Point> = (0..k * k).map(|i| [(i % k) as f64, (i / k) as f64]).collect();
    Rng::new(1).shuffle(&mut grid);
    sets.push(("grid".into(), grid));
    let mut scatter: Vec<Point> = {
        let mut rng = Rng::new(4);
        (0..scale(1500, 300)).map(|_| [rng.uniform(), rng.uniform()]).collect()
    };
    scatter.extend_from_within(..10);
    sets.push(("scatter with duplicates".into(), scatter));
    let cocircular: Vec<Point> = [[16.0, 63.0], [33.0, 56.0], [39.0, 52.0], [25.0, 60.0]]
        .iter()
        .flat_map(|&[x, y]| {
            [[x, y], [y, x], [-x, y], [-y, x], [x, -y], [y, -x], [-x, -y], [-y, -x]]
        })
        .chain([[65.0, 0.0], [0.0, 65.0], [-65.0, 0.0], [0.0, -65.0]])
        .collect();
    sets.push(("cocircular".into(), cocircular));
    sets
}

#[test]
fn results_do_not_depend_on_where_the_triangles_are_stored() {
    let mut differ = Vec::new();
    for (name, points) in inputs() {
        let dt = Triangulation::new(&points).unwrap();
        let layouts: Vec<Triangulation> =
            (1..=2).map(|seed| dt.with_triangles_shuffled(seed)).collect();
        for &method in Method::ALL {
            let options = Options { method, ..Options::default() };
            let first = format!("{:?}", reconstruct_on(&dt, &options));
            for (k, other) in layouts.iter().enumerate() {
                if format!("{:?}", reconstruct_on(other, &options)) != first {
                    differ.push(format!("{name}, {method}, layout {}", k + 1));
                }
            }
        }
    }
    assert!(differ.is_empty(), "the result depends on the layout: {differ:#?}");
}

#[test]
fn a_shuffled_layout_is_the_same_triangulation() {
    for (name, points) in inputs() {
        let dt = Triangulation::new(&points).unwrap();
        let other = dt.with_triangles_shuffled(7);
        sigdt::internals::check_delaunay(&other).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(dt.edges(), other.edges(), "{name}");
        assert_eq!(dt.hull(), other.hull(), "{name}");
    }
}
