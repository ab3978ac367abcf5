//! The two spanning forests SIG-AUTO works on, and the components they define.
//!
//! SIGDT2 is SIGDT plus leaf-elimination edges. By the cycle property, the minimum spanning
//! forest of SIGDT2 is the minimum spanning forest of (SIGDT's forest ∪ the leaf edges), so
//! one sort of the SIGDT edges and a merge with the few leaf edges give both forests.
//!
//! # Complexity
//! O(n log n) for the sort, O(n α(n)) otherwise.
use super::spur_path::path_with_spurs;
use crate::delaunay::Triangulation;
use crate::geometry::distance;
use crate::graph::{EdgeMask, UnionFind};
use crate::proximity::emst::{kruskal_with_sets, merge_sorted, sorted_by_length};
use crate::proximity::leaf_elimination::eliminate_leaves_with_degrees;
use crate::proximity::sigdt::sigdt_with_degrees_for;

/// SIGDT2, the minimum spanning forests of SIGDT and of SIGDT2.
pub(crate) struct Forests {
    /// SIGDT2: SIGDT with leaf elimination.
    pub(crate) graph: EdgeMask,
    /// Edges leaf elimination added.
    pub leaf_edges_added: usize,
    /// The minimum spanning forest of SIGDT ([`Forests::sigdt`]), when it differs from
    /// SIGDT2's (leaf elimination added edges); one tree serves both otherwise.
    sigdt: Option<Tree>,
    /// The minimum spanning forest of SIGDT2.
    pub sigdt2: Tree,
    /// The connected components of SIGDT2 (see [`Forests::components`]).
    components: Vec<(Vec<u32>, bool)>,
}

impl Forests {
    /// The forests of a proper triangulation, given every vertex's nearest-neighbour
    /// distance (`proximity::nearest::nearest_vertex_distances`).
    pub(crate) fn new(dt: &Triangulation, spacing: &[f64]) -> Forests {
        let (sigdt, degree) = sigdt_with_degrees_for(dt, spacing);
        let mut graph = sigdt.clone();
        let leaf_edges_added = eliminate_leaves_with_degrees(dt, &mut graph, degree);
        let sigdt_edges = dt.edge_halfedges().filter(|&h| sigdt.contains(h));
        let (sigdt_forest, sigdt_sets) = kruskal_with_sets(dt, sorted_by_length(dt, sigdt_edges));
        let leaf_edges = sorted_by_length(
            dt,
            dt.edge_halfedges().filter(|&h| graph.contains(h) && !sigdt.contains(h)),
        );
        let sigdt_tree = Tree::new(dt, &sigdt_forest);
        // Without leaf edges, SIGDT2 is SIGDT and so are their forests: one tree.
        let (sigdt, sigdt2, mut sets) = match leaf_edges.is_empty() {
            true => (None, sigdt_tree, sigdt_sets),
            false => {
                let (edges, sets) =
                    kruskal_with_sets(dt, merge_sorted(dt, &sigdt_forest, &leaf_edges));
                (Some(sigdt_tree), Tree::new(dt, &edges), sets)
            }
        };
        // Freed before the components are listed: this is SIG-AUTO's peak.
        drop((sigdt_forest, leaf_edges));
        let components = components(&mut sets, &sigdt2);
        Forests { sigdt, sigdt2, graph, leaf_edges_added, components }
    }

    /// The minimum spanning forest of SIGDT: the sample spacing of every SIGDT piece.
    pub(crate) fn sigdt(&self) -> &Tree {
        self.sigdt.as_ref().unwrap_or(&self.sigdt2)
    }

    /// The connected components of SIGDT2 (vertices in increasing order, components by
    /// their representative) and whether the component's spanning tree branches (some
    /// vertex has three or more tree edges).
    pub(crate) fn components(&self) -> &[(Vec<u32>, bool)] {
        &self.components
    }
}

