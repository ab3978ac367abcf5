//! SIG-AUTO's first reading of the points at their own scale (steps 1–10 of
//! `docs/sig-auto.md`): rounds of outliers left out and the rest read again, chains joined,
//! branching components inflated and sculpted on their own, detours cut, good continuation
//! and the second reading.
use super::chain_join::Chains;
use super::closed_component::closed_component;
use super::continuation::{self, MAX_SAMPLED_TURN};
use super::junctions::Networks;
use super::reading::Reading;
use super::spanning_forests::Forests;
use super::unchanged_components::UnchangedComponents;
use super::{
    checked_network, finish, isolated, outliers, shorter_reading, Facts, Kind, Steps, MAX_ROUNDS,
};
use crate::delaunay::Triangulation;
use crate::geometry::distance;
use crate::proximity::nearest::nearest_vertex_distances;
use crate::proximity::sigdt::TIE_SLACK;
use crate::result::{degenerate_result, Reconstruction, Stats};
use crate::sig_connect2d::sig_connect2d_on;
use std::borrow::Cow;

/// SIG-AUTO's reading of `facts.dt` at the points' own scale (steps 1–10 of the module
/// docs), checked.
pub(super) fn read(facts: &Facts) -> Reconstruction {
    let (dt, steps, spacing, networks) =
        (facts.dt, facts.steps, facts.spacing, facts.networks.as_ref());
    if let Some(result) = degenerate_result(dt) {
        return result;
    }
    // Vertices of `dt` still read, and those left out as outliers so far.
    // (`None`: every vertex, until the first round leaves some out.)
    let mut kept: Option<Vec<u32>> = None;
    let n = dt.num_vertices() as u32;
    let mut outliers: Vec<u32> = Vec::new();
    // The last round's reading with its detours cut out and their ends joined (vertices of
    // `dt`), kept in case reading the rest again gets stuck where it did not.
    let mut relinked: Option<(Vec<[u32; 2]>, Stats)> = None;
    // The isolated pieces left out in the first round (`isolated`), vertices of `dt`.
    let mut isolated: Vec<Vec<u32>> = Vec::new();
    // The vertices of `dt` on networks' curves (`Networks::candidates`), asked for once a
    // spanning tree branches: no branch through them is an outlier.
    let mut on_networks: Option<Vec<bool>> = None;
    // The last round's components, when it read their branches and was not the first.
    let mut settled: Option<UnchangedComponents> = None;
    for round in 0..MAX_ROUNDS {
        let subset;
        let sub = if round == 0 {
            dt
        } else {
            let kept = kept.as_deref().unwrap_or_default();
            let points: Vec<_> = kept.iter().map(|&v| dt.point(v)).collect();
            match Triangulation::new(&points) {
                Ok(t) => subset = t,
                Err(_) => break, // unreachable: the points were valid in `dt`
            }
            &subset
        };
        // Vertex of `sub` -> vertex of `dt` (the same in the first round).
        let whole = |v: u32| match &kept {
            Some(kept) if round > 0 => kept[sub.input_index(v)],
            _ => v,
        };
        let read = match degenerate_result(sub) {
            Some(line) => {
                settled = None;
                Read { pairs: sub.line_edges().collect(), inside: Vec::new(), stats: line.stats }
            }
            None => {
                let spacing = match (round, spacing) {
                    (0, Some(spacing)) => Cow::Borrowed(spacing),
                    _ => Cow::Owned(nearest_vertex_distances(sub)),
                };
                if round == 0 && steps.isolated {
                    isolated = isolated::isolated_pieces(dt, &spacing);
                }
                // Isolated pieces are left out first; the forests are built only without them.
                let (found, forests) = if round == 0 && !isolated.is_empty() {
                    settled = None;
                    (isolated.concat(), None)
                } else {
                    let forests = Forests::new(sub, &spacing);
                    let far_off = round + 1 < MAX_ROUNDS && steps.branch_outliers;
                    let branched = forests.components().iter().any(|&(_, branched)| branched);
                    if let (true, Some(networks)) = (far_off && branched, networks) {
                        let on = on_networks.get_or_insert_with(|| networks.candidates());
                        if round == 0 && on.iter().all(|&on| on) {
                            // Every point is on a network's curves: that is the reading.
                            let stats = Stats {
                                graph_edges: forests.graph.len(),
                                leaf_edges_added: forests.leaf_edges_added,
                                ..Stats::default()
                            };
                            match whole_network(facts, networks, stats) {
                                Some(network) => return network,
                                None => on_networks = None,
                            }
                        }
                    }
                    let curve =
                        |v: u32| on_networks.as_ref().is_some_and(|on| on[whole(v) as usize]);
                    let unchanged = |vertices: &[u32]| {
                        settled
                            .as_ref()
                            .is_some_and(|s| s.unchanged(vertices.iter().map(|&v| whole(v))))
                    };
                    let found = match far_off {
                        true => branches_far_off(sub, &forests, curve, unchanged, steps),
                        false => Vec::new(),
                    };
                    // Rounds after the first break ties alike, so the next can skip what
                    // this one read unchanged.
                    settled = (far_off && round > 0).then(|| {
                        let components = forests.components().iter().map(|(c, _)| c.as_slice());
                        UnchangedComponents::new(dt.num_vertices(), components, whole)
                    });
                    (found, Some(forests))
                };
                match forests {
                    Some(forests) if found.is_empty() => read_components(sub, &forests, steps),
                    _ => {
                        relinked = None;
                        if let Some(settled) = settled.as_mut() {
                            settled.leave_out(sub, &found, whole);
                        }
                        let gone: Vec<u32> = found.iter().map(|&v| whole(v)).collect();
                        outliers.extend(&gone);
                        let gone: std::collections::HashSet<u32> = gone.into_iter().collect();
                        kept.get_or_insert_with(|| (0..n).collect()).retain(|v| !gone.contains(v));
                        continue;
                    }
                }
            }
        };
        let read = match relinked.take() {
            Some((pairs, stats)) if !read.inside.is_empty() => {
                let mut vertex_of = vec![u32::MAX; dt.num_vertices()];
                for v in 0..sub.num_vertices() as u32 {
                    vertex_of[whole(v) as usize] = v;
                }
                let pairs =
                    pairs.iter().map(|&[a, b]| [vertex_of[a as usize], vertex_of[b as usize]]);
                Read { pairs: pairs.collect(), inside: Vec::new(), stats }
            }
            _ => read,
        };
        let mut reading = Reading::new(sub, &read.pairs);
        let cut: Vec<u32> = match steps.detours {
            true => {
                let curve = |v: u32| on_networks.as_ref().is_some_and(|on| on[whole(v) as usize]);
                let cut = outliers::detour_outliers(&mut reading, curve, steps);
                if let Some(settled) = settled.as_mut() {
                    settled.leave_out(sub, &cut, whole);
                }
                cut.into_iter().map(whole).collect()
            }
            false => Vec::new(),
        };
        if !cut.is_empty() && round + 1 < MAX_ROUNDS {
            // Read the rest again: without the detours, the components are cleaner.
            if read.inside.is_empty() {
                let pairs = reading.pairs().into_iter().map(|[a, b]| [whole(a), whole(b)]);
                relinked = Some((pairs.collect(), read.stats));
            }
            let gone: std::collections::HashSet<u32> = cut.iter().copied().collect();
            kept.get_or_insert_with(|| (0..n).collect()).retain(|v| !gone.contains(v));
            outliers.extend(cut);
            continue;
        }
        outliers.extend(cut);
        if steps.continuation {
            continuation::continue_smoothly(&mut reading);
        }
        if steps.shorter_reading && read.inside.is_empty() {
            shorter_reading::prefer_shorter_reading(&mut reading);
        }
        let zigzags = reading.zigzags(MAX_SAMPLED_TURN.cos());
        let mut pairs: Vec<[u32; 2]> =
            reading.pairs().into_iter().map(|[a, b]| [whole(a), whole(b)]).collect();
        // Freed before the result is built: its peak is SIG-AUTO's.
        drop(reading);
        let Read { pairs: read_pairs, inside, stats } = read;
        drop(read_pairs);
        let back = isolated::put_back(dt, &mut pairs, &isolated);
        outliers.retain(|v| back.binary_search(v).is_err());
        let inside: Vec<usize> = inside.iter().map(|&v| dt.input_index(whole(v))).collect();
        let kind = if zigzags { Kind::Zigzags { open_too: true } } else { Kind::Curves };
        return finish(facts, pairs, inside, &outliers, stats, kind);
    }
    unreachable!("the last round always reads its points")
}

