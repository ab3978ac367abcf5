//! The triangulation as spade builds it, for the tests and the fuzz target that check that
//! [`Triangulation::new`](crate::Triangulation::new) fills the same arrays bit for bit.
//!
//! This is the construction sigdt used before its own insertion (`delaunay/incremental.rs`):
//! the same hygiene, seed and BRIO order, spade's `insert_with_hint` from the previous
//! vertex, and spade's DCEL exported to flat arrays (inner face `f` becomes triangle `f - 1`).
use crate::delaunay::brio::brio_order;
use crate::delaunay::hygiene::Scaling;
use crate::delaunay::EMPTY;
use crate::error::Result;
use crate::geometry::{orient2d, Point};
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, Point2, Triangulation as _};

/// What [`spade_reference`] returns: the arrays a `Triangulation` holds.
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
    /// The same arrays read from a triangulation through its public accessors.
    pub fn of(dt: &crate::Triangulation) -> FlatArrays {
        let hs = 0..dt.num_halfedges() as u32;
        FlatArrays {
            points: (0..dt.num_vertices() as u32).map(|v| dt.point(v)).collect(),
            input_index: (0..dt.num_vertices() as u32).map(|v| dt.input_index(v) as u32).collect(),
            triangles: hs.clone().map(|h| dt.origin(h)).collect(),
            halfedges: hs.map(|h| dt.twin(h)).collect(),
        }
    }
}

/// spade's triangulation of `points`, or `None` when the points span no triangle (collinear
/// or fewer than three distinct); errors as `Triangulation::new`.
pub fn spade_reference(input: &[Point]) -> Result<Option<FlatArrays>> {
    let scaling = Scaling::for_points(input)?;
    let p = |i: u32| scaling.apply(input[i as usize]);
    let n = input.len();
    let seed = (|| {
        if n < 3 {
            return None;
        }
        let b = (1..n as u32).find(|&i| p(i) != p(0))?;
        let c = (b + 1..n as u32).find(|&i| orient2d(p(0), p(b), p(i)) != 0.0)?;
        Some([0, b, c])
    })();
    let Some(seed) = seed else { return Ok(None) };
    let mut dt: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::with_capacity(n, 3 * n, 2 * n + 1);
    let mut input_index: Vec<u32> = Vec::with_capacity(n);
    let mut hint = FixedVertexHandle::from_index(0);
    let mut order: Vec<u32> = seed.to_vec();
    let mut rest: Vec<u32> = (0..n as u32).filter(|i| !seed.contains(i)).collect();
    brio_order(p, &mut rest);
    order.extend(rest);
    for i in order {
        let [x, y] = p(i);
        let before = dt.num_vertices();
        let handle = dt.insert_with_hint(Point2::new(x, y), hint).expect("scaled input");
        if dt.num_vertices() == before {
            let rep = &mut input_index[handle.index()];
            *rep = (*rep).min(i);
        } else {
            input_index.push(i);
        }
        hint = handle;
    }
    let nt = dt.num_inner_faces();
    let mut triangles = Vec::with_capacity(3 * nt);
    for face in dt.inner_faces() {
        for e in face.adjacent_edges() {
            triangles.push(e.from().fix().index() as u32);
        }
    }
    let mut halfedges = vec![EMPTY; 3 * nt];
    for (t, face) in dt.inner_faces().enumerate() {
        for (k, e) in face.adjacent_edges().iter().enumerate() {
            if let Some(other) = e.rev().face().as_inner() {
                let t2 = other.fix().index() - 1;
                let start = e.to().fix().index() as u32;
                let k2 = (0..3).find(|&k2| triangles[3 * t2 + k2] == start).expect("twin");
                halfedges[3 * t + k] = (3 * t2 + k2) as u32;
            }
        }
    }
    let points = dt.vertices().map(|v| [v.position().x, v.position().y]).collect();
    Ok(Some(FlatArrays { points, input_index, triangles, halfedges }))
}
