//! Can a cheap statistic tell points that fill an area from samples of curves? The question
//! behind issue 47's S2 (SIG-AUTO's rounds on scatters): a test that refused such input
//! before the rounds would bound their cost. `cargo run --release -p sigdt-lab --example
//! scatter_statistics -- data ../shared/data DIR...` prints one line per `.xy` file:
//!
//! `n round2 round3 leaves_largest largest_size path`
//!
//! - `round2`, `round3`: the share of points off the hull whose Voronoi cell is round: every
//!   Delaunay triangle at the point has a circumradius below 2 (3) times the point's
//!   nearest-neighbour distance. On an ε-sample of a smooth curve the cell reaches at least
//!   the local feature size along the normal on both sides (the empty medial balls touching
//!   the sample: Amenta, Bern and Eppstein, *The crust and the β-skeleton*, 1998), so the
//!   share is low for dense samples; a scatter's cells are round.
//! - `leaves_largest`: the share of leaves in the minimum spanning tree of SIGDT2 ([MOW22]'s
//!   SIGDT with leaf elimination) on its largest component, of `largest_size` points: a sampled
//!   curve's tree is a path with few spurs, a scatter's tree branches everywhere.
//!
//! The measurements (`docs/reliability.md`, S2): both statistics put digitised coastline
//! vertices among the scatters, so neither can decide.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use sigdt::internals::{distance, initial_graph, minimum_spanning_forest, UnionFind};
use sigdt::{Point, Triangulation};
use std::path::{Path, PathBuf};

fn main() {
    let mut folders: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    while let Some(path) = folders.pop() {
        if path.is_dir() {
            let entries = std::fs::read_dir(&path).into_iter().flatten().flatten();
            folders.extend(entries.map(|e| e.path()));
        } else if path.extension().is_some_and(|e| e == "xy") {
            print_statistics(&path);
        }
    }
}

fn print_statistics(path: &Path) {
    let Ok(points) = sigdt_io::read_points_file(path, None, None, 10_000_000) else { return };
    let Ok(dt) = Triangulation::new(&points) else { return };
    if dt.num_triangles() == 0 {
        return;
    }
    let [round2, round3] = round_cell_shares(&dt);
    let (leaves, size) = largest_tree_leaves(&dt);
    println!("{} {round2:.3} {round3:.3} {leaves:.3} {size} {}", dt.num_vertices(), path.display());
}

/// The shares of inner vertices whose triangles' circumradii all stay below 2 and 3 times
/// the vertex's nearest-neighbour distance.
fn round_cell_shares(dt: &Triangulation) -> [f64; 2] {
    let corner = |t: u32, k: u32| dt.point(dt.origin(3 * t + k));
    let circumradius = |t: u32| circumradius(corner(t, 0), corner(t, 1), corner(t, 2));
    let (mut inner, mut round) = (0usize, [0usize; 2]);
    for v in (0..dt.num_vertices() as u32).filter(|&v| !dt.is_hull_vertex(v)) {
        inner += 1;
        let nearest = dt.outgoing(v).map(|h| dt.length(h)).fold(f64::INFINITY, f64::min);
        let farthest = dt.outgoing(v).map(|h| circumradius(h / 3)).fold(0.0, f64::max);
        for (count, ratio) in round.iter_mut().zip([2.0, 3.0]) {
            *count += usize::from(farthest < ratio * nearest);
        }
    }
    round.map(|r| r as f64 / inner.max(1) as f64)
}

fn circumradius(a: Point, b: Point, c: Point) -> f64 {
    let twice_area = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs();
    distance(a, b) * distance(b, c) * distance(c, a) / (2.0 * twice_area)
}

/// The share of leaves in the largest tree of SIGDT2's minimum spanning forest, and that
/// tree's size.
fn largest_tree_leaves(dt: &Triangulation) -> (f64, usize) {
    let (graph, _) = initial_graph(dt, true);
    let tree = minimum_spanning_forest(dt, |h| graph.contains(h));
    let n = dt.num_vertices();
    let degree = tree.degrees(dt);
    let mut sets = UnionFind::new(n);
    for h in dt.edge_halfedges().filter(|&h| tree.contains(h)) {
        sets.union(dt.origin(h), dt.dest(h));
    }
    let (mut size, mut leaves) = (vec![0usize; n], vec![0usize; n]);
    for v in 0..n as u32 {
        let root = sets.find(v) as usize;
        size[root] += 1;
        leaves[root] += usize::from(degree[v as usize] == 1);
    }
    let largest = (0..n).max_by_key(|&r| (size[r], std::cmp::Reverse(r))).unwrap_or(0);
    (leaves[largest] as f64 / size[largest].max(1) as f64, size[largest])
}
