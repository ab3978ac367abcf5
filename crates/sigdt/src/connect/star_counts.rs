//! The counts a vertex's class is read from (`T`, `D` and the exterior edges at it; module
//! `boundary`), kept for every vertex in three bytes.
//!
//! A count never exceeds the vertex's degree, so a vertex of degree below 255 keeps its
//! counts in bytes; the few of higher degree (a fan's apex) keep theirs in a side table,
//! marked by an escape byte. Updating and reading stay O(1); the table is a quarter of the
//! size of three `u32`s a vertex, and it is alive through inflating and sculpting, at the
//! peak memory of a run.
use crate::delaunay::{Triangulation, EMPTY};
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
    /// What one edge adds: its sides' labels (interior or not) and whether it is on the
    /// boundary `B` (it dangles when both sides are exterior).
    pub(crate) fn of_edge(left: bool, right: bool, on_boundary: bool) -> StarCounts {
        StarCounts {
            transitions: u32::from(left != right),
            dangling: u32::from(!left && !right && on_boundary),
            exterior: u32::from(!left || !right),
        }
    }

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
    /// The counts of every vertex given what each edge adds to them (`contribution`, the
    /// same for both halves of an edge), in one pass over the half-edges: each adds to its
    /// origin, a hull half-edge also to its end (which has no half-edge back), so every
    /// edge is counted once at each end. Walking every star instead cost several times more.
    ///
    /// The pass also counts each vertex's outgoing half-edges (saturating at a byte); its
    /// degree is that count, plus one incoming hull edge on the hull. Below [`ESCAPE`] the
    /// wrapping byte sums are exact; the few vertices at or above it are counted again from
    /// their stars into the side table. On several threads the half-edges are split among
    /// them, a table of four bytes a vertex each (`parallel::tally`).
    pub(crate) fn counted(
        dt: &Triangulation,
        contribution: impl Fn(u32) -> StarCounts + Sync + Send,
    ) -> StarTable {
        let add = |cell: &mut [u8; 4], c: StarCounts| {
            cell[1] = cell[1].wrapping_add(c.transitions as u8);
            cell[2] = cell[2].wrapping_add(c.dangling as u8);
            cell[3] = cell[3].wrapping_add(c.exterior as u8);
        };
        let add_range = |range: std::ops::Range<usize>, table: &mut [[u8; 4]]| {
            for h in range.start as u32..range.end as u32 {
                let c = contribution(h);
                let origin = &mut table[dt.origin(h) as usize];
                origin[0] = origin[0].saturating_add(1);
                add(origin, c);
                if dt.twin(h) == EMPTY {
                    add(&mut table[dt.dest(h) as usize], c);
                }
            }
        };
        let merge = |cell: &mut [u8; 4], other: [u8; 4]| {
            cell[0] = cell[0].saturating_add(other[0]);
            for k in 1..4 {
                cell[k] = cell[k].wrapping_add(other[k]);
            }
        };
        let (halfedges, vertices) = (dt.num_halfedges(), dt.num_vertices());
        let sums = crate::parallel::tally(halfedges, vertices, [0; 4], add_range, merge);
        let escaped = |cell: &[u8; 4]| cell[0] >= ESCAPE - 1;
        let small = crate::parallel::map_slice(&sums, |cell| match escaped(cell) {
            true => [ESCAPE, 0, 0],
            false => [cell[1], cell[2], cell[3]],
        });
        let large = (0..dt.num_vertices() as u32)
            .filter(|&v| escaped(&sums[v as usize]))
            .map(|v| {
                let mut counts = StarCounts::default();
                for h in dt.incident(v) {
                    counts.apply(contribution(h), true);
                }
                (v, counts)
            })
            .collect();
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
        let mut table = StarTable::counted(&dt, |_| StarCounts::default());
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

    #[test]
    #[cfg(feature = "parallel")]
    fn counts_are_those_of_every_star_on_any_pool() {
        // A jittered grid of 4,000 points (past the size where the pass splits among the
        // threads) with a fan apex of degree over 255 beside it: each vertex's counts equal
        // the sum over its star of an arbitrary symmetric contribution, on 1 and 3 threads.
        let mut points: Vec<[f64; 2]> = (0..4000)
            .map(|i| [(i % 60) as f64 + 0.37 * ((i * 7) % 11) as f64 / 11.0, (i / 60) as f64])
            .collect();
        points.extend((0..300).map(|i| [-1.0 - i as f64 * 1e-3, 30.0 + i as f64 * 0.2]));
        points.push([-50.0, 60.0]);
        let dt = Triangulation::new(&points).unwrap();
        let contribution = |h: u32| {
            let (a, b) = (dt.origin(h), dt.dest(h));
            let key = a.min(b) * 31 + a.max(b);
            StarCounts {
                transitions: u32::from(key % 3 == 0),
                dangling: u32::from(key % 5 == 0),
                exterior: u32::from(key % 2 == 0),
            }
        };
        let escaped = |table: &StarTable| table.small.iter().filter(|c| c[0] == ESCAPE).count();
        for threads in [1, 3] {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            let table = pool.install(|| StarTable::counted(&dt, contribution));
            assert!(escaped(&table) >= 1, "the apex is counted in the side table");
            for v in 0..dt.num_vertices() as u32 {
                let mut expected = StarCounts::default();
                for h in dt.incident(v) {
                    expected.apply(contribution(h), true);
                }
                assert_eq!(table.get(v), expected, "vertex {v} on {threads} threads");
            }
        }
    }
}
