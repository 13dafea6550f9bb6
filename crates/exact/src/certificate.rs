//! Certificates of "no K-piece dissection": the formula the SAT solver
//! refuted and the solver's proof that it is unsatisfiable, for an
//! independent checker (`dissect-proof`, `dissect check-proof`).
//!
//! The formula is the placement encoding of "at most K pieces"
//! ([`crate::placement_encoding`]) with every clause the search added to it
//! before the solver answered UNSAT: the designer's constraints, the
//! connectivity encoding, connectivity cuts. Each of these only removes
//! assignments that are no connected K-piece dissection, so a refutation
//! of the whole formula proves that none exists.

/// A refuted formula and its DRAT proof.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Certificate {
    /// K: the formula says "a dissection into at most K pieces".
    pub pieces: usize,
    /// The formula, DIMACS CNF.
    pub formula: String,
    /// The proof that it is unsatisfiable, text DRAT (lemmas and `d`
    /// deletions, ended by the empty clause).
    pub proof: String,
    /// Variables of the formula.
    pub vars: usize,
    /// Clauses of the formula.
    pub clauses: usize,
    /// Connectivity cuts among the clauses.
    pub cuts: usize,
    /// Whether the connectivity encoding is among the clauses.
    pub connectivity: bool,
}

impl Certificate {
    /// The lemmas of the proof (lines that are not deletions).
    pub fn lemmas(&self) -> usize {
        self.proof.lines().filter(|l| !l.starts_with('d')).count()
    }
}
