//! Scores for ranking dissections with the same number of pieces, and the
//! canonical form that says when two dissections are the same puzzle.
//!
//! All scores are pure functions of one dissection's pieces (as cut from
//! any one figure: the pieces are the same in every figure).

use std::cmp::Ordering;
use std::fmt;
use std::str::FromStr;

use dissect_core::lattice::Point;
use dissect_core::Cell;
use serde::Serialize;

use crate::geometry::Motions;

/// The paper's area variance: the population variance of the piece areas
/// (0 when every piece has the same number of cells).
pub fn variance(pieces: &[Vec<Cell>]) -> f64 {
    if pieces.is_empty() {
        return 0.0;
    }
    let n = pieces.len() as f64;
    let mean = pieces.iter().map(|p| p.len() as f64).sum::<f64>() / n;
    pieces
        .iter()
        .map(|p| (p.len() as f64 - mean).powi(2))
        .sum::<f64>()
        / n
}

/// The number of cells of the smallest piece.
pub fn smallest(pieces: &[Vec<Cell>]) -> usize {
    pieces.iter().map(Vec::len).min().unwrap_or(0)
}

/// The number of distinct piece shapes up to the allowed motions.
pub fn shapes(motions: &Motions, pieces: &[Vec<Cell>]) -> usize {
    let mut forms: Vec<Vec<Point>> = pieces.iter().map(|p| motions.canonical(p)).collect();
    forms.sort();
    forms.dedup();
    forms.len()
}

/// The pieces' self-symmetries: for every piece, the number of allowed
/// point symmetries other than the identity that map it onto itself (after
/// a translation), summed over the pieces. 0 when no piece is symmetric.
pub fn symmetry(motions: &Motions, pieces: &[Vec<Cell>]) -> usize {
    pieces
        .iter()
        .map(|p| motions.self_symmetries(p).saturating_sub(1))
        .sum()
}

/// The canonical form of a dissection: its pieces' canonical forms, sorted.
/// Two dissections are the same puzzle (the same pieces up to relabelling
/// and the lattice's motions) exactly when their canonical forms are equal.
pub fn canonical(motions: &Motions, pieces: &[Vec<Cell>]) -> Vec<Vec<Point>> {
    let mut forms: Vec<Vec<Point>> = pieces.iter().map(|p| motions.canonical(p)).collect();
    forms.sort();
    forms
}

/// A dissection's scores.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Scores {
    /// The number of pieces.
    pub pieces: usize,
    /// [`variance`].
    pub variance: f64,
    /// [`smallest`].
    pub smallest: usize,
    /// [`shapes`].
    pub shapes: usize,
    /// [`symmetry`].
    pub symmetry: usize,
    /// What `--rank variance` orders by: the variance less the symmetry
    /// weight times [`symmetry`] (`--symmetry-weight`, the paper's proposed
    /// symmetry term; the variance itself when the weight is 0).
    pub objective: f64,
    /// Tilings up to each figure's symmetries, summed over the figures, when
    /// counted (see [`crate::assemblies`]); `None` when not counted or cut
    /// short.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub assemblies: Option<u64>,
    /// Each figure's disassembly level (`None` for a figure that does not
    /// come apart), when computed (see [`crate::disassembly`]); written as
    /// the solution file's own `levels` key, not among the scores.
    #[serde(skip)]
    pub levels: Option<Vec<Option<usize>>>,
}

impl Scores {
    /// Every score but `assemblies` (which needs the figures and a search).
    pub fn of(motions: &Motions, pieces: &[Vec<Cell>]) -> Scores {
        Scores::weighted(motions, pieces, 0.0)
    }

    /// Every score but `assemblies`, with `objective` = variance −
    /// `symmetry_weight` · symmetry.
    pub fn weighted(motions: &Motions, pieces: &[Vec<Cell>], symmetry_weight: f64) -> Scores {
        let variance = variance(pieces);
        let symmetry = symmetry(motions, pieces);
        Scores {
            pieces: pieces.len(),
            variance,
            smallest: smallest(pieces),
            shapes: shapes(motions, pieces),
            symmetry,
            objective: variance - symmetry_weight * symmetry as f64,
            assemblies: None,
            levels: None,
        }
    }

    /// The smallest level over the figures; `None` when the levels were not
    /// computed or a figure does not come apart.
    pub fn least_level(&self) -> Option<usize> {
        self.levels
            .as_ref()
            .and_then(|l| l.iter().copied().collect::<Option<Vec<usize>>>())
            .and_then(|l| l.into_iter().min())
    }
}

