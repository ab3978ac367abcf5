//! spade's Delaunay triangulation as a test-only reference, and the flat arrays of a
//! [`Triangulation`](crate::Triangulation) for comparing two of them.
//!
//! Where no four points are cocircular the Delaunay triangulation is unique, so spade's
//! edges must equal [`Triangulation::edges`](crate::Triangulation::edges) there. (Until the
//! triangulation became canonical, sigdt's insertion was a step-for-step port of spade's and
//! matched its arrays bit for bit; on cocircular points the two now differ by design.)
use crate::delaunay::brio::canonical_order;
use crate::delaunay::hygiene::Scaling;
use crate::error::Result;
use crate::geometry::{Edge, Point};
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, Point2, Triangulation as _};

/// The arrays a `Triangulation` holds, read through its public accessors.
#[derive(Debug, Clone, PartialEq)]
pub struct FlatArrays {
    /// Scaled vertex positions in vertex order.
    pub points: Vec<Point>,
    /// Input index of each vertex (the lowest among exact duplicates).
    pub input_index: Vec<u32>,
    /// Three vertices per triangle, counter-clockwise.
    pub triangles: Vec<u32>,
    /// Twin of each half-edge, `EMPTY` on the hull.
    pub halfedges: Vec<u32>,
}

impl FlatArrays {
    /// The arrays of `dt`.
    pub fn of(dt: &crate::Triangulation) -> FlatArrays {
        let hs = 0..dt.num_halfedges() as u32;
        FlatArrays {
            points: (0..dt.num_vertices() as u32).map(|v| dt.point(v)).collect(),
            input_index: (0..dt.num_vertices() as u32).map(|v| dt.input_index(v) as u32).collect(),
            triangles: hs.clone().map(|h| dt.origin(h)).collect(),
            halfedges: hs.map(|h| dt.twin(h)).collect(),
        }
    }

    /// The triangles whatever their layout: each from its smallest vertex
    /// (counter-clockwise kept), sorted.
    pub fn triangle_set(&self) -> Vec<[u32; 3]> {
        let mut out: Vec<[u32; 3]> = self
            .triangles
            .chunks_exact(3)
            .map(|t| crate::delaunay::from_smallest([t[0], t[1], t[2]]))
            .collect();
        out.sort_unstable();
        out
    }
}

/// spade's Delaunay edges of `points` as sorted input-index pairs (duplicates by their
/// lowest index), or `None` when spade finds no triangle (collinear input, fewer than three
/// distinct points); errors as `Triangulation::new`.
pub fn spade_reference(input: &[Point]) -> Result<Option<Vec<Edge>>> {
    let scaling = Scaling::for_points(input)?;
    let p = |i: u32| scaling.apply(input[i as usize]);
    let mut dt: DelaunayTriangulation<Point2<f64>> = DelaunayTriangulation::new();
    let mut input_index: Vec<usize> = Vec::new();
    let mut hint = FixedVertexHandle::from_index(0);
    for i in canonical_order(p, input.len()) {
        let [x, y] = p(i);
        let before = dt.num_vertices();
        let handle = dt.insert_with_hint(Point2::new(x, y), hint).expect("scaled input");
        if dt.num_vertices() == before {
            let rep = &mut input_index[handle.index()];
            *rep = (*rep).min(i as usize);
        } else {
            input_index.push(i as usize);
        }
        hint = handle;
    }
    if dt.num_inner_faces() == 0 {
        return Ok(None);
    }
    let mut edges: Vec<Edge> = dt
        .undirected_edges()
        .map(|e| {
            let [a, b] = e.vertices().map(|v| input_index[v.fix().index()]);
            [a.min(b), a.max(b)]
        })
        .collect();
    edges.sort_unstable();
    Ok(Some(edges))
}
