//! Compact SVG path data: polylines, dots and circles as relative moves in hundredths of a
//! pixel, and the chaining of edge lists into polylines.
//!
//! One layer is one `<path>`, however many edges it has. Numbers are written the short way
//! SVG allows (`.5`, `-1.25`, no space before a minus sign).

use super::frame::Px;
use sigdt::internals::chains;
use sigdt::Edge;

/// Builds the `d` attribute of one `<path>`.
#[derive(Default)]
pub(crate) struct PathData {
    d: String,
    /// The current point, once there is one.
    at: Option<Px>,
}

impl PathData {
    /// The path data; empty when nothing was drawn.
    pub fn finish(self) -> String {
        self.d
    }

    /// A polyline through `ps`, closed with `z` when it ends where it starts. Zero-length
    /// steps are skipped.
    pub fn polyline(&mut self, ps: &[Px]) {
        let Some((&first, rest)) = ps.split_first() else { return };
        let closed = ps.len() > 2 && ps[ps.len() - 1] == first;
        let rest = if closed { &rest[..rest.len() - 1] } else { rest };
        self.move_to(first);
        let mut first_step = true;
        for &p in rest {
            let at = self.at.unwrap_or(p);
            if p == at {
                continue;
            }
            let step = [p[0] - at[0], p[1] - at[1]];
            if first_step {
                self.d.push('l');
                first_step = false;
            } else {
                self.separator(step[0]);
            }
            self.pair(step);
            self.at = Some(p);
        }
        if closed {
            self.d.push('z');
            self.at = Some(first);
        }
    }

    /// A dot at `p`: a zero-length segment, drawn with round caps as wide as the dot.
    pub fn dot(&mut self, p: Px) {
        self.move_to(p);
        self.d.push_str("h0");
    }

    /// A circle around `p` of radius `r` (hundredths of a pixel), as two arcs.
    pub fn circle(&mut self, p: Px, r: i64) {
        if r <= 0 {
            return self.dot(p);
        }
        self.move_to([p[0] - r, p[1]]);
        for dx in [2 * r, -2 * r] {
            self.d.push('a');
            self.number(r);
            self.separator(r);
            self.number(r);
            self.d.push_str(" 0 1 0");
            self.separator(dx);
            self.number(dx);
            self.d.push_str(" 0");
        }
    }

    fn move_to(&mut self, p: Px) {
        match self.at {
            None => {
                self.d.push('M');
                self.pair(p);
            }
            Some(at) => {
                self.d.push('m');
                self.pair([p[0] - at[0], p[1] - at[1]]);
            }
        }
        self.at = Some(p);
    }

    fn pair(&mut self, [x, y]: Px) {
        self.number(x);
        self.separator(y);
        self.number(y);
    }

    /// A space before `next`, unless it starts with a minus sign or the path is at a
    /// command letter.
    fn separator(&mut self, next: i64) {
        let after_letter = self.d.ends_with(|c: char| c.is_ascii_alphabetic());
        if next >= 0 && !after_letter {
            self.d.push(' ');
        }
    }

    fn number(&mut self, v: i64) {
        push_hundredths(&mut self.d, v);
    }
}

/// Appends `v / 100` in the shortest form: `150` → `1.5`, `-5` → `-.05`, `300` → `3`.
pub(crate) fn push_hundredths(out: &mut String, v: i64) {
    if v < 0 {
        out.push('-');
    }
    let (whole, frac) = (v.unsigned_abs() / 100, v.unsigned_abs() % 100);
    if whole > 0 || frac == 0 {
        out.push_str(&whole.to_string());
    }
    if frac > 0 {
        out.push('.');
        out.push(char::from(b'0' + (frac / 10) as u8));
        if frac % 10 > 0 {
            out.push(char::from(b'0' + (frac % 10) as u8));
        }
    }
}

/// `v` pixels as text with at most two decimals.
pub(crate) fn pixels(v: f64) -> String {
    let mut s = String::new();
    let v = (100.0 * v).round();
    push_hundredths(&mut s, if v.is_finite() && v.abs() < 1e15 { v as i64 } else { 0 });
    s
}

/// `edges` (valid indices below `n`, any order and direction) as polylines that use every
/// edge once: the chains of [`sigdt::internals::chains`], each cycle closed (its last point
/// is its first).
pub(crate) fn polylines(edges: &[Edge], n: usize) -> Vec<Vec<usize>> {
    let mut edges: Vec<Edge> =
        edges.iter().filter(|e| e[0] != e[1]).map(|&[i, j]| [i.min(j), i.max(j)]).collect();
    edges.sort_unstable();
    edges.dedup();
    chains(n, &edges, None)
        .into_iter()
        .map(|chain| {
            let mut vertices = chain.vertices;
            if chain.cycle {
                vertices.push(vertices[0]);
            }
            vertices
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        let text = |v| {
            let mut s = String::new();
            push_hundredths(&mut s, v);
            s
        };
        assert_eq!(
            [150, -5, 300, 0, 12345, -100, 7].map(text),
            ["1.5", "-.05", "3", "0", "123.45", "-1", ".07"]
        );
        assert_eq!(pixels(f64::NAN), "0");
    }

    #[test]
    fn polylines_dots_and_circles() {
        let mut d = PathData::default();
        d.polyline(&[[0, 0], [100, 0], [100, 0], [100, -250], [0, 0]]);
        d.polyline(&[[500, 500], [600, 500]]);
        d.dot([700, 400]);
        d.circle([0, 0], 50);
        assert_eq!(
            d.finish(),
            "M0 0l1 0 0-2.5zm5 5l1 0m1-1h0m-7.5-4a.5 .5 0 1 0 1 0a.5 .5 0 1 0-1 0"
        );
    }

    #[test]
    fn polylines_cover_every_edge_once() {
        // A square 0-1-2-3 with a tail 3-4-5 and a separate triangle 6-7-8.
        let edges = [[0, 1], [3, 0], [1, 2], [2, 3], [3, 4], [4, 5], [6, 7], [6, 8], [7, 8]];
        let got = polylines(&edges, 9);
        assert_eq!(got, vec![vec![3, 0, 1, 2, 3], vec![3, 4, 5], vec![6, 7, 8, 6]]);
        assert!(polylines(&[], 3).is_empty());
    }
}
