//! The plumbing every graph algorithm shares: edge sets over a triangulation, union-find,
//! and the split of an edge set into chains.

mod chains;
mod edge_mask;
mod union_find;

pub use chains::{chains, Chain};
pub(crate) use chains::{chains_of_slots, two_slots};
pub use edge_mask::EdgeMask;
pub use union_find::UnionFind;
