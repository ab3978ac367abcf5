//! A reading of the points: loops and open paths as two neighbour slots per vertex, the form
//! SIG-AUTO's last two passes ([`outliers`](super::outliers) and
//! [`continuation`](super::continuation)) edit. Every vertex has at most two neighbours;
//! an end of a path has one, a point on no curve none.
use crate::delaunay::Triangulation;
use crate::geometry::{distance, orient2d, turning, Point};

/// No neighbour in a slot.
pub(crate) const NONE: u32 = u32::MAX;

/// Loops and paths over the vertices of a triangulation.
pub(crate) struct Reading<'a> {
    pub(crate) dt: &'a Triangulation,
    neighbours: Vec<[u32; 2]>,
}

impl<'a> Reading<'a> {
    /// The reading of `pairs` (vertex pairs of `dt`, every vertex in at most two, no repeats).
    pub(crate) fn new(dt: &'a Triangulation, pairs: &[[u32; 2]]) -> Reading<'a> {
        let mut reading = Reading { dt, neighbours: vec![[NONE; 2]; dt.num_vertices()] };
        reading.link(pairs);
        reading
    }

    /// Adds the edges `pairs`; every vertex keeps at most two.
    pub(crate) fn link(&mut self, pairs: &[[u32; 2]]) {
        for &[a, b] in pairs {
            for (x, y) in [(a, b), (b, a)] {
                let slots = &mut self.neighbours[x as usize];
                let free = usize::from(slots[0] != NONE);
                debug_assert!(slots[free] == NONE, "vertex {x} on three reading edges");
                slots[free] = y;
            }
        }
    }

    /// The edges, each once as `[a, b]` with `a < b`, by vertex.
    pub(crate) fn pairs(&self) -> Vec<[u32; 2]> {
        let mut pairs = Vec::new();
        for (a, slots) in self.neighbours.iter().enumerate() {
            let a = a as u32;
            pairs.extend(slots.iter().filter(|&&b| b != NONE && a < b).map(|&b| [a, b]));
        }
        pairs
    }

    /// The two neighbour slots of `v`.
    pub(crate) fn neighbours(&self, v: u32) -> [u32; 2] {
        self.neighbours[v as usize]
    }

    /// The number of reading edges at `v`.
    pub(crate) fn degree(&self, v: u32) -> usize {
        self.neighbours(v).iter().filter(|&&w| w != NONE).count()
    }

    /// Whether `a` and `b` are joined in the reading.
    pub(crate) fn joined(&self, a: u32, b: u32) -> bool {
        self.neighbours(a).contains(&b)
    }

    /// The neighbour of `v` other than `w` ([`NONE`] if there is none).
    pub(crate) fn other(&self, v: u32, w: u32) -> u32 {
        let [x, y] = self.neighbours(v);
        if x == w {
            y
        } else {
            x
        }
    }

    /// Replaces the neighbour `old` of `v` by `new` ([`NONE`] to drop it).
    pub(crate) fn relink(&mut self, v: u32, old: u32, new: u32) {
        let slots = &mut self.neighbours[v as usize];
        let k = usize::from(slots[0] != old);
        debug_assert_eq!(slots[k], old, "{old} is not a neighbour of {v}");
        slots[k] = new;
    }

    /// Takes `v` off the reading (its neighbours keep their other links).
    pub(crate) fn detach(&mut self, v: u32) {
        self.neighbours[v as usize] = [NONE; 2];
    }

    /// The position of vertex `v` (scaled coordinates).
    pub(crate) fn point(&self, v: u32) -> Point {
        self.dt.point(v)
    }

    /// The length of the segment `ab`.
    pub(crate) fn length(&self, a: u32, b: u32) -> f64 {
        distance(self.point(a), self.point(b))
    }

    /// Every open path (from an end with one neighbour to the other end), each once.
    pub(crate) fn open_paths(&self) -> Vec<Vec<u32>> {
        let mut paths = Vec::new();
        for start in (0..self.neighbours.len() as u32).filter(|&v| self.degree(v) == 1) {
            let [x, y] = self.neighbours(start);
            let mut path = vec![start, if x == NONE { y } else { x }];
            while let [.., previous, v] = path[..] {
                if self.degree(v) != 2 {
                    break;
                }
                path.push(self.other(v, previous));
            }
            if start < path[path.len() - 1] {
                paths.push(path);
            }
        }
        paths
    }

    /// The summed length of the reading's edges.
    pub(crate) fn total_length(&self) -> f64 {
        self.pairs().iter().map(|&[a, b]| self.length(a, b)).sum()
    }

    /// The summed turning (radians) over every vertex.
    pub(crate) fn total_turning(&self) -> f64 {
        (0..self.neighbours.len() as u32).map(|v| self.turning(v)).sum()
    }

    /// How much the reading turns at `v` if its neighbours were `slots` (0 at an end).
    pub(crate) fn turning_with(&self, v: u32, slots: [u32; 2]) -> f64 {
        match slots {
            [x, y] if x != NONE && y != NONE => {
                turning(self.point(x), self.point(v), self.point(y))
            }
            _ => 0.0,
        }
    }

    /// How much the reading turns at `v` (0 at an end).
    pub(crate) fn turning(&self, v: u32) -> f64 {
        self.turning_with(v, self.neighbours(v))
    }

    /// Whether the reading zigzags: four consecutive vertices that each turn by more than
    /// `cos_limit`'s angle, in alternating directions. A sampled curve turns less than that
    /// at every sample (ε < 1 gives 60°); a corner makes one or two such turns in a row, in
    /// one direction or in two, but never three changes of direction.
    pub(crate) fn zigzags(&self, cos_limit: f64) -> bool {
        self.zigzags_at(0..self.neighbours.len() as u32, cos_limit)
    }

    /// [`zigzags`](Self::zigzags), looking only at zigzags centred on `vertices`.
    pub(crate) fn zigzags_at(
        &self,
        vertices: impl IntoIterator<Item = u32>,
        cos_limit: f64,
    ) -> bool {
        let side = |v: u32| {
            let [x, y] = self.neighbours(v);
            orient2d(self.point(x), self.point(v), self.point(y)).signum()
        };
        let sharp = |v: u32| self.degree(v) == 2 && self.turns_more_than(v, cos_limit);
        vertices.into_iter().any(|b| {
            let [a, c] = self.neighbours(b);
            if !(sharp(b) && sharp(a) && sharp(c)) {
                return false;
            }
            let d = self.other(c, b);
            sharp(d) && side(a) == -side(b) && side(c) == -side(b) && side(d) == side(b)
        })
    }

    /// Whether the reading turns at `v` by more than `limit` radians, `limit` in `[0, π)`:
    /// the dot product of the two edge directions against `cos(limit)` times their lengths,
    /// without the arc tangent.
    pub(crate) fn turns_more_than(&self, v: u32, cos_limit: f64) -> bool {
        self.turns_more_than_with(v, self.neighbours(v), cos_limit)
    }

    /// [`turns_more_than`](Self::turns_more_than) with `v`'s neighbours in `slots`.
    pub(crate) fn turns_more_than_with(&self, v: u32, slots: [u32; 2], cos_limit: f64) -> bool {
        let [x, y] = slots;
        if x == NONE || y == NONE {
            return false;
        }
        turns_more_than(self.point(x), self.point(v), self.point(y), cos_limit)
    }
}

/// Whether a curve through `p`, `q` and `r` turns at `q` by more than the angle whose
/// cosine is `cos_limit` (the same whichever way it runs).
pub(crate) fn turns_more_than(p: Point, q: Point, r: Point, cos_limit: f64) -> bool {
    let (u, w) = ([q[0] - p[0], q[1] - p[1]], [r[0] - q[0], r[1] - q[1]]);
    let dot = u[0] * w[0] + u[1] * w[1];
    dot < cos_limit * (u[0].hypot(u[1]) * w[0].hypot(w[1]))
}
