//! Views of a scene as drawings in pixels: every figure assembled from its
//! coloured pieces, plus a legend. 2D lattices are drawn flat, with one
//! merged outline per piece; `cubic` figures in isometric view, assembled
//! and exploded.

use std::collections::HashSet;

use dissect_core::{Cell, LatticeKind};

use crate::colour::Rgb;
use crate::drawing::{polygon_path, Anchor, Drawing, Item, Unit};
use crate::outline::Outline;
use crate::Scene;

const MARGIN: f64 = 20.0;
const TITLE: f64 = 30.0;
const LEGEND_ITEM: f64 = 96.0;
const LEGEND_ROW: f64 = 24.0;

/// How a view is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewOptions {
    /// Pixels per cell edge (default: chosen from the figures' size).
    pub cell_px: Option<f64>,
    /// Write piece labels on the pieces.
    pub labels: bool,
    /// Draw the legend (label, colour, cell count of every piece).
    pub legend: bool,
}

impl Default for ViewOptions {
    fn default() -> Self {
        ViewOptions {
            cell_px: None,
            labels: true,
            legend: true,
        }
    }
}

/// The picture of a scene.
pub fn view(scene: &Scene, opts: &ViewOptions) -> Drawing {
    let (width, height, mut items) = match scene.lattice() {
        LatticeKind::Cubic => iso_figures(scene, opts),
        _ => flat_figures(scene, opts),
    };
    let mut width = width;
    let mut height = height;
    if opts.legend {
        let n = scene.piece_count();
        width = width.max(2.0 * MARGIN + LEGEND_ITEM * n.min(4) as f64);
        let cols = (((width - 2.0 * MARGIN) / LEGEND_ITEM).floor() as usize).max(1);
        for i in 0..n {
            let x = MARGIN + (i % cols) as f64 * LEGEND_ITEM;
            let y = height + (i / cols) as f64 * LEGEND_ROW;
            items.push(Item::Path {
                d: format!("M{x} {y}h16v16h-16Z"),
                fill: Some(scene.colour(i)),
                stroke: Some((Rgb::INK, 1.0)),
            });
            items.push(Item::Text {
                x: x + 22.0,
                y: y + 13.0,
                size: 14.0,
                anchor: Anchor::Start,
                text: format!("{} {}", scene.label(i), scene.area(i)),
                fill: Rgb::INK,
            });
        }
        height += n.div_ceil(cols) as f64 * LEGEND_ROW + MARGIN / 2.0;
    }
    let mut d = Drawing::new(width, height, Unit::Px, Some(Rgb::WHITE));
    for it in items {
        d.push(it);
    }
    d
}

fn title(x: f64, y: f64, text: &str) -> Item {
    Item::Text {
        x,
        y,
        size: 16.0,
        anchor: Anchor::Start,
        text: text.to_string(),
        fill: Rgb::INK,
    }
}

/// Loops of an outline in pixels: plane points mapped by `(p - lo) * s + at`.
fn place(o: &Outline, lo: [f64; 2], s: f64, at: [f64; 2]) -> Vec<Vec<[f64; 2]>> {
    o.loops()
        .iter()
        .map(|l| {
            l.points_f64()
                .iter()
                .map(|p| [at[0] + (p[0] - lo[0]) * s, at[1] + (p[1] - lo[1]) * s])
                .collect()
        })
        .collect()
}

/// The figures' bounds in lattice units (2D lattices).
fn flat_bounds(scene: &Scene) -> Vec<[[f64; 2]; 2]> {
    (0..scene.figure_count())
        .map(|f| {
            scene
                .figure_outline(f)
                .bounds_f64()
                .expect("figures have cells")
        })
        .collect()
}

/// Pixels per cell edge: `opts.cell_px`, or chosen from the largest figure.
pub(crate) fn chosen_cell_px(scene: &Scene, opts: &ViewOptions) -> f64 {
    if let Some(s) = opts.cell_px {
        return s;
    }
    if scene.lattice() != LatticeKind::Cubic {
        let extent = flat_bounds(scene)
            .iter()
            .map(|[lo, hi]| (hi[0] - lo[0]).max(hi[1] - lo[1]).floor())
            .fold(1.0, f64::max);
        return (360.0 / extent).round().clamp(8.0, 40.0);
    }
    let extent = (0..scene.figure_count())
        .map(|f| {
            let all: Vec<Cell> = (0..scene.piece_count())
                .flat_map(|i| scene.cells(f, i).iter().copied())
                .collect();
            let span = |d: usize| {
                let lo = all.iter().map(|c| c[d]).min().unwrap_or(0);
                let hi = all.iter().map(|c| c[d]).max().unwrap_or(0);
                (hi - lo + 1) as f64
            };
            span(0) + span(1) + span(2)
        })
        .fold(1.0, f64::max);
    (300.0 / extent).round().clamp(6.0, 36.0)
}

