//! `dissect render`, `dissect rasterize`, `dissect voxelize` and the
//! `solve --render DIR` hook: file handling around `dissect-render`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use clap::Args;
use dissect_core::LatticeKind;
use dissect_render::ldraw::PartKind;
use dissect_render::rasterize::{RasterOptions, Rasterized};
use dissect_render::stl::PhysicalOptions;
use dissect_render::svg::ViewOptions;
use dissect_render::voxelize::VoxelOptions;
use dissect_render::{RenderError, Scene};

use crate::args::{finite, non_negative, positive, whole_usize};
use crate::{input, output, InputError, Status};

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct RenderArgs {
    /// The solution JSON.
    #[arg(value_name = "SOLUTION.json")]
    pub solution: PathBuf,
    /// The figures, in the solution's order (the solution is checked against them; without them, against the figures its pieces make).
    #[arg(long, num_args = 1.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
    /// svg or png: a picture of every figure; stl: one mesh per piece; ldraw: one LEGO model per figure;
    /// html: one self-contained page with the pieces' motion (and a 3D view for cubic);
    /// steps: instructions to print, one SVG sheet per figure, one piece added per step.
    #[arg(long, default_value = "svg", value_parser = ["svg", "png", "stl", "ldraw", "html", "steps"])]
    pub format: String,
    /// Output: a file (OUT.svg / OUT.png) or a folder (created when missing; its parent must exist).
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: PathBuf,
    /// Also write a laser cut sheet (cut-sheet.svg, millimetres) of the pieces.
    #[arg(long)]
    pub cut_sheet: bool,
    /// The edge of one cell in millimetres (cut sheet and STL).
    #[arg(long, default_value_t = 10.0, value_name = "MM", value_parser = positive)]
    pub cell_mm: f64,
    /// The height of 2D pieces in STL, millimetres.
    #[arg(long, default_value_t = 4.0, value_name = "MM", value_parser = positive)]
    pub thickness: f64,
    /// How much every piece shrinks on each side so printed/cut pieces fit, millimetres.
    #[arg(long, default_value_t = 0.1, value_name = "MM", value_parser = non_negative)]
    pub clearance: f64,
    /// Pixels per cell in svg/png (default: from the figures' size).
    #[arg(long, value_name = "PX", value_parser = positive)]
    pub cell_px: Option<f64>,
    /// Build 2D LDraw models from bricks instead of plates.
    #[arg(long)]
    pub bricks: bool,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct RasterizeArgs {
    /// The picture (PNG, JPEG or SVG), or one picture per z layer (bottom first) for --lattice cubic.
    #[arg(required = true, num_args = 1.., value_name = "PICTURE")]
    pub pictures: Vec<PathBuf>,
    /// The lattice: square, tri4, cubic, tri3 or hex.
    #[arg(long, default_value_t = LatticeKind::Square)]
    pub lattice: LatticeKind,
    /// Exactly this many cells (triangles for tri4); scale and threshold are searched.
    #[arg(long, value_name = "N", value_parser = whole_usize::<1>)]
    pub cells: Option<usize>,
    /// Picture pixels per cell when --cells is not given.
    #[arg(long, default_value_t = 10.0, value_name = "PX", value_parser = positive)]
    pub scale: f64,
    /// Inside fraction from which a cell is filled when --cells is not given.
    #[arg(long, default_value_t = 0.5, value_name = "T", value_parser = finite)]
    pub threshold: f64,
    /// Light pixels are inside (for pictures without transparency).
    #[arg(long)]
    pub invert: bool,
    /// Write the figure here (default: standard output).
    #[arg(short = 'o', long = "output", value_name = "FIGURE.txt")]
    pub output: Option<PathBuf>,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct VoxelizeArgs {
    /// A closed triangle mesh (binary or ASCII STL).
    #[arg(value_name = "MESH.stl")]
    pub mesh: PathBuf,
    /// Exactly this many cubes; the scale is searched.
    #[arg(long, value_name = "N", value_parser = whole_usize::<1>)]
    pub cells: Option<usize>,
    /// Mesh units per cube when --cells is not given (default: a tenth of the longest side).
    #[arg(long, value_name = "UNITS", value_parser = positive)]
    pub scale: Option<f64>,
    /// Write the figure here (default: standard output).
    #[arg(short = 'o', long = "output", value_name = "FIGURE.txt")]
    pub output: Option<PathBuf>,
}

/// Reads a picture or a mesh (at most [`input::MAX_BINARY_BYTES`]).
fn read_bytes(path: &Path) -> Result<Vec<u8>> {
    input::read_capped(path, input::MAX_BINARY_BYTES)
}

/// An error of the render crate about the file `path`.
fn about(path: &Path, e: RenderError) -> anyhow::Error {
    InputError(format!("{}: {e}", path.display())).into()
}

/// Makes `dir` the output folder: it may exist; if not, it is created, but
/// only it: its parent must already be a folder (a mistyped path never
/// grows a tree of folders, nor one inside a file's path).
fn output_dir(dir: &Path) -> Result<()> {
    if dir.as_os_str().is_empty() || dir.is_dir() {
        return Ok(());
    }
    if dir.exists() {
        return Err(InputError(format!(
            "{}: cannot write into it: it is not a folder",
            dir.display()
        ))
        .into());
    }
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !parent.is_dir() {
        return Err(InputError(format!(
            "{}: cannot create the output folder: {} is not an existing folder",
            dir.display(),
            parent.display()
        ))
        .into());
    }
    std::fs::create_dir(dir).with_context(|| format!("cannot create folder {}", dir.display()))
}

/// Reads a solution and its figures into a scene.
fn scene(solution: &Path, figures: &[PathBuf]) -> Result<Scene> {
    let json = input::read(solution, input::MAX_SOLUTION_BYTES)?;
    let texts = figures
        .iter()
        .map(|p| input::read(p, input::MAX_FIGURE_BYTES))
        .collect::<Result<Vec<_>>>()?;
    let refs: Vec<&str> = texts.iter().map(|s| s.as_str()).collect();
    Scene::from_solution(&json, &refs).map_err(|e| match e {
        RenderError::Figure { index, error } => {
            InputError(format!("{}: {error}", figures[index].display())).into()
        }
        e => about(solution, e),
    })
}

pub fn run(args: RenderArgs) -> Result<Status> {
    dissect_render::bounds::check_cell_px(args.cell_px).map_err(|e| InputError(e.to_string()))?;
    let scene = scene(&args.solution, &args.figures)?;
    let physical = PhysicalOptions {
        cell_mm: args.cell_mm,
        thickness_mm: args.thickness,
        clearance_mm: args.clearance,
    };
    physical.check().map_err(|e| InputError(e.to_string()))?;
    let view = ViewOptions {
        cell_px: args.cell_px,
        ..ViewOptions::default()
    };
    let out = &args.output;
    let ext = out.extension().and_then(|e| e.to_str()).unwrap_or("");
    let single_file = matches!(
        (args.format.as_str(), ext),
        ("svg", "svg") | ("png", "png") | ("html", "html" | "htm")
    );
    let dir = if single_file {
        out.parent().map(Path::to_path_buf).unwrap_or_default()
    } else {
        out.clone()
    };
    if !single_file {
        output_dir(&dir)?;
    }
    let mut written: Vec<PathBuf> = Vec::new();
    let mut put = |path: PathBuf, bytes: &[u8]| -> Result<()> {
        output::write_atomic(&path, bytes)?;
        written.push(path);
        Ok(())
    };
    let stem = args
        .solution
        .file_stem()
        .map_or("puzzle".to_string(), |s| s.to_string_lossy().into_owned());
    match args.format.as_str() {
        "svg" => {
            let path = if single_file {
                out.clone()
            } else {
                dir.join(format!("{stem}.svg"))
            };
            put(
                path,
                dissect_render::svg::render_with(&scene, &view).as_bytes(),
            )?;
        }
        "png" => {
            let path = if single_file {
                out.clone()
            } else {
                dir.join(format!("{stem}.png"))
            };
            let png = dissect_render::png::render_with(&scene, &view)
                .map_err(|e| about(&args.solution, e))?;
            put(path, &png)?;
        }
        "html" => {
            let path = if single_file {
                out.clone()
            } else {
                dir.join(format!("{stem}.html"))
            };
            let page = dissect_render::html::page(&scene).map_err(|e| about(&args.solution, e))?;
            put(path, page.as_bytes())?;
        }
        "steps" => {
            for (name, svg) in dissect_render::steps::sheets(&scene) {
                put(dir.join(name), svg.as_bytes())?;
            }
        }
        "stl" => {
            let files = dissect_render::stl::render(&scene, &physical)
                .map_err(|e| about(&args.solution, e))?;
            for (name, bytes) in files {
                put(dir.join(name), &bytes)?;
            }
        }
        _ => {
            let kind = if args.bricks {
                PartKind::Brick
            } else {
                PartKind::Plate
            };
            let files = dissect_render::ldraw::render(&scene, kind)
                .map_err(|e| about(&args.solution, e))?;
            for (name, text) in files {
                put(dir.join(name), text.as_bytes())?;
            }
        }
    }
    if args.cut_sheet {
        let svg = dissect_render::cut_sheet::render(&scene, &physical)
            .map_err(|e| about(&args.solution, e))?;
        put(dir.join("cut-sheet.svg"), svg.as_bytes())?;
    }
    for p in &written {
        println!("wrote {}", p.display());
    }
    Ok(Status::Ok)
}

fn report(r: &Rasterized, output: &Option<PathBuf>, unit: &str) -> Result<Status> {
    let s = r.figure.stats();
    let size: Vec<String> = (0..if r.figure.lattice() == LatticeKind::Cubic {
        3
    } else {
        2
    })
        .map(|k| (s.max[k] - s.min[k] + 1).to_string())
        .collect();
    match output {
        Some(p) => output::write_atomic(p, r.text.as_bytes())?,
        None => print!("{}", r.text),
    }
    eprintln!(
        "{}{} cells ({}), {}; scale {:.3} {unit} per cell, threshold {:.3}; {} cell(s) differ from a plain 50% threshold",
        output
            .as_ref()
            .map_or(String::new(), |p| format!("wrote {}: ", p.display())),
        s.cells,
        r.figure.lattice(),
        size.join("x"),
        r.scale,
        r.threshold,
        r.changed
    );
    Ok(Status::Ok)
}

pub fn rasterize(args: RasterizeArgs) -> Result<Status> {
    let mut paths = args.pictures.clone();
    if args.lattice == LatticeKind::Cubic {
        // slice-2.png before slice-10.png.
        paths.sort_by_key(|p| natural_key(&p.to_string_lossy()));
    }
    let bytes = paths
        .iter()
        .map(|p| read_bytes(p))
        .collect::<Result<Vec<_>>>()?;
    let refs: Vec<&[u8]> = bytes.iter().map(|b| b.as_slice()).collect();
    let opts = RasterOptions {
        lattice: args.lattice,
        cells: args.cells,
        scale: args.scale,
        threshold: args.threshold,
        invert: args.invert,
    };
    let r = dissect_render::rasterize::rasterize(&refs, &opts).map_err(|e| {
        let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
        anyhow::Error::from(InputError(format!("{}: {e}", names.join(", "))))
    })?;
    report(&r, &args.output, "pixels")
}

pub fn voxelize(args: VoxelizeArgs) -> Result<Status> {
    let bytes = read_bytes(&args.mesh)?;
    let opts = VoxelOptions {
        cells: args.cells,
        scale: args.scale,
    };
    let r = dissect_render::voxelize::voxelize(&bytes, &opts).map_err(|e| about(&args.mesh, e))?;
    report(&r, &args.output, "mesh units")
}

/// Writes the SVG views of a solved dissection into `dir` (for `solve --render DIR`).
pub fn write_views(dir: &Path, d: &dissect_core::Dissection) -> Result<()> {
    let scene = Scene::new(d).map_err(|e| anyhow::anyhow!("{e}"))?;
    output_dir(dir)?;
    let path = dir.join("dissection.svg");
    output::write_atomic(&path, dissect_render::svg::render(&scene).as_bytes())?;
    if scene.lattice() != LatticeKind::Cubic {
        let sheet = dissect_render::cut_sheet::render(&scene, &PhysicalOptions::default())
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        output::write_atomic(&dir.join("cut-sheet.svg"), sheet.as_bytes())?;
    }
    Ok(())
}

fn natural_key(s: &str) -> Vec<(String, u64)> {
    let mut out = Vec::new();
    let mut text = String::new();
    let mut digits = String::new();
    for c in s.chars() {
        if c.is_ascii_digit() {
            digits.push(c);
        } else {
            if !digits.is_empty() {
                out.push((
                    std::mem::take(&mut text),
                    digits.parse().unwrap_or(u64::MAX),
                ));
                digits.clear();
            }
            text.push(c);
        }
    }
    out.push((text, digits.parse().unwrap_or(0)));
    out
}

#[cfg(test)]
mod tests {
    use super::natural_key;

    #[test]
    fn slices_sort_by_their_numbers() {
        let mut names = vec!["slice-10.png", "slice-2.png", "slice-1.png"];
        names.sort_by_key(|n| natural_key(n));
        assert_eq!(names, ["slice-1.png", "slice-2.png", "slice-10.png"]);
    }
}
