//! SIG-AUTO's outlier rule: a point is a sample of no curve when it lies farther from the
//! curve than the curve's sample spacing there.
//!
//! Noise moves a sample off its curve by less than the spacing of the samples (that is what
//! separates noise from outliers), so a point farther away than the spacing cannot be a
//! noisy sample. "The curve" near a point is what the reconstruction says it is: the segments
//! at the place where the point is attached, and their straight continuations (tangent
//! rays). The rays matter at sharp corners: a sampled corner lies on the continuation of
//! its two sides however far it is from the chord between its neighbours, so it is never
//! taken for an outlier. The rule is applied twice:
//!
//! 1. [`branch_outliers`], on a component's minimum spanning tree: a *branch* hanging off
//!    the tree's main path (its longest path) is left out when every one of its vertices is
//!    farther than the spacing at the attachment vertex `a` (the longer of the path edges
//!    at `a`) from those path edges and their continuations beyond `a`. A branch with one
//!    vertex near the curve (a noisy sample, a corner, a cusp, the near end of another
//!    curve) is kept, and read again as a tree of its own: a branch of it is left out by
//!    the same rule when it also lies farther than twice the spacing from every other
//!    point. A tree that is a path (a chain) has no branches, but the spanning tree can
//!    string outliers onto the end of a closed curve's path: an end run that breaks
//!    `u < 2`, is far off by the same rule, and keeps the ends from closing with `u < 2`
//!    where they close without it, is left out too ([`chain_end_outliers`]).
//! 2. [`detour_outliers`], on the reading: a *detour* is a run of vertices between two
//!    reading vertices `a` and `b` that are joined by a Delaunay edge. It is cut out, and
//!    `ab` joined, when every run vertex is farther than the spacing `|ab|` (the curve's
//!    sample spacing there once the run is gone) from `ab` and from the continuations of
//!    the reading beyond `a` and `b`, and when `ab` continues the reading as a sampled curve
//!    would: `u < 2` between `ab` and the edges beyond, and at the vertices beyond; and when
//!    the run is the smaller part of its loop or path (a run as large as the rest is the
//!    curve, not a detour from it).
//!
//! # Complexity
//! Branches: O(k · h) per component of `k` points, `h` the depth of branches within kept
//! branches (one or two on curve input). Detours: each walk from `a` stops at the
//! first vertex within the spacing, so O(n · degree) per pass over the reading on curve
//! input; a cut shortens the reading, so at most `n` cuts.
use super::reading::{Reading, NONE};
use super::spanning_forests::Tree;
use super::vertex_marks::{VertexMap, VertexSet};
use super::Steps;
use crate::delaunay::Triangulation;
use crate::geometry::{distance, ray_distance, segment_distance, squared_distance, Point};
use crate::proximity::sigdt::TIE_SLACK;

/// Scratch space of [`branch_outliers`] over a triangulation's vertices, made once for all
/// the components of a round.
pub(crate) struct BranchScratch {
    /// The (sub)tree each vertex is being read in, by an id unique over every call.
    tree_of: VertexMap,
    next_id: u32,
    /// Position of each vertex on the main path of the tree being read.
    position: VertexMap,
    /// Vertices already in a branch.
    in_branch: VertexSet,
    /// Parent of each vertex reached by the search for the main path.
    parent: VertexMap,
    /// The members of the branch whose distance to the other points is measured.
    members: VertexSet,
}

impl BranchScratch {
    /// Scratch space for the vertices of `dt`.
    pub(crate) fn new(dt: &Triangulation) -> BranchScratch {
        let n = dt.num_vertices();
        BranchScratch {
            tree_of: VertexMap::new(n),
            next_id: 0,
            position: VertexMap::new(n),
            in_branch: VertexSet::new(n),
            parent: VertexMap::new(n),
            members: VertexSet::new(n),
        }
    }
}

