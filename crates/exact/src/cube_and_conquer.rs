//! Cube-and-conquer: "at most K pieces" split into cubes solved in
//! parallel.
//!
//! The cubes are the literals `l_1, ..., l_m` of one at-least-one clause
//! `C = (l_1 ∨ ... ∨ l_m)` of the base formula `F` (`Encoding::cube`:
//! piece 0's motions into the second figure, or the pieces a cell may
//! be in). Cube `j` is `F ∧ l_j`, solved on its own (its own solver, its
//! own connectivity encoding and cuts) by one of the worker threads, which
//! take the cubes in order from a shared counter. Every model of `F`
//! satisfies `C`, so some `l_j`: `F` is unsatisfiable exactly when every
//! cube is. The answer does not depend on the timing: UNSAT when every cube
//! is refuted, a dissection when one cube finds one (the first cube in
//! order among those that found one), otherwise unknown.
//!
//! A clause of hundreds of literals (piece 0 has a motion per cell of the
//! second figure) would make as many cubes, each building the encoding
//! again; so the literals are first grouped ([`add_groups`]): group
//! variables `g_1, ..., g_G` (`G` = [`CUBES_PER_THREAD`] × threads) with
//! `g_i → (the literals of chunk i)` and `l → g_i` for each of them, and
//! the clause `(g_1 ∨ ... ∨ g_G)`. Every model of the formula extends to
//! them (`g_i` = some literal of chunk `i` is true), so the formula with
//! them is satisfiable exactly when it was; they belong to the base
//! formula and the cubes are the `g_i`.
//!
//! The certificate ([`Certificate::cubes`]) is the base formula, and per
//! cube the clauses added to it (the unit `l_j` first, then the
//! connectivity encoding and cuts it met) with the DRAT proof refuting the
//! base plus them; `dissect-proof` checks that `C` is a clause of the base
//! and that every literal has its cube.

use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use crate::certificate::{Certificate, CubeProof};
use crate::incompatible_clique::Incompatibility;
use crate::placement_encoding::{encode, MotionEncoding};
use crate::sat_backend::Sat;
use crate::search::{Connected, Cutting, ExactEvent, Pass};
use crate::MotionSet;

/// Cubes per thread: enough for the threads to share the work evenly,
/// few enough that building each cube's encoding costs little.
pub(crate) const CUBES_PER_THREAD: usize = 8;

/// Groups the literals of the at-least-one clause `clause` into at most
/// `groups` contiguous chunks, each defined by a new variable (see the
/// module), and adds the clause of those variables; returns it (the cover).
/// A clause of at most `groups` literals is returned as it is.
pub(crate) fn add_groups(sat: &mut Sat<'_>, clause: &[i32], groups: usize) -> Vec<i32> {
    if clause.len() <= groups.max(1) {
        return clause.to_vec();
    }
    let size = clause.len().div_ceil(groups.max(1));
    let mut cover = Vec::with_capacity(groups);
    for chunk in clause.chunks(size) {
        let g = sat.var();
        let mut some = vec![-g];
        some.extend(chunk);
        sat.add(&some);
        for &l in chunk {
            sat.add(&[-l, g]);
        }
        cover.push(g);
    }
    sat.add(&cover);
    cover
}

/// The settings of a cubed pass.
pub(crate) struct Cubes<'a> {
    pub cutting: &'a Cutting<'a>,
    pub clique: &'a [usize],
    pub incompat: &'a [Incompatibility],
    pub stop: &'a AtomicBool,
    pub upper: &'a AtomicUsize,
    pub style: MotionEncoding,
    pub certify: bool,
    pub sink: Option<&'a crate::ProofSink>,
    pub threads: usize,
}

/// What one cube ended with.
enum Answer {
    Unsat(Option<CubeProof>, usize),
    Found(Vec<Vec<Vec<usize>>>),
    Unknown,
}

