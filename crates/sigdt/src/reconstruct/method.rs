//! Which reconstruction method to run, and its options.

use std::fmt;
use std::str::FromStr;

/// A reconstruction method. Spelled in kebab case on the command line and in Python
/// (`"sig-connect2d"`); [`FromStr`] and [`Display`](fmt::Display) map between the two.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Method {
    /// SIG-CONNECT2D [MOW22](https://doi.org/10.1111/cgf.14654): SIGDT, then CONNECT2D's inflating and sculpting.
    #[default]
    SigConnect2d,
    /// SIG-AUTO (ours, after [MOW22](https://doi.org/10.1111/cgf.14654)'s future work):
    /// SIGDT2 per component; components whose spanning tree is a path are joined and closed
    /// only where the gap is at most twice their longest edge, the rest is inflated and
    /// sculpted on its own. Returns closed loops and open paths. Ignores `leaf_elimination`.
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
    /// PEEL (Parakkat, Methirumangalath, Muthuganapathy 2018): drop every triangle's longest
    /// edge, then filter.
    Peel,
    /// The Euclidean minimum spanning tree: the trivial baseline for open curves.
    Emst,
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
        Method::Peel,
        Method::Emst,
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
            Method::Peel => "peel",
            Method::Emst => "emst",
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = crate::Error;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Method::ALL.iter().copied().find(|m| m.name() == s).ok_or_else(|| {
            let names: Vec<_> = Method::ALL.iter().map(|m| m.name()).collect();
            crate::Error::InvalidOption(format!(
                "unknown method '{s}' (expected one of: {})",
                names.join(", ")
            ))
        })
    }
}

/// Options of [`reconstruct`](crate::reconstruct()).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// The method to run.
    pub method: Method,
    /// Give every SIGDT leaf its shortest missing Delaunay edge before inflating (SIGDT2,
    /// [MOW22](https://doi.org/10.1111/cgf.14654) §4.2.3). On by default: on the 522
    /// labelled curves it is never worse and raises exact reconstructions from 92 to 105 of
    /// 110 manifold and from 65 to 75 of 100 sharp-corner cases (`docs/algorithms.md`).
    pub leaf_elimination: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options { method: Method::SigConnect2d, leaf_elimination: true }
    }
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
