//! Pictures in and out for `dissect`.
//!
//! * Out: a [`Scene`] (the pieces of every figure, their colours, outlines
//!   and voxels) is built once from a solution, then each exporter is one
//!   small function of it: [`svg`], [`png`], [`cut_sheet`], [`stl`],
//!   [`ldraw`].
//! * In: [`rasterize`] turns a picture (PNG, JPEG, SVG, or a stack of
//!   slices) into a figure with an exact cell count; [`voxelize`] does the
//!   same for a closed STL mesh.
//!
//! Architecture invariant: no I/O and no printing. Every public function
//! takes strings or bytes and returns strings or bytes, so a server can
//! call it as well as the command line.

#![forbid(unsafe_code)]

pub mod animation;
pub mod bounds;
pub mod colour;
pub mod cut_sheet;

pub mod drawing;
mod ear_clipping;
mod error;
mod font;
pub mod html;
pub mod ldraw;
pub mod mesh;
pub mod outline;
pub mod png;
pub mod rasterize;
pub mod scene;
pub mod steps;
pub mod stl;
pub mod svg;
pub mod tiling;
mod view;
pub mod voxelize;

pub use error::RenderError;
pub use scene::Scene;
