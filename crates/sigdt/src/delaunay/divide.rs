//! The canonical triangulation built on several threads: divide and conquer.
//!
//! The points (in canonical insertion order) are split at their lexicographic median into
//! a left and a right half, each half is triangulated on its own thread (recursively, as
//! many levels as there are threads to fill; below that by insertion one by one, module
//! [`super::incremental`]), and the halves are joined by the Guibas–Stolfi merge (module
//! [`super::merge`]). The triangulation under the symbolic perturbation is unique and its
//! ranks depend on the coordinates alone (module [`super::perturbation`]), so each half's
//! triangulation is the canonical one of its points and the merge returns the canonical
//! one of the union: the same triangles as the insertion of all the points.
//!
//! Vertices are numbered as the insertion numbers them (the distinct points in canonical
//! order), input indices and duplicates likewise; the triangles are stored in another
//! layout, which no stage after the triangulation depends on
//! (`tests/layout_independence.rs`). A half with all its points on a line, or a merge that
//! fails its checks, gives the points back, and the caller inserts them one by one.
//! `Triangulation::new` divides from 2^16 points on a pool of several threads
//! (`crate::parallel::halvings`); measurements in `docs/algorithms.md` §7.6.
//!
//! # Complexity
//! O(n log n) expected work, as the insertion, in parts of n / 2^d points on 2^d threads;
//! each merge is linear in the triangles it adds and removes (O(√n) on uniform points),
//! plus a scan of its parts' hull half-edges.
use super::brio::put_first_triangle_first;
use super::incremental::Dt;
use super::merge::{merge, Part};
use super::perturbation::lexicographic;
use super::relabel::vertex_halfedges;
use super::EMPTY;
use crate::geometry::Point;

/// The pieces of a [`Triangulation`](super::Triangulation) built in parts.
pub(super) struct Built {
    /// Vertex positions, in vertex order.
    pub points: Vec<Point>,
    /// Input index of each vertex (the lowest of its duplicates).
    pub input_index: Vec<u32>,
    pub triangles: Vec<u32>,
    pub halfedges: Vec<u32>,
    pub vertex_halfedge: Vec<u32>,
    /// `[duplicate, representative]` input indices, sorted.
    pub duplicates: Vec<[usize; 2]>,
}

/// A part's triangulation in the positions of its vertices' first occurrences, and each
/// of its positions that repeats an earlier point with the position of its first occurrence.
struct Piece {
    part: Part,
    repeats: Vec<(u32, u32)>,
}

/// Triangulates `points` (scaled, in canonical insertion order, the first three spanning a
/// triangle; `input[k]` the input index of position `k`) in `2^levels` parts; the points
/// back when the parts cannot be used (module docs).
pub(super) fn triangulate_divided(
    mut points: Vec<Point>,
    input: &[u32],
    levels: u32,
) -> Result<Built, Vec<Point>> {
    let n = points.len();
    let all: Vec<u32> = (0..n as u32).collect();
    let Some(Piece { part, repeats }) = piece(&points, all, levels) else {
        return Err(points);
    };
    // Each position's first occurrence, then, in place and in canonical order, its vertex:
    // a first occurrence is the next vertex, a later one has its first's (already numbered).
    let mut vertex: Vec<u32> = (0..n as u32).collect();
    for (k, f) in repeats {
        vertex[k as usize] = f;
    }
    let mut vertices = 0;
    for k in 0..n {
        let first = vertex[k] as usize;
        vertex[k] = if first == k {
            points[vertices] = points[k]; // the vertex positions, compacted in place
            vertices += 1;
            vertices as u32 - 1
        } else {
            vertex[first]
        };
    }
    points.truncate(vertices);
    points.shrink_to_fit();
    let (input_index, duplicates) = representatives(n, vertices, input, |k| vertex[k]);
    // The parts number their vertices by first occurrence, which is now its vertex.
    let Part { mut triangles, halfedges } = part;
    crate::parallel::update_slice(&mut triangles, |v| *v = vertex[*v as usize]);
    drop(vertex);
    let vertex_halfedge = vertex_halfedges(vertices, &triangles, &halfedges);
    Ok(Built { points, input_index, triangles, halfedges, vertex_halfedge, duplicates })
}

/// The triangulation of the points at positions `members` (in canonical order, or as the
/// split above ordered them): split and merged `levels` times, then inserted one by one.
/// Equal points keep their canonical order through every split, so the first copy of a
/// point a part inserts is its first occurrence.
fn piece(points: &[Point], members: Vec<u32>, levels: u32) -> Option<Piece> {
    if levels == 0 {
        return inserted(points, members);
    }
    let (left, right) = halves(points, members)?;
    let (left, right) = crate::parallel::join(
        || piece(points, left, levels - 1),
        || piece(points, right, levels - 1),
    );
    let (left, right) = (left?, right?);
    let mut repeats = left.repeats;
    repeats.extend(right.repeats);
    let part = merge(points, left.part, right.part)?;
    Some(Piece { part, repeats })
}

