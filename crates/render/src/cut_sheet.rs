//! Cut sheets: every piece once, laid out apart on one SVG sheet in
//! millimetres, outlines only (hairline strokes for a laser cutter) and the
//! piece labels as text to engrave.

use crate::colour::Rgb;
use crate::drawing::{polygon_path, Anchor, Drawing, Item, TextMode, Unit};
use crate::stl::{offset_loops, PhysicalOptions};
use crate::{RenderError, Scene};

/// The cut line colour (red hairline, the usual "cut" colour).
pub const CUT: Rgb = Rgb(255, 0, 0);

/// Whether cut sheets are made for `lattice` (the 2D lattices).
pub fn supports(lattice: dissect_core::LatticeKind) -> bool {
    lattice.lattice().dim() == 2
}

/// The cut sheet of a 2D scene (pieces as they lie in the first figure,
/// shrunk by the clearance), at most `sheet_width_mm` wide.
pub fn drawing(
    scene: &Scene,
    opts: &PhysicalOptions,
    sheet_width_mm: f64,
) -> Result<Drawing, RenderError> {
    opts.check()?;
    if !supports(scene.lattice()) {
        return Err(RenderError::BadOption(
            "cut sheets are made for 2D lattices (square, tri4, tri3, hex); use --format stl or ldraw for cubic".into(),
        ));
    }
    let s = opts.cell_mm;
    let gap = (s / 2.0).max(3.0);
    let margin = 10.0;
    let mut items = Vec::new();
    let (mut x, mut y, mut row_h, mut width): (f64, f64, f64, f64) = (margin, margin, 0.0, 0.0);
    for i in 0..scene.piece_count() {
        let outline = scene.outline(0, i);
        let [lo, hi] = outline.bounds_f64().expect("pieces have cells");
        let (w, h) = ((hi[0] - lo[0]) * s, (hi[1] - lo[1]) * s);
        if x > margin && x + w > sheet_width_mm - margin {
            x = margin;
            y += row_h + gap;
            row_h = 0.0;
        }
        let (ox, oy) = (lo[0], lo[1]);
        let loops: Vec<Vec<[f64; 2]>> = offset_loops(&outline, opts.clearance_mm / s)
            .into_iter()
            .map(|l| {
                l.into_iter()
                    .map(|p| [x + (p[0] - ox) * s, y + (p[1] - oy) * s])
                    .collect()
            })
            .collect();
        items.push(Item::Path {
            d: polygon_path(&loops),
            fill: None,
            stroke: Some((CUT, 0.1)),
        });
        let c = scene.label_point(0, i);
        let size = (s * 0.5).min(12.0);
        items.push(Item::Text {
            x: x + (c[0] - ox) * s,
            y: y + (c[1] - oy) * s + 0.35 * size,
            size,
            anchor: Anchor::Middle,
            text: scene.label(i),
            fill: Rgb::BLACK,
        });
        x += w + gap;
        row_h = row_h.max(h);
        width = width.max(x - gap + margin);
    }
    let mut d = Drawing::new(width, y + row_h + margin, Unit::Mm, None);
    for it in items {
        d.push(it);
    }
    Ok(d)
}

/// The cut sheet as an SVG document (labels as `<text>`), at most 600 mm wide.
pub fn render(scene: &Scene, opts: &PhysicalOptions) -> Result<String, RenderError> {
    Ok(drawing(scene, opts, 600.0)?.to_svg(TextMode::Text))
}
