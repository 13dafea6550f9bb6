//! Reading figure and solution files, with errors that name the file (and
//! the line and column where the problem is at one place).

use std::path::Path;

use anyhow::Result;
use dissect_core::io::{parse_figure, parse_solution, ParseErrorKind, SolutionFile};
use dissect_core::Dissection;
use dissect_core::{Figure, LatticeKind};

use crate::InputError;

/// The largest figure file read, in bytes: a million squares (four million
/// `tri4` triangles), far beyond what the solver can dissect, and still
/// read in well under 2 GiB.
pub const MAX_FIGURE_BYTES: u64 = 1 << 20;
/// The largest solution file read, in bytes.
pub const MAX_SOLUTION_BYTES: u64 = 16 << 20;
/// The largest picture or mesh file read, in bytes.
#[cfg(feature = "render")]
pub const MAX_BINARY_BYTES: u64 = 64 << 20;

/// Reads at most `cap` bytes of a file; a longer file (or an endless one,
/// like `/dev/zero`) is an error, found before more than `cap + 1` bytes are
/// held.
pub fn read_capped(path: &Path, cap: u64) -> Result<Vec<u8>> {
    use std::io::Read;
    let fail = |e: std::io::Error| InputError(format!("{}: cannot read: {e}", path.display()));
    let file = std::fs::File::open(path).map_err(fail)?;
    if file.metadata().map_err(fail)?.is_dir() {
        return Err(InputError(format!("{}: cannot read: it is a folder", path.display())).into());
    }
    let mut bytes = Vec::new();
    file.take(cap + 1).read_to_end(&mut bytes).map_err(fail)?;
    if bytes.len() as u64 > cap {
        return Err(InputError(format!(
            "{}: too large: files of this kind are read up to {} MiB",
            path.display(),
            cap >> 20
        ))
        .into());
    }
    Ok(bytes)
}

/// Reads a text file (a figure or a solution) of at most `cap` bytes.
pub fn read(path: &Path, cap: u64) -> Result<String> {
    let bytes = read_capped(path, cap)?;
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let valid = std::str::from_utf8(&e.as_bytes()[..at]).unwrap_or_default();
        let line = valid.matches('\n').count() + 1;
        let column = valid
            .rsplit('\n')
            .next()
            .unwrap_or_default()
            .chars()
            .count()
            + 1;
        InputError(format!(
            "{}: line {line}, column {column}: not UTF-8 text (byte {at})",
            path.display()
        ))
        .into()
    })
}

/// Reads one figure file.
pub fn figure(path: &Path, lattice: LatticeKind) -> Result<Figure> {
    let text = read(path, MAX_FIGURE_BYTES)?;
    parse_figure(&text, lattice).map_err(|e| {
        let hint = match e.kind {
            ParseErrorKind::UnexpectedChar { found, .. }
                if lattice != LatticeKind::Tri4 && found.is_ascii_hexdigit() =>
            {
                " (hex digits are tri4 cells: is this a tri4 figure? then use --lattice tri4)"
            }
            _ => "",
        };
        InputError(format!("{}: {e}{hint}", path.display())).into()
    })
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
    Err(InputError(format!(
        "figures have different areas (a dissection needs equal cell counts): {}",
        list.join(", ")
    ))
    .into())
}

/// Fails unless `path` can be created or overwritten as a file: its folder
/// exists and it is not a folder itself. Checked before a long search so
/// that its result is not lost to a typo.
pub fn check_writable(path: &Path) -> Result<()> {
    if path.is_dir() {
        return Err(InputError(format!(
            "{}: cannot write the solution: it is a folder",
            path.display()
        ))
        .into());
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !parent.is_dir() {
        return Err(InputError(format!(
            "{}: cannot write the solution: folder {} does not exist",
            path.display(),
            parent.display()
        ))
        .into());
    }
    Ok(())
}

/// Reads a solution file.
pub fn solution(path: &Path) -> Result<(SolutionFile, Dissection)> {
    let text = read(path, MAX_SOLUTION_BYTES)?;
    parse_solution(&text).map_err(|e| InputError(format!("{}: {e}", path.display())).into())
}

/// Fails when a lattice asked for on the command line is not the
/// solution's.
pub fn check_solution_lattice(
    path: &Path,
    solution: LatticeKind,
    asked: Option<LatticeKind>,
) -> Result<()> {
    match asked {
        Some(l) if l != solution => Err(InputError(format!(
            "{}: the solution is on the {solution} lattice, but --lattice {l} was given",
            path.display()
        ))
        .into()),
        _ => Ok(()),
    }
}

/// The file name shown in solutions (`name` key).
pub fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}
