//! Pictures to figures. A picture (PNG or JPEG: dark or opaque pixels are
//! inside; SVG: filled shapes, drawn by resvg) or a stack of slice pictures
//! (one `cubic` z layer each) is sampled onto the lattice. Asked for an
//! exact cell count, it searches the scale (picture pixels per cell) and the
//! threshold (how much of a cell must be inside) that give exactly that
//! many cells with the fewest cells changed from a plain 50 % threshold;
//! where every scale's cut falls among equally covered cells (large
//! figures: few samples per cell), those are told apart by their
//! neighbours' coverage.
//!
//! `tri4` snaps every square to empty, full or a half square cut along a
//! diagonal (so outlines run along 45° edges), using a single or three
//! triangles only when the count is odd.

use dissect_core::io::format_figure;
use dissect_core::{Cell, Figure, LatticeKind};

use crate::RenderError;

/// What to make.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterOptions {
    /// The lattice of the figure.
    pub lattice: LatticeKind,
    /// The exact number of cells (triangles for `tri4`), or `None` for as
    /// many as the picture gives at `scale` and `threshold`.
    pub cells: Option<usize>,
    /// Picture pixels (SVG user units) per cell edge when `cells` is `None`.
    pub scale: f64,
    /// The inside fraction from which a cell is filled when `cells` is `None`.
    pub threshold: f64,
    /// Light pixels are inside instead of dark ones (pictures without transparency).
    pub invert: bool,
}

impl Default for RasterOptions {
    fn default() -> Self {
        RasterOptions {
            lattice: LatticeKind::Square,
            cells: None,
            scale: 10.0,
            threshold: 0.5,
            invert: false,
        }
    }
}

/// A figure made from a picture or a mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct Rasterized {
    /// The figure.
    pub figure: Figure,
    /// The figure in the text format.
    pub text: String,
    /// Picture pixels (or mesh units) per cell edge.
    pub scale: f64,
    /// The inside fraction from which a cell was filled.
    pub threshold: f64,
    /// Cells filled or emptied to hit the count, against a plain 50 %
    /// threshold at the same scale.
    pub changed: usize,
}

/// A grid of "ink" (how much a sample is inside, 0..=1): pictures have one
/// layer, slices and meshes several.
#[derive(Clone, Debug)]
pub(crate) struct Volume {
    pub w: usize,
    pub h: usize,
    pub d: usize,
    pub ink: Vec<f32>,
    /// Whether z is scaled like x and y (meshes) or one layer per z (slices).
    pub z_scaled: bool,
    /// Samples per unit of the input (an SVG is drawn enlarged).
    pub zoom: f64,
}

impl Volume {
    fn at(&self, x: f64, y: f64, z: f64) -> f32 {
        if x < 0.0 || y < 0.0 || z < 0.0 {
            return 0.0;
        }
        let (x, y, z) = (x as usize, y as usize, z as usize);
        if x >= self.w || y >= self.h || z >= self.d {
            return 0.0;
        }
        self.ink[(z * self.h + y) * self.w + x]
    }

    /// The box `[lo, hi)` of samples at least half inside, or `None`.
    fn ink_box(&self) -> Option<([usize; 3], [usize; 3])> {
        let mut lo = [usize::MAX; 3];
        let mut hi = [0; 3];
        for z in 0..self.d {
            for y in 0..self.h {
                for x in 0..self.w {
                    if self.ink[(z * self.h + y) * self.w + x] >= 0.5 {
                        for (k, v) in [x, y, z].into_iter().enumerate() {
                            lo[k] = lo[k].min(v);
                            hi[k] = hi[k].max(v + 1);
                        }
                    }
                }
            }
        }
        (lo[0] != usize::MAX).then_some((lo, hi))
    }
}

