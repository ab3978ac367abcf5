//! Proximity graphs on the input points: DT, SIG, SIGDT, SIGDT2, EMST and kNN, and the
//! nearest-neighbour distances they are built from. One module per graph.

pub(crate) mod emst;
pub(crate) mod kdtree;
pub(crate) mod knn;
pub(crate) mod leaf_elimination;
pub(crate) mod nearest;
pub(crate) mod sig;
pub(crate) mod sigdt;

pub use nearest::nearest_neighbour_distances;

use crate::delaunay::{Shape, Triangulation};
use crate::error::{Error, Result};
use crate::geometry::{Edge, Point};
use std::fmt;

/// Which proximity graph to build.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GraphKind {
    /// The Delaunay triangulation's edges.
    Dt,
    /// The closed spheres-of-influence graph.
    Sig,
    /// SIG ∩ DT.
    SigDt,
    /// SIGDT after leaf elimination (every vertex has degree ≥ 2).
    SigDt2,
    /// The Euclidean minimum spanning tree.
    Emst,
    /// The k-nearest-neighbour graph (undirected union).
    Knn {
        /// Neighbours per point, ≥ 1.
        k: usize,
    },
}

impl GraphKind {
    /// Names accepted by [`GraphKind::from_name`].
    pub const NAMES: &'static [&'static str] = &["dt", "sig", "sigdt", "sigdt2", "emst", "knn"];

    /// Parses `dt|sig|sigdt|sigdt2|emst|knn`; `k` is required for `knn` and refused otherwise.
    pub fn from_name(name: &str, k: Option<usize>) -> Result<GraphKind> {
        let kind = match (name, k) {
            ("knn", Some(k)) if k >= 1 => return Ok(GraphKind::Knn { k }),
            ("knn", Some(_)) => return Err(Error::InvalidOption("knn needs k >= 1".into())),
            ("knn", None) => {
                return Err(Error::InvalidOption("knn needs k (for example -k 2)".into()))
            }
            ("dt", _) => GraphKind::Dt,
            ("sig", _) => GraphKind::Sig,
            ("sigdt", _) => GraphKind::SigDt,
            ("sigdt2", _) => GraphKind::SigDt2,
            ("emst", _) => GraphKind::Emst,
            _ => {
                return Err(Error::InvalidOption(format!(
                    "unknown graph kind '{name}' (expected one of: {})",
                    GraphKind::NAMES.join(", ")
                )))
            }
        };
        match k {
            Some(_) => Err(Error::InvalidOption(format!("k only applies to knn, not {name}"))),
            None => Ok(kind),
        }
    }
}

impl fmt::Display for GraphKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GraphKind::Dt => f.write_str("dt"),
            GraphKind::Sig => f.write_str("sig"),
            GraphKind::SigDt => f.write_str("sigdt"),
            GraphKind::SigDt2 => f.write_str("sigdt2"),
            GraphKind::Emst => f.write_str("emst"),
            GraphKind::Knn { k } => write!(f, "knn (k = {k})"),
        }
    }
}

/// The most neighbour pairs `n · k` the kNN graph is built with (about 2 GB at its peak):
/// a larger request is refused rather than allowed to exhaust memory.
pub const MAX_KNN_PAIRS: usize = 100_000_000;

/// The edges of a proximity graph on `points`, as sorted input-index pairs `[i, j]`, `i < j`.
/// Exact duplicates get no edges (their lowest-index representative stands for them). For
/// the kNN graph, `k` beyond the other distinct points counts as all of them, and an `n · k`
/// above [`MAX_KNN_PAIRS`] is an [`Error::InvalidOption`].
pub fn proximity_graph(points: &[Point], kind: GraphKind) -> Result<Vec<Edge>> {
    let dt = Triangulation::new(points)?;
    if let GraphKind::Knn { k } = kind {
        let n = dt.num_vertices();
        let k = k.min(n.saturating_sub(1));
        if n.saturating_mul(k) > MAX_KNN_PAIRS {
            return Err(Error::InvalidOption(format!(
                "knn with k = {k} on {n} distinct points asks for {} neighbour pairs; at most \
                 {MAX_KNN_PAIRS} are built (choose a smaller k)",
                n.saturating_mul(k)
            )));
        }
    }
    Ok(proximity_graph_on(&dt, kind))
}

/// [`proximity_graph`] on an existing triangulation.
pub fn proximity_graph_on(dt: &Triangulation, kind: GraphKind) -> Vec<Edge> {
    match kind {
        GraphKind::Dt => dt.edges(),
        GraphKind::Sig => sig::sig(dt),
        GraphKind::SigDt => sigdt::sigdt(dt),
        GraphKind::SigDt2 if dt.shape() == Shape::Proper => {
            let mut g = sigdt::sigdt_mask(dt);
            leaf_elimination::eliminate_leaves(dt, &mut g);
            g.edges(dt)
        }
        // On a line every Delaunay edge is a candidate; a leaf's missing edge is the other
        // segment at it, so SIGDT2 is the whole path.
        GraphKind::SigDt2 => dt.edges(),
        GraphKind::Emst => emst::emst(dt),
        GraphKind::Knn { k } => knn::knn(dt, k),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_parse() {
        assert_eq!(GraphKind::from_name("sigdt2", None).unwrap(), GraphKind::SigDt2);
        assert_eq!(GraphKind::from_name("knn", Some(3)).unwrap(), GraphKind::Knn { k: 3 });
        assert!(GraphKind::from_name("knn", None).is_err());
        assert!(GraphKind::from_name("dt", Some(2)).is_err());
        assert!(GraphKind::from_name("gabriel", None).unwrap_err().to_string().contains("sigdt2"));
    }

    #[test]
    fn subgraph_relations_on_a_curve() {
        let pts: Vec<Point> = (0..200)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 200.0;
                [(1.0 + 0.3 * (3.0 * a).cos()) * a.cos(), (1.0 + 0.3 * (3.0 * a).cos()) * a.sin()]
            })
            .collect();
        let dt = Triangulation::new(&pts).unwrap();
        let all = proximity_graph_on(&dt, GraphKind::Dt);
        let subset = |a: &[Edge], b: &[Edge]| a.iter().all(|e| b.binary_search(e).is_ok());
        let sigdt = proximity_graph_on(&dt, GraphKind::SigDt);
        let sig = proximity_graph_on(&dt, GraphKind::Sig);
        assert!(subset(&sigdt, &all) && subset(&sigdt, &sig));
        assert!(subset(&proximity_graph_on(&dt, GraphKind::Emst), &all));
        assert!(subset(&sigdt, &proximity_graph_on(&dt, GraphKind::SigDt2)));
        assert_eq!(proximity_graph_on(&dt, GraphKind::Emst).len(), 199);
        // SIGDT = SIG ∩ DT.
        let both: Vec<Edge> =
            sig.iter().copied().filter(|e| all.binary_search(e).is_ok()).collect();
        assert_eq!(both, sigdt);
    }
}
