//! Regrouping: touching pieces of a dissection cut again with fewer.

use std::sync::atomic::AtomicBool;

use crate::lattice::{Cell, LatticeKind};
use crate::solver::regroup::regroup_once;
use crate::solver::Repair;
use crate::tests::util::{candidate, candidate_of, verified};

/// Dissects small figures into one piece when they are translates of each
/// other, and finds nothing otherwise (a stand-in for the exact search).
struct OnePiece;

impl Repair for OnePiece {
    fn repair(&self, _: &[Vec<Vec<Cell>>], _: &AtomicBool) -> Option<Vec<Vec<Vec<Cell>>>> {
        None
    }

    fn dissect(
        &self,
        figures: &[Vec<Cell>],
        _: usize,
        _: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        let normal = |cells: &Vec<Cell>| {
            let mut v = cells.clone();
            v.sort_unstable();
            let lo = [0, 1, 2].map(|d| v.iter().map(|c| c[d]).min().unwrap_or(0));
            v.iter()
                .map(|c| [c[0] - lo[0], c[1] - lo[1], c[2] - lo[2]])
                .collect::<Vec<_>>()
        };
        let first = normal(&figures[0]);
        figures
            .iter()
            .all(|f| normal(f) == first)
            .then(|| figures.iter().map(|f| vec![f.clone()]).collect())
    }
}

/// Four single cells of a 1x4 bar and a 2x2 square: the dominoes they pair
/// into are found one regrouping at a time, 4 pieces to 3 to 2, each a
/// verified dissection; then nothing is left to merge.
#[test]
fn single_cells_are_regrouped_into_dominoes() {
    let (mut figures, problem, cand) = candidate(LatticeKind::Square, true, &["ABCD", "AB|CD"]);
    let stop = AtomicBool::new(false);
    let mut tried = Vec::new();
    let (mut labels, mut k) = (cand.labels.clone(), cand.k);
    for expected in [3, 2] {
        let pieces = regroup_once(&figures, &problem, &labels, k, &OnePiece, &stop, &mut tried)
            .expect("a pair merges");
        assert_eq!(pieces[0].len(), expected);
        let parts = figures
            .iter()
            .zip(&pieces)
            .map(|(fig, fp)| {
                let l = fig
                    .cells()
                    .iter()
                    .map(|c| fp.iter().position(|p| p.contains(c)).expect("covered") as u16)
                    .collect();
                (fig.clone(), l)
            })
            .collect();
        let (figs, _, next) = candidate_of(LatticeKind::Square, true, parts);
        assert!(verified(LatticeKind::Square, true, &figs, &next));
        figures = figs;
        (labels, k) = (next.labels, next.k);
    }
    assert!(regroup_once(&figures, &problem, &labels, k, &OnePiece, &stop, &mut tried).is_none());
}

/// A raised stop ends the regrouping with nothing.
#[test]
fn a_stop_ends_the_regrouping() {
    let (figures, problem, cand) = candidate(LatticeKind::Square, true, &["ABCD", "AB|CD"]);
    let stop = AtomicBool::new(true);
    let out = regroup_once(
        &figures,
        &problem,
        &cand.labels,
        cand.k,
        &OnePiece,
        &stop,
        &mut Vec::new(),
    );
    assert!(out.is_none());
}
