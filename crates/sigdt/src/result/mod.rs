//! What a reconstruction returns: edges, ordered loops and paths, a status and diagnostics;
//! the documented results of degenerate input; reading any edge set as such a result; and
//! the loops grouped into polygons with holes.

mod degenerate;
mod from_edges;
#[cfg(feature = "geo-types")]
mod geo;
mod polygons;

pub(crate) use degenerate::degenerate_result;
pub(crate) use from_edges::{from_new_vertices, from_vertex_pairs};
// The sampling check is a room of its own (`crate::sampling_check`); its findings are
// part of every result, so their types are also named here.
pub use crate::sampling_check::AREA_TOLERANCE;
#[doc(hidden)]
pub use crate::sampling_check::{measure_curve, EdgeMeasure};
pub use crate::sampling_check::{
    Finding, FindingKind, DEPTH_RATIO, LONG_EDGE_RATIO, MIN_LOOP_POINTS, STRAY_DEPTH_RATIO,
};
pub use polygons::Polygon;

/// The [`LeftOut`] entries of points left inside when sculpting got stuck (input indices,
/// sorted).
pub(crate) fn inside_left_out(indices: &[usize]) -> Vec<LeftOut> {
    indices.iter().map(|&index| LeftOut { index, reason: LeftOutReason::Inside }).collect()
}

use crate::geometry::{Edge, Point};

/// The result of [`reconstruct`](crate::reconstruct()).
///
/// All indices are 0-based indices into the caller's points. Exact duplicates take part
/// through their lowest-index representative: they get no edges and are listed in
/// [`duplicates`](Self::duplicates).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Reconstruction {
    /// Undirected edges `[i, j]`, `i < j`, sorted.
    pub edges: Vec<Edge>,
    /// Closed loops, each an ordered list of vertices (the edge from the last back to the
    /// first is implied). Each loop runs counter-clockwise around the region it bounds and
    /// starts at its smallest index; loops are sorted by that first index.
    pub loops: Vec<Vec<usize>>,
    /// Open paths, each an ordered list of vertices starting at its smaller end; sorted.
    /// SIG-CONNECT2D only produces one, for collinear input or two distinct points; graph
    /// filters such as CRUST produce them for open curves, and at junctions
    /// ([`Status::Network`], [`Status::Branching`]) paths end at the junction (a path may
    /// start and end there).
    pub paths: Vec<Vec<usize>>,
    /// How the run ended.
    pub status: Status,
    /// `[duplicate, representative]` for every point equal to a lower-index point, sorted.
    pub duplicates: Vec<Edge>,
    /// The distinct points the method left out on purpose, each with the reason, sorted by
    /// index. They get no edges. (Duplicates are not listed here.)
    pub left_out: Vec<LeftOut>,
    /// Where the vertices of the edges, loops and paths are: the input points, unless the
    /// method moves them or places its own.
    pub vertices: Vertices,
    /// Per-stage counts, for diagnostics and benchmarks.
    pub stats: Stats,
    /// What the sampling check found: where the loops and paths break the sampling
    /// condition they assume (edges far longer than the point spacing at both of their
    /// ends, readings that double back). Empty when the result reads as a sampled curve,
    /// and for methods that move points or place their own. See [`Finding`].
    pub diagnosis: Vec<Finding>,
}

impl Reconstruction {
    /// True when the result may not be the curves the points came from: its status says so
    /// ([`Status::is_warning`]) or the sampling check found something ([`Self::diagnosis`]).
    /// Front ends warn then.
    pub fn warns(&self) -> bool {
        self.status.is_warning() || !self.diagnosis.is_empty()
    }

    /// The junctions: vertices with three edges or more, where curves cross, end on one
    /// another or share an end (status [`Status::Network`]; [`Status::Branching`] for methods
    /// that do not read junctions), sorted. Indices as in
    /// [`edges`](Self::edges).
    ///
    /// ```
    /// // A T: a bar of 17 samples with a stem of 8 ending on its middle.
    /// let mut points: Vec<[f64; 2]> = (-8..=8).map(|i| [i as f64, 0.0]).collect();
    /// points.extend((1..=8).map(|i| [0.1 * (i as f64).sin(), i as f64]));
    /// let rec = sigdt::reconstruct(&points, &sigdt::Options::default()).unwrap();
    /// assert_eq!(rec.status, sigdt::Status::Network);
    /// assert_eq!(rec.junctions(), vec![8]);
    /// ```
    pub fn junctions(&self) -> Vec<usize> {
        let mut degree: Vec<u8> = Vec::new();
        for &[i, j] in &self.edges {
            let needed = i.max(j) + 1;
            if degree.len() < needed {
                degree.resize(needed, 0);
            }
            degree[i] = degree[i].saturating_add(1);
            degree[j] = degree[j].saturating_add(1);
        }
        (0..degree.len()).filter(|&v| degree[v] >= 3).collect()
    }

