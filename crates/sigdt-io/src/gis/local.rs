//! Longitude and latitude reconstructed in a plane that fits them: the azimuthal
//! equidistant projection centred on the points (Snyder, "Map Projections: A Working
//! Manual", USGS 1395, 1987, §25, spherical form).
//!
//! In degrees a step east is cos(latitude) times as long on the ground as a step north, so
//! spheres of influence and every length sigdt compares would depend on the latitude (at
//! 60° N, twice). The projection keeps distances from its centre exact and every other
//! distance within 1 % over 800 km around it; the reconstruction indexes the input points,
//! so results are written in the input's own coordinates. Only vertices a method places
//! itself are projected back.

use anyhow::{bail, Result};
use std::collections::HashMap;

use sigdt::{LeftOut, LeftOutReason, Options, Point, Reconstruction, Vertices};

use super::Crs;

/// Why points are longitude and latitude in degrees, if they are: their coordinate system
/// is geographic, or a table's columns are named so (`lon_lat`).
pub fn why_degrees(crs: Option<&Crs>, lon_lat: bool) -> Option<String> {
    match crs {
        Some(crs) if crs.is_geographic() == Some(true) => {
            Some(format!("{crs} is longitude/latitude"))
        }
        _ if lon_lat => Some("the columns are longitude and latitude".to_string()),
        _ => None,
    }
}

/// The sphere's radius: the mean Earth radius R₁ of IUGG 1980, in metres.
const RADIUS: f64 = 6_371_008.8;

/// An azimuthal equidistant projection centred at a longitude and latitude.
#[derive(Debug, Clone, Copy)]
pub struct LocalProjection {
    /// The centre's longitude in radians.
    lon0: f64,
    /// Sine and cosine of the centre's latitude.
    sin0: f64,
    cos0: f64,
}

impl LocalProjection {
    /// The projection centred on `points` (longitude, latitude in degrees): the mean
    /// latitude and the circular mean longitude (so a group across the antimeridian is
    /// centred on it). Refuses points that are not longitude and latitude (`what` says
    /// why they should be), and points spread over more than a hemisphere around the
    /// centre (90° of arc, 10,000 km), which no local plane shows.
    pub fn fit(points: &[Point], what: &str) -> Result<LocalProjection> {
        for (k, p) in points.iter().enumerate() {
            if !(-180.0..=360.0).contains(&p[0]) || !(-90.0..=90.0).contains(&p[1]) {
                bail!(
                    "{what}, but point {k} ({:?}, {:?}) is not a longitude and a latitude in \
                     degrees: is the coordinate system right?",
                    p[0],
                    p[1]
                );
            }
        }
        let n = points.len().max(1) as f64;
        let (s, c) = points.iter().fold((0.0, 0.0), |(s, c), p| {
            let lon = p[0].to_radians();
            (s + lon.sin(), c + lon.cos())
        });
        let lat0 = (points.iter().map(|p| p[1]).sum::<f64>() / n).to_radians();
        let lon0 = if s == 0.0 && c == 0.0 { 0.0 } else { s.atan2(c) };
        let projection = LocalProjection { lon0, sin0: lat0.sin(), cos0: lat0.cos() };
        if let Some(k) =
            points.iter().position(|&p| projection.angle(p) > 0.5 * std::f64::consts::PI)
        {
            bail!(
                "{what}, and point {k} lies more than 10,000 km (90° of arc) from the points' \
                 centre: sigdt reconstructs curves in a local plane, so split the data by region"
            );
        }
        Ok(projection)
    }

    /// How far `lon` (degrees, in [-180, 360] as `fit` checks) lies east of the centre, in
    /// radians within [-π, π]. One meridian's spellings (+180 and -180, 10 and 370) are first
    /// made one number, exactly (`lon - 360` is exact for `lon` in [180, 360], Sterbenz), so
    /// a ±180 copy of a point is an exact duplicate, not a point 10⁻⁹ m away; the
    /// antimeridian is recognised up to rounding ([`seam::ROUNDING`](super::seam::ROUNDING)).
    fn east_of_centre(&self, lon: f64) -> f64 {
        // The antimeridian up to rounding is -180 exactly.
        let lon = if super::seam::on_meridian(lon) { -180.0 } else { lon };
        let lon = if lon >= 180.0 { lon - 360.0 } else { lon };
        let d = lon - self.lon0.to_degrees();
        let d = if d > 180.0 {
            d - 360.0
        } else if d < -180.0 {
            d + 360.0
        } else {
            d
        };
        d.to_radians()
    }