/// Decodes a picture into one layer of ink. Sizes are checked against
/// [`crate::bounds`] before the pixels are allocated.
fn decode(bytes: &[u8], invert: bool) -> Result<Volume, RenderError> {
    let head: Vec<u8> = bytes
        .iter()
        .copied()
        .skip_while(|b| b.is_ascii_whitespace() || *b == 0xEF || *b == 0xBB || *b == 0xBF)
        .take(1)
        .collect();
    let (w, h, rgba, zoom) = if head == b"<" {
        let text = std::str::from_utf8(bytes)
            .map_err(|_| RenderError::NotAPicture("SVG that is not UTF-8 text".into()))?;
        let tree = crate::bounds::parse_svg(text)?;
        let size = tree.size();
        // Drawn with its longer side 1024 pixels (at most 64 times enlarged).
        let zoom = (1024.0 / size.width().max(size.height())).min(64.0);
        let pm = crate::png::svg_to_pixmap(&tree, zoom)?;
        // Un-premultiply is not needed: only alpha and darkness are read.
        (
            pm.width() as usize,
            pm.height() as usize,
            pm.take(),
            zoom as f64,
        )
    } else {
        let not_a_picture = |e: &dyn std::fmt::Display| {
            RenderError::NotAPicture(format!("not a PNG, JPEG or SVG picture ({e})"))
        };
        let reader = || {
            image::ImageReader::new(std::io::Cursor::new(bytes))
                .with_guessed_format()
                .map_err(|e| not_a_picture(&e))
        };
        // The header's size first: a small file may claim a huge picture.
        let (pw, ph) = reader()?.into_dimensions().map_err(|e| not_a_picture(&e))?;
        crate::bounds::check_picture_size(pw as u64, ph as u64)?;
        let mut limits = image::Limits::default();
        limits.max_image_width = Some(crate::bounds::MAX_PICTURE_SIDE);
        limits.max_image_height = Some(crate::bounds::MAX_PICTURE_SIDE);
        limits.max_alloc = Some(crate::bounds::MAX_DECODE_BYTES);
        let mut r = reader()?;
        r.limits(limits);
        let img = r.decode().map_err(|e| match e {
            image::ImageError::Limits(l) => RenderError::TooLarge(format!(
                "decoding the picture would take more than {} MiB ({l})",
                crate::bounds::MAX_DECODE_BYTES >> 20
            )),
            e => not_a_picture(&e),
        })?;
        crate::bounds::check_picture_size(img.width() as u64, img.height() as u64)?;
        let img = img.into_rgba8();
        (
            img.width() as usize,
            img.height() as usize,
            img.into_raw(),
            1.0,
        )
    };
    if w == 0 || h == 0 {
        return Err(RenderError::EmptyPicture);
    }
    let transparent = rgba.chunks(4).any(|p| p[3] < 250);
    let ink = rgba
        .chunks(4)
        .map(|p| {
            let a = p[3] as f32 / 255.0;
            let v = if transparent {
                a
            } else {
                let lum =
                    (0.2126 * p[0] as f32 + 0.7152 * p[1] as f32 + 0.0722 * p[2] as f32) / 255.0;
                1.0 - lum
            };
            if invert {
                1.0 - v
            } else {
                v
            }
        })
        .collect();
    Ok(Volume {
        w,
        h,
        d: 1,
        ink,
        z_scaled: false,
        zoom,
    })
}

/// Turns pictures into a figure: one picture for `square`, `tri4`, `tri3`
/// and `hex`, one per z layer (bottom first) for `cubic`.
pub fn rasterize(pictures: &[&[u8]], opts: &RasterOptions) -> Result<Rasterized, RenderError> {
    if pictures.is_empty() {
        return Err(RenderError::BadOption("no picture given".into()));
    }
    check_cells(opts.cells)?;
    if opts.lattice != LatticeKind::Cubic && pictures.len() > 1 {
        return Err(RenderError::BadOption(format!(
            "{} pictures given: only --lattice cubic stacks several pictures (one per z layer)",
            pictures.len()
        )));
    }
    let mut layers = Vec::with_capacity(pictures.len());
    for b in pictures {
        layers.push(decode(b, opts.invert)?);
        let w = layers.iter().map(|l| l.w).max().unwrap_or(0) as u64;
        let h = layers.iter().map(|l| l.h).max().unwrap_or(0) as u64;
        if w * h * layers.len() as u64 > crate::bounds::MAX_PICTURE_PIXELS * 4 {
            return Err(RenderError::TooLarge(format!(
                "{} slices of up to {w}x{h} pixels: more than {} pixels in all",
                layers.len(),
                crate::bounds::MAX_PICTURE_PIXELS * 4
            )));
        }
    }
    let w = layers.iter().map(|l| l.w).max().unwrap_or(0);
    let h = layers.iter().map(|l| l.h).max().unwrap_or(0);
    let mut ink = vec![0.0f32; w * h * layers.len()];
    for (z, l) in layers.iter().enumerate() {
        for y in 0..l.h {
            for x in 0..l.w {
                ink[(z * h + y) * w + x] = l.ink[y * l.w + x];
            }
        }
    }
    // Slices are sampled in the first picture's units.
    let zoom = layers[0].zoom;
    let vol = Volume {
        w,
        h,
        d: layers.len(),
        ink,
        z_scaled: false,
        zoom,
    };
    let mut r = sample(
        &vol,
        opts.lattice,
        opts.cells,
        opts.scale * zoom,
        opts.threshold,
    )?;
    r.scale /= zoom;
    Ok(r)
}

