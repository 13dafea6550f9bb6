//! The polish: an answer with a sliver (a piece of fewer than
//! [`SLIVER_CELLS`](super::SLIVER_CELLS) cells) gets one more round of the search at its piece
//! count that accepts only sliver-free dissections, in the time left (with
//! a time limit, its last [`POLISH_SHARE`](super::POLISH_SHARE)).

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use dissect_core::solver::{solve_anytime_with, Anytime, Executor, Options, Repair};

use super::shared::{NoSlivers, Shared};
use super::sides::Sides;
use super::{has_sliver, EngineError, Plan};
use crate::monitor::monitor;
use crate::report::End;

/// Polishes the heuristic's answer in `sides` when it has a sliver, is
/// the better answer, and time is left; a sliver-free dissection with no
/// more pieces replaces it.
pub(super) fn polish(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &AtomicBool,
    sides: &mut Sides,
    repairer: Option<&dyn Repair>,
    executor: Option<&dyn Executor>,
) -> Result<(), EngineError> {
    let Some(count) = sliver_count(plan, shared, stop, sides) else {
        return Ok(());
    };
    shared
        .observer
        .on_event(&super::EngineEvent::Phase(super::Phase::Polish));
    let options = Options {
        max_pieces: Some(count),
        ..plan.options.solver_options()
    };
    // One round after an optimal or finished run; in the last part of a
    // time limit, rounds until it.
    let rounds = (!sides.polish_early).then_some(1);
    let anytime = Anytime {
        idle_rounds: rounds,
        max_rounds: rounds,
        ..plan.options.anytime()
    };
    let polish_stop = AtomicBool::new(false);
    let polish_done = AtomicBool::new(false);
    let polished = std::thread::scope(|s| {
        let t = s.spawn(|| {
            let r = solve_anytime_with(
                plan.figures,
                &options,
                &anytime,
                &polish_stop,
                &NoSlivers(shared),
                repairer,
                executor,
            );
            polish_done.store(true, Ordering::SeqCst);
            r
        });
        monitor(stop, plan.deadline, || {
            polish_done.load(Ordering::SeqCst).then_some(())
        });
        polish_stop.store(true, Ordering::SeqCst);
        t.join().expect("polish thread")
    })?;
    if let (Some(h), Some(found)) = (sides.heuristic.as_mut(), polished.found) {
        if found.piece_count() <= count && !has_sliver(&found.pieces) {
            h.found = Some(found);
        }
    }
    Ok(())
}

/// The piece count of the heuristic's answer when it is to be polished:
/// it has a sliver, no fewer pieces than the exact side's, the run may be
/// polished and ended by optimality, its work rule or for the polish, and
/// neither the stop nor the deadline has come.
fn sliver_count(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &AtomicBool,
    sides: &Sides,
) -> Option<usize> {
    let sat_count = shared.sat_best.load(Ordering::SeqCst);
    let may = plan.polishable
        && (sides.polish_early || matches!(sides.end, End::Optimal | End::Finished))
        && !stop.load(Ordering::SeqCst)
        && plan.deadline.is_none_or(|d| Instant::now() < d);
    sides
        .heuristic
        .as_ref()
        .and_then(|o| o.found.as_ref())
        .filter(|f| may && f.piece_count() <= sat_count && has_sliver(&f.pieces))
        .map(|f| f.piece_count())
}
