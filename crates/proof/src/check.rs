//! Forward DRAT checking with two watched literals.
//!
//! The clauses present (formula, then lemmas, less deletions) are kept
//! with their top-level unit propagation done. A lemma is checked by
//! assigning its negation on top of that and propagating (RUP); failing
//! that, by checking every resolvent on its first literal the same way
//! (RAT). Soundness does not rest on following every deletion: each check
//! is made against the clauses actually present, and both RUP and RAT
//! lemmas keep those satisfiable when they were.

use std::collections::HashMap;

use crate::parse::{Cnf, Proof, Step};
use crate::ProofError;

/// What a successful check found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verified {
    /// Lemmas checked.
    pub lemmas: usize,
    /// Of them, RAT (not RUP) lemmas.
    pub rat_lemmas: usize,
    /// Clauses deleted.
    pub deletions: usize,
    /// Deletions of clauses that were not present (ignored).
    pub missing_deletions: usize,
    /// The proof line at which unit propagation reached a conflict (0:
    /// the formula alone already did).
    pub refuted_at_line: usize,
}

/// Literal `l` (DIMACS) as an index: `2 (|l| - 1) + (l < 0)`.
fn code(l: i32) -> usize {
    2 * (l.unsigned_abs() as usize - 1) + usize::from(l < 0)
}

struct Db {
    lits: Vec<Vec<usize>>,
    alive: Vec<bool>,
    /// `watches[l]`: clauses watching literal `l` (visited when `l` turns false).
    watches: Vec<Vec<usize>>,
    /// Per variable: 0 unassigned, 1 true, -1 false.
    value: Vec<i8>,
    /// Per variable: the clause that set it at the top level.
    reason: Vec<Option<usize>>,
    trail: Vec<usize>,
    head: usize,
    /// Clause ids by sorted literals, for deletions.
    index: HashMap<Vec<usize>, Vec<usize>>,
    /// A deleted clause was a top-level reason: propagate again from scratch.
    dirty: bool,
}

impl Db {
    fn new(vars: usize) -> Db {
        Db {
            lits: Vec::new(),
            alive: Vec::new(),
            watches: vec![Vec::new(); 2 * vars],
            value: vec![0; vars],
            reason: vec![None; vars],
            trail: Vec::new(),
            head: 0,
            index: HashMap::new(),
            dirty: false,
        }
    }

    fn val(&self, l: usize) -> i8 {
        let v = self.value[l >> 1];
        if l & 1 == 1 {
            -v
        } else {
            v
        }
    }

    fn assign(&mut self, l: usize, reason: Option<usize>) {
        self.value[l >> 1] = if l & 1 == 1 { -1 } else { 1 };
        self.reason[l >> 1] = reason;
        self.trail.push(l);
    }

    fn undo(&mut self, to: usize) {
        for &l in &self.trail[to..] {
            self.value[l >> 1] = 0;
            self.reason[l >> 1] = None;
        }
        self.trail.truncate(to);
        self.head = self.head.min(to);
    }

    /// Unit propagation; `true` on a conflict.
    fn propagate(&mut self) -> bool {
        while self.head < self.trail.len() {
            let falsified = self.trail[self.head] ^ 1;
            self.head += 1;
            let mut list = std::mem::take(&mut self.watches[falsified]);
            let mut keep = 0;
            let mut conflict = false;
            let mut i = 0;
            while i < list.len() {
                let c = list[i];
                i += 1;
                if !self.alive[c] {
                    continue;
                }
                if conflict {
                    list[keep] = c;
                    keep += 1;
                    continue;
                }
                let lits = &mut self.lits[c];
                if lits[0] == falsified {
                    lits.swap(0, 1);
                }
                let other = lits[0];
                let v0 = {
                    let v = self.value[other >> 1];
                    if other & 1 == 1 {
                        -v
                    } else {
                        v
                    }
                };
                if v0 == 1 {
                    list[keep] = c;
                    keep += 1;
                    continue;
                }
                let value = &self.value;
                let free = (2..lits.len()).find(|&k| {
                    let l = lits[k];
                    let v = value[l >> 1];
                    (if l & 1 == 1 { -v } else { v }) != -1
                });
                if let Some(k) = free {
                    lits.swap(1, k);
                    let w = lits[1];
                    self.watches[w].push(c);
                    continue;
                }
                list[keep] = c;
                keep += 1;
                if v0 == -1 {
                    conflict = true;
                } else {
                    self.assign(other, Some(c));
                }
            }
            list.truncate(keep);
            let added = std::mem::replace(&mut self.watches[falsified], list);
            self.watches[falsified].extend(added);
            if conflict {
                return true;
            }
        }
        false
    }

