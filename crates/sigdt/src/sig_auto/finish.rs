//! A reading, given as vertex pairs of the triangulation, turned into SIG-AUTO's result:
//! the points left out listed, and the status of what was read. Every stage of SIG-AUTO
//! ends here, so that the status is set in this one place.
use super::Facts;
use crate::result::{
    from_vertex_pairs, inside_left_out, LeftOut, LeftOutReason, Reconstruction, Stats, Status,
};
use crate::sampling_check::diagnose_with;

/// The outliers `rec` left out, as vertices of its triangulation (`vertex_of` maps input
/// indices to them).
pub(super) fn outlier_vertices(rec: &Reconstruction, vertex_of: &[u32]) -> Vec<u32> {
    let outliers = rec.left_out.iter().filter(|l| l.reason == LeftOutReason::Outlier);
    outliers.map(|l| vertex_of[l.index]).collect()
}

/// What a reading is, beyond what its edges show; its status follows from both ([`finish`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// Curves read through the points.
    Curves,
    /// Curves whose edges zigzag somewhere (the test of step 10, which no sampled curve
    /// fails): a polygon or polygons are `noisy`, and with `open_too` curves with open paths
    /// too. A result stuck in sculpting stays `sculpting-stuck`.
    Zigzags { open_too: bool },
    /// A network read at its junctions (step 15): where it branches it is a `network`,
    /// not a `branching` graph.
    Network,
}

/// The result of the reading `pairs` (vertices of `facts.dt`) of kind `kind`, with the
/// points left inside by sculpting (`inside`, input indices) and the outliers (vertices)
/// left out, and the sampling check's findings on it.
pub(super) fn finish(
    facts: &Facts,
    pairs: Vec<[u32; 2]>,
    mut inside: Vec<usize>,
    outliers: &[u32],
    stats: Stats,
    kind: Kind,
) -> Reconstruction {
    let dt = facts.dt;
    let mut rec = from_vertex_pairs(dt, pairs, stats);
    inside.sort_unstable();
    rec.left_out = inside_left_out(&inside);
    rec.left_out.extend(
        outliers
            .iter()
            .map(|&v| LeftOut { index: dt.input_index(v), reason: LeftOutReason::Outlier }),
    );
    rec.left_out.sort_unstable();
    if !inside.is_empty() {
        rec.status = Status::SculptingStuck { left_out: inside };
    } else if rec.status == Status::Curves && rec.paths.is_empty() && !rec.loops.is_empty() {
        // Every point that is not an outlier is on a loop.
        let on_loops: usize = rec.loops.iter().map(Vec::len).sum();
        if on_loops + outliers.len() == dt.num_vertices() {
            rec.status = if rec.loops.len() == 1 { Status::Polygon } else { Status::Polygons };
        }
    }
    match kind {
        Kind::Zigzags { open_too }
            if rec.status.is_manifold() || (open_too && rec.status == Status::Curves) =>
        {
            rec.status = Status::Noisy;
        }
        Kind::Network if rec.status == Status::Branching => rec.status = Status::Network,
        _ => {}
    }
    rec.diagnosis = diagnose_with(dt, &rec, facts.check_spacing());
    rec
}
