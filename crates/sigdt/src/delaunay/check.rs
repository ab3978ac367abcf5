//! The one invariant checker of a [`Triangulation`], for the tests and the `delaunay` fuzz
//! target: everything it promises, checked exactly.
//!
//! A proper triangulation has consistent twins, counter-clockwise triangles, a convex hull
//! that is one cycle, Euler's counts, and every edge between two triangles locally Delaunay
//! under the symbolic perturbation ([`super::perturbation`]); locally Delaunay everywhere
//! under one lifting means globally Delaunay, and the perturbed test never ties, so this also
//! pins the one canonical triangulation. Collinear input and fewer than three distinct points
//! have no triangles and their vertices in lexicographic order along the line.
//!
//! # Complexity
//! O(n) exact predicates.
use super::{next, perturbation, prev, Shape, Triangulation, EMPTY};
use crate::geometry::orient2d;

/// `Err` naming the first broken invariant of `dt`.
pub fn check_delaunay(dt: &Triangulation) -> Result<(), String> {
    let (nv, nh) = (dt.num_vertices() as u32, dt.num_halfedges() as u32);
    if dt.shape() != Shape::Proper {
        return check_line(dt);
    }
    let mut used = vec![false; nv as usize];
    for h in 0..nh {
        let v = dt.origin(h);
        if v >= nv {
            return Err(format!("half-edge {h} starts at vertex {v} of {nv}"));
        }
        used[v as usize] = true;
        let t = dt.twin(h);
        if t != EMPTY && (t >= nh || dt.twin(t) != h || dt.origin(t) != dt.dest(h)) {
            return Err(format!("half-edge {h}: twin {t} does not run back"));
        }
    }
    if let Some(v) = used.iter().position(|&u| !u) {
        return Err(format!("vertex {v} is in no triangle"));
    }
    for t in 0..dt.num_triangles() as u32 {
        let [a, b, c] = [0, 1, 2].map(|k| dt.point(dt.origin(3 * t + k)));
        if orient2d(a, b, c) <= 0.0 {
            return Err(format!("triangle {t} is not counter-clockwise"));
        }
    }
    for h in (0..nh).filter(|&h| h < dt.twin(h) && dt.twin(h) != EMPTY) {
        let t = dt.twin(h);
        let [a, b, c] = [h, next(h), prev(h)].map(|e| dt.point(dt.origin(e)));
        let d = dt.point(dt.origin(prev(t)));
        if perturbation::incircle(a, b, c, d) >= 0.0 {
            return Err(format!("edge of half-edge {h} is not Delaunay"));
        }
    }
    check_hull(dt)
}

/// The hull half-edges form one convex, counter-clockwise cycle; Euler's count holds.
fn check_hull(dt: &Triangulation) -> Result<(), String> {
    let hull: Vec<u32> = (0..dt.num_halfedges() as u32).filter(|&h| dt.twin(h) == EMPTY).collect();
    let mut after = vec![EMPTY; dt.num_vertices()];
    for &h in &hull {
        if !dt.is_hull_vertex(dt.origin(h)) {
            return Err(format!("hull vertex {} does not start at its hull edge", dt.origin(h)));
        }
        after[dt.origin(h) as usize] = dt.dest(h);
    }
    let Some(&first) = hull.first() else { return Err("no hull edge".to_string()) };
    let start = dt.origin(first);
    let (mut u, mut v, mut steps) = (start, after[start as usize], 1);
    while v != start {
        let w = after[v as usize];
        if w == EMPTY || steps > hull.len() {
            return Err(format!("the hull is not one cycle at vertex {v}"));
        }
        if orient2d(dt.point(u), dt.point(v), dt.point(w)) < 0.0 {
            return Err(format!("the hull turns right at vertex {v}"));
        }
        (u, v, steps) = (v, w, steps + 1);
    }
    if steps != hull.len() {
        return Err(format!("{} hull edges, {steps} on the cycle", hull.len()));
    }
    let (nv, nt) = (dt.num_vertices(), dt.num_triangles());
    if nt != 2 * nv - 2 - hull.len() {
        return Err(format!("{nt} triangles, {nv} vertices and {} on the hull", hull.len()));
    }
    Ok(())
}

/// No triangles, and the vertices in strictly increasing lexicographic order.
fn check_line(dt: &Triangulation) -> Result<(), String> {
    if dt.num_triangles() > 0 {
        return Err(format!("{:?} input with triangles", dt.shape()));
    }
    for v in 1..dt.num_vertices() as u32 {
        let (p, q) = (dt.point(v - 1), dt.point(v));
        if (p[0], p[1]) >= (q[0], q[1]) {
            return Err(format!("vertices {} and {v} are out of order along the line", v - 1));
        }
    }
    Ok(())
}
