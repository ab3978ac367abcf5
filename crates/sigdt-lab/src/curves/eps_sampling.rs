//! ε-sampling of a cubic Bézier chain with a start offset: the sampler of the Bézier
//! experiment of \[MOW22\] (Fig. 14), following the behaviour of the benchmark authors'
//! `sampling2d` \[OMW21\] as specified in `docs/algorithms.md` §4.4 and §4.9.
//!
//! # Steps
//! 1. **Dense curve** ([`lfs`]): every segment is evaluated at [`DENSE_STEPS`] uniform
//!    parameters (an open chain also gets its end point).
//! 2. **Medial axis**: at each dense point `x` with unit normal `n`, take the largest disk
//!    tangent at `x` on each side that contains no other dense point, at most `diag / 2`
//!    across (`diag` = the dense points' bounding-box diagonal); the centre on the side with
//!    the smaller radius is `x`'s medial point. `sampling2d` finds the disk by shrinking it
//!    (while a point `y` is inside, take the disk through `y` tangent at `x`, of radius
//!    `|y − x|² / (2 (y − x)·n)`). We get the limit of shrinking directly: the centre is where
//!    the ray `x + t·n` leaves the Voronoi cell of `x`, so only the Delaunay neighbours of `x`
//!    can bound it. Same disk, O(N log N) in all, even on a circle where shrinking costs
//!    O(N) per point.
//! 3. **lfs**: `lfs(x)` = distance from `x` to the nearest medial point (of any dense point),
//!    for dense points and for any curve point met during the walk.
//! 4. **Walk** ([`eps_sample`]): the first sample is dense point `⌊offset·N⌋`. From the current
//!    sample `s`, step over dense points while `|x − s| < ε·lfs(x)` and bisect the parameter
//!    (to 1e-9) to the last point `p` where it holds. Freeze `L = lfs(p)`, step on while
//!    `|x − p| < ε·L`, bisect likewise: that point is the next sample. Stop when a walk
//!    reaches the first sample (closed) or the end point, which is then appended (open).
//!    An open chain is walked this way from the first sample to both end points.
//! 5. Ground truth: consecutive samples, plus the closing edge of a closed chain.
//!
//! So the spacing is about `2·ε·lfs`, every curve point between two samples is (up to the
//! curvature between them) within `ε·lfs` of one of them, and the spacing is maximal.
//!
//! # Complexity
//! `N = 1000·segments` dense points: O(N log N) for the medial axis (a Delaunay triangulation)
//! and the lfs (k-d tree queries over the medial points), and O(N log N) for the walk.
//!
//! # Limits
//! Only the chain itself is seen: other curves of the same drawing do not bound its lfs
//! (`sampling2d` uses all of them). The medial axis is a point cloud; `sampling2d`'s optional
//! refinement against the medial polyline is not done, so lfs is over-estimated by at most
//! about the medial points' spacing. At a sharp corner lfs tends to zero, so samples crowd
//! geometrically towards it down to the dense resolution. For a large `ε` a closed curve can
//! get fewer than 3 samples.
//!
//! \[MOW22\] D. Marin, S. Ohrhallinger, M. Wimmer. SIGDT: 2D Curve Reconstruction. 2022.
//! \[OMW21\] S. Ohrhallinger, J. Peethambaran, A. Parakkat, T. Dey, R. Muthuganapathy.
//! 2D Points Curve Reconstruction Survey and Benchmark. 2021.
use super::bezier::{fixed_size_power, MAX_SEGMENTS};
use super::BezierPath;
use crate::power_of_two::scale;
use sigdt::internals::{distance, KdTree};
use sigdt::samplers::{cycle_edges, Sample};
use sigdt::{Edge, Error, Point, Result, Triangulation};

/// Dense evaluation parameters per cubic segment.
pub const DENSE_STEPS: usize = 1000;

/// Parameter precision of the bisections, in segment units.
const PRECISION: f64 = 1e-9;

/// A Bézier chain evaluated densely, with normals, medial points and local feature size.
#[derive(Debug, Clone, PartialEq)]
pub struct DenseCurve {
    /// Dense point `k` is the chain's point at parameter `k / DENSE_STEPS`.
    pub points: Vec<Point>,
    /// Unit normals (the tangent turned a quarter counter-clockwise).
    pub normals: Vec<Point>,
    /// The medial point of each dense point (centre of its smaller empty tangent disk).
    pub medial: Vec<Point>,
    /// Local feature size at each dense point: distance to the nearest medial point.
    pub lfs: Vec<f64>,
}

