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
    let svg = crate::view::view(scene, opts).to_svg(TextMode::Paths);
    svg_to_png(&svg)
}

/// Draws an SVG document (without text) to PNG bytes at its own size.
pub fn svg_to_png(svg: &str) -> Result<Vec<u8>, RenderError> {
    let pixmap = svg_to_pixmap(svg, 1.0)?;
    pixmap
        .encode_png()
        .map_err(|e| RenderError::Draw(e.to_string()))
}

/// Draws an SVG document scaled by `zoom` on a transparent pixmap.
pub(crate) fn svg_to_pixmap(svg: &str, zoom: f32) -> Result<resvg::tiny_skia::Pixmap, RenderError> {
    let tree = resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default())
        .map_err(|e| RenderError::NotAPicture(format!("SVG: {e}")))?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(zoom)
        .ok_or_else(|| RenderError::Draw("the picture has no size".into()))?;
    let mut pixmap =
        resvg::tiny_skia::Pixmap::new(size.width(), size.height()).ok_or_else(|| {
            RenderError::Draw(format!(
                "picture too large: {}x{}",
                size.width(),
                size.height()
            ))
        })?;
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(zoom, zoom),
        &mut pixmap.as_mut(),
    );
    Ok(pixmap)
}