/// The pair graph as the reading of every point (when they are all on networks' curves),
/// unless the sampling check finds it broken.
fn whole_network(facts: &Facts, networks: &Networks, stats: Stats) -> Option<Reconstruction> {
    let (pairs, _) = networks.get();
    let n = facts.dt.num_vertices() as u32;
    let edges = (0..n).flat_map(|v| pairs.edges_at(v)).collect();
    checked_network(facts, edges, &[], stats)
}

/// What reading the components of one round gave, in the vertex numbers of its
/// triangulation.
struct Read {
    pairs: Vec<[u32; 2]>,
    /// Points left inside where sculpting got stuck.
    inside: Vec<u32>,
    stats: Stats,
}

/// The branches of every component's SIGDT2 spanning tree that are outliers.
///
/// Components that `unchanged` says the last round read as they are are skipped: it found
/// no outlier in them (`unchanged_components`).
fn branches_far_off(
    dt: &Triangulation,
    forests: &Forests,
    curve: impl Fn(u32) -> bool + Copy,
    unchanged: impl Fn(&[u32]) -> bool,
    steps: &Steps,
) -> Vec<u32> {
    let tree = &forests.sigdt2;
    let mut found = Vec::new();
    let mut scratch = None;
    for (vertices, branched) in forests.components() {
        if unchanged(vertices) {
            continue;
        }
        if *branched {
            let scratch = scratch.get_or_insert_with(|| outliers::BranchScratch::new(dt));
            found.extend(outliers::branch_outliers(dt, vertices, tree, curve, steps, scratch));
        } else {
            found.extend(outliers::chain_end_outliers(dt, &tree.walk(vertices), steps));
        }
    }
    found
}