/// The vertices of `vertices` (one component of `dt`, a tree of `tree`) that lie on branches
/// far from the tree's main path (rule 1 of the module docs).
///
/// A branch that is kept (one of its vertices lies near the curve) is a tree of its own,
/// and the rule is applied to it again: outliers can hang off a second curve that hangs
/// off the first (a small loop joined to a large one by the spanning tree). Such a nested
/// branch is left out only if it also lies farther than twice the spacing from every other
/// point (an edge to any of them would break `u < 2`): the curve it was read against is a
/// piece of the tree, and another piece (a parallel strand of a noisy band) may run nearer.
///
/// A branch with a vertex that `curve` says is on a curve for sure (a network's, read from
/// the junctions) is kept.
pub(crate) fn branch_outliers(
    dt: &Triangulation,
    vertices: &[u32],
    tree: &Tree,
    curve: impl Fn(u32) -> bool,
    steps: &Steps,
    scratch: &mut BranchScratch,
) -> Vec<u32> {
    // A subtree's members are the vertices of its branch, so its adjacency is the tree's
    // restricted to them.
    let mut outliers = Vec::new();
    let mut trees = vec![vertices.to_vec()];
    let first_id = scratch.next_id;
    while let Some(members) = trees.pop() {
        let nested = scratch.next_id > first_id;
        let id = scratch.next_id;
        scratch.next_id += 1;
        members.iter().for_each(|&v| scratch.tree_of.set(v, id));
        let BranchScratch { tree_of, position, in_branch, parent, members: set, .. } = scratch;
        let within = |v: u32| {
            let tree_of = &*tree_of;
            tree.neighbours(v).iter().copied().filter(move |&w| tree_of.get(w) == Some(id))
        };
        let path = main_path(dt, &members, &within, parent);
        let search = Search { within: &within, curve: &curve, nested, steps };
        let (far, kept) = far_branches(dt, &members, &path, search, position, in_branch, set);
        outliers.extend(far);
        trees.extend(kept.into_iter().filter(|b| b.len() >= OWN_CURVE_POINTS));
    }
    outliers.sort_unstable();
    outliers
}

/// What one level of [`branch_outliers`] reads a tree with.
struct Search<'a, W, C> {
    within: &'a W,
    curve: &'a C,
    nested: bool,
    steps: &'a Steps,
}

/// One level of [`branch_outliers`]: the vertices of the branches off `path` (the main path
/// of the tree `vertices`) that lie far from it (and, when nested, from every other point),
/// and the branches kept.
fn far_branches<W, I, C>(
    dt: &Triangulation,
    vertices: &[u32],
    path: &[u32],
    search: Search<'_, W, C>,
    position: &mut VertexMap,
    in_branch: &mut VertexSet,
    set: &mut VertexSet,
) -> (Vec<u32>, Vec<Vec<u32>>)
where
    W: Fn(u32) -> I,
    I: Iterator<Item = u32>,
    C: Fn(u32) -> bool,
{
    position.clear();
    path.iter().enumerate().for_each(|(i, &v)| position.set(v, i as u32));
    in_branch.clear();
    let (mut outliers, mut kept) = (Vec::new(), Vec::new());
    for &start in vertices.iter().filter(|&&v| position.get(v).is_none()) {
        if !in_branch.insert(start) {
            continue;
        }
        let (mut members, mut anchor) = (vec![start], None);
        // The longest tree edge between two members: off the path, a tree neighbour of a
        // member is a member.
        let mut inner = 0.0f64;
        let mut k = 0;
        while k < members.len() {
            let v = members[k];
            for w in (search.within)(v) {
                if let Some(i) = position.get(w) {
                    anchor = Some(i as usize);
                    continue;
                }
                inner = inner.max(distance(dt.point(v), dt.point(w)));
                if in_branch.insert(w) {
                    members.push(w);
                }
            }
            k += 1;
        }
        let Some(i) = anchor else { continue };
        let branch = Branch { members: &members, inner, path, at: i };
        let nested = search.nested.then_some(&mut *set);
        if !members.iter().any(|&v| (search.curve)(v))
            && branch.is_far_off(dt, nested, search.steps)
        {
            outliers.extend(members);
        } else {
            kept.push(members);
        }
    }
    (outliers, kept)
}

