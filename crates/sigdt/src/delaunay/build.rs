//! Building a [`Triangulation`]: hygiene, degenerate shapes, spade insertion in BRIO order,
//! export to flat arrays.
use super::brio::brio_order;
use super::hygiene::Scaling;
use super::{Shape, Triangulation, EMPTY};
use crate::error::{Error, Result};
use crate::geometry::Edge;
use crate::geometry::{orient2d, Point};
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, Point2, Triangulation as _};

impl Triangulation {
    /// Triangulates `points` (`docs/algorithms.md` §0.1–0.2).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for NaN or infinite coordinates, [`Error::CoordinateRange`] when
    /// the coordinates span more than about 2^172, [`Error::TooManyPoints`] past `u32`.
    pub fn new(points: &[Point]) -> Result<Triangulation> {
        let scaling = Scaling::for_points(points)?;
        let scaled = |i: u32| scaling.apply(points[i as usize]);
        match first_triangle(points.len(), scaled) {
            Some(seed) => proper(points, scaled, scaling, seed),
            None => Ok(on_a_line(points.len(), scaled, scaling)),
        }
    }
}

/// The first three input points, in input order, that span a triangle: the first point, the
/// first point different from it, and the first point off the line through both. `None` if
/// all points are collinear (or fewer than three are distinct).
///
/// Inserting these first matters: spade is quadratic while all its vertices are collinear.
fn first_triangle(n: usize, p: impl Fn(u32) -> Point) -> Option<[u32; 3]> {
    if n < 3 {
        return None;
    }
    let a = 0;
    let b = (1..n as u32).find(|&i| p(i) != p(a))?;
    let c = (b + 1..n as u32).find(|&i| orient2d(p(a), p(b), p(i)) != 0.0)?;
    Some([a, b, c])
}

/// Collinear input and fewer than three distinct points: vertices sorted along the line
/// (lexicographic order of the coordinates is the order along any line), duplicates merged.
fn on_a_line(n: usize, p: impl Fn(u32) -> Point, scaling: Scaling) -> Triangulation {
    let mut order: Vec<u32> = (0..n as u32).collect();
    order.sort_by(|&i, &j| {
        let (a, b) = (p(i), p(j));
        a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])).then(i.cmp(&j))
    });
    let mut points = Vec::new();
    let mut input_index = Vec::new();
    let mut duplicates = Vec::new();
    for &i in &order {
        if points.last() == Some(&p(i)) {
            duplicates.push([i as usize, *input_index.last().unwrap() as usize]);
        } else {
            points.push(p(i));
            input_index.push(i);
        }
    }
    duplicates.sort_unstable();
    let shape = if points.len() >= 3 { Shape::Collinear } else { Shape::TooFewPoints };
    Triangulation {
        points,
        input_index,
        triangles: Vec::new(),
        halfedges: Vec::new(),
        vertex_halfedge: Vec::new(),
        duplicates,
        input_len: n,
        shape,
        scaling,
    }
}

fn proper(
    input: &[Point],
    p: impl Fn(u32) -> Point,
    scaling: Scaling,
    seed: [u32; 3],
) -> Result<Triangulation> {
    let n = input.len();
    let mut dt: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::with_capacity(n, 3 * n, 2 * n + 1);
    let mut input_index: Vec<u32> = Vec::with_capacity(n);
    let mut later_duplicates: Vec<(u32, u32)> = Vec::new(); // (input index, vertex)
    let mut hint = FixedVertexHandle::from_index(0);
    let mut insert = |i: u32, dt: &mut DelaunayTriangulation<Point2<f64>>| -> Result<()> {
        let [x, y] = p(i);
        let before = dt.num_vertices();
        // Unreachable after `Scaling::for_points`; reported with the caller's numbers.
        let handle = dt.insert_with_hint(Point2::new(x, y), hint).map_err(|_| {
            let raw = input[i as usize];
            let value = if raw[0].abs() <= raw[1].abs() { raw[0] } else { raw[1] };
            Error::CoordinateRange { index: i as usize, value, largest: scaling.largest() }
        })?;
        if dt.num_vertices() == before {
            // Exact duplicate: keep the lowest input index as the representative.
            let rep = &mut input_index[handle.index()];
            later_duplicates.push((i.max(*rep), handle.index() as u32));
            *rep = (*rep).min(i);
        } else {
            input_index.push(i);
        }
        hint = handle;
        Ok(())
    };
    for &i in &seed {
        insert(i, &mut dt)?;
    }
    let mut order: Vec<u32> = (0..n as u32).filter(|i| !seed.contains(i)).collect();
    brio_order(&p, &mut order);
    for &i in &order {
        insert(i, &mut dt)?;
    }
    drop(order);

    let (triangles, halfedges) = export(&dt);
    drop(dt);
    let points: Vec<Point> = input_index.iter().map(|&i| p(i)).collect();
    let mut vertex_halfedge = vec![EMPTY; points.len()];
    for (h, &v) in triangles.iter().enumerate() {
        let slot = &mut vertex_halfedge[v as usize];
        if *slot == EMPTY || halfedges[h] == EMPTY {
            *slot = h as u32;
        }
    }
    let mut duplicates: Vec<Edge> = later_duplicates
        .into_iter()
        .map(|(i, v)| [i as usize, input_index[v as usize] as usize])
        .collect();
    duplicates.sort_unstable();
    Ok(Triangulation {
        points,
        input_index,
        triangles,
        halfedges,
        vertex_halfedge,
        duplicates,
        input_len: n,
        shape: Shape::Proper,
        scaling,
    })
}