/// The trees of `sets` (Kruskal's sets of the forest `tree`), as [`Forests::components`]
/// lists them: counted first, so that each gets one allocation of its size.
fn components(sets: &mut UnionFind, tree: &Tree) -> Vec<(Vec<u32>, bool)> {
    let n = tree.start.len() - 1;
    // Each vertex's representative is asked for twice (the second time in one step, the
    // paths compressed) rather than kept: this runs at SIG-AUTO's peak.
    // Slot of each representative, in increasing order of representatives.
    let mut slot = vec![u32::MAX; n];
    let mut sizes: Vec<usize> = Vec::new();
    for v in 0..n as u32 {
        if sets.find(v) == v {
            slot[v as usize] = sizes.len() as u32;
            sizes.push(0);
        }
    }
    for v in 0..n as u32 {
        sizes[slot[sets.find(v) as usize] as usize] += 1;
    }
    let mut out: Vec<(Vec<u32>, bool)> =
        sizes.into_iter().map(|size| (Vec::with_capacity(size), false)).collect();
    for v in 0..n as u32 {
        let entry = &mut out[slot[sets.find(v) as usize] as usize];
        entry.0.push(v);
        entry.1 |= tree.degree(v) > 2;
    }
    out
}

/// A forest over the triangulation's vertices as compressed adjacency lists (8 bytes a
/// vertex: `u32` offsets, as the triangulation numbers its vertices).
pub(crate) struct Tree {
    start: Vec<u32>,
    entries: Vec<u32>,
}

impl Tree {
    /// The forest with the half-edges `forest`.
    pub(crate) fn new(dt: &Triangulation, forest: &[u32]) -> Tree {
        let n = dt.num_vertices();
        // Read from the half-edges twice rather than copied: this runs at SIG-AUTO's peak.
        let edges = || forest.iter().map(|&h| [dt.origin(h), dt.dest(h)]);
        // `start[v]` counts up to the end of `v`'s run, then (filled backwards) its start.
        let mut start = vec![0u32; n + 1];
        for [a, b] in edges() {
            start[a as usize] += 1;
            start[b as usize] += 1;
        }
        for v in 1..=n {
            start[v] += start[v - 1];
        }
        let mut entries = vec![0; 2 * forest.len()];
        for [a, b] in edges().rev() {
            for (x, y) in [(b, a), (a, b)] {
                start[x as usize] -= 1;
                entries[start[x as usize] as usize] = y;
            }
        }
        Tree { start, entries }
    }

    /// The tree neighbours of `v`.
    pub(crate) fn neighbours(&self, v: u32) -> &[u32] {
        &self.entries[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }

    /// The longest tree edge at any of `vertices`.
    pub(crate) fn longest_edge(&self, dt: &Triangulation, vertices: &[u32]) -> f64 {
        vertices
            .iter()
            .flat_map(|&v| self.neighbours(v).iter().map(move |&w| (v, w)))
            .map(|(v, w)| distance(dt.point(v), dt.point(w)))
            .fold(0.0, f64::max)
    }

    /// The number of tree edges at `v`.
    pub(crate) fn degree(&self, v: u32) -> usize {
        self.neighbours(v).len()
    }

    /// The vertices of a path-shaped component in order from one end.
    pub(crate) fn walk(&self, vertices: &[u32]) -> Vec<u32> {
        let start = vertices.iter().copied().find(|&v| self.degree(v) <= 1).unwrap_or(vertices[0]);
        let mut path = Vec::with_capacity(vertices.len());
        path.push(start);
        let (mut previous, mut current) = (u32::MAX, start);
        while let Some(&step) = self.neighbours(current).iter().find(|&&w| w != previous) {
            if path.len() == vertices.len() {
                break;
            }
            path.push(step);
            previous = current;
            current = step;
        }
        path
    }

    /// The trees of this forest that hold `vertices` (which must be unions of whole trees),
    /// each as a path (walked, or with its small branches threaded in), or `None` if some
    /// tree is not a path with small branches ([`path_with_spurs`]).
    pub(crate) fn pieces_as_paths(
        &self,
        dt: &Triangulation,
        vertices: &[u32],
    ) -> Option<Vec<Vec<u32>>> {
        let tree = self;
        let mut seen: std::collections::HashSet<u32> = Default::default();
        let mut paths = Vec::new();
        for &v in vertices {
            if !seen.insert(v) {
                continue;
            }
            let mut piece = vec![v];
            let mut k = 0;
            while k < piece.len() {
                for &w in tree.neighbours(piece[k]) {
                    if seen.insert(w) {
                        piece.push(w);
                    }
                }
                k += 1;
            }
            if piece.iter().all(|&x| tree.degree(x) <= 2) {
                paths.push(tree.walk(&piece));
            } else {
                paths.push(path_with_spurs(dt, &piece, |x| tree.neighbours(x).to_vec())?);
            }
        }
        Some(paths)
    }
}
