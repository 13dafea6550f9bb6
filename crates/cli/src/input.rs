//! Reading figure and solution files, with errors that name the file.

use std::path::Path;

use anyhow::Result;
use dissect_core::io::{parse_figure, parse_solution, Dissection, SolutionFile};
use dissect_core::{Figure, LatticeKind};

use crate::InputError;

fn read(path: &Path) -> Result<String> {
    let bytes = std::fs::read(path)
        .map_err(|e| InputError(format!("{}: cannot read: {e}", path.display())))?;
    String::from_utf8(bytes).map_err(|e| {
        InputError(format!(
            "{}: not UTF-8 text (byte {})",
            path.display(),
            e.utf8_error().valid_up_to()
        ))
        .into()
    })
}

/// Reads one figure file.
pub fn figure(path: &Path, lattice: LatticeKind) -> Result<Figure> {
    let text = read(path)?;
    parse_figure(&text, lattice).map_err(|e| InputError(format!("{}: {e}", path.display())).into())
}

/// Reads figure files.
pub fn figures(paths: &[impl AsRef<Path>], lattice: LatticeKind) -> Result<Vec<Figure>> {
    paths.iter().map(|p| figure(p.as_ref(), lattice)).collect()
}

/// Fails with every figure's cell count when areas differ.
pub fn check_equal_areas(paths: &[impl AsRef<Path>], figures: &[Figure]) -> Result<()> {
    if figures.iter().all(|f| f.len() == figures[0].len()) {
        return Ok(());
    }
    let list: Vec<String> = paths
        .iter()
        .zip(figures)
        .map(|(p, f)| format!("{}: {} cells", p.as_ref().display(), f.len()))
        .collect();
    Err(InputError(format!("figures have different areas: {}", list.join(", "))).into())
}

/// Reads a solution file.
pub fn solution(path: &Path) -> Result<(SolutionFile, Dissection)> {
    let text = read(path)?;
    parse_solution(&text).map_err(|e| InputError(format!("{}: {e}", path.display())).into())
}

/// The file name shown in solutions (`name` key).
pub fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}
