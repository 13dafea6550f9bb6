//! The SAT backend: the pure-Rust `batsat` crate (a MiniSat descendant). The
//! only module that names the backend, so another one can replace it here
//! alone.
//!
//! Proofs: when asked ([`Sat::record_proof`]), the solver's learnt clauses
//! and deletions (which batsat reports through its callbacks) are kept as a
//! DRAT proof. Every learnt clause of conflict analysis (with its
//! minimisation) is a RUP lemma of the clauses present, and batsat does no
//! other inprocessing (it only drops satisfied clauses, which a proof may
//! keep), so the lemmas, ended by the empty clause, refute the recorded
//! formula; clauses added between solves only make the formula larger, so
//! earlier lemmas stay RUP in it. `dissect-proof` checks this claim on every
//! certificate instead of trusting it.

use batsat::{lbool, ClauseKind, Lit, SolverInterface, SolverOpts};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;

/// Ends a solve when the stop flag rises or the deadline passes.
struct StopCheck<'a> {
    stop: &'a AtomicBool,
    deadline: Option<Instant>,
    /// Give up once the shared upper bound falls to this or below.
    upper: Option<(&'a AtomicUsize, usize)>,
    /// Conflicts (learnt clauses) since the solver was made: a measure of
    /// work that is the same on every machine.
    conflicts: u64,
    /// Give up once `conflicts` reaches this.
    conflict_limit: Option<u64>,
    /// The DRAT proof so far (learnt clauses, `d` deletions), when recording.
    proof: Option<ProofOut>,
}

/// Where a recorded proof goes.
enum ProofOut {
    /// Kept as text, for [`Sat::proof`].
    Memory(String),
    /// Written line by line as the solver goes ([`Sat::record_proof_to`]).
    Stream {
        out: std::io::BufWriter<Box<dyn std::io::Write + Send>>,
        /// The line being written.
        line: String,
        lemmas: usize,
        /// A write failed: the proof is incomplete.
        failed: bool,
    },
}

impl ProofOut {
    fn push(&mut self, prefix: &str, c: &[Lit]) {
        match self {
            ProofOut::Memory(text) => drat_line(text, prefix, c),
            ProofOut::Stream {
                out,
                line,
                lemmas,
                failed,
            } => {
                if *failed {
                    return;
                }
                line.clear();
                drat_line(line, prefix, c);
                if prefix.is_empty() {
                    *lemmas += 1;
                }
                *failed = std::io::Write::write_all(out, line.as_bytes()).is_err();
            }
        }
    }
}

/// Appends `c` to a DRAT text as one line (`prefix` is `""` or `"d "`).
fn drat_line(proof: &mut String, prefix: &str, c: &[Lit]) {
    use std::fmt::Write;
    proof.push_str(prefix);
    for lit in c {
        let v = lit.var().idx() as i64 + 1;
        let _ = write!(proof, "{} ", if lit.sign() { v } else { -v });
    }
    proof.push_str("0\n");
}

impl batsat::Callbacks for StopCheck<'_> {
    fn on_new_clause(&mut self, c: &[Lit], kind: ClauseKind) {
        if kind == ClauseKind::Learnt {
            self.conflicts += 1;
            if let Some(proof) = &mut self.proof {
                proof.push("", c);
            }
        }
    }

    fn on_delete_clause(&mut self, c: &[Lit]) {
        if let Some(proof) = &mut self.proof {
            proof.push("d ", c);
        }
    }

    fn stop(&self) -> bool {
        self.conflict_limit.is_some_and(|l| self.conflicts >= l)
            || self.stop.load(Ordering::Relaxed)
            || self.deadline.is_some_and(|d| Instant::now() >= d)
            || self
                .upper
                .is_some_and(|(u, at)| u.load(Ordering::Relaxed) <= at)
    }
}

/// An incremental SAT solver with DIMACS literals.
pub(crate) struct Sat<'a> {
    solver: batsat::Solver<StopCheck<'a>>,
    next_var: i32,
    /// A buffer for the literals of the clause being added.
    lits: Vec<Lit>,
    clauses: usize,
    /// The clauses added so far as DIMACS lines, when recording.
    recorded: Option<String>,
}

