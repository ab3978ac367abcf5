//! The facts every stage of SIG-AUTO reads, computed once per triangulation: the
//! triangulation itself, every vertex's nearest-neighbour distance, the junction networks
//! (built on first use) and the steps that run.
use super::junctions::Networks;
use super::Steps;
use crate::delaunay::Triangulation;
use crate::sampling_check::Spacing;

/// What the stages share (module docs).
pub(super) struct Facts<'a> {
    pub dt: &'a Triangulation,
    pub steps: &'a Steps,
    /// Every vertex's nearest-neighbour distance, when `dt` is proper.
    pub spacing: Option<&'a [f64]>,
    /// The junction networks, when `steps.junctions` and `dt` is proper.
    pub networks: Option<Networks<'a>>,
    /// The caller said the points outline areas ([`Expect::Areas`](crate::Expect::Areas)).
    pub areas: bool,
}

impl<'a> Facts<'a> {
    /// The facts of `dt` for `steps`, with `spacing`, the nearest-neighbour distances of its
    /// vertices (`None` when `dt` is not proper).
    pub fn new(dt: &'a Triangulation, steps: &'a Steps, spacing: Option<&'a [f64]>) -> Self {
        let networks = spacing.filter(|_| steps.junctions).map(|s| Networks::new(dt, s));
        Facts { dt, steps, spacing, networks, areas: false }
    }

    /// Where the sampling check reads `r(v)`: the known distances, when there are any.
    pub fn check_spacing(&self) -> Spacing<'a> {
        self.spacing.map_or(Spacing::Measured, Spacing::Known)
    }
}
