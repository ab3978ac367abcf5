//! A path through every vertex of a spanning tree that is a path with small branches.
//!
//! Minimum spanning trees of curve samples branch where a sample sits slightly off the line
//! of its neighbours (near corners, under noise), and at cusps sampled more densely than
//! their sides: the tree is then a long path, its diameter, with small *branches* hanging
//! off it. A branch of at most [`MAX_BRANCH`] vertices hanging off path vertex `t` is
//! threaded into the link from `t` to one of its path neighbours `x`: the link `tx` is
//! replaced by a walk `t b1 … bk x` through all of the branch's vertices, in the order and
//! on the side that add the least length, using Delaunay edges only. Branches with the
//! cheapest threading go first, one branch per link. Anything else (a larger branch, a
//! branch that finds no free link) is not a path with branches: `None`.
//!
//! A one-vertex branch (a *spur*) is the common case. The serif cusp of a glyph is the
//! reason for more: its two sides' samples next to the tip are closer to each other than to
//! the tip, so the tree reaches the tip through one side and hangs the other side off it.
//! The bound on the branch size keeps the orderings tried few (`4! = 24`); on the 522
//! public cases any bound from 3 to 7 gives the same results, and 1 (spurs only) loses one
//! open curve.
//!
//! All links are Delaunay edges between distinct vertices, so the path is simple.
//!
//! # Complexity
//! O(k log k) for a tree of `k` vertices (at most `MAX_BRANCH!` orderings per branch).
use crate::delaunay::Triangulation;
use crate::geometry::distance;
use std::collections::hash_map::{Entry, HashMap};

/// The path through `vertices` (a tree whose adjacency is `neighbours`), or `None`
/// (see the module docs).
pub(crate) fn path_with_spurs(
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
    let branches = branches_off(vertices, &position, &neighbours)?;
    // Each branch's insertions: (extra length, link i for path[i]..path[i+1], branch, order).
    let mut options: Vec<(f64, usize, usize, Vec<u32>)> = Vec::new();
    for (b, (i, members)) in branches.iter().enumerate() {
        let t = path[*i];
        for j in [i.wrapping_sub(1), i + 1].into_iter().filter(|&j| j < path.len()) {
            let x = path[j];
            let mut best: Option<(f64, Vec<u32>)> = None;
            for_each_order(members, &mut |order| {
                let mut walk = Vec::with_capacity(order.len() + 2);
                walk.push(t);
                walk.extend_from_slice(order);
                walk.push(x);
                if walk.windows(2).all(|w| dt.has_edge(w[0], w[1])) {
                    let extra =
                        walk.windows(2).map(|w| length(w[0], w[1])).sum::<f64>() - length(t, x);
                    let better = match &best {
                        None => true,
                        Some((e, _)) => extra < *e,
                    };
                    if better {
                        best = Some((extra, order.to_vec()));
                    }
                }
            });
            if let Some((extra, mut order)) = best {
                if j < *i {
                    order.reverse(); // the link runs x .. t
                }
                options.push((extra, (*i).min(j), b, order));
            }
        }
    }
    options.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then((a.1, a.2).cmp(&(b.1, b.2))));
    let mut inserted: Vec<Option<Vec<u32>>> = vec![None; path.len()];
    let mut placed = vec![false; branches.len()];
    for (_, link, b, order) in options {
        if inserted[link].is_none() && !placed[b] {
            placed[b] = true;
            inserted[link] = Some(order);
        }
    }
    if placed.contains(&false) {
        return None;
    }
    let mut full = Vec::with_capacity(vertices.len());
    for (i, &v) in path.iter().enumerate() {
        full.push(v);
        full.extend(inserted[i].iter().flatten());
    }
    Some(full)
}

/// The most samples a branch may have to be threaded into a link.
pub(crate) const MAX_BRANCH: usize = 4;

