//! Which reconstruction method to run, its options, and the entry points that run it.
//!
//! [`reconstruct`] validates the input once (through [`Triangulation::new`]) and dispatches
//! to the method's module: [`sig_connect2d`], [`sig_auto`]
//! or a baseline. Every method returns a [`Reconstruction`] with the same invariants.

use std::fmt;
use std::str::FromStr;

use crate::baselines;
use crate::connect::{inflate_and_sculpt_traced, trace::Trace};
use crate::delaunay::Triangulation;
use crate::error::Result;
use crate::geometry::Point;
use crate::result::{degenerate_result, from_vertex_pairs, Reconstruction, Stats};
use crate::sampling_check::{diagnose, open_outlines};
use crate::{sig_auto, sig_connect2d};

/// A reconstruction method. Spelled in kebab case on the command line and in Python
/// (`"sig-auto"`); [`FromStr`] and [`Display`](fmt::Display) map between the two.
///
/// The default is SIG-AUTO: on data of unknown kind (open, several or nested curves,
/// noise, outliers) it gives the right curves where SIG-CONNECT2D, which returns closed
/// polygons through every point, cannot, and it loses nothing SIG-CONNECT2D reconstructs
/// within the paper's sampling condition (`docs/sig-auto.md`). SIG-CONNECT2D, the paper's
/// method, is one option away.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Method {
    /// SIG-CONNECT2D [MOW22](https://doi.org/10.1111/cgf.14654), the paper's method: SIGDT,
    /// then CONNECT2D's inflating and sculpting into closed polygons through every point.
    SigConnect2d,
    /// SIG-AUTO (ours, after [MOW22](https://doi.org/10.1111/cgf.14654)'s future work), the
    /// default: SIGDT2 per component; components whose spanning tree is a path are joined
    /// and closed only where the gap is at most twice their longest edge, the rest is
    /// inflated and sculpted on its own; outliers are left out and noise read at a coarser
    /// scale. Returns closed loops and open paths. Ignores `leaf_elimination`.
    #[default]
    SigAuto,
    /// CONNECT2D [OM13](https://doi.org/10.1111/cgf.12227): the same inflating and sculpting
    /// started from BC₀ (EMST plus leaf edges). Ignores `leaf_elimination`.
    Connect2d,
    /// CRUST (Amenta, Bern, Eppstein 1998): Delaunay edges between samples that survive
    /// adding the Voronoi vertices.
    Crust,
    /// NN-CRUST (Dey, Kumar 1999): nearest neighbours plus half neighbours.
    NnCrust,
    /// HNN-CRUST (Ohrhallinger, Mitchell, Wimmer 2016): mutual nearest and half-plane
    /// neighbours, without a triangulation.
    HnnCrust,
    /// CRAWL (Parakkat, Muthuganapathy 2016): grow paths from nearest-neighbour seeds by
    /// the nearest unvisited Delaunay neighbour.
    Crawl,
    /// DISCUR (Zeng, Nguyen, Yan, Li 2008): grow curves along the Delaunay edges, shortest
    /// first; a curve takes a longer edge only if it fits the curve's spacing statistics.
    /// Reconstructed without the paper's text (`docs/algorithms.md` §3.9).
    Discur,
    /// FITCONNECT (Ohrhallinger, Wimmer 2018): grow a fitted circle around each point until
    /// the point lies between its neighbours, and link points whose fits overlap. Thins
    /// noise by leaving points out ([`LeftOutReason::Eliminated`](crate::LeftOutReason)).
    /// Ignores `leaf_elimination`.
    FitConnect,
    /// STRETCHDENOISE (Ohrhallinger, Wimmer 2018): FITCONNECT's edges, with every curve
    /// point moved along its fitted normal, within its noise extent, to straighten the
    /// curve ([`Vertices::Moved`](crate::Vertices::Moved)). Ignores `leaf_elimination`.
    StretchDenoise,
    /// PEEL (Parakkat, Methirumangalath, Muthuganapathy 2018): drop every triangle's longest
    /// edge, then filter.
    Peel,
    /// The Euclidean minimum spanning tree: the trivial baseline for open curves.
    Emst,
    /// OPTIMALTRANSPORT (de Goes, Cohen-Steiner, Alliez, Desbrun 2011): simplifies the
    /// Delaunay triangulation by half-edge collapses that keep the optimal-transport cost of
    /// the points low, until a quarter of them are left as vertices. Its vertices are its own
    /// ([`Vertices::New`](crate::Vertices::New)), not input points, so it is never exact;
    /// meant for noisy input. Ignores `leaf_elimination`.
    OptimalTransport,
}

