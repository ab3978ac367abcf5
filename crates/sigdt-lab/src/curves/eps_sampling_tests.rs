//! Unit tests of [`super`]: a circle of four cubics, the bundled drawings in `data/svg`.
use super::*;
use crate::curves::read_svg_paths;
use sigdt::samplers::lfs_noise;

/// A circle of radius `r` about the origin from 4 cubics (control distance κ·r).
fn circle(r: f64) -> BezierPath {
    let k = 0.552_284_749_8 * r;
    let quarter = |a: Point, b: Point| {
        // From a to b counter-clockwise: tangents are a and b turned a quarter.
        [
            a,
            [a[0] - k * a[1] / r, a[1] + k * a[0] / r],
            [b[0] + k * b[1] / r, b[1] - k * b[0] / r],
            b,
        ]
    };
    let p = [[r, 0.0], [0.0, r], [-r, 0.0], [0.0, -r]];
    BezierPath { segments: (0..4).map(|i| quarter(p[i], p[(i + 1) % 4])).collect(), closed: true }
}

fn drawing(file: &str) -> Vec<BezierPath> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/svg");
    read_svg_paths(&dir.join(file)).unwrap()
}

/// The largest `dist(x, nearest sample) / lfs(x)` over the dense points: the sample's ε.
fn sample_eps(dense: &DenseCurve, points: &[Point]) -> f64 {
    let tree = KdTree::new(points);
    let ratio = |(k, &x): (usize, &Point)| nearest(&tree, x) / dense.lfs[k];
    dense.points.iter().enumerate().map(ratio).fold(0.0, f64::max)
}

#[test]
fn the_lfs_of_a_circle_is_its_radius() {
    let dense = lfs(&circle(2.0)).unwrap();
    assert_eq!(dense.points.len(), 4 * DENSE_STEPS);
    assert!(dense.lfs.iter().all(|&l| (l - 2.0).abs() < 0.03), "{:?}", dense.lfs[..3].to_vec());
    assert!(dense.medial.iter().all(|m| m[0].hypot(m[1]) < 0.03));
}

#[test]
fn a_circle_is_sampled_at_the_eps_spacing() {
    let path = circle(3.0);
    let dense = lfs(&path).unwrap();
    for eps in [0.1, 0.25, 0.5] {
        let framed = eps_sample_with_frames(&path, eps, 0.0).unwrap();
        let (s, l) = (&framed.sample, framed.lfs[0]);
        let n = s.points.len();
        assert_eq!(s.edges, cycle_edges(n));
        let gap = 2.0 * eps * l * (1.0 - eps * eps / 4.0).sqrt();
        let gaps: Vec<f64> = (0..n).map(|i| distance(s.points[i], s.points[(i + 1) % n])).collect();
        assert!(gaps[..n - 1].iter().all(|g| (g / gap - 1.0).abs() < 2e-3), "{eps}: {gaps:?}");
        assert!(gaps[n - 1] <= gap * 1.002);
        let e = sample_eps(&dense, &s.points);
        assert!(e <= eps * (1.0 + 1e-6) && e > 0.95 * eps, "eps {eps}: sample eps {e}");
    }
}

#[test]
fn a_drawing_is_eps_sampled_with_maximal_spacing() {
    let path = &drawing("simple.svg")[0];
    let dense = lfs(path).unwrap();
    let mut counts = Vec::new();
    for eps in [0.1, 0.2, 0.3, 0.4, 0.5] {
        for k in [0, 13] {
            let framed = eps_sample_with_frames(path, eps, k as f64 / 20.0).unwrap();
            let s = &framed.sample;
            let e = sample_eps(&dense, &s.points);
            assert!(e <= eps * 1.02 && e > 0.9 * eps, "eps {eps}, offset {k}: sample eps {e}");
            assert_eq!(s.edges, cycle_edges(s.points.len()));
            assert!(framed
                .lfs
                .iter()
                .zip(&framed.normals)
                .all(|(l, n)| { *l > 0.0 && (n[0].hypot(n[1]) - 1.0).abs() < 1e-12 }));
            if k == 0 {
                counts.push(s.points.len());
            }
        }
    }
    assert!(counts.windows(2).all(|w| w[0] > w[1]), "{counts:?}");
}

