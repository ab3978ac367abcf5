//! Seams: where longitude/latitude data cut a polygon at the antimeridian.
//!
//! GIS files store an area across ±180° as pieces (RFC 7946 §3.1.9; Natural Earth's Russia
//! and Fiji): each piece's boundary runs along the meridian, and every vertex there is stored
//! twice, at +180 and at -180. The two ends of a cut are where the outline crosses the
//! meridian. Data densified or reprojected has vertices between them too, and those lie
//! inside the area, on no curve: read as points, they draw the cut back as a chord across
//! the area (Fiji's Vanua Levu becomes a network of three paths).
//!
//! A point stored at both +180 and -180 is *between the ends of a cut* when the seam points
//! next to it along the meridian, on both sides, are nearer to it than any point off the
//! meridian: along a cut the next vertex is the cut's own, while at an end the outline's
//! vertices come as near as the seam's. Points at an end, and points stored once, are kept.
//!
//! # Complexity
//! O(n log n): the seam points sorted by latitude, and one nearest-neighbour query each in an
//! R-tree of the points off the meridian.

use rstar::RTree;
use sigdt::Point;

/// How far degree arithmetic (interpolating along a cut edge, reprojecting) leaves a value
/// from where it belongs: 8 units in the last place of 180° (2.5·10⁻¹³°, 28 nm). Natural
/// Earth's Russia, densified, has seam vertices at 180.00000000000006 and latitudes that differ
/// by an ulp between the two pieces.
pub const ROUNDING: f64 = 8.0 * f64::EPSILON * 180.0;

/// Whether `lon` is the antimeridian, either spelling, up to [`ROUNDING`].
pub fn on_meridian(lon: f64) -> bool {
    (lon.abs() - 180.0).abs() <= ROUNDING
}

/// The input indices of the points between the ends of a cut at the antimeridian (module
/// docs), sorted: `degrees` as given, `plane` the same points in a local plane where
/// distances are ground distances.
pub fn between_cut_ends(degrees: &[Point], plane: &[Point]) -> Vec<usize> {
    // The points on the meridian by latitude; runs within ROUNDING are one place, a seam
    // vertex when the place is stored on both sides.
    let mut meridian: Vec<usize> =
        (0..degrees.len()).filter(|&i| on_meridian(degrees[i][0])).collect();
    meridian.sort_by(|&i, &j| degrees[i][1].total_cmp(&degrees[j][1]).then(i.cmp(&j)));
    let mut places: Vec<Vec<usize>> = Vec::new();
    for &i in &meridian {
        match places.last_mut() {
            Some(place) if degrees[i][1] - degrees[place[0]][1] <= ROUNDING => place.push(i),
            _ => places.push(vec![i]),
        }
    }
    let twins: Vec<Vec<usize>> = places
        .into_iter()
        .filter(|place| {
            let east = place.iter().any(|&i| degrees[i][0] > 0.0);
            let west = place.iter().any(|&i| degrees[i][0] < 0.0);
            east && west
        })
        .collect();
    if twins.len() < 3 {
        return Vec::new(); // a cut between two ends has nothing between them
    }
    let seam: Vec<Point> = twins.iter().map(|place| plane[place[0]]).collect();
    let off: Vec<Point> =
        degrees.iter().zip(plane).filter(|(d, _)| !on_meridian(d[0])).map(|(_, &q)| q).collect();
    let tree = RTree::bulk_load(off);
    let squared = |a: Point, b: Point| (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2);
    let mut between: Vec<usize> = Vec::new();
    for k in 1..seam.len() - 1 {
        let reach = squared(seam[k], seam[k - 1]).max(squared(seam[k], seam[k + 1]));
        let nearest_off = tree.nearest_neighbor(&seam[k]).map(|&q| squared(seam[k], q));
        if nearest_off.is_none_or(|d| reach < d) {
            between.extend(&twins[k]);
        }
    }
    between.sort_unstable();
    between
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square island of side 2° centred on the antimeridian at 16° S, its outline every
    /// `step` degrees, stored as two pieces cut at ±180 (each piece's cut edge densified
    /// as its outline is).
    fn cut_island(step: f64) -> Vec<Point> {
        let n = (2.0 / step).round() as usize;
        let lat = |k: usize| -17.0 + 2.0 * k as f64 / n as f64;
        let mut points = Vec::new();
        for side in [1.0, -1.0] {
            let meridian = 180.0 * side;
            for k in 0..=n {
                points.push([meridian, lat(k)]); // the cut, on this piece
                points.push([meridian - side * 1.0, lat(k)]); // the far side
            }
            for k in 1..n / 2 {
                let lon = meridian - side * 2.0 * k as f64 / n as f64;
                points.push([lon, -17.0]);
                points.push([lon, -15.0]);
            }
        }
        points
    }

    fn plane(points: &[Point]) -> Vec<Point> {
        let p = crate::gis::local::LocalProjection::fit(points, "test").unwrap();
        points.iter().map(|&q| p.forward(q)).collect()
    }

    #[test]
    fn the_vertices_between_the_ends_of_a_cut_are_found_and_the_ends_kept() {
        let points = cut_island(0.1);
        let between = between_cut_ends(&points, &plane(&points));
        let lats: Vec<f64> = between.iter().map(|&i| points[i][1]).collect();
        // 19 latitudes strictly between -17 and -15, each stored at +180 and at -180.
        assert_eq!(between.len(), 2 * 19);
        assert!(lats.iter().all(|&l| l > -17.0 + 1e-9 && l < -15.0 - 1e-9), "{lats:?}");
        assert!(between.iter().all(|&i| on_meridian(points[i][0])));
    }

    #[test]
    fn a_cut_with_only_its_ends_and_points_stored_once_are_kept() {
        // Undensified: the cut is its two ends.
        let points = vec![[180.0, -16.0], [-180.0, -16.0], [180.0, -15.0], [-180.0, -15.0]];
        assert!(between_cut_ends(&points, &plane(&points)).is_empty());
        // A line along the meridian stored once is a curve, not a seam.
        let line: Vec<Point> = (0..20).map(|k| [180.0, -16.0 + 0.1 * k as f64]).collect();
        assert!(between_cut_ends(&line, &plane(&line)).is_empty());
    }
}
