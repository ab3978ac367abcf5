//! The candidate queue of inflating and sculpting: a binary min-heap with lazy deletion.
//!
//! Entries are `(cost, triangle)`; the smallest cost comes first and equal costs go to the
//! lower triangle number, so runs are deterministic bit for bit. Entries are never removed
//! when they go stale: the consumer re-evaluates a popped triangle and skips it if it is no
//! longer a candidate or its cost changed (the current entry was pushed when it changed).
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// A triangle waiting in the queue with the cost it had when pushed.
#[derive(Debug, Clone, Copy)]
pub struct Candidate {
    /// Change of total boundary length if the triangle is taken.
    pub cost: f64,
    /// The triangle.
    pub t: u32,
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
        other.cost.total_cmp(&self.cost).then(other.t.cmp(&self.t))
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
    /// Adds a candidate.
    #[inline]
    pub fn push(&mut self, t: u32, cost: f64) {
        self.heap.push(Candidate { cost, t });
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

    #[test]
    fn pops_cheapest_then_lowest_triangle() {
        let mut q = CandidateQueue::default();
        q.push(5, 1.0);
        q.push(3, 1.0);
        q.push(9, -2.0);
        let order: Vec<u32> = std::iter::from_fn(|| q.pop()).map(|c| c.t).collect();
        assert_eq!(order, vec![9, 3, 5]);
        let built = [(5, 1.0), (3, 1.0), (9, -2.0)].map(|(t, cost)| Candidate { cost, t });
        let mut q = CandidateQueue::from(built.to_vec());
        let order: Vec<u32> = std::iter::from_fn(|| q.pop()).map(|c| c.t).collect();
        assert_eq!(order, vec![9, 3, 5]);
    }
}
