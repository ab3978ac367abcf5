//! Which of SIG-AUTO's steps run. The method runs all of them with the ratio 2; the
//! switches exist so that what each step buys can be measured
//! (`sigdt-lab/examples/sig_auto_ablation.rs`, `docs/sig-auto.md`). None is a user
//! parameter.
use super::chain_join::JOIN_RATIO;

/// SIG-AUTO's steps, each on or off, and the gap ratio. [`Default`] is the method.
#[doc(hidden)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steps {
    /// The ratio in place of [`JOIN_RATIO`] in all three places it bounds a gap: chain
    /// joins, loop cutting and the leaf-edge check.
    pub join_ratio: f64,
    /// Leave out spanning-tree branches far from the main path (step 6).
    pub branch_outliers: bool,
    /// Leave out small groups of points sampled far more sparsely than a curve beside them,
    /// unless the reading runs straight past them (`isolated`, step 6).
    pub isolated: bool,
    /// Replace the reading by CONNECT2D's polygon when that keeps the open paths' edges and
    /// is both shorter and turns less (`shorter_reading`, step 9).
    pub shorter_reading: bool,
    /// Read a branching component as its spanning tree's path when its loops zigzag (step 8).
    pub zigzag_paths: bool,
    /// Cut detours out of the reading (step 6).
    pub detours: bool,
    /// Good continuation: turning-lowering 2-opt moves (step 7).
    pub continuation: bool,
    /// The outlier rules measure the distance to the curve's straight continuations too,
    /// not only to its segments (what keeps sharp corners in).
    pub tangent_rays: bool,
    /// The outlier rules keep three or more points closer to one another than to the curve
    /// (a curve of their own).
    pub own_curves: bool,
    /// When the reading warns, read the points again at a coarser scale and then through
    /// every point (`coarse_reading`, step 13).
    pub coarse: bool,
    /// Leave out the points where the reading doubles back (`wired_outliers`, step 12).
    pub wired_outliers: bool,
    /// Put back the outliers that lie within the sampling of the result's curves
    /// (`skipped_samples`, step 14).
    pub skipped_samples: bool,
    /// Read junctions where the reading breaks and straight pairs of SIGDT edges meet
    /// (`junctions`, step 15).
    pub junctions: bool,
    /// Where the checked reading breaks the sampling or leaves curves open, weigh it against
    /// the polygons of SIG-CONNECT2D and CONNECT2D by one measure (`candidates`, step 16).
    pub candidates: bool,
}

impl Default for Steps {
    fn default() -> Self {
        Steps {
            join_ratio: JOIN_RATIO,
            branch_outliers: true,
            isolated: true,
            shorter_reading: true,
            zigzag_paths: true,
            detours: true,
            continuation: true,
            tangent_rays: true,
            own_curves: true,
            coarse: true,
            wired_outliers: true,
            skipped_samples: true,
            junctions: true,
            candidates: true,
        }
    }
}
