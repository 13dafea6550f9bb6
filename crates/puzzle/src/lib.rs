//! Puzzle design on top of a dissection: how many ways its pieces assemble
//! ([`assemblies`], an exact cover search by dancing links in [`dlx`]),
//! scores to rank dissections with the same number of pieces and the
//! canonical form that says when two are the same puzzle ([`scores`]), and
//! the designer's constraints ([`constraints`]), and whether a 3D figure's
//! pieces can be taken apart by straight moves ([`disassembly`]).
//!
//! Architecture invariant: like the core, this crate does no I/O and never
//! prints; it sees lattices only through the [`dissect_core::Lattice`]
//! trait ([`geometry::Motions`]), so it works on every lattice.

pub mod assemblies;
pub mod collect;
pub mod constraints;
pub mod disassembly;
pub mod dlx;
pub mod geometry;
pub mod scores;

pub use assemblies::{count, report_line, AssemblyError, Count, CountLimits, PieceSet};
pub use collect::{Added, Collection, Entry};
pub use constraints::{ConstraintError, Constraints, KeepRegions};
pub use disassembly::{disassemble, Disassembly, DisassemblyError, Plan};
pub use geometry::Motions;
pub use scores::{Rank, Scores};
