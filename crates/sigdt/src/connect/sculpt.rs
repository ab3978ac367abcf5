//! Sculpting: bring every interior vertex onto the boundary.
//!
//! CONNECT2D [OM13] as used by SIG-CONNECT2D ([MOW22] §4.2.2, Algorithm 1, l. 16–20):
//! a candidate is an interior triangle `abc` with exactly one boundary edge `ab` whose apex
//! `c` is an interior vertex. Taking it "XORs the triangle's edges with the boundary": `ab`
//! leaves, `ac` and `bc` join, the triangle becomes exterior and `c` lies on the boundary.
//! Candidates are taken in ascending order of the boundary-length increase
//! `|ac| + |bc| − |ab|`, ties by lowest triangle number.
//!
//! # Guarantee
//! Every step keeps the boundary a set of disjoint simple polygons and puts exactly one more
//! vertex on it. Triangles with two boundary edges are never taken (that would drop a vertex
//! from the boundary). Sculpting can get stuck with interior vertices left when no candidate
//! remains; [MOW22]: it "fails if the DT does not contain a Hamiltonian cycle" (and the
//! greedy order can miss one that exists). No fallback is invented: the result reports the
//! vertices left out.
//!
//! # Complexity
//! O(n log n).
//!
//! # References
//! - [OM13] S. Ohrhallinger, S. Mudur. An efficient algorithm for determining an aesthetic
//!   shape connecting unorganised 2D points. CGF 32(8), 2013.
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [OM13]: https://doi.org/10.1111/cgf.12227
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use super::boundary::{Boundary, VertexClass};
use super::queue::{Candidate, CandidateQueue};
use super::trace::Phase;
use crate::delaunay::{next, prev, EMPTY};
use crate::result::Stats;

/// Runs sculpting until no interior vertex is left or no candidate remains.
pub fn sculpt(bd: &mut Boundary<'_>, stats: &mut Stats) {
    stats.interior_before_sculpting = bd.interior;
    // Every candidate once, in one heap built in linear time: a candidate has one boundary
    // edge, so there are at most as many as boundary edges. (Pushing the triangles around
    // each interior vertex pushed most of them three times, and the queue was the largest
    // array alive.) The order of the pops is that of (cost, triangle), whatever the order of
    // the pushes.
    let mut initial = Vec::with_capacity(bd.edges.len());
    if bd.interior > 0 {
        initial.extend(
            (0..bd.dt.num_triangles() as u32)
                .filter_map(|t| candidate(bd, t).map(|(_, cost)| Candidate { cost, t })),
        );
    }
    let mut queue = CandidateQueue::new(bd.dt, initial);
    while bd.interior > 0 {
        let Some(c) = queue.pop(bd.dt) else { break };
        let t = c.t;
        let Some((ab, cost)) = candidate(bd, t) else { continue };
        if cost != c.cost {
            continue;
        }
        let dt = bd.dt;
        bd.set_inside(t, false, Phase::Sculpt);
        bd.set_edge(ab, false);
        bd.set_edge(next(ab), true);
        bd.set_edge(prev(ab), true);
        stats.sculpted_triangles += 1;
        for h in [ab, next(ab), prev(ab)] {
            bd.reclassify(dt.origin(h));
        }
        for h in [next(ab), prev(ab)] {
            if dt.twin(h) != EMPTY {
                push_if_candidate(bd, &mut queue, dt.twin(h) / 3);
            }
        }
    }
    if cfg!(debug_assertions) {
        bd.check_classes();
    }
}

/// For an interior triangle with exactly one boundary edge `ab` and an interior apex: that
/// half-edge and the cost `|ac| + |bc| − |ab|`.
fn candidate(bd: &Boundary<'_>, t: u32) -> Option<(u32, f64)> {
    if !bd.inside[t as usize] {
        return None;
    }
    let mut on_boundary = (3 * t..3 * t + 3).filter(|&h| bd.edges.contains(h));
    let ab = on_boundary.next()?;
    if on_boundary.next().is_some() {
        return None;
    }
    let apex = bd.dt.origin(prev(ab));
    if bd.class[apex as usize] != VertexClass::Interior {
        return None;
    }
    let dt = bd.dt;
    Some((ab, dt.length(next(ab)) + dt.length(prev(ab)) - dt.length(ab)))
}

fn push_if_candidate(bd: &Boundary<'_>, queue: &mut CandidateQueue, t: u32) {
    if let Some((_, cost)) = candidate(bd, t) {
        queue.push(bd.dt, t, cost);
    }
}
