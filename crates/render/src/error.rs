//! The crate's error type.

use dissect_core::io::{ParseError, SolutionError};

/// Occurs when input cannot be rendered, rasterized or voxelized. Messages
/// never name files: the caller knows which file it read and prefixes it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RenderError {
    /// Occurs when the solution JSON cannot be read.
    #[error("{0}")]
    Solution(#[from] SolutionError),
    /// Occurs when a figure text (the `index`-th, 0-based) cannot be read.
    #[error("figure {}: {error}", index + 1)]
    Figure {
        /// 0-based index of the figure.
        index: usize,
        /// What is wrong.
        error: ParseError,
    },
    /// Occurs when the figures given do not match the solution.
    #[error("{0}")]
    Mismatch(String),
    /// Occurs when the solution is not a valid dissection of its figures.
    #[error("not a valid dissection of the figures: {0}")]
    Invalid(String),
    /// Occurs when an option is out of range.
    #[error("{0}")]
    BadOption(String),
    /// Occurs when the bytes are not a PNG, JPEG or SVG picture.
    #[error("not a picture: {0}")]
    NotAPicture(String),
    /// Occurs when a picture has nothing inside (no dark or opaque pixel).
    #[error("the picture is empty: no dark or opaque pixel")]
    EmptyPicture,
    /// Occurs when no scale and threshold give the asked number of cells.
    #[error("cannot make exactly {asked} cells from this picture (nearest: {nearest})")]
    Unreachable {
        /// The cell count asked for.
        asked: usize,
        /// The nearest count that can be made.
        nearest: usize,
    },
    /// Occurs when the bytes are not an STL mesh.
    #[error("not an STL mesh: {0}")]
    BadMesh(String),
    /// Occurs when a mesh is not closed (it has edges not shared by exactly two triangles).
    #[error("the mesh is not closed: {0} edges are not shared by exactly two triangles")]
    OpenMesh(usize),
    /// Occurs when a picture, a mesh, a drawing or the grid they are
    /// sampled on would be larger than the bounds of [`crate::bounds`]
    /// (checked before anything that size is allocated).
    #[error("too large: {0}")]
    TooLarge(String),
    /// Occurs when a picture cannot be drawn.
    #[error("cannot draw the picture: {0}")]
    Draw(String),
}