/// The vertices off the path, grouped into branches (connected once the path is removed),
/// each with the path position it hangs from; `None` if a branch is larger than
/// [`MAX_BRANCH`].
fn branches_off(
    vertices: &[u32],
    position: &HashMap<u32, usize>,
    neighbours: &impl Fn(u32) -> Vec<u32>,
) -> Option<Vec<(usize, Vec<u32>)>> {
    let mut seen: std::collections::HashSet<u32> = Default::default();
    let mut branches = Vec::new();
    for &s in vertices.iter().filter(|v| !position.contains_key(v)) {
        if !seen.insert(s) {
            continue;
        }
        let (mut members, mut anchor) = (vec![s], None);
        let mut k = 0;
        while k < members.len() {
            for w in neighbours(members[k]) {
                if let Some(&i) = position.get(&w) {
                    anchor = Some(i);
                } else if seen.insert(w) {
                    members.push(w);
                }
            }
            k += 1;
        }
        if members.len() > MAX_BRANCH {
            return None;
        }
        branches.push((anchor?, members));
    }
    Some(branches)
}

/// Calls `f` with every ordering of `items` (at most [`MAX_BRANCH`] of them).
fn for_each_order(items: &[u32], f: &mut impl FnMut(&[u32])) {
    fn permute(items: &mut Vec<u32>, k: usize, f: &mut impl FnMut(&[u32])) {
        if k == items.len() {
            f(items);
            return;
        }
        for i in k..items.len() {
            items.swap(k, i);
            permute(items, k + 1, f);
            items.swap(k, i);
        }
    }
    permute(&mut items.to_vec(), 0, f);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Point;

    #[test]
    fn a_cusp_reached_through_one_side_is_threaded_in_order() {
        // A line y = 0 with a narrow spike between x = 10 and x = 11: sides (10.2, 1) and
        // (10.8, 1), tip (10.5, 3). The tree reaches the tip through the right side and hangs
        // the left side off the right side's sample: a three-vertex branch at (10, 0).
        let mut points: Vec<Point> = (0..=20).map(|i| [i as f64, 0.0]).collect();
        points.extend([[10.2, 1.0], [10.8, 1.0], [10.5, 3.0]]);
        let (left, right, tip) = (21u32, 22u32, 23u32);
        let dt = Triangulation::new(&points).unwrap();
        let vertex =
            |i: usize| (0..dt.num_vertices() as u32).find(|&v| dt.input_index(v) == i).unwrap();
        let mut tree: HashMap<u32, Vec<u32>> = HashMap::new();
        let mut link = |a: u32, b: u32| {
            tree.entry(vertex(a as usize)).or_default().push(vertex(b as usize));
            tree.entry(vertex(b as usize)).or_default().push(vertex(a as usize));
        };
        for i in 0..20 {
            link(i, i + 1);
        }
        link(10, right);
        link(right, left);
        link(right, tip);
        let vertices: Vec<u32> = (0..points.len()).map(vertex).collect();
        let path = path_with_spurs(&dt, &vertices, |v| tree[&v].clone()).expect("a path");
        let mut order: Vec<usize> = path.iter().map(|&v| dt.input_index(v)).collect();
        if order[0] != 0 {
            order.reverse();
        }
        let mut expected: Vec<usize> = (0..=10).collect();
        expected.extend([left as usize, tip as usize, right as usize]);
        expected.extend(11..=20);
        assert_eq!(order, expected);
    }

    #[test]
    fn a_branch_above_the_bound_is_not_a_path() {
        // Five samples stacked above (10, 0), each hanging off the one below.
        let mut points: Vec<Point> = (0..=20).map(|i| [i as f64, 0.0]).collect();
        points.extend((1..=MAX_BRANCH + 1).map(|k| [10.0, 0.9 * k as f64]));
        let dt = Triangulation::new(&points).unwrap();
        let vertex =
            |i: usize| (0..dt.num_vertices() as u32).find(|&v| dt.input_index(v) == i).unwrap();
        let mut tree: HashMap<u32, Vec<u32>> = HashMap::new();
        let mut link = |a: usize, b: usize| {
            tree.entry(vertex(a)).or_default().push(vertex(b));
            tree.entry(vertex(b)).or_default().push(vertex(a));
        };
        for i in 0..20 {
            link(i, i + 1);
        }
        link(10, 21);
        for k in 21..points.len() - 1 {
            link(k, k + 1);
        }
        let vertices: Vec<u32> = (0..points.len()).map(vertex).collect();
        assert!(path_with_spurs(&dt, &vertices, |v| tree[&v].clone()).is_none());
    }
}
