//! Joining the open chains of SIG-AUTO: which ends meet, and which chains close.
//!
//! Every input is a *chain*: a component of SIGDT2 whose minimum spanning tree is a path
//! (its vertices in order, with its longest edge `M`). Candidate joins are the Delaunay
//! edges between two chain ends (the two ends of one chain included), tried shortest
//! first. A join `ab` is accepted when both `a` and `b` are still ends and
//!
//! > `|ab| <= 2 · max(M_a, M_b)`,
//!
//! where `M_a`, `M_b` are the longest edges of the SIGDT trees that `a` and `b` belong to
//! (joins do not raise `M`, so gaps cannot grow step by step). Joining an end to the other
//! end of its own chain closes the chain into a loop (chains of at least three points).
//!
//! The bound is the non-uniformity condition of [MOW22] Theorem 1 (`u < 2`: the longer
//! of the two edges at a sample is less than twice the shorter) applied to the gap: a gap
//! that satisfies `u < 2` at one of its ends is shorter than twice the edge there, so it is
//! always joined; the ends of an open curve that are more than twice the curve's longest
//! sample spacing apart are never joined.
//!
//! Every join is a Delaunay edge, and so are the chains' edges, so the result never has
//! crossing edges.
//!
//! # Complexity
//! O(k log k) for `k` candidate edges (at most the Delaunay degree of the ends).
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use crate::delaunay::Triangulation;
use crate::graph::UnionFind;
use crate::proximity::sigdt::TIE_SLACK;

/// The largest accepted ratio of a join to the longest edge of the chains it joins: the
/// `u < 2` of \[MOW22\] Theorem 1. SIG-AUTO always uses it; other values exist only for
/// studying the bound (`sigdt-lab/examples/join_ratio_sweep.rs`, `docs/sig-auto.md`).
pub const JOIN_RATIO: f64 = 2.0;

/// Open chains over the vertices of a triangulation, and the joins made between them.
pub(crate) struct Chains<'a> {
    dt: &'a Triangulation,
    /// Chain number of every vertex (`u32::MAX` for vertices on no chain).
    chain_of: Vec<u32>,
    /// Number of chain edges (tree edges and joins) at every vertex.
    degree: Vec<u8>,
    /// Per chain: its number of vertices and its longest tree edge.
    size: Vec<usize>,
    longest: Vec<f64>,
    /// The join bound's ratio ([`JOIN_RATIO`] in SIG-AUTO).
    ratio: f64,
}

impl<'a> Chains<'a> {
    /// No chains yet; joins will be bounded by `ratio` times the longest edge.
    pub(crate) fn new(dt: &'a Triangulation, ratio: f64) -> Chains<'a> {
        let n = dt.num_vertices();
        Chains {
            dt,
            chain_of: vec![u32::MAX; n],
            degree: vec![0; n],
            size: Vec::new(),
            longest: Vec::new(),
            ratio,
        }
    }

    /// Adds the path through `vertices` (in order, at least one).
    pub(crate) fn add(&mut self, vertices: &[u32]) {
        let id = self.size.len() as u32;
        let mut longest = 0.0f64;
        for (k, &v) in vertices.iter().enumerate() {
            self.chain_of[v as usize] = id;
            self.degree[v as usize] = if vertices.len() == 1 {
                0
            } else if k == 0 || k + 1 == vertices.len() {
                1
            } else {
                2
            };
            if k > 0 {
                let (p, q) = (self.dt.point(vertices[k - 1]), self.dt.point(v));
                longest = longest.max(crate::geometry::distance(p, q));
            }
        }
        self.size.push(vertices.len());
        self.longest.push(longest);
    }

    fn is_end(&self, v: u32) -> bool {
        self.chain_of[v as usize] != u32::MAX && self.degree[v as usize] < 2
    }

    /// Makes the joins (see the module docs) and returns them as vertex pairs.
    pub(crate) fn join(mut self) -> Vec<[u32; 2]> {
        let dt = self.dt;
        let mut candidates: Vec<(f64, usize, usize, u32, u32)> = Vec::new();
        for a in 0..dt.num_vertices() as u32 {
            if !self.is_end(a) {
                continue;
            }
            for h in dt.incident(a) {
                let b = dt.other(h, a);
                if a < b && self.is_end(b) && !self.adjacent_on_chain(a, b) {
                    let (i, j) = (dt.input_index(a), dt.input_index(b));
                    candidates.push((dt.length(h), i.min(j), i.max(j), a, b));
                }
            }
        }
        candidates.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then((x.1, x.2).cmp(&(y.1, y.2))));
        let mut merged = UnionFind::new(self.size.len());
        let mut joins = Vec::new();
        for (len, _, _, a, b) in candidates {
            if !self.is_end(a) || !self.is_end(b) {
                continue;
            }
            let (ca, cb) = (self.chain_of[a as usize], self.chain_of[b as usize]);
            let bound = self.ratio * self.longest[ca as usize].max(self.longest[cb as usize]);
            if len > bound * (1.0 + TIE_SLACK) {
                continue;
            }
            let (ra, rb) = (merged.find(ca), merged.find(cb));
            if ra == rb && self.size[ra as usize] < 3 {
                continue; // two points cannot close into a loop
            }
            if ra != rb {
                merged.union(ra, rb);
                let (root, other) = if merged.find(ra) == ra { (ra, rb) } else { (rb, ra) };
                self.size[root as usize] += self.size[other as usize];
            }
            self.degree[a as usize] += 1;
            self.degree[b as usize] += 1;
            joins.push([a, b]);
        }
        joins
    }

    /// Whether `a` and `b` are the two points of one two-point chain (already joined by
    /// their tree edge).
    fn adjacent_on_chain(&self, a: u32, b: u32) -> bool {
        let c = self.chain_of[a as usize];
        c == self.chain_of[b as usize] && self.size[c as usize] == 2
    }
}
