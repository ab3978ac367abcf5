//! Hand-drawn polygons and lines across the antimeridian, checked with `geo` (validity,
//! area) and for exact coordinates.

use super::*;
use geo::{Area, LineString, Polygon, Validation};

/// `rings` as a `geo` polygon (closed by `geo`).
fn to_geo(rings: &[Vec<Point>]) -> Polygon<f64> {
    let ring =
        |r: &Vec<Point>| LineString::from(r.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>());
    Polygon::new(ring(&rings[0]), rings[1..].iter().map(ring).collect())
}

/// Checks every piece: valid, longitudes in [-180, 180], no wider than 180°, each vertex one
/// of `allowed` (bit for bit) or on ±180 exactly; returns the total area.
fn check(pieces: &[Vec<Vec<Point>>], allowed: &[Point]) -> f64 {
    check_within(pieces, allowed, 180.0)
}

/// [`check`], with pieces up to `widest` degrees of longitude wide.
fn check_within(pieces: &[Vec<Vec<Point>>], allowed: &[Point], widest: f64) -> f64 {
    let mut area = 0.0;
    for piece in pieces {
        let polygon = to_geo(piece);
        assert!(polygon.is_valid(), "{piece:?}: {:?}", polygon.check_validation());
        let xs = piece.iter().flatten().map(|p| p[0]);
        let (west, east) =
            xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(w, e), x| (w.min(x), e.max(x)));
        assert!(-180.0 <= west && east <= 180.0 && east - west <= widest, "{piece:?}");
        for p in piece.iter().flatten() {
            let known = allowed
                .iter()
                .any(|a| a[0].to_bits() == p[0].to_bits() && a[1].to_bits() == p[1].to_bits());
            assert!(known || p[0].abs() == 180.0, "{p:?} is neither an input vertex nor on ±180");
        }
        area += polygon.unsigned_area();
    }
    area
}

fn bits(rings: &[Vec<Point>]) -> Vec<[u64; 2]> {
    rings.iter().flatten().map(|p| [p[0].to_bits(), p[1].to_bits()]).collect()
}

#[test]
fn a_square_across_180_becomes_two_pieces_meeting_on_it() {
    let square = vec![vec![[179.0, 0.0], [-179.0, 0.0], [-179.0, 1.0], [179.0, 1.0]]];
    let pieces = split_polygon(&square);
    assert_eq!(pieces.len(), 2, "{pieces:?}");
    assert!((check(&pieces, &square[0]) - 2.0).abs() < 1e-12);
    let mut wests: Vec<f64> =
        pieces.iter().map(|p| p[0].iter().map(|q| q[0]).fold(f64::INFINITY, f64::min)).collect();
    wests.sort_by(f64::total_cmp);
    assert_eq!(wests, [-180.0, 179.0]);
    // Shells counter-clockwise (positive signed area).
    assert!(pieces.iter().all(|p| to_geo(p).signed_area() > 0.0));
}

#[test]
fn a_hole_across_180_stays_inside_its_shell() {
    let shell = vec![[178.0, -2.0], [-178.0, -2.0], [-178.0, 2.0], [178.0, 2.0]];
    let across = vec![[179.5, -1.0], [179.5, 1.0], [-179.5, 1.0], [-179.5, -1.0]];
    let pieces = split_polygon(&[shell.clone(), across.clone()]);
    let allowed: Vec<Point> = shell.iter().chain(&across).copied().collect();
    assert!((check(&pieces, &allowed) - (16.0 - 2.0)).abs() < 1e-12, "{pieces:?}");
    // A hole wholly east of 180 in a shell that starts west of it.
    let east = vec![[-179.0, -1.0], [-179.0, 1.0], [-178.5, 1.0], [-178.5, -1.0]];
    let pieces = split_polygon(&[shell.clone(), east.clone()]);
    let allowed: Vec<Point> = shell.iter().chain(&east).copied().collect();
    assert!((check(&pieces, &allowed) - (16.0 - 1.0)).abs() < 1e-12, "{pieces:?}");
    assert!(pieces.iter().any(|p| p.len() == 2), "the hole is a hole of the eastern piece");
}

