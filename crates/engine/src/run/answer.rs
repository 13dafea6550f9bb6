//! The answer of a run: both sides' dissections verified, the better one
//! chosen, a puzzle run's collection ranked and checked, and the report.

use std::sync::atomic::AtomicBool;

use dissect_core::Cell;
use dissect_puzzle::collect::CountTime;

use super::shared::Shared;
use super::sides::Sides;
use super::{EngineError, Plan, COUNT_GRACE, COUNT_TIME};
use crate::report::{End, Ranking, Report, Solution, Source};
use crate::verified::Verified;

/// The answer: the dissection, which search found it, and at which level
/// (the heuristic's).
type Best = (Verified, Source, Option<usize>);

/// Verifies, chooses, ranks and reports.
pub(super) fn answer(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &AtomicBool,
    sides: Sides,
) -> Result<Report, EngineError> {
    let mut best = best(plan, shared, &sides)?;
    let (solutions, ranking) = match &shared.judge {
        Some(_) => {
            let solutions = ranked(plan, shared, stop, &sides, best.as_ref())?;
            // The best is the first by the ranking.
            best = solutions.first().map(|s| {
                let level = best
                    .as_ref()
                    .filter(|b| b.0 == s.dissection)
                    .and_then(|b| b.2);
                (s.dissection.clone(), s.source, level)
            });
            let config = plan.config();
            let ranking = Ranking {
                rank: config.rank,
                asked: plan.wanted(),
                constraints: config.constraints.to_json(plan.lattice),
            };
            (solutions, Some(ranking))
        }
        None => (Vec::new(), None),
    };
    Ok(report(plan, shared, sides, best, solutions, ranking))
}

/// Verifies `pieces` (found by `what`: an error names it).
fn verified(
    plan: &Plan<'_>,
    what: &'static str,
    pieces: Vec<Vec<Vec<Cell>>>,
) -> Result<Verified, EngineError> {
    Verified::new(
        plan.lattice,
        plan.mirror,
        plan.names.clone(),
        plan.figures,
        pieces,
    )
    .map_err(|e| EngineError::Unverified(what, e))
}

/// The dissection with the fewest pieces; on a tie the heuristic's.
fn best(plan: &Plan<'_>, shared: &Shared<'_>, sides: &Sides) -> Result<Option<Best>, EngineError> {
    let mut best: Option<Best> = None;
    if let Some(found) = sides.heuristic.as_ref().and_then(|o| o.found.as_ref()) {
        let v = verified(plan, "heuristic", found.pieces.clone())?;
        let source = shared.heuristic_source(v.piece_count());
        best = Some((v, source, Some(found.level)));
    }
    if let Some(pieces) = sides.exact.as_ref().and_then(|o| o.found.clone()) {
        let v = verified(plan, "SAT", pieces)?;
        if best
            .as_ref()
            .is_none_or(|(b, _, _)| v.piece_count() < b.piece_count())
        {
            best = Some((v, Source::Sat, None));
        }
    }
    Ok(best)
}

/// A puzzle run: the collection, with the answers of both sides, ranked;
/// every one verified and checked against the constraints.
fn ranked(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    stop: &AtomicBool,
    sides: &Sides,
    best: Option<&Best>,
) -> Result<Vec<Solution>, EngineError> {
    let Some(judge) = &shared.judge else {
        return Ok(Vec::new());
    };
    let config = plan.config();
    let mut collection = judge
        .collection
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .clone();
    let heuristic_pieces = sides
        .heuristic
        .as_ref()
        .and_then(|o| o.found.as_ref())
        .map(|f| f.pieces.clone());
    let sat_pieces = sides.exact.as_ref().and_then(|o| o.found.clone());
    for p in heuristic_pieces.iter().chain(&sat_pieces) {
        collection.add(p.clone());
    }
    let heuristic_source = best
        .filter(|b| b.1 != Source::Sat)
        .map_or(Source::Search, |b| b.1);
    let mut solutions = Vec::new();
    shared
        .observer
        .on_event(&super::EngineEvent::Phase(super::Phase::Ranking));
    // The counts of `--rank unique` end at the stop, or just after the
    // time limit.
    let count_time = CountTime {
        each: COUNT_TIME,
        until: plan.deadline.map(|d| d + COUNT_GRACE),
        stop: Some(stop),
    };
    for e in collection.ranked(config.rank, plan.wanted(), plan.figures, count_time) {
        let broken = config.constraints.check(&plan.motions, &e.pieces);
        if let Some(v) = broken.first() {
            return Err(EngineError::Unverified(
                "constrained",
                format!("it breaks a constraint: {v}"),
            ));
        }
        let source = if sat_pieces.as_ref() == Some(&e.pieces) {
            Source::Sat
        } else if heuristic_pieces.as_ref() == Some(&e.pieces) {
            heuristic_source
        } else if judge
            .interlocked
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .contains(&e.pieces)
        {
            Source::Interlock
        } else {
            Source::Search
        };
        solutions.push(Solution {
            dissection: verified(plan, "collected", e.pieces)?,
            scores: e.scores,
            source,
        });
    }
    Ok(solutions)
}

/// The report of the run.
fn report(
    plan: &Plan<'_>,
    shared: &Shared<'_>,
    sides: Sides,
    best: Option<Best>,
    solutions: Vec<Solution>,
    ranking: Option<Ranking>,
) -> Report {
    let lower_bound = shared.lower_bound();
    let history = shared.history();
    let count = best.as_ref().map(|(b, _, _)| b.piece_count());
    let optimal = count.is_some_and(|c| c <= lower_bound.value);
    let end = if optimal && sides.end == End::Finished {
        End::Optimal
    } else {
        sides.end
    };
    let outcome = sides.heuristic.as_ref();
    Report {
        seed: plan.config().seed,
        time_to_first: history.first().map(|i| i.seconds),
        time_to_best: count
            .and_then(|c| history.iter().find(|i| i.pieces <= c))
            .map(|i| i.seconds),
        source: best.as_ref().map(|b| b.1),
        level: best.as_ref().and_then(|b| b.2),
        best: best.map(|b| b.0),
        seconds: plan.start.elapsed().as_secs_f64(),
        lower_bound,
        optimal,
        history,
        end,
        explorations: outcome.map_or(0, |o| o.explorations),
        rounds: outcome.map_or(0, |o| o.rounds),
        last_pieces: outcome.map_or(0, |o| o.last_pieces),
        best_mismatch: outcome.and_then(|o| o.best_mismatch),
        solutions,
        ranking,
    }
}
