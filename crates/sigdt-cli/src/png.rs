//! Rasterising the SVG pictures of `sigdt_lab::render` to PNG with `resvg` (pure Rust).
//!
//! Text is drawn with the system's fonts, loaded once per call: the generic `sans-serif`
//! and `serif` families resolve to the first installed of DejaVu Sans, Liberation Sans,
//! Noto Sans, Arial and Helvetica, or else to any installed face. On a system without
//! fonts, text (titles, legend labels) is simply not drawn; the picture itself is.

use anyhow::{anyhow, Context};
use resvg::{tiny_skia, usvg};

/// Families tried, in order, for the generic font names.
const FAMILIES: &[&str] = &["DejaVu Sans", "Liberation Sans", "Noto Sans", "Arial", "Helvetica"];

/// The PNG image of the SVG document `svg`, at its own size (one pixel per user unit).
pub fn svg_to_png(svg: &str) -> anyhow::Result<Vec<u8>> {
    let mut options = usvg::Options::default();
    let fonts = options.fontdb_mut();
    fonts.load_system_fonts();
    let installed = |name: &str| {
        fonts.faces().any(|face| face.families.iter().any(|(family, _)| family == name))
    };
    let family =
        FAMILIES.iter().map(|s| s.to_string()).find(|name| installed(name)).or_else(|| {
            fonts.faces().next().and_then(|face| face.families.first().map(|(f, _)| f.clone()))
        });
    if let Some(family) = family {
        fonts.set_sans_serif_family(family.clone());
        fonts.set_serif_family(family);
    }
    let tree = usvg::Tree::from_str(svg, &options).context("cannot read the SVG picture")?;
    let size = tree.size().to_int_size();
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| anyhow!("cannot make a {}x{} image", size.width(), size.height()))?;
    resvg::render(&tree, tiny_skia::Transform::identity(), &mut pixmap.as_mut());
    pixmap.encode_png().context("cannot encode the PNG image")
}

#[cfg(test)]
mod tests {
    use super::*;
    use sigdt_lab::render::{render_svg, Layers, RenderOptions};

    #[test]
    fn a_square_renders_to_a_png_that_is_not_blank() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let edges = [[0, 1], [0, 3], [1, 2], [2, 3]];
        let layers = Layers { points: true, dt: Some(&edges), ..Layers::default() };
        let options = RenderOptions { width_px: 120, title: Some("a & b".into()), legend: true };
        let png = svg_to_png(&render_svg(&square, &layers, &options)).unwrap();
        assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
        let image = tiny_skia::Pixmap::decode_png(&png).unwrap();
        assert_eq!(image.width(), 120);
        let background = image.pixels()[0];
        let drawn = image.pixels().iter().filter(|&&p| p != background).count();
        assert!(drawn > 100, "{drawn} pixels differ from the background");
        assert!(svg_to_png("<svg").is_err());
    }
}