/// An ε-sample with each sample's curve frame, for lfs noise.
#[derive(Debug, Clone, PartialEq)]
pub struct FramedSample {
    /// The points in curve order and the ground-truth edges.
    pub sample: Sample,
    /// Global curve parameter of each sample (segment index plus local parameter).
    pub params: Vec<f64>,
    /// Unit curve normal at each sample.
    pub normals: Vec<Point>,
    /// Local feature size at each sample.
    pub lfs: Vec<f64>,
}

/// The dense curve of `path` with its medial points and local feature size, as in
/// `sampling2d` \[OMW21\].
///
/// Every segment is evaluated at [`DENSE_STEPS`] parameters (an open path also at its end).
/// A dense point's medial point is the centre of the smaller of its two largest empty
/// tangent disks (one per side, no other dense point inside, radius at most half the
/// bounding-box diagonal), and its lfs is the distance to the nearest medial point. Only
/// `path` itself is seen, not other curves of the same drawing. Medial points form a point
/// cloud, so lfs is over-estimated by up to their spacing.
///
/// # Errors
/// [`Error::InvalidOption`] if the path has no segment, a non-finite control point, zero
/// length, or a point where no tangent direction exists.
pub fn lfs(path: &BezierPath) -> Result<DenseCurve> {
    lfs_at_density(path, DENSE_STEPS)
}

/// [`lfs`] with `density` evaluation parameters per segment instead of [`DENSE_STEPS`]
/// (dense point `k` is at parameter `k / density`).
///
/// # Errors
/// As [`lfs`].
pub fn lfs_at_density(path: &BezierPath, density: usize) -> Result<DenseCurve> {
    let density = density.max(1);
    let bad =
        |what: String| Error::InvalidOption(format!("cannot eps-sample the Bezier path: {what}"));
    if path.segments.is_empty() {
        return Err(bad("it has no segment".into()));
    }
    if path.segments.iter().flatten().flatten().any(|v| !v.is_finite()) {
        return Err(bad("a control point is not finite".into()));
    }
    if path.segments.len() > MAX_SEGMENTS {
        return Err(bad(format!(
            "{} segments is more than {MAX_SEGMENTS} (each is evaluated at {density} \
             parameters)",
            path.segments.len()
        )));
    }
    let n = density * path.segments.len() + usize::from(!path.closed);
    let points: Vec<Point> = (0..n).map(|k| path.point(k as f64 / density as f64)).collect();
    let diag = diagonal(&points);
    let scale = path.segments.iter().flatten().flatten().fold(0.0, |m: f64, v| m.max(v.abs()));
    if diag <= 1e-12 * scale || !diag.is_finite() {
        return Err(bad("it has zero length (or overflows)".into()));
    }
    let normals = (0..n)
        .map(|k| normal(path, k as f64 / density as f64))
        .collect::<Option<Vec<Point>>>()
        .ok_or_else(|| bad("it has a point without tangent direction".into()))?;
    let medial = medial_points(&points, &normals, 0.5 * diag)?;
    let medial_tree = KdTree::new(&medial);
    let lfs = points.iter().map(|&x| nearest(&medial_tree, x)).collect();
    Ok(DenseCurve { points, normals, medial, lfs })
}

/// The ε-sample of `path` whose first sample is dense point `⌊offset·N⌋`, `N` the number of
/// dense points (\[MOW22\] Fig. 14 uses `ε ∈ {0.1, …, 0.5}` and offsets `k / 20`).
///
/// From each sample `s` the walk goes forward over the dense points while
/// `|x − s| < ε·lfs(x)` and bisects the curve parameter (to 1e-9) to the last such point
/// `p`; it then goes on while `|x − p| < ε·lfs(p)` and bisects again: that is the next
/// sample. It stops on returning to the first sample of a closed path. An open path is
/// walked from the first sample to both ends, which become samples. So the spacing is about
/// `2·ε·lfs` and every curve point is within about `ε·lfs` of a sample. The edges join
/// consecutive samples (and close the cycle). lfs is that of [`lfs`]: at a sharp corner it
/// tends to zero and samples crowd towards the corner; a large `ε` may leave a closed path
/// with fewer than 3 samples.
///
/// # Errors
/// [`Error::InvalidOption`] if `eps` is not in `(0, 2]`, `offset` not in `[0, 1)`, the path
/// is degenerate (see [`lfs`]), or the walk stalls where lfs vanishes.
pub fn eps_sample(path: &BezierPath, eps: f64, offset: f64) -> Result<Sample> {
    Ok(eps_sample_with_frames(path, eps, offset)?.sample)
}