fn flat_figures(scene: &Scene, opts: &ViewOptions) -> (f64, f64, Vec<Item>) {
    let bounds = flat_bounds(scene);
    let s = chosen_cell_px(scene, opts);
    let stroke = (s / 14.0).clamp(1.0, 2.5);
    let gap = (2.0 * s).max(40.0);
    let mut items = Vec::new();
    let mut x = MARGIN;
    let mut max_h: f64 = 0.0;
    for (f, [lo, hi]) in bounds.iter().enumerate() {
        let at = [x, MARGIN + TITLE];
        items.push(title(x, MARGIN + 16.0, scene.name(f)));
        for i in 0..scene.piece_count() {
            items.push(Item::Path {
                d: polygon_path(&place(&scene.outline(f, i), *lo, s, at)),
                fill: Some(scene.colour(i)),
                stroke: Some((Rgb::INK, stroke)),
            });
        }
        items.push(Item::Path {
            d: polygon_path(&place(&scene.figure_outline(f), *lo, s, at)),
            fill: None,
            stroke: Some((Rgb::INK, 2.0 * stroke)),
        });
        if opts.labels && s >= 10.0 {
            let size = (s * 0.6).min(22.0);
            for i in 0..scene.piece_count() {
                let c = scene.label_point(f, i);
                items.push(Item::Text {
                    x: at[0] + (c[0] - lo[0]) * s,
                    y: at[1] + (c[1] - lo[1]) * s + 0.35 * size,
                    size,
                    anchor: Anchor::Middle,
                    text: scene.label(i),
                    fill: Rgb::INK,
                });
            }
        }
        let w = (hi[0] - lo[0]) * s;
        let h = (hi[1] - lo[1]) * s;
        max_h = max_h.max(h);
        x += w.max(120.0) + gap;
    }
    let width = x - gap + MARGIN;
    (width, MARGIN + TITLE + max_h + MARGIN, items)
}

/// A label at a point on screen.
type Label = ([f64; 2], String);

/// One cube face to paint: its corners on screen, colour and depth.
struct Face {
    depth: f64,
    order: u8,
    corners: [[f64; 2]; 4],
    fill: Rgb,
}

/// The visible faces (+x, +y, +z) of cubes offset by `off`, skipping faces
/// whose neighbour is in `solid`; projected with edge `s`.
fn cube_faces(
    cells: &[Cell],
    solid: &HashSet<Cell>,
    off: [f64; 3],
    colour: Rgb,
    s: f64,
) -> Vec<Face> {
    let (a, b) = (s * 0.866_025_403_8, s * 0.5);
    let project = |p: [f64; 3]| [(p[0] - p[1]) * a, (p[0] + p[1]) * b - p[2] * s];
    let mut out = Vec::new();
    for &[x, y, z] in cells {
        let (fx, fy, fz) = (x as f64 + off[0], y as f64 + off[1], z as f64 + off[2]);
        let depth = fx + fy + fz;
        let faces: [([i32; 3], [[f64; 3]; 4], f64); 3] = [
            (
                [x + 1, y, z],
                [[1., 0., 0.], [1., 1., 0.], [1., 1., 1.], [1., 0., 1.]],
                0.82,
            ),
            (
                [x, y + 1, z],
                [[0., 1., 0.], [1., 1., 0.], [1., 1., 1.], [0., 1., 1.]],
                0.66,
            ),
            (
                [x, y, z + 1],
                [[0., 0., 1.], [1., 0., 1.], [1., 1., 1.], [0., 1., 1.]],
                1.0,
            ),
        ];
        for (order, (n, quad, shade)) in faces.into_iter().enumerate() {
            if solid.contains(&n) {
                continue;
            }
            let corners = quad.map(|q| project([fx + q[0], fy + q[1], fz + q[2]]));
            out.push(Face {
                depth,
                order: order as u8,
                corners,
                fill: colour.shade(shade),
            });
        }
    }
    out
}