    /// Adds a clause at the top level (no temporary assignment); `true`
    /// when the clauses present now propagate to a conflict.
    fn add(&mut self, clause: &[i32]) -> bool {
        let mut lits: Vec<usize> = clause.iter().map(|&l| code(l)).collect();
        lits.sort_unstable();
        lits.dedup();
        let id = self.lits.len();
        self.index.entry(lits.clone()).or_default().push(id);
        let tautology = lits.windows(2).any(|w| w[0] ^ 1 == w[1]);
        // Watch the non-false literals first, true ones before the rest.
        lits.sort_by_key(|&l| match self.val(l) {
            1 => 0,
            0 => 1,
            _ => 2,
        });
        self.lits.push(lits);
        self.alive.push(true);
        let lits = &self.lits[id];
        if tautology {
            return false;
        }
        match lits.len() {
            0 => return true,
            1 => {}
            _ => {
                let (a, b) = (lits[0], lits[1]);
                self.watches[a].push(id);
                self.watches[b].push(id);
            }
        }
        let first = lits[0];
        match self.val(first) {
            -1 => true,
            1 => false,
            _ if lits.len() == 1 || self.val(lits[1]) == -1 => {
                self.assign(first, Some(id));
                self.propagate()
            }
            _ => false,
        }
    }

    /// Deletes a clause with these literals; `false` when none is present.
    fn delete(&mut self, clause: &[i32]) -> bool {
        let mut lits: Vec<usize> = clause.iter().map(|&l| code(l)).collect();
        lits.sort_unstable();
        lits.dedup();
        let Some(id) = self.index.get_mut(&lits).and_then(Vec::pop) else {
            return false;
        };
        self.alive[id] = false;
        let first = self.lits[id][0];
        if self.reason[first >> 1] == Some(id) {
            self.dirty = true;
        }
        true
    }

    /// Propagates the top level again from scratch (after a reason was
    /// deleted); `true` on a conflict.
    fn rebuild(&mut self) -> bool {
        self.dirty = false;
        self.undo(0);
        self.head = 0;
        for id in 0..self.lits.len() {
            if self.alive[id] && self.lits[id].len() == 1 {
                let l = self.lits[id][0];
                match self.val(l) {
                    -1 => return true,
                    0 => self.assign(l, Some(id)),
                    _ => {}
                }
            }
        }
        self.propagate()
    }

    /// Whether assigning the negation of `lits` propagates to a conflict.
    fn rup(&mut self, lits: &[usize]) -> bool {
        let saved = self.trail.len();
        for &l in lits {
            match self.val(l) {
                1 => {
                    self.undo(saved);
                    return true;
                }
                -1 => {}
                _ => self.assign(l ^ 1, None),
            }
        }
        let conflict = self.propagate();
        self.undo(saved);
        self.head = saved;
        conflict
    }

    /// Whether `lemma` is a RAT on its first literal: every resolvent with
    /// a clause present that holds the negation is a tautology or RUP.
    fn rat(&mut self, lemma: &[usize]) -> bool {
        let Some(&pivot) = lemma.first() else {
            return false;
        };
        for id in 0..self.lits.len() {
            if !self.alive[id] || !self.lits[id].contains(&(pivot ^ 1)) {
                continue;
            }
            let mut resolvent: Vec<usize> = lemma.to_vec();
            resolvent.extend(self.lits[id].iter().copied().filter(|&l| l != pivot ^ 1));
            resolvent.sort_unstable();
            resolvent.dedup();
            if resolvent.windows(2).any(|w| w[0] ^ 1 == w[1]) {
                continue;
            }
            if !self.rup(&resolvent) {
                return false;
            }
        }
        true
    }
}

/// Replays `proof` against `cnf`: `Ok` when it proves `cnf` unsatisfiable.
pub fn check(cnf: &Cnf, proof: &Proof) -> Result<Verified, ProofError> {
    let mut verified = Verified {
        lemmas: 0,
        rat_lemmas: 0,
        deletions: 0,
        missing_deletions: 0,
        refuted_at_line: 0,
    };
    let vars = cnf.vars().max(max_var(proof));
    let mut db = Db::new(vars);
    for clause in cnf.clauses() {
        if db.add(clause) {
            return Ok(verified);
        }
    }
    for (step, (line, s)) in proof.steps().iter().enumerate() {
        if db.dirty && db.rebuild() {
            verified.refuted_at_line = *line;
            return Ok(verified);
        }
        match s {
            Step::Delete(lits) => {
                verified.deletions += 1;
                if !db.delete(lits) {
                    verified.missing_deletions += 1;
                }
            }
            Step::Add(lemma) => {
                verified.lemmas += 1;
                let codes: Vec<usize> = lemma.iter().map(|&l| code(l)).collect();
                if !db.rup(&codes) {
                    if !db.rat(&codes) {
                        return Err(ProofError::NotImplied {
                            line: *line,
                            step: step + 1,
                            lemma: dimacs(lemma),
                        });
                    }
                    verified.rat_lemmas += 1;
                }
                if db.add(lemma) {
                    verified.refuted_at_line = *line;
                    return Ok(verified);
                }
            }
        }
    }
    if db.dirty && db.rebuild() {
        verified.refuted_at_line = proof.last_line();
        return Ok(verified);
    }
    Err(ProofError::Incomplete {
        line: proof.last_line(),
    })
}

fn max_var(proof: &Proof) -> usize {
    proof
        .steps()
        .iter()
        .flat_map(|(_, s)| match s {
            Step::Add(l) | Step::Delete(l) => l.iter(),
        })
        .map(|l| l.unsigned_abs() as usize)
        .max()
        .unwrap_or(0)
}

fn dimacs(lits: &[i32]) -> String {
    let mut s: String = lits.iter().map(|l| format!("{l} ")).collect();
    s.push('0');
    s
}
