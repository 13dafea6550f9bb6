//! Cube-and-conquer certificates: a base formula `F`, a clause
//! `C = (l_1 ∨ ... ∨ l_m)` of `F` (the cover), and per literal `l_j` a set
//! of clauses `E_j` holding the unit `l_j` with a DRAT proof that `F ∧ E_j`
//! is unsatisfiable.
//!
//! Why that proves the claim: the encoder claims (as for a single
//! certificate, whose formula holds such clauses too) that every real
//! dissection is a model of `F` that extends to a model of each `E_j`
//! less its unit (connectivity clauses, cuts). Such a model satisfies `C`,
//! so some `l_j`, and then extends to a model of `F ∧ E_j`, which the
//! proof of cube `j` refutes. [`check_cubes`] checks every part of this: that `C`
//! is a clause of `F`, that there is one cube per literal of `C` in order,
//! that cube `j` holds the unit `l_j`, and each proof against `F ∧ E_j`.

use crate::check::{check, Verified};
use crate::parse::{literal, Cnf, Proof};
use crate::{ProofError, Source};

/// Parses the cover file: `c` comment lines and one clause ended by `0`.
pub fn parse_cover(text: &str) -> Result<Vec<i32>, ProofError> {
    let err = |line: usize, message: String| ProofError::Parse {
        text: Source::Cubes,
        line,
        message,
    };
    let mut clause: Vec<i32> = Vec::new();
    let mut ended: Option<usize> = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('c') {
            continue;
        }
        for token in trimmed.split_whitespace() {
            if ended.is_some() {
                return Err(err(line, "more than one clause".into()));
            }
            let lit = literal(token, line, Source::Cubes)?;
            if lit == 0 {
                ended = Some(line);
            } else {
                clause.push(lit);
            }
        }
    }
    if ended.is_none() {
        return Err(err(
            text.lines().count().max(1),
            "no clause ended by 0".into(),
        ));
    }
    if clause.is_empty() {
        return Err(err(ended.unwrap_or(1), "the clause is empty".into()));
    }
    Ok(clause)
}

/// The literals of a clause as a sorted set.
fn sorted(clause: &[i32]) -> Vec<i32> {
    let mut c = clause.to_vec();
    c.sort_unstable();
    c.dedup();
    c
}

/// Checks a cube-and-conquer certificate (see the module): `Ok` with each
/// cube's [`Verified`] when it proves `base` unsatisfiable; else the
/// first failure, with the index of the cube it is in (`None`: the
/// cover).
pub fn check_cubes(
    base: &Cnf,
    cover: &[i32],
    cubes: &[(Cnf, Proof)],
) -> Result<Vec<Verified>, (Option<usize>, ProofError)> {
    check_cover(base, cover, cubes.len()).map_err(|e| (None, e))?;
    cubes
        .iter()
        .zip(cover)
        .enumerate()
        .map(|(j, ((extra, proof), &literal))| {
            check_cube(base, literal, extra, proof).map_err(|e| (Some(j), e))
        })
        .collect()
}

/// The part of [`check_cubes`] about the cover: it is a clause of `base`,
/// with one literal per cube (`cubes` of them). With [`check_cube`] for
/// each cube, a certificate too large to hold whole is checked a cube at
/// a time.
pub fn check_cover(base: &Cnf, cover: &[i32], cubes: usize) -> Result<(), ProofError> {
    let wanted = sorted(cover);
    if !base.clauses().iter().any(|c| sorted(c) == wanted) {
        return Err(ProofError::NotCovered {
            cover: crate::check::dimacs(cover),
        });
    }
    if cubes != cover.len() {
        return Err(ProofError::MissingCube {
            cubes,
            literals: cover.len(),
        });
    }
    Ok(())
}

/// The part of [`check_cubes`] about one cube: its clauses `extra` hold
/// the unit of `literal`, and `proof` refutes `base` with them.
pub fn check_cube(
    base: &Cnf,
    literal: i32,
    extra: &Cnf,
    proof: &Proof,
) -> Result<Verified, ProofError> {
    check(&cube_formula(base, literal, extra)?, proof)
}

/// The formula a cube's proof refutes: `base` with the cube's clauses
/// `extra`, which must hold the unit of `literal` (for checking a proof
/// read a line at a time, with [`Checker`](crate::Checker)).
pub fn cube_formula(base: &Cnf, literal: i32, extra: &Cnf) -> Result<Cnf, ProofError> {
    if !extra.clauses().iter().any(|c| c.as_slice() == [literal]) {
        return Err(ProofError::NoUnit { literal });
    }
    let mut clauses = base.clauses().to_vec();
    clauses.extend(extra.clauses().iter().cloned());
    Ok(Cnf::new(base.vars().max(extra.vars()), clauses))
}
