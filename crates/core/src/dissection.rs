//! [`Dissection`]: the result of a search, in typed form. The solution
//! JSON format (`io::solution_json`) only reads and writes it, and the
//! verifier checks it, so neither depends on the other.

use crate::lattice::{Cell, LatticeKind};

/// Every figure cut into pieces: `pieces()[f][i]` are the cells of piece
/// `i` in figure `f`. Whether it is a *valid* dissection of given figures is
/// the verifier's question ([`crate::verify::verify`]).
///
/// # Validity
/// Every cell is a cell of `lattice`; there is one name per figure (empty
/// when unknown); `mirror` is false on lattices without flips (`cubic`).
/// The constructor enforces this.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dissection {
    lattice: LatticeKind,
    mirror: bool,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Cell>>>,
}

/// Occurs when parts do not make a [`Dissection`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum DissectionError {
    /// Occurs when a cell is not of the lattice's form.
    #[error("figure {figure} piece {piece}: {cell:?} is not a cell of the {lattice} lattice")]
    BadCell {
        /// Figure index.
        figure: usize,
        /// Piece index.
        piece: usize,
        /// The cell.
        cell: Cell,
        /// The lattice.
        lattice: LatticeKind,
    },
    /// Occurs when the names are not one per figure.
    #[error("{names} names for {figures} figures")]
    NameCount {
        /// Names given.
        names: usize,
        /// Figures given.
        figures: usize,
    },
}

impl Dissection {
    /// A dissection from its parts; `mirror` is ignored where the lattice
    /// has no flips.
    pub fn new(
        lattice: LatticeKind,
        mirror: bool,
        names: Vec<String>,
        pieces: Vec<Vec<Vec<Cell>>>,
    ) -> Result<Dissection, DissectionError> {
        let l = lattice.lattice();
        if names.len() != pieces.len() {
            return Err(DissectionError::NameCount {
                names: names.len(),
                figures: pieces.len(),
            });
        }
        for (figure, fp) in pieces.iter().enumerate() {
            for (piece, cells) in fp.iter().enumerate() {
                if let Some(&cell) = cells.iter().find(|c| !l.is_cell(**c)) {
                    return Err(DissectionError::BadCell {
                        figure,
                        piece,
                        cell,
                        lattice,
                    });
                }
            }
        }
        Ok(Dissection {
            lattice,
            mirror: mirror && l.supports_mirror(),
            names,
            pieces,
        })
    }

    /// [`Dissection::new`] with empty names.
    pub fn unnamed(
        lattice: LatticeKind,
        mirror: bool,
        pieces: Vec<Vec<Vec<Cell>>>,
    ) -> Result<Dissection, DissectionError> {
        let names = vec![String::new(); pieces.len()];
        Dissection::new(lattice, mirror, names, pieces)
    }

    /// The lattice.
    pub fn lattice(&self) -> LatticeKind {
        self.lattice
    }

    /// Whether pieces may be turned over.
    pub fn mirror(&self) -> bool {
        self.mirror
    }

    /// The figures' names (empty when unknown), one per figure.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// `pieces()[f][i]`: the cells of piece `i` in figure `f`.
    pub fn pieces(&self) -> &[Vec<Vec<Cell>>] {
        &self.pieces
    }

    /// The number of figures.
    pub fn figure_count(&self) -> usize {
        self.pieces.len()
    }

    /// The number of pieces (of the first figure).
    pub fn piece_count(&self) -> usize {
        self.pieces.first().map_or(0, |p| p.len())
    }

    /// The parts: lattice, mirror, names and pieces.
    pub fn into_parts(self) -> (LatticeKind, bool, Vec<String>, Vec<Vec<Vec<Cell>>>) {
        (self.lattice, self.mirror, self.names, self.pieces)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parts_are_checked() {
        let sq = LatticeKind::Square;
        let d = Dissection::new(sq, true, vec!["a".into()], vec![vec![vec![[0, 0, 0]]]]).unwrap();
        assert_eq!((d.figure_count(), d.piece_count()), (1, 1));
        assert!(d.mirror());
        assert_eq!(
            Dissection::new(sq, true, vec![], vec![vec![vec![[0, 0, 0]]]]),
            Err(DissectionError::NameCount {
                names: 0,
                figures: 1
            })
        );
        assert_eq!(
            Dissection::unnamed(sq, true, vec![vec![vec![[0, 0, 0]], vec![[0, 0, 1]]]]),
            Err(DissectionError::BadCell {
                figure: 0,
                piece: 1,
                cell: [0, 0, 1],
                lattice: sq
            })
        );
        let cubic = Dissection::unnamed(LatticeKind::Cubic, true, vec![]).unwrap();
        assert!(!cubic.mirror(), "no flips in 3D");
        assert_eq!(cubic.piece_count(), 0);
    }
}
