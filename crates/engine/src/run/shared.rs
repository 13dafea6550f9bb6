//! What both sides of a run share while it lasts ([`Shared`]: the best
//! piece counts, the lower bound, the history, the judge of a puzzle run),
//! and the observers that feed it.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::Sender;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use dissect_core::solver::{Event, Judgement, Observer, Via};
use dissect_core::Cell;
use dissect_exact::{Bound, ExactEvent, ExactObserver, Reason};
use dissect_puzzle::constraints::Violation;
use dissect_puzzle::{Added, Collection, Constraints, Motions};

use super::{EngineEvent, EngineObserver, CONSTRAINT_PENALTY, MAX_COLLECTED, SLIVER_CELLS};
use crate::report::{Improvement, LowerBound, Source};

/// The judge of a puzzle run: the constraints every answer honours, and
/// the collection of the different valid dissections with the fewest
/// pieces.
pub(super) struct Judge {
    pub(super) motions: Motions,
    pub(super) constraints: Constraints,
    /// Whether the constraints steer the search (keep regions, sizes).
    pub(super) steer: bool,
    pub(super) collection: Mutex<Collection>,
    /// Solutions asked for: a new one up to this many is fresh (progress
    /// for the run's work rule).
    pub(super) wanted: usize,
    /// Valid dissections refused only by the assembly rules, the fewest
    /// pieces (at most [`MAX_REFUSED`]): where the interlocking search
    /// starts.
    refused: Mutex<Vec<Vec<Vec<Vec<Cell>>>>>,
    /// The answers of the interlocking search (their source in the report).
    pub(super) interlocked: Mutex<Vec<Vec<Vec<Vec<Cell>>>>>,
}

/// The most refused dissections a judge keeps for the interlocking search.
const MAX_REFUSED: usize = 8;

impl Judge {
    /// The judge of a run that collects `wanted` solutions honouring
    /// `constraints`.
    pub(super) fn new(motions: &Motions, constraints: &Constraints, wanted: usize) -> Judge {
        Judge {
            motions: motions.clone(),
            constraints: constraints.clone(),
            steer: !constraints.keep().is_empty()
                || constraints.min_piece().is_some()
                || constraints.max_piece().is_some(),
            collection: Mutex::new(Collection::new(motions.clone(), constraints.clone())),
            wanted,
            refused: Mutex::new(Vec::new()),
            interlocked: Mutex::new(Vec::new()),
        }
    }

    /// Keeps a valid dissection that only the assembly rules refuse, when
    /// it has no more pieces than those kept (fewer: they are dropped).
    fn refuse(&self, pieces: &[Vec<Vec<Cell>>]) {
        let mut r = self.refused.lock().unwrap_or_else(|e| e.into_inner());
        let n = pieces.first().map_or(0, Vec::len);
        let kept = r.first().map_or(usize::MAX, |p| p[0].len());
        if n < kept {
            r.clear();
        }
        if n <= kept && r.len() < MAX_REFUSED && !r.iter().any(|p| p == pieces) {
            r.push(pieces.to_vec());
        }
    }

    /// Whether a valid dissection was refused only by the assembly rules.
    pub(super) fn has_refused(&self) -> bool {
        !self
            .refused
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .is_empty()
    }

    /// The valid dissections refused only by the assembly rules (the
    /// fewest pieces).
    pub(super) fn refused(&self) -> Vec<Vec<Vec<Vec<Cell>>>> {
        self.refused
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    /// Offers a valid dissection to the collection (skipped past
    /// `MAX_COLLECTED` at the same count); `Some((pieces, count))` when it
    /// was kept.
    pub(super) fn collect(&self, pieces: &[Vec<Vec<Cell>>]) -> Option<(usize, usize)> {
        let mut c = self.collection.lock().unwrap_or_else(|e| e.into_inner());
        let n = pieces.first().map_or(0, Vec::len);
        if c.len() < MAX_COLLECTED || c.fewest().is_some_and(|k| n < k) {
            if let Added::New | Added::Fewer = c.add(pieces.to_vec()) {
                return Some((n, c.len()));
            }
        }
        None
    }

    /// The number of different dissections kept.
    pub(super) fn collected(&self) -> usize {
        self.collection
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .len()
    }
}

/// What both sides share while the run lasts.
pub(super) struct Shared<'a> {
    pub(super) start: Instant,
    pub(super) names: &'a [String],
    pub(super) observer: &'a dyn EngineObserver,
    /// The best piece count of each side (`usize::MAX`: none yet).
    pub(super) heuristic_best: AtomicUsize,
    pub(super) sat_best: AtomicUsize,
    /// The cells of the smallest piece of the heuristic's best.
    pub(super) heuristic_smallest: AtomicUsize,
    /// The best piece count known to either side, for the exact search.
    pub(super) upper: Arc<AtomicUsize>,
    pub(super) lower: Mutex<LowerBound>,
    pub(super) lower_value: AtomicUsize,
    pub(super) history: Mutex<Vec<Improvement>>,
    /// Present in a puzzle run ([`crate::RunOptions::collects`]).
    pub(super) judge: Option<Judge>,
}

