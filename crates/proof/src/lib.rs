//! An independent checker of `dissect`'s SAT certificates: a DIMACS CNF
//! formula and a DRAT proof that it is unsatisfiable.
//!
//! The checker shares no code with the encoder or the solver: it parses the
//! two texts itself ([`Cnf::parse`], [`Proof::parse`]) and replays the proof
//! forwards ([`check`]): every added lemma must be a RUP (reverse unit
//! propagation) or a RAT (resolution asymmetric tautology, on its first
//! literal) lemma of the clauses present at that step; deletions remove
//! clauses. The proof is accepted once unit propagation on the clauses
//! present yields a conflict (the empty clause is then RUP), which proves
//! the formula unsatisfiable.
//!
//! A proof too large to hold is checked a line at a time: [`ProofStream`]
//! splits the lines the caller reads into steps and [`Checker`] replays
//! them, holding only the clauses present (the deleted ones are dropped
//! from memory once they outweigh the rest).
//!
//! Cube-and-conquer certificates ([`check_cubes`]): a base formula, one of
//! its clauses whose literals are the cubes, and per cube the clauses it
//! adds (its unit first) with a proof refuting the base plus them.
//!
//! Architecture invariant: no I/O, no printing; the texts come in as
//! strings, errors name the line.

mod check;
mod cubes;
mod parse;

pub use check::{check, Checker, Verified};
pub use cubes::{check_cover, check_cube, check_cubes, cube_formula, parse_cover};
pub use parse::{Cnf, Proof, ProofStream, Step};

/// Which of the two texts an error is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// The DIMACS CNF formula.
    Formula,
    /// The DRAT proof.
    Proof,
    /// The cover of a cube-and-conquer certificate (one clause).
    Cubes,
}

impl std::fmt::Display for Source {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Source::Formula => "formula",
            Source::Proof => "proof",
            Source::Cubes => "cubes",
        })
    }
}

/// Why a certificate was rejected.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ProofError {
    /// Occurs when a text is not well-formed DIMACS CNF or DRAT.
    #[error("{text} line {line}: {message}")]
    Parse {
        /// The text.
        text: Source,
        /// The line (from 1).
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// Occurs when a lemma of the proof is neither RUP nor RAT.
    #[error("proof line {line}: lemma {lemma} is neither RUP nor RAT (step {step})")]
    NotImplied {
        /// The line (from 1) of the lemma in the proof.
        line: usize,
        /// The step (lemmas and deletions, from 1).
        step: usize,
        /// The lemma, in DIMACS.
        lemma: String,
    },
    /// Occurs when the proof ends without a conflict: it proves nothing.
    #[error("proof ends at line {line} without deriving the empty clause")]
    Incomplete {
        /// The last line of the proof.
        line: usize,
    },
    /// Occurs when the cubes' literals are no clause of the base formula:
    /// the cubes need not cover it.
    #[error("the cubes {cover} are not a clause of the base formula")]
    NotCovered {
        /// The cover clause, in DIMACS.
        cover: String,
    },
    /// Occurs when there are not as many cubes as literals in the cover.
    #[error("{cubes} cubes for the {literals} literals of the cover")]
    MissingCube {
        /// Cubes given.
        cubes: usize,
        /// Literals of the cover.
        literals: usize,
    },
    /// Occurs when a cube's clauses lack the unit of its literal.
    #[error("the cube of literal {literal} does not hold the unit clause `{literal} 0`")]
    NoUnit {
        /// The cube's literal.
        literal: i32,
    },
}

impl ProofError {
    /// The text the error is in and its line (0: the text as a whole).
    pub fn location(&self) -> (Source, usize) {
        match self {
            ProofError::Parse { text, line, .. } => (*text, *line),
            ProofError::NotImplied { line, .. } | ProofError::Incomplete { line } => {
                (Source::Proof, *line)
            }
            ProofError::NotCovered { .. } | ProofError::MissingCube { .. } => (Source::Cubes, 0),
            ProofError::NoUnit { .. } => (Source::Formula, 0),
        }
    }
}