/// The inside fraction of every cell at scale `s` with the grid's origin at
/// `origin`: `(cell, fraction)` for cells with some ink.
fn coverage(
    vol: &Volume,
    lattice: LatticeKind,
    origin: [f64; 3],
    s: f64,
    size: [usize; 3],
) -> Vec<(Cell, f64)> {
    if matches!(lattice, LatticeKind::Tri3 | LatticeKind::Hex) {
        return coverage_plane(vol, lattice, origin, s, size);
    }
    let m = 8usize;
    let mz = if vol.z_scaled { 4 } else { 1 };
    let mut out = Vec::new();
    for cz in 0..size[2] {
        for cy in 0..size[1] {
            for cx in 0..size[0] {
                let mut sum = [0.0f64; 4];
                let mut cnt = [0usize; 4];
                for a in 0..m {
                    for b in 0..m {
                        let u = (a as f64 + 0.5) / m as f64;
                        let v = (b as f64 + 0.5) / m as f64;
                        let px = origin[0] + (cx as f64 + u) * s;
                        let py = origin[1] + (cy as f64 + v) * s;
                        let t = if lattice == LatticeKind::Tri4 {
                            let (dx, dy) = (u - 0.5, v - 0.5);
                            if dy.abs() >= dx.abs() {
                                if dy < 0.0 {
                                    0
                                } else {
                                    2
                                }
                            } else if dx > 0.0 {
                                1
                            } else {
                                3
                            }
                        } else {
                            0
                        };
                        for c in 0..mz {
                            let pz = if vol.z_scaled {
                                origin[2] + (cz as f64 + (c as f64 + 0.5) / mz as f64) * s
                            } else {
                                cz as f64
                            };
                            sum[t] += vol.at(px, py, pz) as f64;
                            cnt[t] += 1;
                        }
                    }
                }
                let ts = if lattice == LatticeKind::Tri4 {
                    0..4
                } else {
                    0..1
                };
                for t in ts {
                    let f = sum[t] / cnt[t].max(1) as f64;
                    if f > 0.0 {
                        let cell = match lattice {
                            LatticeKind::Square | LatticeKind::Tri3 | LatticeKind::Hex => {
                                [cx as i32, cy as i32, 0]
                            }
                            LatticeKind::Tri4 => [cx as i32, cy as i32, t as i32],
                            LatticeKind::Cubic => [cx as i32, cy as i32, cz as i32],
                        };
                        out.push((cell, f));
                    }
                }
            }
        }
    }
    out
}

/// The coverage of `tri3` triangles or `hex` hexagons (side, or distance
/// between centres, `s` pixels) over a picture whose ink box starts at
/// `origin` and spans `size` squares of `s` pixels: every cell is sampled on
/// a 10×10 grid over its bounding box, keeping the samples inside it.
fn coverage_plane(
    vol: &Volume,
    lattice: LatticeKind,
    origin: [f64; 3],
    s: f64,
    size: [usize; 3],
) -> Vec<(Cell, f64)> {
    let h = 3f64.sqrt() / 2.0;
    let rows = (size[1] as f64 / h).ceil() as usize + 1;
    let (cols, off) = if lattice == LatticeKind::Tri3 {
        (2 * size[0] + 1, [0.0, 0.0])
    } else {
        // Hexagon (0, 0) reaches half a cell left of and 2h/3 above its centre.
        (size[0] + 1, [0.5, 2.0 * h / 3.0])
    };
    let unit = crate::outline::grid_unit(lattice);
    let m = 10usize;
    let mut out = Vec::new();
    for cy in 0..rows {
        for cx in 0..cols {
            let cell = [cx as i32, cy as i32, 0];
            let poly: Vec<[f64; 2]> = crate::outline::cell_polygon(lattice, cell)
                .iter()
                .map(|p| [p[0] as f64 * unit[0], p[1] as f64 * unit[1]])
                .collect();
            let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
            for p in &poly {
                for d in 0..2 {
                    lo[d] = lo[d].min(p[d]);
                    hi[d] = hi[d].max(p[d]);
                }
            }
            // Positive orientation: inside is left of no edge.
            let inside = |q: [f64; 2]| {
                (0..poly.len()).all(|k| {
                    let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
                    (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) >= 0.0
                })
            };
            let (mut sum, mut cnt) = (0.0f64, 0usize);
            for a in 0..m {
                for b in 0..m {
                    let q = [
                        lo[0] + (a as f64 + 0.5) / m as f64 * (hi[0] - lo[0]),
                        lo[1] + (b as f64 + 0.5) / m as f64 * (hi[1] - lo[1]),
                    ];
                    if inside(q) {
                        let px = origin[0] + (q[0] + off[0]) * s;
                        let py = origin[1] + (q[1] + off[1]) * s;
                        sum += vol.at(px, py, 0.0) as f64;
                        cnt += 1;
                    }
                }
            }
            let f = sum / cnt.max(1) as f64;
            if f > 0.0 {
                out.push((cell, f));
            }
        }
    }
    out
}