#[test]
fn a_ring_through_both_copies_of_its_crossing_points_is_cut_there() {
    // As Russia's outline is stored: the crossing points at +180 and again at -180.
    let ring = vec![
        [170.0, 60.0],
        [180.0, 60.5],
        [-180.0, 60.5],
        [-170.0, 61.0],
        [-170.0, 70.0],
        [-180.0, 69.5],
        [180.0, 69.5],
        [170.0, 70.0],
    ];
    let pieces = split_polygon(std::slice::from_ref(&ring));
    assert_eq!(pieces.len(), 2, "{pieces:?}");
    let area = check(&pieces, &ring);
    let expected = to_geo(&[vec![
        [170.0, 60.0],
        [180.0, 60.5],
        [190.0, 61.0],
        [190.0, 70.0],
        [180.0, 69.5],
        [170.0, 70.0],
    ]]);
    assert!((area - expected.unsigned_area()).abs() < 1e-9, "{area}");
    // The crossing points are the input's, on the side of each piece.
    let all: Vec<Point> = pieces.iter().flatten().flatten().copied().collect();
    for p in [[180.0, 60.5], [-180.0, 60.5], [180.0, 69.5], [-180.0, 69.5]] {
        assert!(all.contains(&p), "{p:?} in {pieces:?}");
    }
}

#[test]
fn densified_edges_keep_every_vertex() {
    // geo's BooleanOps dropped the collinear ones: 21 vertices along the bottom became 2.
    let mut ring: Vec<Point> = (0..=20).map(|i| [170.0 + i as f64, 0.123456789]).collect();
    ring.push([190.0, 10.3]);
    ring.push([170.0, 10.3]);
    let ring: Vec<Point> =
        ring.iter().map(|&[x, y]| [if x > 180.0 { x - 360.0 } else { x }, y]).collect();
    let pieces = split_polygon(std::slice::from_ref(&ring));
    check(&pieces, &ring);
    let vertices: usize = pieces.iter().flatten().map(Vec::len).sum();
    // Every input vertex once, except 180 itself (on both pieces), and the new crossing at
    // the top, also on both.
    assert_eq!(vertices, ring.len() + 1 + 2, "{pieces:?}");
    assert!(pieces.iter().flatten().flatten().any(|p| *p == [180.0, 10.3]));
}

#[test]
fn what_does_not_cross_comes_back_bit_for_bit() {
    let odd = 0.1 + 0.2;
    let polygon = vec![
        vec![[odd, odd], [179.999_999_999, odd], [179.999_999_999, 1.0 / 3.0], [odd, 1.0]],
        vec![[1.0 / 7.0 + 1.0, 0.31], [1.0 / 7.0 + 1.0, 0.32], [2.0 / 3.0 + 1.0, 0.32]],
    ];
    let pieces = split_polygon(&polygon);
    assert_eq!(pieces.len(), 1);
    assert_eq!(bits(&pieces[0]), bits(&polygon));
    let line = vec![[-179.9, odd], [-10.0 / 3.0, 2.0], [100.0, 0.0], [179.999, -odd]];
    assert_eq!(bits(&split_line(&line)), bits(std::slice::from_ref(&line)));
    // Touching 180 from the west is not crossing.
    let touching = vec![vec![[179.0, 0.0], [180.0, 0.0], [180.0, 1.0], [179.0, 1.0]]];
    assert_eq!(bits(&split_polygon(&touching)[0]), bits(&touching));
    let line = vec![[179.0, 0.0], [180.0, 1.0], [179.0, 2.0]];
    assert_eq!(split_line(&line), vec![line]);
}

#[test]
fn a_square_east_of_180_stored_as_180_is_moved_to_minus_180() {
    let square = vec![vec![[180.0, 0.0], [-179.0, 0.0], [-179.0, 1.0], [180.0, 1.0]]];
    let pieces = split_polygon(&square);
    assert_eq!(pieces.len(), 1, "{pieces:?}");
    assert!((check(&pieces, &square[0]) - 1.0).abs() < 1e-12);
    assert!(pieces[0][0].iter().all(|p| p[0] <= -179.0), "{pieces:?}");
    // Longitudes stored in [180, 360] come back in [-180, 180].
    let east = vec![vec![[190.0, 0.0], [200.0, 0.0], [200.0, 1.0]]];
    let mut pieces = split_polygon(&east);
    assert_eq!(pieces.len(), 1);
    let start = pieces[0][0].iter().position(|p| *p == [-170.0, 0.0]).unwrap();
    pieces[0][0].rotate_left(start);
    assert_eq!(pieces, vec![vec![vec![[-170.0, 0.0], [-160.0, 0.0], [-160.0, 1.0]]]]);
}

