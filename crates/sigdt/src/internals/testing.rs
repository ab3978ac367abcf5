//! Checkers shared by every test layer (unit, property, golden, CLI, fuzz).
//!
//! [`check_reconstruction`] states the output invariants every method must keep: edges join
//! two distinct valid indices and are sorted and unique; loops and paths are simple and
//! disjoint (paths may share a junction end in a network) and agree with the edges; a
//! manifold status means every distinct point has degree 2; no two output edges cross, unless
//! the status is [`Crossing`](Status::Crossing), which needs a crossing, or
//! [`Unfinished`](Status::Unfinished), whose edges may cross.
use crate::geometry::{Edge, Point};
use crate::result::{LeftOutReason, Reconstruction, Status, Vertices};
use crate::segment_grid::first_crossing;

/// Checks the output invariants of `rec` for `points`; the error says what is violated.
/// With [`Vertices::New`] the edges, loops and paths are checked on the new vertices, while
/// duplicates and left-out points still name input points.
pub fn check_reconstruction(points: &[Point], rec: &Reconstruction) -> Result<(), String> {
    let inputs = points.len();
    let new = matches!(rec.vertices, Vertices::New(_));
    let points: &[Point] = match &rec.vertices {
        Vertices::Input => points,
        Vertices::Moved(moved) if moved.len() != points.len() => {
            return Err(format!("{} moved points for {} points", moved.len(), points.len()));
        }
        Vertices::Moved(moved) | Vertices::New(moved) => moved,
    };
    let n = points.len();
    for w in rec.edges.windows(2) {
        if w[0] >= w[1] {
            return Err(format!("edges not sorted and unique at {:?}, {:?}", w[0], w[1]));
        }
    }
    for &[i, j] in &rec.edges {
        if i >= j || j >= n {
            return Err(format!("edge [{i}, {j}] is not [i < j] within {n} points"));
        }
        if points[i] == points[j] {
            return Err(format!("edge [{i}, {j}] joins two equal points"));
        }
    }
    // Every vertex is on at most one chain, once, except that in a network (junctions) a
    // junction ends several paths.
    let network = matches!(rec.status, Status::Network | Status::Branching);
    let mut from_chains: Vec<Edge> = Vec::new();
    let mut on_chain = vec![false; n];
    let mut path_end = vec![false; n];
    for (closed, chain) in
        rec.loops.iter().map(|l| (true, l)).chain(rec.paths.iter().map(|p| (false, p)))
    {
        if chain.len() < if closed { 3 } else { 2 } {
            return Err(format!("chain {chain:?} is too short"));
        }
        let k = chain.len();
        for (a, &v) in chain.iter().enumerate() {
            if v >= n {
                return Err(format!("vertex {v} is out of range"));
            }
            if network && !closed && (a == 0 || a == k - 1) {
                path_end[v] = true;
            } else if std::mem::replace(&mut on_chain[v], true) {
                return Err(format!("vertex {v} is on two chains, or twice on one"));
            }
        }
        let links = if closed { k } else { k - 1 };
        from_chains.extend((0..links).map(|a| {
            let (x, y) = (chain[a], chain[(a + 1) % k]);
            [x.min(y), x.max(y)]
        }));
    }
    if let Some(v) = (0..n).find(|&v| path_end[v] && on_chain[v]) {
        return Err(format!("vertex {v} ends a path and lies inside a chain"));
    }
    from_chains.sort_unstable();
    if network {
        // A path that closes through a junction lists the junction at both ends, which
        // repeats no edge; paths between the same two junctions never share an edge.
        from_chains.dedup();
    }
    if from_chains != rec.edges {
        return Err("edges differ from the edges of the loops and paths".into());
    }
    if rec.duplicates.iter().flatten().any(|&i| i >= inputs) {
        return Err("a duplicate is out of range".into());
    }
    if rec.status.is_manifold() {
        // Duplicates and the points left out on purpose are on no loop.
        let off: Vec<bool> = {
            let mut d = vec![false; n];
            if !new {
                rec.duplicates.iter().for_each(|&[i, _]| d[i] = true);
                rec.left_out.iter().filter(|l| l.index < n).for_each(|l| d[l.index] = true);
            }
            d
        };
        if let Some(v) = (0..n).find(|&v| !off[v] && !on_chain[v]) {
            return Err(format!("status {} but point {v} is on no loop", rec.status.name()));
        }
        if !rec.paths.is_empty() {
            return Err("manifold status with open paths".into());
        }
    }
    if let Status::SculptingStuck { left_out } = &rec.status {
        if left_out.is_empty() || left_out.iter().any(|&v| v >= n || on_chain[v]) {
            return Err("left-out points must be off every loop".into());
        }
        let inside: Vec<usize> = rec
            .left_out
            .iter()
            .filter(|l| l.reason == LeftOutReason::Inside)
            .map(|l| l.index)
            .collect();
        if &inside != left_out {
            return Err("the status's left-out points differ from left_out".into());
        }
    }
    for w in rec.left_out.windows(2) {
        if w[0].index >= w[1].index {
            return Err(format!("left_out not sorted and unique at {:?}, {:?}", w[0], w[1]));
        }
    }
    let has_edge: Vec<bool> = {
        let mut has = vec![false; n];
        rec.edges.iter().flatten().for_each(|&v| has[v] = true);
        has
    };
    let has_edge = |i: usize| !new && has_edge[i];
    if let Some(l) = rec.left_out.iter().find(|l| l.index >= inputs || has_edge(l.index)) {
        return Err(format!("left-out point {} is out of range or has an edge", l.index));
    }
    match first_crossing(points, &rec.edges) {
        Some((a, b)) if !matches!(rec.status, Status::Crossing | Status::Unfinished) => {
            return Err(format!("edges {a:?} and {b:?} cross"));
        }
        None if rec.status == Status::Crossing => {
            return Err("status crossing but no two edges cross".into());
        }
        _ => {}
    }
    Ok(())
}

/// The edges a graph filter (vertex pairs on the triangulation) gives for `points`, as
/// sorted input-index pairs; for the baselines' unit tests.
pub fn filter_edges(
    points: &[Point],
    filter: impl Fn(&crate::delaunay::Triangulation) -> Vec<[u32; 2]>,
) -> Vec<Edge> {
    let dt = crate::delaunay::Triangulation::new(points).expect("valid test points");
    dt.to_input_edges(filter(&dt))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn detects_a_crossing_bow_tie() {
        let pts = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        let rec = Reconstruction {
            edges: vec![[0, 1], [0, 3], [1, 2], [2, 3]],
            loops: vec![vec![0, 1, 2, 3]],
            ..Reconstruction::default()
        };
        assert!(check_reconstruction(&pts, &rec).unwrap_err().contains("cross"));
    }

    #[test]
    fn new_vertices_are_checked_apart_from_the_input() {
        // Three new vertices for six input points, two of them duplicates.
        let inputs = [[0.0, 0.0]; 6];
        let mut rec = Reconstruction {
            edges: vec![[0, 1], [0, 2], [1, 2]],
            loops: vec![vec![0, 1, 2]],
            duplicates: vec![[4, 0], [5, 1]],
            vertices: Vertices::New(vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
            ..Reconstruction::default()
        };
        check_reconstruction(&inputs, &rec).unwrap();
        rec.duplicates.push([6, 0]);
        assert!(check_reconstruction(&inputs, &rec).unwrap_err().contains("duplicate"));
    }

    #[test]
    fn accepts_a_square() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let rec = crate::reconstruct(&pts, &crate::Options::default()).unwrap();
        check_reconstruction(&pts, &rec).unwrap();
    }
}
