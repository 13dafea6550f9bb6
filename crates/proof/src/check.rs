//! Forward DRAT checking with two watched literals.
//!
//! The clauses present (formula, then lemmas, less deletions) are kept
//! with their top-level unit propagation done. A lemma is checked by
//! assigning its negation on top of that and propagating (RUP); failing
//! that, by checking every resolvent on its first literal the same way
//! (RAT). Soundness does not rest on following every deletion: each check
//! is made against the clauses actually present, and both RUP and RAT
//! lemmas keep those satisfiable when they were.

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
fn code(l: i32) -> u32 {
    2 * (l.unsigned_abs() - 1) + u32::from(l < 0)
}

/// The literals of `clause` as sorted, distinct codes.
fn codes(clause: &[i32]) -> Vec<u32> {
    let mut lits: Vec<u32> = clause.iter().map(|&l| code(l)).collect();
    lits.sort_unstable();
    lits.dedup();
    lits
}

/// The clauses present and their top-level unit propagation.
///
/// # Validity
/// Clause `c` is `arena[start[c]..start[c] + size[c]]`; a clause of two or
/// more literals is watched by its first two, in `watches` of each with the
/// other as its blocker; at the top level (between steps) every watch is
/// true or unassigned unless the other watch is true.
struct Db {
    arena: Vec<u32>,
    start: Vec<usize>,
    size: Vec<u32>,
    alive: Vec<bool>,
    /// `watches[l]`: (clause, blocker) of the clauses watching literal `l`
    /// (visited when `l` turns false).
    watches: Vec<Vec<(u32, u32)>>,
    /// Per literal: 0 unassigned, 1 true, -1 false.
    value: Vec<i8>,
    /// Per variable: the clause that set it at the top level.
    reason: Vec<Option<u32>>,
    trail: Vec<u32>,
    head: usize,
    /// Clause ids by sorted literals, for deletions (built at the first).
    index: Option<std::collections::HashMap<Vec<u32>, Vec<u32>>>,
    /// A deleted clause was a top-level reason: propagate again from scratch.
    dirty: bool,
}

impl Db {
    fn new(vars: usize) -> Db {
        Db {
            arena: Vec::new(),
            start: Vec::new(),
            size: Vec::new(),
            alive: Vec::new(),
            watches: vec![Vec::new(); 2 * vars],
            value: vec![0; 2 * vars],
            reason: vec![None; vars],
            trail: Vec::new(),
            head: 0,
            index: None,
            dirty: false,
        }
    }

    fn lits(&self, c: usize) -> &[u32] {
        &self.arena[self.start[c]..self.start[c] + self.size[c] as usize]
    }

    fn assign(&mut self, l: u32, reason: Option<u32>) {
        self.value[l as usize] = 1;
        self.value[(l ^ 1) as usize] = -1;
        self.reason[(l >> 1) as usize] = reason;
        self.trail.push(l);
    }

    fn undo(&mut self, to: usize) {
        for &l in &self.trail[to..] {
            self.value[l as usize] = 0;
            self.value[(l ^ 1) as usize] = 0;
            self.reason[(l >> 1) as usize] = None;
        }
        self.trail.truncate(to);
        self.head = self.head.min(to);
    }

    /// Unit propagation; `true` on a conflict.
    fn propagate(&mut self) -> bool {
        while self.head < self.trail.len() {
            let falsified = self.trail[self.head] ^ 1;
            self.head += 1;
            let mut list = std::mem::take(&mut self.watches[falsified as usize]);
            let (mut i, mut keep) = (0, 0);
            let mut conflict = false;
            while i < list.len() {
                let (c, blocker) = list[i];
                i += 1;
                if self.value[blocker as usize] == 1 {
                    list[keep] = (c, blocker);
                    keep += 1;
                    continue;
                }
                let c = c as usize;
                if !self.alive[c] {
                    continue;
                }
                let (s, n) = (self.start[c], self.size[c] as usize);
                if self.arena[s] == falsified {
                    self.arena.swap(s, s + 1);
                }
                let other = self.arena[s];
                if self.value[other as usize] == 1 {
                    list[keep] = (c as u32, other);
                    keep += 1;
                    continue;
                }
                let free = (s + 2..s + n).find(|&k| self.value[self.arena[k] as usize] != -1);
                if let Some(k) = free {
                    self.arena.swap(s + 1, k);
                    let w = self.arena[s + 1];
                    self.watches[w as usize].push((c as u32, other));
                    continue;
                }
                list[keep] = (c as u32, other);
                keep += 1;
                if self.value[other as usize] == -1 {
                    conflict = true;
                    while i < list.len() {
                        list[keep] = list[i];
                        keep += 1;
                        i += 1;
                    }
                } else {
                    self.assign(other, Some(c as u32));
                }
            }
            list.truncate(keep);
            self.watches[falsified as usize] = list;
            if conflict {
                return true;
            }
        }
        false
    }

