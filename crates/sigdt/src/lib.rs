//! # sigdt: 2D curve reconstruction from unorganised points
//!
//! Turns a set of points sampled from one or more curves into the polygon(s) they came from,
//! with **SIG-CONNECT2D** (Marin, Ohrhallinger, Wimmer, *SIGDT: 2D Curve Reconstruction*,
//! Pacific Graphics 2022): intersect the spheres-of-influence graph with the Delaunay
//! triangulation, then inflate and sculpt its boundary into a manifold polygon that
//! interpolates every point. Parameter-free, exact predicates, `O(n log n)`.
//!
//! ```
//! let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
//! let rec = sigdt::reconstruct(&square, &sigdt::Options::default()).unwrap();
//! assert_eq!(rec.edges, vec![[0, 1], [0, 3], [1, 2], [2, 3]]);
//! assert!(rec.status.is_manifold());
//! ```
//!
//! Everything a user calls is re-exported here; the modules below document the algorithms
//! (with their papers, guarantees and complexity) and hold the samplers. The main path runs
//! one way: points → [`delaunay`] → [`proximity`] (SIGDT) → [`connect`] (inflate, sculpt,
//! loops) → [`result`] (read back by the sampling check). Files in and out (plain points,
//! WKT, GeoJSON, GIS formats) are the crate `sigdt-io`.
//!
//! Evaluation metrics, the research samplers and pictures are in the `sigdt-lab` crate.

#![forbid(unsafe_code)]

pub mod baselines;
mod bits;
pub mod connect;
pub mod delaunay;
mod error;
mod geometry;
mod graph;
#[doc(hidden)]
pub mod internals;
mod method;
mod parallel;
pub mod proximity;
pub mod result;
pub mod samplers;
mod sampling_check;
mod segment_grid;
pub mod sig_auto;
pub mod sig_connect2d;

pub use connect::trace::{Phase, Step, Trace};
pub use delaunay::Triangulation;
pub use error::{Error, Result};
pub use geometry::{Edge, Point};
pub use method::{
    reconstruct, reconstruct_on, reconstruct_owned, reconstruct_traced, reconstruct_traced_on,
    Expect, Method, Options,
};
pub use proximity::{
    nearest_neighbour_distances, proximity_graph, proximity_graph_on, GraphKind, MAX_KNN_PAIRS,
};
pub use result::{
    Finding, FindingKind, LeftOut, LeftOutReason, Polygon, Reconstruction, Stats, Status, Vertices,
    AREA_TOLERANCE, DEPTH_RATIO, LONG_EDGE_RATIO, MIN_LOOP_POINTS, STRAY_DEPTH_RATIO,
};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
