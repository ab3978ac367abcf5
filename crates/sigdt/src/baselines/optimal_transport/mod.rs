//! OPTIMALTRANSPORT: reconstruction and simplification by optimal transport [dGCSAD11].
//!
//! The points are samples of a measure (mass 1 each); the output is a simplicial complex
//! whose edges carry that mass with the least transport cost. It starts from the Delaunay
//! triangulation of the points, where every sample sits on its own vertex (cost 0), and
//! collapses half-edges greedily, cheapest first, until the stopping rule holds. Implemented
//! from the paper and the behaviour of CGAL's `Optimal_transportation_reconstruction_2`
//! (5.5.1, read, not ported), as specified in `docs/algorithms.md` §3.10; `tools/cgal-otr/`
//! compares the two (§7.4).
//!
//! # Steps
//! 1. *Triangulate* the distinct points and the corners of their bounding box enlarged by
//!    half its larger side on every side (`mesh`). The corners are pinned.
//! 2. *Assign* every sample to the nearest simplex of the triangle containing it, and give
//!    every edge the cheaper of two transport plans: spread uniformly along the edge, or sent
//!    to the nearer end (`transport`). Edges with mass and the edge plan are *solid*, the
//!    others *ghosts*.
//! 3. *Queue* every half-edge collapse `s → t` (`s` not pinned) by the rise in the transport
//!    cost of `s`'s star. A collapse that would fold a triangle is first made possible by
//!    flipping spokes of `s`, or dropped (`region`).
//! 4. *Collapse* the cheapest: flip, merge `s` into `t`, assign the samples of the old star
//!    again within the new triangles, update the costs (`simplify`, `star`).
//! 5. *Relocate* the vertices of the old link, twice: each moves to the least-squares
//!    position for its samples when that keeps its star valid and lowers its cost
//!    (`relocate`).
//! 6. Evaluate the changed candidates again and repeat until the stopping rule ([`Stop`]).
//!
//! The output is the solid edges between vertices of the points (not the frame), and the
//! vertices that receive mass without a solid edge (isolated points), as
//! [`Vertices::New`](crate::Vertices::New): they are where the transport put them, not input
//! points. Loops, paths and the status are read from those edges as for the graph filters.
//!
//! # Stopping rule
//! [`default_stop`]: collapse until a quarter of the distinct points are left as vertices
//! (`docs/algorithms.md` §7.4 measures the choice against others on the noise sweep).
//! [`optimal_transport_with`] takes any [`Stop`].
//!
//! # Guarantee
//! The solid edges are edges of a valid triangulation, so they never cross, and every
//! output vertex lies inside the points' bounding box. Nothing is guaranteed about their
//! topology: a result may have junctions, open ends and isolated points. It never passes
//! through all input points ([MOW22] Table 2's 0 %): an untouched vertex holds its sample
//! and has no solid edge, each collapse removes a vertex, and relocations move them.
//!
//! # Complexity
//! The triangulation is O(n log n). Filling the queue evaluates every vertex's collapses
//! once. A vertex is evaluated only while it has at most
//! [`MAX_DEGREE`](simplify::MAX_DEGREE) edges and its region (star and link) holds at most
//! `max(256, 16·n/v)` samples, `v` vertices being left
//! ([`MAX_REGION_SAMPLES`](simplify::MAX_REGION_SAMPLES)), so an evaluation costs
//! O(d·k log k) for `d` edges and `k` samples. A step re-evaluates a bounded number of
//! vertices (the changed stars and the vertices across their changed boundary edges) and
//! costs O(log n) of queue work. Summed over the steps, a run down to `v` vertices is
//! O(n log n + n·log²(n/v)): O(n log n) for the default rule. Memory is O(n).
//!
//! # Departures
//! - **Degenerate input** (fewer than three distinct points, all collinear) gets the shared
//!   result of every method (`docs/algorithms.md` §0.1); CGAL triangulates it with the frame.
//!   Exact duplicates are one sample of mass 1 (CGAL keeps one of them on the vertex).
//! - **Assignment** measures the distance to an edge as the distance to the segment; CGAL
//!   measures it to the segment's line. Ties are broken by vertex number.
//! - **Flips**: our own rule (`region`), not CGAL's ordering by intersection distances.
//! - **Relocation** compares the whole transport cost of the star before and after; CGAL
//!   compares its normal part. A move outside the samples' bounding box is refused.
//! - **Queue**: one entry per vertex (its cheapest collapse), evaluated again once per step,
//!   after the relocations, when something it depends on changed; CGAL keeps every half-edge
//!   and re-queues after each relocation. The chosen collapse is the one an exhaustive queue
//!   of our candidates would choose.
//! - **Limits**: vertices with more than [`MAX_DEGREE`](simplify::MAX_DEGREE) edges or too
//!   many samples in their region (see the complexity) wait until their neighbours' collapses
//!   bring them under (CGAL has no limit). A run may then stop short of its vertex count.
//!   On a straight line of samples this keeps one edge from collecting all of them.
//! - **Tolerance** ([`Stop::Tolerance`]) bounds the RMS transport distance over all samples
//!   of the collapse region, the outer sides of its boundary included; CGAL divides by the
//!   mass of the star only.
//! - **Output**: solid edges at a frame corner are left out, and so are corners that
//!   receive mass (CGAL lists them); isolated points include vertices that receive mass by a
//!   ghost edge's vertex plan (CGAL lists only vertices with a sample on them).
//!
//! # References
//! - [dGCSAD11] F. de Goes, D. Cohen-Steiner, P. Alliez, M. Desbrun. An Optimal Transport
//!   Approach to Robust Reconstruction and Simplification of 2D Shapes. Computer Graphics
//!   Forum 30(5), SGP 2011.
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [dGCSAD11]: https://doi.org/10.1111/j.1467-8659.2011.02033.x
//! [MOW22]: https://doi.org/10.1111/cgf.14654
mod mesh;
mod region;
mod relocate;
mod simplify;
mod star;
mod transport;

