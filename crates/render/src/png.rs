//! PNG pictures: the SVG view drawn by resvg/tiny-skia. Labels use the
//! built-in pixel font, so a PNG is the same on every machine.

use crate::drawing::TextMode;
use crate::svg::ViewOptions;
use crate::{RenderError, Scene};

/// The PNG picture of a scene with the default options.
pub fn render(scene: &Scene) -> Result<Vec<u8>, RenderError> {
    render_with(scene, &ViewOptions::default())
}

/// The PNG picture of a scene.
pub fn render_with(scene: &Scene, opts: &ViewOptions) -> Result<Vec<u8>, RenderError> {
    crate::bounds::check_cell_px(opts.cell_px)?;
    let svg = crate::view::view(scene, opts).to_svg(TextMode::Paths);
    svg_to_png(&svg)
}

/// Draws an SVG document (without text) to PNG bytes at its own size.
pub fn svg_to_png(svg: &str) -> Result<Vec<u8>, RenderError> {
    let tree = crate::bounds::parse_svg(svg)?;
    let pixmap = svg_to_pixmap(&tree, 1.0)?;
    pixmap
        .encode_png()
        .map_err(|e| RenderError::Draw(e.to_string()))
}

/// Draws a parsed SVG document scaled by `zoom` on a transparent pixmap, after
/// checking its size in pixels against [`crate::bounds::MAX_DRAWN_PIXELS`].
pub(crate) fn svg_to_pixmap(
    tree: &resvg::usvg::Tree,
    zoom: f32,
) -> Result<resvg::tiny_skia::Pixmap, RenderError> {
    // As tiny-skia's `to_int_size().scale_by(zoom)`, without its overflow.
    let side = |v: f32| (v.round().max(1.0) * zoom).round() as f64;
    let (w, h) = (side(tree.size().width()), side(tree.size().height()));
    if !(w.is_finite() && h.is_finite() && w >= 1.0 && h >= 1.0) {
        return Err(RenderError::Draw(format!(
            "the picture has no size ({w}x{h} pixels)"
        )));
    }
    let max = crate::bounds::MAX_DRAWN_PIXELS as f64;
    if w * h > max || w > max || h > max {
        return Err(RenderError::TooLarge(format!(
            "the picture would be {w:.0}x{h:.0} pixels; at most {} pixels are drawn",
            crate::bounds::MAX_DRAWN_PIXELS
        )));
    }
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w as u32, h as u32).ok_or_else(|| {
        RenderError::TooLarge(format!("the picture would be {w:.0}x{h:.0} pixels"))
    })?;
    resvg::render(
        tree,
        resvg::tiny_skia::Transform::from_scale(zoom, zoom),
        &mut pixmap.as_mut(),
    );
    Ok(pixmap)
}