/// The vertices at one end of a chain (a component whose tree is the path `path`) that
/// keep a closed curve from closing: an end run that breaks `u < 2` ([`end_run`]), lies far
/// from the rest by the branch rule, and without which the chain's ends close with
/// `u < 2` at both, where with it they do not. (Outliers the spanning tree strung onto the
/// end of a closed curve's path; an open curve's end stays.)
pub(crate) fn chain_end_outliers(dt: &Triangulation, path: &[u32], steps: &Steps) -> Vec<u32> {
    let mut path = path.to_vec();
    for _ in 0..2 {
        let k = end_run(dt, &path);
        if k > 0 && k + 3 <= path.len() && !closes(dt, &path) && closes(dt, &path[k..]) {
            let members = &path[..k];
            let inner = members
                .windows(2)
                .map(|e| distance(dt.point(e[0]), dt.point(e[1])))
                .fold(0.0, f64::max);
            let branch = Branch { members, inner, path: &path[k..], at: 0 };
            if branch.is_far_off(dt, None, steps) {
                let mut outliers = members.to_vec();
                outliers.sort_unstable();
                return outliers;
            }
        }
        path.reverse();
    }
    Vec::new()
}

/// Whether the edge between the two ends of `path` keeps `u < 2` with the path's edge at
/// each end.
fn closes(dt: &Triangulation, path: &[u32]) -> bool {
    let n = path.len();
    let length = |a: u32, b: u32| distance(dt.point(a), dt.point(b));
    let gap = length(path[0], path[n - 1]);
    n >= 3
        && u_below_2(gap, length(path[0], path[1]))
        && u_below_2(gap, length(path[n - 1], path[n - 2]))
}

/// How many vertices at the start of `path` come before its first vertex that keeps
/// `u < 2` toward the start: the run `p0 … p(k-1)` such that at each of `p1 … pk` the edge
/// toward the start is more than twice the edge away from it. A sampled curve's end has
/// no such run (k = 0); outliers the spanning tree strung onto the end of a curve do.
fn end_run<'a>(dt: &Triangulation, path: impl IntoIterator<Item = &'a u32>) -> usize {
    let mut path = path.into_iter().map(|&v| dt.point(v));
    let (Some(mut previous), Some(mut current)) = (path.next(), path.next()) else {
        return 0;
    };
    let mut k = 0;
    for next in path {
        let (toward, away) = (distance(previous, current), distance(current, next));
        if toward <= 2.0 * away * (1.0 + TIE_SLACK) {
            break;
        }
        k += 1;
        (previous, current) = (current, next);
    }
    k
}

/// A branch off a tree's main path: its `members`, the longest tree edge among them
/// (`inner`), and the vertex of `path` it hangs from (`at`).
struct Branch<'a> {
    members: &'a [u32],
    inner: f64,
    path: &'a [u32],
    at: usize,
}

impl Branch<'_> {
    /// Rule 1 of the module docs: every member farther than the spacing at the attachment
    /// vertex from the path edges there and their continuations, not a curve of its own,
    /// and, when `nested` (given scratch space for its members), farther than twice the
    /// spacing from every other point.
    fn is_far_off(
        &self,
        dt: &Triangulation,
        nested: Option<&mut VertexSet>,
        steps: &Steps,
    ) -> bool {
        let (path, i) = (self.path, self.at);
        let a = path[i];
        let sides: Vec<u32> =
            [i.wrapping_sub(1), i + 1].into_iter().filter_map(|j| path.get(j).copied()).collect();
        let spacing = sides.iter().map(|&s| distance(dt.point(a), dt.point(s))).fold(0.0, f64::max);
        // Distance from a member to the path edges at `a` and their continuations.
        let off = |o: u32| {
            let (q, pa) = (dt.point(o), dt.point(a));
            let near = sides.iter().map(|&s| {
                let ps = dt.point(s);
                segment_distance(q, pa, ps).min(continuation_distance(steps, q, ps, pa))
            });
            near.fold(distance(q, pa), f64::min)
        };
        let nearest = self.members.iter().map(|&o| off(o)).fold(f64::INFINITY, f64::min);
        let far = |d: f64, ratio: f64| d > ratio * spacing * (1.0 + TIE_SLACK);
        spacing > 0.0
            && far(nearest, 1.0)
            && nested.map_or(true, |set| far(distance_to_others(dt, self.members, set), 2.0))
            && !(steps.own_curves && own_curve(self.members.len(), self.inner, nearest))
    }
}

