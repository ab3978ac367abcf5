//! An optional record of inflating and sculpting, step by step, for figures and debugging.
//!
//! A [`Trace`] holds the triangulation (as input indices), the initial graph `G`, the labels
//! right after the boundary of `G` is found, and every later label change in order:
//! inflating turns exterior triangles interior one at a time ([`Phase::Inflate`]) and fills
//! enclosed pockets several at once ([`Phase::Pocket`]); sculpting turns interior triangles
//! exterior one at a time ([`Phase::Sculpt`]).
//!
//! The replay is here and only here: [`Trace::boundary_at`] gives the boundary after any
//! number of steps, [`Trace::boundary_changes`] the edges each step adds to or removes from
//! it (what the HTML viewer and the Python binding are handed), [`Trace::inside_at`] the
//! labels.
//!
//! Recording costs one branch per changed label when it is off, and one [`Step`] (24 bytes)
//! per changed label when it is on.
//!
//! # Complexity
//! Building the trace: O(n) beyond the run. Each replay: O(n log n) for its edge table, then
//! O(1) per step.
use crate::geometry::Edge;

/// Which part of the run changed a label.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// Inflating took one exterior triangle (`inflate`).
    Inflate,
    /// Inflating closed a cycle and filled the enclosed pocket
    /// (`pocket`); a pocket is several steps in a row.
    Pocket,
    /// Sculpting took one interior triangle (`sculpt`).
    Sculpt,
}

impl Phase {
    /// Every phase, in the order of its numeric code (`Phase::ALL[code]`): the one encoding
    /// of phases that the CLI viewer and the Python binding use.
    pub const ALL: [Phase; 3] = [Phase::Inflate, Phase::Pocket, Phase::Sculpt];

    /// The numeric code: the index in [`Phase::ALL`].
    pub fn code(self) -> u8 {
        self as u8
    }

    /// The lower-case name: `inflate`, `pocket` or `sculpt`.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Inflate => "inflate",
            Phase::Pocket => "pocket",
            Phase::Sculpt => "sculpt",
        }
    }
}

/// One label change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Step {
    /// The triangle, an index into [`Trace::triangles`].
    pub triangle: usize,
    /// Its new label: `true` for interior.
    pub inside: bool,
    /// What changed it.
    pub phase: Phase,
}

/// Every label change of one inflate-and-sculpt run. See the module docs.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Trace {
    /// Every Delaunay triangle as input indices (duplicates by their representative),
    /// counter-clockwise.
    pub triangles: Vec<[usize; 3]>,
    /// The initial graph `G` (SIGDT, SIGDT2 or BC₀), sorted input-index edges `[i, j]`,
    /// `i < j`.
    pub graph: Vec<Edge>,
    /// The labels right after the boundary of the initial graph is found: `true` for
    /// interior.
    pub initial_inside: Vec<bool>,
    /// Edges of the initial boundary with exterior on both sides (the outside of the hull
    /// counts as exterior), sorted.
    pub dangling: Vec<Edge>,
    /// Every label change, in order.
    pub steps: Vec<Step>,
    /// Number of steps when inflating ended and sculpting started.
    pub inflated_at: usize,
}

impl Trace {
    /// The same trace with its triangles in one order whatever the layout of the
    /// triangulation's arrays (which differs with the thread count, `delaunay::divide`):
    /// each triangle from its smallest input index (counter-clockwise kept), sorted; the
    /// initial labels and the steps follow them.
    pub(crate) fn in_canonical_order(mut self) -> Trace {
        let rotated: Vec<[usize; 3]> =
            self.triangles.iter().map(|&t| crate::delaunay::from_smallest(t)).collect();
        let mut order: Vec<usize> = (0..rotated.len()).collect();
        order.sort_unstable_by_key(|&t| rotated[t]);
        let mut rank = vec![0; order.len()];
        for (new, &old) in order.iter().enumerate() {
            rank[old] = new;
        }
        self.triangles = order.iter().map(|&t| rotated[t]).collect();
        self.initial_inside = order.iter().map(|&t| self.initial_inside[t]).collect();
        self.steps.iter_mut().for_each(|s| s.triangle = rank[s.triangle]);
        self
    }