impl Cubes<'_> {
    /// Solves the cubes `cube` (the cover [`add_groups`] returned for the
    /// encoding of `k` pieces; the base formula with the groups was
    /// `base`: its DIMACS text when recording, and its clause count) on
    /// [`Cubes::threads`] threads, each cube until the deadline or
    /// `conflicts_each` conflicts. Returns the pass and the conflicts
    /// spent.
    pub(crate) fn pass(
        &self,
        k: usize,
        cube: &[i32],
        base: (Option<String>, usize),
        (deadline, conflicts_each): (Option<Instant>, Option<u64>),
        start: Instant,
    ) -> (Pass, u64) {
        let next = AtomicUsize::new(0);
        let abort = AtomicBool::new(false);
        let spent_all = AtomicU64::new(0);
        if cube.is_empty() {
            return (Pass::Unknown, 0);
        }
        let answers = Mutex::new(self.kept(k, cube, base.0.as_deref()));
        let threads = self.threads.clamp(1, cube.len());
        // Workers that have ended, counted even when one panics (the
        // monitor below must not wait for it).
        let ended = AtomicUsize::new(0);
        struct Ended<'a>(&'a AtomicUsize);
        impl Drop for Ended<'_> {
            fn drop(&mut self) {
                self.0.fetch_add(1, Ordering::SeqCst);
            }
        }
        std::thread::scope(|scope| {
            for _ in 0..threads {
                scope.spawn(|| {
                    let _ended = Ended(&ended);
                    self.work(
                        k,
                        cube,
                        (base.1, conflicts_each),
                        (&next, &abort),
                        deadline,
                        (&answers, &spent_all),
                    );
                });
            }
            // The caller's stop flag ends the cubes too.
            scope.spawn(|| {
                while ended.load(Ordering::SeqCst) < threads {
                    if self.stop.load(Ordering::Relaxed) {
                        abort.store(true, Ordering::SeqCst);
                    }
                    std::thread::sleep(Duration::from_millis(20));
                }
            });
        });
        let answers = answers.into_inner().unwrap_or_else(|e| e.into_inner());
        let spent = spent_all.load(Ordering::SeqCst);
        (self.gather(k, answers, base.0, start), spent)
    }

    /// The answers known before solving: the cubes the proof writers
    /// already hold refuted for this base and cover (each announced as
    /// [`ExactEvent::CubeKept`]).
    fn kept(&self, k: usize, cube: &[i32], base: Option<&str>) -> Vec<Option<Answer>> {
        let held = match (self.certify, self.sink, base) {
            (true, Some(sink), Some(base)) => sink.writers().begin(k, base, cube),
            _ => Vec::new(),
        };
        let mut answers: Vec<Option<Answer>> = (0..cube.len()).map(|_| None).collect();
        for (j, proof) in held.into_iter().enumerate().take(cube.len()) {
            let Some(proof) = proof.filter(|p| p.literal == cube[j]) else {
                continue;
            };
            self.cutting.observer.on_event(&ExactEvent::CubeKept {
                pieces: k,
                index: j,
                of: cube.len(),
            });
            let cuts = proof.cuts;
            answers[j] = Some(Answer::Unsat(Some(proof), cuts));
        }
        answers
    }

    /// One worker: takes the next cube until none is left or `abort`
    /// rises, and files each answer; skips the cubes already answered.
    fn work(
        &self,
        k: usize,
        cube: &[i32],
        (base_clauses, conflicts): (usize, Option<u64>),
        (next, abort): (&AtomicUsize, &AtomicBool),
        deadline: Option<Instant>,
        (answers, spent_all): (&Mutex<Vec<Option<Answer>>>, &AtomicU64),
    ) {
        loop {
            let j = next.fetch_add(1, Ordering::SeqCst);
            if j >= cube.len() || abort.load(Ordering::SeqCst) {
                break;
            }
            if answers.lock().unwrap_or_else(|e| e.into_inner())[j].is_some() {
                continue;
            }
            let began = Instant::now();
            let (answer, spent) =
                self.one(k, (j, cube[j]), (base_clauses, conflicts), abort, deadline);
            self.cutting.observer.on_event(&ExactEvent::Cube {
                pieces: k,
                index: j,
                of: cube.len(),
                refuted: matches!(answer, Answer::Unsat(..)),
                seconds: began.elapsed().as_secs_f64(),
            });
            spent_all.fetch_add(spent, Ordering::SeqCst);
            if let (Answer::Unsat(Some(proof), _), Some(sink)) = (&answer, self.sink) {
                sink.writers().refuted(k, j, proof);
            }
            let stop_all = !matches!(answer, Answer::Unsat(..));
            answers.lock().unwrap_or_else(|e| e.into_inner())[j] = Some(answer);
            if stop_all {
                abort.store(true, Ordering::SeqCst);
            }
        }
    }

    /// The pass the cubes' answers make.
    fn gather(
        &self,
        k: usize,
        answers: Vec<Option<Answer>>,
        base: Option<String>,
        start: Instant,
    ) -> Pass {
        let mut proofs = Vec::with_capacity(answers.len());
        let mut cuts = 0;
        let mut unknown = false;
        for answer in answers {
            match answer {
                Some(Answer::Found(p)) => return Pass::Found(p),
                Some(Answer::Unsat(proof, c)) => {
                    cuts += c;
                    proofs.push(proof);
                }
                Some(Answer::Unknown) | None => unknown = true,
            }
        }
        if unknown {
            return Pass::Unknown;
        }
        let certificate = match (base, proofs.into_iter().collect::<Option<Vec<_>>>()) {
            (Some(formula), Some(cubes)) if self.certify => {
                let clauses = formula.lines().count().saturating_sub(1);
                let vars = cubes
                    .iter()
                    .map(|c| c.vars)
                    .max()
                    .unwrap_or(0)
                    .max(header_vars(&formula));
                Some(Box::new(Certificate {
                    pieces: k,
                    formula,
                    proof: String::new(),
                    vars,
                    clauses,
                    cuts,
                    connectivity: cubes.iter().any(|c| c.connectivity),
                    clique_only: false,
                    cubes,
                }))
            }
            _ => None,
        };
        Pass::Unsat {
            cuts,
            seconds: start.elapsed().as_secs_f64(),
            certificate,
        }
    }

    /// Cube `index` (its literal `literal`): the encoding again in a
    /// solver of its own (the same variables, as `encode` is
    /// deterministic), the unit, then the connectivity loop. Returns the
    /// answer and the conflicts spent. When certifying, only the clauses
    /// added after the base formula are recorded, and the proof goes to
    /// the sink's writer when there is one.
    fn one(
        &self,
        k: usize,
        (index, literal): (usize, i32),
        (base_clauses, conflicts): (usize, Option<u64>),
        abort: &AtomicBool,
        deadline: Option<Instant>,
    ) -> (Answer, u64) {
        let interrupted =
            || abort.load(Ordering::Relaxed) || deadline.is_some_and(|d| Instant::now() >= d);
        let mut sat = Sat::new(abort, Some((self.upper, k)));
        sat.set_conflict_limit(conflicts);
        let streamed = self.certify
            && match self.sink.and_then(|s| s.writers().open(k, index)) {
                Some(out) => {
                    sat.record_proof_to(out);
                    true
                }
                None => {
                    sat.record_proof();
                    false
                }
            };
        let inst = self.cutting.inst;
        let Some(enc) = encode(
            inst,
            &mut sat,
            k,
            (MotionSet::All, self.style),
            self.clique,
            self.incompat,
            &interrupted,
        ) else {
            return (Answer::Unknown, 0);
        };
        add_groups(&mut sat, &enc.cube, self.threads * CUBES_PER_THREAD);
        debug_assert_eq!(sat.clauses(), base_clauses, "encode is deterministic");
        if self.certify {
            sat.record();
        }
        sat.add(&[literal]);
        let answer = self
            .cutting
            .solve(&mut sat, &enc, k, deadline, &interrupted);
        let spent = sat.conflicts();
        let answer = match answer {
            Connected::Unknown => Answer::Unknown,
            Connected::Found(p) => Answer::Found(p),
            Connected::Unsat { cuts, connected } => {
                let proof = if !self.certify {
                    None
                } else if streamed {
                    sat.end_proof_stream().map(|lemmas| (None, lemmas))
                } else {
                    sat.proof().map(|p| {
                        let lemmas = p.lines().filter(|l| !l.starts_with('d')).count();
                        (Some(p), lemmas)
                    })
                };
                let proof = proof
                    .zip(sat.dimacs())
                    .map(|((proof, lemmas), (formula, clauses))| CubeProof {
                        literal,
                        formula,
                        clauses,
                        proof,
                        lemmas,
                        vars: sat.vars(),
                        cuts,
                        connectivity: connected,
                    });
                Answer::Unsat(proof, cuts)
            }
        };
        (answer, spent)
    }
}

/// The variables a DIMACS header declares (0 when there is none).
fn header_vars(formula: &str) -> usize {
    formula
        .lines()
        .next()
        .and_then(|l| l.split_whitespace().nth(2))
        .and_then(|v| v.parse().ok())
        .unwrap_or(0)
}
