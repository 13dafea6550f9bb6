//! The topics of the integration suite.

mod anytime;
mod ascii_art;
mod explore;
mod lattice;
mod parse;
mod solution_json;
mod solve;
mod stats;
mod transform;
pub mod util;
mod verifier;
