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

use std::sync::atomic::{AtomicBool, Ordering};

use crate::lattice::{Point, Symmetry};
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
    /// How each step's motion is chosen.
    pub(crate) choice: Choice,
    /// Added to the translation of the first step's motion of the first
    /// other figure ([`Point::ORIGIN`]: the paper's greedy): a displaced
    /// start, whose first piece lies off the largest common part and
    /// leaves another large part beside it (the anytime search's
    /// displaced starts). Ignored where the displaced motion keeps no cell.
    pub(crate) start: Point,
}

/// How a greedy step chooses the motion of a figure onto the pivot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Choice {
    /// The most cells in common (the paper's largest common sub-figure).
    Overlap,
    /// Among the best [`CANDIDATES`] translations of every symmetry class
    /// by overlap, the one whose common part has the largest connected
    /// component (then the most cells): a large overlap in many small
    /// components makes many small pieces.
    Connected,
    /// Among [`Choice::Connected`]'s candidates whose largest component
    /// gives up at most `1 / slack` of the best one's cells, the one whose
    /// cut leaves the fewest components in the remainder of the more
    /// broken of the two figures (each component needs a piece of its
    /// own), then in both, then the connected choice's order: the cut is
    /// chosen for the remainder it leaves, not only for its own size.
    Tidy {
        /// The largest component may be `1 / slack` smaller than the best.
        slack: usize,
    },
}

/// The tidy choices the anytime search tries (slack 1/4 is the pilot's
/// usual choice; BENCHMARKS, "3D: remainder-aware cuts").
pub(crate) const TIDY_SLACKS: [usize; 3] = [4, 3, 6];

/// Translations per symmetry class that [`Choice::Connected`] compares.
const CANDIDATES: usize = 8;

/// A valid dissection of the problem's shapes (labels `0..k`, every piece
/// connected and congruent in every figure).
#[cfg(test)]
pub(crate) fn greedy(problem: &Problem, style: GreedyStyle) -> Candidate {
    greedy_until(problem, style, &AtomicBool::new(false)).expect("never stopped")
}

/// [`greedy`], or `None` when `stop` is raised before it ends (asked once
/// per step).
pub(crate) fn greedy_until(
    problem: &Problem,
    style: GreedyStyle,
    stop: &AtomicBool,
) -> Option<Candidate> {
    let mut state = State::new(problem, style);
    state.finish(stop)?;
    Some(state.into_candidate())
}

/// How far [`pilot_until`] looks ahead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Lookahead {
    /// Motions tried from each kept state at a step.
    pub(crate) width: usize,
    /// Steps looked ahead (the rest are finished greedily).
    pub(crate) depth: usize,
    /// States kept from one step to the next (1: the pilot method).
    pub(crate) beam: usize,
}

/// The pilot method on the greedy, as a beam: at each of the first `depth`
/// steps, from each of the `beam` kept states, the best `width` motions of
/// the first other figure (by the style's ranking) are each taken and the
/// dissection finished greedily; the `beam` distinct next states whose
/// finished dissections have the fewest pieces are kept (on ties, the
/// earlier kept state's, then the better-ranked motion's). With `beam` 1
/// this is the pilot method: the step whose finished dissection has the
/// fewest pieces, the first on ties. Returns the fewest-piece dissection
/// finished on the way and whether some step had more motions than
/// `width` (a wider pilot would look at more); `None` when `stop` is
/// raised before it ends.
pub(crate) fn pilot_until(
    problem: &Problem,
    style: GreedyStyle,
    look: Lookahead,
    stop: &AtomicBool,
) -> Option<(Candidate, bool)> {
    let root = State::new(problem, style);
    let other = (0..problem.shapes.len()).find(|&f| f != root.pivot)?;
    let mut best: Option<Candidate> = None;
    let mut truncated = false;
    let (width, beam_width) = (look.width.max(1), look.beam.max(1));
    let mut beam = vec![root];
    for _ in 0..look.depth {
        if beam.iter().all(|s| s.left == 0) {
            break;
        }
        // (pieces once finished, index of the state it came from, state).
        let mut next: Vec<(usize, usize, State)> = Vec::new();
        for (from, state) in beam.iter().enumerate() {
            if state.left == 0 {
                // Finished: its dissection was counted when it was cut.
                continue;
            }
            let cells = state.free_pivot_cells();
            let motions = ranked_motions(
                problem,
                state.pivot,
                &cells,
                other,
                &state.labels[other],
                (style.choice, style.divisor),
            );
            truncated |= motions.len() > width;
            for &m in motions.iter().take(width) {
                let mut stepped = state.clone();
                stepped.step(Some((other, m)));
                let mut done = stepped.clone();
                done.finish(stop)?;
                let pieces = done.k as usize;
                if best.as_ref().is_none_or(|b| pieces < b.k) {
                    best = Some(done.into_candidate());
                }
                next.push((pieces, from, stepped));
            }
        }
        // Stable: ties keep the kept state's order, then the motions'.
        next.sort_by_key(|&(pieces, from, _)| (pieces, from));
        let mut kept: Vec<State> = Vec::with_capacity(beam_width);
        for (_, _, state) in next {
            if kept.len() == beam_width {
                break;
            }
            // Two motions that differ by a symmetry of the piece they cut
            // give the same state.
            if kept.iter().all(|k| k.labels != state.labels) {
                kept.push(state);
            }
        }
        if kept.is_empty() {
            break;
        }
        beam = kept;
    }
    let mut state = beam.swap_remove(0);
    if state.left > 0 {
        state.finish(stop)?;
    }
    let last = state.into_candidate();
    let found = match best {
        Some(b) if b.k <= last.k => b,
        _ => last,
    };
    Some((found, truncated))
}

