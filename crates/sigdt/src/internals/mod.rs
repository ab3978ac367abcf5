//! Not part of the API: the building blocks that the configuration and trace tests, the
//! examples and the `sigdt-lab` crate reach into. Anything here may change in any release.

mod spade_reference;
mod testing;

pub use crate::baselines::connect2d::bc0;
pub use crate::baselines::discur::{discur_variant, Variant as DiscurVariant};
pub use crate::baselines::optimal_transport::{default_stop, optimal_transport_with, Stop};
pub use crate::baselines::{
    crawl::crawl, crust::crust, discur::discur, hnn_crust::hnn_crust, nn_crust::nn_crust,
    peel::peel,
};
pub use crate::connect::boundary::{Boundary, VertexClass};
pub use crate::connect::extract::{loop_edges, loops};
pub use crate::connect::{inflate::inflate, sculpt::sculpt};
pub use crate::delaunay::check::check_delaunay;
pub use crate::delaunay::hygiene::Scaling;
pub use crate::delaunay::perturbation::incircle as perturbed_incircle;
pub use crate::error::find_by_name;
pub use crate::geometry::{distance, orient2d, segments_cross, squared_distance, turning};
pub use crate::graph::{chains, Chain, EdgeMask, UnionFind};
pub use crate::proximity::emst::{emst_mask, minimum_spanning_forest};
pub use crate::proximity::kdtree::KdTree;
pub use crate::proximity::leaf_elimination::eliminate_leaves;
pub use crate::proximity::sigdt::sigdt_mask;
pub use crate::segment_grid::first_crossing;
pub use crate::sig_auto::{sig_auto_with, Steps as SigAutoSteps, JOIN_RATIO};
pub use crate::sig_connect2d::initial_graph;
pub use spade_reference::{spade_reference, FlatArrays};
pub use testing::{check_reconstruction, filter_edges};