impl Method {
    /// Every method, in the order they are listed in help texts.
    pub const ALL: &'static [Method] = &[
        Method::SigConnect2d,
        Method::SigAuto,
        Method::Connect2d,
        Method::Crust,
        Method::NnCrust,
        Method::HnnCrust,
        Method::Crawl,
        Method::Discur,
        Method::FitConnect,
        Method::StretchDenoise,
        Method::Peel,
        Method::Emst,
        Method::OptimalTransport,
    ];

    /// The kebab-case name.
    pub fn name(self) -> &'static str {
        match self {
            Method::SigConnect2d => "sig-connect2d",
            Method::SigAuto => "sig-auto",
            Method::Connect2d => "connect2d",
            Method::Crust => "crust",
            Method::NnCrust => "nn-crust",
            Method::HnnCrust => "hnn-crust",
            Method::Crawl => "crawl",
            Method::Discur => "discur",
            Method::FitConnect => "fit-connect",
            Method::StretchDenoise => "stretch-denoise",
            Method::Peel => "peel",
            Method::Emst => "emst",
            Method::OptimalTransport => "optimal-transport",
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = crate::error::Error;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        crate::error::find_by_name(Method::ALL, Method::name, s, "method")
    }
}

/// What the caller knows the points outline ([`Options::expect`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub enum Expect {
    /// Nothing more: curves come back open or closed as the points read (the default).
    #[default]
    Curves,
    /// Areas: every curve is a closed outline (polygon vertices, parcels, islands). SIG-AUTO
    /// then closes an open reading where a polygon through the points it keeps breaks the
    /// sampling no more often, and every method's open path is a finding, `open-outlines`
    /// (a warning), never a quiet line.
    Areas,
}

impl Expect {
    /// Every expectation, in the order of `--help`.
    pub const ALL: &'static [Expect] = &[Expect::Curves, Expect::Areas];

    /// The kebab-case name: `curves` or `areas`.
    pub fn name(self) -> &'static str {
        match self {
            Expect::Curves => "curves",
            Expect::Areas => "areas",
        }
    }
}

impl fmt::Display for Expect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Expect {
    type Err = crate::error::Error;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        crate::error::find_by_name(Expect::ALL, Expect::name, s, "expectation")
    }
}

/// Options of [`reconstruct`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// The method to run.
    pub method: Method,
    /// Give every SIGDT leaf its shortest missing Delaunay edge before inflating (SIGDT2,
    /// [MOW22](https://doi.org/10.1111/cgf.14654) §4.2.3). On by default: on the labelled
    /// curves it is never worse, and better on manifold and sharp-corner cases
    /// (`docs/algorithms.md` §7.1 has the numbers).
    pub leaf_elimination: bool,
    /// What the points outline, as far as the caller knows ([`Expect::Curves`] by default).
    pub expect: Expect,
}

impl Default for Options {
    fn default() -> Self {
        Options { method: Method::default(), leaf_elimination: true, expect: Expect::default() }
    }
}

/// Reconstructs the curve(s) through `points` with the method and options in `options`.
///
/// Validates the input once (non-finite coordinates and impossible coordinate ranges are
/// errors), then runs the method. Degenerate but valid input has a documented result; see
/// [`Status`](crate::Status).
///
/// # Errors
/// [`NonFinite`](crate::Error::NonFinite), [`CoordinateRange`](crate::Error::CoordinateRange)
/// and [`TooManyPoints`](crate::Error::TooManyPoints), from [`Triangulation::new`].
pub fn reconstruct(points: &[Point], options: &Options) -> Result<Reconstruction> {
    reconstruct_triangulation(Triangulation::new(points)?, options)
}