    /// The angle at the Earth's centre between the projection's centre and `p`.
    fn angle(&self, [lon, lat]: Point) -> f64 {
        let (lat, dlon) = (lat.to_radians(), self.east_of_centre(lon));
        let cos_c = self.sin0 * lat.sin() + self.cos0 * lat.cos() * dlon.cos();
        cos_c.clamp(-1.0, 1.0).acos()
    }

    /// `p` (longitude, latitude in degrees) in metres east and north of the centre.
    pub fn forward(&self, p: Point) -> Point {
        // A pole is one place whatever its longitude (Antarctica's outline runs along
        // -90° from 180° to -180°): one spelling, so that its copies are exact duplicates.
        let p = if p[1].abs() == 90.0 { [0.0, p[1]] } else { p };
        let (lat, dlon) = (p[1].to_radians(), self.east_of_centre(p[0]));
        let c = self.angle(p);
        // c / sin c, which tends to 1 at the centre.
        let k = if c < 1e-8 { 1.0 } else { c / c.sin() };
        let x = k * lat.cos() * dlon.sin();
        let y = k * (self.cos0 * lat.sin() - self.sin0 * lat.cos() * dlon.cos());
        [RADIUS * x, RADIUS * y]
    }

    /// The longitude and latitude in degrees of the point `q` metres from the centre.
    pub fn inverse(&self, q: Point) -> Point {
        let (x, y) = (q[0] / RADIUS, q[1] / RADIUS);
        let c = x.hypot(y);
        if c == 0.0 {
            return [self.lon0.to_degrees(), self.sin0.atan2(self.cos0).to_degrees()];
        }
        let (sin_c, cos_c) = c.sin_cos();
        let lat = (cos_c * self.sin0 + y * sin_c * self.cos0 / c).clamp(-1.0, 1.0).asin();
        let lon = self.lon0 + (x * sin_c).atan2(c * self.cos0 * cos_c - y * self.sin0 * sin_c);
        let lon = lon.to_degrees();
        // Back into [-180, 180].
        let lon = (lon + 180.0).rem_euclid(360.0) - 180.0;
        [lon, lat.to_degrees()]
    }
}

/// Reconstructs the longitude/latitude `points` in their local plane (refused as
/// [`LocalProjection::fit`] refuses, `what` saying why they are degrees); vertices a method
/// places itself come back in degrees, and so do the places the findings name. The indices
/// refer to `points`, as always. Points between the ends of a cut at the antimeridian
/// (the module `seam`) are left out as [`LeftOutReason::Seam`].
pub fn reconstruct_in_plane(
    points: &[Point],
    options: &Options,
    what: &str,
) -> Result<Reconstruction> {
    let plane = LocalProjection::fit(points, what)?;
    let projected: Vec<Point> = points.iter().map(|&p| plane.forward(p)).collect();
    let seam = super::seam::between_cut_ends(points, &projected);
    let mut rec = if seam.is_empty() {
        sigdt::reconstruct_owned(projected, options)?
    } else {
        without_seam(&projected, &seam, options)?
    };
    if let Vertices::Moved(placed) | Vertices::New(placed) = &mut rec.vertices {
        placed.iter_mut().for_each(|p| *p = plane.inverse(*p));
    }
    for finding in &mut rec.diagnosis {
        finding.point = points[finding.at];
    }
    Ok(rec)
}

