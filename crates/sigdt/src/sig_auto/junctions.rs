//! Junctions (step 15 of SIG-AUTO): where curves meet, crossing (X), one ending on another
//! (T) or several sharing an end (Y), read from the straightest pairs of SIGDT edges.
//!
//! Every vertex takes the pair of its SIGDT edges that runs straightest through it, when
//! that pair turns by at most [`MAX_SAMPLED_TURN`] (a sample of a curve sampled with ε < 1
//! turns by less; `continuation`), among the edges not hidden behind a shorter one in
//! nearly the same direction ([`SHADOW`]). The union of these *straight pairs* is the pair graph. On
//! a sampled curve every sample takes its two curve neighbours, so the pair graph is the
//! curve. Where curves meet in a sample `j`, the samples next to `j` on every curve take `j`
//! in their pairs: `j` gets degree 4 where two curves cross, 3 where a curve ends on
//! another, and one edge per curve at a common end. Short edges across two branches near
//! `j` are nobody's straight pair, and an outlier is on none.
//!
//! A vertex of degree 3 or more in the pair graph is a junction when
//! 1. its edges there are sampled like one curve: the longest is less than twice the
//!    shortest (the non-uniformity bound u < 2 of [MOW22], applied across the branches);
//! 2. no other vertex of degree 3 or more lies within two edges of it: two so close are
//!    samples of two curves that pass near each other and swapped neighbours (noise does
//!    this), not curves that meet;
//! 3. every branch at it is a curve of its own: it runs through at least [`MIN_BRANCH`]
//!    samples before it ends or branches (a few outliers in a row beside a curve do not);
//!    at a crossing (degree 4), a branch of one sample fewer also counts when it continues
//!    such a branch straight through the crossing, turning by at most
//!    [`MAX_SAMPLED_TURN`]: a curve that stops just past the curve it crosses.
//!
//! A component of the pair graph whose vertices of degree 3 or more are all junctions
//! replaces SIG-AUTO's reading on its points when that reading breaks within two edges of
//! one of its junctions (a point there is left out, ends a path or turns by more than
//! [`MAX_SAMPLED_TURN`]) and no reading edge joins the component to a point outside it.
//! Where the reading passes smoothly, it reads the points as the paper's sampling condition
//! says they are, and is kept; so it is where the sampling check finds the network broken.
//! The points of the components whose branching vertices are all junctions, wherever the
//! reading breaks ([`Networks::candidates`]), are curves: SIG-AUTO's outlier rules leave
//! them in.
//!
//! # Complexity
//! O(n + Σ deg²) time over the SIGDT degrees (O(n) on curve samples, whose SIGDT degrees
//! are bounded), O(n) memory.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use super::continuation::MAX_SAMPLED_TURN;
use crate::delaunay::Triangulation;
use crate::delaunay::EMPTY;
use crate::geometry::{squared_distance, Point};
use crate::graph::EdgeMask;
use crate::proximity::sigdt::sigdt_with_degrees_for;

/// The fewest samples past a junction that make a branch (test 3 of the module docs): three
/// show a curve's direction and how it bends.
pub const MIN_BRANCH: usize = 3;

/// Seen from a vertex, a neighbour within this angle of the direction of a nearer one lies
/// behind it: half of [`MAX_SAMPLED_TURN`], the most by which the directions from a sample
/// to its next and its next but one differ on a curve sampled with ε < 1. On evenly spaced
/// straight runs SIGDT keeps the edges that skip a sample (their length ties `r(p) + r(q)`);
/// they are hidden so.
const SHADOW: f64 = MAX_SAMPLED_TURN / 2.0;

/// No vertex, in a pair.
const NONE: u32 = u32::MAX;

/// The pair graph of one triangulation and its junctions, built the first time a step of
/// the run asks (most runs never do: their reading breaks nowhere and their spanning trees
/// do not branch).
pub(super) struct Networks<'a> {
    dt: &'a Triangulation,
    spacing: &'a [f64],
    built: std::cell::OnceCell<(PairGraph, Vec<u32>)>,
}

