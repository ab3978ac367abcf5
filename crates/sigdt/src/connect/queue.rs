//! The candidate queue of inflating and sculpting: a binary min-heap with lazy deletion.
//!
//! Entries are `(cost, triangle)`; the smallest cost comes first and equal costs go to the
//! triangle whose vertices come first (its smallest vertex, then the next one
//! counter-clockwise: vertices are numbered by the canonical insertion order, so this
//! depends on the points alone, not on where the triangle is stored), so runs are
//! deterministic bit for bit and the same on every layout of the triangle arrays. Entries
//! are never removed when they go stale: the consumer re-evaluates a popped triangle and
//! skips it if it is no longer a candidate or its cost changed (the current entry was
//! pushed when it changed).
use crate::delaunay::Triangulation;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// A triangle waiting in the queue with the cost it had when pushed.
#[derive(Debug, Clone, Copy)]
pub struct Candidate {
    /// Change of total boundary length if the triangle is taken.
    pub cost: f64,
    /// The triangle's [`vertex_key`], which orders ties.
    key: u64,
    /// The triangle.
    pub t: u32,
}

impl Candidate {
    /// The candidate `t` of `dt` at `cost`.
    pub fn new(dt: &Triangulation, t: u32, cost: f64) -> Candidate {
        Candidate { cost, key: vertex_key(dt, t), t }
    }
}

/// A triangle named by its vertices, whatever its number and first corner: its smallest
/// vertex and the vertex after it counter-clockwise (an edge in that direction belongs to
/// one triangle only).
fn vertex_key(dt: &Triangulation, t: u32) -> u64 {
    let [a, b, c] = [3 * t, 3 * t + 1, 3 * t + 2].map(|h| dt.origin(h));
    let (first, then) = if a < b && a < c {
        (a, b)
    } else if b < c {
        (b, c)
    } else {
        (c, a)
    };
    u64::from(first) << 32 | u64::from(then)
}

impl PartialEq for Candidate {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Candidate {}
impl PartialOrd for Candidate {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Candidate {
    /// Reversed, so that `BinaryHeap` (a max-heap) pops the cheapest first.
    fn cmp(&self, other: &Self) -> Ordering {
        other.cost.total_cmp(&self.cost).then(other.key.cmp(&self.key))
    }
}

/// Min-queue of candidates.
#[derive(Debug, Default)]
pub struct CandidateQueue {
    heap: BinaryHeap<Candidate>,
}

impl From<Vec<Candidate>> for CandidateQueue {
    /// The queue of `candidates`, in linear time.
    fn from(candidates: Vec<Candidate>) -> CandidateQueue {
        CandidateQueue { heap: BinaryHeap::from(candidates) }
    }
}

impl CandidateQueue {
    /// Adds the triangle `t` of `dt` at `cost`.
    #[inline]
    pub fn push(&mut self, dt: &Triangulation, t: u32, cost: f64) {
        self.heap.push(Candidate::new(dt, t, cost));
    }

    /// Removes and returns the cheapest candidate.
    #[inline]
    pub fn pop(&mut self) -> Option<Candidate> {
        self.heap.pop()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fan of triangles around the origin: ties go to the triangle with the smaller
    /// vertices, whatever its number; the same triangle has the same key on every layout.
    #[test]
    fn pops_cheapest_then_the_triangle_with_the_first_vertices() {
        let points = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];
        let dt = Triangulation::new(&points).unwrap();
        let triangles = 0..dt.num_triangles() as u32;
        let mut by_key: Vec<u32> = triangles.clone().collect();
        by_key.sort_by_key(|&t| vertex_key(&dt, t));
        let mut q = CandidateQueue::default();
        for t in triangles.clone().rev() {
            q.push(&dt, t, 1.0);
        }
        let cheap = by_key[by_key.len() - 1];
        q.push(&dt, cheap, -2.0);
        let order: Vec<u32> = std::iter::from_fn(|| q.pop()).map(|c| c.t).collect();
        let mut expected = vec![cheap];
        expected.extend(&by_key);
        assert_eq!(order, expected);
        let shuffled = dt.with_triangles_shuffled(3);
        let keys = |dt: &Triangulation| {
            let mut keys: Vec<u64> = triangles.clone().map(|t| vertex_key(dt, t)).collect();
            keys.sort_unstable();
            keys
        };
        assert_eq!(keys(&dt), keys(&shuffled));
    }
}