impl fmt::Display for Scores {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} pieces, variance {:.3}, smallest {}, shapes {}, symmetry {}",
            self.pieces, self.variance, self.smallest, self.shapes, self.symmetry
        )?;
        if let Some(a) = self.assemblies {
            write!(f, ", assemblies {a}")?;
        }
        Ok(())
    }
}

/// How dissections with the same number of pieces are ranked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Rank {
    /// Least area variance (the paper's choice; less the symmetry term
    /// under `--symmetry-weight`).
    #[default]
    Variance,
    /// Largest smallest piece.
    Smallest,
    /// Fewest distinct piece shapes.
    Shapes,
    /// Most piece self-symmetries.
    Symmetry,
    /// Fewest assemblies (tilings up to symmetry, summed over the figures).
    Unique,
    /// The highest smallest disassembly level over the figures first (the
    /// most interlocking puzzle); one that does not come apart ranks last.
    Level,
}

impl Rank {
    /// Every criterion.
    pub const ALL: [Rank; 6] = [
        Rank::Variance,
        Rank::Smallest,
        Rank::Shapes,
        Rank::Symmetry,
        Rank::Unique,
        Rank::Level,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Rank::Variance => "variance",
            Rank::Smallest => "smallest",
            Rank::Shapes => "shapes",
            Rank::Symmetry => "symmetry",
            Rank::Unique => "unique",
            Rank::Level => "level",
        }
    }

    /// Whether ranking needs the assembly counts.
    pub fn needs_assemblies(self) -> bool {
        self == Rank::Unique
    }

    /// Whether ranking needs the disassembly levels.
    pub fn needs_levels(self) -> bool {
        self == Rank::Level
    }

    /// `Less` when `a` is better than `b`: fewer pieces first, then this
    /// criterion, then the others in the order variance, smallest, shapes,
    /// symmetry as tie-breaks.
    pub fn compare(self, a: &Scores, b: &Scores) -> Ordering {
        let by_variance = |a: &Scores, b: &Scores| a.objective.total_cmp(&b.objective);
        let by_smallest = |a: &Scores, b: &Scores| b.smallest.cmp(&a.smallest);
        let by_shapes = |a: &Scores, b: &Scores| a.shapes.cmp(&b.shapes);
        let by_symmetry = |a: &Scores, b: &Scores| b.symmetry.cmp(&a.symmetry);
        // Uncounted assemblies rank after every counted one.
        let by_unique = |a: &Scores, b: &Scores| {
            a.assemblies
                .unwrap_or(u64::MAX)
                .cmp(&b.assemblies.unwrap_or(u64::MAX))
        };
        let first = match self {
            Rank::Variance => by_variance(a, b),
            Rank::Smallest => by_smallest(a, b),
            Rank::Shapes => by_shapes(a, b),
            Rank::Symmetry => by_symmetry(a, b),
            Rank::Unique => by_unique(a, b),
            Rank::Level => {
                let least = |s: &Scores| s.least_level().map_or(-1, |l| l as i64);
                least(b).cmp(&least(a))
            }
        };
        a.pieces
            .cmp(&b.pieces)
            .then(first)
            .then_with(|| by_variance(a, b))
            .then_with(|| by_smallest(a, b))
            .then_with(|| by_shapes(a, b))
            .then_with(|| by_symmetry(a, b))
    }

    /// Sorts items best first by their scores (stable: equal scores keep
    /// their order).
    pub fn sort<T>(self, items: &mut [(Scores, T)]) {
        items.sort_by(|a, b| self.compare(&a.0, &b.0));
    }
}

impl fmt::Display for Rank {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Occurs when a ranking name is unknown.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown ranking {0:?} (expected variance, smallest, shapes, symmetry, unique or level)")]
pub struct UnknownRank(pub String);

impl FromStr for Rank {
    type Err = UnknownRank;
    fn from_str(s: &str) -> Result<Rank, UnknownRank> {
        Rank::ALL
            .into_iter()
            .find(|r| r.name() == s)
            .ok_or_else(|| UnknownRank(s.to_string()))
    }
}

/// Keeps the first of every group of dissections with the same canonical
/// form; returns the indices kept, in order.
pub fn distinct(motions: &Motions, dissections: &[&[Vec<Cell>]]) -> Vec<usize> {
    let mut seen = std::collections::HashSet::new();
    (0..dissections.len())
        .filter(|&i| seen.insert(canonical(motions, dissections[i])))
        .collect()
}