/// The distance from the points `members` to the nearest other point. The closest pair
/// between two point sets is a Delaunay edge (its diametral disk is empty), so the
/// members' Delaunay edges suffice.
fn distance_to_others(dt: &Triangulation, members: &[u32], set: &mut VertexSet) -> f64 {
    set.clear();
    members.iter().for_each(|&v| _ = set.insert(v));
    let mut nearest = f64::INFINITY;
    for &o in members {
        for h in dt.outgoing(o) {
            if !set.contains(dt.dest(h)) {
                nearest = nearest.min(dt.length(h));
            }
        }
    }
    nearest
}

/// The distance from `q` to the ray from `through` away from `from` (the straight
/// continuation of the curve `from → through`), or infinity without tangent rays.
fn continuation_distance(steps: &Steps, q: Point, from: Point, through: Point) -> f64 {
    match steps.tangent_rays {
        true => ray_distance(q, from, through),
        false => f64::INFINITY,
    }
}

/// Whether `count` points that lie at least `off` from the curve, joined among themselves by
/// edges at most `inner` long, are a curve of their own rather than outliers: at least three
/// points (a curve needs three samples to have a direction), closer to one another than to
/// the curve. (Outliers lie apart from each other as well as from the curve.)
fn own_curve(count: usize, inner: f64, off: f64) -> bool {
    count >= OWN_CURVE_POINTS && inner < off
}

/// The fewest points that make a curve of their own: three, the fewest with a direction.
const OWN_CURVE_POINTS: usize = 3;

/// The longest path of the tree, by length: from the vertex farthest from `vertices[0]` to
/// the vertex farthest from it (`neighbours` its adjacency; `parent` scratch space).
fn main_path<W, I>(
    dt: &Triangulation,
    vertices: &[u32],
    neighbours: &W,
    parent: &mut VertexMap,
) -> Vec<u32>
where
    W: Fn(u32) -> I,
    I: Iterator<Item = u32>,
{
    let mut farthest = |from: u32| {
        let mut best = (0.0, from);
        parent.clear();
        parent.set(from, NONE);
        let mut stack = vec![(from, 0.0)];
        while let Some((v, d)) = stack.pop() {
            if d > best.0 {
                best = (d, v);
            }
            for w in neighbours(v) {
                if parent.insert_new(w, v) {
                    stack.push((w, d + distance(dt.point(v), dt.point(w))));
                }
            }
        }
        best.1
    };
    let x = farthest(vertices[0]);
    let y = farthest(x);
    let mut path = vec![y];
    while let Some(p) = path.last().and_then(|&v| parent.get(v)) {
        if p == NONE {
            break;
        }
        path.push(p);
    }
    path
}

