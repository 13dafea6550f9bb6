//! The core of `dissect`: lattices, figures, the dissection solver of Zhou
//! and Wang, and an independent verifier.
//!
//! Architecture invariant: this crate does no I/O and never prints. Text
//! formats are parsed from and written to strings; progress leaves through
//! the [`solver::Observer`] trait.

pub mod ascii;
pub mod dissection;
pub mod figure;
pub mod io;
pub mod lattice;
pub mod motion;
pub mod palette;
pub mod solver;
pub mod transform;
pub mod verify;

pub use dissection::Dissection;
pub use figure::Figure;
pub use lattice::{Cell, Lattice, LatticeKind};
pub use solver::{solve, solve_anytime, Options};

#[cfg(test)]
mod tests;
