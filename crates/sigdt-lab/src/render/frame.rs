//! The page: where the drawing, the title and the legend go, and how large lines and dots
//! are.
//!
//! Picture coordinates are integers in hundredths of a pixel ([`Px`]), so paths can be
//! written with relative moves that never drift and every number is short.

use sigdt::internals::KdTree;
use sigdt::Point;

/// A picture coordinate in hundredths of a pixel.
pub(crate) type Px = [i64; 2];

/// Blank space around the drawing, in pixels.
pub(crate) const MARGIN: f64 = 20.0;
/// The drawing is at most this many times as tall as it is wide.
const MAX_ASPECT: f64 = 1.25;
/// How many points the median nearest-neighbour distance is measured on.
const SPACING_SAMPLE: usize = 4096;
/// Below this median nearest-neighbour distance (in pixels) the points are not drawn when
/// any other layer is (dots would merge into a thick band that hides the curve).
pub(crate) const DENSE_SPACING_PX: f64 = 3.0;

/// Maps input coordinates to the picture and holds the sizes that follow the spacing.
pub(crate) struct Frame {
    /// Picture width and height in pixels.
    pub width: f64,
    pub height: f64,
    /// Height of the drawing alone, in pixels.
    drawing: f64,
    /// Pixels per scaled unit (an input unit times `unit`).
    scale: f64,
    /// The exact power-of-two factor applied to input coordinates before subtracting `lo`
    /// (1, or 1/4 when the extent would overflow).
    unit: f64,
    /// Scaled input coordinates of the drawing's lower-left corner.
    lo: Point,
    /// Picture position of `lo`, in pixels (y pointing down).
    at: [f64; 2],
    /// Median nearest-neighbour distance, in pixels.
    pub spacing: f64,
}

impl Frame {
    /// A frame `width` pixels wide for the finite points and `pad` input units around them
    /// (for circles); the scale depends only on these, not on the bands set by
    /// [`bands`](Self::bands).
    pub fn new(points: &[Point], width: f64, pad: f64) -> Frame {
        let finite: Vec<Point> = points.iter().copied().filter(|p| is_finite(*p)).collect();
        let (mut lo, mut hi) = ([0.0; 2], [0.0; 2]);
        if let Some(&first) = finite.first() {
            (lo, hi) = (first, first);
            for p in &finite {
                lo = [lo[0].min(p[0]), lo[1].min(p[1])];
                hi = [hi[0].max(p[0]), hi[1].max(p[1])];
            }
        }
        // Extents beyond f64::MAX (points near ±f64::MAX) are measured in quarter units,
        // an exact scaling, so the picture keeps its shape instead of collapsing to height 0.
        let fits = |lo: Point, hi: Point| (hi[0] - lo[0]).max(hi[1] - lo[1]) < f64::MAX / 4.0;
        let unit = if fits(lo, hi) { 1.0 } else { 0.25 };
        (lo, hi) = (lo.map(|v| v * unit), hi.map(|v| v * unit));
        let pad = pad * unit;
        // At most half the box's longer side, so that one far outlier's circle does not
        // shrink the drawing.
        let side = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let pad = if pad > 0.0 { pad.min(if side > 0.0 { 0.5 * side } else { pad }) } else { 0.0 };
        let pad = if pad.is_finite() { pad } else { 0.0 };
        (lo, hi) = ([lo[0] - pad, lo[1] - pad], [hi[0] + pad, hi[1] + pad]);
        let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
        let inner = (width - 2.0 * MARGIN).max(1.0);
        let fit = |extent: f64, room: f64| if extent > 0.0 { room / extent } else { f64::INFINITY };
        let mut scale = fit(w, inner).min(fit(h, MAX_ASPECT * inner));
        if !(scale.is_finite() && scale > 0.0) {
            scale = 1.0;
        }
        let drawing = h * scale;
        let at = [(width - w * scale) / 2.0, MARGIN + drawing];
        let spacing = median_nearest_distance(&finite) * unit * scale;
        let height = (2.0 * MARGIN + drawing).ceil();
        Frame { width, height, drawing, scale, unit, lo, at, spacing }
    }

    /// Makes room for `top` pixels above the drawing (title) and `bottom` below it
    /// (legend); returns where the bottom band starts.
    pub fn bands(&mut self, top: f64, bottom: f64) -> f64 {
        self.at[1] = top + MARGIN + self.drawing;
        self.height = (top + 2.0 * MARGIN + self.drawing + bottom).ceil();
        top + 2.0 * MARGIN + self.drawing - MARGIN / 2.0
    }

    /// `p` in picture coordinates (hundredths of a pixel, y pointing down), or `None` when
    /// it is not finite.
    pub fn map(&self, p: Point) -> Option<Px> {
        let x = self.at[0] + (p[0] * self.unit - self.lo[0]) * self.scale;
        let y = self.at[1] - (p[1] * self.unit - self.lo[1]) * self.scale;
        let (x, y) = ((100.0 * x).round(), (100.0 * y).round());
        // Far outside the page only when the input is not finite or the frame is degenerate.
        (x.abs() < 1e15 && y.abs() < 1e15).then_some([x as i64, y as i64])
    }

    /// A length in input units, in hundredths of a pixel.
    pub fn length(&self, d: f64) -> i64 {
        let v = (100.0 * d * self.unit * self.scale).round();
        if v.is_finite() && v.abs() < 1e15 {
            v as i64
        } else {
            0
        }
    }