/// [`eps_sample`] with each sample's parameter, normal and local feature size.
///
/// # Errors
/// As [`eps_sample`].
pub fn eps_sample_with_frames(path: &BezierPath, eps: f64, offset: f64) -> Result<FramedSample> {
    eps_sample_at_density(path, eps, offset, DENSE_STEPS)
}

/// [`eps_sample_with_frames`] on a dense curve of `density` parameters per segment instead
/// of [`DENSE_STEPS`]: the same walk, coarser lfs. For the fuzz target, which needs many
/// runs a second.
///
/// # Errors
/// As [`eps_sample`].
pub fn eps_sample_at_density(
    path: &BezierPath,
    eps: f64,
    offset: f64,
    density: usize,
) -> Result<FramedSample> {
    let density = density.max(1);
    if !(eps > 0.0 && eps <= 2.0) {
        return Err(Error::InvalidOption(format!("eps must be in (0, 2], got {eps}")));
    }
    if !(0.0..1.0).contains(&offset) {
        return Err(Error::InvalidOption(format!("offset must be in [0, 1), got {offset}")));
    }
    // The walk is the same at every scale, but squared distances overflow past 1e154 and
    // underflow below 1e-154: it runs on the path scaled by a power of two to a fixed size,
    // and its points and lfs are scaled back (exactly).
    let power = fixed_size_power(path.largest_coordinate());
    if power != 0 {
        let mut framed = eps_sample_at_density(&path.scaled(power), eps, offset, density)?;
        let back = |v: f64| scale(v, -power);
        framed.sample.points.iter_mut().for_each(|p| *p = p.map(back));
        framed.lfs.iter_mut().for_each(|l| *l = back(*l));
        return Ok(framed);
    }
    let dense = lfs_at_density(path, density)?;
    let walker = Walker { path, tree: KdTree::new(&dense.medial), eps, density: density as f64 };
    let span = path.segments.len() as f64;
    let steps = density * path.segments.len();
    let first = ((offset * steps as f64).floor() as usize).min(steps - 1) as f64 / density as f64;
    let mut params = if path.closed {
        walker.walk(first, first + span, steps)?
    } else {
        let mut backward = walker.walk(first, 0.0, steps)?;
        backward.reverse();
        backward.pop(); // the first sample again
        backward.extend(walker.walk(first, span, steps)?);
        backward
    };
    if path.closed {
        params.iter_mut().for_each(|u| *u = u.rem_euclid(span));
    }
    let points: Vec<Point> = params.iter().map(|&u| path.point(u)).collect();
    let n = points.len();
    let edges = if path.closed {
        cycle_edges(n)
    } else {
        (1..n).map(|i| [i - 1, i]).collect::<Vec<Edge>>()
    };
    let normals = params.iter().map(|&u| normal(path, u).unwrap_or([0.0, 0.0])).collect();
    let lfs = points.iter().map(|&x| nearest(&walker.tree, x)).collect();
    Ok(FramedSample { sample: Sample { points, edges }, params, normals, lfs })
}

/// The greedy walk of step 4 over the medial points' k-d tree.
struct Walker<'a> {
    path: &'a BezierPath,
    tree: KdTree<'a>,
    eps: f64,
    /// Dense parameters per segment.
    density: f64,
}

