//! SIG-AUTO: SIG-CONNECT2D per component, with open curves kept open, outliers left out
//! and the reading smoothed where curves come closer than their spacing.
//!
//! SIG-CONNECT2D ([MOW22]) returns closed manifold polygons only; the paper names open and
//! multiple curves as future work. SIG-AUTO starts from the same graph, SIGDT2 (SIGDT with
//! leaf elimination). Its steps are numbered as in `docs/sig-auto.md` ("How it works"),
//! which gives each in full; the code is a pipeline of four stages, one room each:
//!
//! **The first reading** (`first_reading`), at the points' own scale, per connected
//! component of SIGDT2:
//! 1–3. the graph, each component's minimum spanning tree (`spanning_forests`), and a tree
//!    that is a path read as a *chain*, a piece of curve;
//! 4. a component whose tree branches inflated and sculpted on its own triangulation
//!    (`closed_component`), so nested curves stay separate, with its SIGDT pieces as
//!    chains (`spur_path`) where a loop would reach across;
//! 5. chains joined end to end and closed along Delaunay edges no longer than twice the
//!    longest edge of the chains they join (`chain_join`, after `u < 2` of [MOW22]
//!    Theorem 1); what stays open is an open path;
//! 6. outliers: tree branches and detours of the reading farther from the curve than its
//!    spacing (`outliers`), and isolated pieces (`isolated`), left out, and the rest read
//!    again (at most [`MAX_ROUNDS`] rounds);
//! 7. good continuation: 2-opt moves that lower the reading's turning (`continuation`);
//! 8. zigzag loops of a branching component given up for its spanning tree read as a path;
//! 9. CONNECT2D's polygon where it is shorter and turns less (`shorter_reading`);
//! 10. status `noisy` where the reading still zigzags.
//!
//! **The checked reading** (`checked_reading`):
//! 11. the sampling check (`crate::sampling_check`) reads the result back;
//! 12. where it doubles back through a far point, that point is cut out (`wired_outliers`);
//! 13. where its curves still break, the points are read again at two to four times their
//!     spacing and threaded along the first coarse reading that passes the check
//!     (`coarse_reading`): noise of up to a quarter of the spacing;
//! 14. points left out beside the curves are put back (`skipped_samples`).
//!
//! **Networks** (`network_reading`):
//! 15. where curves meet (cross, branch, share an end) and the reading breaks beside a
//!     junction (`junctions`), the straightest pairs of SIGDT edges replace it there.
//!     Points on such networks are known before the reading, so that step 6 leaves none
//!     of them out; a broken reading meets the networks before step 13.
//!
//! **Candidates** (`candidates`):
//! 16. where the result still breaks the sampling or leaves curves open, the polygons of
//!     SIG-CONNECT2D and CONNECT2D through the points it keeps are weighed against it by
//!     one measure (fewest breaks, then shortest), and the best is kept.
//!
//! Every stage ends in `finish` (the points left out listed, the status of what was read)
//! and the sampling check. Points left out are listed with the reason `outlier`; a result
//! whose loops pass through every point that is not left out is a `polygon` or `polygons`.
//!
//! # Guarantees
//! - The output is made of Delaunay edges, no two of which cross (of the points not left
//!   out as outliers, where a candidate polygon of step 16 replaces a reading that left
//!   some out). Without junctions (status other than `network`) it is a set of
//!   vertex-disjoint simple loops and simple open paths; a network's paths share only
//!   junctions.
//! - A closed curve sampled with ρ < 1 and u < 2 ([MOW22] Theorem 1): SIGDT contains its
//!   polygon; when that polygon is the component's spanning path plus one edge, the closing
//!   edge satisfies the join bound and the curve comes back closed.
//! - An open curve whose two end samples are more than twice the longest sample spacing
//!   apart is never closed by a join; when its SIGDT2 component's spanning tree is the
//!   sample path (dense sampling), it comes back as that path. A component that must be
//!   inflated (its tree branches beyond what small branches explain) can still come back
//!   closed, and the second reading (step 9) may merge a path with a loop beside it; it
//!   never closes a path on its own (the polygon that keeps all of a path's edges is the
//!   path plus its chord, not shorter than itself).
//! - Separate curves whose SIGDT2 components are separate (each curve sampled more densely
//!   than the gap between them) are reconstructed independently, nested or not.
//! - When the fallback applies (a loop of a component's own triangulation that is not a
//!   Delaunay edge of all points, which could cross another component), the reading is
//!   SIG-CONNECT2D's (before steps 6 and 7).
//! - A point is left out only by the outlier rule, which never applies to a point within
//!   the sample spacing of the curve through its neighbours: noisy samples stay in. A
//!   detour never holds most of its loop or path, so a curve is never left out in bulk.
//!
//! # Complexity
//! O(n log n) time per round, O(n) memory, on curve input.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
mod candidates;
mod chain_join;
mod checked_reading;
mod closed_component;
mod coarse_reading;
mod continuation;
mod facts;
mod finish;
mod first_reading;
mod isolated;
mod junctions;
mod network_reading;
mod outliers;
mod reading;
mod shorter_reading;
mod skipped_samples;
mod spanning_forests;
mod spur_path;
mod steps;
mod unchanged_components;
mod vertex_marks;
mod wired_outliers;