use crate::delaunay::{Triangulation, EMPTY};
use crate::error::{Error, Result};
use crate::geometry::Point;
use crate::result::{degenerate_result, from_new_vertices, Reconstruction};
use mesh::{Mesh, FRAME};
use simplify::Simplifier;

/// When OPTIMALTRANSPORT stops collapsing (it also stops when no collapse is left).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stop {
    /// When at most this many vertices are left, frame corners not counted (CGAL's
    /// `run_until`).
    Vertices(usize),
    /// After this many collapses (CGAL's `run`).
    Steps(usize),
    /// When every remaining collapse would raise the RMS transport distance of its region
    /// above this distance, in the caller's units (CGAL's
    /// `run_under_wasserstein_tolerance`).
    Tolerance(f64),
}

/// The default stopping rule: collapse until `ceil(m / DEFAULT_DIVISOR)` of the `m` distinct
/// points are left as vertices (see the module docs).
pub const DEFAULT_DIVISOR: usize = 4;

/// The default stopping rule for `m` distinct points.
pub fn default_stop(m: usize) -> Stop {
    Stop::Vertices(m.div_ceil(DEFAULT_DIVISOR))
}

/// OPTIMALTRANSPORT on `dt` with the default stopping rule.
pub(crate) fn optimal_transport_on(dt: &Triangulation) -> Reconstruction {
    optimal_transport_with(dt, default_stop(dt.num_vertices())).expect("a valid stopping rule")
}