/// The reconstruction of `projected` but the points `seam` (sorted), left out as
/// [`LeftOutReason::Seam`]: the others reconstructed alone, their indices lifted back.
fn without_seam(projected: &[Point], seam: &[usize], options: &Options) -> Result<Reconstruction> {
    let mut on_seam = vec![false; projected.len()];
    seam.iter().for_each(|&i| on_seam[i] = true);
    let kept: Vec<usize> = (0..projected.len()).filter(|&i| !on_seam[i]).collect();
    let mut rec = sigdt::reconstruct_owned(kept.iter().map(|&i| projected[i]).collect(), options)?;
    // `kept` increases, so lifting keeps every order the result promises (sorted edges,
    // loops starting at their smallest index).
    let lift = |i: &mut usize| *i = kept[*i];
    if !matches!(rec.vertices, Vertices::New(_)) {
        rec.edges.iter_mut().flatten().for_each(lift);
        rec.loops.iter_mut().flatten().for_each(lift);
        rec.paths.iter_mut().flatten().for_each(lift);
    }
    if let Vertices::Moved(moved) = &mut rec.vertices {
        let mut all = projected.to_vec();
        kept.iter().zip(moved.iter()).for_each(|(&i, &p)| all[i] = p);
        *moved = all;
    }
    rec.duplicates.iter_mut().flatten().for_each(lift);
    rec.left_out.iter_mut().for_each(|l| lift(&mut l.index));
    rec.diagnosis.iter_mut().for_each(|f| lift(&mut f.at));
    // A seam point's copy at the other spelling projects to the same point: a duplicate of
    // the first, as the kernel lists duplicates.
    let mut first: HashMap<[u64; 2], usize> = HashMap::new();
    for &i in seam {
        let key = projected[i].map(f64::to_bits);
        match first.get(&key) {
            Some(&representative) => rec.duplicates.push([i, representative]),
            None => {
                first.insert(key, i);
                rec.left_out.push(LeftOut { index: i, reason: LeftOutReason::Seam });
            }
        }
    }
    rec.duplicates.sort_unstable();
    rec.left_out.sort_unstable_by_key(|l| l.index);
    rec.stats.points = projected.len();
    rec.stats.distinct_points += first.len();
    Ok(rec)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_are_ground_distances_at_every_latitude() {
        for lat in [0.0, 30.0, 60.0, -75.0] {
            let p = LocalProjection::fit(&[[10.0, lat]], "test").unwrap();
            // One degree of latitude and cos(lat) of a degree of longitude are the same
            // length on the ground, about 111.2 km.
            let north = p.forward([10.0, lat + 0.01]);
            let east = p.forward([10.0 + 0.01 / f64::cos(f64::to_radians(lat)), lat]);
            let (dn, de) = (north[0].hypot(north[1]), east[0].hypot(east[1]));
            assert!((dn - 1111.95).abs() < 0.1, "{lat}: {dn}");
            assert!((de / dn - 1.0).abs() < 1e-4, "{lat}: {de} {dn}");
        }
    }

    #[test]
    fn inverse_undoes_forward() {
        let points = [[179.9, 10.0], [-179.9, 10.2], [179.95, 9.9]];
        let p = LocalProjection::fit(&points, "test").unwrap();
        for q in points {
            let back = p.inverse(p.forward(q));
            assert!(
                (back[0] - q[0]).abs() < 1e-9 && (back[1] - q[1]).abs() < 1e-9,
                "{q:?} {back:?}"
            );
        }
        // Across the antimeridian the centre is between the points, not at 0°.
        assert!(p.forward(points[0])[0].abs() < 20_000.0);
    }

    #[test]
    fn a_meridian_or_a_pole_spelled_twice_projects_to_one_point() {
        let points = [[179.5, -16.0], [180.0, -16.5], [-180.0, -16.5], [-179.5, -17.0]];
        for centre in [&points[..], &[[10.0, 0.0]][..], &[[-179.9, 80.0]][..]] {
            let p = LocalProjection::fit(centre, "test").unwrap();
            assert_eq!(p.forward([180.0, -16.5]), p.forward([-180.0, -16.5]));
            assert_eq!(p.forward([10.0, 5.0]), p.forward([370.0, 5.0]));
            assert_eq!(p.forward([-180.0, -90.0]), p.forward([56.3, -90.0]));
        }
        // So the copy is an exact duplicate of the reconstruction, not a second point.
        let mut ring: Vec<Point> = (0..24)
            .map(|k| k as f64 * std::f64::consts::TAU / 24.0)
            .map(|t| [180.0 + 0.5 * t.cos(), -16.5 + 0.5 * t.sin()])
            .map(|[x, y]| [if x > 180.0 { x - 360.0 } else { x }, y])
            .collect();
        ring.push([-180.0, -16.0]); // point 6 is [180, -16]
        let rec = reconstruct_in_plane(&ring, &Options::default(), "test").unwrap();
        assert_eq!(ring[6], [180.0, -16.0]);
        assert_eq!(rec.duplicates, vec![[24, 6]]);
        assert_eq!(rec.loops.len(), 1);
    }

    #[test]
    fn what_is_not_longitude_and_latitude_is_refused() {
        let err = LocalProjection::fit(&[[400_000.0, 300_000.0]], "EPSG:4326 says degrees")
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("point 0 (400000.0, 300000.0) is not a longitude and a latitude"),
            "{err}"
        );
        let spread = [[-170.0, 0.0], [-10.0, 0.0], [90.0, 0.0]];
        let err = LocalProjection::fit(&spread, "x").unwrap_err().to_string();
        assert!(err.contains("point 0 lies more than 10,000 km"), "{err}");
    }
}
