//! The paper's schedule ([`solve`]): levels of 2, 3, ... pieces, stopping
//! at the first level that holds a valid dissection.

use std::sync::atomic::AtomicBool;

use crate::figure::Figure;
use crate::solver::candidate::{Candidate, Score};
use crate::solver::explore::Executor;
use crate::solver::search::{From, Search};
use crate::solver::{Event, Observer, Options, Outcome, SolveError, Via};

/// Finds a dissection of `figures` into as few connected pieces as it can,
/// by the paper's schedule: levels of 2, 3, ... pieces, stopping at the
/// first level that holds a valid dissection.
///
/// Raising `stop` ends the search soon after; the best valid dissection found
/// so far is returned.
pub fn solve(
    figures: &[Figure],
    options: &Options,
    stop: &AtomicBool,
    observer: &dyn Observer,
) -> Result<Outcome, SolveError> {
    solve_with(figures, options, stop, observer, None)
}

/// [`solve`], with the explorations run by `executor` (`None`: the
/// solver's thread pool). An executor that returns what
/// [`Explorer::explore`](crate::solver::Explorer::explore) returns gives
/// the same answer as [`solve`].
pub fn solve_with(
    figures: &[Figure],
    options: &Options,
    stop: &AtomicBool,
    observer: &dyn Observer,
    executor: Option<&dyn Executor>,
) -> Result<Outcome, SolveError> {
    let search = Search::new(figures, options, stop, observer, executor)?;
    let (whole, s0) = search.level_zero();
    if s0.valid {
        observer.on_event(&Event::Improved {
            pieces: 1,
            smallest: figures[0].len(),
            level: 0,
            round: 0,
            via: Via::Search,
        });
        return Ok(Outcome {
            found: Some(search.found(&whole, &s0, 0)),
            best_mismatch: Some(0),
            last_pieces: 1,
            stopped: false,
            explorations: 1,
            rounds: 0,
        });
    }
    let cells = figures[0].len();
    let max_pieces = options.max_pieces.unwrap_or(cells).min(cells);
    let mut parents: Vec<(Candidate, Score)> = Vec::new();
    let mut outcome = Outcome {
        found: None,
        best_mismatch: Some(s0.mismatch),
        last_pieces: 1,
        stopped: false,
        explorations: 1,
        rounds: 1,
    };
    for level in 1.. {
        let pieces = level + 1;
        if pieces > max_pieces || search.stopped() {
            break;
        }
        let result = search.level(0, level, From::Below(&parents))?;
        outcome.explorations += result.results.len();
        outcome.last_pieces = pieces;
        outcome.best_mismatch = Some(result.best_mismatch());
        outcome.stopped |= result.stopped;
        if let Some((cand, score)) = result.best_valid() {
            let found = search.found(cand, score, level);
            observer.on_event(&Event::Improved {
                pieces: found.piece_count(),
                smallest: found.smallest(),
                level,
                round: 0,
                via: Via::Search,
            });
            outcome.found = Some(found);
            return Ok(outcome);
        }
        if result.stopped || result.results.is_empty() {
            break;
        }
        parents = result.kept(options.keep);
    }
    outcome.stopped |= search.stopped();
    Ok(outcome)
}
