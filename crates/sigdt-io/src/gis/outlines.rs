//! A result's outlines as coordinates, the one walk every geometry writer shares: loops
//! grouped into polygons with holes, open paths told apart by whether an end is a junction;
//! and, for longitude and latitude, loops grouped in a local plane (in degrees, a ring across
//! ±180 would not contain its holes) and every outline cut at the antimeridian
//! ([`antimeridian`](super::antimeridian)), so that it is valid in EPSG:4326.
//!
//! Shells run counter-clockwise and holes clockwise (OGC, RFC 7946); rings are not closed.

use sigdt::{Point, Reconstruction};

use super::antimeridian::{split_line, split_polygon};
use super::local::LocalProjection;

/// The outlines of a result, in the coordinates of its vertices.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Outlines {
    /// The polygons: each a shell and its holes, as [`Reconstruction::polygons`] groups
    /// them (after the cut at the antimeridian, the pieces of each in turn).
    pub polygons: Vec<Vec<Vec<Point>>>,
    /// How many vertices the loops have (before any cut).
    pub loop_vertices: usize,
    /// The open paths, in the order of [`Reconstruction::paths`].
    pub lines: Vec<Line>,
}

/// One open path of a result.
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    /// Its line, or its pieces once cut at the antimeridian.
    pub pieces: Vec<Vec<Point>>,
    /// How many vertices it has (before any cut).
    pub vertices: usize,
    /// Whether an end is a junction ([`Reconstruction::junctions`]): a path of a network.
    pub at_junction: bool,
}

/// The outlines of `rec`, computed from `points`; `lon_lat` when the points are longitude
/// and latitude in degrees (grouped in a local plane, cut at the antimeridian).
pub fn outlines(points: &[Point], rec: &Reconstruction, lon_lat: bool) -> Outlines {
    let vertices = rec.vertex_positions(points);
    let ring = |l: usize| rec.loops[l].iter().map(|&i| vertices[i]).collect::<Vec<Point>>();
    // Loops do not cross in the plane they were found in; in degrees they may seem to.
    let plane = lon_lat.then(|| LocalProjection::fit(vertices, "").ok()).flatten();
    let projected: Vec<Point>;
    let nesting = match plane {
        Some(plane) if !rec.loops.is_empty() => {
            projected = vertices.iter().map(|&p| plane.forward(p)).collect();
            &projected
        }
        _ => vertices,
    };
    let mut polygons = Vec::new();
    for polygon in rec.polygons(nesting) {
        let holes = polygon.holes.iter().map(|&h| {
            let mut hole = ring(h);
            hole.reverse();
            hole
        });
        let rings: Vec<Vec<Point>> = std::iter::once(ring(polygon.shell)).chain(holes).collect();
        match lon_lat {
            true => polygons.extend(split_polygon(&rings)),
            false => polygons.push(rings),
        }
    }
    let junctions = rec.junctions();
    let is_junction = |i: &usize| junctions.binary_search(i).is_ok();
    let lines = rec
        .paths
        .iter()
        .map(|path| {
            let line: Vec<Point> = path.iter().map(|&i| vertices[i]).collect();
            let ends = [path.first(), path.last()];
            Line {
                pieces: if lon_lat { split_line(&line) } else { vec![line] },
                vertices: path.len(),
                at_junction: ends.into_iter().flatten().any(is_junction),
            }
        })
        .collect();
    Outlines { polygons, loop_vertices: rec.loops.iter().map(Vec::len).sum(), lines }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_island_with_a_lake_across_180_keeps_its_lake_and_is_cut() {
        // A square from 179 to -179 with a square lake inside it, also across 180: in
        // degrees the lake is not inside the island, in the local plane it is.
        let points = [
            [179.0, -1.0],
            [-179.0, -1.0],
            [-179.0, 1.0],
            [179.0, 1.0],
            [179.5, -0.5],
            [179.5, 0.5],
            [-179.5, 0.5],
            [-179.5, -0.5],
        ];
        let rec = Reconstruction {
            loops: vec![vec![0, 1, 2, 3], vec![4, 7, 6, 5]],
            ..Reconstruction::default()
        };
        let cut = outlines(&points, &rec, true);
        assert_eq!(cut.polygons.len(), 2, "{cut:?}");
        assert_eq!(cut.loop_vertices, 8);
        for piece in &cut.polygons {
            assert!(piece.iter().flatten().all(|p| p[0].abs() >= 179.0), "{piece:?}");
        }
        let area: f64 = cut.polygons.iter().flatten().map(|ring| shoelace(ring)).sum();
        assert!((area - 3.0).abs() < 1e-12, "the island less its lake: {area}");
        // In the plane, the loops are what they are: here the lake is a separate polygon.
        assert_eq!(outlines(&points, &rec, false).polygons.len(), 2);
    }

    /// The signed area of `ring` (positive counter-clockwise).
    fn shoelace(ring: &[Point]) -> f64 {
        let n = ring.len();
        (0..n)
            .map(|i| {
                let (a, b) = (ring[i], ring[(i + 1) % n]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f64>()
            / 2.0
    }

    #[test]
    fn paths_ending_at_a_junction_are_told_apart() {
        // A T: the bar's two halves and the stem meet at point 1.
        let points = [[-1.0, 0.0], [0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [5.0, 5.0], [6.0, 5.0]];
        let rec = Reconstruction {
            edges: vec![[0, 1], [1, 2], [1, 3], [4, 5]],
            paths: vec![vec![0, 1], vec![1, 2], vec![1, 3], vec![4, 5]],
            ..Reconstruction::default()
        };
        let lines = outlines(&points, &rec, false).lines;
        let at: Vec<bool> = lines.iter().map(|l| l.at_junction).collect();
        assert_eq!(at, [true, true, true, false]);
        assert_eq!(lines[3].pieces, vec![vec![[5.0, 5.0], [6.0, 5.0]]]);
    }
}
