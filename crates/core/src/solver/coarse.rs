//! Coarse to fine: a large figure is solved at half resolution first, and
//! the coarse dissection is lifted back (every fine cell takes the piece of
//! the coarse cell that holds it) and refined at full resolution, where
//! copy-paste and label switching repair the boundaries.
//!
//! The search itself costs about the same per level at any resolution in
//! explorations and iterations; only the cells per iteration grow. Solving
//! the coarse figures (recursively coarser still) and refining once at each
//! resolution makes the whole cost a geometric series in the cell count:
//! linear for a fixed piece count.
//!
//! The coarse figures must have equal areas: each takes the same number of
//! coarse cells, the fullest blocks first (ties: nearest the figure's
//! centre, then cell order), under the block grid phase that leaves the
//! fewest partly filled blocks.

use std::collections::HashMap;
use std::sync::atomic::AtomicBool;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::figure::Figure;
use crate::lattice::Cell;
use crate::solver::candidate::{Candidate, Problem, Score};
use crate::solver::flood_fill::{flood_fill, Fallback};
use crate::solver::levels::lambda;
use crate::solver::piece::UNSET;
use crate::solver::refine::refine_with_patience;
use crate::solver::{Found, Options};

/// Every coarse cell is a `FACTOR`-block (per coordinate) of fine cells.
pub(crate) const FACTOR: i32 = 2;

/// Figures with fewer cells are solved directly.
pub(crate) const MIN_CELLS: usize = 300;

/// Lifted candidates refined per coarse dissection before giving up.
pub(crate) const TRIES: usize = 4;

/// Figures at half resolution, and where every fine cell went.
#[derive(Clone, Debug)]
pub(crate) struct Coarse {
    /// The coarse figures (equal areas).
    pub(crate) figures: Vec<Figure>,
    /// `of[f][c]`: the index, in `figures[f].cells()`, of the coarse cell
    /// holding fine cell `c` of figure `f`, or `None` when that coarse cell
    /// was left out.
    of: Vec<Vec<Option<u32>>>,
}

/// The figures at `1 / factor` resolution, or `None` when the lattice has no
/// coarsening or a coarse figure would be too small to be worth solving.
pub(crate) fn downsample(figures: &[Figure], factor: i32) -> Option<Coarse> {
    let kind = figures.first()?.lattice();
    let lattice = kind.lattice();
    let phases = lattice.coarse_phases(factor);
    if phases == 0 {
        return None;
    }
    let per_block = (factor as usize).pow(lattice.dim() as u32);
    let area = figures[0].len().div_ceil(per_block);
    if area < 2 {
        return None;
    }
    let mut coarse = Vec::with_capacity(figures.len());
    let mut of = Vec::with_capacity(figures.len());
    for figure in figures {
        // The phase with the fewest partly filled blocks (the first on ties).
        let mut best: Option<(usize, usize, HashMap<Cell, usize>)> = None;
        for phase in 0..phases {
            let mut fill: HashMap<Cell, usize> = HashMap::new();
            for &c in figure.cells() {
                *fill
                    .entry(lattice.coarse_cell(c, factor, phase)?)
                    .or_default() += 1;
            }
            let partial = fill.values().filter(|&&n| n < per_block).count();
            if best.as_ref().is_none_or(|(p, _, _)| partial < *p) {
                best = Some((partial, phase, fill));
            }
            if partial == 0 {
                break;
            }
        }
        let (_, phase, fill) = best?;
        let mut blocks: Vec<(Cell, usize)> = fill.into_iter().collect();
        if blocks.len() < area {
            return None;
        }
        let centre = centre(blocks.iter().map(|(b, _)| *b));
        let dist = |b: &Cell| -> i64 {
            (0..3)
                .map(|d| {
                    let x = b[d] as i64 * blocks_len_scale() - centre[d];
                    x * x
                })
                .sum()
        };
        blocks.sort_by(|a, b| {
            b.1.cmp(&a.1)
                .then(dist(&a.0).cmp(&dist(&b.0)))
                .then(a.0.cmp(&b.0))
        });
        blocks.truncate(area);
        let fig = Figure::new(kind, blocks.iter().map(|(b, _)| *b)).ok()?;
        let index: HashMap<Cell, u32> = fig
            .cells()
            .iter()
            .enumerate()
            .map(|(i, c)| (*c, i as u32))
            .collect();
        of.push(
            figure
                .cells()
                .iter()
                .map(|&c| {
                    let b = lattice.coarse_cell(c, factor, phase)?;
                    index.get(&b).copied()
                })
                .collect(),
        );
        coarse.push(fig);
    }
    Some(Coarse {
        figures: coarse,
        of,
    })
}