/// [`reconstruct`] on points it owns: the same result, with less memory at its peak, since
/// the points are freed once copied into the triangulation and the triangulation before
/// the result is built (`docs/algorithms.md` §7.3). For callers that do not need the
/// points afterwards, such as the command line writing edges.
///
/// # Errors
/// As [`reconstruct`].
pub fn reconstruct_owned(points: Vec<Point>, options: &Options) -> Result<Reconstruction> {
    reconstruct_triangulation(Triangulation::from_vec(points)?, options)
}

fn reconstruct_triangulation(dt: Triangulation, options: &Options) -> Result<Reconstruction> {
    if options.method == Method::SigConnect2d {
        return Ok(sig_connect2d::sig_connect2d_owning(dt, options.leaf_elimination));
    }
    Ok(reconstruct_on(&dt, options))
}

/// [`reconstruct`] on an existing triangulation of the points, so that one triangulation can
/// serve several methods and graphs.
pub fn reconstruct_on(dt: &Triangulation, options: &Options) -> Reconstruction {
    let mut rec = run_method(dt, options);
    if options.method != Method::SigAuto {
        // SIG-AUTO checks its own readings (it reads again when they warn).
        rec.diagnosis = diagnose(dt, &rec);
    }
    if options.expect == Expect::Areas {
        rec.diagnosis.extend(open_outlines(dt, &rec));
    }
    rec
}

/// `options.method` on `dt`, before the sampling check.
fn run_method(dt: &Triangulation, options: &Options) -> Reconstruction {
    let filter: fn(&Triangulation) -> Vec<[u32; 2]> = match options.method {
        Method::SigConnect2d => {
            return sig_connect2d::sig_connect2d_on(dt, options.leaf_elimination)
        }
        Method::SigAuto => return sig_auto::sig_auto_expecting(dt, options.expect),
        Method::Connect2d => return baselines::connect2d::connect2d_on(dt),
        Method::OptimalTransport => return baselines::optimal_transport::optimal_transport_on(dt),
        Method::FitConnect => return baselines::fit_connect::fit_connect_on(dt),
        Method::StretchDenoise => return baselines::stretch_denoise::stretch_denoise_on(dt),
        Method::Crust => baselines::crust::crust,
        Method::NnCrust => baselines::nn_crust::nn_crust,
        Method::HnnCrust => baselines::hnn_crust::hnn_crust,
        Method::Crawl => baselines::crawl::crawl,
        Method::Discur => baselines::discur::discur,
        Method::Peel => baselines::peel::peel,
        Method::Emst => baselines::emst::emst,
    };
    // The graph filters: the same degenerate results, then their edges read as chains.
    degenerate_result(dt).unwrap_or_else(|| from_vertex_pairs(dt, filter(dt), Stats::default()))
}

/// [`reconstruct`], also returning the [`Trace`] of inflating and sculpting: every label
/// change in order. The reconstruction is the same as [`reconstruct`]'s. The trace is
/// `None` for methods other than SIG-CONNECT2D and CONNECT2D (SIG-AUTO inflates components
/// on triangulations of their own, the graph filters do not inflate) and for degenerate
/// input (no triangles).
///
/// # Errors
/// As [`reconstruct`].
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
    if let Some(result) = degenerate_result(dt) {
        return (result, None);
    }
    let (graph, leaf_edges_added) = match options.method {
        Method::SigConnect2d => sig_connect2d::initial_graph(dt, options.leaf_elimination),
        Method::Connect2d => baselines::connect2d::bc0(dt),
        _ => return (reconstruct_on(dt, options), None),
    };
    let (mut rec, trace) = inflate_and_sculpt_traced(dt, &graph, leaf_edges_added, true);
    rec.diagnosis = diagnose(dt, &rec);
    (rec, trace)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for &m in Method::ALL {
            assert_eq!(m.to_string().parse::<Method>().unwrap(), m);
        }
        assert!("crust3".parse::<Method>().unwrap_err().to_string().contains("sig-connect2d"));
    }
}
