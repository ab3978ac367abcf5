//! A set of Delaunay edges with one bit per half-edge.
use crate::bits::word_bit;
use crate::delaunay::{Triangulation, EMPTY};

/// A set of Delaunay edges, one bit per half-edge (both halves of an edge always agree):
/// the graph and the boundary are alive together through inflating and sculpting, and bits
/// keep them at under two bytes a point.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EdgeMask {
    bits: Vec<u64>,
    count: usize,
}

impl EdgeMask {
    /// The empty set for `dt`.
    pub fn new(dt: &Triangulation) -> EdgeMask {
        EdgeMask { bits: vec![0; dt.num_halfedges().div_ceil(64)], count: 0 }
    }

    /// The set whose bits are `words` (half-edge `h` is bit `h % 64` of word `h / 64`, both
    /// halves of an edge equal, no bit past the last half-edge), holding `count` edges.
    pub(crate) fn from_words(words: Vec<u64>, count: usize) -> EdgeMask {
        EdgeMask { bits: words, count }
    }

    /// Whether the edge of half-edge `h` is in the set.
    #[inline]
    pub fn contains(&self, h: u32) -> bool {
        word_bit(&self.bits, h)
    }

    #[inline]
    fn put(&mut self, h: u32, value: bool) {
        let (word, bit) = ((h / 64) as usize, h % 64);
        self.bits[word] = self.bits[word] & !(1 << bit) | u64::from(value) << bit;
    }

    /// Puts the edge of `h` in (`true`) or out of (`false`) the set.
    #[inline]
    pub fn set(&mut self, dt: &Triangulation, h: u32, value: bool) {
        if self.contains(h) != value {
            self.count = if value { self.count + 1 } else { self.count - 1 };
        }
        self.put(h, value);
        let t = dt.twin(h);
        if t != EMPTY {
            self.put(t, value);
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
        for h in (0..dt.num_halfedges() as u32).step_by(2) {
            mask.set(&dt, h, false);
        }
        assert_eq!(mask.len(), dt.edge_halfedges().filter(|&h| mask.contains(h)).count());
        assert!(mask.len() < 5);
        assert_eq!(EdgeMask::from_words(mask.bits.clone(), mask.len()), mask);
    }

    #[test]
    fn bits_past_a_word() {
        // More than 128 half-edges: three words or more, the last partly used.
        let mut dt_points = Vec::new();
        for i in 0..30 {
            dt_points.push([i as f64, (i * i % 7) as f64]);
        }
        let dt = Triangulation::new(&dt_points).unwrap();
        assert!(dt.num_halfedges() > 128);
        let mut mask = EdgeMask::new(&dt);
        let last = dt.num_halfedges() as u32 - 1;
        for h in [0, 63, 64, 127, 128, last] {
            mask.set(&dt, h, true);
        }
        for h in 0..=last {
            let twin = dt.twin(h);
            let on = [0, 63, 64, 127, 128, last].iter().any(|&s| s == h || dt.twin(s) == h);
            assert_eq!(mask.contains(h), on, "half-edge {h} (twin {twin})");
        }
    }
}
