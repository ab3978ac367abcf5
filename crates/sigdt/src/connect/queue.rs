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

/// A triangle waiting in the queue with the cost it had when pushed (16 bytes: the queue
/// can be the largest array alive, so the tie key is computed only on a tie).
#[derive(Debug, Clone, Copy)]
pub struct Candidate {
    /// Change of total boundary length if the triangle is taken.
    pub cost: f64,
    /// The triangle.
    pub t: u32,
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

/// The order of the queue: cost, then the triangles' vertices.
fn order(dt: &Triangulation, a: &Candidate, b: &Candidate) -> Ordering {
    a.cost.total_cmp(&b.cost).then_with(|| vertex_key(dt, a.t).cmp(&vertex_key(dt, b.t)))
}

/// Min-queue of candidates: a binary heap ordered by [`order`].
#[derive(Debug, Default)]
pub struct CandidateQueue {
    heap: Vec<Candidate>,
}

impl CandidateQueue {
    /// The queue of `candidates`, in linear time.
    pub fn new(dt: &Triangulation, candidates: Vec<Candidate>) -> CandidateQueue {
        let mut queue = CandidateQueue { heap: candidates };
        for i in (0..queue.heap.len() / 2).rev() {
            queue.sift_down(dt, i);
        }
        queue
    }

    /// Adds the triangle `t` at `cost`.
    pub fn push(&mut self, dt: &Triangulation, t: u32, cost: f64) {
        self.heap.push(Candidate { cost, t });
        let mut i = self.heap.len() - 1;
        while i > 0 {
            let parent = (i - 1) / 2;
            if order(dt, &self.heap[i], &self.heap[parent]) != Ordering::Less {
                break;
            }
            self.heap.swap(i, parent);
            i = parent;
        }
    }

    /// Removes and returns the cheapest candidate.
    pub fn pop(&mut self, dt: &Triangulation) -> Option<Candidate> {
        let last = self.heap.len().checked_sub(1)?;
        self.heap.swap(0, last);
        let top = self.heap.pop();
        self.sift_down(dt, 0);
        top
    }

    fn sift_down(&mut self, dt: &Triangulation, mut i: usize) {
        let n = self.heap.len();
        loop {
            let (left, right) = (2 * i + 1, 2 * i + 2);
            let mut least = i;
            for child in [left, right] {
                if child < n && order(dt, &self.heap[child], &self.heap[least]) == Ordering::Less {
                    least = child;
                }
            }
            if least == i {
                return;
            }
            self.heap.swap(i, least);
            i = least;
        }
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
        let cheap = by_key[by_key.len() - 1];
        let mut expected = vec![cheap];
        expected.extend(&by_key);
        let mut q = CandidateQueue::default();
        for t in triangles.clone().rev() {
            q.push(&dt, t, 1.0);
        }
        q.push(&dt, cheap, -2.0);
        let popped: Vec<u32> = std::iter::from_fn(|| q.pop(&dt)).map(|c| c.t).collect();
        assert_eq!(popped, expected);
        let mut built: Vec<Candidate> =
            triangles.clone().map(|t| Candidate { cost: 1.0, t }).collect();
        built.push(Candidate { cost: -2.0, t: cheap });
        let mut q = CandidateQueue::new(&dt, built);
        let popped: Vec<u32> = std::iter::from_fn(|| q.pop(&dt)).map(|c| c.t).collect();
        assert_eq!(popped, expected);
        let shuffled = dt.with_triangles_shuffled(3);
        let keys = |dt: &Triangulation| {
            let mut keys: Vec<u64> = triangles.clone().map(|t| vertex_key(dt, t)).collect();
            keys.sort_unstable();
            keys
        };
        assert_eq!(keys(&dt), keys(&shuffled));
    }
}