    /// Whether the points are too dense to draw as dots next to other layers.
    pub fn dense(&self) -> bool {
        self.spacing < DENSE_SPACING_PX
    }

    /// Width of the main lines (result, graphs), in pixels: a tenth of the spacing, kept
    /// between 0.8 and 2.2 pixels so sparse glyphs are not drawn with bars and dense
    /// contours stay visible.
    pub fn line(&self) -> f64 {
        clamp(0.1 * self.spacing, 0.8, 2.2)
    }

    /// Radius of a point's dot, in pixels: a fifth of the spacing, between 1 and 3.5.
    pub fn dot(&self) -> f64 {
        clamp(0.2 * self.spacing, 1.0, 3.5)
    }
}

/// Where [`render_svg`](super::render_svg) puts `points` on a page `width` pixels wide,
/// without title or legend: the page's height and each point's position in pixels (y
/// pointing down, rounded to 0.01 px), `None` for a point that is not finite. For pictures
/// drawn elsewhere (Python's `Reconstruction.to_svg`), so that they frame input of any
/// range, from subnormal to ±`f64::MAX`, as `sigdt render` does.
pub fn place(points: &[Point], width: f64) -> (f64, Vec<Option<[f64; 2]>>) {
    let frame = Frame::new(points, width, 0.0);
    let at = |p| frame.map(p).map(|[x, y]| [x as f64 / 100.0, y as f64 / 100.0]);
    (frame.height, points.iter().map(|&p| at(p)).collect())
}

/// `v` limited to `lo..=hi`; `lo` for NaN.
fn clamp(v: f64, lo: f64, hi: f64) -> f64 {
    if v >= lo {
        v.min(hi)
    } else {
        lo
    }
}

pub(crate) fn is_finite(p: Point) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// The median distance from a point to its nearest distinct neighbour, measured on up to
/// [`SPACING_SAMPLE`] evenly spread points; 0 with fewer than two distinct points.
fn median_nearest_distance(points: &[Point]) -> f64 {
    if points.len() < 2 {
        return 0.0;
    }
    let tree = KdTree::new(points);
    let step = points.len().div_ceil(SPACING_SAMPLE);
    let mut distances: Vec<f64> = (0..points.len())
        .step_by(step)
        .filter_map(|i| {
            // A few neighbours, so that exact duplicates do not count as the nearest.
            let near = tree.nearest(points[i], 4, i as u32);
            near.iter().map(|&(d, _)| d).find(|&d| d > 0.0).map(f64::sqrt)
        })
        .collect();
    if distances.is_empty() {
        return 0.0;
    }
    let mid = distances.len() / 2;
    *distances.select_nth_unstable_by(mid, f64::total_cmp).1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_fits_the_width_and_flips_y() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mut f = Frame::new(&square, 240.0, 0.0);
        assert_eq!(f.height, 240.0);
        assert_eq!(f.bands(10.0, 20.0), 10.0 + 240.0 - 10.0);
        assert_eq!(f.height, 10.0 + 40.0 + 200.0 + 20.0);
        assert_eq!(f.map([0.0, 0.0]), Some([2000, 23000]));
        assert_eq!(f.map([1.0, 1.0]), Some([22000, 3000]));
        // The padding is at most half the box's side.
        let padded = Frame::new(&square, 240.0, 1.0);
        assert_eq!(padded.map([-0.5, -0.5]), Some([2000, 22000]));
        assert_eq!(f.spacing, 200.0);
        assert_eq!((f.line(), f.dot()), (2.2, 3.5));
        assert_eq!(f.map([f64::NAN, 0.0]), None);
    }

    #[test]
    fn degenerate_boxes_are_finite() {
        for points in [vec![], vec![[5.0, 5.0]], vec![[0.0, 3.0], [2.0, 3.0]]] {
            let f = Frame::new(&points, 800.0, f64::NAN);
            assert!(f.height.is_finite() && f.height >= 2.0 * MARGIN, "{points:?}");
            assert!(f.map([5.0, 5.0]).is_some() && f.line() > 0.0);
        }
        let tall = Frame::new(&[[0.0, 0.0], [0.0, 100.0], [1.0, 50.0]], 240.0, 0.0);
        assert_eq!(tall.height, 40.0 + 250.0);
        assert_eq!(clamp(f64::NAN, 1.0, 2.0), 1.0);
    }

    #[test]
    fn place_is_the_frame_in_pixels() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [f64::NAN, 0.0]];
        let (height, at) = place(&square, 240.0);
        assert_eq!(height, 240.0);
        let corners = [[20.0, 220.0], [220.0, 220.0], [220.0, 20.0], [20.0, 20.0]];
        assert_eq!(at, corners.map(Some).into_iter().chain([None]).collect::<Vec<_>>());
    }

    #[test]
    fn extents_beyond_f64_max_keep_their_shape() {
        // The same triangle at a normal scale and stretched to ±f64::MAX: the same picture.
        let small = [[-1.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let huge = small.map(|p| p.map(|v| v * f64::MAX));
        let (a, b) = (Frame::new(&small, 800.0, 0.0), Frame::new(&huge, 800.0, 0.0));
        assert_eq!(a.height, b.height);
        assert!(b.height > 2.0 * MARGIN + 100.0);
        for (p, q) in small.iter().zip(&huge) {
            assert_eq!(a.map(*p), b.map(*q));
        }
    }
}