/// Coordinates are compared to the centre in units of `1 / SCALE`.
fn blocks_len_scale() -> i64 {
    1024
}

/// The mean of some cells' coordinates, times [`blocks_len_scale`].
fn centre(cells: impl Iterator<Item = Cell>) -> [i64; 3] {
    let mut sum = [0i64; 3];
    let mut n = 0i64;
    for c in cells {
        for d in 0..3 {
            sum[d] += c[d] as i64;
        }
        n += 1;
    }
    let n = n.max(1);
    sum.map(|s| s * blocks_len_scale() / n)
}

impl Coarse {
    /// The fine candidate of a coarse dissection: every fine cell takes the
    /// piece of its coarse cell; cells whose coarse cell was left out are
    /// filled from their labelled neighbours.
    pub(crate) fn lift<R: rand::Rng>(
        &self,
        problem: &Problem,
        found: &Found,
        rng: &mut R,
    ) -> Candidate {
        let k = found.piece_count();
        let labels = self
            .figures
            .iter()
            .zip(&found.pieces)
            .zip(&self.of)
            .zip(&problem.shapes)
            .map(|(((fig, pieces), of), shape)| {
                let mut coarse = vec![UNSET; fig.len()];
                for (i, cells) in pieces.iter().enumerate() {
                    for c in cells {
                        if let Ok(j) = fig.cells().binary_search(c) {
                            coarse[j] = i as u16;
                        }
                    }
                }
                let mut fine: Vec<u16> = of
                    .iter()
                    .map(|j| j.map_or(UNSET, |j| coarse[j as usize]))
                    .collect();
                flood_fill(shape, &mut fine, Fallback::Random(k.max(1)), rng);
                fine
            })
            .collect();
        Candidate { labels, k }
    }
}

/// A dissection of `problem` (the shapes of `figures`) lifted from one of
/// the figures at half resolution, which `solve_coarse` finds (typically
/// the solver itself, so the figures are halved again while they are
/// large). Up to [`TRIES`] lifts are refined with seeds from `seed`; the
/// first valid one is returned, else the best, else `None` when the figures
/// are too small to coarsen or the coarse search found nothing.
pub(crate) fn from_coarse(
    figures: &[Figure],
    problem: &Problem,
    options: &Options,
    seed: u64,
    stop: &AtomicBool,
    solve_coarse: impl FnOnce(&[Figure]) -> Option<Found>,
) -> Option<(Candidate, Score)> {
    if figures.first()?.len() < MIN_CELLS {
        return None;
    }
    let coarse = downsample(figures, FACTOR)?;
    let found = solve_coarse(&coarse.figures)?;
    let level = found.piece_count().saturating_sub(1).max(1);
    let mut best: Option<(Candidate, Score)> = None;
    for t in 0..TRIES {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ (0xC0A5_5E00 + t as u64));
        let mut cand = coarse.lift(problem, &found, &mut rng);
        refine_with_patience(
            problem,
            &mut cand,
            options.iterations,
            options.patience,
            &mut rng,
            stop,
        );
        let score = cand.evaluate(problem, lambda(options, level), options.split_penalty);
        let valid = score.valid;
        if best.as_ref().is_none_or(|(_, b)| score.value < b.value) {
            best = Some((cand, score));
        }
        if valid || stop.load(std::sync::atomic::Ordering::Relaxed) {
            break;
        }
    }
    best
}