impl<'a> Shared<'a> {
    /// The state of a run started at `start`, with nothing found yet.
    pub(super) fn new(
        start: Instant,
        names: &'a [String],
        observer: &'a dyn EngineObserver,
        judge: Option<Judge>,
    ) -> Shared<'a> {
        let piece = "every dissection has a piece".to_string();
        Shared {
            start,
            names,
            observer,
            heuristic_best: AtomicUsize::new(usize::MAX),
            sat_best: AtomicUsize::new(usize::MAX),
            heuristic_smallest: AtomicUsize::new(usize::MAX),
            upper: Arc::new(AtomicUsize::new(usize::MAX)),
            lower: Mutex::new(LowerBound {
                value: 1,
                reason: piece.clone(),
                proof: piece,
            }),
            lower_value: AtomicUsize::new(1),
            history: Mutex::new(Vec::new()),
            judge,
        }
    }

    /// The lower bound proved so far.
    pub(super) fn lower_bound(&self) -> LowerBound {
        self.lower.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// Every improvement so far.
    pub(super) fn history(&self) -> Vec<Improvement> {
        self.history
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    /// Which search of the heuristic's side last found `pieces` pieces.
    pub(super) fn heuristic_source(&self, pieces: usize) -> Source {
        self.history
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .iter()
            .rev()
            .find(|i| i.source != Source::Sat && i.pieces == pieces)
            .map_or(Source::Search, |i| i.source)
    }

    /// Whether the run's constraints hold rules the exact side does not
    /// encode (`--assemblable`, `--min-level`): its dissections then count
    /// only once the judge's collection accepts them.
    fn exact_unchecked(&self) -> bool {
        self.judge
            .as_ref()
            .is_some_and(|j| j.constraints.assemblable())
    }

    pub(super) fn seconds(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    /// Notes a dissection of `pieces` pieces; an improvement when it has
    /// fewer than any before.
    pub(super) fn found(&self, pieces: usize, source: Source) {
        let side = match source {
            Source::Sat => &self.sat_best,
            _ => &self.heuristic_best,
        };
        side.fetch_min(pieces, Ordering::SeqCst);
        self.upper.fetch_min(pieces, Ordering::SeqCst);
        let improvement = {
            let mut h = self.history.lock().unwrap_or_else(|e| e.into_inner());
            if h.last().is_some_and(|l| l.pieces <= pieces) {
                return;
            }
            let i = Improvement {
                pieces,
                seconds: self.seconds(),
                source,
            };
            h.push(i);
            i
        };
        self.observer.on_event(&EngineEvent::Improved(improvement));
    }

    /// [`Shared::found`] for the heuristic's dissection, whose smallest
    /// piece has `smallest` cells.
    pub(super) fn found_by_heuristic(&self, pieces: usize, smallest: usize, source: Source) {
        if pieces <= self.heuristic_best.load(Ordering::SeqCst) {
            self.heuristic_smallest.store(smallest, Ordering::SeqCst);
        }
        self.found(pieces, source);
    }

    pub(super) fn raise_lower(&self, value: usize, reason: impl FnOnce() -> (String, String)) {
        let bound = {
            let mut l = self.lower.lock().unwrap_or_else(|e| e.into_inner());
            if value <= l.value {
                return;
            }
            let (reason, proof) = reason();
            *l = LowerBound {
                value,
                reason,
                proof,
            };
            self.lower_value.store(value, Ordering::SeqCst);
            l.clone()
        };
        self.observer.on_event(&EngineEvent::LowerBound(&bound));
    }
}

impl Observer for Shared<'_> {
    fn on_event(&self, event: &Event) {
        match event {
            Event::LevelFinished {
                level: 0,
                found: false,
                ..
            } => self.raise_lower(2, || {
                // A judged run refuses one piece that breaks a constraint
                // (a single piece has level 0): the figures may well be
                // congruent.
                let r = if self.judge.is_some() {
                    "no single piece honours the constraints"
                } else {
                    "the figures are not congruent"
                }
                .to_string();
                (r.clone(), r)
            }),
            Event::Improved {
                pieces,
                smallest,
                via,
                ..
            } => self.found_by_heuristic(
                *pieces,
                *smallest,
                match via {
                    Via::Greedy => Source::Greedy,
                    Via::Repair => Source::Repair,
                    Via::Coarse => Source::Coarse,
                    Via::Sectors => Source::Sectors,
                    Via::Regroup => Source::Regroup,
                    Via::Rebuild => Source::Rebuild,
                    Via::Boxes => Source::Boxes,
                    _ => Source::Search,
                },
            ),
            _ => {}
        }
        self.observer.on_event(&EngineEvent::Search(event));
    }

    fn judges(&self) -> bool {
        self.judge.is_some()
    }

    /// Steers by the distance to the keep regions and size bounds, refuses
    /// a dissection that breaks a constraint, and collects the others.
    fn judge(&self, pieces: &[Vec<Vec<Cell>>], valid: bool) -> Judgement {
        let Some(j) = &self.judge else {
            return Judgement::default();
        };
        let penalty = if j.steer {
            CONSTRAINT_PENALTY * j.constraints.distance(pieces) as f64
        } else {
            0.0
        };
        if !valid {
            return Judgement {
                accept: true,
                penalty,
                fresh: false,
            };
        }
        let broken = j.constraints.check(&j.motions, pieces);
        let accept = broken.is_empty();
        if broken.iter().all(|v| {
            matches!(
                v,
                Violation::NotAssemblable { .. } | Violation::LevelTooLow { .. }
            )
        }) && !accept
        {
            j.refuse(pieces);
        }
        let mut fresh = false;
        if accept {
            if let Some((pieces, count)) = j.collect(pieces) {
                fresh = count <= j.wanted;
                self.observer.on_event(&EngineEvent::Collected {
                    pieces,
                    count,
                    seconds: self.seconds(),
                });
            }
        }
        Judgement {
            accept,
            penalty,
            fresh,
        }
    }
}

/// The exact search's events, sent to the thread that owns the run (the
/// exact search runs on a thread of its own that a stop does not wait for:
/// parts of it, such as the cheap bound, do not look at the stop flag).
pub(crate) struct Forward(pub(crate) Mutex<Sender<ExactEvent>>);

impl ExactObserver for Forward {
    fn on_event(&self, event: &ExactEvent) {
        let _ = self
            .0
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .send(event.clone());
    }
}

impl ExactObserver for Shared<'_> {
    fn on_event(&self, event: &ExactEvent) {
        match event {
            ExactEvent::CheapBound(b) | ExactEvent::Refuted(b) => {
                self.raise_lower(b.value, || (b.describe(self.names), proof(b, self.names)))
            }
            // The exact side cannot encode the assembly rules: what it
            // finds under them is no answer until the collection checks it.
            ExactEvent::Found { pieces, .. } if !self.exact_unchecked() => {
                self.found(*pieces, Source::Sat)
            }
            _ => {}
        }
        self.observer.on_event(&EngineEvent::Exact(event));
    }
}

