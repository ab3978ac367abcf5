//! CRAWL: grow curves from nearest-neighbour seeds, one Delaunay neighbour at a time.
//!
//! [PM16] A. D. Parakkat, R. Muthuganapathy, *Crawl through Neighbors: A Simple Curve
//! Reconstruction Algorithm*, Computer Graphics Forum (SGP 2016). The paper text was not
//! at hand; the rules below are those of the authors' reference implementation
//! (`github.com/amaldevp/Crawl_through_Neighbors`, `Crawl.cpp` / `CrawlEdited.cpp`, CGAL 4.6),
//! read and restated in our own words.
//!
//! # Steps
//! 1. *Seeds*: the Delaunay edges `ab` where `b` is the nearest Delaunay neighbour of `a`, or
//!    `a` that of `b`, ordered by length (shortest first).
//! 2. *Start a component*: take the next seed whose two endpoints are both unvisited; if there
//!    is none, stop. Output it, mark both endpoints visited; they are the two *extremities*
//!    `e₁, e₂` of the current path, and the component's step counter is 0.
//! 3. *Close*: if the step counter exceeds 3 and `e₂` is the *second*-nearest Delaunay
//!    neighbour of `e₁` (or `e₁` that of `e₂`), output `e₁e₂` and go back to 2.
//! 4. *Crawl*: let `uᵢ` be the nearest *unvisited* Delaunay neighbour of `eᵢ`. Extend the
//!    path at `e₁` if `|e₁u₁| < |e₂u₂|` (or `u₂` does not exist), else at `e₂`: output `eᵢuᵢ`,
//!    mark `uᵢ` visited, make it the new `eᵢ` and count one step. If neither extremity has an
//!    unvisited neighbour the component ends (an open curve): go back to 2. Else repeat 3.
//!
//! Points that never become an endpoint of a seed with both ends unvisited, nor a crawl target,
//! stay isolated. The result is a set of paths and cycles (every vertex has degree ≤ 2).
//!
//! # Guarantee
//! None is proven. The crawl always jumps to the nearest unvisited neighbour, however far, so
//! an open curve's end is joined to another curve; cycles with fewer than 6 points cannot be
//! closed (the step counter). [MOW22] Table 2: 75.3 % manifold, 10.6 % sharp, 21.7 % open,
//! 40.7 % multiple.
//!
//! # Complexity
//! O(n log n) time and O(n) memory in the worst case, whatever the input; O(n) after the
//! sorts. Each vertex's Delaunay neighbours are sorted once, nearest first (O(d log d) at a
//! vertex of degree `d`, O(n log n) in all; the seeds' sort is O(n log n) too). Then every
//! step is O(1) amortised: an extremity's nearest and second-nearest neighbours are the first
//! two of its list, and its nearest *unvisited* one is found by a cursor that only moves
//! forward, since a visited point stays visited. So the crawl passes each list entry at most
//! once (fewer than `6n` in all) and reads at most four more per step: under `10n` reads,
//! which the tests count.
//!
//! Scanning both extremities' neighbours at every step instead, as the reference code does,
//! is O(n · d): on a densely sampled spiral of few turns the point at its centre has
//! thousands of neighbours and stays an extremity for most of the crawl (10⁵ points, 3
//! turns: 7 s instead of 0.12 s, Delaunay included; the edges are the same).
//!
//! # Departures from the reference code
//! - Lengths are compared as `f64` squared distances instead of `f32` lengths, and
//!   every "nearest" breaks ties by the neighbour's input index (the reference takes the first
//!   in CGAL's circulation order); equal seeds are ordered by their sorted input indices.
//! - The reference's `9999` "no candidate" sentinel (which fails for coordinates above about
//!   10⁴) is replaced by an explicit "none".
//! - CGAL's infinite vertex, whose coordinates are unspecified, appears among the neighbours of
//!   hull points in the reference; here only real points are neighbours.
//!
//! [PM16]: https://github.com/amaldevp/Crawl_through_Neighbors
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::Triangulation;
use crate::geometry::squared_distance;

/// The CRAWL edges of `dt` as vertex pairs (see the module docs). `dt` must be
/// [`Shape::Proper`](crate::delaunay::Shape::Proper); otherwise there are no triangles and
/// the result is empty.
pub fn crawl(dt: &Triangulation) -> Vec<[u32; 2]> {
    crawl_counted(dt).0
}