    /// Adds a clause at the top level (no temporary assignment); `true`
    /// when the clauses present now propagate to a conflict.
    fn add(&mut self, clause: &[i32]) -> bool {
        let mut lits = codes(clause);
        let id = self.start.len() as u32;
        if let Some(index) = &mut self.index {
            index.entry(lits.clone()).or_default().push(id);
        }
        let tautology = lits.windows(2).any(|w| w[0] ^ 1 == w[1]);
        // Watch the non-false literals first, true ones before the rest.
        lits.sort_by_key(|&l| match self.value[l as usize] {
            1 => 0,
            0 => 1,
            _ => 2,
        });
        self.start.push(self.arena.len());
        self.size.push(lits.len() as u32);
        self.arena.extend_from_slice(&lits);
        self.alive.push(true);
        if tautology {
            return false;
        }
        match lits.len() {
            0 => return true,
            1 => {}
            _ => {
                let (a, b) = (lits[0], lits[1]);
                self.watches[a as usize].push((id, b));
                self.watches[b as usize].push((id, a));
            }
        }
        let first = lits[0];
        match self.value[first as usize] {
            -1 => true,
            1 => false,
            _ if lits.len() == 1 || self.value[lits[1] as usize] == -1 => {
                self.assign(first, Some(id));
                self.propagate()
            }
            _ => false,
        }
    }

    /// Deletes a clause with these literals; `false` when none is present.
    fn delete(&mut self, clause: &[i32]) -> bool {
        if self.index.is_none() {
            let mut index: std::collections::HashMap<Vec<u32>, Vec<u32>> =
                std::collections::HashMap::new();
            for c in 0..self.start.len() {
                if self.alive[c] {
                    let mut key = self.lits(c).to_vec();
                    key.sort_unstable();
                    index.entry(key).or_default().push(c as u32);
                }
            }
            self.index = Some(index);
        }
        let lits = codes(clause);
        let found = self
            .index
            .as_mut()
            .and_then(|index| index.get_mut(&lits))
            .and_then(Vec::pop);
        let Some(id) = found else {
            return false;
        };
        self.alive[id as usize] = false;
        if let Some(&first) = self.lits(id as usize).first() {
            if self.reason[(first >> 1) as usize] == Some(id) {
                self.dirty = true;
            }
        }
        true
    }

    /// Propagates the top level again from scratch (after a reason was
    /// deleted); `true` on a conflict.
    fn rebuild(&mut self) -> bool {
        self.dirty = false;
        self.undo(0);
        self.head = 0;
        for id in 0..self.start.len() {
            if self.alive[id] && self.size[id] == 1 {
                let l = self.arena[self.start[id]];
                match self.value[l as usize] {
                    -1 => return true,
                    0 => self.assign(l, Some(id as u32)),
                    _ => {}
                }
            }
        }
        self.propagate()
    }

    /// Whether assigning the negation of `lits` propagates to a conflict.
    fn rup(&mut self, lits: &[u32]) -> bool {
        let saved = self.trail.len();
        for &l in lits {
            match self.value[l as usize] {
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
    fn rat(&mut self, lemma: &[u32]) -> bool {
        let Some(&pivot) = lemma.first() else {
            return false;
        };
        for id in 0..self.start.len() {
            if !self.alive[id] || !self.lits(id).contains(&(pivot ^ 1)) {
                continue;
            }
            let mut resolvent: Vec<u32> = lemma.to_vec();
            resolvent.extend(self.lits(id).iter().copied().filter(|&l| l != pivot ^ 1));
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
                // The pivot (the first literal) first, for RAT.
                let codes: Vec<u32> = lemma.iter().map(|&l| code(l)).collect();
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

pub(crate) fn dimacs(lits: &[i32]) -> String {
    let mut s: String = lits.iter().map(|l| format!("{l} ")).collect();
    s.push('0');
    s
}
