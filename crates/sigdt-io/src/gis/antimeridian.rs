//! Outlines in longitude/latitude made valid in EPSG:4326: cut at the antimeridian.
//!
//! A group of points across ±180 is reconstructed in a plane that does not cut there
//! ([`local`](super::local)), but its outlines are written in the input's degrees, where a
//! ring that crosses jumps by about 360°: read as it stands, it runs round the world the
//! other way. GIS readers (and RFC 7946 §3.1.9 for GeoJSON) want such a geometry cut in
//! two at the antimeridian, every longitude in [-180, 180].
//!
//! # Steps
//! 1. Unwrap every ring so that consecutive longitudes differ by at most 180°. A hole is
//!    shifted by the multiple of 360° that puts its first vertex within its shell's
//!    longitudes (nearest the shell's first vertex), so it stays inside. A ring that goes
//!    round a pole (its longitudes end 360° from where they start) is closed through that
//!    pole (the one on the side of its mean latitude), along the antimeridian.
//! 2. If every longitude is then in [-180, 180] and nothing moved, the polygon is returned
//!    as given, bit for bit. Otherwise each edge that crosses a line 180° + k·360° gets a
//!    vertex there (longitude exactly on the line, latitude interpolated linearly in
//!    degrees), and the polygon is intersected with the boxes [-180, 180] + k·360°, each
//!    piece shifted back into [-180, 180].
//! 3. Every vertex of a piece is then the input's own coordinates (bit for bit), or a
//!    crossing vertex of step 2 (exactly ±180), or a pole vertex of step 1.
//!
//! Lines are cut the same way, by hand: a cut is a vertex on ±180 ending one piece and
//! starting the next.
//!
//! # Why `i_overlay` and not `geo`'s `BooleanOps`
//! The intersection is `i_overlay`'s, the engine under `geo`'s `BooleanOps`, called
//! directly for two options `geo` fixes: collinear vertices are kept (`geo` drops them, so a
//! densified straight edge loses its points: 21 vertices along one edge came back as 2),
//! and the integer grid is centred on 0 with a power-of-two scale, so ±180 and the box
//! corners are exact grid values (`geo` centres it on the bounding box: 10.3 came back as
//! 10.300000190734863). Output vertices are then mapped back to the exact coordinates they
//! came from through that grid.
//!
//! # Orientation
//! A split polygon comes back with shells counter-clockwise and holes clockwise (OGC,
//! RFC 7946); one that is not split keeps its rings as given. Rings are not closed.
//!
//! # Complexity
//! O(n) for a polygon or line that does not cross; otherwise that of `i_overlay` (about
//! O(n log n) per box crossed).

use std::collections::HashMap;

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay::{ContourDirection, ShapeType};
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::{FloatOverlay, OverlayOptions};
use i_overlay::i_float::adapter::FloatPointAdapter;
use i_overlay::i_float::float::rect::FloatRect;
use sigdt::Point;

/// One polygon (shell then holes, rings not closed, lon/lat degrees as the input stores them,
/// so a ring may jump by ~360° where it crosses ±180) as polygons that are valid in
/// EPSG:4326: every longitude in [-180, 180], split at the antimeridian. A polygon that does
/// not cross comes back unchanged (same coordinates, bit for bit).
pub fn split_polygon(rings: &[Vec<Point>]) -> Vec<Vec<Vec<Point>>> {
    let Some(shell) = rings.first().filter(|shell| shell.len() >= 3) else {
        return vec![rings.to_vec()];
    };
    let mut unwrapped: Vec<Vec<Vertex>> = vec![unwrap(shell, shell[0][0])];
    let (west, east) = longitude_range(&unwrapped[0]);
    for hole in &rings[1..] {
        let Some(first) = hole.first() else { continue };
        let reference = hole_reference(first[0], west, east, unwrapped[0][0].at[0]);
        unwrapped.push(unwrap(hole, reference));
    }
    let moved = unwrapped.iter().flatten().any(|v| v.at != v.stored);
    // Every ring is closed (no short cut past the first polar one).
    let polar = unwrapped.iter_mut().map(close_round_a_pole).filter(|&closed| closed).count() > 0;
    let inside = unwrapped.iter().flatten().all(|v| (-180.0..=180.0).contains(&v.at[0]));
    if inside && !moved && !polar {
        return vec![rings.to_vec()];
    }
    let rings: Vec<Vec<Vertex>> = unwrapped.iter().map(|ring| with_crossings(ring, true)).collect();
    let (west, east) = rings.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(w, e), ring| {
        let (rw, re) = longitude_range(ring);
        (w.min(rw), e.max(re))
    });
    (box_of(west)..=box_of(east)).flat_map(|k| pieces_in_box(&rings, k)).collect()
}

