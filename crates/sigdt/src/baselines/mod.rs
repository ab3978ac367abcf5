//! The methods SIG-CONNECT2D is measured against, one module per paper. CONNECT2D runs the
//! shared engine from its own graph; OPTIMALTRANSPORT simplifies a triangulation of its own
//! and returns vertices of its own; the others are graph filters (DISCUR a curve grower)
//! that return vertex pairs,
//! read as loops and paths by the caller. Why GATHAN, CCRUST, LENZ and VICUR are not here:
//! `docs/evaluation.md`, section "Methods without an implementation".

pub(crate) mod connect2d;
pub(crate) mod crawl;
pub(crate) mod crust;
pub(crate) mod discur;
pub(crate) mod emst;
pub(crate) mod fit_connect;
pub(crate) mod hnn_crust;
pub(crate) mod nn_crust;
pub(crate) mod optimal_transport;
pub(crate) mod peel;
pub(crate) mod stretch_denoise;
