//! The mutable triangulation OPTIMALTRANSPORT simplifies: the Delaunay triangulation of the
//! points and of a bounding frame, with the half-edge flips and collapses of [dGCSAD11] §4.
//!
//! Same layout as the kernel's [`Triangulation`](crate::delaunay::Triangulation): half-edge
//! `h` starts at `tri[h]`, belongs to triangle `h / 3` (counter-clockwise), and `twin[h]` is
//! its opposite or [`EMPTY`] on the frame's border. Vertices `0..FRAME` are the frame's
//! corners (pinned: never moved, never collapsed); vertex `FRAME + v` is the kernel's vertex
//! `v`. A collapse deletes two triangles, whose slots stay dead (`tri` holds [`EMPTY`]); a
//! flip rewrites two triangles in place. Every operation keeps all triangles strictly
//! counter-clockwise; callers check that with exact `orient2d` before asking for it.
//!
//! [dGCSAD11]: https://doi.org/10.1111/j.1467-8659.2011.02033.x
use crate::delaunay::{next, prev, EMPTY};
use crate::geometry::Point;
use spade::handles::FixedVertexHandle;
use spade::{DelaunayTriangulation, Point2, Triangulation as _};

/// Number of frame corners; they are vertices `0..FRAME`.
pub(super) const FRAME: u32 = 4;

/// See the module docs.
pub(super) struct Mesh {
    /// Vertex positions, in the kernel's scaled coordinates.
    pub(super) pos: Vec<Point>,
    tri: Vec<u32>,
    twin: Vec<u32>,
    /// One outgoing half-edge per vertex ([`EMPTY`] once collapsed).
    out: Vec<u32>,
    degree: Vec<u32>,
}