/// Cuts every detour of the reading (rule 2 of the module docs), farthest first, and
/// returns the vertices cut out. A run through a vertex that `curve` says is on a curve
/// for sure (a network's) is no detour.
pub(crate) fn detour_outliers(
    reading: &mut Reading<'_>,
    curve: impl Fn(u32) -> bool,
    steps: &Steps,
) -> Vec<u32> {
    let dt = reading.dt;
    let mut outliers = Vec::new();
    loop {
        // Every detour of the current reading, farthest first; a cut can spoil a later one
        // (they share a vertex), so each is checked again before it is made.
        let mut found: Vec<(f64, u32, u32, u32)> = Vec::new();
        for a in (0..dt.num_vertices() as u32).filter(|&a| reading.degree(a) == 2) {
            // The first run vertex lies farther from `a` than the spacing, so it is the end of
            // the longer reading edge at `a`, and `b` is nearer to `a` than it.
            let [x, y] = reading.neighbours(a);
            let squared = |v: u32| squared_distance(reading.point(a), reading.point(v));
            let (first, reach) = match squared(x).total_cmp(&squared(y)) {
                std::cmp::Ordering::Greater => (x, squared(x)),
                std::cmp::Ordering::Less => (y, squared(y)),
                std::cmp::Ordering::Equal => continue,
            };
            // ... and farther than the edge beyond `a` from the reading's continuation
            // beyond `a` (on a smooth curve it lies near it: most vertices stop here).
            let beyond = reading.other(a, first);
            let (pa, pb) = (reading.point(a), reading.point(beyond));
            if continuation_distance(steps, reading.point(first), pb, pa) <= distance(pa, pb) {
                continue;
            }
            for h in dt.incident(a) {
                let b = dt.other(h, a);
                if squared(b) >= reach || reading.degree(b) != 2 || reading.joined(a, b) {
                    continue;
                }
                match detour(reading, steps, a, first, b) {
                    Some((margin, run)) if !run.iter().any(|&v| curve(v)) => {
                        found.push((margin, a, first, b))
                    }
                    _ => {}
                }
            }
        }
        if found.is_empty() {
            break;
        }
        found.sort_by(|x, y| y.0.total_cmp(&x.0).then((x.1, x.2, x.3).cmp(&(y.1, y.2, y.3))));
        let before = outliers.len();
        for (_, a, first, b) in found {
            let still = reading.joined(a, first) && reading.degree(b) == 2;
            let Some((_, run)) = still.then(|| detour(reading, steps, a, first, b)).flatten()
            else {
                continue;
            };
            if run.iter().any(|&v| curve(v)) {
                continue;
            }

            let last = run[run.len() - 1];
            reading.relink(a, first, b);
            reading.relink(b, last, a);
            for &o in &run {
                reading.detach(o);
            }
            outliers.extend(run);
        }
        if outliers.len() == before {
            break; // every detour left was spoilt by an earlier cut into a curve's
        }
    }
    outliers.sort_unstable();
    outliers
}

