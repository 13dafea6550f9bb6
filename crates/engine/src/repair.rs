//! The heuristic's repair hook, implemented by the exact local repair of
//! `dissect-exact` (SAT over a neighbourhood of the mismatched cells, the
//! rest of the candidate fixed).

use std::sync::atomic::AtomicBool;

use dissect_core::solver::Repair;
use dissect_core::{Cell, Figure};
use dissect_exact::{repair, RepairOptions};

/// [`Repair`] by [`dissect_exact::repair()`] with a deterministic budget (SAT
/// conflicts); a deadline only when the run has a time limit.
pub struct ExactRepair<'a> {
    figures: &'a [Figure],
    options: RepairOptions,
}

impl<'a> ExactRepair<'a> {
    /// The repairer of near misses of `figures` with these options.
    pub fn new(figures: &'a [Figure], options: RepairOptions) -> ExactRepair<'a> {
        ExactRepair { figures, options }
    }
}

impl Repair for ExactRepair<'_> {
    fn repair(&self, pieces: &[Vec<Vec<Cell>>], stop: &AtomicBool) -> Option<Vec<Vec<Vec<Cell>>>> {
        // An error is a candidate the repair cannot take (or a bug it
        // reports); the search goes on without it.
        repair(self.figures, pieces, &self.options, stop)
            .ok()
            .flatten()
    }
}
