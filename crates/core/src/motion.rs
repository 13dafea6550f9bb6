//! How the pieces move: the rigid motion that carries each piece from its
//! place in one figure to its place in another, and an order in which a
//! person could lay the pieces of a figure down.
//!
//! Both are computed from the cells of a dissection and the lattice's
//! points, symmetries and blocks only, so they hold for every lattice.

use std::collections::HashSet;

use crate::lattice::{Cell, Lattice, Point};
use crate::transform::Transform;

/// Occurs when a piece of one figure is not congruent to the piece with the
/// same number in another figure.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum MotionError {
    /// No point symmetry and translation maps the piece onto its partner.
    #[error("piece {piece} of figure {from} is not congruent to piece {piece} of figure {to}")]
    NotCongruent {
        /// The piece (0-based).
        piece: usize,
        /// The figure it moves from (0-based).
        from: usize,
        /// The figure it moves to (0-based).
        to: usize,
    },
    /// The figures do not have the same number of pieces.
    #[error("figure {figure} has {found} pieces, figure 0 has {expected}")]
    PieceCount {
        /// The figure (0-based).
        figure: usize,
        /// Its number of pieces.
        found: usize,
        /// The number of pieces of figure 0.
        expected: usize,
    },
}

/// The motion (a point symmetry, then a lattice translation: multiples of
/// [`Lattice::modulus`] in the moved coordinates) that maps the cells `from` exactly onto the cells `to`, or `None`
/// when there is none. Proper rotations are preferred over flips (the
/// lattice lists them first), so a piece is only turned over when it must be.
pub fn piece_motion(lattice: &dyn Lattice, from: &[Cell], to: &[Cell]) -> Option<Transform> {
    if from.len() != to.len() || from.is_empty() {
        return None;
    }
    let mut target: Vec<Point> = to.iter().map(|c| lattice.to_point(*c)).collect();
    target.sort_unstable();
    let source: Vec<Point> = from.iter().map(|c| lattice.to_point(*c)).collect();
    let mut moved: Vec<Point> = Vec::with_capacity(source.len());
    for sym in lattice.symmetries(lattice.supports_mirror()) {
        moved.clear();
        moved.extend(source.iter().map(|p| sym.apply(*p)));
        moved.sort_unstable();
        let shift = target[0] - moved[0];
        let m = lattice.modulus();
        let translation = (0..lattice.dim()).all(|d| shift[d] % m == 0);
        let fits = translation && moved.iter().zip(&target).all(|(m, t)| *m + shift == *t);
        if fits {
            return Some(Transform::new(sym, shift));
        }
    }
    None
}

/// `motions[f][i]`: the motion carrying piece `i` of figure 0 onto piece `i`
/// of figure `f` (`pieces[f][i]` are the cells of piece `i` in figure `f`).
/// The motion from figure `a` to figure `b` is `motions[b][i] ∘
/// motions[a][i]⁻¹`.
pub fn motions(
    lattice: &dyn Lattice,
    pieces: &[Vec<Vec<Cell>>],
) -> Result<Vec<Vec<Transform>>, MotionError> {
    let Some(first) = pieces.first() else {
        return Ok(Vec::new());
    };
    pieces
        .iter()
        .enumerate()
        .map(|(f, fp)| {
            if fp.len() != first.len() {
                return Err(MotionError::PieceCount {
                    figure: f,
                    found: fp.len(),
                    expected: first.len(),
                });
            }
            first
                .iter()
                .zip(fp)
                .enumerate()
                .map(|(i, (a, b))| {
                    piece_motion(lattice, a, b).ok_or(MotionError::NotCongruent {
                        piece: i,
                        from: 0,
                        to: f,
                    })
                })
                .collect()
        })
        .collect()
}

