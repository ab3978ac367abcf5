//! The colours of every sigdt picture: [`render_svg`](super::render_svg), the viewer of
//! `sigdt view` and Python's `sigdt.plot` / `plot_steps` all read them from here (the
//! viewer gets [`PALETTE`] in its page, Python as `sigdt._core.PALETTE`), so one layer looks
//! the same everywhere.
//!
//! The hues are the Okabe–Ito palette, which stays distinct under the common colour-vision
//! deficiencies. Missing and extra edges use its most distinct pair, vermillion and blue, and
//! missing edges are also dashed so they differ in shape, not only in colour.

/// Points and the result's edges.
pub const INK: &str = "#1a1a1a";
/// The inside of the result's loops, and of the interior while it is inflated and sculpted.
pub const FILL: &str = "#dce8f4";
/// Behind everything.
pub const BACKGROUND: &str = "#ffffff";
/// Delaunay edges.
pub const GREY: &str = "#b4b4b4";
/// SIG circles.
pub const SKY: &str = "#56b4e9";
/// SIGDT edges.
pub const GREEN: &str = "#009e73";
/// SIGDT2 edges.
pub const PURPLE: &str = "#cc79a7";
/// The boundary after inflating; the triangle an inflating step turned interior.
pub const ORANGE: &str = "#e69f00";
/// Ground-truth edges missing from the result; the triangle a sculpting step removed.
pub const VERMILLION: &str = "#d55e00";
/// Result edges not in the ground truth; the boundary while it is inflated and sculpted.
pub const BLUE: &str = "#0072b2";
/// The ground truth drawn on its own.
pub const TRUTH: &str = "#6b6b6b";

/// Every colour by the role it plays, as the viewer and Python name them. Each step phase
/// ([`sigdt::Phase`] by name) has the colour of the triangle it changes: a pocket is filled as
/// inflating fills triangles; sculpting removes them.
pub const PALETTE: [(&str, &str); 16] = [
    ("ink", INK),
    ("fill", FILL),
    ("background", BACKGROUND),
    ("dt", GREY),
    ("sig", SKY),
    ("sigdt", GREEN),
    ("sigdt2", PURPLE),
    ("boundary", ORANGE),
    ("result", INK),
    ("truth", TRUTH),
    ("missing", VERMILLION),
    ("extra", BLUE),
    ("step_boundary", BLUE),
    ("inflate", ORANGE),
    ("pocket", SKY),
    ("sculpt", VERMILLION),
];

/// The colour of `role` in [`PALETTE`].
pub fn colour(role: &str) -> Option<&'static str> {
    PALETTE.iter().find(|(name, _)| *name == role).map(|&(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_phase_has_a_colour_and_roles_are_unique() {
        for phase in sigdt::Phase::ALL {
            assert!(colour(phase.name()).is_some(), "{}", phase.name());
        }
        let mut roles: Vec<_> = PALETTE.iter().map(|(r, _)| r).collect();
        roles.sort_unstable();
        roles.dedup();
        assert_eq!(roles.len(), PALETTE.len());
        for (_, c) in PALETTE {
            assert!(c.len() == 7 && c.starts_with('#'), "{c}");
            assert!(c[1..].bytes().all(|b| b.is_ascii_hexdigit() && !b.is_ascii_uppercase()));
        }
    }
}