/// A randomized rebuild of a dissection's tail (a large neighbourhood
/// search step): the `keep` largest pieces of `cand` (whose label names the
/// same piece in every figure) stay, and what is left of every figure is
/// cut again greedily, each step's motion of the first other figure drawn
/// from the style's ranking: the best, except with a probability drawn
/// once per rebuild (0.05, 0.15 or 0.3) one of the next `top - 1`. The
/// constructive steps draw nothing at random, so their tails are all
/// alike; this looks at their neighbours. `None` when stopped.
pub(crate) fn rebuild_until(
    problem: &Problem,
    style: GreedyStyle,
    (cand, keep): (&Candidate, usize),
    (rng, top): (&mut impl rand::Rng, usize),
    stop: &AtomicBool,
) -> Option<Candidate> {
    use rand::RngExt;
    let mut state = State::new(problem, style);
    let pivot = state.pivot;
    let mut size = vec![0usize; cand.k];
    for &l in &cand.labels[pivot] {
        size[l as usize] += 1;
    }
    let mut order: Vec<usize> = (0..cand.k).collect();
    order.sort_by_key(|&l| (std::cmp::Reverse(size[l]), l));
    let mut relabel = vec![FREE; cand.k];
    for (new, &l) in order.iter().take(keep).enumerate() {
        relabel[l] = new as u16;
    }
    for (mine, theirs) in state.labels.iter_mut().zip(&cand.labels) {
        for (m, &t) in mine.iter_mut().zip(theirs) {
            *m = relabel[t as usize];
        }
    }
    state.k = keep.min(cand.k) as u16;
    state.left = state.labels[pivot].iter().filter(|&&l| l == FREE).count();
    let other = (0..problem.shapes.len()).find(|&f| f != pivot)?;
    // How often a step leaves the best motion: a few steps of the tail.
    let stray = [0.05, 0.15, 0.3][rng.random_range(0..3)];
    while state.left > 0 {
        if stop.load(Ordering::Relaxed) {
            return None;
        }
        let cells = state.free_pivot_cells();
        let motions = ranked_motions(
            problem,
            pivot,
            &cells,
            other,
            &state.labels[other],
            (style.choice, style.divisor),
        );
        let pick = if motions.len() < 2 || !rng.random_bool(stray) {
            0
        } else {
            rng.random_range(1..motions.len().min(top.max(2)))
        };
        state.step(motions.get(pick).map(|&m| (other, m)));
    }
    Some(state.into_candidate())
}

/// A greedy dissection under way: the labels given so far.
#[derive(Clone)]
struct State<'p> {
    problem: &'p Problem,
    style: GreedyStyle,
    pivot: usize,
    labels: Vec<Vec<u16>>,
    left: usize,
    k: u16,
}

