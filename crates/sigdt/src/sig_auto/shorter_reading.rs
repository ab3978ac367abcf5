//! A second reading, CONNECT2D's closed polygon, taken when it is better by both measures
//! of a curve reading: shorter and turning less.
//!
//! SIG-AUTO reads from SIGDT2 ([MOW22]), which holds the polygon of a closed curve sampled
//! with ρ < 1 and u < 2. Polygon outlines given by their vertices (map outlines, census
//! tracts: `data/real`'s `_k` cases) break u < 2 at almost every vertex, and SIGDT2 then
//! misreads some of them. CONNECT2D ([OM13]) starts from BC₀, an approximation of the
//! shortest boundary through every point, and follows such outlines where SIGDT2 does not.
//! Neither start is right everywhere, so CONNECT2D's polygon of the same points is a
//! candidate whenever SIG-AUTO's reading leaves no point on its own. Open paths count as
//! closed by the chord between their ends, and the polygon must keep every edge of them: it
//! may close a path by merging it with another path or a loop (a knot of three noisy samples
//! read as a triangle beside the rest of its curve), never re-route it. It replaces the
//! reading only when it is
//!
//! - **shorter**: the polygon of a densely sampled closed curve is the shortest closed tour
//!   through its samples ([Gie99], [AM00]), and
//! - **turns less** in total: the good-continuation measure that step 7
//!   ([`continuation`](super::continuation)) lowers.
//!
//! The second reading is sought only when some vertex of the first turns by more than 60°,
//! which no sample of a curve with ε < 1 does ([`MAX_SAMPLED_TURN`]): a reading that turns
//! less everywhere already looks like a sampled curve, and skipping it keeps SIG-AUTO's time
//! on smooth input close to SIG-CONNECT2D's.
//!
//! Requiring both, instead of weighing one against the other, leaves no constant to choose.
//! Either alone is wrong somewhere: at a sparsely sampled sharp corner the shortest tour cuts
//! the corner off and comes back for it, which turns more; and two separate islands read as
//! one polygon turn less but are longer by the two bridges. Ties (within [`TIE_SLACK`]) keep
//! SIGDT2's reading.
//!
//! # Complexity
//! O(k) to check the turns; O(k log k) for the `k` points read (a minimum spanning tree and
//! one more inflate-and-sculpt) only when the reading has a turn over 60° or several open
//! curves (one open path through every point is never replaced, so it is not tried).
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
//! [OM13]: https://doi.org/10.1111/cgf.12227
//! [Gie99]: https://doi.org/10.1145/304893.304971
//! [AM00]: https://doi.org/10.1145/336154.336185
use super::continuation::MAX_SAMPLED_TURN;
use super::reading::Reading;
use crate::baselines::connect2d::connect2d_on;
use crate::proximity::sigdt::TIE_SLACK;
use crate::result::Status;

/// Replaces `reading` by CONNECT2D's polygon of the same points when every vertex is on a
/// loop or path, the polygon keeps every path edge, and it is both shorter and turns less in
/// total than the reading with each path closed by the chord between its ends.
pub(crate) fn prefer_shorter_reading(reading: &mut Reading<'_>) {
    let dt = reading.dt;
    let vertices = 0..dt.num_vertices() as u32;
    if vertices.clone().any(|v| reading.degree(v) == 0) {
        return;
    }
    // With open paths the chords closing them turn sharply, so only loops alone can look
    // like a sampled curve everywhere.
    let paths = reading.open_paths();
    if paths.len() == 1 && paths[0].len() == dt.num_vertices() {
        // One path through every point: the only polygon that keeps all its edges is the
        // path plus its chord, which is not shorter than itself.
        return;
    }
    let cos_limit = MAX_SAMPLED_TURN.cos();
    if paths.is_empty() && !vertices.clone().any(|v| reading.turns_more_than(v, cos_limit)) {
        return;
    }
    let polygon = connect2d_on(dt);
    if polygon.status != Status::Polygon {
        return;
    }
    let vertex_of = dt.vertex_of_inputs();
    let pairs: Vec<[u32; 2]> =
        polygon.edges.iter().map(|&[i, j]| [vertex_of[i], vertex_of[j]]).collect();
    let other = Reading::new(dt, &pairs);
    // Open paths are closed, never re-routed: the polygon keeps every edge of them.
    let keeps_paths = paths.iter().all(|p| p.windows(2).all(|w| other.joined(w[0], w[1])));
    if !keeps_paths {
        return;
    }
    // Open paths count as closed by the chord between their ends.
    let mut pairs = reading.pairs();
    pairs.extend(paths.iter().map(|p| [p[0], p[p.len() - 1]]));
    let ours = Reading::new(dt, &pairs);
    let better = |ours: f64, theirs: f64| theirs < ours * (1.0 - TIE_SLACK);
    if better(ours.total_length(), other.total_length())
        && better(ours.total_turning(), other.total_turning())
    {
        *reading = other;
    }
}
