//! The search of both sides: the heuristic on a scoped thread, the exact
//! search on a thread of its own, and the monitor that ends them.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, Receiver};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use dissect_core::solver::{solve_anytime_with, solve_with, Executor, Outcome, Repair};
use dissect_exact::{search as exact_search, ExactError, ExactEvent, ExactObserver, ExactOutcome};

use super::shared::{Forward, Shared};
use super::{EngineError, Plan, EXACT_GRACE, SLIVER_CELLS};
use crate::monitor::{monitor, Watch};
use crate::options::Strategy;
use crate::report::End;

/// What the search of both sides left.
pub(super) struct Sides {
    /// The heuristic's outcome (`None`: it did not run).
    pub(super) heuristic: Option<Outcome>,
    /// The exact side's outcome (`None`: it did not run, or did not
    /// return within [`EXACT_GRACE`] of the stop).
    pub(super) exact: Option<ExactOutcome>,
    /// Why the search ended.
    pub(super) end: End,
    /// Whether it ended early for the polish (the last part of a time
    /// limit, an answer with a sliver).
    pub(super) polish_early: bool,
}

/// Why the run's own step ends the search.
enum Step {
    /// The best meets the lower bound (and enough solutions are kept).
    Optimal,
    /// Both sides ended by their work rules.
    Finished,
    /// The last part of the time limit goes to the polish.
    Polish,
    /// The last part of the time limit goes to the interlocking search.
    Interlock,
}

/// The exact side's thread.
type ExactThread = JoinHandle<Result<ExactOutcome, ExactError>>;

/// Runs both sides until the monitor ends them, then collects their
/// outcomes.
pub(super) fn search(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &AtomicBool,
    repairer: Option<&dyn Repair>,
    executor: Option<&dyn Executor>,
) -> Result<Sides, EngineError> {
    let heuristic_stop = AtomicBool::new(false);
    let exact_stop = Arc::new(AtomicBool::new(false));
    let heuristic_done = AtomicBool::new(!plan.heuristic_on);
    if plan.deadline.is_some_and(|d| Instant::now() >= d) {
        // No time at all: stop before anything starts.
        heuristic_stop.store(true, Ordering::SeqCst);
        exact_stop.store(true, Ordering::SeqCst);
    }
    let (exact, events) = spawn_exact(plan, shared, &exact_stop);
    let exact_done = || exact.as_ref().is_none_or(|t| t.is_finished());
    let drain = || drain(&events, shared);
    let (watch, heuristic) = std::thread::scope(|s| {
        let heuristic = plan.heuristic_on.then(|| {
            s.spawn(|| {
                let r = heuristic_side(plan, shared, &heuristic_stop, repairer, executor);
                heuristic_done.store(true, Ordering::SeqCst);
                r
            })
        });
        let watch = monitor(stop, plan.deadline, || {
            drain();
            step(
                plan,
                shared,
                heuristic_done.load(Ordering::SeqCst),
                exact_done(),
            )
        });
        heuristic_stop.store(true, Ordering::SeqCst);
        exact_stop.store(true, Ordering::SeqCst);
        (
            watch,
            heuristic.map(|t| t.join().expect("heuristic thread")),
        )
    });
    let exact = join_exact(exact)?;
    drain();
    let (end, polish_early) = match watch {
        Watch::Stopped(end) => (end, false),
        Watch::Ended(Step::Optimal) => (End::Optimal, false),
        Watch::Ended(Step::Finished) => (End::Finished, false),
        Watch::Ended(Step::Polish) => (End::TimeLimit, true),
        Watch::Ended(Step::Interlock) => (End::TimeLimit, false),
    };
    Ok(Sides {
        heuristic: heuristic.transpose()?,
        exact,
        end,
        polish_early,
    })
}

