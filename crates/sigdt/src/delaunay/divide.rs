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
//! fails its checks, gives `None`, and the caller inserts the points one by one instead.
//!
//! # Complexity
//! O(n log n) expected work, as the insertion, in parts of n / 2^d points on 2^d threads;
//! each merge is linear in the triangles it adds and removes (O(√n) on uniform points),
//! plus a scan of its parts' hull half-edges.
use super::build::put_first_triangle_first;
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
/// of its positions with the position of the first occurrence of its point.
struct Piece {
    part: Part,
    first_of: Vec<(u32, u32)>,
}

/// Triangulates `points` (scaled, in canonical insertion order, the first three spanning a
/// triangle; `input[k]` the input index of position `k`) in `2^levels` parts; `None` when
/// the parts cannot be used (module docs).
pub(super) fn triangulate_divided(points: &[Point], input: &[u32], levels: u32) -> Option<Built> {
    let n = points.len();
    let all: Vec<u32> = (0..n as u32).collect();
    let Piece { part, first_of } = piece(points, all, levels)?;
    // Vertices: the first occurrences, numbered in canonical order.
    let mut first = vec![u32::MAX; n];
    for (k, f) in first_of {
        first[k as usize] = f;
    }
    let mut vertex_of_position = vec![u32::MAX; n];
    let mut vertex_points = Vec::new();
    for k in 0..n {
        if first[k] == k as u32 {
            vertex_of_position[k] = vertex_points.len() as u32;
            vertex_points.push(points[k]);
        }
    }
    let vertex_of = |k: usize| vertex_of_position[first[k] as usize];
    let (input_index, duplicates) = representatives(n, vertex_points.len(), input, vertex_of);
    drop(first);
    let Part { triangles, halfedges } = part;
    let triangles = crate::parallel::map_slice(&triangles, |&k| vertex_of_position[k as usize]);
    drop(vertex_of_position);
    let vertex_halfedge = vertex_halfedges(vertex_points.len(), &triangles, &halfedges);
    Some(Built {
        points: vertex_points,
        input_index,
        triangles,
        halfedges,
        vertex_halfedge,
        duplicates,
    })
}

/// The triangulation of the points at positions `members` (canonical order): split and
/// merged `levels` times, then inserted one by one.
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
    let mut first_of = left.first_of;
    first_of.extend(right.first_of);
    let part = merge(points, left.part, right.part)?;
    Some(Piece { part, first_of })
}

/// `members` split at the lexicographic median of their points, each half in canonical
/// order; equal points go to the same half. `None` if a half would hold fewer than three.
fn halves(points: &[Point], members: Vec<u32>) -> Option<(Vec<u32>, Vec<u32>)> {
    let lexicographic = |a: &u32, b: &u32| lexicographic(points[*a as usize], points[*b as usize]);
    let mut sorted = members.clone();
    let middle = sorted.len() / 2;
    let (_, &mut pivot, _) = sorted.select_nth_unstable_by(middle, lexicographic);
    drop(sorted);
    let (left, right): (Vec<u32>, Vec<u32>) =
        members.into_iter().partition(|k| lexicographic(k, &pivot).is_lt());
    (left.len() >= 3 && right.len() >= 3).then_some((left, right))
}

/// The points at `members` inserted one by one; `None` if they are collinear.
fn inserted(points: &[Point], members: Vec<u32>) -> Option<Piece> {
    let mut order = members;
    if !put_first_triangle_first(&mut order, |k| points[k as usize]) {
        return None;
    }
    let mut dt = Dt::new(order.iter().map(|&k| points[k as usize]).collect());
    // The first position of each local vertex, and each position's first occurrence.
    let mut first_position: Vec<u32> = order[..3].to_vec();
    let mut first_of: Vec<(u32, u32)> = order[..3].iter().map(|&k| (k, k)).collect();
    let mut hint = 2;
    for (j, &k) in order.iter().enumerate().skip(3) {
        let (v, new) = dt.insert(j, hint);
        if new {
            first_position.push(k);
        }
        first_of.push((k, first_position[v as usize]));
        hint = v;
    }
    drop(order);
    let (_, mut triangles, halfedges) = dt.finish();
    for v in &mut triangles {
        *v = first_position[*v as usize];
    }
    debug_assert!(halfedges.iter().all(|&h| h == EMPTY || (h as usize) < triangles.len()));
    Some(Piece { part: Part { triangles, halfedges }, first_of })
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
