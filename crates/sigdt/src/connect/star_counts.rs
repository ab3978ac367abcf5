//! The counts a vertex's class is read from (`T`, `D` and the exterior edges at it; module
//! `boundary`), kept for every vertex in three bytes.
//!
//! A count never exceeds the vertex's degree, so a vertex of degree below 255 keeps its
//! counts in bytes; the few of higher degree (a fan's apex) keep theirs in a side table,
//! marked by an escape byte. Updating and reading stay O(1); the table is a quarter of the
//! size of three `u32`s a vertex, and it is alive through inflating and sculpting, at the
//! peak memory of a run.
use crate::delaunay::Triangulation;
use std::collections::HashMap;

/// How a vertex sits on the boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VertexClass {
    /// Exactly one exterior and one interior wedge, no dangling edge.
    Manifold,
    /// Pinched, dangling, or otherwise not (yet) a polygon vertex.
    NonManifold,
    /// Surrounded by interior triangles: not on the boundary.
    Interior,
}

/// The edges at a vertex that decide its class.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct StarCounts {
    /// Edges whose two sides have different labels (`T`).
    pub transitions: u32,
    /// Boundary edges with both sides exterior (`D`).
    pub dangling: u32,
    /// Edges with an exterior side (the outside of the hull counts): none means interior.
    pub exterior: u32,
}

impl StarCounts {
    /// Adds `c` to every count (`add`), or takes it away.
    fn apply(&mut self, c: StarCounts, add: bool) {
        let step = |count: &mut u32, delta: u32| {
            *count = if add { *count + delta } else { *count - delta };
        };
        step(&mut self.transitions, c.transitions);
        step(&mut self.dangling, c.dangling);
        step(&mut self.exterior, c.exterior);
    }

    pub(crate) fn class(self) -> VertexClass {
        if self.exterior == 0 {
            VertexClass::Interior
        } else if self.transitions == 2 && self.dangling == 0 {
            VertexClass::Manifold
        } else {
            VertexClass::NonManifold
        }
    }
}

/// Marks a vertex whose counts are in the side table.
const ESCAPE: u8 = u8::MAX;

/// Star counts of every vertex of a triangulation, all zero to start with.
pub(crate) struct StarTable {
    /// `[T, D, exterior]` of a vertex of degree below `ESCAPE`, or `ESCAPE` first.
    small: Vec<[u8; 3]>,
    large: HashMap<u32, StarCounts>,
}

impl StarTable {
    pub(crate) fn new(dt: &Triangulation) -> StarTable {
        // The outgoing half-edges of every vertex, counted in the first byte up to ESCAPE in
        // one pass over the half-edges (walking every star cost several times more): the
        // degree is that count, plus one incoming hull edge on the hull.
        let mut small = vec![[0u8; 3]; dt.num_vertices()];
        for h in 0..dt.num_halfedges() as u32 {
            let out = &mut small[dt.origin(h) as usize][0];
            *out = out.saturating_add(1);
        }
        let mut large = HashMap::new();
        for (v, counts) in small.iter_mut().enumerate() {
            if counts[0] >= ESCAPE - 1 {
                counts[0] = ESCAPE;
                large.insert(v as u32, StarCounts::default());
            } else {
                counts[0] = 0;
            }
        }
        StarTable { small, large }
    }

    pub(crate) fn get(&self, v: u32) -> StarCounts {
        match self.small[v as usize] {
            [ESCAPE, _, _] => self.large[&v],
            [t, d, e] => {
                StarCounts { transitions: t.into(), dangling: d.into(), exterior: e.into() }
            }
        }
    }

    /// Adds `c` to the counts of `v` (`add`), or takes it away.
    pub(crate) fn update(&mut self, v: u32, c: StarCounts, add: bool) {
        let counts = &mut self.small[v as usize];
        if counts[0] == ESCAPE {
            let big = self.large.get_mut(&v).expect("an escaped vertex is in the side table");
            big.apply(c, add);
            return;
        }
        for (count, delta) in counts.iter_mut().zip([c.transitions, c.dangling, c.exterior]) {
            // Below the degree, so below ESCAPE: no overflow.
            let delta = delta as u8;
            *count = if add { *count + delta } else { *count - delta };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fan_apex_counts_past_a_byte() {
        // 400 points on a line and one off it: the apex has degree 400.
        let mut points: Vec<[f64; 2]> = (0..400).map(|i| [i as f64, 0.0]).collect();
        points.push([200.0, 1.0]);
        let dt = Triangulation::new(&points).unwrap();
        let apex = (0..dt.num_vertices() as u32).find(|&v| dt.input_index(v) == 400).unwrap();
        let mut table = StarTable::new(&dt);
        let one = StarCounts { transitions: 1, dangling: 1, exterior: 1 };
        for _ in 0..300 {
            table.update(apex, one, true);
        }
        table.update(apex, one, false);
        assert_eq!(table.get(apex), StarCounts { transitions: 299, dangling: 299, exterior: 299 });
        let other = (apex + 1) % dt.num_vertices() as u32;
        table.update(other, StarCounts { transitions: 2, dangling: 0, exterior: 1 }, true);
        assert_eq!(table.get(other).class(), VertexClass::Manifold);
        assert_eq!(table.get(apex).class(), VertexClass::NonManifold);
    }
}