/// OPTIMALTRANSPORT on `dt` with the stopping rule `stop`. Not a user parameter: it exists so
/// that stopping rules can be compared (`docs/algorithms.md` §7.4).
///
/// # Errors
/// [`Error::InvalidOption`] for a tolerance that is negative or not finite.
#[doc(hidden)]
pub fn optimal_transport_with(dt: &Triangulation, stop: Stop) -> Result<Reconstruction> {
    if let Stop::Tolerance(t) = stop {
        if !(t.is_finite() && t >= 0.0) {
            return Err(Error::InvalidOption(format!("tolerance {t} is not a distance >= 0")));
        }
    }
    if let Some(result) = degenerate_result(dt) {
        return Ok(result);
    }
    let points: Vec<Point> = (0..dt.num_vertices() as u32).map(|v| dt.point(v)).collect();
    // The scale from the caller's units to the triangulation's: a power of two.
    let scale = {
        let p = points.iter().flatten().copied().find(|&c| c != 0.0).unwrap_or(1.0);
        let q = dt.unscale([p, p])[0];
        p / q
    };
    let mut ot = Simplifier::new(&points, stop, scale);
    ot.run(stop);
    let (vertices, edges) = output(&mut ot);
    Ok(from_new_vertices(dt, &vertices, edges))
}

