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

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use crate::sat_backend::Sat;

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
    /// The formula holds only the clauses over the cells of a clique of
    /// pairwise incompatible cells (each in some piece, the first K fixed to
    /// pieces `0..K`, no two in one piece), a part of the placement
    /// encoding: written when the whole encoding would not fit.
    pub clique_only: bool,
    /// With cube-and-conquer: the cubes, each refuted on its own (then
    /// [`Certificate::formula`] is the base formula every cube extends and
    /// [`Certificate::proof`] is empty). The cubes' literals, in order,
    /// are a clause of the base formula, so a model of it satisfies one of
    /// them: the base is unsatisfiable when every cube is.
    pub cubes: Vec<CubeProof>,
}

/// One cube's refutation: the base formula plus [`CubeProof::formula`]'s
/// clauses is unsatisfiable.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubeProof {
    /// The cube's literal (the first clause of `formula`, a unit).
    pub literal: i32,
    /// The clauses added to the base formula, DIMACS (the header counts
    /// every variable): the unit, then the connectivity encoding and the
    /// cuts this cube met.
    pub formula: String,
    /// Clauses of `formula`.
    pub clauses: usize,
    /// The DRAT proof that the base and `formula` together are
    /// unsatisfiable; `None` when it went to the writer of
    /// [`ExactOptions::cube_proofs`](crate::ExactOptions::cube_proofs)
    /// (then complete there, ended by the empty clause).
    pub proof: Option<String>,
    /// The lemmas of the proof (lines that are not deletions).
    pub lemmas: usize,
    /// Variables of the base and `formula` together.
    pub vars: usize,
    /// Connectivity cuts among the clauses.
    pub cuts: usize,
    /// Whether the connectivity encoding is among the clauses.
    pub connectivity: bool,
}

/// Writers for the DRAT proofs of cube-and-conquer's cubes, so that no
/// proof is held in memory: the solver of cube `cube` of the refutation of
/// `pieces` pieces writes its proof to `open(pieces, cube)` as it goes.
/// The proof there is whole once the certificate that lists the cube
/// ([`ExactEvent::Certified`](crate::ExactEvent::Certified)) comes;
/// a cube that is not refuted leaves an incomplete proof behind, and the
/// same cube of a later pass for the same `pieces` opens its writer again.
///
/// The writers may also keep refuted cubes across runs: [`begin`](CubeProofWriters::begin)
/// gives back those they hold for the same base formula and cover, and
/// [`refuted`](CubeProofWriters::refuted) says when a cube's proof is whole.
/// A kept cube is trusted by the search as refuted; the certificate that
/// lists it is checked like any other (`dissect check-proof`).
pub trait CubeProofWriters: Send + Sync {
    /// A writer for the proof of one cube; `None`: keep that proof in
    /// memory ([`CubeProof::proof`]).
    fn open(&self, pieces: usize, cube: usize) -> Option<Box<dyn std::io::Write + Send>>;

    /// A cubed pass for `pieces` pieces begins, with the base formula
    /// `base` (DIMACS) and the cubes' literals `cover`: per cube, the
    /// refutation the writers already hold for exactly this base and cover
    /// (its proof whole where they keep it), or `None` to solve it. The
    /// default holds none.
    fn begin(&self, pieces: usize, base: &str, cover: &[i32]) -> Vec<Option<CubeProof>> {
        let _ = (pieces, base);
        vec![None; cover.len()]
    }

    /// Cube `cube` of the pass for `pieces` pieces was refuted: its proof
    /// (written through [`CubeProofWriters::open`], or in `proof.proof`)
    /// is whole. The default does nothing.
    fn refuted(&self, pieces: usize, cube: usize, proof: &CubeProof) {
        let _ = (pieces, cube, proof);
    }
}

/// A shared [`CubeProofWriters`], for [`crate::ExactOptions::cube_proofs`].
#[derive(Clone)]
pub struct ProofSink(Arc<dyn CubeProofWriters>);

impl ProofSink {
    /// The sink of `writers`.
    pub fn new(writers: Arc<dyn CubeProofWriters>) -> ProofSink {
        ProofSink(writers)
    }

    pub(crate) fn writers(&self) -> &dyn CubeProofWriters {
        &*self.0
    }
}

impl std::fmt::Debug for ProofSink {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ProofSink(..)")
    }
}

impl PartialEq for ProofSink {
    fn eq(&self, other: &ProofSink) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

/// The certificate of an UNSAT answer of `sat` (recording) for `k` pieces
/// with `cuts` connectivity cuts; `None` when it was not recording.
pub(crate) fn of_sat(
    sat: &Sat<'_>,
    k: usize,
    cuts: usize,
    connectivity: bool,
) -> Option<Box<Certificate>> {
    let (formula, clauses) = sat.dimacs()?;
    Some(Box::new(Certificate {
        pieces: k,
        formula,
        proof: sat.proof()?,
        vars: sat.vars(),
        clauses,
        cuts,
        connectivity,
        clique_only: false,
        cubes: Vec::new(),
    }))
}

/// The placement encoding's clauses over `clique` pairwise incompatible
/// cells for `k` pieces (`k < clique`), refuted: the clique bound's
/// certificate when the whole encoding would not fit. `None` when stopped.
pub(crate) fn clique(k: usize, clique: usize, stop: &AtomicBool) -> Option<Box<Certificate>> {
    let mut sat = Sat::new(stop, None);
    sat.record();
    sat.record_proof();
    let x: Vec<Vec<i32>> = (0..clique)
        .map(|_| (0..k).map(|_| sat.var()).collect())
        .collect();
    for cell in &x {
        sat.add(cell);
    }
    for (i, cell) in x.iter().enumerate().take(k) {
        sat.add(&[cell[i]]);
    }
    for piece in 0..k {
        for (a, first) in x.iter().enumerate() {
            for second in &x[a + 1..] {
                sat.add(&[-first[piece], -second[piece]]);
            }
        }
    }
    if sat.solve(None) != Some(false) {
        return None;
    }
    let mut c = of_sat(&sat, k, 0, false)?;
    c.clique_only = true;
    Some(c)
}

impl Certificate {
    /// The lemmas of the proof (lines that are not deletions), of every
    /// cube's proof with cube-and-conquer.
    pub fn lemmas(&self) -> usize {
        let count = |p: &str| p.lines().filter(|l| !l.starts_with('d')).count();
        if self.cubes.is_empty() {
            count(&self.proof)
        } else {
            self.cubes.iter().map(|c| c.lemmas).sum()
        }
    }
}
