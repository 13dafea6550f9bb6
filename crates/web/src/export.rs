//! Downloads made by `dissect-render` from a solution: SVG and PNG views, a
//! laser cut sheet (SVG, 2D lattices), STL meshes of the pieces (a ZIP with
//! one file per piece) and LDraw LEGO models (a ZIP with one `.ldr` per
//! figure; square and cubic lattices), the self-contained HTML page with the
//! pieces' motion, and the motion player's data (`animation`, JSON).
//!
//! `POST /api/export/{format}` with `{"solution": <solution JSON object or
//! text>, "cell_mm": .., "thickness_mm": .., "clearance_mm": .., "parts":
//! "plate"|"brick"}`.

use std::io::Write;

use dissect_core::io::parse_solution;
use dissect_core::Dissection;
use dissect_render::ldraw::PartKind;
use dissect_render::stl::PhysicalOptions;
use dissect_render::{RenderError, Scene};
use serde::Deserialize;
use serde_json::Value;

use crate::error::ApiError;
use crate::limits::Limits;

/// The body of an export request.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExportRequest {
    /// The solution: the JSON object of a `dissection-solution/1` file, or its text.
    pub solution: Value,
    /// The edge of a cell, mm (STL, cut sheet).
    #[serde(default)]
    pub cell_mm: Option<f64>,
    /// The height of an extruded 2D piece, mm (STL).
    #[serde(default)]
    pub thickness_mm: Option<f64>,
    /// How much every piece shrinks on each side, mm (STL, cut sheet).
    #[serde(default)]
    pub clearance_mm: Option<f64>,
    /// LDraw parts for 2D figures: `plate` (default) or `brick`.
    #[serde(default)]
    pub parts: Option<String>,
}

/// A file to download.
pub struct Download {
    /// Its name.
    pub name: String,
    /// Its MIME type.
    pub content_type: &'static str,
    /// Its bytes.
    pub bytes: Vec<u8>,
}

/// The formats `POST /api/export/{format}` knows.
pub const FORMATS: &[&str] = &[
    "svg",
    "png",
    "cut-sheet",
    "stl",
    "ldraw",
    "html",
    "animation",
];

/// The formats of [`FORMATS`] made for `lattice` (no cut sheet in 3D, LDraw
/// only where LEGO has the part).
pub fn formats_for(lattice: dissect_core::LatticeKind) -> Vec<&'static str> {
    FORMATS
        .iter()
        .copied()
        .filter(|f| match *f {
            "cut-sheet" => dissect_render::cut_sheet::supports(lattice),
            "ldraw" => dissect_render::ldraw::supports(lattice),
            _ => true,
        })
        .collect()
}

fn render_error(e: RenderError) -> ApiError {
    match e {
        RenderError::BadOption(m) => ApiError::BadValue(m),
        RenderError::Draw(m) => ApiError::Internal(m),
        RenderError::TooLarge(m) => ApiError::TooLarge(m),
        other => ApiError::BadSolution(other.to_string()),
    }
}

/// Reads the solution of a request and checks it against the limits.
fn dissection(req: &ExportRequest, limits: &Limits) -> Result<Dissection, ApiError> {
    let text = match &req.solution {
        Value::String(s) => s.clone(),
        v @ Value::Object(_) => v.to_string(),
        _ => {
            return Err(ApiError::BadValue(
                "\"solution\" must be a solution JSON object (or its text)".into(),
            ))
        }
    };
    let (_, d) = parse_solution(&text).map_err(|e| ApiError::BadSolution(e.to_string()))?;
    if d.pieces().len() > limits.max_figures() {
        return Err(ApiError::TooLarge(format!(
            "{} figures; this server takes at most {}",
            d.pieces().len(),
            limits.max_figures()
        )));
    }
    for (f, pieces) in d.pieces().iter().enumerate() {
        let n: usize = pieces.iter().map(|p| p.len()).sum();
        if n > limits.max_cells() {
            return Err(ApiError::TooLarge(format!(
                "figure {} has {n} cells; this server takes at most {}",
                f + 1,
                limits.max_cells()
            )));
        }
        let ext = limits.max_extent();
        if let Some(c) = pieces
            .iter()
            .flatten()
            .find(|c| c[0].abs() > ext || c[1].abs() > ext || c[2].abs() > ext)
        {
            return Err(ApiError::TooLarge(format!(
                "figure {}: cell {c:?} lies beyond {ext} rows/columns/layers",
                f + 1
            )));
        }
    }
    Ok(d)
}

