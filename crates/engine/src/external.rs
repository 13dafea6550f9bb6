//! `bound --solver`: the lower bound proved by another SAT solver. For K
//! from the cheap bound up, the formula of "at most K connected pieces"
//! (`dissect_exact::dimacs_connected`) goes to a solver outside the
//! process, which the front end runs (the engine does no I/O) through
//! [`ExternalSolver`]: UNSAT raises the bound to K + 1 (the solver's proof
//! is its own, for `dissect check-proof`), a model is decoded into a
//! dissection and verified (the bound is then optimal), and no answer
//! (the time limit, Ctrl-C, the solver's own limit) ends the bound where
//! it stands.
//!
//! The solver runs on a thread of its own while the monitor watches the
//! deadline and the stop flag; when either comes, the solver's stop flag
//! is raised and the front end ends the solver.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use dissect_core::Figure;
use dissect_exact::{Bound, Dimacs, ExactEvent, Reason};

use crate::bound::{verified_sat, BoundConfig, BoundReport};
use crate::monitor::{monitor, Watch};
use crate::report::{End, LowerBound};
use crate::run::{proof, EngineError, EngineEvent, EngineObserver};

/// What another SAT solver answered on one formula.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ExternalAnswer {
    /// The formula is unsatisfiable.
    Unsat,
    /// A model: the literals it sets true (the others are false).
    Sat(Vec<i32>),
    /// No answer (stopped, or the solver gave up).
    Unknown,
}

/// A SAT solver outside the engine (the front end runs it).
pub trait ExternalSolver: Sync {
    /// Its name in reasons and messages (e.g. its command).
    fn name(&self) -> String;

    /// Solves `cnf`, the formula of "at most `k` connected pieces"; ends
    /// soon with [`ExternalAnswer::Unknown`] once `stop` is raised. An
    /// error is a solver that could not run or answered nonsense.
    fn solve(&self, k: usize, cnf: &Dimacs, stop: &AtomicBool) -> Result<ExternalAnswer, String>;
}

/// [`crate::bound`] by `solver`: the cheap bound, then "at most K connected
/// pieces?" for K from it up to `config.max_pieces` (the cells when none),
/// each formula built within `max_encoding_bytes`. `config.certify`,
/// `cube_proofs` and `threads` are not used (the solver's proofs are the
/// certificates). Events: the cheap bound as [`ExactEvent::CheapBound`],
/// each refutation as [`ExactEvent::Refuted`] with [`Reason::External`].
pub fn bound_external(
    figures: &[Figure],
    names: &[String],
    (config, max_encoding_bytes): (&BoundConfig, u64),
    solver: &dyn ExternalSolver,
    stop: &AtomicBool,
    observer: &dyn EngineObserver,
) -> Result<BoundReport, EngineError> {
    let start = Instant::now();
    let deadline = config.time_limit.deadline_from(start);
    let mirror = config.mirror_for(figures);
    let cheap = dissect_exact::cheap_bound(figures, mirror)?;
    observer.on_event(&EngineEvent::Exact(&ExactEvent::CheapBound(cheap.clone())));
    let describe = |b: &Bound| LowerBound {
        value: b.value,
        reason: b.describe(names),
        proof: proof(b, names),
    };
    let mut report = BoundReport::new(describe(&cheap));
    let cells = figures.first().map_or(1, Figure::len);
    let last = config.max_pieces.unwrap_or(cells).min(cells);
    for k in cheap.value.max(1)..=last {
        let cnf = match dissect_exact::dimacs_connected(figures, mirror, k, max_encoding_bytes) {
            Ok(cnf) => cnf,
            Err(dissect_exact::ExactError::TooLarge { pieces, bytes, cap }) => {
                report.too_large = Some((pieces, bytes, cap));
                break;
            }
            Err(e) => return Err(e.into()),
        };
        let asked = Instant::now();
        let (answer, end) = solve_watched(solver, k, &cnf, stop, deadline);
        let answer = answer.map_err(|e| EngineError::External(solver.name(), e))?;
        if let Some(end) = end {
            report.end = end;
        }
        match answer {
            ExternalAnswer::Unsat => {
                let b = Bound {
                    value: k + 1,
                    reason: Reason::External {
                        refuted: k,
                        seconds: asked.elapsed().as_secs_f64(),
                        solver: solver.name(),
                    },
                };
                observer.on_event(&EngineEvent::Exact(&ExactEvent::Refuted(b.clone())));
                report.lower_bound = describe(&b);
            }
            ExternalAnswer::Sat(model) => {
                let pieces = dissect_exact::decode_model_within(
                    figures,
                    mirror,
                    k,
                    &model,
                    max_encoding_bytes,
                )
                .map_err(|e| EngineError::External(solver.name(), e.to_string()))?;
                report.found = Some(verified_sat(figures, names, mirror, pieces)?);
                break;
            }
            ExternalAnswer::Unknown => break,
        }
        if report.end != End::Finished {
            break;
        }
    }
    report.seconds = start.elapsed().as_secs_f64();
    Ok(report)
}

/// `solver` on `cnf` on a thread of its own, stopped at `deadline` or when
/// `stop` is raised: its answer, and how the watch ended when it was
/// stopped (`None`: the solver ended by itself).
fn solve_watched(
    solver: &dyn ExternalSolver,
    k: usize,
    cnf: &Dimacs,
    stop: &AtomicBool,
    deadline: Option<Instant>,
) -> (Result<ExternalAnswer, String>, Option<End>) {
    let solver_stop = AtomicBool::new(false);
    std::thread::scope(|scope| {
        let handle = scope.spawn(|| solver.solve(k, cnf, &solver_stop));
        let watch = monitor(stop, deadline, || handle.is_finished().then_some(()));
        solver_stop.store(true, Ordering::SeqCst);
        let answer = handle
            .join()
            .unwrap_or_else(|_| Err("the solver's thread panicked".to_string()));
        match watch {
            Watch::Stopped(end) => (answer, Some(end)),
            Watch::Ended(()) => (answer, None),
        }
    })
}
