//! A dissection that passed the independent verifier.

use std::sync::atomic::AtomicBool;
use std::time::Duration;

use dissect_core::verify::verify;
use dissect_core::Dissection;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_puzzle::assemblies::{AssemblyError, Count};

use crate::limits::TimeLimit;

/// A dissection checked by [`dissect_core::verify`] against its figures.
///
/// # Validity
/// Built only by [`Verified::new`], which runs the verifier: every piece is
/// connected and congruent in every figure and the pieces tile each figure.
#[derive(Clone, Debug, PartialEq)]
pub struct Verified {
    dissection: Dissection,
}

impl Verified {
    /// Verifies `pieces[f][i]` (cells of piece `i` in figure `f`) against
    /// `figures`; the error is the verifier's first complaint.
    pub fn new(
        lattice: LatticeKind,
        mirror: bool,
        names: Vec<String>,
        figures: &[Figure],
        pieces: Vec<Vec<Vec<Cell>>>,
    ) -> Result<Verified, String> {
        let dissection =
            Dissection::new(lattice, mirror, names, pieces).map_err(|e| e.to_string())?;
        match verify(&dissection, figures) {
            Ok(_) => Ok(Verified { dissection }),
            Err(v) => Err(v
                .first()
                .map_or_else(|| "rejected".to_string(), |v| v.to_string())),
        }
    }

    /// The same dissection with its figures in another order: figure `f`
    /// of the result is figure `from[f]` of this one (a permutation). The
    /// pieces are the same in every figure, so it stays verified.
    pub(crate) fn reordered(&self, from: &[usize]) -> Verified {
        let (lattice, mirror, names, pieces) = self.dissection.clone().into_parts();
        let dissection = Dissection::new(
            lattice,
            mirror,
            from.iter().map(|&f| names[f].clone()).collect(),
            from.iter().map(|&f| pieces[f].clone()).collect(),
        )
        .expect("a permutation of a valid dissection's figures is valid");
        Verified { dissection }
    }

    /// The dissection.
    pub fn dissection(&self) -> &Dissection {
        &self.dissection
    }

    /// `pieces[f][i]`: the cells of piece `i` in figure `f`.
    pub fn pieces(&self) -> &[Vec<Vec<Cell>>] {
        self.dissection.pieces()
    }

    /// The number of pieces.
    pub fn piece_count(&self) -> usize {
        self.dissection.piece_count()
    }

    /// Each piece's area.
    pub fn areas(&self) -> Vec<usize> {
        self.dissection
            .pieces()
            .first()
            .map_or(Vec::new(), |p| p.iter().map(Vec::len).collect())
    }

    /// The variance of the piece areas.
    pub fn variance(&self) -> f64 {
        let a = self.areas();
        if a.is_empty() {
            return 0.0;
        }
        let mean = a.iter().sum::<usize>() as f64 / a.len() as f64;
        a.iter().map(|&x| (x as f64 - mean).powi(2)).sum::<f64>() / a.len() as f64
    }

    /// In how many ways the pieces tile each of `figures` (the count of
    /// `dissect assemblies`: [`dissect_puzzle::assemblies::count`], every
    /// placement the lattice allows, mirror images as the dissection
    /// allows them, identical pieces interchangeable), one [`Count`] per
    /// figure ([`crate::assemblies()`]). The counts stop after `time` in all
    /// or when `stop` is raised; a count cut short says so ([`Count::complete`]) and its numbers are
    /// lower bounds.
    pub fn assemblies(
        &self,
        figures: &[Figure],
        time: Duration,
        stop: Option<&AtomicBool>,
    ) -> Result<Vec<Count>, AssemblyError> {
        let never = AtomicBool::new(false);
        crate::assemblies::assemblies(
            &self.dissection,
            figures,
            TimeLimit::from_duration(time),
            stop.unwrap_or(&never),
            &mut |_| {},
        )
        .map_err(|e| e.error)
    }
}