/// The output vertices (positions, sorted) and solid edges between them; see the module
/// docs.
fn output(ot: &mut Simplifier) -> (Vec<Point>, Vec<[u32; 2]>) {
    let mut pairs = Vec::new();
    for k in 0..ot.mesh.num_slots() {
        if !ot.mesh.alive(k) {
            continue;
        }
        for h in 3 * k..3 * k + 3 {
            let (a, b, g) = (ot.mesh.origin(h), ot.mesh.dest(h), ot.mesh.twin(h));
            if (g == EMPTY || h < g) && ot.solid[h as usize] && !Mesh::pinned(a) && !Mesh::pinned(b)
            {
                pairs.push([a, b]);
            }
        }
    }
    let n = ot.mesh.pos.len();
    let mut used = vec![false; n];
    pairs.iter().flatten().for_each(|&v| used[v as usize] = true);
    let mut kept: Vec<u32> = (FRAME..n as u32).filter(|&v| used[v as usize]).collect();
    let isolated: Vec<u32> = (FRAME..n as u32)
        .filter(|&v| !used[v as usize] && ot.mesh.degree(v) > 0 && ot.has_mass(v))
        .collect();
    kept.extend(isolated);
    // Numbered by position, so that the numbering does not depend on the input order.
    let pos = &ot.mesh.pos;
    kept.sort_by(|&a, &b| {
        let (p, q) = (pos[a as usize], pos[b as usize]);
        p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
    });
    let mut index = vec![u32::MAX; n];
    for (i, &v) in kept.iter().enumerate() {
        index[v as usize] = i as u32;
    }
    let edges = pairs.iter().map(|&[a, b]| [index[a as usize], index[b as usize]]).collect();
    (kept.iter().map(|&v| pos[v as usize]).collect(), edges)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::orient2d;
    use crate::internals::check_reconstruction;
    use crate::result::{Status, Vertices};
    use crate::samplers::uniform_noise;

    /// `n` points on the unit circle, moved by uniform noise of `s` of the diagonal.
    fn noisy_circle(n: usize, s: f64) -> Vec<Point> {
        let circle: Vec<Point> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                [a.cos(), a.sin()]
            })
            .collect();
        uniform_noise(&circle, s, 7).unwrap()
    }

    fn run(points: &[Point], stop: Stop) -> Reconstruction {
        let dt = Triangulation::new(points).unwrap();
        let rec = optimal_transport_with(&dt, stop).unwrap();
        check_reconstruction(points, &rec).unwrap();
        rec
    }

    fn new_vertices(rec: &Reconstruction) -> &[Point] {
        match &rec.vertices {
            Vertices::New(v) => v,
            other => panic!("not new vertices: {other:?}"),
        }
    }

    #[test]
    fn a_noisy_circle_becomes_a_polygon_near_it() {
        let points = noisy_circle(400, 0.002);
        let rec = run(&points, Stop::Vertices(40));
        let v = new_vertices(&rec);
        assert!(v.len() <= 40 && rec.edges.len() >= 30, "{} vertices", v.len());
        for p in v {
            let r = p[0].hypot(p[1]);
            assert!((r - 1.0).abs() < 0.02, "vertex {p:?} at radius {r}");
        }
        // Edges span several samples: longer than five sample spacings.
        let [i, j] = rec.edges[0];
        let length = (v[i][0] - v[j][0]).hypot(v[i][1] - v[j][1]);
        assert!(length > 5.0 * std::f64::consts::TAU / 400.0, "{length}");
    }

    #[test]
    fn the_mesh_and_the_samples_stay_consistent() {
        let points = noisy_circle(300, 0.01);
        let dt = Triangulation::new(&points).unwrap();
        let scaled: Vec<Point> = (0..dt.num_vertices() as u32).map(|v| dt.point(v)).collect();
        let mut ot = Simplifier::new(&scaled, Stop::Vertices(30), 1.0);
        ot.run(Stop::Vertices(30));
        assert_eq!(ot.vertices, 30);
        ot.mesh.check();
        // Every sample is assigned once, to a vertex at its position or to a half-edge of a
        // triangle that contains it.
        let mut seen = vec![0; scaled.len()];
        for k in (0..ot.mesh.num_slots()).filter(|&k| ot.mesh.alive(k)) {
            let c = ot.mesh.corners(k).map(|v| ot.mesh.pos[v as usize]);
            for h in 3 * k..3 * k + 3 {
                for s in ot.samples.on(h) {
                    let p = ot.samples.pos[s as usize];
                    assert!((0..3).all(|a| orient2d(c[a], c[(a + 1) % 3], p) >= 0.0));
                    seen[s as usize] += 1;
                }
            }
        }
        for (v, &s) in ot.samples.on_vertex.iter().enumerate().filter(|(_, &s)| s != EMPTY) {
            assert_eq!(ot.samples.pos[s as usize], ot.mesh.pos[v]);
            seen[s as usize] += 1;
        }
        assert!(seen.iter().all(|&k| k == 1));
    }

    #[test]
    fn the_stopping_rules() {
        let points = noisy_circle(200, 0.005);
        // No collapse: every sample stays on its vertex, no edge carries mass.
        let rec = run(&points, Stop::Steps(0));
        assert_eq!((rec.edges.len(), new_vertices(&rec).len()), (0, 200));
        assert_eq!(rec.status, Status::Curves);
        // A zero tolerance allows only free collapses, and there are none.
        assert_eq!(run(&points, Stop::Tolerance(0.0)).edges.len(), 0);
        // A tolerance of the circle's size allows every collapse that is left.
        let coarse = run(&points, Stop::Tolerance(10.0));
        assert!(new_vertices(&coarse).len() < 10, "{coarse:?}");
        let rec = run(&points, default_stop(200));
        assert!(new_vertices(&rec).len() <= 50);
        let dt = Triangulation::new(&points).unwrap();
        for bad in [-1.0, f64::NAN, f64::INFINITY] {
            assert!(optimal_transport_with(&dt, Stop::Tolerance(bad)).is_err());
        }
    }

    #[test]
    fn scaling_by_a_power_of_two_scales_the_result_exactly() {
        let points = noisy_circle(150, 0.01);
        let rec = run(&points, Stop::Vertices(20));
        let big: Vec<Point> = points.iter().map(|p| [p[0] * 1024.0, p[1] * 1024.0]).collect();
        let scaled = run(&big, Stop::Vertices(20));
        assert_eq!(scaled.edges, rec.edges);
        let expected: Vec<Point> =
            new_vertices(&rec).iter().map(|p| [p[0] * 1024.0, p[1] * 1024.0]).collect();
        assert_eq!(new_vertices(&scaled), expected.as_slice());
    }

    #[test]
    fn degenerate_input_gets_the_shared_result() {
        let rec = run(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]], default_stop(3));
        assert_eq!((rec.status, rec.vertices), (Status::Collinear, Vertices::Input));
    }
}