/// Steps 2–5 of the module docs on every component of `dt`.
fn read_components(dt: &Triangulation, forests: &Forests, steps: &Steps) -> Read {
    let join_ratio = steps.join_ratio;
    let (graph, sigdt, tree) = (&forests.graph, forests.sigdt(), &forests.sigdt2);
    let mut stats = Stats {
        graph_edges: graph.len(),
        leaf_edges_added: forests.leaf_edges_added,
        ..Stats::default()
    };
    // About one edge a point: reserved, not grown by doubling at SIG-AUTO's peak.
    let mut pairs: Vec<[u32; 2]> = Vec::with_capacity(dt.num_vertices());
    let mut inside: Vec<u32> = Vec::new();
    let mut chains = Chains::new(dt, join_ratio);
    // Made for the first branching component: curves that chain alone never need it.
    let mut scratch: Option<Scratch> = None;
    for (vertices, branched) in forests.components() {
        if !*branched {
            let path = tree.walk(vertices);
            pairs.extend(path.windows(2).map(|w| [w[0], w[1]]));
            chains.add(&path);
            continue;
        }
        let Some(closed) = closed_component(dt, graph, vertices, join_ratio) else {
            return fallback(dt);
        };
        let bound = join_ratio * sigdt.longest_edge(dt, vertices) * (1.0 + TIE_SLACK);
        let within = |&[a, b]: &[u32; 2]| distance(dt.point(a), dt.point(b)) <= bound;
        // Loops that zigzag are no curve's polygon (no sampled curve zigzags, corners
        // included): the component's own spanning tree, read as a path, replaces them when
        // it does not zigzag (an open curve whose samples come closer across a bend than
        // along it). Loops with an edge beyond the join bound give way to the SIGDT pieces.
        let mut paths = None;
        let scratch = scratch.get_or_insert_with(|| Scratch(Reading::new(dt, &[])));
        if steps.zigzag_paths && scratch.zigzags(&closed.edges) {
            paths = tree.pieces_as_paths(dt, vertices).filter(|p| !scratch.zigzags(&path_pairs(p)));
        }
        if paths.is_none() && !closed.edges.iter().all(within) {
            paths = sigdt.pieces_as_paths(dt, vertices);
        }
        if let Some(paths) = paths {
            pairs.extend(path_pairs(&paths));
            paths.iter().for_each(|path| chains.add(path));
            continue;
        }
        pairs.extend(closed.edges);
        inside.extend(closed.left_out);
        add_counts(&mut stats, &closed.stats);
    }
    pairs.extend(chains.join());
    Read { pairs, inside, stats }
}

/// One empty reading of the whole triangulation, to test a component's edges for zigzags
/// in time proportional to the component, not to all the points.
struct Scratch<'a>(Reading<'a>);

impl Scratch<'_> {
    /// Whether the edges `pairs` zigzag (the test of the `noisy` status).
    fn zigzags(&mut self, pairs: &[[u32; 2]]) -> bool {
        self.0.link(pairs);
        let zigzags = self.0.zigzags_at(pairs.iter().flatten().copied(), MAX_SAMPLED_TURN.cos());
        pairs.iter().flatten().for_each(|&v| self.0.detach(v));
        zigzags
    }
}

/// The edges of `paths`.
fn path_pairs(paths: &[Vec<u32>]) -> Vec<[u32; 2]> {
    paths.iter().flat_map(|path| path.windows(2).map(|w| [w[0], w[1]])).collect()
}

/// SIG-CONNECT2D's reading of `dt`, for when a component's own loops could cross another
/// component.
fn fallback(dt: &Triangulation) -> Read {
    let rec = sig_connect2d_on(dt, true);
    let vertex_of = dt.vertex_of_inputs();
    let to_vertex = |i: usize| vertex_of[i];
    let inside = rec.left_out.iter().map(|l| to_vertex(l.index)).collect();
    let pairs = rec.edges.iter().map(|&[i, j]| [to_vertex(i), to_vertex(j)]).collect();
    Read { pairs, inside, stats: rec.stats }
}

/// Adds the inflating and sculpting counts of one component to `total`.
fn add_counts(total: &mut Stats, part: &Stats) {
    total.non_manifold_before += part.non_manifold_before;
    total.inflated_triangles += part.inflated_triangles;
    total.pockets += part.pockets;
    total.interior_before_sculpting += part.interior_before_sculpting;
    total.sculpted_triangles += part.sculpted_triangles;
}
