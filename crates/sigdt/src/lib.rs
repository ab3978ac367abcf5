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
//! Module graph: `geometry ← delaunay ← proximity ← reconstruct`, with `io` and `curves`
//! beside them.

#![forbid(unsafe_code)]

pub mod baselines;
pub mod curves;
pub mod delaunay;
pub mod error;
pub mod eval;
pub mod geometry;
pub mod graph;
pub mod io;
pub mod proximity;
pub mod reconstruct;
pub mod render;
pub mod testing;

pub use delaunay::Triangulation;
pub use error::{Error, Result};
pub use geometry::Point;
pub use proximity::{proximity_graph, GraphKind};
pub use reconstruct::{
    reconstruct, reconstruct_traced, Method, Options, Phase, Reconstruction, Stats, Status, Step,
    Trace,
};

/// An undirected edge `[i, j]` between input point indices, `i < j`.
pub type Edge = [usize; 2];