impl<'a> Networks<'a> {
    /// `spacing`: every vertex's nearest-neighbour distance.
    pub fn new(dt: &'a Triangulation, spacing: &'a [f64]) -> Networks<'a> {
        Networks { dt, spacing, built: std::cell::OnceCell::new() }
    }

    /// The pair graph and its junctions (sorted).
    pub fn get(&self) -> &(PairGraph, Vec<u32>) {
        self.built.get_or_init(|| {
            let pairs = PairGraph::new(self.dt, self.spacing);
            let found = match (0..self.dt.num_vertices() as u32).any(|v| pairs.degree(v) >= 3) {
                true => junctions(self.dt, &pairs),
                false => Vec::new(),
            };
            (pairs, found)
        })
    }

    /// Whether each vertex lies in a component of the pair graph that reads as a network
    /// (its vertices of degree 3 or more are all junctions, and there is one), wherever the
    /// reading breaks: the points that are curves, not outliers, whatever the reading.
    pub fn candidates(&self) -> Vec<bool> {
        let (pairs, found) = self.get();
        network_vertices(pairs, self.dt.num_vertices(), found, |_| true)
    }
}

/// The pair graph of `dt` (see the module docs) in compressed rows: the neighbours of vertex
/// `v` are `neighbours[start[v]..start[v + 1]]`.
pub(super) struct PairGraph {
    start: Vec<u32>,
    neighbours: Vec<u32>,
}

impl PairGraph {
    /// Every vertex's straightest pair of SIGDT edges, joined. O(n) beyond the SIGDT test:
    /// the SIGDT rows are filled in one pass over the half-edges, the pairs taken in
    /// parallel, and a row of the pair graph holds the vertex's own pair and the vertices
    /// that took it into theirs.
    /// `spacing`: every vertex's nearest-neighbour distance.
    pub fn new(dt: &Triangulation, spacing: &[f64]) -> PairGraph {
        let n = dt.num_vertices();
        let (sigdt, degree) = sigdt_with_degrees_for(dt, spacing);
        let (row_start, rows) = rows_of(dt, &sigdt, &degree);
        let limit = -MAX_SAMPLED_TURN.cos();
        let picks: Vec<[u32; 2]> = crate::parallel::map_range(n, |v| {
            let around = &rows[row_start[v] as usize..row_start[v + 1] as usize];
            straightest_pair(dt.point(v as u32), around, |u| dt.point(u), limit)
                .unwrap_or([NONE; 2])
        });
        let takes = |v: u32, w: u32| picks[v as usize].contains(&w);
        let mut start = vec![0u32; n + 1];
        for v in 0..n as u32 {
            for w in picks[v as usize].into_iter().filter(|&w| w != NONE) {
                start[v as usize + 1] += 1;
                if !takes(w, v) {
                    start[w as usize + 1] += 1;
                }
            }
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut neighbours = vec![0u32; start[n] as usize];
        let mut put = |v: u32, w: u32| {
            neighbours[fill[v as usize] as usize] = w;
            fill[v as usize] += 1;
        };
        for v in 0..n as u32 {
            for w in picks[v as usize].into_iter().filter(|&w| w != NONE) {
                put(v, w);
                if !takes(w, v) {
                    put(w, v);
                }
            }
        }
        PairGraph { start, neighbours }
    }

    /// The edges `[v, w]` of `v` with `v < w` (each edge of the graph at one of its ends).
    pub fn edges_at(&self, v: u32) -> impl Iterator<Item = [u32; 2]> + '_ {
        self.neighbours(v).iter().filter(move |&&w| v < w).map(move |&w| [v, w])
    }