/// The run from `a` through `first` to `b`, and by how much its nearest vertex exceeds the
/// spacing (a ratio above 1), if it is a detour.
fn detour(
    reading: &Reading<'_>,
    steps: &Steps,
    a: u32,
    first: u32,
    b: u32,
) -> Option<(f64, Vec<u32>)> {
    let ray = |q, from, through| continuation_distance(steps, q, from, through);
    let a_beyond = reading.other(a, first);
    if a_beyond == NONE || a_beyond == b {
        return None;
    }
    let (pa, pb, pa_beyond) = (reading.point(a), reading.point(b), reading.point(a_beyond));
    let ab = reading.length(a, b);
    let regular = |v: u32| match reading.neighbours(v) {
        [x, y] if x != NONE && y != NONE => u_below_2(reading.length(v, x), reading.length(v, y)),
        _ => true,
    };
    // Whether `ab` continues the reading beyond `end` into `beyond` (checked before the walk
    // for `a`, and for both candidates beyond `b`, so that most pairs need no walk).
    let continues_into = |end: u32, beyond: u32| {
        beyond != NONE && u_below_2(ab, reading.length(end, beyond)) && regular(beyond)
    };
    if !continues_into(a, a_beyond) || !reading.neighbours(b).iter().any(|&x| continues_into(b, x))
    {
        return None;
    }
    // Distance from a run vertex to the shortcut and to the continuation beyond `a`; a vertex
    // within the spacing ends the walk, as it could never be cut out.
    let near_a = |v: u32| {
        let q = reading.point(v);
        segment_distance(q, pa, pb).min(ray(q, pa_beyond, pa))
    };
    let mut run = Vec::new();
    let (mut previous, mut v) = (a, first);
    // Links shorter than `ab` in a row: shorter than the run's distance to the curve too
    // (a detour's exceeds `ab`), so OWN_CURVE_POINTS of them make the run a curve of its
    // own and end the walk, which keeps it short on a scatter, where the reading is long
    // and no run is a detour.
    let mut short_stretch = 1;
    // The other way round from `a`, in step: on a loop it reaches `b` after the vertices
    // outside the run, which must outnumber the run ([`outnumbered`]), so the run's walk
    // ends there too.
    let (mut rest_previous, mut rest_v, mut rest) = (a, a_beyond, 1);
    let mut rest_bound = usize::MAX;
    while v != b {
        if v == NONE || v == a || near_a(v) <= ab || run.len() + 1 >= rest_bound {
            return None;
        }
        if rest_bound == usize::MAX && rest_v != NONE {
            rest += 1;
            if rest_v == b {
                rest_bound = rest;
            }
            (rest_previous, rest_v) = (rest_v, reading.other(rest_v, rest_previous));
        }
        if let Some(&last) = run.last() {
            short_stretch = if reading.length(last, v) < ab { short_stretch + 1 } else { 1 };
            if steps.own_curves && short_stretch >= OWN_CURVE_POINTS {
                return None;
            }
        }
        run.push(v);
        let next = reading.other(v, previous);
        (previous, v) = (v, next);
    }
    let b_beyond = reading.other(b, previous);
    if run.is_empty() || b_beyond == NONE || b_beyond == a {
        return None;
    }
    let continues = continues_into(b, b_beyond);
    let pb_beyond = reading.point(b_beyond);
    let nearest = run
        .iter()
        .map(|&o| near_a(o).min(ray(reading.point(o), pb_beyond, pb)))
        .fold(f64::INFINITY, f64::min);
    // The longest stretch of the run whose links are all shorter than its distance to the
    // curve: three such points are a curve of their own, even when the run also reaches
    // an outlier (a stroke read with an outlier at its tip).
    let mut stretch = 1;
    let mut longest_stretch = 1;
    for w in run.windows(2) {
        stretch = if reading.length(w[0], w[1]) < nearest { stretch + 1 } else { 1 };
        longest_stretch = longest_stretch.max(stretch);
    }
    // Along the reading, a run with u < 2 at every inner vertex is sampled like a curve.
    let regular = run.len() >= 3
        && run
            .windows(3)
            .all(|w| u_below_2(reading.length(w[0], w[1]), reading.length(w[1], w[2])));
    (continues
        && nearest > ab * (1.0 + TIE_SLACK)
        && outnumbered(reading, [a, first], [b, run[run.len() - 1]], run.len())
        && !(steps.own_curves && longest_stretch >= OWN_CURVE_POINTS)
        && !regular)
        .then(|| (nearest / ab, run))
}

/// Whether the reading's loop or path through the run that leaves `a` by `a_run` and
/// reaches `b` from `b_run` has more than `run` vertices outside the run. A detour is an
/// excursion from a curve, so the curve it leaves must be the larger part: otherwise the
/// run is the curve, and `ab` would cut it short (a noisy loop read as a shortcut between
/// two of its own samples). The walk stops after `run + 1` vertices, so it costs no more
/// than the run's own walk.
fn outnumbered(
    reading: &Reading<'_>,
    [a, a_run]: [u32; 2],
    [b, b_run]: [u32; 2],
    run: usize,
) -> bool {
    let mut count = 0;
    for (start, from) in [(b, b_run), (a, a_run)] {
        let (mut previous, mut v) = (from, start);
        while v != NONE && count <= run {
            count += 1;
            if v == a && start == b {
                // Around a loop: the walk from `b` came back to `a`.
                return count > run;
            }
            (previous, v) = (v, reading.other(v, previous));
        }
    }
    count > run
}

/// The non-uniformity condition of \[MOW22\] Theorem 1 for two edges at one sample: the longer
/// is less than twice the shorter (ties allowed, as everywhere in SIG-AUTO).
pub(crate) fn u_below_2(l1: f64, l2: f64) -> bool {
    l1.max(l2) <= 2.0 * l1.min(l2) * (1.0 + TIE_SLACK)
}
