//! What the sampling check finds ([`Finding`], one per kind), and how a finding reads: the
//! message names where (the coordinates as given) and says what to do.
use super::{LONG_EDGE_RATIO, MIN_LOOP_POINTS, STRAY_DEPTH_RATIO};

/// What the sampling check found wrong with a result: one entry per kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Finding {
    /// What kind of violation.
    pub kind: FindingKind,
    /// How many edges (passing over samples), vertices (doubling back), loops, open ends,
    /// pairs of ends or outliers show it.
    pub count: usize,
    /// The worst value: how deep a sample reaches into an edge's disk, in point spacings,
    /// the sharpest turn in degrees, the number of points of the smallest small loop, an
    /// open end's last edge over its nearest distance, the smallest gap between two ends
    /// over their longer last edge, the nearest outlier's distance to the curves over the
    /// spacing it is measured against, or the share of the area that noise makes uncertain.
    pub worst: f64,
    /// Input index of a point where the worst value is (an end of the edge, or the vertex
    /// that turns).
    pub at: usize,
    /// The coordinates of point [`at`](Self::at), as given: where to look.
    pub point: [f64; 2],
}

/// The kinds of [`Finding`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[non_exhaustive]
pub enum FindingKind {
    /// Edges whose diametral disk holds a sample at least [`STRAY_DEPTH_RATIO`] point
    /// spacings deep ([`DEPTH_RATIO`](super::DEPTH_RATIO) for the curve's next vertex beyond an end): the edge
    /// passes over samples it skips (slivers, bridges).
    PassesOverSamples,
    /// Vertices where the reading turns by more than 150° between two edges that are each
    /// at least [`LONG_EDGE_RATIO`] times the spacing at their far end (outliers wired in).
    DoublesBack,
    /// Loops of fewer than [`MIN_LOOP_POINTS`] points, which no closed curve sampled with
    /// ρ < 1 gives, beside a curve of at least that many.
    SmallLoops,
    /// Ends of open paths with another point nearer than half their last edge.
    OpenEnds,
    /// Points left out as outliers within half their spacing of an edge of the result,
    /// nearer to one of its vertices than half that vertex's longer edge, or nearer to an
    /// edge than its length.
    OutliersOnCurve,
    /// Pairs of ends of open paths nearer to each other than [`LONG_EDGE_RATIO`] times their
    /// longer last edge (`sampling_check/ends_meet.rs`): the curve may go on, or close, there.
    EndsMeet,
    /// Loops whose points scatter like noise (the turn reverses at most of them), by enough
    /// to make the area they enclose uncertain by more than a twentieth
    /// (`sampling_check/noisy_area.rs`).
    NoisyArea,
    /// Open paths where the caller said the points outline areas
    /// ([`Expect::Areas`](crate::Expect::Areas)): no reading closed them.
    OpenOutlines,
}

impl FindingKind {
    /// The kebab-case name: `passes-over-samples`, `doubles-back`, `small-loops`,
    /// `open-ends`, `ends-meet`, `outliers-on-curve`, `noisy-area` or `open-outlines`.
    pub fn name(self) -> &'static str {
        match self {
            FindingKind::PassesOverSamples => "passes-over-samples",
            FindingKind::DoublesBack => "doubles-back",
            FindingKind::SmallLoops => "small-loops",
            FindingKind::OpenEnds => "open-ends",
            FindingKind::OutliersOnCurve => "outliers-on-curve",
            FindingKind::EndsMeet => "ends-meet",
            FindingKind::NoisyArea => "noisy-area",
            FindingKind::OpenOutlines => "open-outlines",
        }
    }
}

/// A finding in words a user acts on: what is wrong, where (the coordinates of the worst
/// place, as given) and what to do about it.
impl std::fmt::Display for Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let near = Near(self.point);
        let (count, worst) = (self.count, self.worst);
        match self.kind {
            FindingKind::PassesOverSamples => write!(
                f,
                "{count} edge(s) pass over other points (worst near {near}, reaching {} point \
                 spacings into the edge's diametral disk where a sampled curve allows less \
                 than {STRAY_DEPTH_RATIO}): the points are too sparse or too noisy there to \
                 tell which way the curve runs; densify the source lines there",
                Spacings(worst)
            ),
            FindingKind::DoublesBack => write!(
                f,
                "the curve runs out to a far point and back at {count} point(s) (worst near \
                 {near}, a turn of {worst:.0} degrees): probably an outlier wired in; remove \
                 it if it is no part of the shape"
            ),
            FindingKind::SmallLoops => write!(
                f,
                "{count} loop(s) of fewer than {MIN_LOOP_POINTS} points beside larger curves \
                 (the smallest, of {worst} points, near {near}; a closed curve sampled densely \
                 enough has at least {MIN_LOOP_POINTS}): noise, or points sparser than the \
                 curve's detail; check them, or densify the source lines there"
            ),
            FindingKind::OpenEnds => write!(
                f,
                "{count} open end(s) stop next to other points (worst near {near}: its last \
                 edge is {worst:.1}x the distance to its nearest point): the curve may go on \
                 there; if the points outline areas, densify their long sides"
            ),
            FindingKind::OutliersOnCurve => write!(
                f,
                "{count} point(s) left out as outliers lie on or near the curves (worst near \
                 {near}, {worst:.2} of the point spacing from them, where an outlier lies \
                 farther off than the spacing): they may be samples of the curve; check them"
            ),
            FindingKind::EndsMeet => write!(
                f,
                "{count} pair(s) of open ends lie less than {LONG_EDGE_RATIO} last edges apart \
                 (worst near {near}, {worst:.1} last edges): the curve may go on, or close, \
                 there; if the points outline areas, densify their long sides"
            ),
            FindingKind::NoisyArea => write!(
                f,
                "{count} loop(s) scatter like noise (their turns reverse at most points, as \
                 noisy points or a coarsely digitised border do; worst near {near}): if the \
                 points are noisy samples, the area they enclose is uncertain by about {:.0} %; \
                 if they are exact vertices, only the order they are joined in is in doubt",
                100.0 * worst
            ),
            FindingKind::OpenOutlines => write!(
                f,
                "{count} outline(s) come back open although the points outline areas (worst \
                 near {near}, where its ends lie {worst:.1} times its longest edge apart): \
                 the points do not close it there; densify the source lines there, or look \
                 for a missing stretch"
            ),
        }
    }
}

/// Coordinates in a message: six significant digits, enough to find the place.
struct Near([f64; 2]);

impl std::fmt::Display for Near {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [x, y] = self.0;
        write!(f, "({}, {})", Significant(x), Significant(y))
    }
}

/// A number to six significant digits, without trailing zeros.
pub(super) struct Significant(pub(super) f64);

impl std::fmt::Display for Significant {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if !x.is_finite() || x == 0.0 {
            return write!(f, "{x}");
        }
        let magnitude = x.abs().log10().floor() as i32;
        if !(-4..15).contains(&magnitude) {
            return write!(f, "{x:.5e}");
        }
        let decimals = (5 - magnitude).max(0) as usize;
        let text = format!("{x:.decimals$}");
        let text = if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.')
        } else {
            &text
        };
        write!(f, "{text}")
    }
}

/// A depth in point spacings; beyond a thousand the number says nothing more (a point next
/// to a near-duplicate has a spacing close to zero).
pub(super) struct Spacings(pub(super) f64);

impl std::fmt::Display for Spacings {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            d if d > 1000.0 => write!(f, "more than 1000"),
            d => write!(f, "{d:.1}"),
        }
    }
}