#[test]
fn a_ring_round_the_north_pole_is_closed_through_it() {
    let ring: Vec<Point> = (0..12).map(|k| [-165.0 + 30.0 * k as f64, 80.0]).collect();
    let pieces = split_polygon(std::slice::from_ref(&ring));
    assert_eq!(pieces.len(), 1, "{pieces:?}");
    // A cap round a pole spans every longitude, from -180 to 180.
    let area = check_within(&pieces, &ring, 360.0);
    assert!((area - 3600.0).abs() < 1e-9, "{area}");
    // Round the south pole, the other way.
    let ring: Vec<Point> = (0..12).map(|k| [165.0 - 30.0 * k as f64, -70.0]).collect();
    let area = check_within(&split_polygon(std::slice::from_ref(&ring)), &ring, 360.0);
    assert!((area - 7200.0).abs() < 1e-9, "{area}");
}

#[test]
fn a_line_crossing_twice_is_cut_twice_with_ends_on_180() {
    let line = vec![[179.0, 0.0], [-179.0, 1.0], [179.0, 2.0]];
    let pieces = split_line(&line);
    assert_eq!(
        pieces,
        vec![
            vec![[179.0, 0.0], [180.0, 0.5]],
            vec![[-180.0, 0.5], [-179.0, 1.0], [-180.0, 1.5]],
            vec![[180.0, 1.5], [179.0, 2.0]],
        ]
    );
    // Through a vertex on 180, and through both copies of one.
    let line = vec![[170.0, 0.0], [180.0, 1.0], [-170.0, 2.0]];
    assert_eq!(
        split_line(&line),
        vec![vec![[170.0, 0.0], [180.0, 1.0]], vec![[-180.0, 1.0], [-170.0, 2.0]]]
    );
    let line = vec![[170.0, 0.0], [180.0, 1.0], [-180.0, 1.0], [-170.0, 2.0]];
    let pieces = split_line(&line);
    assert_eq!(pieces.len(), 2, "{pieces:?}");
    assert_eq!((pieces[0].last(), pieces[1].first()), (Some(&[180.0, 1.0]), Some(&[-180.0, 1.0])));
    // Westwards.
    let line = vec![[-179.0, 0.0], [179.0, 2.0]];
    assert_eq!(
        split_line(&line),
        vec![vec![[-179.0, 0.0], [-180.0, 1.0]], vec![[180.0, 1.0], [179.0, 2.0]]]
    );
}

#[test]
fn random_stars_across_180_keep_their_area_and_vertices() {
    // Star-shaped shells with a star-shaped hole, centred on or near the antimeridian,
    // stored as a reader gives them (longitudes in [-180, 180]).
    let mut rng = sigdt::samplers::Rng::new(7);
    for case in 0..300 {
        let centre = [180.0 + 4.0 * (rng.uniform() - 0.5), 120.0 * (rng.uniform() - 0.5)];
        let size = 0.01 + 20.0 * rng.uniform();
        let star = |rng: &mut sigdt::samplers::Rng, scale: f64, n: usize, clockwise: bool| {
            (0..n)
                .map(|k| {
                    let turn = std::f64::consts::TAU * k as f64 / n as f64;
                    let turn = if clockwise { -turn } else { turn };
                    let r = scale * (0.6 + 0.4 * rng.uniform());
                    [centre[0] + r * turn.cos(), centre[1] + r * turn.sin()]
                })
                .collect::<Vec<Point>>()
        };
        let unwrapped = vec![star(&mut rng, size, 40, false), star(&mut rng, 0.5 * size, 9, true)];
        let stored: Vec<Vec<Point>> = unwrapped
            .iter()
            .map(|ring| {
                ring.iter().map(|&[x, y]| [if x > 180.0 { x - 360.0 } else { x }, y]).collect()
            })
            .collect();
        let pieces = split_polygon(&stored);
        let allowed: Vec<Point> = stored.iter().flatten().copied().collect();
        let area = check(&pieces, &allowed);
        let expected = to_geo(&unwrapped).unsigned_area();
        assert!(
            (area - expected).abs() < 1e-9 * expected.max(1.0),
            "case {case}: {area} {expected}"
        );
        let written: Vec<Point> = pieces.iter().flatten().flatten().copied().collect();
        assert!(allowed.iter().all(|p| written.contains(p)), "case {case}: a vertex was lost");
    }
}