fn physical(req: &ExportRequest) -> PhysicalOptions {
    let d = PhysicalOptions::default();
    PhysicalOptions {
        cell_mm: req.cell_mm.unwrap_or(d.cell_mm),
        thickness_mm: req.thickness_mm.unwrap_or(d.thickness_mm),
        clearance_mm: req.clearance_mm.unwrap_or(d.clearance_mm),
    }
}

/// Makes the file of `format` for a request.
pub fn export(format: &str, req: &ExportRequest, limits: &Limits) -> Result<Download, ApiError> {
    if !FORMATS.contains(&format) {
        return Err(ApiError::NotFound(format!(
            "unknown export format {format:?} (known: {})",
            FORMATS.join(", ")
        )));
    }
    let d = dissection(req, limits)?;
    let scene = Scene::verified(&d).map_err(render_error)?;
    Ok(match format {
        "svg" => Download {
            name: "dissection.svg".into(),
            content_type: "image/svg+xml",
            bytes: dissect_render::svg::render(&scene).into_bytes(),
        },
        "png" => Download {
            name: "dissection.png".into(),
            content_type: "image/png",
            bytes: dissect_render::png::render(&scene).map_err(render_error)?,
        },
        "cut-sheet" => Download {
            name: "dissection-cut-sheet.svg".into(),
            content_type: "image/svg+xml",
            bytes: dissect_render::cut_sheet::render(&scene, &physical(req))
                .map_err(render_error)?
                .into_bytes(),
        },
        "html" => Download {
            name: "dissection.html".into(),
            content_type: "text/html; charset=utf-8",
            bytes: dissect_render::html::page(&scene)
                .map_err(render_error)?
                .into_bytes(),
        },
        "animation" => Download {
            name: "dissection-animation.json".into(),
            content_type: "application/json",
            bytes: dissect_render::animation::data(&scene)
                .map_err(render_error)?
                .to_string()
                .into_bytes(),
        },
        "stl" => {
            let files =
                dissect_render::stl::render(&scene, &physical(req)).map_err(render_error)?;
            Download {
                name: "dissection-stl.zip".into(),
                content_type: "application/zip",
                bytes: zip(&files)?,
            }
        }
        _ => {
            let kind = match req.parts.as_deref() {
                None | Some("plate") => PartKind::Plate,
                Some("brick") => PartKind::Brick,
                Some(other) => {
                    return Err(ApiError::BadValue(format!(
                        "parts must be \"plate\" or \"brick\", got {other:?}"
                    )))
                }
            };
            let files: Vec<(String, Vec<u8>)> = dissect_render::ldraw::render(&scene, kind)
                .map_err(render_error)?
                .into_iter()
                .map(|(n, t)| (n, t.into_bytes()))
                .collect();
            Download {
                name: "dissection-ldraw.zip".into(),
                content_type: "application/zip",
                bytes: zip(&files)?,
            }
        }
    })
}

/// A ZIP archive of named files.
fn zip(files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, ApiError> {
    let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opts = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    let fail = |e: &dyn std::fmt::Display| ApiError::Internal(format!("cannot write the ZIP: {e}"));
    for (name, bytes) in files {
        w.start_file(name.as_str(), opts).map_err(|e| fail(&e))?;
        w.write_all(bytes).map_err(|e| fail(&e))?;
    }
    Ok(w.finish().map_err(|e| fail(&e))?.into_inner())
}
