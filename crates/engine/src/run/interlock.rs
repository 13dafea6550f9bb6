//! The interlocking phase: when the assembly rules (`--min-level`,
//! `--assemblable`) refused every valid dissection the sides found, the
//! interlocking search ([`crate::interlock`]) starts from the refused ones
//! and runs until the deadline, the stop flag or its work budget; an
//! answer joins the judge's collection.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use super::shared::Shared;
use super::sides::Sides;
use super::{EngineEvent, Phase, Plan};
use crate::interlock::Interlock;
use crate::report::{End, Source};

/// Neighbourhoods the interlocking search may try in a run without a time
/// limit (its work rule).
pub const INTERLOCK_STEPS: usize = 100;

/// Runs the interlocking search when the run has the assembly rules, no
/// answer honours them yet, a valid dissection was refused, and neither
/// the stop nor the deadline has come.
pub(super) fn interlock(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &AtomicBool,
    sides: &mut Sides,
) {
    let Some(judge) = &shared.judge else {
        return;
    };
    let constraints = &plan.config().constraints;
    if !constraints.assemblable()
        || judge.collected() > 0
        || stop.load(Ordering::SeqCst)
        || plan.deadline.is_some_and(|d| Instant::now() >= d)
    {
        return;
    }
    let starts = judge.refused();
    if starts.is_empty() {
        return;
    }
    shared
        .observer
        .on_event(&EngineEvent::Phase(Phase::Interlock));
    let search = Interlock {
        figures: plan.figures,
        mirror: plan.mirror,
        constraints,
        motions: &plan.motions,
        stop,
        deadline: plan.deadline,
        steps: if plan.deadline.is_some() {
            usize::MAX
        } else {
            INTERLOCK_STEPS
        },
        seed: plan.config().seed,
    };
    if let Some(found) = search.run(&starts) {
        if let Some((pieces, count)) = judge.collect(&found) {
            judge
                .interlocked
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .push(found);
            shared.found(pieces, Source::Interlock);
            shared.observer.on_event(&EngineEvent::Collected {
                pieces,
                count,
                seconds: shared.seconds(),
            });
            if sides.end == End::TimeLimit {
                sides.end = End::Finished;
            }
        }
    }
}
