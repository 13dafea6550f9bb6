//! A constructive dissection that always succeeds: align what is left of
//! every figure with what is left of the pivot figure by the motion (point
//! symmetry + lattice translation) that keeps the most cells in common, cut
//! the connected components of that common part out of every figure as
//! pieces, and repeat on what is left. A motion keeps adjacency, so a
//! component connected in the pivot is connected in every figure, and every
//! step removes at least one cell, so the worst case is single cells.
//!
//! It gives the anytime search a valid dissection within a fraction of a
//! second on figures of a few thousand cells; the level search then looks
//! for fewer pieces.

use crate::lattice::Point;
use crate::solver::candidate::{Candidate, Problem};
use crate::solver::shape::Shape;

/// Which components of the common part become pieces at each step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct GreedyStyle {
    /// The figure whose remainder the others are aligned to.
    pub(crate) pivot: usize,
    /// Keep the components of at least `largest / divisor` cells (1: only
    /// the largest ones).
    pub(crate) divisor: usize,
}

/// A valid dissection of the problem's shapes (labels `0..k`, every piece
/// connected and congruent in every figure).
pub(crate) fn greedy(problem: &Problem, style: GreedyStyle) -> Candidate {
    let shapes = &problem.shapes;
    let nf = shapes.len();
    let pivot = style.pivot.min(nf - 1);
    let n = shapes[0].len();
    let mut labels: Vec<Vec<u16>> = shapes.iter().map(|s| vec![FREE; s.len()]).collect();
    let mut left = n;
    let mut k: u16 = 0;
    while left > 0 {
        let (common, motions) = common_part(problem, pivot, &labels);
        debug_assert!(!common.is_empty(), "a single cell always fits");
        let comps = components(&shapes[pivot], &common);
        let largest = comps.iter().map(Vec::len).max().unwrap_or(0);
        let keep = (largest / style.divisor.max(1)).max(1);
        for comp in comps.into_iter().filter(|c| c.len() >= keep) {
            for &c in &comp {
                labels[pivot][c as usize] = k;
                for (f, m) in motions.iter().enumerate() {
                    if let Some((s, t)) = m {
                        let p = problem.geo.syms[*s].apply(shapes[pivot].point(c));
                        let j = shapes[f].lookup(p + *t).expect("kept cells land inside");
                        labels[f][j as usize] = k;
                    }
                }
            }
            left -= comp.len();
            k += 1;
        }
    }
    Candidate {
        labels,
        k: k as usize,
    }
}

/// The pivot's free cells whose images are free in every other figure
/// under the motions (one per other figure, `None` for the pivot) that keep
/// the most of them, chosen figure by figure.
pub(crate) fn common_part(
    problem: &Problem,
    pivot: usize,
    labels: &[Vec<u16>],
) -> (Vec<u32>, Vec<Option<(usize, Point)>>) {
    let shapes = &problem.shapes;
    let nf = shapes.len();
    let mut common: Vec<u32> = (0..shapes[pivot].len() as u32)
        .filter(|&c| labels[pivot][c as usize] == FREE)
        .collect();
    let mut motions: Vec<Option<(usize, Point)>> = vec![None; nf];
    for f in (0..nf).filter(|&f| f != pivot) {
        let (s, t) = best_motion(problem, pivot, &common, f, &labels[f]);
        let sym = problem.geo.syms[s];
        common.retain(|&c| {
            let p = sym.apply(shapes[pivot].point(c));
            shapes[f]
                .lookup(p + t)
                .is_some_and(|j| labels[f][j as usize] == FREE)
        });
        motions[f] = Some((s, t));
    }
    (common, motions)
}

/// The label of a cell no piece holds yet.
pub(crate) const FREE: u16 = u16::MAX;

/// Cell pairs that vote for translations in one symmetry, at most.
const VOTE_PAIRS: usize = 1 << 22;