/// An order in which a person could lay down the pieces of one figure
/// (`pieces[i]`: the cells of piece `i`), one at a time.
///
/// In 3D the third block coordinate is the height: a piece can be put down
/// when one of its blocks rests on the ground (the figure's lowest layer) or
/// on a piece already placed, and no placed block lies above any of its
/// blocks (it comes in from above); the lowest such piece goes first. In 2D
/// the pieces are laid on a table, starting from the bottom row (largest
/// `y`), each next piece touching the pieces already laid. Ties go to the
/// piece with the most contact with the placed ones, then to the larger
/// piece, then to the lower number, so the order is reproducible. When no
/// piece fits these rules (interlocking pieces) the lowest remaining piece
/// goes next.
pub fn assembly_order(lattice: &dyn Lattice, pieces: &[Vec<Cell>]) -> Vec<usize> {
    let three_d = lattice.dim() == 3;
    // "Height" of a block: z in 3D, -y in 2D (y grows downward).
    let height = |b: [i32; 3]| if three_d { b[2] } else { -b[1] };
    let blocks: Vec<Vec<[i32; 3]>> = pieces
        .iter()
        .map(|p| p.iter().map(|c| lattice.block(*c)).collect())
        .collect();
    let ground = blocks
        .iter()
        .flatten()
        .map(|b| height(*b))
        .min()
        .unwrap_or(0);
    let mut placed_cells: HashSet<Cell> = HashSet::new();
    let mut placed_blocks: HashSet<[i32; 3]> = HashSet::new();
    let mut left: Vec<usize> = (0..pieces.len()).collect();
    let mut order = Vec::with_capacity(pieces.len());
    while !left.is_empty() {
        let contact = |i: usize| -> usize {
            pieces[i]
                .iter()
                .filter(|c| {
                    lattice
                        .neighbors(**c)
                        .iter()
                        .any(|n| placed_cells.contains(n))
                })
                .count()
        };
        let lowest = |i: usize| blocks[i].iter().map(|b| height(*b)).min().unwrap_or(0);
        let can_place = |i: usize| -> bool {
            if three_d {
                let rests = blocks[i]
                    .iter()
                    .any(|b| b[2] == ground || placed_blocks.contains(&[b[0], b[1], b[2] - 1]));
                let covered = placed_blocks.iter().any(|p| {
                    blocks[i]
                        .iter()
                        .any(|b| p[0] == b[0] && p[1] == b[1] && p[2] > b[2])
                });
                rests && !covered
            } else {
                order.is_empty() && lowest(i) == ground || contact(i) > 0
            }
        };
        let candidates: Vec<usize> = left.iter().copied().filter(|&i| can_place(i)).collect();
        let pool = if candidates.is_empty() {
            &left
        } else {
            &candidates
        };
        // 3D and the first flat piece: the lowest first, then the most
        // contact; later flat pieces: the most contact first, then the lowest.
        let lowest_first = three_d || order.is_empty();
        let next = *pool
            .iter()
            .max_by_key(|&&i| {
                let (low, touch) = (-(lowest(i) as i64), contact(i) as i64);
                let (a, b) = if lowest_first {
                    (low, touch)
                } else {
                    (touch, low)
                };
                (a, b, pieces[i].len(), std::cmp::Reverse(i))
            })
            .expect("a piece is left");
        left.retain(|&i| i != next);
        placed_cells.extend(pieces[next].iter().copied());
        placed_blocks.extend(blocks[next].iter().copied());
        order.push(next);
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_figure;
    use crate::lattice::LatticeKind;

    fn cells(l: LatticeKind, text: &str) -> Vec<Cell> {
        parse_figure(text, l).unwrap().cells().to_vec()
    }

    #[test]
    fn an_l_piece_turned_a_quarter() {
        let l = LatticeKind::Square.lattice();
        let a = cells(LatticeKind::Square, "#.\n#.\n##\n");
        let b = cells(LatticeKind::Square, "###\n#..\n");
        let t = piece_motion(l, &a, &b).unwrap();
        assert_eq!(t.symmetry().determinant(), 1);
        let mut moved: Vec<Cell> = a
            .iter()
            .map(|c| l.from_point(t.apply(l.to_point(*c))).unwrap())
            .collect();
        moved.sort();
        let mut want = b.clone();
        want.sort();
        assert_eq!(moved, want);
    }

    #[test]
    fn a_chiral_piece_must_be_flipped() {
        let l = LatticeKind::Square.lattice();
        let a = cells(LatticeKind::Square, "##.\n.##\n");
        let b = cells(LatticeKind::Square, ".##\n##.\n");
        let t = piece_motion(l, &a, &b).unwrap();
        assert_eq!(t.symmetry().determinant(), -1);
        assert!(piece_motion(l, &a, &cells(LatticeKind::Square, "###\n")).is_none());
    }

    #[test]
    fn tri4_and_cubic_pieces_move_onto_their_partners() {
        let l = LatticeKind::Tri4.lattice();
        // One triangle, top to right: a quarter turn.
        let t = piece_motion(l, &[[0, 0, 0]], &[[3, 1, 1]]).unwrap();
        assert_eq!(
            l.from_point(t.apply(l.to_point([0, 0, 0]))),
            Some([3, 1, 1])
        );
        let c = LatticeKind::Cubic.lattice();
        let a = [[0, 0, 0], [1, 0, 0], [0, 0, 1]];
        let b = [[5, 5, 5], [5, 6, 5], [5, 5, 6]];
        let t = piece_motion(c, &a, &b).unwrap();
        assert_eq!(t.symmetry().determinant(), 1);
    }

    #[test]
    fn motions_of_every_figure_start_with_the_identity() {
        let l = LatticeKind::Square.lattice();
        let pieces = vec![
            vec![vec![[0, 0, 0], [1, 0, 0]], vec![[0, 1, 0], [1, 1, 0]]],
            vec![vec![[0, 0, 0], [0, 1, 0]], vec![[1, 0, 0], [1, 1, 0]]],
        ];
        let m = motions(l, &pieces).unwrap();
        assert!(m[0].iter().all(|t| *t == Transform::IDENTITY));
        let bad = vec![pieces[0].clone(), vec![vec![[0, 0, 0]], vec![[1, 0, 0]]]];
        assert!(matches!(
            motions(l, &bad),
            Err(MotionError::NotCongruent {
                piece: 0,
                from: 0,
                to: 1
            })
        ));
    }

    #[test]
    fn cubes_are_laid_bottom_up_and_never_under_a_placed_one() {
        let l = LatticeKind::Cubic.lattice();
        // Piece 0 sits on top of piece 1; piece 2 is a pillar beside them.
        let pieces = vec![vec![[0, 0, 1]], vec![[0, 0, 0]], vec![[1, 0, 0], [1, 0, 1]]];
        let order = assembly_order(l, &pieces);
        assert_eq!(order.len(), 3);
        let pos = |i: usize| order.iter().position(|&p| p == i).unwrap();
        assert!(pos(1) < pos(0));
    }

    #[test]
    fn flat_pieces_are_laid_each_touching_the_last() {
        let l = LatticeKind::Square.lattice();
        // Three strips: top, middle, bottom rows of a 3x3 square.
        let row = |y| vec![[0, y, 0], [1, y, 0], [2, y, 0]];
        let order = assembly_order(l, &[row(0), row(1), row(2)]);
        assert_eq!(order, vec![2, 1, 0]);
    }
}
