//! The research samplers: cubic Bézier paths read from SVG files, and their ε-sampling with
//! a start offset, the sampler of the paper's Bézier experiment (`docs/algorithms.md` §4.9).
//! The small seeded samplers (blobs, spirals, noise) are in [`sigdt::samplers`].

mod bezier;
mod eps_sampling;

pub use bezier::{parse_svg_paths, read_svg_paths, BezierPath};
pub use eps_sampling::{
    eps_sample, eps_sample_with_frames, lfs, DenseCurve, FramedSample, DENSE_STEPS,
};