impl Walker<'_> {
    /// The parameters of the samples from `first` towards `limit` (either direction): `first`,
    /// then each next sample; `limit` itself is appended for an open end (`limit` an end of
    /// the chain), not for the return to `first` of a closed walk.
    fn walk(&self, first: f64, limit: f64, steps: usize) -> Result<Vec<f64>> {
        let mut samples = vec![first];
        let reaches_end = !self.path.closed;
        let mut s = first;
        loop {
            // Each sample moves by more than PRECISION, and near a corner the samples thin
            // out geometrically from the dense points: this bound is never reached in practice.
            if samples.len() > 4 * steps + 16 {
                return Err(Error::InvalidOption("eps-sampling did not terminate".into()));
            }
            if s == limit {
                return Ok(samples); // an open walk starting at its end
            }
            let centre = self.path.point(s);
            let eps = self.eps;
            let Some(p) = self.reach(s, limit, |x, u| distance(x, centre) < eps * self.lfs_at(u))
            else {
                break;
            };
            let (at, l) = (self.path.point(p), self.lfs_at(p));
            let Some(q) = self.reach(p, limit, |x, _| distance(x, at) < eps * l) else {
                break;
            };
            if (q - s).abs() <= PRECISION {
                let seg = (s.rem_euclid(self.path.segments.len() as f64)).floor();
                return Err(Error::InvalidOption(format!(
                    "eps-sampling stalled in segment {seg} (local feature size vanishes near \
                     parameter {s:.6}): a cusp or self-intersection?"
                )));
            }
            samples.push(q);
            s = q;
        }
        if reaches_end {
            samples.push(limit);
        }
        Ok(samples)
    }

    /// From parameter `from`, steps over the dense parameters towards `limit` while
    /// `inside(point, parameter)` holds; the last parameter where it holds, bisected, or
    /// `None` if the walk reaches `limit`.
    fn reach(&self, from: f64, limit: f64, inside: impl Fn(Point, f64) -> bool) -> Option<f64> {
        let dir = if limit > from { 1.0 } else { -1.0 };
        let scale = self.density;
        let mut k =
            if dir > 0.0 { (from * scale).floor() + 1.0 } else { (from * scale).ceil() - 1.0 };
        let end = (limit * scale).round(); // limits are dense parameters
        let mut good = from;
        loop {
            let u = k / scale;
            if (k - end) * dir >= 0.0 {
                return None;
            }
            if !inside(self.path.point(u), u) {
                let mut bad = u;
                while (bad - good).abs() > PRECISION {
                    let mid = 0.5 * (good + bad);
                    if inside(self.path.point(mid), mid) {
                        good = mid;
                    } else {
                        bad = mid;
                    }
                }
                return Some(good);
            }
            good = u;
            k += dir;
        }
    }

    fn lfs_at(&self, u: f64) -> f64 {
        nearest(&self.tree, self.path.point(u))
    }
}

/// The medial point of each of `points` (step 2), tangent disks capped at radius `cap`.
///
/// The largest disk tangent at `x` on the side of `n` with no point inside has its centre
/// where the ray `x + t·n` leaves the Voronoi cell of `x`: the limit of shrinking, found
/// directly. The cell is bounded by the bisectors with the Delaunay neighbours `y` of `x`,
/// and the ray crosses the one of `y` at `t = |y − x|² / (2 (y − x)·n)` if `(y − x)·n > 0`.
fn medial_points(points: &[Point], normals: &[Point], cap: f64) -> Result<Vec<Point>> {
    let dt = Triangulation::new(points)?;
    let mut vertex = vec![0; points.len()];
    for v in 0..dt.num_vertices() as u32 {
        vertex[dt.input_index(v)] = v;
    }
    for &[duplicate, representative] in dt.duplicates() {
        vertex[duplicate] = vertex[representative];
    }
    let medial = |(i, (&x, &n)): (usize, (&Point, &Point))| {
        let (mut plus, mut minus) = (cap, cap);
        for h in dt.incident(vertex[i]) {
            let y = points[dt.input_index(dt.other(h, vertex[i]))];
            let v = [y[0] - x[0], y[1] - x[1]];
            let along = v[0] * n[0] + v[1] * n[1];
            let t = (v[0] * v[0] + v[1] * v[1]) / (2.0 * along.abs());
            if along > 0.0 {
                plus = plus.min(t);
            } else if along < 0.0 {
                minus = minus.min(t);
            }
        }
        let r = if minus < plus { -minus } else { plus };
        [x[0] + r * n[0], x[1] + r * n[1]]
    };
    Ok(points.iter().zip(normals).enumerate().map(medial).collect())
}

/// The unit normal at parameter `u`; where the derivative vanishes (coinciding control
/// points), the direction of a short chord around `u`. `None` if that vanishes too.
fn normal(path: &BezierPath, u: f64) -> Option<Point> {
    let mut d = path.derivative(u);
    if d == [0.0, 0.0] {
        let h = 1e-6;
        let (a, b) = (path.point(u - h), path.point(u + h));
        d = [b[0] - a[0], b[1] - a[1]];
    }
    let len = d[0].hypot(d[1]);
    (len > 0.0 && len.is_finite()).then(|| [-d[1] / len, d[0] / len])
}

fn nearest(tree: &KdTree, x: Point) -> f64 {
    tree.nearest(x, 1, u32::MAX).first().map_or(f64::INFINITY, |&(d2, _)| d2.sqrt())
}

/// The diagonal of the bounding box of `points`; infinite for none.
pub(super) fn diagonal(points: &[Point]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

#[cfg(test)]
#[path = "eps_sampling_tests.rs"]
mod tests;
