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
/// Every clause added is a header (its size, with [`DEAD`] once deleted)
/// followed by its literals in `arena`, and is named by the offset of its
/// first literal. A clause of two or more literals is watched by its first
/// two, in `watches` of each with the other as its blocker (a binary
/// clause's watch is marked [`BINARY`]: its blocker is the rest of the
/// clause, so propagation reads the arena only for its header); at the top
/// level (between steps) every watch is true or unassigned unless the other
/// watch is true.
struct Db {
    arena: Vec<u32>,
    /// `watches[l]`: (clause, blocker) of the clauses watching literal `l`
    /// (visited when `l` turns false); the clause carries [`BINARY`] when
    /// it has two literals.
    watches: Vec<Vec<(u32, u32)>>,
    /// Per literal: 0 unassigned, 1 true, -1 false.
    value: Vec<i8>,
    /// Per variable: the clause that set it at the top level.
    reason: Vec<Option<u32>>,
    trail: Vec<u32>,
    head: usize,
    /// Clauses by sorted literals, for deletions (built at the first).
    index: Option<Index>,
    /// The unit clauses added (deleted ones too), for [`Db::rebuild`].
    units: Vec<u32>,
    /// A deleted clause was a top-level reason: propagate again from scratch.
    dirty: bool,
    /// Words of deleted clauses still in `arena`.
    dead: usize,
    /// Compact once `dead` is past this and half the arena.
    compact_at: usize,
}

/// Clauses by their sorted literals.
type Index = rustc_hash::FxHashMap<Vec<u32>, Vec<u32>>;

/// The mark of a binary clause in its watches.
const BINARY: u32 = 1 << 31;
/// The mark of a deleted clause in its header.
const DEAD: u32 = 1 << 31;

impl Db {
    fn new(vars: usize) -> Db {
        Db {
            arena: Vec::new(),
            watches: vec![Vec::new(); 2 * vars],
            value: vec![0; 2 * vars],
            reason: vec![None; vars],
            trail: Vec::new(),
            head: 0,
            index: None,
            units: Vec::new(),
            dirty: false,
            dead: 0,
            compact_at: 1 << 22,
        }
    }

    /// Whether the deleted clauses hold more of `arena` than the clauses
    /// present (and a few million literals): time for [`Db::compacted`].
    fn wasteful(&self) -> bool {
        self.dead > self.compact_at && 2 * self.dead > self.arena.len()
    }

    /// The clauses present, in order, in a fresh database (deleted clauses
    /// dropped: a long proof's memory stays that of the clauses present),
    /// and whether they propagate to a conflict.
    fn compacted(&self) -> (Db, bool) {
        let mut db = Db::new(self.reason.len());
        db.compact_at = self.compact_at;
        let mut conflict = false;
        for c in self.clauses().filter(|&c| self.is_alive(c)) {
            let clause: Vec<i32> = self
                .lits(c)
                .iter()
                .map(|&l| {
                    let v = (l >> 1) as i32 + 1;
                    if l & 1 == 1 {
                        -v
                    } else {
                        v
                    }
                })
                .collect();
            conflict |= db.add(&clause);
        }
        (db, conflict)
    }

    /// Makes room for the variables of `clause` (a proof may name
    /// variables the formula's header does not).
    fn grow(&mut self, clause: &[i32]) {
        let Some(vars) = clause.iter().map(|l| l.unsigned_abs() as usize).max() else {
            return;
        };
        if vars > self.reason.len() {
            self.watches.resize(2 * vars, Vec::new());
            self.value.resize(2 * vars, 0);
            self.reason.resize(vars, None);
        }
    }

