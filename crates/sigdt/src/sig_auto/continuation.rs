//! Good continuation: 2-opt moves on the reading that lower its total turning.
//!
//! A move takes two reading edges `ab` and `cd` whose ends are joined by the Delaunay edges
//! `ac` and `bd`, and replaces them by `ac` and `bd`. Every vertex keeps its number of
//! edges, so loops and paths stay loops and paths; a loop may split into two (two curves that
//! the graph had merged, such as islands closer together than their sample spacing), two
//! loops may merge, or a stretch may be reversed (a zigzag across a corner). Every new edge
//! is a Delaunay edge, so no two edges cross.
//!
//! A move is made only when it lowers the sum of the turning angles at `a`, `b`, `c` and `d`
//! (the only vertices whose angle changes), and when both new edges satisfy the
//! non-uniformity condition `u < 2` of [MOW22] Theorem 1 against the other edge at each of
//! their ends: a sampled curve turns little from sample to sample (at most 60° at every
//! sample of an ε < 1 sampling) and changes its spacing by less than a factor of two, so
//! among readings that respect the spacing, the one that turns least follows the curve.
//! Moves are taken largest gain first; each lowers the total turning, so the process ends.
//! Only moves at a vertex that turns more than a sampled curve can (60°, from ε < 1) are
//! considered: a reading that is locally consistent with a sampled curve is left alone. A
//! move that makes a vertex turn that sharply where it did not is made only when it gains
//! more than one such turn: otherwise it trades one turn a sampled curve cannot make for
//! another, which is how a curve comes apart across a neck about a spacing wide.
//!
//! # Complexity
//! O(n · d³) to collect the first moves (`d` the Delaunay degree), then O(d³ log n) per move.
//!
//! [MOW22]: https://doi.org/10.1111/cgf.14654
use super::outliers::u_below_2;
use super::reading::{Reading, NONE};
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// The smallest gain in radians that counts: below it, two readings turn the same.
const MIN_GAIN: f64 = 1e-9;

/// The most a curve sampled with ε < 1 turns at a sample (60°: each of its two edges makes
/// an angle of at most arcsin(ε/2) < 30° with the tangent).
pub(crate) const MAX_SAMPLED_TURN: f64 = std::f64::consts::FRAC_PI_3;

/// Makes every improving move (see the module docs).
pub(crate) fn continue_smoothly(reading: &mut Reading<'_>) {
    let n = reading.dt.num_vertices();
    let mut queue = BinaryHeap::new();
    // A move changes the turning only at its four vertices, one of which must turn sharply
    // (`push_moves`). Seen from the edge `ab` it starts from, the sharp one is `a`, `b` (a
    // reading neighbour of `a`), `c` (a Delaunay neighbour of `a`) or `d` (a reading
    // neighbour of such a `c`): so the first moves start at those `a`.
    let cos_limit = MAX_SAMPLED_TURN.cos();
    let dt = reading.dt;
    let mut near_sharp = vec![false; n];
    for v in (0..n as u32).filter(|&v| reading.turns_more_than(v, cos_limit)) {
        let mut mark = |x: u32| {
            near_sharp[x as usize] = true;
            dt.incident(x).for_each(|h| near_sharp[dt.other(h, x) as usize] = true);
        };
        mark(v);
        reading.neighbours(v).into_iter().filter(|&w| w != NONE).for_each(&mut mark);
    }
    for a in (0..n as u32).filter(|&a| near_sharp[a as usize]) {
        for b in reading.neighbours(a).into_iter().filter(|&b| b != NONE) {
            push_moves(reading, a, b, &mut queue);
        }
    }
    while let Some(Move { gain, a, b, c, d }) = queue.pop() {
        let valid = reading.joined(a, b)
            && reading.joined(c, d)
            && !reading.joined(a, c)
            && !reading.joined(b, d)
            && respects_spacing(reading, a, b, c, d);
        if !valid {
            continue;
        }
        let now = gain_of(reading, a, b, c, d);
        if trades_sharp_turns(reading, [a, b, c, d], now) || now <= MIN_GAIN {
            continue;
        }
        if now != gain {
            queue.push(Move { gain: now, a, b, c, d });
            continue;
        }
        reading.relink(a, b, c);
        reading.relink(b, a, d);
        reading.relink(c, d, a);
        reading.relink(d, c, b);
        // The turning changed at a, b, c, d: every move involving an edge at one of them.
        for x in [a, b, c, d] {
            for y in reading.neighbours(x).into_iter().filter(|&y| y != NONE) {
                push_moves(reading, x, y, &mut queue);
                push_moves(reading, y, x, &mut queue);
            }
        }
    }
}

