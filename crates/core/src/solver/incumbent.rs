//! The anytime search's incumbent: the best dissection so far and the
//! outcome it is reported in. Every improvement, whichever step found it,
//! goes through [`Incumbent::improve`].

use crate::solver::candidate::{Candidate, Score};
use crate::solver::search::Search;
use crate::solver::{Event, Outcome, Via};

/// The best dissection so far (within the piece cap) and the outcome.
pub(crate) struct Incumbent {
    /// The best dissection so far, as a candidate whose `k` is its piece
    /// count.
    pub(crate) best: Option<(Candidate, Score)>,
    /// What the run reports.
    pub(crate) outcome: Outcome,
    /// No answer has more pieces.
    max_pieces: usize,
}

impl Incumbent {
    /// No dissection yet.
    pub(crate) fn new(outcome: Outcome, max_pieces: usize) -> Incumbent {
        Incumbent {
            best: None,
            outcome,
            max_pieces,
        }
    }

    /// The best dissection's piece count.
    pub(crate) fn pieces(&self) -> Option<usize> {
        self.best.as_ref().map(|(b, _)| b.k)
    }

    /// Takes a valid dissection when it has fewer pieces than the best so
    /// far (and no more than the cap), reporting [`Event::Improved`];
    /// whether it did.
    pub(crate) fn improve(
        &mut self,
        search: &Search<'_>,
        cand: Candidate,
        score: Score,
        level: usize,
        round: usize,
        via: Via,
    ) -> bool {
        let found = search.found(&cand, &score, level);
        let pieces = found.piece_count();
        if pieces > self.max_pieces || self.pieces().is_some_and(|k| pieces >= k) {
            return false;
        }
        // Labels that vanished are dropped, so `k` is the piece count.
        let cand = search.candidate_of(&found.pieces).map_or(cand, |(c, _)| c);
        search.observer.on_event(&Event::Improved {
            pieces,
            smallest: found.smallest(),
            level,
            round,
            via,
        });
        self.outcome.found = Some(found);
        self.best = Some((cand, score));
        true
    }
}