/// One open line likewise: cut where it crosses ±180 (latitude interpolated linearly in
/// degrees), each piece's end on exactly +180 or −180.
pub fn split_line(line: &[Point]) -> Vec<Vec<Point>> {
    let Some(first) = line.first() else { return vec![line.to_vec()] };
    let unwrapped = with_crossings(&unwrap(line, first[0]), false);
    let inside = unwrapped.iter().all(|v| (-180.0..=180.0).contains(&v.at[0]));
    if inside && unwrapped.len() == line.len() && unwrapped.iter().all(|v| v.at == v.stored) {
        return vec![line.to_vec()];
    }
    // The box of the first vertex: where the line goes next, for a vertex on a boundary.
    let next_x = unwrapped.iter().map(|v| v.at[0]).find(|&x| x != unwrapped[0].at[0]);
    let mut k = side_box(unwrapped[0].at[0], next_x.unwrap_or(unwrapped[0].at[0]));
    let mut pieces = Vec::new();
    let mut piece: Vec<Point> = Vec::new();
    for (i, v) in unwrapped.iter().enumerate() {
        let x = v.at[0] - 360.0 * k as f64;
        if x.abs() == 180.0 {
            // On a boundary: it ends this piece and starts the next when the line goes on
            // to the other side.
            piece.push(v.exact(k));
            let next = unwrapped[i + 1..].iter().map(|w| w.at[0]).find(|&w| w != v.at[0]);
            if let Some(next) = next {
                let beyond = side_box(v.at[0], next);
                if beyond != k {
                    pieces.push(std::mem::take(&mut piece));
                    k = beyond;
                    piece.push(v.exact(k));
                }
            }
        } else {
            piece.push(v.exact(k));
        }
    }
    pieces.push(piece);
    pieces.retain(|piece| piece.len() >= 2);
    pieces
}

/// A vertex unwrapped (`at`), with the coordinates the input stores for it (`stored`); a
/// vertex this module adds stores its own.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Vertex {
    at: Point,
    stored: Point,
}

impl Vertex {
    /// The coordinates written for it in box `k` (shifted by `-k·360°`): exactly ±180 on a
    /// boundary, else the input's own longitude brought into [-180, 180].
    fn exact(&self, k: i64) -> Point {
        let x = self.at[0] - 360.0 * k as f64;
        if x.abs() == 180.0 {
            return [x, self.stored[1]];
        }
        let lon = self.stored[0];
        // Exact (Sterbenz) for every longitude the readers accept, [-180, 360].
        let lon = if lon > 180.0 {
            lon - 360.0
        } else if lon < -180.0 {
            lon + 360.0
        } else {
            lon
        };
        [lon, self.stored[1]]
    }
}

/// `ring` with each longitude shifted by a multiple of 360° so that it differs from the one
/// before by at most 180°; the first is shifted nearest `reference`.
fn unwrap(ring: &[Point], reference: f64) -> Vec<Vertex> {
    let mut out: Vec<Vertex> = Vec::with_capacity(ring.len());
    let mut previous = reference;
    for &p in ring {
        let lon = p[0] + 360.0 * ((previous - p[0]) / 360.0).round();
        out.push(Vertex { at: [lon, p[1]], stored: p });
        previous = lon;
    }
    out
}

/// The longitude a hole starting at `lon` is unwrapped from: `lon` shifted into the shell's
/// longitudes `[west, east]` if a shift does, the one nearest the shell's first vertex
/// `start`; else nearest `start`.
fn hole_reference(lon: f64, west: f64, east: f64, start: f64) -> f64 {
    let nearest = lon + 360.0 * ((start - lon) / 360.0).round();
    [nearest, nearest - 360.0, nearest + 360.0]
        .into_iter()
        .find(|x| (west..=east).contains(x))
        .unwrap_or(nearest)
}

/// Closes an unwrapped ring that goes round a pole (its closing edge would end 360° from its
/// first vertex) through that pole (the one on the side of its mean latitude): started where
/// it crosses a line 180° + k·360°, so that it spans one box, then up that line to the pole,
/// along it and down again. Whether it did.
fn close_round_a_pole(ring: &mut Vec<Vertex>) -> bool {
    let (Some(&first), Some(&last)) = (ring.first(), ring.last()) else { return false };
    let closing = first.at[0] - last.at[0];
    let turn = closing - 360.0 * (closing / 360.0).round() + last.at[0] - first.at[0];
    if turn.abs() < 180.0 {
        return false;
    }
    let mean = ring.iter().map(|v| v.at[1]).sum::<f64>() / ring.len() as f64;
    let pole = if mean >= 0.0 { 90.0 } else { -90.0 };
    ring.push(Vertex { at: [first.at[0] + turn, first.at[1]], stored: first.stored });
    let open = with_crossings(ring, false);
    // The ring spans 360°, so some vertex lies on a line.
    let on_line = |v: &Vertex| (v.at[0] - 180.0).rem_euclid(360.0) == 0.0;
    let start = open.iter().position(on_line).unwrap_or(0);
    let shifted = |v: &Vertex| Vertex { at: [v.at[0] + turn, v.at[1]], ..*v };
    let mut closed: Vec<Vertex> = open[start..].to_vec();
    closed.extend(open[1..=start].iter().map(shifted));
    let (from, to) = (closed[0].at[0], closed[closed.len() - 1].at[0]);
    let added = |at: Point| Vertex { at, stored: at };
    closed.push(added([to, pole]));
    closed.push(added([from, pole]));
    *ring = closed;
    true
}