/// Spade's DCEL to `triangles` and `halfedges` arrays. Inner face `f` becomes triangle
/// `f - 1` (face 0 is spade's outer face).
fn export(dt: &DelaunayTriangulation<Point2<f64>>) -> (Vec<u32>, Vec<u32>) {
    let nt = dt.num_inner_faces();
    let mut triangles = Vec::with_capacity(3 * nt);
    for face in dt.inner_faces() {
        for e in face.adjacent_edges() {
            triangles.push(e.from().fix().index() as u32);
        }
    }
    let mut halfedges = vec![EMPTY; 3 * nt];
    for (t, face) in dt.inner_faces().enumerate() {
        debug_assert_eq!(face.fix().index(), t + 1);
        for (k, e) in face.adjacent_edges().iter().enumerate() {
            let h = 3 * t + k;
            if halfedges[h] != EMPTY {
                continue;
            }
            if let Some(other) = e.rev().face().as_inner() {
                let t2 = other.fix().index() - 1;
                let start = e.to().fix().index() as u32;
                let k2 =
                    (0..3).find(|&k2| triangles[3 * t2 + k2] == start).expect("twin in neighbour");
                halfedges[h] = (3 * t2 + k2) as u32;
                halfedges[3 * t2 + k2] = h as u32;
            }
        }
    }
    (triangles, halfedges)
}

#[cfg(test)]
mod tests {
    use super::super::{next, Shape, Triangulation, EMPTY};
    use crate::geometry::orient2d;

    fn check(dt: &Triangulation) {
        for h in 0..dt.num_halfedges() as u32 {
            let t = dt.twin(h);
            if t != EMPTY {
                assert_eq!(dt.twin(t), h);
                assert_eq!(dt.origin(t), dt.dest(h));
                assert_eq!(dt.dest(t), dt.origin(h));
            }
        }
        for t in 0..dt.num_triangles() as u32 {
            let [a, b, c] = [3 * t, 3 * t + 1, 3 * t + 2].map(|h| dt.point(dt.origin(h)));
            assert!(orient2d(a, b, c) > 0.0, "triangle {t} not counter-clockwise");
        }
        for v in 0..dt.num_vertices() as u32 {
            for h in dt.outgoing(v) {
                assert_eq!(dt.origin(h), v);
                assert_eq!(dt.origin(next(next(h))), dt.dest(next(h)));
            }
        }
    }

    #[test]
    fn square_has_two_triangles_and_five_edges() {
        let dt = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).unwrap();
        check(&dt);
        assert_eq!(dt.shape(), Shape::Proper);
        assert_eq!(dt.num_triangles(), 2);
        assert_eq!(dt.edges().len(), 5);
        assert_eq!(dt.hull().len(), 4);
    }

    #[test]
    fn euler_counts_on_a_circle_with_centre() {
        let mut pts: Vec<[f64; 2]> = (0..16)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 16.0;
                [a.cos(), a.sin()]
            })
            .collect();
        pts.push([0.0, 0.0]);
        let dt = Triangulation::new(&pts).unwrap();
        check(&dt);
        let (m, h) = (dt.num_vertices(), dt.hull().len());
        assert_eq!(dt.num_triangles(), 2 * m - 2 - h);
        assert_eq!(dt.edges().len(), 3 * m - 3 - h);
        for v in 0..m as u32 {
            assert_eq!(dt.outgoing(v).count() + usize::from(dt.is_hull_vertex(v)), {
                let i = dt.input_index(v);
                dt.edges().iter().filter(|e| e.contains(&i)).count()
            });
        }
    }

    #[test]
    fn duplicates_map_to_lowest_index() {
        let pts =
            [[1.0, 1.0], [0.0, 0.0], [2.0, 0.0], [0.0, 0.0], [1.0, 1.0], [1.0, 3.0], [-0.0, 0.0]];
        let dt = Triangulation::new(&pts).unwrap();
        check(&dt);
        assert_eq!(dt.num_vertices(), 4);
        assert_eq!(dt.duplicates(), &[[3, 1], [4, 0], [6, 1]]);
    }

    #[test]
    fn collinear_and_tiny_inputs_have_no_triangles() {
        let dt = Triangulation::new(&[[2.0, 2.0], [0.0, 0.0], [1.0, 1.0], [3.0, 3.0], [1.0, 1.0]])
            .unwrap();
        assert_eq!(dt.shape(), Shape::Collinear);
        assert_eq!(dt.edges(), vec![[0, 2], [0, 3], [1, 2]]);
        assert_eq!(dt.duplicates(), &[[4, 2]]);
        let dt = Triangulation::new(&[[0.0, 0.0], [0.0, 0.0]]).unwrap();
        assert_eq!((dt.shape(), dt.num_vertices()), (Shape::TooFewPoints, 1));
        let dt = Triangulation::new(&[]).unwrap();
        assert_eq!((dt.shape(), dt.num_vertices()), (Shape::TooFewPoints, 0));
    }

    #[test]
    fn many_collinear_points_then_one_off_the_line() {
        let mut pts: Vec<[f64; 2]> = (0..20_000).map(|i| [i as f64, 2.0 * i as f64]).collect();
        pts.push([5.0, 0.0]);
        let dt = Triangulation::new(&pts).unwrap();
        assert_eq!(dt.shape(), Shape::Proper);
        assert_eq!(dt.num_triangles(), 19_999);
    }

    #[test]
    fn non_finite_is_an_error() {
        assert!(Triangulation::new(&[[0.0, 0.0], [1.0, f64::INFINITY], [0.0, 1.0]]).is_err());
    }
}
