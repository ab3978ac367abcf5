//! Curve reconstruction: SIG-CONNECT2D and the machinery it shares with CONNECT2D.

pub mod boundary;
pub mod degenerate;
pub mod extract;
pub mod inflate;
pub mod inflate_sculpt;
pub mod method;
pub mod pocket;
pub mod queue;
pub mod result;
pub mod sculpt;
pub mod sig_connect2d;

pub use method::{Method, Options};
pub use result::{Reconstruction, Stats, Status};
pub use sig_connect2d::sig_connect2d;

use crate::{Point, Result};

/// Reconstructs the curve(s) through `points` with the method and options in `options`.
///
/// Validates the input once (non-finite coordinates and impossible coordinate ranges are
/// errors), then runs the method. Degenerate but valid input has a documented result; see
/// [`Status`].
pub fn reconstruct(points: &[Point], options: &Options) -> Result<Reconstruction> {
    match options.method {
        Method::SigConnect2d => sig_connect2d(points, options.leaf_elimination),
        Method::Connect2d => crate::baselines::connect2d::connect2d(points),
    }
}
