//! The heuristic's repair hook, implemented by the exact local repair of
//! `dissect-exact` (SAT over a neighbourhood of the mismatched cells, the
//! rest of the candidate fixed), and its exact dissection of small figures
//! (the sectors of large ones) by the exact search.

use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};

use dissect_core::solver::Repair;
use dissect_core::{Cell, Figure};
use dissect_exact::{repair, search, ExactOptions, Mode, RepairOptions};
use dissect_puzzle::Constraints;

use crate::run::{EngineEvent, EngineObserver, Phase, SLIVER_CELLS};

/// SAT conflicts for one exact dissection of small figures (each of its
/// two searches), so that it ends the same way on every machine.
const DISSECT_BUDGET: u64 = 4_000;

/// SAT conflicts for all the exact dissections of small figures of one
/// run: the sectors of a run cost at most a few seconds.
const DISSECT_TOTAL_BUDGET: u64 = 16_000;

/// Conflicts of each restricted-motion pass of those searches.
const DISSECT_PASS_BUDGET: u64 = 1_000;

/// SAT conflicts for one regrouping search (the union of a few pieces of
/// the best dissection cut again).
const REGROUP_BUDGET: u64 = 6_000;

/// SAT conflicts for all of one run's regrouping searches.
const REGROUP_TOTAL_BUDGET: u64 = 400_000;

/// The memory one of those encodings may take.
const DISSECT_MAX_ENCODING_BYTES: u64 = 32 << 20;

/// [`Repair`] by [`dissect_exact::repair()`] (near misses) and
/// [`dissect_exact::search()`] (small figures: the sectors), each with a
/// deterministic budget of SAT conflicts; a deadline only when the run has a
/// time limit. The small figures' budget is one per repairer, so one run's
/// searches (its coarse run and its polish included) share it.
pub struct ExactRepair<'a> {
    figures: &'a [Figure],
    options: RepairOptions,
    /// Conflicts spent so far by [`Repair::dissect`].
    spent: AtomicU64,
    /// Conflicts spent so far by [`Repair::regroup`].
    regrouped: AtomicU64,
    /// Hears [`EngineEvent::Phase`] at each call.
    observer: Option<&'a dyn EngineObserver>,
}

impl<'a> ExactRepair<'a> {
    /// The repairer of near misses of `figures` with these options.
    pub fn new(figures: &'a [Figure], options: RepairOptions) -> ExactRepair<'a> {
        ExactRepair {
            figures,
            options,
            spent: AtomicU64::new(0),
            regrouped: AtomicU64::new(0),
            observer: None,
        }
    }

    /// The same repairer, telling `observer` of each call
    /// ([`EngineEvent::Phase`]: repair, sectors, regroup).
    pub fn with_observer(mut self, observer: &'a dyn EngineObserver) -> ExactRepair<'a> {
        self.observer = Some(observer);
        self
    }

    fn phase(&self, phase: Phase) {
        if let Some(o) = self.observer {
            o.on_event(&EngineEvent::Phase(phase));
        }
    }
}

impl Repair for ExactRepair<'_> {
    fn repair(&self, pieces: &[Vec<Vec<Cell>>], stop: &AtomicBool) -> Option<Vec<Vec<Vec<Cell>>>> {
        self.phase(Phase::Repair);
        // An error is a candidate the repair cannot take (or a bug it
        // reports); the search goes on without it.
        repair(self.figures, pieces, &self.options, stop)
            .ok()
            .flatten()
    }

    /// The exact search ([`Mode::Minimum`], at most `max_pieces` pieces,
    /// 4,000 conflicts); when its answer has a piece of fewer than
    /// [`SLIVER_CELLS`] cells, again with that as `--min-piece` and no more
    /// pieces. All these searches of one run share 16,000 conflicts.
    fn dissect(
        &self,
        figures: &[Vec<Cell>],
        max_pieces: usize,
        stop: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        self.phase(Phase::Sectors);
        let figures = self.small_figures(figures)?;
        let budget = Budget {
            spent: &self.spent,
            total: DISSECT_TOTAL_BUDGET,
            each: DISSECT_BUDGET,
        };
        let minimum = |max_pieces: usize, constraints: Option<Constraints>| {
            self.minimum(&figures, max_pieces, constraints, &budget, stop)
        };
        let first = minimum(max_pieces, None)?;
        let k = first[0].len();
        let small = first[0].iter().any(|p| p.len() < SLIVER_CELLS);
        if !small || figures[0].len() < SLIVER_CELLS * k {
            return Some(first);
        }
        let sized = Constraints::none().with_sizes(Some(SLIVER_CELLS), None);
        Some(minimum(k, Some(sized)).unwrap_or(first))
    }

    /// The exact search ([`Mode::Minimum`], at most `max_pieces` pieces,
    /// 6,000 conflicts); all of one run's regrouping searches share 400,000.
    fn regroup(
        &self,
        figures: &[Vec<Cell>],
        max_pieces: usize,
        stop: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        self.phase(Phase::Regroup);
        let figures = self.small_figures(figures)?;
        let budget = Budget {
            spent: &self.regrouped,
            total: REGROUP_TOTAL_BUDGET,
            each: REGROUP_BUDGET,
        };
        self.minimum(&figures, max_pieces, None, &budget, stop)
    }
}

/// A share of SAT conflicts: `each` per search, `total` for all of them.
struct Budget<'a> {
    spent: &'a AtomicU64,
    total: u64,
    each: u64,
}

impl ExactRepair<'_> {
    /// Cells as figures of the run's lattice.
    fn small_figures(&self, figures: &[Vec<Cell>]) -> Option<Vec<Figure>> {
        let lattice = self.figures.first()?.lattice();
        figures
            .iter()
            .map(|cells| Figure::new(lattice, cells.iter().copied()))
            .collect::<Result<_, _>>()
            .ok()
    }

    /// A minimum dissection of `figures` with at most `max_pieces` pieces
    /// under `constraints`, within what is left of `budget`.
    fn minimum(
        &self,
        figures: &[Figure],
        max_pieces: usize,
        constraints: Option<Constraints>,
        budget: &Budget<'_>,
        stop: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        let left = budget
            .total
            .checked_sub(budget.spent.load(Ordering::SeqCst))?;
        if left == 0 {
            return None;
        }
        let options = ExactOptions {
            mirror: self.options.mirror,
            mode: Mode::Minimum,
            deadline: self.options.deadline,
            max_pieces: Some(max_pieces),
            conflict_budget: Some(left.min(budget.each)),
            restricted_conflicts: Some(DISSECT_PASS_BUDGET),
            max_encoding_bytes: DISSECT_MAX_ENCODING_BYTES,
            constraints,
            ..ExactOptions::default()
        };
        let upper = AtomicUsize::new(usize::MAX);
        let outcome = search(figures, &options, stop, &upper, &()).ok()?;
        budget.spent.fetch_add(outcome.conflicts, Ordering::SeqCst);
        outcome.found
    }
}