#[test]
fn the_offset_moves_the_first_sample() {
    let path = &drawing("simple.svg")[0];
    let a = eps_sample_with_frames(path, 0.3, 0.0).unwrap();
    let b = eps_sample_with_frames(path, 0.3, 0.35).unwrap();
    assert_eq!(a.sample.points[0], path.segments[0][0]);
    assert_eq!(b.params[0], 1.75);
    assert_eq!(b.sample.points[0], path.point(1.75));
    assert_eq!(a, eps_sample_with_frames(path, 0.3, 0.0).unwrap());
    assert!(a.params.windows(2).all(|w| w[0] < w[1]));
    let noisy = lfs_noise(&a.sample.points, &a.normals, &a.lfs, 0.3, 9).unwrap();
    let moved = noisy.iter().zip(&a.sample.points).map(|(&p, &q)| distance(p, q));
    assert!(moved.zip(&a.lfs).all(|(d, l)| d <= 0.3 * l && d > 0.0));
}

#[test]
fn open_paths_keep_both_end_points() {
    let path = &drawing("corner.svg")[1];
    let end = path.segments[path.segments.len() - 1][3];
    for offset in [0.0, 0.5] {
        let s = eps_sample(path, 0.2, offset).unwrap();
        let n = s.points.len();
        assert_eq!((s.points[0], s.points[n - 1]), (path.segments[0][0], end));
        assert_eq!(s.edges, (1..n).map(|i| [i - 1, i]).collect::<Vec<_>>());
        let e = sample_eps(&lfs(path).unwrap(), &s.points);
        assert!(e <= 0.2 * 1.02, "{e}");
    }
}

#[test]
fn samples_crowd_towards_a_sharp_corner() {
    let path = &drawing("corner.svg")[0];
    let dense = lfs(path).unwrap();
    assert!(dense.lfs[0] < 0.2 && dense.lfs[DENSE_STEPS / 2] > 5.0, "{}", dense.lfs[0]);
    let s = eps_sample(path, 0.3, 0.5).unwrap();
    let corner = path.segments[0][0];
    let near = s.points.iter().filter(|&&p| distance(p, corner) < 5.0).count();
    assert!(near > s.points.len() / 3, "{near} of {}", s.points.len());
}

#[test]
fn bad_options_and_degenerate_paths_are_errors() {
    let path = circle(1.0);
    let message = |r: Result<Sample>| r.unwrap_err().to_string();
    for eps in [0.0, -1.0, 2.5, f64::NAN] {
        assert!(message(eps_sample(&path, eps, 0.0)).contains("eps must be in (0, 2]"));
    }
    for offset in [1.0, -0.1, f64::NAN] {
        assert!(message(eps_sample(&path, 0.1, offset)).contains("offset must be in [0, 1)"));
    }
    let empty = BezierPath::default();
    assert!(message(eps_sample(&empty, 0.1, 0.0)).contains("no segment"));
    let point = BezierPath { segments: vec![[[1.0, 1.0]; 4]], closed: true };
    let m = message(eps_sample(&point, 0.1, 0.0));
    assert!(m.contains("zero length"), "{m}");
    let nan = BezierPath { segments: vec![[[f64::NAN, 1.0]; 4]], closed: false };
    assert!(message(eps_sample(&nan, 0.1, 0.0)).contains("not finite"));
    assert!(eps_sample(&path, 2.0, 0.0).unwrap().points.len() <= 2);
}

/// A circle drawn with `k` cubics: the medial points of all its dense points crowd at the
/// centre, which made every lfs query scan them all (k = 32: 73 s; now the k-d tree's cell
/// pruning makes it about a second in a release build).
fn circle_of(k: usize, r: f64) -> BezierPath {
    let step = std::f64::consts::TAU / k as f64;
    let kappa = 4.0 / 3.0 * (step / 4.0).tan() * r;
    let arc = |i: usize| {
        let (a, b) = (i as f64 * step, (i + 1) as f64 * step);
        let (p, q) = ([r * a.cos(), r * a.sin()], [r * b.cos(), r * b.sin()]);
        [
            p,
            [p[0] - kappa * a.sin(), p[1] + kappa * a.cos()],
            [q[0] + kappa * b.sin(), q[1] - kappa * b.cos()],
            q,
        ]
    };
    BezierPath { segments: (0..k).map(arc).collect(), closed: true }
}

#[test]
fn a_circle_of_many_cubics_is_sampled_evenly() {
    let path = circle_of(16, 5.0);
    let s = eps_sample(&path, 0.3, 0.0).unwrap();
    let n = s.points.len();
    let gaps: Vec<f64> = (0..n).map(|i| distance(s.points[i], s.points[(i + 1) % n])).collect();
    let gap = 2.0 * 0.3 * 5.0 * (1.0 - 0.09 / 4.0f64).sqrt();
    assert!(gaps[..n - 1].iter().all(|g| (g / gap - 1.0).abs() < 2e-3), "{gaps:?}");
}