/// The motion `(symmetry index, translation)` carrying the most of `cells`
/// (of shape `from`) onto free cells of shape `to`. Ties go to the first
/// symmetry, then the smallest translation in index order.
fn best_motion(
    problem: &Problem,
    from: usize,
    cells: &[u32],
    to: usize,
    to_labels: &[u16],
) -> (usize, Point) {
    let src = &problem.shapes[from];
    let dst = &problem.shapes[to];
    let free: Vec<Point> = (0..dst.len() as u32)
        .filter(|&c| to_labels[c as usize] == u16::MAX)
        .map(|c| dst.point(c))
        .collect();
    let m = problem.geo.modulus;
    let dim = problem.geo.dim;
    let (qlo, qhi) = bounds(&free);
    let mut best = (0u32, 0usize, [0i32; 3]);
    let mut votes: Vec<u32> = Vec::new();
    // Votes are counted over at most VOTE_PAIRS pairs per symmetry: on large
    // figures every `stride`-th cell votes (the count of a translation then
    // estimates its overlap), which keeps a step linear in the cells.
    let stride = (cells.len() * free.len()).div_ceil(VOTE_PAIRS).max(1);
    for (s, sym) in problem.geo.syms.iter().enumerate() {
        let moved: Vec<Point> = cells
            .iter()
            .step_by(stride)
            .map(|&c| sym.apply(src.point(c)))
            .collect();
        let (plo, phi) = bounds(&moved);
        // Translations t = q - p over every pair; only lattice translations
        // (multiples of the modulus in the moved coordinates, 0 elsewhere)
        // count.
        let mut lo = [0i32; 3];
        let mut size = [1usize; 3];
        for d in 0..dim {
            lo[d] = (qlo[d] - phi[d]).div_euclid(m);
            let hi = (qhi[d] - plo[d]).div_euclid(m);
            size[d] = (hi - lo[d] + 1) as usize;
        }
        votes.clear();
        votes.resize(size[0] * size[1] * size[2], 0);
        for p in &moved {
            for q in &free {
                let mut idx = 0usize;
                let mut ok = true;
                for d in (0..3).rev() {
                    let diff = q[d] - p[d];
                    if d >= dim {
                        ok &= diff == 0;
                        continue;
                    }
                    ok &= diff.rem_euclid(m) == 0;
                    idx = idx * size[d] + (diff.div_euclid(m) - lo[d]) as usize;
                }
                if ok {
                    votes[idx] += 1;
                }
            }
        }
        for (idx, &v) in votes.iter().enumerate() {
            if v > best.0 {
                let mut rest = idx;
                let mut t = [0i32; 3];
                for d in 0..dim {
                    t[d] = ((rest % size[d]) as i32 + lo[d]) * m;
                    rest /= size[d];
                }
                best = (v, s, t);
            }
        }
    }
    (best.1, Point::from(best.2))
}

fn bounds(points: &[Point]) -> (Point, Point) {
    let mut lo = [i32::MAX; 3];
    let mut hi = [i32::MIN; 3];
    for p in points {
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    (Point::from(lo), Point::from(hi))
}

/// The connected components of `cells` in `shape`, each sorted, in order of
/// their smallest cell.
pub(crate) fn components(shape: &Shape, cells: &[u32]) -> Vec<Vec<u32>> {
    let mut inside = vec![false; shape.len()];
    for &c in cells {
        inside[c as usize] = true;
    }
    let mut out = Vec::new();
    for &c in cells {
        if !inside[c as usize] {
            continue;
        }
        inside[c as usize] = false;
        let mut comp = vec![c];
        let mut i = 0;
        while i < comp.len() {
            for &nb in shape.neighbors(comp[i]) {
                if inside[nb as usize] {
                    inside[nb as usize] = false;
                    comp.push(nb);
                }
            }
            i += 1;
        }
        comp.sort_unstable();
        out.push(comp);
    }
    out
}
