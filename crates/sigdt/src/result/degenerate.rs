//! The documented results for degenerate input (`docs/algorithms.md` §0.1), shared by every
//! method.
//!
//! - fewer than three distinct points: none or one edge, status `TooFewPoints`;
//! - all distinct points on one line: the path through them in their order along the line,
//!   status `Collinear`.
use super::{Reconstruction, Stats, Status, Vertices};
use crate::delaunay::{Shape, Triangulation};

/// The result for a triangulation without triangles, or `None` for a proper one.
pub(crate) fn degenerate_result(dt: &Triangulation) -> Option<Reconstruction> {
    let status = match dt.shape() {
        Shape::Proper => return None,
        Shape::Collinear => Status::Collinear,
        Shape::TooFewPoints => Status::TooFewPoints,
    };
    let mut path: Vec<usize> = (0..dt.num_vertices() as u32).map(|v| dt.input_index(v)).collect();
    if path.first() > path.last() {
        path.reverse();
    }
    let paths = if path.len() >= 2 { vec![path] } else { Vec::new() };
    Some(Reconstruction {
        edges: dt.edges(),
        loops: Vec::new(),
        paths,
        status,
        duplicates: dt.duplicates().to_vec(),
        left_out: Vec::new(),
        vertices: Vertices::Input,
        diagnosis: Vec::new(),
        stats: Stats {
            points: dt.input_len(),
            distinct_points: dt.num_vertices(),
            ..Stats::default()
        },
    })
}
