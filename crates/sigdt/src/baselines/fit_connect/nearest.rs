//! The neighbours of each point one at a time, nearest first, by a best-first walk of the
//! Delaunay triangulation.
//!
//! The `k`-th nearest neighbour of `p` is a Delaunay neighbour of `p` or of one of its
//! `k − 1` nearer neighbours (M. T. Dickerson, R. L. Drysdale, J.-R. Sack, *Simple
//! algorithms for enumerating interpoint distances and finding k nearest neighbors*,
//! IJCGA 2(3), 1992). So a priority queue seeded with `p`'s Delaunay neighbours, to which
//! each neighbour handed out adds its own, yields them in order. FITCONNECT grows most
//! neighbourhoods by a handful of points and a few to every point, so the walk is kept per
//! point and resumed. O(Δ log(kΔ)) per neighbour for Delaunay degrees Δ.
//!
//! Distances are compared as `f64` squared distances, ties by input index: every decision
//! FITCONNECT takes from a neighbourhood goes through a floating-point fit anyway.
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashSet};

use crate::delaunay::Triangulation;
use crate::geometry::squared_distance;

/// A resumable walk for every point, created on first use.
pub(crate) struct Nearest<'a> {
    dt: &'a Triangulation,
    walks: Vec<Option<Walk>>,
}

struct Walk {
    queue: BinaryHeap<Reverse<(Key, u32)>>,
    seen: HashSet<u32>,
}

/// `f64` squared distance (never NaN here) with the input index as tie-break.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Key(f64, usize);

impl Eq for Key {}

impl PartialOrd for Key {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Key {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0).then(self.1.cmp(&other.1))
    }
}

impl<'a> Nearest<'a> {
    pub(crate) fn new(dt: &'a Triangulation) -> Self {
        Nearest { dt, walks: (0..dt.num_vertices()).map(|_| None).collect() }
    }

    /// The next nearest vertex to `p` not handed out before, `None` once every other vertex
    /// has been.
    pub(crate) fn next(&mut self, p: u32) -> Option<u32> {
        let dt = self.dt;
        let walk = self.walks[p as usize].get_or_insert_with(|| {
            let mut walk = Walk { queue: BinaryHeap::new(), seen: HashSet::from([p]) };
            push_neighbours(dt, p, p, &mut walk);
            walk
        });
        let Reverse((_, v)) = walk.queue.pop()?;
        push_neighbours(dt, p, v, walk);
        Some(v)
    }

    /// Frees the walk of `p` (it is rebuilt from the start if asked again).
    pub(crate) fn forget(&mut self, p: u32) {
        self.walks[p as usize] = None;
    }
}

fn push_neighbours(dt: &Triangulation, p: u32, from: u32, walk: &mut Walk) {
    let origin = dt.point(p);
    for h in dt.incident(from) {
        let w = dt.other(h, from);
        if walk.seen.insert(w) {
            let key = Key(squared_distance(origin, dt.point(w)), dt.input_index(w));
            walk.queue.push(Reverse((key, w)));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Point;

    #[test]
    fn hands_out_every_point_in_distance_order() {
        // A jittered grid: compare with a brute-force sort for every point.
        let pts: Vec<Point> = (0..49)
            .map(|i| {
                let (x, y) = ((i % 7) as f64, (i / 7) as f64);
                [x + 0.01 * ((i * 37 % 11) as f64), y + 0.013 * ((i * 53 % 7) as f64)]
            })
            .collect();
        let dt = Triangulation::new(&pts).unwrap();
        let mut nearest = Nearest::new(&dt);
        for p in 0..dt.num_vertices() as u32 {
            let got: Vec<u32> = std::iter::from_fn(|| nearest.next(p)).collect();
            let mut want: Vec<u32> = (0..dt.num_vertices() as u32).filter(|&v| v != p).collect();
            want.sort_by(|&a, &b| {
                let (da, db) = (
                    squared_distance(dt.point(p), dt.point(a)),
                    squared_distance(dt.point(p), dt.point(b)),
                );
                da.total_cmp(&db).then(dt.input_index(a).cmp(&dt.input_index(b)))
            });
            assert_eq!(got, want, "point {p}");
        }
    }
}
