//! Junction networks as the reading (step 15 of `docs/sig-auto.md`): where curves meet
//! and the reading breaks beside a junction, the straightest pairs of SIGDT edges replace
//! it there, when the sampling check finds them unbroken.
use super::continuation::MAX_SAMPLED_TURN;
use super::junctions;
use super::reading::{self, Reading};
use super::{curves_fail, finish, outlier_vertices, Facts, Kind};
use crate::delaunay::Shape;
use crate::geometry::Point;
use crate::result::{Reconstruction, Stats, Status, Vertices};

/// `rec` with the pair graph in place of its reading on the components whose branching
/// vertices are all junctions and where the reading breaks beside one (`junctions`),
/// checked again; `None` when there is none, when a reading edge joins such a component to
/// a point outside it, when `rec` is `noisy`, when points it left inside lie outside the
/// networks, or when the sampling check finds the network broken.
pub(super) fn network_reading(facts: &Facts, rec: &Reconstruction) -> Option<Reconstruction> {
    let (dt, networks) = (facts.dt, facts.networks.as_ref()?);
    // Where the reading zigzags like noise, pairs of edges run straight by chance.
    if dt.shape() != Shape::Proper || rec.vertices != Vertices::Input || rec.status == Status::Noisy
    {
        return None;
    }
    let vertex_of = dt.vertex_of_inputs();
    let cos_limit = MAX_SAMPLED_TURN.cos();
    // Where the reading breaks nowhere, no network can replace it: the pair graph is not
    // built (most curves). Loops through every point break only where they turn sharply,
    // which their own vertices tell, without a reading of every vertex.
    let n = dt.num_vertices();
    let at = |i: usize| dt.point(vertex_of[i]);
    let on_loops: usize = rec.loops.iter().map(Vec::len).sum();
    if rec.paths.is_empty()
        && on_loops == n
        && !rec.loops.iter().any(|l| loop_turns_more_than(at, l, cos_limit))
    {
        return None;
    }
    let read_pairs: Vec<[u32; 2]> =
        rec.edges.iter().map(|&[i, j]| [vertex_of[i], vertex_of[j]]).collect();
    let reading = Reading::new(dt, &read_pairs);
    let breaks = |v: u32| reading.degree(v) != 2 || reading.turns_more_than(v, cos_limit);
    if !(0..n as u32).any(breaks) {
        return None;
    }
    let (pairs, found) = networks.get();
    if found.is_empty() {
        return None;
    }
    let network = junctions::network_vertices(pairs, n, found, breaks);
    let inside = |v: u32| network[v as usize];
    if !network.contains(&true) || read_pairs.iter().any(|&[a, b]| inside(a) != inside(b)) {
        return None;
    }
    // Points left inside a stuck reading are read by the network, or the result stays stuck.
    if let Status::SculptingStuck { left_out } = &rec.status {
        if !left_out.iter().all(|&i| inside(vertex_of[i])) {
            return None;
        }
    }
    let mut network: Vec<[u32; 2]> = read_pairs.into_iter().filter(|&[a, _]| !inside(a)).collect();
    for v in (0..n as u32).filter(|&v| inside(v)) {
        network.extend(pairs.edges_at(v));
    }
    let outliers: Vec<u32> =
        outlier_vertices(rec, &vertex_of).into_iter().filter(|&v| !inside(v)).collect();
    checked_network(facts, network, &outliers, rec.stats)
}

/// The result whose edges are `pairs`, a network read from `networks`' junctions, with
/// `outliers` left out, unless the sampling check finds it broken (it doubles back, or its
/// edges reach over points): then it is no better read than the curves were.
pub(super) fn checked_network(
    facts: &Facts,
    pairs: Vec<[u32; 2]>,
    outliers: &[u32],
    stats: Stats,
) -> Option<Reconstruction> {
    let rec = finish(facts, pairs, Vec::new(), outliers, stats, Kind::Network);
    (!curves_fail(&rec.diagnosis)).then_some(rec)
}

/// Whether the closed loop `ring` (input indices; `at` their points) turns anywhere by more
/// than the angle whose cosine is `cos_limit`.
fn loop_turns_more_than(at: impl Fn(usize) -> Point, ring: &[usize], cos_limit: f64) -> bool {
    let k = ring.len();
    (0..k).any(|j| {
        let (p, q, r) = (at(ring[(j + k - 1) % k]), at(ring[j]), at(ring[(j + 1) % k]));
        reading::turns_more_than(p, q, r, cos_limit)
    })
}