/// The polish's observer: the run's, refusing every dissection with a
/// sliver and steering candidates away from tiny pieces.
pub(super) struct NoSlivers<'s, 'a>(pub(super) &'s Shared<'a>);

impl Observer for NoSlivers<'_, '_> {
    fn on_event(&self, event: &Event) {
        Observer::on_event(self.0, event);
    }

    fn judges(&self) -> bool {
        true
    }

    fn judge(&self, pieces: &[Vec<Vec<Cell>>], valid: bool) -> Judgement {
        let missing: usize = pieces.first().map_or(0, |p| {
            p.iter().map(|c| SLIVER_CELLS.saturating_sub(c.len())).sum()
        });
        Judgement {
            accept: !valid || missing == 0,
            penalty: 2.0 * missing as f64,
            fresh: false,
        }
    }
}

/// Why a dissection meeting `b` is optimal, in words.
pub(crate) fn proof(b: &Bound, names: &[String]) -> String {
    match &b.reason {
        Reason::Sat {
            refuted, seconds, ..
        }
        | Reason::External {
            refuted, seconds, ..
        } => format!(
            "no {refuted}-piece dissection exists; proof {}",
            if *seconds < 10.0 {
                format!("{seconds:.1} s")
            } else {
                format!("{seconds:.0} s")
            }
        ),
        _ => b.describe(names),
    }
}