/// Cells chosen from coverages ([`Chosen`]): the `n` most covered, ties at
/// the cut broken by [`break_ties`].
fn choose(lattice: LatticeKind, cov: &[(Cell, f64)], n: Option<usize>, threshold: f64) -> Chosen {
    let plain: Vec<Cell> = cov.iter().filter(|c| c.1 >= 0.5).map(|c| c.0).collect();
    if lattice == LatticeKind::Tri4 {
        return snap_tri4(cov, n, threshold, &plain);
    }
    match n {
        None => {
            let cells: Vec<Cell> = cov
                .iter()
                .filter(|c| c.1 >= threshold)
                .map(|c| c.0)
                .collect();
            let changed = plain.len().abs_diff(cells.len());
            Ok((cells, threshold, changed, false))
        }
        Some(n) => {
            let mut v: Vec<&(Cell, f64)> = cov.iter().collect();
            v.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
            if n == 0 || n > v.len() {
                return Err(v.len());
            }
            let last_in = v[n - 1].1;
            let first_out = v.get(n).map_or(0.0, |c| c.1);
            if last_in <= first_out {
                // Cells of equal coverage on both sides of the cut (fine
                // samples are few per cell on large figures, so coverages
                // repeat): no threshold gives n cells, but the tied cells
                // can be told apart by how inked their neighbours are.
                if last_in <= 0.0 {
                    return Err(plain.len());
                }
                break_ties(lattice, cov, &mut v, last_in);
                let cells: Vec<Cell> = v[..n].iter().map(|c| c.0).collect();
                return Ok((cells, last_in, plain.len().abs_diff(n), true));
            }
            let t = if first_out < 0.5 && 0.5 <= last_in {
                0.5
            } else {
                (last_in + first_out) / 2.0
            };
            let cells: Vec<Cell> = v[..n].iter().map(|c| c.0).collect();
            Ok((cells, t, plain.len().abs_diff(n), false))
        }
    }
}

/// The `tri4` masks a square may take, with a penalty for the ragged ones.
const MASKS: [(u8, f64); 16] = [
    (0, 0.0),
    (15, 0.0),
    (3, 0.0),
    (6, 0.0),
    (12, 0.0),
    (9, 0.0),
    (1, 0.3),
    (2, 0.3),
    (4, 0.3),
    (8, 0.3),
    (7, 0.3),
    (11, 0.3),
    (13, 0.3),
    (14, 0.3),
    (5, 9.0),
    (10, 9.0),
];