    pub fn neighbours(&self, v: u32) -> &[u32] {
        &self.neighbours[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }

    pub fn degree(&self, v: u32) -> usize {
        self.neighbours(v).len()
    }

    /// Whether the branch that leaves `j` along its edge to `w` runs through at least `k`
    /// vertices before it ends or branches.
    fn branch_reaches(&self, j: u32, w: u32, k: usize) -> bool {
        let (mut previous, mut current) = (j, w);
        for _ in 1..k {
            let &[a, b] = self.neighbours(current) else { return false };
            (previous, current) = (current, if a == previous { b } else { a });
        }
        true
    }

    /// `v` and the vertices within two edges of it (with repeats).
    fn within_two(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        let near = self.neighbours(v).iter().flat_map(move |&w| self.neighbours(w));
        std::iter::once(v).chain(self.neighbours(v).iter().copied()).chain(near.copied())
    }
}

/// The SIGDT neighbours of every vertex in compressed rows (`degree` from the SIGDT test):
/// vertex `v`'s are `rows[start[v]..start[v + 1]]`, in half-edge order.
fn rows_of(dt: &Triangulation, sigdt: &EdgeMask, degree: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let n = dt.num_vertices();
    let mut start = vec![0u32; n + 1];
    for v in 0..n {
        start[v + 1] = start[v] + degree[v];
    }
    let mut fill = start.clone();
    let mut rows = vec![0u32; start[n] as usize];
    for h in (0..dt.num_halfedges() as u32).filter(|&h| sigdt.contains(h)) {
        let (a, b) = (dt.origin(h), dt.dest(h));
        rows[fill[a as usize] as usize] = b;
        fill[a as usize] += 1;
        // A hull half-edge has no twin to list the edge at its other end.
        if dt.twin(h) == EMPTY {
            rows[fill[b as usize] as usize] = a;
            fill[b as usize] += 1;
        }
    }
    (start, rows)
}

/// The two of `around` whose directions from `p` make the widest angle, if its cosine is at
/// most `limit`; ties go to the pair with the lowest indices. A neighbour within
/// [`SHADOW`] of the direction of a nearer one is hidden behind it and takes no part.
fn straightest_pair(
    p: Point,
    around: &[u32],
    point: impl Fn(u32) -> Point,
    limit: f64,
) -> Option<[u32; 2]> {
    let measure = |u: u32| {
        let q = point(u);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let length = (dx * dx + dy * dy).sqrt();
        ([dx / length, dy / length], length)
    };
    // SIGDT degrees are small on curve samples: no allocation for up to 16 neighbours.
    // Each ray: direction, length, and whether it is hidden.
    let mut fixed = [([0.0f64; 2], 0.0f64, false); 16];
    let mut grown = Vec::new();
    let rays: &mut [([f64; 2], f64, bool)] = if around.len() <= fixed.len() {
        &mut fixed[..around.len()]
    } else {
        grown.resize(around.len(), ([0.0f64; 2], 0.0f64, false));
        &mut grown
    };
    for (ray, &u) in rays.iter_mut().zip(around) {
        let (direction, length) = measure(u);
        *ray = (direction, length, false);
    }
    let shadow = SHADOW.cos();
    let dot = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
    for i in 0..rays.len() {
        let (direction, length, _) = rays[i];
        rays[i].2 = (0..rays.len()).any(|k| {
            k != i
                && dot(direction, rays[k].0) > shadow
                && (rays[k].1, around[k]) < (length, around[i])
        });
    }
    let mut best: Option<(f64, [u32; 2])> = None;
    for i in (0..rays.len()).filter(|&i| !rays[i].2) {
        for k in (i + 1..rays.len()).filter(|&k| !rays[k].2) {
            let cos = dot(rays[i].0, rays[k].0);
            let pair = [around[i].min(around[k]), around[i].max(around[k])];
            let better = match best {
                None => true,
                Some((c, p)) => cos < c || (cos == c && pair < p),
            };
            if better {
                best = Some((cos, pair));
            }
        }
    }
    best.filter(|&(cos, _)| cos <= limit).map(|(_, pair)| pair)
}

/// The junctions of `pairs` (see the module docs, tests 1–3), sorted.
pub(super) fn junctions(dt: &Triangulation, pairs: &PairGraph) -> Vec<u32> {
    let branching = |v: u32| pairs.degree(v) >= 3;
    let uniform = |j: u32| {
        let lengths =
            pairs.neighbours(j).iter().map(|&w| squared_distance(dt.point(j), dt.point(w)));
        let (short, long) = lengths.fold((f64::INFINITY, 0.0f64), |(s, l), x| (s.min(x), l.max(x)));
        long < 4.0 * short
    };
    // A curve may stop just past a crossing: its end there is a branch of two samples that
    // continues, straight through the crossing, a branch of its own length.
    let overshoot = |j: u32, w: u32| {
        let around = pairs.neighbours(j);
        let beyond = straight_beyond(dt.point(j), around, w, |u| dt.point(u));
        around.len() == 4
            && pairs.branch_reaches(j, w, MIN_BRANCH - 1)
            && beyond.is_some_and(|x| pairs.branch_reaches(j, x, MIN_BRANCH))
    };
    (0..dt.num_vertices() as u32)
        .filter(|&j| branching(j) && uniform(j))
        .filter(|&j| pairs.within_two(j).all(|v| v == j || !branching(v)))
        .filter(|&j| {
            let long = |w: u32| pairs.branch_reaches(j, w, MIN_BRANCH);
            pairs.neighbours(j).iter().all(|&w| long(w) || overshoot(j, w))
        })
        .collect()
}

/// The vertex of `around` (the neighbours of `p`) that continues the edge from `w` through
/// `p` straightest, if it turns by at most [`MAX_SAMPLED_TURN`]; ties by index.
fn straight_beyond(p: Point, around: &[u32], w: u32, point: impl Fn(u32) -> Point) -> Option<u32> {
    let direction = |u: u32| {
        let q = point(u);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let length = (dx * dx + dy * dy).sqrt();
        [dx / length, dy / length]
    };
    let from = direction(w);
    let cos = |u: u32| {
        let d = direction(u);
        from[0] * d[0] + from[1] * d[1]
    };
    let best = around
        .iter()
        .copied()
        .filter(|&u| u != w)
        .min_by(|&a, &b| cos(a).total_cmp(&cos(b)).then(a.cmp(&b)))?;
    (cos(best) <= -MAX_SAMPLED_TURN.cos()).then_some(best)
}

/// Whether each vertex lies in a component of the pair graph whose vertices of degree 3 or
/// more are all `junctions` (sorted), at one of which at least SIG-AUTO's reading breaks
/// (the last paragraph of the module docs: `breaks(v)` says whether it breaks at `v`).
pub(super) fn network_vertices(
    pairs: &PairGraph,
    n: usize,
    junctions: &[u32],
    breaks: impl Fn(u32) -> bool,
) -> Vec<bool> {
    let mut seen = vec![false; n];
    let mut network = vec![false; n];
    let mut component = Vec::new();
    for &j in junctions {
        if seen[j as usize] {
            continue;
        }
        seen[j as usize] = true;
        component.clear();
        component.push(j);
        let mut k = 0;
        while let Some(&v) = component.get(k) {
            k += 1;
            for &w in pairs.neighbours(v) {
                if !seen[w as usize] {
                    seen[w as usize] = true;
                    component.push(w);
                }
            }
        }
        let known = |v: &u32| pairs.degree(*v) < 3 || junctions.binary_search(v).is_ok();
        let breaks_near = |&j: &u32| pairs.within_two(j).any(&breaks);
        let mut met = component.iter().filter(|&&v| pairs.degree(v) >= 3);
        if component.iter().all(known) && met.any(breaks_near) {
            for &v in &component {
                network[v as usize] = true;
            }
        }
    }
    network
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proximity::nearest::nearest_vertex_distances;

    fn graph(points: &[Point]) -> (Triangulation, PairGraph) {
        let dt = Triangulation::new(points).unwrap();
        let pairs = PairGraph::new(&dt, &nearest_vertex_distances(&dt));
        (dt, pairs)
    }

    /// Two straight strokes of `k` samples each side crossing at the origin at `angle`.
    fn cross(k: usize, angle: f64) -> Vec<Point> {
        let mut points = vec![[0.0, 0.0]];
        for s in 1..=k {
            let t = s as f64;
            points.extend([[t, 0.0], [-t, 0.0]]);
            points
                .extend([[t * angle.cos(), t * angle.sin()], [-t * angle.cos(), -t * angle.sin()]]);
        }
        points
    }

    #[test]
    fn a_crossing_is_one_vertex_of_degree_four() {
        let (dt, pairs) = graph(&cross(6, 1.2));
        let centre = dt.vertex_of_inputs()[0];
        assert_eq!(pairs.degree(centre), 4);
        let others = (0..dt.num_vertices() as u32).filter(|&v| v != centre);
        assert!(others.clone().all(|v| pairs.degree(v) <= 2));
        let found = junctions(&dt, &pairs);
        assert_eq!(found, vec![centre]);
        let n = dt.num_vertices();
        assert!(network_vertices(&pairs, n, &found, |_| true).iter().all(|&x| x));
        // Where the reading passes smoothly, it is kept.
        assert!(!network_vertices(&pairs, n, &found, |_| false).contains(&true));
    }

    #[test]
    fn an_evenly_spaced_straight_tee_is_one_junction() {
        // On evenly spaced straight runs SIGDT also keeps the edges that skip a sample, and
        // after rounding they can run straighter than the curve's own.
        for turn in 0..12 {
            let (sin, cos) = (0.13 * turn as f64).sin_cos();
            let mut points: Vec<Point> = (-8..=8).map(|i| [i as f64, 0.0]).collect();
            points.extend((1..=8).map(|i| [0.0, i as f64]));
            for p in &mut points {
                *p = [p[0] * cos - p[1] * sin + 3.7, p[0] * sin + p[1] * cos - 1.3];
            }
            let (dt, pairs) = graph(&points);
            let vertex_of = dt.vertex_of_inputs();
            let degree = |i: usize| pairs.degree(vertex_of[i]);
            assert_eq!(degree(8), 3, "the junction at the origin, turn {turn}");
            for end in [0, 16, 24] {
                assert_eq!(degree(end), 1, "turn {turn}");
            }
            let others = (0..points.len()).filter(|i| ![0, 8, 16, 24].contains(i));
            assert!(others.clone().all(|i| degree(i) == 2), "turn {turn}");
            assert_eq!(junctions(&dt, &pairs), vec![vertex_of[8]]);
        }
    }

    #[test]
    fn a_stroke_that_stops_just_past_a_crossing_still_crosses() {
        // One stroke of the crossing ends two samples past it: a branch one sample short,
        // continued straight through the crossing by six. The same two samples as the stem
        // of a T are no branch of their own (a pair of outliers beside a curve).
        let mut crossing = cross(6, 1.2);
        let (sin, cos) = 1.2f64.sin_cos();
        crossing.retain(|p| {
            let along = -(p[0] * cos + p[1] * sin);
            let across = p[1] * cos - p[0] * sin;
            !(across.abs() < 1e-9 && along > 2.5)
        });
        let (dt, pairs) = graph(&crossing);
        let centre = dt.vertex_of_inputs()[0];
        assert_eq!(pairs.degree(centre), 4);
        assert_eq!(junctions(&dt, &pairs), vec![centre]);

        let mut tee: Vec<Point> = (-8..=8).map(|i| [i as f64, 0.0]).collect();
        tee.extend((1..=2).map(|i| [0.0, i as f64]));
        let (dt, pairs) = graph(&tee);
        assert_eq!(pairs.degree(dt.vertex_of_inputs()[8]), 3);
        assert!(junctions(&dt, &pairs).is_empty());
    }

    #[test]
    fn a_smooth_closed_curve_has_no_branching_vertex() {
        let points: Vec<Point> = (0..40)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 40.0;
                [2.0 * a.cos(), a.sin()]
            })
            .collect();
        let (dt, pairs) = graph(&points);
        assert!((0..dt.num_vertices() as u32).all(|v| pairs.degree(v) == 2));
        assert!(junctions(&dt, &pairs).is_empty());
    }

    #[test]
    fn unevenly_spaced_branches_are_no_junction() {
        // A T whose stem arrives at more than twice the spacing of the bar.
        let mut points: Vec<Point> = (-8..=8).map(|i| [i as f64, 0.0]).collect();
        points.extend((1..=6).map(|i| [0.3, 2.5 * i as f64]));
        let (dt, pairs) = graph(&points);
        assert!(junctions(&dt, &pairs).is_empty());
    }

    #[test]
    fn straightest_pair_breaks_ties_by_index() {
        let around = [1, 2, 3, 4];
        let at = |u: u32| [[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]][u as usize - 1];
        assert_eq!(straightest_pair([0.0, 0.0], &around, at, -0.5), Some([1, 2]));
        assert_eq!(straightest_pair([0.0, 0.0], &around[2..], at, -0.5), Some([3, 4]));
        let bent = [[1.0, 0.0], [0.0, 1.0]];
        assert_eq!(straightest_pair([0.0, 0.0], &[1, 2], |u| bent[u as usize - 1], -0.5), None);
    }
}
