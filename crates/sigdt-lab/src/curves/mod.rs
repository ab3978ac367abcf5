//! The research samplers: cubic Bézier paths read from SVG files, and their ε-sampling with
//! a start offset, the sampler of the paper's Bézier experiment (`docs/algorithms.md` §4.9);
//! non-manifold drawings sampled with shared junctions (§4.11).
//! The small seeded samplers (blobs, spirals, noise) are in [`sigdt::samplers`].

mod bezier;
mod drawings;
mod eps_sampling;
mod junctions;
mod non_manifold_set;

pub use bezier::{parse_svg_paths, read_svg_paths, BezierPath};
pub use drawings::{random_drawing, to_svg, DrawingKind};
pub use eps_sampling::{
    eps_sample, eps_sample_at_density, eps_sample_with_frames, lfs, lfs_at_density, DenseCurve,
    FramedSample, DENSE_STEPS,
};
pub use junctions::{sample_with_junctions, JunctionSample, CROSSING_STEPS, SNAP};
pub use non_manifold_set::{folder_files, non_manifold_cases, NonManifoldCase, PER_KIND};
