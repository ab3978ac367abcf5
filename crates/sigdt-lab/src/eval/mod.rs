//! Evaluation against ground truth (`docs/algorithms.md` §4): exactness, sampling density,
//! distance and area errors, and proximity-graph statistics.
//!
//! Every function takes the input points and edges `[i, j]` over their 0-based indices, in
//! any order and direction. Entry points validate once: a non-finite point gives
//! [`Error::NonFinite`](sigdt::Error::NonFinite), an edge index out of range
//! [`Error::InvalidOption`](sigdt::Error::InvalidOption) naming the edge.

mod area;
mod bvh;
mod crossing;
mod distance;
mod epsilon;
mod exact;
mod features;
mod grid;
mod input;
mod medial;
mod metrics;
mod overlap;
mod region;
mod stray;

pub use area::{area_difference, AreaDifference};
pub use distance::{
    distance_errors, reconstruction_distance_errors, DistanceErrors, SAMPLES_PER_DIAGONAL,
};
pub use epsilon::{epsilon, graph_epsilon, EpsilonVariant};
pub use exact::{edge_diff, is_exact, EdgeDiff};
pub use metrics::{evaluate, Metrics};
pub use overlap::{overlap, Coverage, GtCoverage, Overlap};
pub use region::{region_overlap, topology, RegionOverlap, Topology};
pub use stray::stray;