    /// The coordinates the edges, loops and paths index: `input` (the caller's points),
    /// unless the method moved them or placed its own ([`Vertices`]).
    pub fn vertex_positions<'a>(&'a self, input: &'a [Point]) -> &'a [Point] {
        match &self.vertices {
            Vertices::Input => input,
            Vertices::Moved(points) | Vertices::New(points) => points,
        }
    }
}

/// A distinct input point that a method left out on purpose.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct LeftOut {
    /// The point's input index.
    pub index: usize,
    /// Why it has no edge.
    pub reason: LeftOutReason,
}

/// Why a method left a point out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum LeftOutReason {
    /// Sculpting found no candidate triangle while the point was still inside the boundary
    /// ([`Status::SculptingStuck`]).
    Inside,
    /// The method's outlier criterion says the point is a sample of no curve.
    Outlier,
    /// FITCONNECT eliminated it (redundant between two linked points, inside an edge, or a
    /// one-point obstacle).
    Eliminated,
    /// FITCONNECT's fitted neighbourhood of the point never conformed.
    NonConforming,
    /// FITCONNECT stopped at a pass or work limit before deciding the point
    /// ([`Status::Unfinished`]).
    Unresolved,
    /// A vertex of a seam, not of a curve: longitude/latitude data stores a polygon cut at
    /// the antimeridian as pieces whose boundaries run along ±180°, and the vertices between
    /// the ends of the cut lie inside the area (set by `sigdt-io`'s local plane, which
    /// recognises them; no method leaves points out for this).
    Seam,
}

impl LeftOutReason {
    /// Every reason, in the order of their names' listing.
    pub const ALL: [LeftOutReason; 6] = [
        LeftOutReason::Inside,
        LeftOutReason::Outlier,
        LeftOutReason::Eliminated,
        LeftOutReason::NonConforming,
        LeftOutReason::Unresolved,
        LeftOutReason::Seam,
    ];

    /// The kebab-case name: `inside`, `outlier`, `eliminated`, `non-conforming`,
    /// `unresolved` or `seam`.
    pub fn name(self) -> &'static str {
        match self {
            LeftOutReason::Inside => "inside",
            LeftOutReason::Outlier => "outlier",
            LeftOutReason::Eliminated => "eliminated",
            LeftOutReason::NonConforming => "non-conforming",
            LeftOutReason::Unresolved => "unresolved",
            LeftOutReason::Seam => "seam",
        }
    }
}

/// Where a result's vertices are.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Vertices {
    /// The input points: edges, loops and paths hold input indices (every method but the
    /// two below).
    #[default]
    Input,
    /// Every input point moved to a new position, by index (STRETCHDENOISE moves points
    /// within their noise extents); edges still hold input indices.
    Moved(Vec<Point>),
    /// The method's own vertices (OPTIMALTRANSPORT places them where the transport plan
    /// puts them): edges, loops and paths index these, not the input.
    New(Vec<Point>),
}

/// How a reconstruction ended.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Status {
    /// One closed simple polygon through every distinct point (but those listed in
    /// [`Reconstruction::left_out`] as outliers).
    #[default]
    Polygon,
    /// Several pairwise disjoint closed simple polygons that together pass through every
    /// distinct point (but the outliers left out).
    Polygons,
    /// Sculpting found no candidate triangle while these points (input indices, sorted)
    /// were still inside the boundary. The loops are simple and disjoint but miss them.
    /// [MOW22](https://doi.org/10.1111/cgf.14654) §4.2.2: sculpting can fail when the
    /// Delaunay triangulation has no suitable Hamiltonian cycle.
    SculptingStuck {
        /// The points not on any loop.
        left_out: Vec<usize>,
    },
    /// The edges form vertex-disjoint loops and open paths (every point has at most two
    /// edges), but not closed loops through every distinct point: some paths are open or
    /// some points have no edge. Methods that filter a graph (CRUST and its kin) return this.
    Curves,
    /// Curves that meet: SIG-AUTO read some points as junctions, each where three or four
    /// curves, each sampled like a curve on its own, end or cross (see
    /// [`Reconstruction::junctions`]). Paths run between junctions and ends; a path may
    /// start and end at the same junction. A reading, not a failure: no warning.
    Network,
    /// Some point has three or more edges, from a method that filters a graph (the crusts,
    /// EMST, …) and does not read junctions: a branch may be a junction of the curves or a
    /// stray edge. Paths run as for [`Network`](Status::Network).
    Branching,
    /// The edges zigzag somewhere (four consecutive vertices turning by more than 60° in
    /// alternating directions, which no curve sampled with ε < 1 does, corners included):
    /// the points are too noisy, or too sparse, for a curve through them there. The loops
    /// and paths are the method's best reading all the same. (SIG-AUTO.)
    Noisy,
    /// Some edges cross: FITCONNECT links points whose fitted neighbourhoods overlap, which
    /// does not rule out crossings (the authors' program gives them too), and
    /// STRETCHDENOISE's moves can make them. The loops and paths are read from the edges
    /// all the same.
    Crossing,
    /// FITCONNECT stopped at a pass or work limit with points still undecided; they are
    /// left out as [`Unresolved`](LeftOutReason::Unresolved) and the edges are those decided
    /// so far (they may cross: see [`Crossing`](Status::Crossing)).
    Unfinished,
    /// All distinct points lie on one line: the result is the path through them in their
    /// order along the line.
    Collinear,
    /// Fewer than three distinct points: two give the edge between them, one or none give
    /// nothing.
    TooFewPoints,
}