/// `ring` (closed when `closed`) with a vertex wherever an edge crosses a line 180° + k·360°
/// strictly between its ends: the longitude exactly on the line, the latitude interpolated
/// linearly.
fn with_crossings(ring: &[Vertex], closed: bool) -> Vec<Vertex> {
    let mut out = Vec::with_capacity(ring.len() + 4);
    let n = ring.len();
    for i in 0..n {
        let a = ring[i];
        out.push(a);
        if i + 1 == n && !closed {
            break;
        }
        let b = ring[(i + 1) % n];
        let (lo, hi) = (a.at[0].min(b.at[0]), a.at[0].max(b.at[0]));
        // Steps are at most 180°: at most one line strictly between the ends.
        let line = 180.0 + 360.0 * ((lo - 180.0) / 360.0).floor();
        let line = if line <= lo { line + 360.0 } else { line };
        if line < hi {
            let t = (line - a.at[0]) / (b.at[0] - a.at[0]);
            let lat = a.at[1] + t * (b.at[1] - a.at[1]);
            out.push(Vertex { at: [line, lat], stored: [line, lat] });
        }
    }
    out
}

/// The box `k` of longitudes [-180, 180] + k·360° holding `x` (the eastern one on a
/// boundary).
fn box_of(x: f64) -> i64 {
    ((x + 180.0) / 360.0).floor() as i64
}

/// The box a line at `x` is in when it goes on to `next`: on a boundary, the box towards
/// `next`.
fn side_box(x: f64, next: f64) -> i64 {
    let k = box_of(x);
    let on_boundary = x - 360.0 * k as f64 == -180.0;
    if on_boundary && next < x {
        k - 1
    } else {
        k
    }
}

/// The westernmost and easternmost unwrapped longitudes of `ring`.
fn longitude_range(ring: &[Vertex]) -> (f64, f64) {
    ring.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(w, e), v| (w.min(v.at[0]), e.max(v.at[0])))
}

/// The pieces of the polygon `rings` (unwrapped, with their crossing vertices) in box `k`,
/// shifted into [-180, 180], their vertices the exact coordinates they came from.
fn pieces_in_box(rings: &[Vec<Vertex>], k: i64) -> Vec<Vec<Vec<Point>>> {
    let shift = 360.0 * k as f64;
    let subject: Vec<Vec<Point>> = rings
        .iter()
        .map(|ring| ring.iter().map(|v| [v.at[0] - shift, v.at[1]]).collect())
        .collect();
    let reach = subject.iter().flatten().fold(180.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    // Centred on 0 with a power-of-two scale: ±180 and ±90 are exact grid values.
    let rect = FloatRect { min_x: -reach, max_x: reach, min_y: -reach, max_y: reach };
    let adapter = FloatPointAdapter::<Point, f64>::new(rect);
    let scale = adapter.dir_scale;
    let grid = |p: Point| ((p[0] * scale).round() as i64, (p[1] * scale).round() as i64);
    let mut exact: HashMap<(i64, i64), Point> = HashMap::new();
    for (ring, shifted) in rings.iter().zip(&subject) {
        for (v, p) in ring.iter().zip(shifted) {
            if p[0].abs() <= 180.0 {
                exact.entry(grid(*p)).or_insert_with(|| v.exact(k));
            }
        }
    }
    let clip = vec![[-180.0, -90.0], [180.0, -90.0], [180.0, 90.0], [-180.0, 90.0]];
    let options = OverlayOptions {
        preserve_input_collinear: true,
        output_direction: ContourDirection::CounterClockwise,
        preserve_output_collinear: true,
        min_output_area: 0.0,
        ogc: true,
        clean_result: false,
    };
    let capacity = subject.iter().map(Vec::len).sum::<usize>() + clip.len();
    let shapes = FloatOverlay::new_custom(adapter, options, Default::default(), capacity)
        .unsafe_add_source(&subject, ShapeType::Subject)
        .unsafe_add_contour(&clip, ShapeType::Clip)
        .overlay(OverlayRule::Intersect, FillRule::EvenOdd);
    let restore = |p: Point| -> Point {
        let (gx, gy) = grid(p);
        let near = (-1..=1).flat_map(|dx| (-1..=1).map(move |dy| (gx + dx, gy + dy)));
        let found = std::iter::once((gx, gy)).chain(near).find_map(|key| exact.get(&key));
        found.copied().unwrap_or(p)
    };
    shapes
        .into_iter()
        .map(|shape| {
            shape.into_iter().map(|ring| ring.into_iter().map(restore).collect()).collect()
        })
        .collect()
}

#[cfg(test)]
mod tests;