fn iso_figures(scene: &Scene, opts: &ViewOptions) -> (f64, f64, Vec<Item>) {
    let s = chosen_cell_px(scene, opts);
    let stroke = (s / 24.0).clamp(0.5, 1.2);
    let mut items = Vec::new();
    let mut y = MARGIN;
    let mut width: f64 = 0.0;
    for f in 0..scene.figure_count() {
        let all: Vec<Cell> = (0..scene.piece_count())
            .flat_map(|i| scene.cells(f, i).iter().copied())
            .collect();
        let solid: HashSet<Cell> = all.iter().copied().collect();
        let centroid = mean(&all);
        // Panel 0: assembled. Panel 1: exploded.
        let mut panels: Vec<(Vec<Face>, Vec<Label>)> = Vec::new();
        for exploded in [false, true] {
            let mut faces = Vec::new();
            let mut labels = Vec::new();
            for i in 0..scene.piece_count() {
                let cells = scene.cells(f, i);
                let (off, own): ([f64; 3], HashSet<Cell>) = if exploded {
                    let c = mean(cells);
                    let k = 0.9;
                    (
                        [
                            (c[0] - centroid[0]) * k,
                            (c[1] - centroid[1]) * k,
                            (c[2] - centroid[2]) * k,
                        ],
                        cells.iter().copied().collect(),
                    )
                } else {
                    ([0.0; 3], solid.clone())
                };
                faces.extend(cube_faces(cells, &own, off, scene.colour(i), s));
                if exploded {
                    let top = cells
                        .iter()
                        .max_by_key(|c| (c[2], c[0] + c[1], std::cmp::Reverse(**c)))
                        .expect("pieces have cells");
                    let p = [
                        top[0] as f64 + 0.5 + off[0],
                        top[1] as f64 + 0.5 + off[1],
                        top[2] as f64 + 1.0 + off[2],
                    ];
                    let (a, b) = (s * 0.866_025_403_8, s * 0.5);
                    labels.push((
                        [(p[0] - p[1]) * a, (p[0] + p[1]) * b - p[2] * s],
                        scene.label(i),
                    ));
                }
            }
            faces.sort_by(|p, q| p.depth.total_cmp(&q.depth).then(p.order.cmp(&q.order)));
            panels.push((faces, labels));
        }
        items.push(title(MARGIN, y + 16.0, scene.name(f)));
        let top = y + TITLE;
        let mut x = MARGIN;
        let mut row_h: f64 = 0.0;
        for (faces, labels) in panels {
            let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
            for face in &faces {
                for c in face.corners {
                    lo = [lo[0].min(c[0]), lo[1].min(c[1])];
                    hi = [hi[0].max(c[0]), hi[1].max(c[1])];
                }
            }
            let shift = [x - lo[0], top - lo[1]];
            for face in &faces {
                let pts: Vec<[f64; 2]> = face
                    .corners
                    .iter()
                    .map(|c| [c[0] + shift[0], c[1] + shift[1]])
                    .collect();
                items.push(Item::Path {
                    d: polygon_path(&[pts]),
                    fill: Some(face.fill),
                    stroke: Some((Rgb::INK, stroke)),
                });
            }
            if opts.labels && s >= 10.0 {
                let size = (s * 0.6).min(20.0);
                for (p, text) in labels {
                    items.push(Item::Text {
                        x: p[0] + shift[0],
                        y: p[1] + shift[1] + 0.35 * size,
                        size,
                        anchor: Anchor::Middle,
                        text,
                        fill: Rgb::INK,
                    });
                }
            }
            x += (hi[0] - lo[0]) + (2.0 * s).max(40.0);
            row_h = row_h.max(hi[1] - lo[1]);
        }
        width = width.max(x - (2.0 * s).max(40.0) + MARGIN);
        y = top + row_h + MARGIN;
    }
    (width, y, items)
}

fn mean(cells: &[Cell]) -> [f64; 3] {
    let n = cells.len().max(1) as f64;
    let mut m = [0.0; 3];
    for c in cells {
        for d in 0..3 {
            m[d] += c[d] as f64 / n;
        }
    }
    m
}
