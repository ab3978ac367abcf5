//! Inflating: make every boundary vertex manifold by turning exterior triangles interior.
//!
//! CONNECT2D [OM13] as used by SIG-CONNECT2D ([MOW22] §4.2.1, Algorithm 1, l. 11–15):
//! candidate triangles are exterior triangles incident to a non-manifold vertex through a
//! boundary edge; the one that least increases the total boundary length is taken (its new
//! edges added, edges that become interior removed) until no non-manifold vertex is left.
//!
//! Cost of a triangle `t` (the paper's rule, made exact in `docs/algorithms.md` §2.4): for
//! each edge, `+len` if it is not on the boundary (it becomes boundary), `−len` if it is on
//! the boundary with interior on the other side (it becomes interior), `0` if it is a
//! boundary edge with exterior on both sides (dangling). Interior edges are removed at once,
//! not at the end as in the paper's figure: the labels are the same, and the vertex tests
//! need the current boundary. Enclosed pockets become interior as they form
//! ([`pocket`](super::pocket)). Ties: lowest triangle number.
//!
//! # Guarantee
//! Terminates after at most `#triangles` steps (each turns one exterior triangle interior for
//! good) and cannot get stuck: a non-manifold vertex always has an exterior triangle beside
//! one of its boundary edges; in the worst case the result is the convex hull. Afterwards
//! the boundary is a set of vertex-disjoint simple polygons around disjoint disks, and every
//! vertex is manifold or interior.
//!
//! # Complexity
//! O(n log n) for Delaunay triangulations of bounded degree. A step pushes the triangles
//! beside the ones it turned interior and the stars of vertices whose class changed, and
//! reclassifies three vertices in O(1) each (the boundary keeps their star counts): a fan
//! around one vertex of degree `d` costs O(log n) a step, not O(d).
//!
//! # References
//! - [OM13] S. Ohrhallinger, S. Mudur. An efficient algorithm for determining an aesthetic
//!   shape connecting unorganised 2D points. CGF 32(8), 2013.
//! - [MOW22] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
//! [OM13]: https://doi.org/10.1111/cgf.12227
use super::boundary::{Boundary, VertexClass};
use super::pocket::fill_pocket;
use super::queue::CandidateQueue;
use super::trace::Phase;
use crate::delaunay::{next, prev, EMPTY};
use crate::graph::EdgeMask;
use crate::result::Stats;

/// Runs inflating to completion on the boundary of graph `g`, updating `stats`.
pub fn inflate(bd: &mut Boundary<'_>, g: &EdgeMask, stats: &mut Stats) {
    stats.non_manifold_before = bd.non_manifold;
    if bd.non_manifold == 0 {
        return;
    }
    bd.track_components(g);
    let mut queue = CandidateQueue::default();
    for v in 0..bd.dt.num_vertices() as u32 {
        if bd.class[v as usize] == VertexClass::NonManifold {
            push_around(bd, &mut queue, v);
        }
    }
    while bd.non_manifold > 0 {
        let Some(c) = queue.pop(bd.dt) else { break };
        let t = c.t;
        if bd.inside[t as usize] || !is_candidate(bd, t) || cost(bd, t) != c.cost {
            continue;
        }
        let (touched, filled) = accept(bd, t, stats);
        // A triangle's cost reads its own edges and the labels across them, so it changes
        // only beside a triangle that turned interior; its candidacy changes only there or
        // at a vertex whose class changed. Exactly those are pushed again (their entries
        // went stale); every other candidate keeps its valid entry. Pushing the whole star
        // of every touched vertex instead made a fan of degree n cost O(n) a step.
        for &v in &touched {
            let before = bd.class[v as usize];
            bd.reclassify(v);
            if bd.class[v as usize] != before {
                push_around(bd, &mut queue, v);
            }
        }
        for &f in &filled {
            for h in 3 * f..3 * f + 3 {
                let twin = bd.dt.twin(h);
                if twin != EMPTY {
                    push_if_candidate(bd, &mut queue, twin / 3);
                }
            }
        }
    }
    debug_assert_eq!(bd.non_manifold, 0, "inflating left non-manifold vertices");
    if cfg!(debug_assertions) {
        bd.check_classes();
    }
}

/// Exterior triangle with a boundary edge that has a non-manifold end.
fn is_candidate(bd: &Boundary<'_>, t: u32) -> bool {
    (3 * t..3 * t + 3).any(|h| {
        bd.edges.contains(h)
            && (bd.class[bd.dt.origin(h) as usize] == VertexClass::NonManifold
                || bd.class[bd.dt.dest(h) as usize] == VertexClass::NonManifold)
    })
}

/// Change of total boundary length if `t` turns interior (edges in a fixed order, from its
/// smallest vertex on, so the same triangle always gives the bit-identical cost wherever it
/// is stored).
fn cost(bd: &Boundary<'_>, t: u32) -> f64 {
    let dt = bd.dt;
    let first = (3 * t..3 * t + 3).min_by_key(|&h| dt.origin(h)).unwrap_or(3 * t);
    let mut delta = 0.0;
    for h in [first, next(first), prev(first)] {
        if !bd.edges.contains(h) {
            delta += bd.dt.length(h);
        } else if bd.right_is_in(h) {
            delta -= bd.dt.length(h);
        }
    }
    delta
}

fn push_around(bd: &Boundary<'_>, queue: &mut CandidateQueue, v: u32) {
    for h in bd.dt.outgoing(v) {
        push_if_candidate(bd, queue, h / 3);
    }
}

fn push_if_candidate(bd: &Boundary<'_>, queue: &mut CandidateQueue, t: u32) {
    if !bd.inside[t as usize] && is_candidate(bd, t) {
        queue.push(bd.dt, t, cost(bd, t));
    }
}

/// Turns `t` interior; returns the vertices whose star changed and the triangles that
/// turned interior (`t` and a filled pocket's).
fn accept(bd: &mut Boundary<'_>, t: u32, stats: &mut Stats) -> (Vec<u32>, Vec<u32>) {
    let dt = bd.dt;
    let on_boundary: Vec<u32> = (3 * t..3 * t + 3).filter(|&h| bd.edges.contains(h)).collect();
    // §2.5: a single boundary edge `ab` whose apex `c` is already connected to it means the
    // two new edges close a cycle around an exterior region.
    let closes_cycle = on_boundary.len() == 1 && {
        let ab = on_boundary[0];
        let c = dt.origin(prev(ab));
        bd.components.find(c) == bd.components.find(dt.origin(ab))
    };
    bd.set_inside(t, true, Phase::Inflate);
    for h in 3 * t..3 * t + 3 {
        if !bd.edges.contains(h) {
            bd.set_edge(h, true);
            bd.components.union(dt.origin(h), dt.dest(h));
        } else if bd.right_is_in(h) {
            bd.set_edge(h, false);
        }
    }
    stats.inflated_triangles += 1;
    let mut touched: Vec<u32> = (3 * t..3 * t + 3).map(|h| dt.origin(h)).collect();
    let mut filled = vec![t];
    if closes_cycle {
        let ab = on_boundary[0];
        let across = |h: u32| match dt.twin(h) {
            EMPTY => EMPTY,
            twin => twin / 3,
        };
        let pocket = fill_pocket(bd, across(next(ab)), across(prev(ab)));
        if !pocket.is_empty() {
            stats.pockets += 1;
            touched.extend(pocket.iter().flat_map(|&p| (3 * p..3 * p + 3).map(|h| dt.origin(h))));
            touched.sort_unstable();
            touched.dedup();
            filled.extend(pocket);
        }
    }
    (touched, filled)
}
