//! Which components of a round of outlier removal the last round already read, unchanged.
//!
//! Leaving points out changes SIGDT2 only near them: a Delaunay triangle with no vertex left
//! out stays Delaunay, so the new edges join neighbours of the points left out (the hole's
//! rim); a nearest-neighbour distance changes only at such a neighbour; and the distances
//! only grow, so no SIG edge among the points kept is lost. A component of the new round
//! with no such neighbour, all of whose points formed one component of the last round, is
//! therefore that component with the same edges, the same spanning tree (ties are broken by
//! the points' order, the same in every round after the first) and the same branches: the
//! last round found no outlier in it, and neither would this one.
//!
//! # Complexity
//! O(k) per component of `k` points; O(n) memory over the input's vertices.
use crate::delaunay::Triangulation;

/// The components of the last round that read their branches (vertices of the input
/// triangulation), and the points next to those left out since.
pub(super) struct UnchangedComponents {
    component: Vec<u32>,
    sizes: Vec<u32>,
    touched: Vec<bool>,
}

impl UnchangedComponents {
    /// The components `components` of a round, as vertices of the input triangulation
    /// (`whole`), over `n` such vertices; nothing is touched yet.
    pub(super) fn new<'a>(
        n: usize,
        components: impl Iterator<Item = &'a [u32]>,
        whole: impl Fn(u32) -> u32,
    ) -> UnchangedComponents {
        let mut component = vec![u32::MAX; n];
        let mut sizes = Vec::new();
        for (c, vertices) in components.enumerate() {
            vertices.iter().for_each(|&v| component[whole(v) as usize] = c as u32);
            sizes.push(vertices.len() as u32);
        }
        UnchangedComponents { component, sizes, touched: vec![false; n] }
    }

    /// Marks the Delaunay neighbours in `sub` of the points `gone` that the round leaves out
    /// (vertices of `sub`; `whole` gives the input's).
    pub(super) fn leave_out(
        &mut self,
        sub: &Triangulation,
        gone: &[u32],
        whole: impl Fn(u32) -> u32,
    ) {
        for &v in gone {
            for h in sub.incident(v) {
                self.touched[whole(sub.other(h, v)) as usize] = true;
            }
        }
    }

    /// Whether the component `vertices` (of the input triangulation) is one of the last
    /// round's, untouched (module docs).
    pub(super) fn unchanged(&self, mut vertices: impl ExactSizeIterator<Item = u32>) -> bool {
        let size = vertices.len();
        let Some(first) = vertices.next() else { return false };
        let c = self.component[first as usize];
        let same = |v: u32| self.component[v as usize] == c && !self.touched[v as usize];
        c != u32::MAX
            && self.sizes[c as usize] as usize == size
            && same(first)
            && vertices.all(same)
    }
}
