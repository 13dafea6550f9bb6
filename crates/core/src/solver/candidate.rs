//! Candidates (one labelling of every figure) and their objective.

use crate::figure::Figure;
use crate::lattice::Cell;
use crate::solver::distance::{Geometry, Side};
use crate::solver::matching::{match_pieces, PairMatching};
use crate::solver::piece::Pieces;
use crate::solver::shape::{LabelGrid, Layout, Shape};

/// The figures of one solve, in solver form.
///
/// # Validity
/// `moved[f]` is `shapes[f].moved(&geo.syms, &layout)`; built only by
/// [`Problem::new`].
#[derive(Clone, Debug)]
pub(crate) struct Problem {
    pub(crate) shapes: Vec<Shape>,
    pub(crate) geo: Geometry,
    layout: Layout,
    moved: Vec<Vec<i64>>,
}

impl Problem {
    /// The problem of these shapes under this geometry.
    pub(crate) fn new(shapes: Vec<Shape>, geo: Geometry) -> Problem {
        let spread = geo.syms.iter().map(|g| g.spread()).max().unwrap_or(1);
        let layout = Layout::new(&shapes, geo.dim, geo.modulus, spread);
        let moved = shapes.iter().map(|s| s.moved(&geo.syms, &layout)).collect();
        Problem {
            shapes,
            geo,
            layout,
            moved,
        }
    }

    /// One side of a distance computation: figure `f` with these pieces.
    fn side<'a>(&'a self, f: usize, pieces: &'a Pieces, grid: &'a [u16]) -> Side<'a> {
        Side {
            pieces,
            moved: &self.moved[f],
            grid,
            origin: self.layout.origin(f),
            layout: &self.layout,
        }
    }

    /// Labels of figure `f` by address.
    fn label_grid(&self, f: usize, labels: &[u16]) -> LabelGrid<'_> {
        self.layout.label_grid(f, labels)
    }
}

/// One labelling of every figure with piece ids `0..k`.
///
/// # Validity
/// `labels[f].len() == shapes[f].len()` and every label is `< k`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Candidate {
    pub(crate) labels: Vec<Vec<u16>>,
    pub(crate) k: usize,
}

/// The objective of a candidate and what it is made of.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Score {
    /// `E = E_M + λ·ΣEα + penalty·split`.
    pub(crate) value: f64,
    /// `E_M`: total matching cost against figure 0.
    pub(crate) mismatch: u64,
    /// Number of (figure, piece) pairs that are not connected.
    pub(crate) split: u32,
    /// `E_M = 0` and every piece connected.
    pub(crate) valid: bool,
    /// Variance of the non-empty piece areas.
    pub(crate) variance: f64,
}

/// The pieces of every figure, with labels aligned to a pivot figure.
pub(crate) struct Aligned {
    pub(crate) pieces: Vec<Pieces>,
    /// `matchings[f]` (`None` for the pivot itself): its `transforms[a]` and
    /// `dists[a]` carry the pivot's piece `a` onto figure `f`'s piece now
    /// labelled `a`; its `partner` keeps the labels `f` had before alignment.
    pub(crate) matchings: Vec<Option<PairMatching>>,
}

impl Candidate {
    /// The cells of each label of each figure (`[f][label]`), `figures` being
    /// the figures the shapes were made from. Labels that no figure uses
    /// (a piece that vanished) are dropped.
    pub(crate) fn cells_by_label(&self, figures: &[Figure]) -> Vec<Vec<Vec<Cell>>> {
        let mut pieces: Vec<Vec<Vec<Cell>>> = figures
            .iter()
            .zip(&self.labels)
            .map(|(fig, labels)| {
                let mut p = vec![Vec::new(); self.k];
                for (c, &l) in fig.cells().iter().zip(labels) {
                    p[l as usize].push(*c);
                }
                p
            })
            .collect();
        for i in (0..self.k).rev() {
            if pieces.iter().all(|p| p[i].is_empty()) {
                for p in &mut pieces {
                    p.remove(i);
                }
            }
        }
        pieces
    }

    /// The pieces of figure `f`.
    pub(crate) fn pieces(&self, problem: &Problem, f: usize) -> Pieces {
        Pieces::of(&problem.shapes[f], &self.labels[f], self.k)
    }

    /// Computes the matching from `pivot` to every other figure and relabels
    /// the other figures so that matched pieces carry the pivot's labels.
    pub(crate) fn align(&mut self, problem: &Problem, pivot: usize) -> Aligned {
        let pp = self.pieces(problem, pivot);
        let mut pieces = Vec::with_capacity(problem.shapes.len());
        let mut matchings = Vec::with_capacity(problem.shapes.len());
        for f in 0..problem.shapes.len() {
            if f == pivot {
                pieces.push(pp.clone());
                matchings.push(None);
                continue;
            }
            let pf = self.pieces(problem, f);
            let grid_f = problem.label_grid(f, &self.labels[f]);
            let m = match_pieces(
                &problem.geo,
                problem.side(pivot, &pp, &[]),
                problem.side(f, &pf, &grid_f),
            );
            let mut relabel = vec![0u16; self.k];
            for (a, &b) in m.partner.iter().enumerate() {
                relabel[b] = a as u16;
            }
            for l in self.labels[f].iter_mut() {
                *l = relabel[*l as usize];
            }
            pieces.push(pf.permuted(&m.partner));
            matchings.push(Some(m));
        }
        Aligned { pieces, matchings }
    }

    /// Aligns every figure to figure 0 and scores the candidate.
    pub(crate) fn evaluate(&mut self, problem: &Problem, lambda: f64, split_penalty: f64) -> Score {
        let aligned = self.align(problem, 0);
        let mismatch: u64 = aligned.matchings.iter().flatten().map(|m| m.cost).sum();
        let mut area = 0.0;
        let mut split = 0u32;
        for (f, pieces) in aligned.pieces.iter().enumerate() {
            let shape = &problem.shapes[f];
            let mean = shape.len() as f64 / self.k as f64;
            let mut scratch = vec![false; shape.len()];
            for i in 0..self.k {
                let s = pieces.size(i) as f64;
                area += area_penalty(s, mean);
                if s > 0.0 && pieces.components(shape, i, &mut scratch) > 1 {
                    split += 1;
                }
            }
        }
        let sizes: Vec<f64> = (0..self.k)
            .map(|i| aligned.pieces[0].size(i) as f64)
            .filter(|s| *s > 0.0)
            .collect();
        let mean = sizes.iter().sum::<f64>() / sizes.len().max(1) as f64;
        let variance =
            sizes.iter().map(|s| (s - mean) * (s - mean)).sum::<f64>() / sizes.len().max(1) as f64;
        Score {
            value: mismatch as f64 + lambda * area + split_penalty * split as f64,
            mismatch,
            split,
            valid: mismatch == 0 && split == 0,
            variance,
        }
    }
}

/// The paper's area term `α` for a piece of area `s` when the mean is `mean`.
pub(crate) fn area_penalty(s: f64, mean: f64) -> f64 {
    if s > 2.0 * mean {
        s / mean - 1.0
    } else if s < mean / 2.0 {
        mean / s.max(0.5) - 1.0
    } else {
        0.0
    }
}