    /// The labels after the first `step` steps (all of them if `step` is larger).
    pub fn inside_at(&self, step: usize) -> Vec<bool> {
        let mut inside = self.initial_inside.clone();
        for s in &self.steps[..step.min(self.steps.len())] {
            inside[s.triangle] = s.inside;
        }
        inside
    }

    /// The boundary after the first `step` steps (all of them if `step` is larger), sorted:
    /// the edges whose two sides differ (the outside of the hull counts as exterior), plus
    /// the initially dangling edges whose sides have stayed exterior all along. (A dangling
    /// edge leaves the boundary for good once a side turns interior: it then lies between
    /// two labels until both sides are interior, and sculpting never adds dangling edges.)
    pub fn boundary_at(&self, step: usize) -> Vec<Edge> {
        let mut replay = Replay::new(self);
        for s in &self.steps[..step.min(self.steps.len())] {
            replay.apply(s, |_, _| {});
        }
        let mut edges: Vec<Edge> =
            (0..replay.edges.len()).filter(|&e| replay.on[e]).map(|e| replay.edges[e]).collect();
        edges.sort_unstable();
        edges
    }

    /// For every step, the edges it adds to or removes from the boundary, sorted: the
    /// boundary after step `s` is that before it with `boundary_changes()[s]` toggled.
    pub fn boundary_changes(&self) -> Vec<Vec<Edge>> {
        let mut replay = Replay::new(self);
        let mut changes = Vec::with_capacity(self.steps.len());
        for s in &self.steps {
            let mut toggled = Vec::new();
            replay.apply(s, |_, e| toggled.push(e));
            toggled.sort_unstable();
            changes.push(toggled);
        }
        changes
    }

    /// [`boundary_changes`](Self::boundary_changes) said through the step's triangle: bit `k`
    /// of the byte of step `s` is set when the side from `triangles[t][k]` to
    /// `triangles[t][(k + 1) % 3]` of its triangle `t` enters or leaves the boundary (a step
    /// changes no other edge). One byte a step, for compact storage.
    pub fn boundary_change_sides(&self) -> Vec<u8> {
        let mut replay = Replay::new(self);
        let mut sides = Vec::with_capacity(self.steps.len());
        for s in &self.steps {
            let mut mask = 0u8;
            replay.apply(s, |k, _| mask |= 1 << k);
            sides.push(mask);
        }
        sides
    }
}

/// The state of a replay: labels, whether each triangle was ever interior, and every edge
/// with its two sides and whether it is on the boundary.
struct Replay {
    inside: Vec<bool>,
    ever_inside: Vec<bool>,
    /// Every edge once, `[i, j]` with `i < j`.
    edges: Vec<Edge>,
    /// The triangles on each side of an edge (`usize::MAX` beyond the hull).
    sides: Vec<[usize; 2]>,
    dangling: Vec<bool>,
    /// The edges of every triangle.
    of_triangle: Vec<[usize; 3]>,
    on: Vec<bool>,
}

impl Replay {
    fn new(trace: &Trace) -> Replay {
        let nt = trace.triangles.len();
        let mut sides: Vec<(Edge, usize, usize)> = Vec::with_capacity(3 * nt);
        for (t, tri) in trace.triangles.iter().enumerate() {
            for k in 0..3 {
                let (i, j) = (tri[k], tri[(k + 1) % 3]);
                sides.push(([i.min(j), i.max(j)], t, k));
            }
        }
        sides.sort_unstable();
        let mut replay = Replay {
            inside: trace.initial_inside.clone(),
            ever_inside: trace.initial_inside.clone(),
            edges: Vec::new(),
            sides: Vec::new(),
            dangling: Vec::new(),
            of_triangle: vec![[0; 3]; nt],
            on: Vec::new(),
        };
        for (e, t, k) in sides {
            if replay.edges.last() == Some(&e) {
                replay.sides.last_mut().expect("an edge has a first side")[1] = t;
            } else {
                replay.edges.push(e);
                replay.sides.push([t, usize::MAX]);
                replay.dangling.push(trace.dangling.binary_search(&e).is_ok());
            }
            replay.of_triangle[t][k] = replay.edges.len() - 1;
        }
        replay.on = (0..replay.edges.len()).map(|e| replay.member(e)).collect();
        replay
    }