/// A candidate move: replace `ab`, `cd` by `ac`, `bd`; ordered by gain, then by vertices.
#[derive(Debug, PartialEq)]
struct Move {
    gain: f64,
    a: u32,
    b: u32,
    c: u32,
    d: u32,
}

impl Eq for Move {}

impl PartialOrd for Move {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Move {
    fn cmp(&self, other: &Self) -> Ordering {
        let key = |m: &Move| [m.a, m.b, m.c, m.d];
        self.gain.total_cmp(&other.gain).then_with(|| key(other).cmp(&key(self)))
    }
}

/// Pushes every improving move that removes the reading edge `ab`.
fn push_moves(reading: &Reading<'_>, a: u32, b: u32, queue: &mut BinaryHeap<Move>) {
    let dt = reading.dt;
    let cos_limit = MAX_SAMPLED_TURN.cos();
    let sharp = |v: u32| reading.turns_more_than(v, cos_limit);
    // Asked once per vertex rather than once per candidate: on a scatter nearly every
    // vertex turns sharply and every one has candidates.
    let sharp_ab = sharp(a) || sharp(b);
    for h in dt.incident(a) {
        let c = dt.other(h, a);
        if c == b || reading.joined(a, c) {
            continue;
        }
        let sharp_abc = sharp_ab || sharp(c);
        for d in reading.neighbours(c) {
            if d == NONE || d == a || d == b || reading.joined(b, d) {
                continue;
            }
            // A reading that turns no more than a sampled curve can at all four vertices
            // is left as it is.
            if !(sharp_abc || sharp(d)) {
                continue;
            }
            if !respects_spacing(reading, a, b, c, d) || !dt.has_edge(b, d) {
                continue;
            }
            let gain = gain_of(reading, a, b, c, d);
            if gain > MIN_GAIN && !trades_sharp_turns(reading, [a, b, c, d], gain) {
                queue.push(Move { gain, a, b, c, d });
            }
        }
    }
}

/// How much the move lowers the turning at its four vertices.
fn gain_of(reading: &Reading<'_>, a: u32, b: u32, c: u32, d: u32) -> f64 {
    let after = |v: u32, old: u32, new: u32| {
        let [x, y] = reading.neighbours(v);
        reading.turning_with(v, if x == old { [new, y] } else { [x, new] })
    };
    let before: f64 = [a, b, c, d].iter().map(|&v| reading.turning(v)).sum();
    before - (after(a, b, c) + after(b, a, d) + after(c, d, a) + after(d, c, b))
}

/// Whether both new edges satisfy `u < 2` against the other edge at each of their ends.
fn respects_spacing(reading: &Reading<'_>, a: u32, b: u32, c: u32, d: u32) -> bool {
    let fits = |v: u32, old: u32, new: u32| match reading.other(v, old) {
        NONE => true,
        other => u_below_2(reading.length(v, new), reading.length(v, other)),
    };
    fits(a, b, c) && fits(c, d, a) && fits(b, a, d) && fits(d, c, b)
}

/// Whether the move, which gains `gain`, makes one of its four vertices turn more than a
/// sampled curve can where it did not before, and gains no more than one such turn. A move like that trades a turn a
/// sampled curve cannot make for another: cut across a neck about a spacing wide, a curve
/// comes apart into two loops that each keep a corner at the cut. Two curves the graph
/// merged turn sharply at all four ends of their two bridges and come apart smoothly, with a
/// far larger gain.
fn trades_sharp_turns(reading: &Reading<'_>, [a, b, c, d]: [u32; 4], gain: f64) -> bool {
    let cos_limit = MAX_SAMPLED_TURN.cos();
    let sharpened = |v: u32, old: u32, new: u32| {
        let [x, y] = reading.neighbours(v);
        let slots = if x == old { [new, y] } else { [x, new] };
        !reading.turns_more_than(v, cos_limit) && reading.turns_more_than_with(v, slots, cos_limit)
    };
    gain <= MAX_SAMPLED_TURN
        && (sharpened(a, b, c) || sharpened(b, a, d) || sharpened(c, d, a) || sharpened(d, c, b))
}