/// `members` split at the lexicographic median of their points, each half in the order of
/// `members` but for its points nearest the cut, which go first ([`near_cut_first`]);
/// equal points go to the same half and group. `None` if a half would hold fewer than three.
fn halves(points: &[Point], members: Vec<u32>) -> Option<(Vec<u32>, Vec<u32>)> {
    let lexicographic = |a: &u32, b: &u32| lexicographic(points[*a as usize], points[*b as usize]);
    let mut sorted = members.clone();
    let middle = sorted.len() / 2;
    let (_, &mut pivot, _) = sorted.select_nth_unstable_by(middle, lexicographic);
    drop(sorted);
    let (left, right): (Vec<u32>, Vec<u32>) =
        members.into_iter().partition(|k| lexicographic(k, &pivot).is_lt());
    if left.len() < 3 || right.len() < 3 {
        return None;
    }
    let cut = points[pivot as usize][0];
    Some((near_cut_first(points, left, cut), near_cut_first(points, right, cut)))
}

/// The share of a half's points, nearest the cut, inserted before the rest.
const NEAR_CUT_SHARE: usize = 512;

/// `part` with its [`NEAR_CUT_SHARE`]th of points nearest the line `x = cut` moved to the
/// front, each group in the order of `part`. This changes no triangle, only the work: a half
/// of a curve is open at the cut, and inserted in canonical order the curve's points near
/// the cut arrive late, each outside the hull across the wide mouth, and flip a long fan
/// of the triangles spanning it (one half of a smooth closed curve of 10⁶ points took 517
/// ms, nearly what all the points take). Inserted first, they close the mouth: 222 ms, as
/// the other half (`docs/algorithms.md` §7.6).
fn near_cut_first(points: &[Point], part: Vec<u32>, cut: f64) -> Vec<u32> {
    let count = (part.len() / NEAR_CUT_SHARE).max(3).min(part.len() - 1);
    let off = |k: u32| (points[k as usize][0] - cut).abs();
    let mut offsets: Vec<f64> = part.iter().map(|&k| off(k)).collect();
    let (_, &mut bound, _) = offsets.select_nth_unstable_by(count, f64::total_cmp);
    drop(offsets);
    let (mut near, far): (Vec<u32>, Vec<u32>) = part.into_iter().partition(|&k| off(k) < bound);
    near.extend(far);
    near
}

/// The points at `members` inserted one by one; `None` if they are collinear.
fn inserted(points: &[Point], members: Vec<u32>) -> Option<Piece> {
    let mut order = members;
    if !put_first_triangle_first(&mut order, |k| points[k as usize]) {
        return None;
    }
    let mut dt = Dt::new(order.iter().map(|&k| points[k as usize]).collect());
    // The first position of each local vertex; the positions that repeat one.
    let mut first_position: Vec<u32> = order[..3].to_vec();
    let mut repeats: Vec<(u32, u32)> = Vec::new();
    let mut hint = 2;
    for (j, &k) in order.iter().enumerate().skip(3) {
        let (v, new) = dt.insert(j, hint);
        match new {
            true => first_position.push(k),
            false => repeats.push((k, first_position[v as usize])),
        }
        hint = v;
    }
    drop(order);
    let (_, mut triangles, halfedges) = dt.finish();
    for v in &mut triangles {
        *v = first_position[*v as usize];
    }
    debug_assert!(halfedges.iter().all(|&h| h == EMPTY || (h as usize) < triangles.len()));
    Some(Piece { part: Part { triangles, halfedges }, repeats })
}

/// Each vertex's input index (the lowest of its duplicates) and the `[duplicate,
/// representative]` pairs, sorted, as the insertion one by one gives them; `vertex_of(k)`
/// is the vertex of position `k`, `input[k]` its input index.
fn representatives(
    n: usize,
    vertices: usize,
    input: &[u32],
    vertex_of: impl Fn(usize) -> u32,
) -> (Vec<u32>, Vec<[usize; 2]>) {
    let mut input_index = vec![u32::MAX; vertices];
    for k in 0..n {
        let slot = &mut input_index[vertex_of(k) as usize];
        *slot = (*slot).min(input[k]);
    }
    let mut duplicates: Vec<[usize; 2]> = (0..n)
        .filter_map(|k| {
            let representative = input_index[vertex_of(k) as usize];
            (input[k] != representative).then(|| [input[k] as usize, representative as usize])
        })
        .collect();
    duplicates.sort_unstable();
    (input_index, duplicates)
}