impl Mesh {
    /// The Delaunay triangulation of `points` and of the corners of their bounding box
    /// enlarged by half its larger side on every side ([dGCSAD11] §4; CGAL's loose box).
    /// `points` are distinct and not all collinear.
    ///
    /// [dGCSAD11]: https://doi.org/10.1111/j.1467-8659.2011.02033.x
    pub(super) fn new(points: &[Point]) -> Mesh {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points {
            for a in 0..2 {
                lo[a] = lo[a].min(p[a]);
                hi[a] = hi[a].max(p[a]);
            }
        }
        let margin = 0.5 * (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let (x0, y0, x1, y1) = (lo[0] - margin, lo[1] - margin, hi[0] + margin, hi[1] + margin);
        let mut pos = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
        pos.extend_from_slice(points);
        let n = pos.len();
        let mut dt: DelaunayTriangulation<Point2<f64>> =
            DelaunayTriangulation::with_capacity(n, 3 * n, 2 * n);
        // The kernel's vertex order is spatially coherent, so each point is a good hint for
        // the next. Coordinates come from the kernel: inside spade's range, distinct.
        let mut hint = FixedVertexHandle::from_index(0);
        for (v, p) in pos.iter().enumerate() {
            hint = dt.insert_with_hint(Point2::new(p[0], p[1]), hint).expect("scaled point");
            debug_assert_eq!(hint.index(), v);
        }
        let nt = dt.num_inner_faces();
        let mut tri = Vec::with_capacity(3 * nt);
        for face in dt.inner_faces() {
            tri.extend(face.adjacent_edges().iter().map(|e| e.from().fix().index() as u32));
        }
        let mut twin = vec![EMPTY; 3 * nt];
        for (t, face) in dt.inner_faces().enumerate() {
            for (k, e) in face.adjacent_edges().iter().enumerate() {
                if let Some(other) = e.rev().face().as_inner() {
                    let t2 = other.fix().index() - 1;
                    let start = e.to().fix().index() as u32;
                    let k2 = (0..3).find(|&k2| tri[3 * t2 + k2] == start).expect("twin");
                    twin[3 * t + k] = (3 * t2 + k2) as u32;
                }
            }
        }
        let mut out = vec![EMPTY; n];
        let mut degree = vec![0; n];
        for (h, &v) in tri.iter().enumerate() {
            out[v as usize] = h as u32;
            // Each edge once: the lower of a twin pair, or a border half-edge.
            if (h as u32) < twin[h] {
                degree[v as usize] += 1;
                degree[tri[next(h as u32) as usize] as usize] += 1;
            }
        }
        Mesh { pos, tri, twin, out, degree }
    }

    /// Number of triangle slots, dead ones included.
    pub(super) fn num_slots(&self) -> u32 {
        (self.tri.len() / 3) as u32
    }

    /// Whether triangle `t` is still there.
    #[inline]
    pub(super) fn alive(&self, t: u32) -> bool {
        self.tri[3 * t as usize] != EMPTY
    }

    #[inline]
    pub(super) fn origin(&self, h: u32) -> u32 {
        self.tri[h as usize]
    }

    #[inline]
    pub(super) fn dest(&self, h: u32) -> u32 {
        self.tri[next(h) as usize]
    }

    #[inline]
    pub(super) fn twin(&self, h: u32) -> u32 {
        self.twin[h as usize]
    }

    /// The vertices of triangle `t`, counter-clockwise from its first half-edge.
    #[inline]
    pub(super) fn corners(&self, t: u32) -> [u32; 3] {
        let h = 3 * t as usize;
        [self.tri[h], self.tri[h + 1], self.tri[h + 2]]
    }

    /// Whether `v` is a frame corner.
    #[inline]
    pub(super) fn pinned(v: u32) -> bool {
        v < FRAME
    }

    /// Number of edges at `v` (0 once collapsed).
    #[inline]
    pub(super) fn degree(&self, v: u32) -> u32 {
        self.degree[v as usize]
    }

    /// The outgoing half-edges of the interior vertex `v`, counter-clockwise, into `star`:
    /// `star[i]` runs from `v` to its `i`-th link vertex, in the triangle
    /// `(v, link[i], link[i + 1])`.
    pub(super) fn star(&self, v: u32, star: &mut Vec<u32>) {
        star.clear();
        let start = self.out[v as usize];
        let mut h = start;
        loop {
            star.push(h);
            h = self.twin[prev(h) as usize];
            debug_assert!(h != EMPTY, "vertex {v} is on the border");
            if h == start {
                return;
            }
        }
    }

    /// The half-edge from the interior vertex `s` to its neighbour `b`.
    pub(super) fn spoke(&self, s: u32, b: u32) -> u32 {
        let start = self.out[s as usize];
        let mut h = start;
        while self.dest(h) != b {
            h = self.twin[prev(h) as usize];
            assert!(h != start, "{b} is not a neighbour of {s}");
        }
        h
    }

    /// Flips the interior edge of `h` (`a → b`, triangles `(a, b, c)` and `(b, a, d)`) to
    /// `c → d`: the triangles become `(c, a, d)` (slot of `h`'s triangle, starting at `h`)
    /// and `(d, b, c)`. The quadrilateral `a d b c` must be strictly convex.
    pub(super) fn flip(&mut self, h: u32) {
        let g = self.twin(h);
        debug_assert!(g != EMPTY);
        let (h1, h2, g1, g2) = (next(h), prev(h), next(g), prev(g));
        let (a, b, c, d) = (self.origin(h), self.origin(g), self.origin(h2), self.origin(g2));
        let (th1, th2, tg1, tg2) = (self.twin(h1), self.twin(h2), self.twin(g1), self.twin(g2));
        for (slot, v) in [(h, c), (h1, a), (h2, d), (g, d), (g1, b), (g2, c)] {
            self.tri[slot as usize] = v;
        }
        self.link(h, th2);
        self.link(h1, tg1);
        self.link(g, tg2);
        self.link(g1, th1);
        self.link(h2, g2);
        self.out[a as usize] = h1;
        self.out[b as usize] = g1;
        self.out[c as usize] = h;
        self.out[d as usize] = g;
        self.degree[a as usize] -= 1;
        self.degree[b as usize] -= 1;
        self.degree[c as usize] += 1;
        self.degree[d as usize] += 1;
    }

    /// Collapses the half-edge `h` from the interior vertex `s` into its end `t`: the two
    /// triangles at `st` die and `t` takes `s`'s place in the others. The caller has checked
    /// that `t` sees every edge of `s`'s link that does not end at `t` (the kernel test).
    pub(super) fn collapse(&mut self, h: u32) {
        let g = self.twin(h);
        let (s, t) = (self.origin(h), self.dest(h));
        let (x, y) = (self.origin(prev(h)), self.origin(prev(g)));
        let mut star = Vec::new();
        self.star(s, &mut star);
        for &k in &star {
            self.tri[k as usize] = t;
        }
        // Triangle (s, t, x): x → t outside meets s → x (now t → x) inside; likewise at y.
        let (outer_x, inner_x) = (self.twin(next(h)), self.twin(prev(h)));
        let (inner_y, outer_y) = (self.twin(next(g)), self.twin(prev(g)));
        self.link(inner_x, outer_x);
        self.link(inner_y, outer_y);
        for k in [h - h % 3, g - g % 3] {
            self.tri[k as usize..k as usize + 3].fill(EMPTY);
        }
        self.out[s as usize] = EMPTY;
        self.out[t as usize] = inner_x;
        self.out[x as usize] = next(inner_x);
        self.out[y as usize] = inner_y;
        // t loses s and gains s's link but for itself, x and y.
        let ds = self.degree[s as usize];
        self.degree[t as usize] = self.degree[t as usize] + ds - 4;
        self.degree[x as usize] -= 1;
        self.degree[y as usize] -= 1;
        self.degree[s as usize] = 0;
    }

    /// Makes `h` and `g` twins; `g` may be [`EMPTY`] (the frame's border).
    fn link(&mut self, h: u32, g: u32) {
        self.twin[h as usize] = g;
        if g != EMPTY {
            self.twin[g as usize] = h;
        }
    }

    /// Checks every invariant (tests only): twins agree, triangles are counter-clockwise,
    /// degrees and outgoing half-edges are right.
    #[cfg(test)]
    pub(super) fn check(&self) {
        use crate::geometry::orient2d;
        let mut degree = vec![0u32; self.pos.len()];
        for t in (0..self.num_slots()).filter(|&t| self.alive(t)) {
            let [a, b, c] = self.corners(t).map(|v| self.pos[v as usize]);
            assert!(orient2d(a, b, c) > 0.0, "triangle {t} is not counter-clockwise");
            for h in 3 * t..3 * t + 3 {
                let g = self.twin(h);
                if g == EMPTY {
                    degree[self.origin(h) as usize] += 1;
                    degree[self.dest(h) as usize] += 1;
                    continue;
                }
                assert_eq!(self.twin(g), h);
                assert_eq!((self.origin(g), self.dest(g)), (self.dest(h), self.origin(h)));
                if h < g {
                    degree[self.origin(h) as usize] += 1;
                    degree[self.dest(h) as usize] += 1;
                }
            }
        }
        assert_eq!(degree, self.degree);
        for (v, &h) in self.out.iter().enumerate() {
            if h != EMPTY {
                assert!(self.alive(h / 3) && self.origin(h) == v as u32, "out[{v}]");
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square with its centre: 4 frame corners and 5 points.
    fn square() -> Mesh {
        Mesh::new(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]])
    }

    #[test]
    fn frame_and_points_are_triangulated() {
        let mesh = square();
        mesh.check();
        // 9 vertices, 4 on the border: 2·9 − 2 − 4 triangles.
        assert_eq!(mesh.num_slots(), 12);
        assert_eq!(mesh.pos[0], [-1.0, -1.0]);
        assert_eq!(mesh.degree(FRAME + 4), 4);
    }

    #[test]
    fn collapse_and_flip_keep_the_invariants() {
        let mut mesh = square();
        let centre = FRAME + 4;
        let mut star = Vec::new();
        mesh.star(centre, &mut star);
        assert_eq!(star.len(), 4);
        // The centre into the corner (0, 0): the square's other three corners see it.
        let h = mesh.spoke(centre, FRAME);
        mesh.collapse(h);
        mesh.check();
        assert_eq!(mesh.degree(centre), 0);
        assert_eq!(mesh.num_slots() - (0..12).filter(|&t| mesh.alive(t)).count() as u32, 2);
        // The diagonal (0, 0)-(2, 2) can be flipped to (2, 0)-(0, 2).
        let before = [FRAME, FRAME + 1, FRAME + 2, FRAME + 3].map(|v| mesh.degree(v));
        let d = mesh.spoke(FRAME, FRAME + 2);
        mesh.flip(d);
        mesh.check();
        let after = [FRAME, FRAME + 1, FRAME + 2, FRAME + 3].map(|v| mesh.degree(v));
        assert_eq!(after, [before[0] - 1, before[1] + 1, before[2] - 1, before[3] + 1]);
    }
}
