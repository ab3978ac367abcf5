//! Curve reconstruction: SIG-CONNECT2D and the machinery it shares with CONNECT2D.

pub mod boundary;
pub mod chain_join;
pub mod closed_component;
pub mod degenerate;
pub mod extract;
pub mod from_edges;
pub mod inflate;
pub mod inflate_sculpt;
pub mod method;
pub mod pocket;
pub mod queue;
pub mod result;
pub mod sculpt;
pub mod sig_auto;
pub mod sig_connect2d;
pub mod spanning_forests;
pub mod spur_path;
pub mod trace;

pub use method::{Method, Options};
pub use result::{Reconstruction, Stats, Status};
pub use sig_connect2d::sig_connect2d;
pub use trace::{Phase, Step, Trace};

use crate::baselines::{
    connect2d::{bc0, connect2d_on},
    crawl::crawl,
    crust::crust,
    hnn_crust::hnn_crust,
    nn_crust::nn_crust,
    peel::peel,
};
use crate::delaunay::Triangulation;
use crate::{Point, Result};
use inflate_sculpt::inflate_and_sculpt_traced;
use sig_connect2d::sig_connect2d_on;

/// Reconstructs the curve(s) through `points` with the method and options in `options`.
///
/// Validates the input once (non-finite coordinates and impossible coordinate ranges are
/// errors), then runs the method. Degenerate but valid input has a documented result; see
/// [`Status`].
pub fn reconstruct(points: &[Point], options: &Options) -> Result<Reconstruction> {
    let dt = Triangulation::new(points)?;
    Ok(reconstruct_on(&dt, options))
}

/// [`reconstruct`] on an existing triangulation of the points.
pub fn reconstruct_on(dt: &Triangulation, options: &Options) -> Reconstruction {
    let filter: fn(&Triangulation) -> Vec<[u32; 2]> = match options.method {
        Method::SigConnect2d => return sig_connect2d_on(dt, options.leaf_elimination),
        Method::SigAuto => return sig_auto::sig_auto_on(dt),
        Method::Connect2d => return connect2d_on(dt),
        Method::Crust => crust,
        Method::NnCrust => nn_crust,
        Method::HnnCrust => hnn_crust,
        Method::Crawl => crawl,
        Method::Peel => peel,
        Method::Emst => |dt: &Triangulation| {
            let tree = crate::proximity::emst::emst_mask(dt);
            dt.edge_halfedges()
                .filter(|&h| tree.contains(h))
                .map(|h| [dt.origin(h), dt.dest(h)])
                .collect()
        },
    };
    // The graph filters: the same degenerate results, then their edges read as chains.
    degenerate::degenerate_result(dt)
        .unwrap_or_else(|| from_edges::from_vertex_pairs(dt, filter(dt), Stats::default()))
}

/// [`reconstruct`], also returning the [`Trace`] of inflating and sculpting: every label
/// change in order. The reconstruction is the same as [`reconstruct`]'s. The trace is
/// `None` for methods that neither inflate nor sculpt (the graph filters) and for
/// degenerate input (no triangles).
pub fn reconstruct_traced(
    points: &[Point],
    options: &Options,
) -> Result<(Reconstruction, Option<Trace>)> {
    let dt = Triangulation::new(points)?;
    Ok(reconstruct_traced_on(&dt, options))
}

/// [`reconstruct_traced`] on an existing triangulation of the points.
pub fn reconstruct_traced_on(
    dt: &Triangulation,
    options: &Options,
) -> (Reconstruction, Option<Trace>) {
    if let Some(result) = degenerate::degenerate_result(dt) {
        return (result, None);
    }
    let (graph, leaf_edges_added) = match options.method {
        Method::SigConnect2d => sig_connect2d::initial_graph(dt, options.leaf_elimination),
        Method::Connect2d => bc0(dt),
        _ => return (reconstruct_on(dt, options), None),
    };
    inflate_and_sculpt_traced(dt, &graph, leaf_edges_added, true)
}
