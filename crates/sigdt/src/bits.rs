//! Bit sets in `u64` words, shared by the triangulation (which half of each edge is
//! normalized) and the edge sets of the graphs ([`EdgeMask`](crate::graph::EdgeMask)); below
//! both, so that neither imports the other for it.

/// Bit `h` of `words`: half-edge `h` is bit `h % 64` of word `h / 64`, the layout of
/// [`EdgeMask`](crate::graph::EdgeMask) and of the triangulation's normalized bits.
#[inline]
pub(crate) fn word_bit(words: &[u64], h: u32) -> bool {
    words[(h / 64) as usize] >> (h % 64) & 1 == 1
}
