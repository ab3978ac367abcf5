//! A path through every vertex of a spanning tree that is a path with one-vertex spurs.
//!
//! Minimum spanning trees of curve samples branch where a sample sits slightly off the line
//! of its neighbours (near corners, under noise): the tree is then a long path, its
//! diameter, with *spurs*, single vertices hanging off it. Each spur `s` on path vertex `t`
//! is put between `t` and one of `t`'s path neighbours `x`, replacing link `tx` by `ts`,
//! `sx`, when `sx` is a Delaunay edge; the side that adds the least length wins, spurs with
//! the cheapest insertion first, one spur per link. Anything else (a branch of two or more
//! vertices, a spur that finds no free link) is not a path with spurs: `None`.
//!
//! All links are Delaunay edges, so the path is simple.
//!
//! # Complexity
//! O(k log k) for a tree of `k` vertices.
use crate::delaunay::Triangulation;
use crate::geometry::distance;
use std::collections::hash_map::{Entry, HashMap};

/// The path through `vertices` (a tree whose adjacency is `neighbours`), or `None`.
pub fn path_with_spurs(
    dt: &Triangulation,
    vertices: &[u32],
    neighbours: impl Fn(u32) -> Vec<u32>,
) -> Option<Vec<u32>> {
    let length = |a: u32, b: u32| distance(dt.point(a), dt.point(b));
    let farthest = |from: u32| {
        // Depth-first over the tree: (distance, parent) per visited vertex.
        let mut best = (0.0, from);
        let mut parent = HashMap::from([(from, u32::MAX)]);
        let mut stack = vec![(from, 0.0)];
        while let Some((v, d)) = stack.pop() {
            if d > best.0 {
                best = (d, v);
            }
            for w in neighbours(v) {
                if let Entry::Vacant(slot) = parent.entry(w) {
                    slot.insert(v);
                    stack.push((w, d + length(v, w)));
                }
            }
        }
        (best.1, parent)
    };
    let (x, _) = farthest(vertices[0]);
    let (y, parent) = farthest(x);
    let mut path = vec![y];
    while let Some(&p) = parent.get(path.last()?) {
        if p == u32::MAX {
            break;
        }
        path.push(p);
    }
    let position: HashMap<u32, usize> = path.iter().enumerate().map(|(i, &v)| (v, i)).collect();
    // Each spur's insertions: (extra length, link index i for link path[i]..path[i+1], spur).
    let mut options: Vec<(f64, usize, u32)> = Vec::new();
    let mut spurs = 0;
    for &s in vertices.iter().filter(|v| !position.contains_key(v)) {
        let around = neighbours(s);
        let [t] = around[..] else { return None };
        let &i = position.get(&t)?;
        spurs += 1;
        for j in [i.wrapping_sub(1), i + 1].into_iter().filter(|&j| j < path.len()) {
            let x = path[j];
            if dt.has_edge(s, x) {
                let extra = length(t, s) + length(s, x) - length(t, x);
                options.push((extra, i.min(j), s));
            }
        }
    }
    options.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then((a.1, a.2).cmp(&(b.1, b.2))));
    let mut link_taken = vec![false; path.len()];
    let mut placed: HashMap<u32, usize> = HashMap::new();
    for (_, link, s) in options {
        if !link_taken[link] && !placed.contains_key(&s) {
            link_taken[link] = true;
            placed.insert(s, link);
        }
    }
    if placed.len() != spurs {
        return None;
    }
    let mut inserted: Vec<Option<u32>> = vec![None; path.len()];
    for (s, link) in placed {
        inserted[link] = Some(s);
    }
    let mut full = Vec::with_capacity(vertices.len());
    for (i, &v) in path.iter().enumerate() {
        full.push(v);
        full.extend(inserted[i]);
    }
    Some(full)
}
