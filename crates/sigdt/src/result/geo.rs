//! Results as [`geo_types`] geometries (feature `geo-types`), the types that `geo` and the
//! rest of the georust crates compute with.
//!
//! Loops become polygons with holes, grouped as [`Reconstruction::polygons`] groups them
//! (exact predicates): each shell counter-clockwise and each hole clockwise, the orientation
//! of the OGC simple features and RFC 7946. Open paths become line strings. A result on
//! vertices of its own (a denoising method's moved points) uses those vertices.
//!
//! # Complexity
//! That of [`Reconstruction::polygons`], plus O(n) to copy the coordinates.
use super::Reconstruction;
use crate::geometry::Point;
use geo_types::{Coord, LineString, MultiLineString, MultiPolygon, Polygon};

impl Reconstruction {
    /// The loops as polygons with holes: the areas the result outlines. `points` are the
    /// points the result was computed from.
    ///
    /// ```
    /// use geo::{Area, Contains};
    /// use std::f64::consts::TAU;
    ///
    /// // A ring of 24 points round a ring of 12: a disc with a hole.
    /// let ring = |r: f64, n: usize| (0..n).map(move |k| {
    ///     let a = k as f64 * TAU / n as f64;
    ///     [r * a.cos(), r * a.sin()]
    /// });
    /// let points: Vec<[f64; 2]> = ring(4.0, 24).chain(ring(1.0, 12)).collect();
    /// let rec = sigdt::reconstruct(&points, &sigdt::Options::default())?;
    ///
    /// // A geo user's three lines: outlines in, geo's algorithms on them.
    /// let areas = rec.to_multi_polygon(&points);
    /// assert!(!areas.contains(&geo::point!(x: 0.0, y: 0.0)));
    /// let (outer, inner) = (12.0 * 16.0 * (TAU / 24.0).sin(), 6.0 * (TAU / 12.0).sin());
    /// assert!((areas.unsigned_area() - (outer - inner)).abs() < 1e-9);
    /// # Ok::<(), sigdt::Error>(())
    /// ```
    pub fn to_multi_polygon(&self, points: &[Point]) -> MultiPolygon<f64> {
        let vertices = self.vertex_positions(points);
        let ring = |l: usize, reversed: bool| -> LineString<f64> {
            let coord = |&i: &usize| Coord { x: vertices[i][0], y: vertices[i][1] };
            let mut coords: Vec<Coord<f64>> = self.loops[l].iter().map(coord).collect();
            if reversed {
                coords.reverse();
            }
            LineString::new(coords)
        };
        let polygons = self.polygons(vertices).into_iter().map(|polygon| {
            let holes = polygon.holes.iter().map(|&h| ring(h, true)).collect();
            Polygon::new(ring(polygon.shell, false), holes)
        });
        MultiPolygon::new(polygons.collect())
    }

    /// The open paths as line strings. `points` are the points the result was computed
    /// from.
    pub fn to_multi_line_string(&self, points: &[Point]) -> MultiLineString<f64> {
        let vertices = self.vertex_positions(points);
        let line = |path: &Vec<usize>| -> LineString<f64> {
            path.iter().map(|&i| Coord { x: vertices[i][0], y: vertices[i][1] }).collect()
        };
        MultiLineString::new(self.paths.iter().map(line).collect())
    }
}

#[cfg(test)]
mod tests {
    use crate::Reconstruction;

    #[test]
    fn shells_turn_counter_clockwise_and_holes_clockwise() {
        let points = [
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0],
            [1.0, 1.0],
            [3.0, 1.0],
            [3.0, 3.0],
            [1.0, 3.0],
            [9.0, 0.0],
            [9.0, 2.0],
            [9.0, 5.0],
        ];
        let rec = Reconstruction {
            loops: vec![vec![0, 1, 2, 3], vec![4, 5, 6, 7]],
            paths: vec![vec![8, 9, 10]],
            ..Default::default()
        };
        let areas = rec.to_multi_polygon(&points);
        assert_eq!(areas.0.len(), 1);
        let polygon = &areas.0[0];
        let signed = |ring: &geo_types::LineString<f64>| -> f64 {
            ring.0.windows(2).map(|w| w[0].x * w[1].y - w[1].x * w[0].y).sum::<f64>() / 2.0
        };
        assert_eq!(signed(polygon.exterior()), 16.0);
        assert_eq!(polygon.interiors().len(), 1);
        assert_eq!(signed(&polygon.interiors()[0]), -4.0);
        // Rings are closed, as geo-types wants them.
        assert_eq!(polygon.exterior().0.first(), polygon.exterior().0.last());
        let lines = rec.to_multi_line_string(&points);
        assert_eq!(lines.0.len(), 1);
        assert_eq!(lines.0[0].0.len(), 3);
        assert_eq!(lines.0[0].0[2], geo_types::Coord { x: 9.0, y: 5.0 });
    }
}
