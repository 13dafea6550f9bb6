//! Refinement (paper section 3.3): copy-paste, hole filling by random flood
//! fill, and random label switching, with every figure in turn as the pivot.
//!
//! With two figures, the step with pivot A is the paper's forward refinement
//! (B is changed toward A) and the step with pivot B its backward one. With
//! more figures (section 3.6) the pivot is pasted into every other figure and
//! label switching runs in every figure, a cell being a candidate when its
//! image in any other figure conflicts.

use std::sync::atomic::{AtomicBool, Ordering};

use rand::seq::SliceRandom;
use rand::RngExt;

use crate::solver::candidate::{Aligned, Candidate, Problem};
use crate::solver::flood_fill::{flood_fill, Fallback};
use crate::solver::piece::UNSET;
use crate::transform::Transform;

/// The transforms that carry each figure's piece `a` onto the pivot's piece
/// `a` and on to every other figure.
pub(crate) struct Motions {
    pivot: usize,
    /// `to[f][a]`: pivot piece `a` → figure `f` (identity for the pivot).
    to: Vec<Vec<Transform>>,
    /// `from[f][a]`: figure `f` piece `a` → pivot.
    from: Vec<Vec<Transform>>,
}

impl Motions {
    pub(crate) fn of(aligned: &Aligned, pivot: usize, k: usize) -> Motions {
        let to: Vec<Vec<Transform>> = aligned
            .matchings
            .iter()
            .map(|m| match m {
                Some(m) => m.transforms.clone(),
                None => vec![Transform::IDENTITY; k],
            })
            .collect();
        let from = to
            .iter()
            .map(|ts| ts.iter().map(|t| t.inverse()).collect())
            .collect();
        Motions { pivot, to, from }
    }
}

/// The cells of figure `f` whose image conflicts: lands outside another
/// figure or on a cell of another piece there. With `all_figures` false only
/// the pivot is compared against.
pub(crate) fn conflicts(
    problem: &Problem,
    cand: &Candidate,
    motions: &Motions,
    f: usize,
    all_figures: bool,
) -> Vec<u32> {
    let shape = &problem.shapes[f];
    let labels = &cand.labels[f];
    let p = motions.pivot;
    let mut out = Vec::new();
    let hits = |g: usize, q, a: u16| -> bool {
        matches!(problem.shapes[g].lookup(q), Some(j) if cand.labels[g][j as usize] == a)
    };
    for c in 0..shape.len() as u32 {
        let a = labels[c as usize];
        let x = shape.point(c);
        let ai = a as usize;
        let at_pivot = if f == p {
            x
        } else {
            motions.from[f][ai].apply(x)
        };
        let mut bad = f != p && !hits(p, at_pivot, a);
        if !bad && (all_figures || f == p) {
            for g in 0..problem.shapes.len() {
                if g == f || g == p {
                    continue;
                }
                if !hits(g, motions.to[g][ai].apply(at_pivot), a) {
                    bad = true;
                    break;
                }
            }
        }
        if bad {
            out.push(c);
        }
    }
    out
}

/// One refinement step with `pivot`; returns the number of conflicting
/// cells found by label switching (0 means every figure matches the pivot).
pub(crate) fn pivot_step<R: rand::Rng>(
    problem: &Problem,
    cand: &mut Candidate,
    pivot: usize,
    rng: &mut R,
) -> usize {
    let nfig = problem.shapes.len();
    // 1-2. Copy-paste from the pivot into every other figure, then fill holes.
    let aligned = cand.align(problem, pivot);
    let pivot_pieces = &aligned.pieces[pivot];
    let mut order: Vec<usize> = (0..cand.k).collect();
    for f in 0..nfig {
        if f == pivot {
            continue;
        }
        let m = aligned.matchings[f]
            .as_ref()
            .expect("non-pivot has a matching");
        let shape = &problem.shapes[f];
        let pshape = &problem.shapes[pivot];
        let mut fresh = vec![UNSET; shape.len()];
        order.shuffle(rng);
        for &a in &order {
            let t = m.transforms[a];
            for &c in pivot_pieces.members(a) {
                if let Some(j) = shape.lookup(t.apply(pshape.point(c))) {
                    fresh[j as usize] = a as u16;
                }
            }
        }
        flood_fill(shape, &mut fresh, Fallback::Previous(&cand.labels[f]), rng);
        cand.labels[f] = fresh;
    }
    // 3. Random label switching against the new matching.
    let aligned = cand.align(problem, pivot);
    let motions = Motions::of(&aligned, pivot, cand.k);
    let all = nfig > 2;
    let mut total = 0;
    for f in 0..nfig {
        if f == pivot && !all {
            continue;
        }
        let bad = conflicts(problem, cand, &motions, f, all);
        total += bad.len();
        let shape = &problem.shapes[f];
        let old = cand.labels[f].clone();
        for c in bad {
            let nb = shape.neighbors(c);
            if !nb.is_empty() {
                cand.labels[f][c as usize] = old[nb[rng.random_range(0..nb.len())] as usize];
            }
        }
    }
    total
}

/// The cells of each figure whose image conflicts in some other figure,
/// with labels aligned to figure 0.
pub(crate) fn mismatched_cells(problem: &Problem, cand: &mut Candidate) -> Vec<Vec<u32>> {
    let aligned = cand.align(problem, 0);
    let motions = Motions::of(&aligned, 0, cand.k);
    (0..problem.shapes.len())
        .map(|f| conflicts(problem, cand, &motions, f, true))
        .collect()
}

/// Runs up to `iterations` refinement iterations (every figure once as the
/// pivot). Stops early when nothing changes, when the candidate becomes a
/// valid dissection, or when `stop` is raised (the paper's loop), and also
/// once the number of conflicting cells has not
/// improved on its best for `patience` iterations (0: never). Random label
/// switching keeps changing labels on a plateau, so without this a stuck
/// exploration runs all its iterations for nothing.
pub(crate) fn refine_with_patience<R: rand::Rng>(
    problem: &Problem,
    cand: &mut Candidate,
    iterations: usize,
    patience: usize,
    rng: &mut R,
    stop: &AtomicBool,
) {
    let nfig = problem.shapes.len();
    let mut best = usize::MAX;
    let mut since_best = 0;
    for _ in 0..iterations {
        if stop.load(Ordering::Relaxed) {
            return;
        }
        let before = cand.labels.clone();
        let mut total = 0;
        for pivot in 0..nfig {
            let conflicts = pivot_step(problem, cand, pivot, rng);
            if conflicts == 0 && all_connected(problem, cand) {
                return;
            }
            total += conflicts;
        }
        if cand.labels == before {
            return;
        }
        if total < best {
            best = total;
            since_best = 0;
        } else {
            since_best += 1;
            if patience > 0 && since_best >= patience {
                return;
            }
        }
    }
}

/// Whether every non-empty piece of every figure is connected.
pub(crate) fn all_connected(problem: &Problem, cand: &Candidate) -> bool {
    (0..problem.shapes.len()).all(|f| {
        let shape = &problem.shapes[f];
        let pieces = cand.pieces(problem, f);
        let mut scratch = vec![false; shape.len()];
        (0..cand.k).all(|i| pieces.size(i) == 0 || pieces.components(shape, i, &mut scratch) == 1)
    })
}
