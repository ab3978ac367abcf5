//! PEEL: drop the longest edge of every Delaunay triangle, then keep short-edge pairs.
//!
//! [PMM18] A. D. Parakkat, S. Methirumangalath, R. Muthuganapathy, *Peeling the longest: A
//! simple generalized curve reconstruction algorithm*, Computers & Graphics (SMI 2018).
//! The paper text was not at hand; the rules below are those of the authors' reference
//! implementation (`github.com/amaldevp/Peeling_the_Longest`, `Reconstruct/reconstruct.cpp`,
//! CGAL 4.7), read and restated in our own words.
//!
//! # Steps
//! 1. *Peel*: in every Delaunay triangle, mark its longest edge (every edge at least as long as
//!    the other two, so ties peel all of them). The *peeled graph* `G` is the set of Delaunay
//!    edges that are marked in none of their triangles.
//! 2. *Filter*: keep an edge `ab` of `G` unless two or more other `G`-edges at one endpoint are
//!    strictly shorter than `ab` (see the departure below for the exact count at `b`).
//! 3. *Restore self-intersections*: at every endpoint of degree 1 in the kept set, add its
//!    shortest Delaunay edge not yet kept if that edge is shorter than `λ` times the kept edge.
//!    The parameter `λ` is entered by the user; the program's prompt says "0 if no
//!    self-intersections", and with `λ = 0` this step adds nothing. The benchmark's curves do
//!    not self-intersect, so `λ = 0` and the step is omitted here.
//!
//! The result can have open ends, several components and vertices of degree up to 2 (step 2
//! keeps at most the two shortest `G`-edges at a vertex, ties aside).
//!
//! # Guarantee
//! None is proven for this variant. [MOW22] Table 2: 64.7 % manifold, 14.8 % sharp, 43.4 % open,
//! 57.4 % multiple.
//!
//! # Complexity
//! O(n) given the triangulation (the reference scans all edges for each edge, O(n²)).
//!
//! # Departures from the reference code
//! - Lengths are compared as `f64` squared distances instead of `f32` lengths.
//! - In step 2 the reference counts, at endpoint `a`, the other `G`-neighbours `c` of `a` with
//!   `|ac| < |ab|`; at endpoint `b` it does not reset its neighbour list, so it counts the
//!   `G`-neighbours of both `a` and `b` (other than `b`, `a`) whose distance *from `b`* is
//!   below `|ab|`. [`peel`] reproduces that count, since it is what the authors' program
//!   computes. Counting at `b` only `b`'s own neighbours, the evident intent, changes results
//!   on the labelled curves (`docs/evaluation.md`). The reference's `a` is whichever end
//!   CGAL's edge iterator names first; here `a` is the end with the lexicographically
//!   smaller point `(x, y)`, so that the result does not depend on the input order.
//!
//! [PMM18]: https://github.com/amaldevp/Peeling_the_Longest
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::{next, Triangulation};
use crate::geometry::squared_distance;
use crate::graph::EdgeMask;

/// The PEEL edges of `dt` as vertex pairs, with the reference implementation's filter count
/// (see the module docs). Empty if `dt` has no triangles.
pub fn peel(dt: &Triangulation) -> Vec<[u32; 2]> {
    peel_with(dt, true)
}

/// Steps 1–2; `reference_count` selects the reference program's count at the second endpoint.
fn peel_with(dt: &Triangulation, reference_count: bool) -> Vec<[u32; 2]> {
    let graph = peeled_graph(dt);
    // Step 2, on an adjacency list of `G` (neighbours of each vertex).
    let n = dt.num_vertices();
    let mut adjacency: Vec<Vec<u32>> = vec![Vec::new(); n];
    for h in dt.edge_halfedges().filter(|&h| graph.contains(h)) {
        let (a, b) = (dt.origin(h), dt.dest(h));
        adjacency[a as usize].push(b);
        adjacency[b as usize].push(a);
    }
    let d2 = |p: u32, q: u32| squared_distance(dt.point(p), dt.point(q));
    // Other neighbours `c` of `from`'s list `at`, excluding `skip`, closer to `from` than `len`.
    let shorter = |at: u32, skip: u32, from: u32, len: f64| {
        adjacency[at as usize].iter().filter(|&&c| c != skip && d2(from, c) < len).count()
    };
    let mut edges = Vec::new();
    for h in dt.edge_halfedges().filter(|&h| graph.contains(h)) {
        // The count is asymmetric, so which end is `a` matters: the lexicographically
        // smaller point, not the half-edge's origin, which depends on the input order.
        let (a, b) = match dt.point(dt.origin(h)) < dt.point(dt.dest(h)) {
            true => (dt.origin(h), dt.dest(h)),
            false => (dt.dest(h), dt.origin(h)),
        };
        let len = d2(a, b);
        let at_a = shorter(a, b, a, len);
        let mut at_b = shorter(b, a, b, len);
        if reference_count {
            at_b += shorter(a, b, b, len);
        }
        if at_a < 2 && at_b < 2 {
            edges.push([a, b]);
        }
    }
    edges
}

/// Step 1: the Delaunay edges that are the longest edge of none of their triangles.
fn peeled_graph(dt: &Triangulation) -> EdgeMask {
    let mut peeled = vec![false; dt.num_halfedges()];
    for t in 0..dt.num_triangles() as u32 {
        let hs = [3 * t, next(3 * t), next(next(3 * t))];
        let len = hs.map(|h| squared_distance(dt.point(dt.origin(h)), dt.point(dt.dest(h))));
        let longest = len.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        for (k, &h) in hs.iter().enumerate() {
            if len[k] >= longest {
                peeled[h as usize] = true;
            }
        }
    }
    let mut graph = EdgeMask::new(dt);
    for h in dt.edge_halfedges() {
        let t = dt.twin(h);
        let marked = peeled[h as usize] || (t != crate::delaunay::EMPTY && peeled[t as usize]);
        if !marked {
            graph.set(dt, h, true);
        }
    }
    graph
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Point;

    fn run(pts: &[Point]) -> Vec<crate::geometry::Edge> {
        let dt = Triangulation::new(pts).unwrap();
        let reference = dt.to_input_edges(peel(&dt));
        assert_eq!(reference, dt.to_input_edges(peel_with(&dt, false)));
        reference
    }

    #[test]
    fn regular_16_gon_is_its_cycle() {
        let gon = crate::samplers::regular_polygon(16, 1.0);
        assert_eq!(run(&gon.points), gon.edges);
    }

    #[test]
    fn open_arc_is_a_path() {
        // A quarter circle, 12 points: every chord is the longest edge of a fan triangle.
        let pts: Vec<Point> = (0..12)
            .map(|i| {
                let a = i as f64 * std::f64::consts::FRAC_PI_2 / 11.0;
                [a.cos(), a.sin()]
            })
            .collect();
        let expected: Vec<crate::geometry::Edge> = (0..11).map(|i| [i, i + 1]).collect();
        assert_eq!(run(&pts), expected);
    }

    #[test]
    fn small_inputs_do_not_panic() {
        // Right triangle: the hypotenuse is peeled.
        assert_eq!(run(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), vec![[0, 1], [0, 2]]);
        // Four cocircular points: the diagonal is peeled, the square remains.
        let square = run(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        assert_eq!(square, vec![[0, 1], [0, 3], [1, 2], [2, 3]]);
        let collinear = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]).unwrap();
        assert!(peel(&collinear).is_empty());
    }
}