fn snap_tri4(cov: &[(Cell, f64)], n: Option<usize>, threshold: f64, plain: &[Cell]) -> Chosen {
    use std::collections::BTreeMap;
    let mut squares: BTreeMap<[i32; 2], [f64; 4]> = BTreeMap::new();
    for &(c, f) in cov {
        squares.entry([c[0], c[1]]).or_default()[c[2] as usize] = f;
    }
    let keys: Vec<[i32; 2]> = squares.keys().copied().collect();
    let q: Vec<[f64; 4]> = squares.values().copied().collect();
    // Error of a mask: how far its triangles are from their coverage,
    // measured against the threshold.
    let err = |q: &[f64; 4], mask: u8, pen: f64| -> f64 {
        (0..4)
            .map(|t| {
                let on = mask >> t & 1 == 1;
                let d = q[t] - threshold;
                if on == (d >= 0.0) {
                    0.0
                } else {
                    d.abs()
                }
            })
            .sum::<f64>()
            + pen * 0.5
    };
    let mut state: Vec<(u8, f64)> = q
        .iter()
        .map(|qq| {
            MASKS[..6]
                .iter()
                .map(|&(m, p)| (m, err(qq, m, p)))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .expect("masks")
        })
        .collect();
    let count = |st: &[(u8, f64)]| st.iter().map(|s| s.0.count_ones() as usize).sum::<usize>();
    if let Some(n) = n {
        let mut c = count(&state);
        while c != n {
            let diff = n as i64 - c as i64;
            let mut best: Option<(f64, usize, u8, f64)> = None;
            for (k, qq) in q.iter().enumerate() {
                let cur = state[k];
                for &(m, p) in &MASKS[..14] {
                    // Ragged masks only to fix an odd count.
                    if p > 0.0 && diff % 2 == 0 {
                        continue;
                    }
                    let delta = m.count_ones() as i64 - cur.0.count_ones() as i64;
                    if delta == 0
                        || delta.signum() != diff.signum()
                        || delta.abs() > diff.abs()
                        || delta.abs() > 2
                    {
                        continue;
                    }
                    let e = err(qq, m, p);
                    let cost = (e - cur.1) / delta.abs() as f64;
                    if !matches!(best, Some(b) if cost >= b.0) {
                        best = Some((cost, k, m, e));
                    }
                }
            }
            let Some((_, k, m, e)) = best else {
                return Err(c);
            };
            state[k] = (m, e);
            c = count(&state);
        }
    }
    let mut cells = Vec::new();
    for (k, st) in state.iter().enumerate() {
        for t in 0..4 {
            if st.0 >> t & 1 == 1 {
                cells.push([keys[k][0], keys[k][1], t]);
            }
        }
    }
    let plain: std::collections::HashSet<Cell> = plain.iter().copied().collect();
    let chosen: std::collections::HashSet<Cell> = cells.iter().copied().collect();
    let changed = plain.symmetric_difference(&chosen).count();
    Ok((cells, threshold, changed, false))
}

/// How a pick at one scale ranks: `(tied, changed, scale step)`, least first.
type PickKey = (bool, usize, usize);

/// Scales tried for a plain threshold after ties broken by neighbours gave
/// the asked count with no cell changed from 50 %.
const TIED_SCALES: usize = 20;

/// Cells chosen at one scale: `(cells, threshold, changed, tied)` (`tied`:
/// cells of the threshold's coverage were told apart by their neighbours,
/// [`break_ties`]), or the count reached when the asked one cannot be met.
type Chosen = Result<(Vec<Cell>, f64, usize, bool), usize>;

/// Orders the cells of coverage `level` in `v` (sorted by coverage, most
/// first, so they are contiguous) by the coverage of their neighbours,
/// most first, then by cell: of two equally covered cells, the one
/// deeper in the ink is filled first, so the boundary stays smooth
/// instead of following the cells' order.
fn break_ties(lattice: LatticeKind, cov: &[(Cell, f64)], v: &mut [&(Cell, f64)], level: f64) {
    let of: std::collections::HashMap<Cell, f64> = cov.iter().copied().collect();
    let lat = lattice.lattice();
    let around = |c: Cell| -> f64 {
        lat.neighbors(c)
            .into_iter()
            .map(|nb| of.get(&nb).copied().unwrap_or(0.0))
            .sum()
    };
    let lo = v.partition_point(|c| c.1 > level);
    let hi = v.partition_point(|c| c.1 >= level);
    let mut keyed: Vec<(f64, &(Cell, f64))> = v[lo..hi].iter().map(|c| (around(c.0), *c)).collect();
    keyed.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1 .0.cmp(&b.1 .0)));
    for (slot, (_, c)) in v[lo..hi].iter_mut().zip(keyed) {
        *slot = c;
    }
}

/// Fails unless an asked cell count is from 1 to [`crate::bounds::MAX_GRID_CELLS`].
pub(crate) fn check_cells(n: Option<usize>) -> Result<(), RenderError> {
    match n {
        Some(0) => Err(RenderError::BadOption("--cells must be at least 1".into())),
        Some(n) if n as u64 > crate::bounds::MAX_GRID_CELLS => {
            Err(RenderError::BadOption(format!(
                "--cells must be at most {}, got {n}",
                crate::bounds::MAX_GRID_CELLS
            )))
        }
        _ => Ok(()),
    }
}