use crate::delaunay::{Shape, Triangulation};
use crate::proximity::nearest::nearest_vertex_distances;
use crate::result::{Reconstruction, Status};
use crate::Expect;
use checked_reading::{checked_reading, curves_fail, fails, with_skipped_samples};
use facts::Facts;
use finish::{finish, outlier_vertices, Kind};
use network_reading::{checked_network, network_reading};

#[doc(hidden)]
pub use chain_join::JOIN_RATIO;
#[doc(hidden)]
pub use steps::Steps;

/// The most rounds of outlier removal: later rounds still read their points, they only no
/// longer look for tree branches to leave out. A safety bound for adversarial input; on the
/// labelled data a reading takes at most 8 rounds, most take one or two
/// (`docs/reliability.md`, S2).
pub const MAX_ROUNDS: usize = 16;

/// Reconstructs `dt`'s points with SIG-AUTO (see the module docs), expecting nothing.
#[cfg(test)]
pub(crate) fn sig_auto_on(dt: &Triangulation) -> Reconstruction {
    sig_auto_with(dt, &Steps::default())
}

/// SIG-AUTO on `dt`'s points, told what they outline: with [`Expect::Areas`], step 16 reads
/// the polygons through the points it keeps wherever the result has open paths, and takes
/// one that closes them unless it breaks the sampling more often.
pub(crate) fn sig_auto_expecting(dt: &Triangulation, expect: Expect) -> Reconstruction {
    read_all(dt, &Steps::default(), expect == Expect::Areas)
}

/// SIG-AUTO with some of its steps switched off or another gap ratio ([`Steps`]). Not a
/// user parameter: it exists so that each step can be measured
/// (`sigdt-lab/examples/sig_auto_ablation.rs`, `sigdt-lab/examples/join_ratio_sweep.rs`).
///
/// The result carries the sampling check's findings ([`Reconstruction::diagnosis`]). Where
/// the reading doubles back, the point it went out to is left out (`wired_outliers`). When
/// the check still finds something, or sculpting got stuck, the points are read again at a
/// coarser scale and then through every point (`coarse_reading`); that reading replaces the
/// first when it passes the check.
#[doc(hidden)]
pub fn sig_auto_with(dt: &Triangulation, steps: &Steps) -> Reconstruction {
    read_all(dt, steps, false)
}

/// The pipeline: the stages of the module docs in turn (`areas`: [`Expect::Areas`]).
fn read_all(dt: &Triangulation, steps: &Steps, areas: bool) -> Reconstruction {
    // Every vertex's nearest-neighbour distance, shared by every stage.
    let spacing = (dt.shape() == Shape::Proper).then(|| nearest_vertex_distances(dt));
    let facts = Facts { areas, ..Facts::new(dt, steps, spacing.as_deref()) };
    let rec = checked_reading(&facts);
    if rec.status == Status::Network {
        return rec;
    }
    let rec = match steps.skipped_samples {
        true => with_skipped_samples(&facts, rec),
        false => rec,
    };
    let rec = network_reading(&facts, &rec).unwrap_or(rec);
    match steps.candidates {
        true => candidates::best_reading(&facts, rec),
        false => rec,
    }
}

/// Steps 1–12 and 14 on `dt`: the reading at the points' own scale, checked and mended,
/// with no other scale, networks or candidates. The coarse reading (step 13) reads its
/// thinned points with it.
fn own_scale_reading(dt: &Triangulation, steps: &Steps) -> Reconstruction {
    let steps = Steps { coarse: false, junctions: false, candidates: false, ..*steps };
    let spacing = (dt.shape() == Shape::Proper).then(|| nearest_vertex_distances(dt));
    let facts = Facts::new(dt, &steps, spacing.as_deref());
    let rec = checked_reading(&facts);
    match steps.skipped_samples {
        true => with_skipped_samples(&facts, rec),
        false => rec,
    }
}

#[cfg(test)]
mod tests;