/// [`crawl`], also returning how many neighbour-list entries the crawl read (steps 2–4,
/// after sorting): the work bound of the module docs, for the tests.
fn crawl_counted(dt: &Triangulation) -> (Vec<[u32; 2]>, usize) {
    let n = dt.num_vertices();
    if dt.num_triangles() == 0 {
        return (Vec::new(), 0);
    }
    let mut nb = Neighbours::new(dt);
    // Step 1: the seeds, shortest first.
    let mut seeds: Vec<(f64, [usize; 2], [u32; 2])> = dt
        .edge_halfedges()
        .map(|h| (dt.origin(h), dt.dest(h)))
        .filter(|&(a, b)| nb.nearest(a) == Some(b) || nb.nearest(b) == Some(a))
        .map(|(a, b)| {
            let (i, j) = (dt.input_index(a), dt.input_index(b));
            let pair = if i < j { [a, b] } else { [b, a] };
            (squared_distance(dt.point(a), dt.point(b)), [i.min(j), i.max(j)], pair)
        })
        .collect();
    seeds.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
    nb.reads = 0;

    let dist = |v: u32, w: u32| squared_distance(dt.point(v), dt.point(w));
    let mut visited = vec![false; n];
    let mut edges = Vec::with_capacity(n);
    // Step 2: one component per seed with both endpoints unvisited.
    for &(_, _, [a, b]) in &seeds {
        if visited[a as usize] || visited[b as usize] {
            continue;
        }
        edges.push([a, b]);
        visited[a as usize] = true;
        visited[b as usize] = true;
        let (mut e1, mut e2, mut steps) = (a, b, 0usize);
        loop {
            // Step 3: close when the other extremity is an extremity's second-nearest neighbour.
            if steps > 3 && (nb.second_nearest(e1) == Some(e2) || nb.second_nearest(e2) == Some(e1))
            {
                edges.push([e1, e2]);
                break;
            }
            // Step 4: crawl from the extremity with the shorter step; ties go to `e₂`.
            let u1 = nb.nearest_unvisited(e1, &visited).map(|w| (dist(e1, w), w));
            let u2 = nb.nearest_unvisited(e2, &visited).map(|w| (dist(e2, w), w));
            let (end, u) = match (u1, u2) {
                (Some((d1, w1)), Some((d2, _))) if d1 < d2 => (&mut e1, w1),
                (_, Some((_, w2))) => (&mut e2, w2),
                (Some((_, w1)), None) => (&mut e1, w1),
                (None, None) => break,
            };
            edges.push([*end, u]);
            visited[u as usize] = true;
            *end = u;
            steps += 1;
        }
    }
    (edges, nb.reads)
}

/// Every vertex's Delaunay neighbours, nearest first (squared distance, then input index), in
/// one flat array: those of `v` are `list[start[v]..start[v + 1]]`.
struct Neighbours {
    start: Vec<usize>,
    list: Vec<u32>,
    /// Per vertex, the first entry of its list that may be unvisited.
    cursor: Vec<usize>,
    /// Entries read by the crawl (the tests' work count).
    reads: usize,
}