/// Samples a volume at a fixed scale, or searches the scale for an exact count.
pub(crate) fn sample(
    vol: &Volume,
    lattice: LatticeKind,
    n: Option<usize>,
    scale: f64,
    threshold: f64,
) -> Result<Rasterized, RenderError> {
    let (lo, hi) = vol.ink_box().ok_or(RenderError::EmptyPicture)?;
    if !(threshold > 0.0 && threshold <= 1.0) {
        return Err(RenderError::BadOption(format!(
            "--threshold must be in (0, 1], got {threshold}"
        )));
    }
    let origin = [
        lo[0] as f64,
        lo[1] as f64,
        if vol.z_scaled { lo[2] as f64 } else { 0.0 },
    ];
    let span = |s: f64, k: usize| ((hi[k] - lo[k]) as f64 / s).ceil() + 1.0;
    let dims = |s: f64| {
        [
            span(s, 0),
            span(s, 1),
            if vol.z_scaled {
                span(s, 2)
            } else {
                vol.d as f64
            },
        ]
    };
    // The grid is bounded before it is sampled (a tiny scale would make it
    // endless).
    let run = |s: f64| -> Result<Chosen, RenderError> {
        let d = dims(s);
        crate::bounds::check_grid(d, "use a larger scale or fewer cells")?;
        let size = d.map(|v| v as usize);
        let cov = coverage(vol, lattice, origin, s, size);
        Ok(choose(lattice, &cov, n, threshold))
    };
    let finish =
        |cells: Vec<Cell>, s: f64, t: f64, changed: usize| -> Result<Rasterized, RenderError> {
            let figure = Figure::new(lattice, cells).map_err(|_| RenderError::EmptyPicture)?;
            let text = format_figure(&figure);
            Ok(Rasterized {
                figure,
                text,
                scale: s,
                threshold: t,
                changed,
            })
        };
    let Some(n) = n else {
        if !(scale.is_finite() && scale > 0.0) {
            return Err(RenderError::BadOption(format!(
                "--scale must be > 0, got {scale}"
            )));
        }
        let (cells, t, changed, _) = run(scale)?.map_err(|_| RenderError::EmptyPicture)?;
        return finish(cells, scale, t, changed);
    };
    check_cells(Some(n))?;
    // The scale at which the ink's area is n cells.
    // The area of a cell, in squares of the cell's edge (or centre distance).
    let cell_area = match lattice {
        LatticeKind::Tri4 => 0.25,
        LatticeKind::Tri3 => 3f64.sqrt() / 4.0,
        LatticeKind::Hex => 3f64.sqrt() / 2.0,
        LatticeKind::Square | LatticeKind::Cubic => 1.0,
    };
    let total: f64 = vol.ink.iter().map(|v| *v as f64).sum();
    let dims = if vol.z_scaled { 3.0 } else { 2.0 };
    let s0 = (total / (n as f64 * cell_area)).powf(1.0 / dims);
    // Cells much smaller than a sample carry no information.
    let finest = if vol.z_scaled { 1.0 } else { 0.5 };
    if s0 < finest {
        let nearest = run(finest)?.map_or_else(|c| c, |(cells, ..)| cells.len());
        return Err(RenderError::Unreachable { asked: n, nearest });
    }
    // The best pick so far: a threshold that gives n cells is preferred to
    // ties broken by neighbours ([`break_ties`]), then the fewest cells
    // changed from 50 %, then the scale nearest s0.
    let mut best: Option<(PickKey, Vec<Cell>, f64, f64)> = None;
    let mut nearest: Option<usize> = None;
    for k in 0..=120usize {
        // 0, +1, -1, +2, -2 ... steps of 0.5 %.
        let step = k.div_ceil(2) as f64 * if k % 2 == 1 { 1.0 } else { -1.0 };
        let s = s0 * (1.0 + 0.005 * step);
        if s <= 0.0 {
            continue;
        }
        match run(s)? {
            Ok((cells, t, changed, tied)) => {
                let key = (tied, changed, k);
                if !matches!(&best, Some(b) if key >= b.0) {
                    best = Some((key, cells, s, t));
                }
                // Ties broken at the nearest scales are as good as any
                // further away; a plain threshold is looked for a while.
                if changed == 0 && (!tied || k >= TIED_SCALES) {
                    break;
                }
            }
            Err(reached) => {
                if !matches!(nearest, Some(m) if reached.abs_diff(n) >= m.abs_diff(n)) {
                    nearest = Some(reached);
                }
            }
        }
    }
    match best {
        Some(((_, changed, _), cells, s, t)) => finish(cells, s, t, changed),
        None => Err(RenderError::Unreachable {
            asked: n,
            nearest: nearest.unwrap_or(0),
        }),
    }
}
