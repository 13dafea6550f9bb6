//! SVG pictures of a scene: every figure assembled from its pieces in
//! distinct colours, with labels and a legend.

pub use crate::view::ViewOptions;

use crate::drawing::{Drawing, TextMode};
use crate::Scene;

/// The drawing behind [`render`] (for callers that want other text modes).
pub fn drawing(scene: &Scene, opts: &ViewOptions) -> Drawing {
    crate::view::view(scene, opts)
}

/// The SVG picture of a scene with the default options.
pub fn render(scene: &Scene) -> String {
    render_with(scene, &ViewOptions::default())
}

/// The SVG picture of a scene.
pub fn render_with(scene: &Scene, opts: &ViewOptions) -> String {
    drawing(scene, opts).to_svg(TextMode::Text)
}
