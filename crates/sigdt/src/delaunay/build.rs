//! Building a [`Triangulation`]: hygiene, degenerate shapes, then the points copied once into
//! BRIO order and inserted one by one into the flat arrays (module `incremental`).
use super::brio::{canonical_order, put_first_triangle_first};
use super::divide::triangulate_divided;
use super::hygiene::Scaling;
use super::incremental::Dt;
use super::relabel::vertex_halfedges;
use super::{Shape, Triangulation, EMPTY};
use crate::error::{Error, Result};
use crate::geometry::Edge;
use crate::geometry::Point;
use std::borrow::Cow;

impl Triangulation {
    /// Triangulates `points` (`docs/algorithms.md` §0.1–0.2).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for NaN or infinite coordinates, [`Error::CoordinateRange`] when
    /// the coordinates span more than about 2^172, [`Error::TooManyPoints`] past `u32`.
    ///
    /// On a pool of several threads and from 2^16 points, the points are divided among the
    /// threads and the parts' triangulations merged (module `divide`): the same vertices
    /// and triangles, stored in another order.
    pub fn new(points: &[Point]) -> Result<Triangulation> {
        Triangulation::build(Cow::Borrowed(points), crate::parallel::halvings(points.len()))
    }

    /// [`new`](Self::new) divided `halvings` times and conquered on the current pool
    /// (module `divide`), whatever the number of points or threads: for the tests that it
    /// builds the same triangulation, and `make bench`.
    #[doc(hidden)]
    pub fn new_divided(points: &[Point], halvings: u32) -> Result<Triangulation> {
        Triangulation::build(Cow::Borrowed(points), halvings)
    }

    /// [`new`](Self::new) on points it owns, which it frees once they are copied into
    /// insertion order, before the triangulation's arrays are allocated.
    pub(crate) fn from_vec(points: Vec<Point>) -> Result<Triangulation> {
        let halvings = crate::parallel::halvings(points.len());
        Triangulation::build(Cow::Owned(points), halvings)
    }

    fn build(points: Cow<'_, [Point]>, halvings: u32) -> Result<Triangulation> {
        // Half-edges are numbered in `u32` (`EMPTY` excluded): at most 6 per point.
        let max = EMPTY as usize / 6;
        if points.len() > max {
            return Err(Error::TooManyPoints { got: points.len(), max });
        }
        let scaling = Scaling::for_points(&points)?;
        let scaled = |i: u32| scaling.apply(points[i as usize]);
        let mut order = canonical_order(scaled, points.len());
        if put_first_triangle_first(&mut order, scaled) {
            proper(points, scaling, order, halvings)
        } else {
            Ok(on_a_line(points.len(), scaled, scaling))
        }
    }
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
    input: Cow<'_, [Point]>,
    scaling: Scaling,
    order: Vec<u32>,
    halvings: u32,
) -> Result<Triangulation> {
    let n = input.len();
    // Reorder once: the points in insertion order, read sequentially from here on.
    let points = crate::parallel::map_slice(&order, |&i| scaling.apply(input[i as usize]));
    drop(input);
    let points = match halvings {
        0 => points,
        _ => match triangulate_divided(points, &order, halvings) {
            Err(points) => points,
            Ok(built) => {
                return Ok(Triangulation {
                    points: built.points,
                    input_index: built.input_index,
                    triangles: built.triangles,
                    halfedges: built.halfedges,
                    vertex_halfedge: built.vertex_halfedge,
                    duplicates: built.duplicates,
                    input_len: n,
                    shape: Shape::Proper,
                    scaling,
                })
            }
        },
    };
    let mut dt = Dt::new(points);
    // `order` becomes `input_index` in place: vertex `v` is written at `v <= k`.
    let mut input_index = order;
    // spade's hint is the last vertex inserted, and the seed's last is vertex 2.
    let mut hint = 2;
    let mut later_duplicates: Vec<(u32, u32)> = Vec::new(); // (input index, vertex)
    for k in 3..n {
        let i = input_index[k];
        let (v, new) = dt.insert(k, hint);
        if new {
            input_index[v as usize] = i;
        } else {
            // Exact duplicate: keep the lowest input index as the representative.
            let rep = &mut input_index[v as usize];
            later_duplicates.push((i.max(*rep), v));
            *rep = (*rep).min(i);
        }
        hint = v;
    }
    input_index.truncate(dt.num_vertices);
    input_index.shrink_to_fit();
    let (points, triangles, halfedges) = dt.finish();
    let vertex_halfedge = vertex_halfedges(points.len(), &triangles, &halfedges);
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

#[cfg(test)]
mod tests {
    use super::super::check::check_delaunay;
    use super::super::{Shape, Triangulation};

    fn check(dt: &Triangulation) {
        check_delaunay(dt).unwrap();
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