    /// The boundary rule of [`Trace::boundary_at`] for edge `e` under the current labels.
    fn member(&self, e: usize) -> bool {
        let [left, right] = self.sides[e];
        let label = |t: usize| t != usize::MAX && self.inside[t];
        let ever = |t: usize| t != usize::MAX && self.ever_inside[t];
        label(left) != label(right) || (self.dangling[e] && !ever(left) && !ever(right))
    }

    /// Applies step `s`, calling `toggled(k, edge)` with every edge that enters or leaves the
    /// boundary: side `k` of the step's triangle.
    fn apply(&mut self, s: &Step, mut toggled: impl FnMut(usize, Edge)) {
        self.inside[s.triangle] = s.inside;
        self.ever_inside[s.triangle] |= s.inside;
        for (k, e) in self.of_triangle[s.triangle].into_iter().enumerate() {
            let now = self.member(e);
            if now != self.on[e] {
                self.on[e] = now;
                toggled(k, self.edges[e]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two triangles `0 1 2` and `0 2 3` of a square, both exterior, with the dangling
    /// path `0-1-2` as the initial graph.
    fn square() -> Trace {
        Trace {
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            graph: vec![[0, 1], [1, 2]],
            initial_inside: vec![false, false],
            dangling: vec![[0, 1], [1, 2]],
            steps: vec![
                Step { triangle: 0, inside: true, phase: Phase::Inflate },
                Step { triangle: 1, inside: true, phase: Phase::Inflate },
                Step { triangle: 1, inside: false, phase: Phase::Sculpt },
            ],
            inflated_at: 2,
        }
    }

    #[test]
    fn changes_toggle_one_boundary_into_the_next() {
        let trace = square();
        assert_eq!(trace.boundary_at(0), vec![[0, 1], [1, 2]]);
        assert_eq!(trace.boundary_at(1), vec![[0, 1], [0, 2], [1, 2]]);
        assert_eq!(trace.boundary_at(2), vec![[0, 1], [0, 3], [1, 2], [2, 3]]);
        assert_eq!(trace.boundary_at(9), trace.boundary_at(1));
        let changes = trace.boundary_changes();
        assert_eq!(
            changes,
            vec![vec![[0, 2]], vec![[0, 2], [0, 3], [2, 3]], vec![[0, 2], [0, 3], [2, 3]]]
        );
        let mut boundary = trace.boundary_at(0);
        for (s, change) in changes.iter().enumerate() {
            for e in change {
                match boundary.binary_search(e) {
                    Ok(k) => drop(boundary.remove(k)),
                    Err(k) => boundary.insert(k, *e),
                }
            }
            assert_eq!(boundary, trace.boundary_at(s + 1));
        }
        assert_eq!(trace.inside_at(2), vec![true, true]);
        assert_eq!(Phase::ALL.map(Phase::code), [0, 1, 2]);
    }

    #[test]
    fn change_sides_name_the_changed_edges() {
        let trace = square();
        // Triangle 0 is [0, 1, 2]: side 2 is 2-0. Triangle 1 is [0, 2, 3]: all three sides.
        assert_eq!(trace.boundary_change_sides(), vec![0b100, 0b111, 0b111]);
        for ((step, mask), change) in
            trace.steps.iter().zip(trace.boundary_change_sides()).zip(trace.boundary_changes())
        {
            let tri = trace.triangles[step.triangle];
            let mut sides: Vec<Edge> = (0..3)
                .filter(|k| mask & (1 << k) != 0)
                .map(|k| {
                    let (i, j) = (tri[k], tri[(k + 1) % 3]);
                    [i.min(j), i.max(j)]
                })
                .collect();
            sides.sort_unstable();
            assert_eq!(sides, change);
        }
    }
}
