//! The compact encoding of the page's data: typed arrays as base64 of their little-endian
//! bytes, and every edge layer as one bit per edge of a list both sides build the same way.
//!
//! Writing numbers as decimal JSON took 334 bytes a point at 10⁶ points (the replay's steps
//! alone 112); binary keeps every coordinate exact in 16 bytes, and a layer costs one bit per
//! edge of the list instead of two decimal indices per edge (sizes in `docs/viewer.md`).

use base64::engine::general_purpose::STANDARD;
use base64::Engine as _;
use sigdt::Edge;

/// Every edge the page can draw, sorted and unique, `[i, j]` with `i < j`: the sides of the
/// triangles and the `extra` edges (those of a layer that no triangle has). The page builds
/// the same list from the triangles and `extra` alone, so a layer can be sent as a bit per
/// edge of it.
pub struct EdgeList {
    keys: Vec<u64>,
    /// The edges of [`EdgeList::new`]'s layers that are no triangle's side, sorted.
    pub extra: Vec<u64>,
}

/// `[i, j]` as one sortable number, `i < j`.
fn key([i, j]: Edge) -> u64 {
    let (a, b) = (i.min(j) as u64, i.max(j) as u64);
    (a << 32) | b
}

impl EdgeList {
    /// The list for these triangles and layers; edges from a point to itself are left out
    /// (they draw nothing).
    pub fn new<'a>(
        triangles: &[[usize; 3]],
        layers: impl IntoIterator<Item = &'a [Edge]>,
    ) -> EdgeList {
        let mut sides: Vec<u64> = triangles
            .iter()
            .flat_map(|&[a, b, c]| [key([a, b]), key([b, c]), key([c, a])])
            .collect();
        sides.sort_unstable();
        sides.dedup();
        let mut extra: Vec<u64> = layers
            .into_iter()
            .flatten()
            .filter(|[i, j]| i != j)
            .map(|&e| key(e))
            .filter(|k| sides.binary_search(k).is_err())
            .collect();
        extra.sort_unstable();
        extra.dedup();
        let mut keys = sides;
        keys.extend_from_slice(&extra);
        keys.sort_unstable();
        EdgeList { keys, extra }
    }

    /// One bit per edge of the list: set for the edges in `edges`.
    pub fn mask(&self, edges: &[Edge]) -> Vec<bool> {
        let mut keys: Vec<u64> = edges.iter().filter(|[i, j]| i != j).map(|&e| key(e)).collect();
        // Layers usually come sorted; then one merging walk finds them all.
        if !keys.windows(2).all(|w| w[0] <= w[1]) {
            keys.sort_unstable();
        }
        let mut bits = vec![false; self.keys.len()];
        let mut at = 0;
        for k in keys {
            while at < self.keys.len() && self.keys[at] < k {
                at += 1;
            }
            if at < self.keys.len() && self.keys[at] == k {
                bits[at] = true;
            }
        }
        bits
    }
}

/// Base64 of bits, eight to a byte, bit `k` in byte `k / 8` at value `1 << (k % 8)`.
pub fn bits(bits: impl ExactSizeIterator<Item = bool>) -> String {
    let mut bytes = vec![0u8; bits.len().div_ceil(8)];
    for (k, bit) in bits.enumerate() {
        bytes[k / 8] |= u8::from(bit) << (k % 8);
    }
    STANDARD.encode(bytes)
}

/// Base64 of `f64`s, little-endian: exact.
pub fn f64s(values: impl Iterator<Item = f64>) -> String {
    STANDARD.encode(values.flat_map(f64::to_le_bytes).collect::<Vec<u8>>())
}

/// Base64 of `f32`s, little-endian.
pub fn f32s(values: impl Iterator<Item = f32>) -> String {
    STANDARD.encode(values.flat_map(f32::to_le_bytes).collect::<Vec<u8>>())
}

/// Base64 of `u32`s, little-endian.
pub fn u32s(values: impl Iterator<Item = u32>) -> String {
    STANDARD.encode(values.flat_map(u32::to_le_bytes).collect::<Vec<u8>>())
}

/// Base64 of bytes.
pub fn u8s(values: &[u8]) -> String {
    STANDARD.encode(values)
}

/// The two indices of the sortable number of an edge.
pub fn ends(key: u64) -> [u32; 2] {
    [(key >> 32) as u32, key as u32]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_list_is_the_sorted_union_of_sides_and_extras() {
        let list = EdgeList::new(&[[0, 1, 2]], [&[[3, 0], [0, 1], [4, 4]][..], &[[0, 3]]]);
        assert_eq!(list.keys, [key([0, 1]), key([0, 2]), key([0, 3]), key([1, 2])]);
        assert_eq!(list.extra, [key([0, 3])]);
        assert_eq!(list.mask(&[[2, 0], [3, 0], [5, 6]]), [false, true, true, false]);
        assert_eq!(ends(key([7, 2])), [2, 7]);
    }

    #[test]
    fn encodings() {
        assert_eq!(
            bits([true, false, false, true, false, false, false, false, true].into_iter()),
            "CQE="
        );
        assert_eq!(u32s([1, 256].into_iter()), "AQAAAAABAAA=");
        assert_eq!(u8s(&[0xff]), "/w==");
        let x = 0.1f64;
        assert_eq!(STANDARD.decode(f64s([x].into_iter())).unwrap(), x.to_le_bytes());
        assert_eq!(STANDARD.decode(f32s([1.5].into_iter())).unwrap(), 1.5f32.to_le_bytes());
    }
}