impl Neighbours {
    fn new(dt: &Triangulation) -> Self {
        let n = dt.num_vertices();
        let mut start = vec![0usize; n + 1];
        for h in dt.edge_halfedges() {
            start[dt.origin(h) as usize + 1] += 1;
            start[dt.dest(h) as usize + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut cursor = start[..n].to_vec();
        let mut list = vec![0u32; start[n]];
        for h in dt.edge_halfedges() {
            let (a, b) = (dt.origin(h), dt.dest(h));
            for (v, w) in [(a, b), (b, a)] {
                list[cursor[v as usize]] = w;
                cursor[v as usize] += 1;
            }
        }
        for v in 0..n {
            let p = dt.point(v as u32);
            list[start[v]..start[v + 1]].sort_unstable_by(|&b, &c| {
                let (db, dc) = (squared_distance(p, dt.point(b)), squared_distance(p, dt.point(c)));
                db.total_cmp(&dc).then(dt.input_index(b).cmp(&dt.input_index(c)))
            });
        }
        cursor.copy_from_slice(&start[..n]);
        Neighbours { start, list, cursor, reads: 0 }
    }

    /// The `k`-th nearest Delaunay neighbour of `v` (from 0), if it has that many.
    fn kth(&mut self, v: u32, k: usize) -> Option<u32> {
        let i = self.start[v as usize] + k;
        (i < self.start[v as usize + 1]).then(|| {
            self.reads += 1;
            self.list[i]
        })
    }

    fn nearest(&mut self, v: u32) -> Option<u32> {
        self.kth(v, 0)
    }

    fn second_nearest(&mut self, v: u32) -> Option<u32> {
        self.kth(v, 1)
    }

    /// The nearest unvisited Delaunay neighbour of `v`. `visited` only ever gains points, so
    /// the entries the cursor has passed stay visited and are never read again.
    fn nearest_unvisited(&mut self, v: u32, visited: &[bool]) -> Option<u32> {
        let (c, end) = (&mut self.cursor[v as usize], self.start[v as usize + 1]);
        while *c < end {
            self.reads += 1;
            let w = self.list[*c];
            if !visited[w as usize] {
                return Some(w);
            }
            *c += 1;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Point;
    use crate::internals::filter_edges;
    use crate::samplers::cycle_edges as cycle;

    fn run(pts: &[Point]) -> Vec<crate::geometry::Edge> {
        filter_edges(pts, crawl)
    }

    #[test]
    fn regular_16_gon_is_its_cycle() {
        let pts = crate::samplers::regular_polygon(16, 1.0).points;
        assert_eq!(run(&pts), cycle(16));
    }

    #[test]
    fn open_zigzag_is_a_path() {
        // A zigzag line, 20 points: each end's second-nearest neighbour is two steps along the
        // line, so the crawl reaches both ends and stops without closing.
        let pts: Vec<Point> =
            (0..20).map(|i| [i as f64, if i % 2 == 0 { 0.3 } else { -0.3 }]).collect();
        let expected: Vec<crate::geometry::Edge> = (0..19).map(|i| [i, i + 1]).collect();
        assert_eq!(run(&pts), expected);
    }

    #[test]
    fn open_convex_arc_is_closed() {
        // A limitation of the rule: on a quarter circle the end points are Delaunay neighbours
        // and each is the other's second-nearest neighbour, so the arc is closed into a cycle.
        let pts: Vec<Point> = (0..12)
            .map(|i| {
                let a = i as f64 * std::f64::consts::FRAC_PI_2 / 11.0;
                [a.cos(), a.sin()]
            })
            .collect();
        assert_eq!(run(&pts), cycle(12));
    }

    /// An open Archimedean spiral `r = θ` of `turns` turns, points about `spacing` apart along
    /// it and shuffled: its centre point has many Delaunay neighbours (about 400 at 6000
    /// points and 3 turns), and the crawl reaches it early and keeps it as an extremity.
    fn spiral(turns: f64, spacing: f64) -> Vec<Point> {
        let mut pts = Vec::new();
        let mut t = 0.0f64;
        while t <= turns * std::f64::consts::TAU {
            pts.push([t * t.cos(), t * t.sin()]);
            t += spacing / t.hypot(1.0);
        }
        crate::samplers::Rng::new(7).shuffle(&mut pts);
        pts
    }

    /// The crawl as the reference code does it, scanning both extremities' neighbours at every
    /// step; also returns the neighbours it scanned.
    fn crawl_by_scanning(dt: &Triangulation) -> (Vec<[u32; 2]>, usize) {
        let key = |v: u32, w: u32| (squared_distance(dt.point(v), dt.point(w)), dt.input_index(w));
        let scan = |v: u32, skip: &dyn Fn(u32) -> bool, scanned: &mut usize| {
            let mut ws: Vec<u32> = dt.incident(v).map(|h| dt.other(h, v)).collect();
            *scanned += ws.len();
            ws.retain(|&w| !skip(w));
            ws.sort_by(|&b, &c| key(v, b).partial_cmp(&key(v, c)).unwrap());
            ws
        };
        let mut scanned = 0;
        let nearest: Vec<Option<u32>> = (0..dt.num_vertices() as u32)
            .map(|v| scan(v, &|_| false, &mut 0).first().copied())
            .collect();
        let mut seeds: Vec<_> = dt
            .edge_halfedges()
            .map(|h| (dt.origin(h), dt.dest(h)))
            .filter(|&(a, b)| nearest[a as usize] == Some(b) || nearest[b as usize] == Some(a))
            .map(|(a, b)| if dt.input_index(a) < dt.input_index(b) { (a, b) } else { (b, a) })
            .collect();
        seeds.sort_by(|&(a, b), &(c, d)| {
            let (x, y) = (
                squared_distance(dt.point(a), dt.point(b)),
                squared_distance(dt.point(c), dt.point(d)),
            );
            x.total_cmp(&y)
                .then(dt.input_index(a).cmp(&dt.input_index(c)))
                .then(dt.input_index(b).cmp(&dt.input_index(d)))
        });
        let mut visited = vec![false; dt.num_vertices()];
        let mut edges = Vec::new();
        for (a, b) in seeds {
            if visited[a as usize] || visited[b as usize] {
                continue;
            }
            edges.push([a, b]);
            (visited[a as usize], visited[b as usize]) = (true, true);
            let (mut e, mut steps) = ([a, b], 0);
            loop {
                let second = |v: u32, s: &mut usize| scan(v, &|_| false, s).get(1).copied();
                if steps > 3
                    && (second(e[0], &mut scanned) == Some(e[1])
                        || second(e[1], &mut scanned) == Some(e[0]))
                {
                    edges.push(e);
                    break;
                }
                let u = e.map(|v| {
                    scan(v, &|w| visited[w as usize], &mut scanned)
                        .first()
                        .map(|&w| (key(v, w).0, w))
                });
                let (i, w) = match u {
                    [Some((d1, w1)), Some((d2, _))] if d1 < d2 => (0, w1),
                    [_, Some((_, w2))] => (1, w2),
                    [Some((_, w1)), None] => (0, w1),
                    [None, None] => break,
                };
                edges.push([e[i], w]);
                visited[w as usize] = true;
                e[i] = w;
                steps += 1;
            }
        }
        (edges, scanned)
    }

    #[test]
    fn same_edges_as_scanning_every_step() {
        let grid: Vec<Point> = (0..400).map(|k| [(k % 20) as f64, (k / 20) as f64]).collect();
        let mut rng = crate::samplers::Rng::new(3);
        let cloud: Vec<Point> = (0..2000).map(|_| [rng.uniform(), rng.uniform()]).collect();
        let blob = crate::samplers::random_closed_curve(5, 3000).shuffled(9).points;
        let band = crate::samplers::spiral_band(2000).shuffled(1).points;
        for pts in [spiral(3.0, 0.05), spiral(10.0, 0.5), grid, cloud, blob, band] {
            let dt = Triangulation::new(&pts).unwrap();
            assert_eq!(crawl(&dt), crawl_by_scanning(&dt).0);
        }
    }

    #[test]
    fn reads_each_neighbour_once() {
        // Each list entry is passed at most once (fewer than 6n in all), plus at most four
        // reads per step. Scanning reads the centre's few hundred neighbours at every step.
        let pts = spiral(3.0, 0.03);
        let (n, dt) = (pts.len(), Triangulation::new(&pts).unwrap());
        let (edges, reads) = crawl_counted(&dt);
        let (scanned_edges, scanned) = crawl_by_scanning(&dt);
        assert_eq!(edges, scanned_edges);
        assert!(n > 5000 && reads < 10 * n, "{reads} reads for {n} points");
        assert!(scanned > 100 * n, "{scanned} scanned for {n} points");
    }

    #[test]
    #[ignore = "10⁵ points: run with --release -- --ignored"]
    fn spiral_of_100k_points_reads_each_neighbour_once() {
        let pts = spiral(3.0, 0.0017);
        let (n, dt) = (pts.len(), Triangulation::new(&pts).unwrap());
        let (edges, reads) = crawl_counted(&dt);
        assert!(n > 100_000 && reads < 10 * n, "{reads} reads for {n} points");
        let mut degree = vec![0; n];
        edges.iter().flatten().for_each(|&v| degree[v as usize] += 1);
        assert!(edges.len() >= n - 1 && degree.iter().all(|&d| d <= 2));
    }

    #[test]
    fn small_inputs_do_not_panic() {
        let tri = run(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        assert_eq!(tri, vec![[0, 1], [0, 2]]);
        let square = run(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        assert!(square.len() <= 4);
        let collinear = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]).unwrap();
        assert!(crawl(&collinear).is_empty());
    }
}