impl<'a> Sat<'a> {
    /// A solver that gives up when `stop` rises or when `upper.0` falls to
    /// `upper.1` or below.
    pub fn new(stop: &'a AtomicBool, upper: Option<(&'a AtomicUsize, usize)>) -> Sat<'a> {
        let solver = batsat::Solver::new(
            SolverOpts::default(),
            StopCheck {
                stop,
                deadline: None,
                upper,
                conflicts: 0,
                conflict_limit: None,
                proof: None,
            },
        );
        Sat {
            solver,
            next_var: 1,
            lits: Vec::new(),
            clauses: 0,
            recorded: None,
        }
    }

    /// Keeps a copy of every clause added from now on, for [`Sat::dimacs`].
    pub fn record(&mut self) {
        self.recorded.get_or_insert_with(String::new);
    }

    /// Keeps the solver's learnt clauses and deletions from now on as a DRAT
    /// proof, for [`Sat::proof`]; call it with [`Sat::record`], before the
    /// first clause.
    pub fn record_proof(&mut self) {
        self.solver
            .cb_mut()
            .proof
            .get_or_insert_with(|| ProofOut::Memory(String::new()));
    }

    /// Like [`Sat::record_proof`], but the proof is written to `out` as
    /// the solver goes (nothing of it is kept); end it with
    /// [`Sat::end_proof_stream`].
    pub fn record_proof_to(&mut self, out: Box<dyn std::io::Write + Send>) {
        self.solver.cb_mut().proof = Some(ProofOut::Stream {
            out: std::io::BufWriter::with_capacity(1 << 20, out),
            line: String::new(),
            lemmas: 0,
            failed: false,
        });
    }

    /// The DRAT proof recorded since [`Sat::record_proof`], ended by the
    /// empty clause: after a solve that answered "unsatisfiable" it refutes
    /// [`Sat::dimacs`]. `None` when not recording in memory.
    pub fn proof(&self) -> Option<String> {
        let ProofOut::Memory(text) = self.solver.cb().proof.as_ref()? else {
            return None;
        };
        let mut text = text.clone();
        text.push_str("0\n");
        Some(text)
    }

    /// Ends the proof of [`Sat::record_proof_to`] with the empty clause,
    /// flushes and closes its writer; its lemmas (the empty clause among
    /// them), or `None` when a write
    /// failed (the proof written is incomplete) or there was no stream.
    pub fn end_proof_stream(&mut self) -> Option<usize> {
        use std::io::Write;
        let ProofOut::Stream {
            mut out,
            lemmas,
            failed,
            ..
        } = self.solver.cb_mut().proof.take()?
        else {
            return None;
        };
        if failed || out.write_all(b"0\n").is_err() || out.flush().is_err() {
            return None;
        }
        Some(lemmas + 1)
    }

    /// The clauses recorded since [`Sat::record`] as a DIMACS CNF (the header
    /// counts all variables and the recorded clauses).
    pub fn dimacs(&self) -> Option<(String, usize)> {
        let body = self.recorded.as_ref()?;
        let count = body.lines().count();
        Some((format!("p cnf {} {count}\n{body}", self.vars()), count))
    }

    /// A fresh variable.
    pub fn var(&mut self) -> i32 {
        let v = self.next_var;
        self.next_var += 1;
        self.solver.var_of_int(v.unsigned_abs() - 1);
        v
    }

    pub fn add(&mut self, clause: &[i32]) {
        self.clauses += 1;
        if let Some(text) = &mut self.recorded {
            use std::fmt::Write;
            for lit in clause {
                let _ = write!(text, "{lit} ");
            }
            text.push_str("0\n");
        }
        self.lits.clear();
        for &lit in clause {
            let var = self.solver.var_of_int(lit.unsigned_abs() - 1);
            self.lits.push(Lit::new(var, lit > 0));
        }
        // `false` only means the clauses are already unsatisfiable, which
        // the next solve reports.
        self.solver.add_clause_reuse(&mut self.lits);
    }

    pub fn clauses(&self) -> usize {
        self.clauses
    }

    pub fn vars(&self) -> usize {
        (self.next_var - 1) as usize
    }

    /// Conflicts met by every solve so far.
    pub fn conflicts(&self) -> u64 {
        self.solver.cb().conflicts
    }

    /// Makes [`Sat::solve`] give up once [`Sat::conflicts`] reaches `limit`
    /// (`None`: no limit).
    pub fn set_conflict_limit(&mut self, limit: Option<u64>) {
        self.solver.cb_mut().conflict_limit = limit;
    }

    /// `Some(true)`: satisfiable, `Some(false)`: unsatisfiable, `None`:
    /// stopped, past the deadline or out of conflicts.
    pub fn solve(&mut self, deadline: Option<Instant>) -> Option<bool> {
        self.solver.cb_mut().deadline = deadline;
        let answer = self.solver.solve_limited(&[]);
        if answer == lbool::TRUE {
            Some(true)
        } else if answer == lbool::FALSE {
            Some(false)
        } else {
            None
        }
    }

    /// The value of a variable in the last model.
    pub fn value(&self, var: i32) -> bool {
        let var = batsat::Var::unsafe_from_idx(var.unsigned_abs() - 1);
        self.solver.value_var(var) == lbool::TRUE
    }
}
