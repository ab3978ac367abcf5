//! Enclosed exterior pockets (`docs/algorithms.md` §2.5; our decision, since the paper does
//! not discuss them).
//!
//! When inflating takes a triangle `abc` that had only `ab` on the boundary while `c` was
//! already connected to `a` along the boundary, the new edges `ac` and `bc` close a cycle:
//! the exterior region beyond them splits in two and one part is now a bounded face of the
//! boundary. Algorithm 1 re-evaluates `boundary(G)` after every addition, so such a pocket is
//! no longer exterior: its triangles become interior and boundary edges with interior on
//! both sides are dropped.
//!
//! Finding it: two breadth-first searches over exterior triangles, one from each side,
//! crossing only non-boundary edges, advance in lockstep. A search that reaches the convex
//! hull is outside; one that runs out of triangles first is the pocket; if they meet there is
//! no pocket (possible because union-find only over-approximates boundary connectivity).
//!
//! # Complexity
//! Lockstep search costs O(size of the smaller side) plus O(pocket); a triangle is filled at
//! most once, so O(n) over a whole run.
use super::boundary::Boundary;
use super::trace::Phase;
use crate::delaunay::EMPTY;

struct Search {
    queue: Vec<u32>,
    head: usize,
    stamp: u32,
}

enum Step {
    Continue,
    Exhausted,
    Outside,
    Met,
}

/// Fills the pocket, if any, among the exterior regions containing triangles `s1` and `s2`
/// (either may be [`EMPTY`], the outside of the hull). Returns the filled triangles.
pub fn fill_pocket(bd: &mut Boundary<'_>, s1: u32, s2: u32) -> Vec<u32> {
    if s1 == EMPTY && s2 == EMPTY {
        return Vec::new();
    }
    bd.epoch += 1;
    let base = 2 * bd.epoch;
    let mut searches: Vec<Search> = Vec::with_capacity(2);
    for (k, &s) in [s1, s2].iter().enumerate() {
        if s != EMPTY {
            bd.stamp[s as usize] = base + k as u32;
            searches.push(Search { queue: vec![s], head: 0, stamp: base + k as u32 });
        }
    }
    // With one side outside the hull from the start, only the other can be a pocket.
    let mut single = searches.len() == 1;
    loop {
        for k in 0..searches.len() {
            match step(bd, &mut searches[k], base) {
                Step::Continue => {}
                Step::Met => return Vec::new(),
                Step::Exhausted => return fill(bd, std::mem::take(&mut searches[k].queue)),
                Step::Outside if single => return Vec::new(),
                Step::Outside => {
                    searches.remove(k);
                    single = true;
                    break;
                }
            }
        }
    }
}

/// Expands one triangle of a search.
fn step(bd: &mut Boundary<'_>, s: &mut Search, base: u32) -> Step {
    let Some(&t) = s.queue.get(s.head) else { return Step::Exhausted };
    s.head += 1;
    for h in 3 * t..3 * t + 3 {
        if bd.edges.contains(h) {
            continue;
        }
        let twin = bd.dt.twin(h);
        if twin == EMPTY {
            return Step::Outside;
        }
        let u = twin / 3;
        let mark = bd.stamp[u as usize];
        if mark == s.stamp {
            continue;
        }
        if mark >= base {
            return Step::Met;
        }
        debug_assert!(!bd.inside[u as usize], "non-boundary edge between interior and exterior");
        bd.stamp[u as usize] = s.stamp;
        s.queue.push(u);
    }
    if s.head == s.queue.len() {
        Step::Exhausted
    } else {
        Step::Continue
    }
}

/// Makes the pocket interior and drops boundary edges now interior on both sides.
fn fill(bd: &mut Boundary<'_>, pocket: Vec<u32>) -> Vec<u32> {
    for &t in &pocket {
        bd.set_inside(t, true, Phase::Pocket);
    }
    for &t in &pocket {
        for h in 3 * t..3 * t + 3 {
            if bd.edges.contains(h) && bd.right_is_in(h) {
                bd.set_edge(h, false);
            }
        }
    }
    pocket
}
