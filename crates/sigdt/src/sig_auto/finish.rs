//! A reading, given as vertex pairs of the triangulation, turned into SIG-AUTO's result:
//! the points left out listed, and the status of what was read.
use crate::delaunay::Triangulation;
use crate::result::{
    from_vertex_pairs, inside_left_out, LeftOut, LeftOutReason, Reconstruction, Stats, Status,
};

/// The outliers `rec` left out, as vertices of its triangulation (`vertex_of` maps input
/// indices to them).
pub(super) fn outlier_vertices(rec: &Reconstruction, vertex_of: &[u32]) -> Vec<u32> {
    let outliers = rec.left_out.iter().filter(|l| l.reason == LeftOutReason::Outlier);
    outliers.map(|l| vertex_of[l.index]).collect()
}

/// The result of the reading `pairs` (vertices of `dt`), with the points left inside by
/// sculpting (`inside`, input indices) and the outliers (vertices of `dt`) left out.
pub(super) fn finish(
    dt: &Triangulation,
    pairs: Vec<[u32; 2]>,
    mut inside: Vec<usize>,
    outliers: &[u32],
    stats: Stats,
) -> Reconstruction {
    let mut rec = from_vertex_pairs(dt, pairs, stats);
    inside.sort_unstable();
    rec.left_out = inside_left_out(&inside);
    rec.left_out.extend(
        outliers
            .iter()
            .map(|&v| LeftOut { index: dt.input_index(v), reason: LeftOutReason::Outlier }),
    );
    rec.left_out.sort_unstable();
    if !inside.is_empty() {
        rec.status = Status::SculptingStuck { left_out: inside };
    } else if rec.status == Status::Curves && rec.paths.is_empty() && !rec.loops.is_empty() {
        // Every point that is not an outlier is on a loop.
        let on_loops: usize = rec.loops.iter().map(Vec::len).sum();
        if on_loops + outliers.len() == dt.num_vertices() {
            rec.status = if rec.loops.len() == 1 { Status::Polygon } else { Status::Polygons };
        }
    }
    rec
}
