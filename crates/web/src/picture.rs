//! Pictures to figures: `POST /api/rasterize?lattice=..&cells=..` with the
//! picture's bytes (PNG, JPEG or SVG) as the body; `dissect-render`
//! rasterizes it to exactly `cells` cells.

use dissect_render::rasterize::{rasterize, RasterOptions};
use dissect_render::RenderError;
use serde::Deserialize;
use serde_json::{json, Value};

use crate::error::ApiError;
use crate::figures;
use crate::limits::Limits;

/// The query of a rasterize request.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RasterQuery {
    /// The lattice (`cubic`: the picture becomes one layer).
    pub lattice: String,
    /// The exact number of cells.
    pub cells: usize,
    /// Light pixels are inside instead of dark ones.
    #[serde(default)]
    pub invert: bool,
    /// The figure's name in the answer.
    #[serde(default)]
    pub name: Option<String>,
}

/// Rasterizes `picture`; answers like `POST /api/figures` for one figure,
/// plus `changed` (cells changed to hit the count), `scale` and `threshold`.
pub fn rasterize_picture(
    q: &RasterQuery,
    picture: &[u8],
    limits: &Limits,
) -> Result<Value, ApiError> {
    let lattice = figures::lattice(&q.lattice)?;
    if q.cells == 0 {
        return Err(ApiError::BadValue("cells must be at least 1".into()));
    }
    if q.cells > limits.max_cells() {
        return Err(ApiError::TooLarge(format!(
            "cells must be from 1 to {}, got {}",
            limits.max_cells(),
            q.cells
        )));
    }
    if picture.is_empty() {
        return Err(ApiError::BadValue(
            "the request body is empty; send the picture's bytes".into(),
        ));
    }
    let opts = RasterOptions {
        lattice,
        cells: Some(q.cells),
        invert: q.invert,
        ..RasterOptions::default()
    };
    let name = q.name.clone().unwrap_or_else(|| "picture.txt".into());
    let r = rasterize(&[picture], &opts).map_err(|e| match e {
        RenderError::BadOption(m) => ApiError::BadValue(format!("{name}: {m}")),
        RenderError::TooLarge(m) => ApiError::TooLarge(format!("{name}: {m}")),
        other => ApiError::BadFigure(format!("{name}: {other}")),
    })?;
    let figure = figures::normalized(&r.figure);
    let ext = limits.max_extent();
    if figure
        .cells()
        .iter()
        .any(|c| c[0] > ext || c[1] > ext || c[2] > ext)
    {
        return Err(ApiError::TooLarge(format!(
            "{name}: the figure is wider than {ext} cells; ask for fewer cells"
        )));
    }
    let mut v = figures::describe(&name, &figure);
    v["changed"] = json!(r.changed);
    v["scale"] = json!(r.scale);
    v["threshold"] = json!(r.threshold);
    Ok(v)
}