    /// Every clause added (deleted ones too), in order.
    fn clauses(&self) -> impl Iterator<Item = usize> + '_ {
        let mut header = 0;
        std::iter::from_fn(move || {
            let c = header + 1;
            (c <= self.arena.len()).then(|| {
                header = c + self.size(c);
                c
            })
        })
    }

    fn size(&self, c: usize) -> usize {
        (self.arena[c - 1] & !DEAD) as usize
    }

    fn is_alive(&self, c: usize) -> bool {
        self.arena[c - 1] & DEAD == 0
    }

    fn lits(&self, c: usize) -> &[u32] {
        &self.arena[c..c + self.size(c)]
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
                let blocked = self.value[blocker as usize];
                if blocked == 1 {
                    list[keep] = (c, blocker);
                    keep += 1;
                    continue;
                }
                let s = (c & !BINARY) as usize;
                let header = self.arena[s - 1];
                if header & DEAD != 0 {
                    continue;
                }
                if c & BINARY != 0 {
                    list[keep] = (c, blocker);
                    keep += 1;
                    if blocked == -1 {
                        conflict = true;
                        break;
                    }
                    self.assign(blocker, Some(s as u32));
                    continue;
                }
                if self.arena[s] == falsified {
                    self.arena.swap(s, s + 1);
                }
                let other = self.arena[s];
                if self.value[other as usize] == 1 {
                    list[keep] = (c, other);
                    keep += 1;
                    continue;
                }
                let end = s + header as usize;
                let free = (s + 2..end).find(|&k| self.value[self.arena[k] as usize] != -1);
                if let Some(k) = free {
                    self.arena.swap(s + 1, k);
                    let w = self.arena[s + 1];
                    self.watches[w as usize].push((c, other));
                    continue;
                }
                list[keep] = (c, other);
                keep += 1;
                if self.value[other as usize] == -1 {
                    conflict = true;
                    break;
                }
                self.assign(other, Some(c));
            }
            if conflict {
                // Keep the watches not visited.
                while i < list.len() {
                    list[keep] = list[i];
                    keep += 1;
                    i += 1;
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
        let c = self.arena.len() + 1;
        assert!(
            c + lits.len() < BINARY as usize,
            "over 2^31 literals present"
        );
        let id = c as u32;
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
        self.arena.push(lits.len() as u32);
        self.arena.extend_from_slice(&lits);
        if tautology {
            return false;
        }
        match lits.len() {
            0 => return true,
            1 => self.units.push(id),
            _ => {
                let (a, b) = (lits[0], lits[1]);
                let mark = if lits.len() == 2 { id | BINARY } else { id };
                self.watches[a as usize].push((mark, b));
                self.watches[b as usize].push((mark, a));
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
            let mut index = Index::default();
            for c in self.clauses().filter(|&c| self.is_alive(c)) {
                let mut key = self.lits(c).to_vec();
                key.sort_unstable();
                index.entry(key).or_default().push(c as u32);
            }
            self.index = Some(index);
        }
        let lits = codes(clause);
        let found = self
            .index
            .as_mut()
            .and_then(|index| index.get_mut(&lits))
            .and_then(Vec::pop);
        let Some(c) = found else {
            return false;
        };
        let c = c as usize;
        self.arena[c - 1] |= DEAD;
        self.dead += 1 + self.size(c);
        // The literal a clause implied is its first, or either of a
        // binary clause's (their watches never reorder them).
        let implied = self.lits(c).iter().take(2);
        if implied
            .into_iter()
            .any(|&l| self.reason[(l >> 1) as usize] == Some(c as u32))
        {
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
        self.units
            .retain(|&c| self.arena[c as usize - 1] & DEAD == 0);
        for k in 0..self.units.len() {
            let c = self.units[k];
            let l = self.arena[c as usize];
            match self.value[l as usize] {
                -1 => return true,
                0 => self.assign(l, Some(c)),
                _ => {}
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
        let holders: Vec<usize> = self
            .clauses()
            .filter(|&c| self.is_alive(c) && self.lits(c).contains(&(pivot ^ 1)))
            .collect();
        for c in holders {
            let mut resolvent: Vec<u32> = lemma.to_vec();
            resolvent.extend(self.lits(c).iter().copied().filter(|&l| l != pivot ^ 1));
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
    let mut checker = Checker::new(cnf);
    for (line, step) in proof.steps() {
        if checker.step(*line, step)? {
            break;
        }
    }
    checker.finish(proof.last_line())
}

/// [`check`] a step at a time, for a proof read as it goes
/// ([`ProofStream`](crate::ProofStream)): only the clauses present are
/// held, never the proof.
pub struct Checker {
    db: Db,
    verified: Verified,
    /// Steps seen.
    steps: usize,
    /// The clauses present propagated to a conflict: proved.
    refuted: bool,
    /// Times the deleted clauses were dropped from memory.
    compactions: usize,
}

impl Checker {
    /// A checker of proofs of `cnf`, its clauses added.
    pub fn new(cnf: &Cnf) -> Checker {
        let mut checker = Checker {
            db: Db::new(cnf.vars()),
            verified: Verified {
                lemmas: 0,
                rat_lemmas: 0,
                deletions: 0,
                missing_deletions: 0,
                refuted_at_line: 0,
            },
            steps: 0,
            refuted: false,
            compactions: 0,
        };
        for clause in cnf.clauses() {
            checker.db.grow(clause);
            if checker.db.add(clause) {
                checker.refuted = true;
                break;
            }
        }
        checker
    }

    /// Checks the next step, which starts on `line` of the proof: `true`
    /// once the formula is refuted (the steps after that are not looked
    /// at), an error when a lemma is neither RUP nor RAT.
    pub fn step(&mut self, line: usize, step: &Step) -> Result<bool, ProofError> {
        if self.refuted {
            return Ok(true);
        }
        self.steps += 1;
        if self.db.dirty && self.db.rebuild() {
            return Ok(self.refute(line));
        }
        match step {
            Step::Delete(lits) => {
                self.verified.deletions += 1;
                if !self.db.delete(lits) {
                    self.verified.missing_deletions += 1;
                }
                if self.db.wasteful() {
                    let (db, conflict) = self.db.compacted();
                    self.db = db;
                    self.compactions += 1;
                    if conflict {
                        return Ok(self.refute(line));
                    }
                }
            }
            Step::Add(lemma) => {
                self.db.grow(lemma);
                self.verified.lemmas += 1;
                // The pivot (the first literal) first, for RAT.
                let codes: Vec<u32> = lemma.iter().map(|&l| code(l)).collect();
                if !self.db.rup(&codes) {
                    if !self.db.rat(&codes) {
                        return Err(ProofError::NotImplied {
                            line,
                            step: self.steps,
                            lemma: dimacs(lemma),
                        });
                    }
                    self.verified.rat_lemmas += 1;
                }
                if self.db.add(lemma) {
                    return Ok(self.refute(line));
                }
            }
        }
        Ok(false)
    }

    fn refute(&mut self, line: usize) -> bool {
        self.refuted = true;
        self.verified.refuted_at_line = line;
        true
    }

    /// The end of the proof, whose last line is `last_line`: `Ok` when the
    /// formula is refuted.
    pub fn finish(mut self, last_line: usize) -> Result<Verified, ProofError> {
        if !self.refuted && self.db.dirty && self.db.rebuild() {
            self.refute(last_line);
        }
        if self.refuted {
            Ok(self.verified)
        } else {
            Err(ProofError::Incomplete { line: last_line })
        }
    }
}

pub(crate) fn dimacs(lits: &[i32]) -> String {
    let mut s: String = lits.iter().map(|l| format!("{l} ")).collect();
    s.push('0');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks `proof` against `cnf` compacting after every deletion that
    /// leaves more dead literals than live ones.
    fn check_compacting(cnf: &Cnf, proof: &Proof) -> (Result<Verified, ProofError>, usize) {
        let mut checker = Checker::new(cnf);
        checker.db.compact_at = 0;
        for (line, step) in proof.steps() {
            match checker.step(*line, step) {
                Ok(true) => break,
                Ok(false) => {}
                Err(e) => return (Err(e), checker.compactions),
            }
        }
        let n = checker.compactions;
        (checker.finish(proof.last_line()), n)
    }

    #[test]
    fn compacting_the_clauses_present_changes_no_answer() {
        let mut x: u64 = 0x2545_f491_4f6c_dd1d;
        let mut below = |n: u64| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x % n
        };
        let mut compactions = 0;
        for _ in 0..1000 {
            let vars = 2 + below(4) as i32;
            let clause = |below: &mut dyn FnMut(u64) -> u64| -> Vec<i32> {
                (0..1 + below(3))
                    .map(|_| {
                        let v = 1 + below(vars as u64) as i32;
                        if below(2) == 0 {
                            v
                        } else {
                            -v
                        }
                    })
                    .collect()
            };
            let clauses: Vec<Vec<i32>> = (0..2 + below(12)).map(|_| clause(&mut below)).collect();
            let cnf = Cnf::new(vars as usize, clauses.clone());
            // Lemmas and deletions of the formula's clauses and of lemmas.
            let mut text = String::new();
            let mut added: Vec<Vec<i32>> = Vec::new();
            for _ in 0..below(12) {
                let (del, c) = match below(3) {
                    0 => (true, clauses[below(clauses.len() as u64) as usize].clone()),
                    1 if !added.is_empty() => {
                        (true, added[below(added.len() as u64) as usize].clone())
                    }
                    _ => (false, clause(&mut below)),
                };
                if !del {
                    added.push(c.clone());
                }
                text.push_str(if del { "d " } else { "" });
                text.push_str(&dimacs(&c));
                text.push('\n');
            }
            text.push_str("0\n");
            let proof = Proof::parse(&text).unwrap();
            let (answer, n) = check_compacting(&cnf, &proof);
            assert_eq!(answer, check(&cnf, &proof), "{text}");
            compactions += n;
        }
        assert!(compactions > 100, "{compactions} compactions");
    }
}