impl<'p> State<'p> {
    fn new(problem: &'p Problem, style: GreedyStyle) -> State<'p> {
        let shapes = &problem.shapes;
        State {
            problem,
            style,
            pivot: style.pivot.min(shapes.len() - 1),
            labels: shapes.iter().map(|s| vec![FREE; s.len()]).collect(),
            left: shapes[0].len(),
            k: 0,
        }
    }

    /// The pivot's cells no piece holds yet.
    fn free_pivot_cells(&self) -> Vec<u32> {
        (0..self.labels[self.pivot].len() as u32)
            .filter(|&c| self.labels[self.pivot][c as usize] == FREE)
            .collect()
    }

    /// Steps until every cell is in a piece; `None` when stopped.
    fn finish(&mut self, stop: &AtomicBool) -> Option<()> {
        while self.left > 0 {
            if stop.load(Ordering::Relaxed) {
                return None;
            }
            self.step(None);
        }
        Some(())
    }

    /// One step: the common part (with figure `forced.0`'s motion
    /// `forced.1` when given), its kept components cut as pieces.
    fn step(&mut self, forced: Option<(usize, (usize, Point))>) {
        let (problem, pivot) = (self.problem, self.pivot);
        let shapes = &problem.shapes;
        // The first step may be displaced.
        let start = (self.k == 0 && self.style.start != Point::ORIGIN).then_some(self.style.start);
        let (common, motions) = common_part_with(
            problem,
            pivot,
            &self.labels,
            (self.style.choice, self.style.divisor),
            (forced, start),
        );
        debug_assert!(!common.is_empty(), "a single cell always fits");
        let comps = components(&shapes[pivot], &common);
        let largest = comps.iter().map(Vec::len).max().unwrap_or(0);
        let keep = (largest / self.style.divisor.max(1)).max(1);
        for comp in comps.into_iter().filter(|c| c.len() >= keep) {
            for &c in &comp {
                self.labels[pivot][c as usize] = self.k;
                for (f, m) in motions.iter().enumerate() {
                    if let Some((s, t)) = m {
                        let p = problem.geo.syms[*s].apply(shapes[pivot].point(c));
                        let j = shapes[f].lookup(p + *t).expect("kept cells land inside");
                        self.labels[f][j as usize] = self.k;
                    }
                }
            }
            self.left -= comp.len();
            self.k += 1;
        }
    }

    fn into_candidate(self) -> Candidate {
        Candidate {
            labels: self.labels,
            k: self.k as usize,
        }
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
    common_part_by(problem, pivot, labels, Choice::Overlap)
}

/// [`common_part`], each motion chosen by `choice`.
pub(crate) fn common_part_by(
    problem: &Problem,
    pivot: usize,
    labels: &[Vec<u16>],
    choice: Choice,
) -> (Vec<u32>, Vec<Option<(usize, Point)>>) {
    common_part_with(problem, pivot, labels, (choice, 1), (None, None))
}

/// A figure's motion imposed on a greedy step: the figure, then its motion
/// (symmetry index, translation).
type Forced = (usize, (usize, Point));

/// [`common_part_by`] (with the style's divisor for [`Choice::Tidy`]),
/// figure `forced.0` moved by `forced.1` when given; the first other
/// figure's translation displaced by `start` when given and the displaced
/// motion keeps a cell.
fn common_part_with(
    problem: &Problem,
    pivot: usize,
    labels: &[Vec<u16>],
    choice: (Choice, usize),
    (forced, start): (Option<Forced>, Option<Point>),
) -> (Vec<u32>, Vec<Option<(usize, Point)>>) {
    let shapes = &problem.shapes;
    let nf = shapes.len();
    let mut common: Vec<u32> = (0..shapes[pivot].len() as u32)
        .filter(|&c| labels[pivot][c as usize] == FREE)
        .collect();
    let mut motions: Vec<Option<(usize, Point)>> = vec![None; nf];
    let first_other = (0..nf).find(|&f| f != pivot);
    for f in (0..nf).filter(|&f| f != pivot) {
        let (s, t) = match forced {
            Some((g, m)) if g == f => m,
            _ => best_motion(problem, pivot, &common, f, &labels[f], choice),
        };
        let sym = problem.geo.syms[s];
        let keeps = |t: Point, c: u32| {
            let p = sym.apply(shapes[pivot].point(c));
            shapes[f]
                .lookup(p + t)
                .is_some_and(|j| labels[f][j as usize] == FREE)
        };
        // A displaced first motion, when it keeps a cell; the chosen one
        // otherwise (in place: every greedy step comes here).
        let displaced = start.filter(|_| Some(f) == first_other).and_then(|d| {
            let cells: Vec<u32> = common
                .iter()
                .copied()
                .filter(|&c| keeps(t + d, c))
                .collect();
            (!cells.is_empty()).then_some((t + d, cells))
        });
        let t = if let Some((displaced_t, cells)) = displaced {
            common = cells;
            displaced_t
        } else {
            common.retain(|&c| keeps(t, c));
            t
        };
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
///
/// Symmetries that are equivalent for this question are counted once: when
/// `h` maps the free cells of `to` onto themselves (up to a lattice
/// translation) and `r` does so for `cells`, then `h ∘ s ∘ r` carries as
/// many cells as `s` does, so only the first symmetry of each such class
/// votes (on a cube into a box, one of 48 at the first step). The classes'
/// votes run in parallel on the current rayon pool and are combined in
/// symmetry order, so the answer does not depend on the threads.
fn best_motion(
    problem: &Problem,
    from: usize,
    cells: &[u32],
    to: usize,
    to_labels: &[u16],
    choice: (Choice, usize),
) -> (usize, Point) {
    match choice.0 {
        Choice::Overlap => {
            let mut top = (0u32, 0usize, [0i32; 3]);
            for b in candidate_votes(problem, from, cells, to, to_labels, 1) {
                if b.0 > top.0 {
                    top = b;
                }
            }
            (top.1, Point::from(top.2))
        }
        Choice::Connected | Choice::Tidy { .. } => {
            ranked_motions(problem, from, cells, to, to_labels, choice)
                .first()
                .copied()
                .unwrap_or((0, Point::from([0, 0, 0])))
        }
    }
}

/// The motions of [`Choice::Connected`]'s candidates, best first: the
/// largest component of the common part, then the most cells, then the
/// candidates' order. With [`Choice::Tidy`] (and the style's divisor), the
/// candidates within its slack of the largest component come first, by
/// the components their cut leaves ([`remainder_parts`]).
fn ranked_motions(
    problem: &Problem,
    from: usize,
    cells: &[u32],
    to: usize,
    to_labels: &[u16],
    choice: (Choice, usize),
) -> Vec<(usize, Point)> {
    use rayon::prelude::*;
    let src = &problem.shapes[from];
    let dst = &problem.shapes[to];
    let in_free = |p: Point| dst.lookup(p).is_some_and(|j| to_labels[j as usize] == FREE);
    let all = candidate_votes(problem, from, cells, to, to_labels, CANDIDATES);
    let tidy_choice = matches!(choice.0, Choice::Tidy { .. });
    // Per candidate: (largest component, cells in common), and the
    // components themselves when the tidy choice looks at their cut.
    let scored: Vec<(MotionScore, Vec<Vec<u32>>)> = all
        .par_iter()
        .map(|&(_, s, t)| {
            let (sym, t) = (problem.geo.syms[s], Point::from(t));
            let common: Vec<u32> = cells
                .iter()
                .copied()
                .filter(|&c| in_free(sym.apply(src.point(c)) + t))
                .collect();
            let comps = components(src, &common);
            let largest = comps.iter().map(Vec::len).max().unwrap_or(0);
            let kept = if tidy_choice { comps } else { Vec::new() };
            ((largest, common.len()), kept)
        })
        .collect();
    let best = scored.iter().map(|s| s.0 .0).max().unwrap_or(0);
    let floor = match choice.0 {
        Choice::Tidy { slack } => best - best / slack.max(1),
        _ => usize::MAX,
    };
    // The tidy key: the same for every candidate under the connected choice.
    let tidy: Vec<(usize, usize)> = all
        .par_iter()
        .zip(&scored)
        .map(|(&(_, s, t), ((largest, _), comps))| {
            if *largest < floor || *largest == 0 {
                return (usize::MAX, usize::MAX);
            }
            let motion = (s, Point::from(t));
            remainder_parts(
                problem,
                from,
                cells,
                to,
                to_labels,
                motion,
                (comps, choice.1),
            )
        })
        .collect();
    let mut order: Vec<usize> = (0..all.len()).collect();
    order.sort_by_key(|&i| (tidy[i], std::cmp::Reverse(scored[i].0), i));
    order
        .into_iter()
        .map(|i| (all[i].1, Point::from(all[i].2)))
        .collect()
}

/// A candidate motion's score under the connected choice: its common
/// part's largest component, then its cells.
type MotionScore = (usize, usize);

/// What the cut of `motion` leaves (of the common part's components
/// `cut.0`, those of at least `largest / cut.1` cells): the components of
/// the remainder in the more broken of the two figures, then in both
/// together.
fn remainder_parts(
    problem: &Problem,
    from: usize,
    cells: &[u32],
    to: usize,
    to_labels: &[u16],
    motion: (usize, Point),
    cut: (&[Vec<u32>], usize),
) -> (usize, usize) {
    let (comps, divisor) = cut;
    let (src, dst) = (&problem.shapes[from], &problem.shapes[to]);
    let sym = problem.geo.syms[motion.0];
    let largest = comps.iter().map(Vec::len).max().unwrap_or(0);
    let keep = (largest / divisor.max(1)).max(1);
    let mut left_src = vec![false; src.len()];
    for &c in cells {
        left_src[c as usize] = true;
    }
    let mut left_dst: Vec<bool> = to_labels.iter().map(|&l| l == FREE).collect();
    for comp in comps.iter().filter(|c| c.len() >= keep) {
        for &c in comp {
            left_src[c as usize] = false;
            let j = dst
                .lookup(sym.apply(src.point(c)) + motion.1)
                .expect("a common cell lands inside");
            left_dst[j as usize] = false;
        }
    }
    let a = src.count_marked(cells.iter().copied(), &mut left_src);
    let b = dst.count_marked(0..dst.len() as u32, &mut left_dst);
    (a.max(b), a + b)
}

/// The best `take` translations by votes of every class of symmetries
/// (see [`best_motion`]), classes in symmetry order.
fn candidate_votes(
    problem: &Problem,
    from: usize,
    cells: &[u32],
    to: usize,
    to_labels: &[u16],
    take: usize,
) -> Vec<(u32, usize, [i32; 3])> {
    use rayon::prelude::*;
    let src = &problem.shapes[from];
    let dst = &problem.shapes[to];
    let free: Vec<Point> = (0..dst.len() as u32)
        .filter(|&c| to_labels[c as usize] == FREE)
        .map(|c| dst.point(c))
        .collect();
    let source: Vec<Point> = cells.iter().map(|&c| src.point(c)).collect();
    let syms = &problem.geo.syms;
    let in_free = |p: Point| dst.lookup(p).is_some_and(|j| to_labels[j as usize] == FREE);
    let mut in_cells = vec![false; src.len()];
    for &c in cells {
        in_cells[c as usize] = true;
    }
    let in_source = |p: Point| src.lookup(p).is_some_and(|j| in_cells[j as usize]);
    let left = stabilizer(problem, &free, &in_free);
    let right = stabilizer(problem, &source, &in_source);
    let reps = representatives(syms, &left, &right);
    // Votes are counted over at most VOTE_PAIRS pairs per symmetry: on large
    // figures every `stride`-th cell votes (the count of a translation then
    // estimates its overlap), which keeps a step linear in the cells.
    let stride = (cells.len() * free.len()).div_ceil(VOTE_PAIRS).max(1);
    let best: Vec<Vec<(u32, usize, [i32; 3])>> = reps
        .par_iter()
        .map(|&s| votes_of(problem, &source, &free, stride, s, take))
        .collect();
    best.into_iter().flatten().collect()
}

/// The `take` translations carrying the most of `source` (every
/// `stride`-th point) under symmetry `s` onto `free` ([`top_votes`]:
/// fewer when fewer have a vote): `(votes, s, translation)`, most votes
/// first, the smallest translation in index order on ties.
fn votes_of(
    problem: &Problem,
    source: &[Point],
    free: &[Point],
    stride: usize,
    s: usize,
    take: usize,
) -> Vec<(u32, usize, [i32; 3])> {
    let m = problem.geo.modulus;
    let dim = problem.geo.dim;
    let sym = problem.geo.syms[s];
    let (qlo, qhi) = bounds(free);
    let moved: Vec<Point> = source
        .iter()
        .step_by(stride)
        .map(|&p| sym.apply(p))
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
    // With q = p + t, t a lattice translation: same residue, and the vote's
    // index is U(q) - U(p) - L for the quotients' linear index U.
    let (mut residues, mut classes): (Vec<Point>, Vec<Vec<i64>>) = (Vec::new(), Vec::new());
    let split = |x: Point| -> (Point, i64) {
        let mut r = [0i32; 3];
        let (mut u, mut step) = (0i64, 1i64);
        for d in 0..3 {
            if d < dim {
                r[d] = x[d].rem_euclid(m);
                u += i64::from(x[d].div_euclid(m)) * step;
                step *= size[d] as i64;
            } else {
                r[d] = x[d];
            }
        }
        (Point::from(r), u)
    };
    for &q in free {
        let (r, u) = split(q);
        match residues.iter().position(|x| *x == r) {
            Some(i) => classes[i].push(u),
            None => {
                residues.push(r);
                classes.push(vec![u]);
            }
        }
    }
    let low: i64 = (0..dim)
        .rev()
        .fold(0i64, |acc, d| acc * size[d] as i64 + i64::from(lo[d]));
    let mut votes = vec![0u32; size[0] * size[1] * size[2]];
    for &p in &moved {
        let (r, u) = split(p);
        let Some(i) = residues.iter().position(|x| *x == r) else {
            continue;
        };
        let base = -u - low;
        for &uq in &classes[i] {
            votes[(uq + base) as usize] += 1;
        }
    }
    let translation = |idx: usize| {
        let mut rest = idx;
        let mut t = [0i32; 3];
        for d in 0..dim {
            t[d] = ((rest % size[d]) as i32 + lo[d]) * m;
            rest /= size[d];
        }
        t
    };
    top_votes(&votes, take)
        .into_iter()
        .map(|(v, idx)| (v, s, translation(idx)))
        .collect()
}

/// The `take` entries of `votes` with the most votes (none with 0), most
/// first, the smaller index first on ties: one pass that keeps the best
/// `take` so far in a heap whose top is the worst of them.
pub(crate) fn top_votes(votes: &[u32], take: usize) -> Vec<(u32, usize)> {
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    if take == 0 {
        return Vec::new();
    }
    let mut heap: BinaryHeap<(Reverse<u32>, usize)> = BinaryHeap::with_capacity(take + 1);
    // While the heap is full, an entry must beat its worst vote: indices
    // only grow, so an equal vote loses the tie.
    let mut floor = 0u32;
    for (idx, &v) in votes.iter().enumerate() {
        if v <= floor {
            continue;
        }
        heap.push((Reverse(v), idx));
        if heap.len() > take {
            heap.pop();
        }
        if heap.len() == take {
            floor = heap.peek().map_or(0, |(Reverse(w), _)| *w);
        }
    }
    let mut ranked = heap.into_vec();
    ranked.sort_unstable();
    ranked
        .into_iter()
        .map(|(Reverse(v), idx)| (v, idx))
        .collect()
}

/// The symmetries `h` (indices) with `h(points) = points + c` for a lattice
/// translation `c`, the identity included; `inside` says whether a point is
/// in the set. Tried point by point, so a symmetry that fails usually fails
/// at once.
fn stabilizer(problem: &Problem, points: &[Point], inside: &dyn Fn(Point) -> bool) -> Vec<usize> {
    let (lo, hi) = bounds(points);
    let (dim, m) = (problem.geo.dim, problem.geo.modulus);
    problem
        .geo
        .syms
        .iter()
        .enumerate()
        .filter(|(_, h)| {
            if points.is_empty() {
                return true;
            }
            // The moved box's low corner must be the box's low corner + c.
            let mut mlo = [i32::MAX; 3];
            for corner in 0..8u32 {
                let c = Point::from([
                    if corner & 1 == 0 { lo[0] } else { hi[0] },
                    if corner & 2 == 0 { lo[1] } else { hi[1] },
                    if corner & 4 == 0 { lo[2] } else { hi[2] },
                ]);
                let q = h.apply(c);
                for d in 0..3 {
                    mlo[d] = mlo[d].min(q[d]);
                }
            }
            let c = Point::from(mlo) - lo;
            let lattice = (0..3).all(|d| {
                if d < dim {
                    c[d].rem_euclid(m) == 0
                } else {
                    c[d] == 0
                }
            });
            lattice && points.iter().all(|&p| inside(h.apply(p) - c))
        })
        .map(|(i, _)| i)
        .collect()
}

/// The first symmetry of each class `{h ∘ s ∘ r : h in left, r in right}`,
/// in index order.
fn representatives(syms: &[Symmetry], left: &[usize], right: &[usize]) -> Vec<usize> {
    let mut covered = vec![false; syms.len()];
    let mut reps = Vec::new();
    for s in 0..syms.len() {
        if covered[s] {
            continue;
        }
        reps.push(s);
        for &h in left {
            for &r in right {
                let g = syms[h].compose(&syms[s]).compose(&syms[r]);
                if let Some(i) = syms.iter().position(|x| *x == g) {
                    covered[i] = true;
                }
            }
        }
    }
    reps
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