/// The heuristic's side: the paper's schedule or the anytime one.
fn heuristic_side(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &AtomicBool,
    repairer: Option<&dyn Repair>,
    executor: Option<&dyn Executor>,
) -> Result<Outcome, dissect_core::solver::SolveError> {
    let solver_options = plan.options.solver_options();
    match plan.strategy() {
        Strategy::Paper => solve_with(plan.figures, &solver_options, stop, shared, executor),
        _ => solve_anytime_with(
            plan.figures,
            &solver_options,
            &plan.options.anytime(),
            stop,
            shared,
            repairer,
            executor,
        ),
    }
}

/// The exact side, on a thread of its own with its own copies (a stop
/// does not wait for it: parts of it, such as the cheap bound, do not look
/// at the stop flag); its events come back through the receiver.
fn spawn_exact(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &Arc<AtomicBool>,
) -> (Option<ExactThread>, Receiver<ExactEvent>) {
    let (events_tx, events) = channel::<ExactEvent>();
    let exact = plan.exact_on.then(|| {
        let figures = plan.figures.to_vec();
        let stop = Arc::clone(stop);
        let upper = Arc::clone(&shared.upper);
        let forward = Forward(Mutex::new(events_tx));
        let options = plan.exact_options();
        std::thread::spawn(move || exact_search(&figures, &options, &stop, &upper, &forward))
    });
    (exact, events)
}

/// Hands the exact side's events to the shared state (on this thread).
fn drain(events: &Receiver<ExactEvent>, shared: &Shared<'_>) {
    while let Ok(e) = events.try_recv() {
        ExactObserver::on_event(shared, &e);
    }
}

/// The exact side gets a moment to see its stop flag; past that it is
/// left to end on its own (what it would have said is not waited for).
fn join_exact(exact: Option<ExactThread>) -> Result<Option<ExactOutcome>, EngineError> {
    let Some(t) = exact else {
        return Ok(None);
    };
    let grace = Instant::now() + EXACT_GRACE;
    while !t.is_finished() && Instant::now() < grace {
        std::thread::sleep(Duration::from_millis(2));
    }
    if !t.is_finished() {
        return Ok(None);
    }
    Ok(Some(t.join().expect("exact thread")?))
}

/// The run's own reasons to end, looked at by the monitor between its
/// checks of the stop flag and the deadline.
fn step(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    heuristic_done: bool,
    exact_done: bool,
) -> Option<Step> {
    let heuristic_best = shared.heuristic_best.load(Ordering::SeqCst);
    let sat_best = shared.sat_best.load(Ordering::SeqCst);
    // The last part of a time limit goes to the polish when the
    // heuristic's answer (the better one) has a sliver.
    if plan.polish_from.is_some_and(|t| Instant::now() >= t)
        && shared.heuristic_smallest.load(Ordering::SeqCst) < SLIVER_CELLS
        && heuristic_best <= sat_best
        && !heuristic_done
    {
        return Some(Step::Polish);
    }
    // The last part of a time limit goes to the interlocking search when
    // the assembly rules refused every valid dissection so far.
    if plan.interlock_from.is_some_and(|t| Instant::now() >= t)
        && shared
            .judge
            .as_ref()
            .is_some_and(|j| j.collected() == 0 && j.has_refused())
    {
        return Some(Step::Interlock);
    }
    let lower = shared.lower_value.load(Ordering::SeqCst);
    // Without a time limit only the heuristic's answer ends the run early
    // (on a tie it is the answer), so the answer does not depend on how
    // fast the exact side is.
    let best = if plan.deadline.is_some() || !plan.heuristic_on {
        heuristic_best.min(sat_best)
    } else {
        heuristic_best
    };
    // A run that does not prove (no exact side) goes on to its own end:
    // the paper's `--full-level` keeps looking. Several solutions: optimal
    // only ends the run once enough different ones are collected.
    let wanted = plan.wanted();
    let enough = wanted <= 1
        || shared
            .judge
            .as_ref()
            .is_some_and(|j| j.collected() >= wanted);
    if best <= lower && plan.exact_on && enough {
        return Some(Step::Optimal);
    }
    // Both sides end on their own: the heuristic by its work rule (or the
    // time limit), the exact side by its conflict budget (or the time
    // limit).
    (heuristic_done && exact_done).then_some(Step::Finished)
}
