//! The exact mode of `dissect`: lower bounds with their reasons, and a SAT
//! search that finds minimum dissections and proves that none with fewer
//! pieces exists.
//!
//! * Cheap bounds ([`bound::cheap_bound`]): the number of connected
//!   components of a figure, and a clique of *incompatible* cells (cells of
//!   one figure that no single connected piece can hold together because it
//!   would not fit inside another figure; the 8 corners of a 6³ cube against
//!   three separate smaller cubes force 8 pieces).
//! * The question "is there a dissection into at most K pieces?" as SAT
//!   ([`placement_encoding`]), solved by batsat. Without connectivity the
//!   encoding is a relaxation: UNSAT proves the lower bound K+1. Connectivity
//!   is added lazily (`connectivity_cut`): a model whose pieces are split
//!   gets clauses that forbid the split, so a model that survives is a real
//!   K-piece dissection (and is checked by `dissect_core::verify` before it
//!   is reported).
//! * Certificates ([`certificate`], with [`ExactOptions::certify`]): every
//!   refutation comes with the formula and batsat's DRAT proof, which the
//!   independent checker `dissect-proof` replays.
//! * [`enumerate::enumerate`] counts every dissection with K pieces (the
//!   minimum, proved first, unless K is given): SAT again and again, each
//!   model verified and then forbidden by a blocking clause over the cut of
//!   the first figure; classes up to the first figure's symmetries.
//! * [`search::search`] runs the loop over K, shares its bounds with a
//!   caller (the heuristic solver running beside it) and stops on request.
//!
//! Architecture invariant: like the core, this crate does no I/O and never
//! prints; progress leaves through [`search::ExactObserver`]. The SAT backend
//! (the `batsat` crate) is a dependency of this crate only, and only
//! `sat_backend` names it.

pub mod bound;
pub mod certificate;
pub(crate) mod component_count;
pub(crate) mod connectivity_cut;
pub(crate) mod constraint_encoding;
pub(crate) mod cube_and_conquer;
pub mod enumerate;
pub(crate) mod enumerate_symmetry;
pub(crate) mod extent_clique;
pub(crate) mod incompatible_clique;
pub(crate) mod instance;
pub mod motion;
pub mod placement_encoding;
pub(crate) mod reachability_encoding;
pub mod repair;
pub(crate) mod sat_backend;
pub mod search;
pub(crate) mod shift_encoding;

pub use bound::{cheap_bound, Bound, Reason};
pub use certificate::{Certificate, CubeProof, CubeProofWriters, ProofSink};
pub use enumerate::{enumerate, EnumerateEvent, EnumerateObserver, EnumerateOptions, Enumeration};
pub use motion::MotionSet;
pub use placement_encoding::{EncodingSize, MotionEncoding};
pub use repair::{repair, repair_report, RepairOptions, RepairReport};
pub use search::{
    decode_model, decode_model_within, dimacs, dimacs_connected, dimacs_within, search, Dimacs,
    ExactEvent, ExactObserver, ExactOptions, ExactOutcome, Limit, Mode, DEFAULT_MAX_ENCODING_BYTES,
};

/// Occurs when figures cannot be given to the exact search.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ExactError {
    /// Occurs when the figures are not a valid dissection problem (fewer than
    /// two, mixed lattices, unequal areas).
    #[error(transparent)]
    Figures(#[from] dissect_core::solver::SolveError),
    /// Occurs when a model decoded from the SAT solver fails the independent
    /// verifier: a bug in the encoding, never the user's fault.
    #[error("internal error: a SAT model decoded into an invalid dissection: {0}")]
    InvalidModel(String),
    /// Occurs when a model given to [`decode_model`] is no dissection of
    /// the figures (a model of another formula, or of another K).
    #[error("the model is no dissection of these figures: {0}")]
    Model(String),
    /// Occurs when a candidate given to [`repair()`] does not partition the
    /// figures into the same number of labels.
    #[error("invalid candidate: {0}")]
    Candidate(String),
    /// Occurs when an encoding would need more memory than allowed.
    #[error(
        "the SAT encoding for {pieces} pieces would need about {} MiB, over the cap of {} MiB",
        bytes >> 20,
        cap >> 20
    )]
    TooLarge {
        /// K.
        pieces: usize,
        /// The estimate, in bytes.
        bytes: u64,
        /// The cap, in bytes.
        cap: u64,
    },
}