impl Status {
    /// True when the loops pass through every distinct point (`Polygon` or `Polygons`).
    pub fn is_manifold(&self) -> bool {
        matches!(self, Status::Polygon | Status::Polygons)
    }

    /// True when the status says the result is not a faithful reading of curves: sculpting
    /// got stuck, edges branch where the method does not read junctions, or they zigzag; or there is no curve at all
    /// (fewer than three distinct points: an empty export fed to a pipeline must not pass
    /// unnoticed). Front ends warn then.
    pub fn is_warning(&self) -> bool {
        matches!(
            self,
            Status::SculptingStuck { .. }
                | Status::Branching
                | Status::Noisy
                | Status::Crossing
                | Status::Unfinished
                | Status::TooFewPoints
        )
    }

    /// A short kebab-case name: `polygon`, `polygons`, `sculpting-stuck`, `curves`,
    /// `network`, `branching`, `noisy`, `crossing`, `unfinished`, `collinear`, `too-few-points`.
    pub fn name(&self) -> &'static str {
        match self {
            Status::Polygon => "polygon",
            Status::Polygons => "polygons",
            Status::SculptingStuck { .. } => "sculpting-stuck",
            Status::Curves => "curves",
            Status::Network => "network",
            Status::Branching => "branching",
            Status::Noisy => "noisy",
            Status::Crossing => "crossing",
            Status::Unfinished => "unfinished",
            Status::Collinear => "collinear",
            Status::TooFewPoints => "too-few-points",
        }
    }
}

impl std::fmt::Display for Status {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Status::Polygon => f.write_str("one closed polygon through every point not left out"),
            Status::Polygons => {
                f.write_str("several closed polygons through every point not left out")
            }
            Status::SculptingStuck { left_out } => write!(
                f,
                "sculpting got stuck: {} point(s) left inside the boundary",
                left_out.len()
            ),
            Status::Curves => f.write_str("loops and open paths, not all points on loops"),
            Status::Network => f.write_str("curves meeting at junctions (read as such)"),
            Status::Branching => f.write_str(
                "edges branch (a point with 3+ edges) where the method does not read junctions",
            ),
            Status::Noisy => f.write_str("the edges zigzag: the points are too noisy or sparse"),
            Status::Crossing => f.write_str("some edges cross"),
            Status::Unfinished => {
                f.write_str("stopped at a pass or work limit: undecided points are left out")
            }
            Status::Collinear => f.write_str("all points are collinear: one open path"),
            Status::TooFewPoints => f.write_str("fewer than three distinct points"),
        }
    }
}

/// Per-stage counts of one run ([MOW22](https://doi.org/10.1111/cgf.14654) Algorithm 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Stats {
    /// Number of input points.
    pub points: usize,
    /// Number of distinct points.
    pub distinct_points: usize,
    /// Edges of the initial graph (SIGDT or SIGDT2).
    pub graph_edges: usize,
    /// Edges added by leaf elimination.
    pub leaf_edges_added: usize,
    /// Non-manifold vertices before inflating.
    pub non_manifold_before: usize,
    /// Triangles turned interior by inflating (pockets not included).
    pub inflated_triangles: usize,
    /// Enclosed exterior pockets filled during inflating.
    pub pockets: usize,
    /// Interior (isolated) vertices before sculpting.
    pub interior_before_sculpting: usize,
    /// Triangles removed by sculpting.
    pub sculpted_triangles: usize,
}
