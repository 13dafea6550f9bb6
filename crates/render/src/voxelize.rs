//! Meshes to figures: a closed triangle mesh (binary or ASCII STL) becomes a
//! `cubic` figure. The mesh is sampled once on a fine grid (inside/outside by
//! counting crossings along vertical rays), then sampled onto cubes like a
//! stack of slice pictures, searching the scale for an exact cube count.
//!
//! Axes: the mesh's x is the figure's x, its z the figure's z layers, and
//! its y runs against the figure's rows (rows run toward the viewer).

use dissect_core::LatticeKind;

use crate::mesh::Mesh;
use crate::rasterize::{sample, Rasterized, Volume};
use crate::RenderError;

/// The most ray and triangle pairs tested (and crossings kept).
const MAX_CROSSINGS: usize = 1 << 25;

/// What to make.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct VoxelOptions {
    /// The exact number of cubes, or `None` for as many as `scale` gives.
    pub cells: Option<usize>,
    /// Mesh units per cube edge when `cells` is `None` (default: a tenth of
    /// the longest side).
    pub scale: Option<f64>,
}

/// Turns a closed STL mesh into a `cubic` figure.
pub fn voxelize(stl: &[u8], opts: &VoxelOptions) -> Result<Rasterized, RenderError> {
    crate::rasterize::check_cells(opts.cells)?;
    let mesh = Mesh::from_stl(stl)?;
    let open = mesh.open_edges();
    if open > 0 {
        return Err(RenderError::OpenMesh(open));
    }
    let tris = mesh.triangles();
    let mut lo = [f64::MAX; 3];
    let mut hi = [f64::MIN; 3];
    for p in tris.iter().flatten() {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let size = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
    let longest = size.iter().copied().fold(0.0, f64::max);
    if longest.is_nan() || longest <= 0.0 || size.iter().any(|v| *v <= 0.0) {
        return Err(RenderError::BadMesh(
            "the mesh is flat (it encloses no volume)".into(),
        ));
    }
    // Fine grid: about 12 samples per cube edge.
    let cubes_long = match (opts.cells, opts.scale) {
        (Some(n), _) => {
            let vol = size[0] * size[1] * size[2];
            longest / (vol / n as f64).cbrt()
        }
        (None, Some(s)) if s.is_finite() && s > 0.0 => longest / s,
        (None, Some(s)) => {
            return Err(RenderError::BadOption(format!(
                "--scale must be > 0, got {s}"
            )));
        }
        (None, None) => 10.0,
    };
    let res = (cubes_long * 12.0).ceil().clamp(24.0, 240.0);
    let h = longest / res;
    let dims = size.map(|v| ((v / h).ceil() as usize).max(1));
    let (w, hh, d) = (dims[0], dims[1], dims[2]);
    let mut ink = vec![0.0f32; w * hh * d];
    // Crossings of the vertical ray through every column, from triangles.
    let mut columns: Vec<Vec<f64>> = vec![Vec::new(); w * hh];
    let (ex, ey) = (1.37e-4 * h, 2.91e-4 * h);
    // Every crossing is kept: a mesh of many large overlapping triangles
    // could otherwise fill the memory.
    let mut crossings = 0usize;
    for t in tris {
        let (x0, x1) = (
            t.iter().map(|p| p[0]).fold(f64::MAX, f64::min),
            t.iter().map(|p| p[0]).fold(f64::MIN, f64::max),
        );
        let (y0, y1) = (
            t.iter().map(|p| p[1]).fold(f64::MAX, f64::min),
            t.iter().map(|p| p[1]).fold(f64::MIN, f64::max),
        );
        let i0 = (((x0 - lo[0]) / h - 0.5).floor().max(0.0)) as usize;
        let i1 = ((((x1 - lo[0]) / h - 0.5).ceil()) as usize).min(w - 1);
        let j0 = (((y0 - lo[1]) / h - 0.5).floor().max(0.0)) as usize;
        let j1 = ((((y1 - lo[1]) / h - 0.5).ceil()) as usize).min(hh - 1);
        let [a, b, c] = *t;
        let den = (b[1] - c[1]) * (a[0] - c[0]) + (c[0] - b[0]) * (a[1] - c[1]);
        if den == 0.0 {
            continue;
        }
        crossings += (i1 + 1).saturating_sub(i0) * (j1 + 1).saturating_sub(j0);
        if crossings > MAX_CROSSINGS {
            return Err(RenderError::TooLarge(format!(
                "the mesh's triangles cover its sampling grid more than {MAX_CROSSINGS} times"
            )));
        }
        for i in i0..=i1 {
            for j in j0..=j1 {
                let px = lo[0] + (i as f64 + 0.5) * h + ex;
                let py = lo[1] + (j as f64 + 0.5) * h + ey;
                let l1 = ((b[1] - c[1]) * (px - c[0]) + (c[0] - b[0]) * (py - c[1])) / den;
                let l2 = ((c[1] - a[1]) * (px - c[0]) + (a[0] - c[0]) * (py - c[1])) / den;
                let l3 = 1.0 - l1 - l2;
                if l1 >= 0.0 && l2 >= 0.0 && l3 >= 0.0 {
                    columns[j * w + i].push(l1 * a[2] + l2 * b[2] + l3 * c[2]);
                }
            }
        }
    }
    for (k, col) in columns.iter_mut().enumerate() {
        if col.len() % 2 == 1 {
            // A ray grazing the surface: leave the column empty.
            continue;
        }
        col.sort_by(|p, q| p.total_cmp(q));
        let (i, j) = (k % w, k / w);
        // Figure rows run against the mesh's y.
        let row = hh - 1 - j;
        for pair in col.chunks(2) {
            let z0 = ((pair[0] - lo[2]) / h - 0.5).ceil().max(0.0) as usize;
            let z1 = ((pair[1] - lo[2]) / h - 0.5).floor();
            if z1 < 0.0 {
                continue;
            }
            for z in z0..=(z1 as usize).min(d - 1) {
                ink[(z * hh + row) * w + i] = 1.0;
            }
        }
    }
    let vol = Volume {
        w,
        h: hh,
        d,
        ink,
        z_scaled: true,
        zoom: 1.0,
    };
    let scale_fine = opts.scale.map_or(res / 10.0, |s| s / h);
    let mut r = sample(&vol, LatticeKind::Cubic, opts.cells, scale_fine, 0.5)?;
    r.scale *= h;
    Ok(r)
}
