//! A set of Delaunay edges with one flag per half-edge.
use crate::delaunay::{Triangulation, EMPTY};

/// A set of Delaunay edges, one flag per half-edge (both halves of an edge always agree).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EdgeMask {
    on: Vec<bool>,
    count: usize,
}

impl EdgeMask {
    /// The empty set for `dt`.
    pub fn new(dt: &Triangulation) -> EdgeMask {
        EdgeMask { on: vec![false; dt.num_halfedges()], count: 0 }
    }

    /// The set whose flags are `on` (one per half-edge, both halves of an edge equal),
    /// holding `count` edges.
    pub(crate) fn from_flags(on: Vec<bool>, count: usize) -> EdgeMask {
        EdgeMask { on, count }
    }

    /// Whether the edge of half-edge `h` is in the set.
    #[inline]
    pub fn contains(&self, h: u32) -> bool {
        self.on[h as usize]
    }

    /// Puts the edge of `h` in (`true`) or out of (`false`) the set.
    #[inline]
    pub fn set(&mut self, dt: &Triangulation, h: u32, value: bool) {
        if self.on[h as usize] != value {
            self.count = if value { self.count + 1 } else { self.count - 1 };
        }
        self.on[h as usize] = value;
        let t = dt.twin(h);
        if t != EMPTY {
            self.on[t as usize] = value;
        }
    }

    /// Number of edges in the set.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether the set is empty.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// Degree of every vertex in the set, in one pass over the edges.
    pub fn degrees(&self, dt: &Triangulation) -> Vec<u32> {
        let mut degree = vec![0; dt.num_vertices()];
        for h in dt.edge_halfedges().filter(|&h| self.contains(h)) {
            degree[dt.origin(h) as usize] += 1;
            degree[dt.dest(h) as usize] += 1;
        }
        degree
    }

    /// Number of edges of the set at vertex `v`.
    pub fn degree(&self, dt: &Triangulation, v: u32) -> usize {
        dt.incident(v).filter(|&h| self.contains(h)).count()
    }

    /// The edges as sorted input-index pairs.
    pub fn edges(&self, dt: &Triangulation) -> Vec<crate::geometry::Edge> {
        dt.to_input_edges(
            dt.edge_halfedges().filter(|&h| self.contains(h)).map(|h| [dt.origin(h), dt.dest(h)]),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mask_sets_both_halves() {
        let dt = Triangulation::new(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).unwrap();
        let mut mask = EdgeMask::new(&dt);
        for h in 0..dt.num_halfedges() as u32 {
            mask.set(&dt, h, true);
        }
        assert_eq!(mask.len(), 5);
        assert_eq!(mask.edges(&dt).len(), 5);
    }
}
