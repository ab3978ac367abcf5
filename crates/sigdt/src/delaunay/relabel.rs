//! The same triangulation with its triangles stored in another order: for the tests that
//! every stage after the triangulation gives the same result whatever the layout of its
//! arrays. That is what lets a triangulation be built another way (in parallel, issue 48)
//! without a pass that puts the triangles back in one canonical order.
//!
//! # Complexity
//! O(n).
use super::{Triangulation, EMPTY};
use crate::samplers::Rng;

impl Triangulation {
    #[doc(hidden)]
    /// This triangulation with its triangles in a random order fixed by `seed`, each with its
    /// corners rotated at random (counter-clockwise kept): the same vertices, triangles and
    /// edges, every half-edge numbered anew.
    pub fn with_triangles_shuffled(&self, seed: u64) -> Triangulation {
        let count = self.triangles.len() / 3;
        let mut rng = Rng::new(seed);
        let mut place: Vec<u32> = (0..count as u32).collect();
        rng.shuffle(&mut place);
        let rotation: Vec<u32> = (0..count).map(|_| rng.below(3) as u32).collect();
        // Corner `i` of old triangle `t` goes to corner `(i + r) mod 3` of triangle place[t].
        let new_slot = |s: u32| {
            let t = (s / 3) as usize;
            3 * place[t] + (s % 3 + rotation[t]) % 3
        };
        let mut triangles = vec![0; self.triangles.len()];
        let mut halfedges = vec![EMPTY; self.halfedges.len()];
        for s in 0..self.triangles.len() as u32 {
            let to = new_slot(s) as usize;
            triangles[to] = self.triangles[s as usize];
            halfedges[to] = match self.halfedges[s as usize] {
                EMPTY => EMPTY,
                twin => new_slot(twin),
            };
        }
        let vertex_halfedge = vertex_halfedges(self.points.len(), &triangles, &halfedges);
        Triangulation {
            points: self.points.clone(),
            input_index: self.input_index.clone(),
            triangles,
            halfedges,
            vertex_halfedge,
            duplicates: self.duplicates.clone(),
            input_len: self.input_len,
            shape: self.shape,
            scaling: self.scaling,
        }
    }
}

/// Each vertex's first outgoing half-edge, or its outgoing hull half-edge on the hull (the
/// one whose twin is [`EMPTY`]), as `Triangulation::vertex_halfedge` holds them.
pub(super) fn vertex_halfedges(n: usize, triangles: &[u32], halfedges: &[u32]) -> Vec<u32> {
    let mut vertex_halfedge = vec![EMPTY; n];
    for (h, &v) in triangles.iter().enumerate() {
        let slot = &mut vertex_halfedge[v as usize];
        if *slot == EMPTY || halfedges[h] == EMPTY {
            *slot = h as u32;
        }
    }
    vertex_halfedge
}
