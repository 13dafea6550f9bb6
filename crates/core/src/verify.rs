//! An independent check that a dissection is valid.
//!
//! Architecture invariant: this module shares no code with the solver. It
//! uses the lattice only for its definitions (cell points, neighbours, the
//! translation modulus) and enumerates the point symmetries itself, so a bug
//! in the solver's geometry cannot hide here.

use std::collections::{BTreeSet, HashSet};

use crate::dissection::Dissection;
use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind, Point};

/// One reason a dissection is invalid.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum Violation {
    /// Occurs when the solution and the input disagree on the lattice.
    #[error("solution lattice is {found}, the figures are {expected}")]
    LatticeMismatch {
        /// The solution's lattice.
        found: LatticeKind,
        /// The figures' lattice.
        expected: LatticeKind,
    },
    /// Occurs when the numbers of figures differ.
    #[error("solution has {found} figures, {expected} were given")]
    FigureCount {
        /// In the solution.
        found: usize,
        /// Given.
        expected: usize,
    },
    /// Occurs when figures list different numbers of pieces.
    #[error("figures list different numbers of pieces: {0:?}")]
    PieceCount(Vec<usize>),
    /// Occurs when there is no piece.
    #[error("no pieces")]
    NoPieces,
    /// Occurs when a piece has no cell.
    #[error("figure {figure} piece {piece} is empty")]
    EmptyPiece {
        /// Figure index.
        figure: usize,
        /// Piece index.
        piece: usize,
    },
    /// Occurs when a cell is listed twice (in one piece or in two).
    #[error("figure {figure}: cell {cell:?} is listed more than once")]
    Overlap {
        /// Figure index.
        figure: usize,
        /// The cell.
        cell: Cell,
    },
    /// Occurs when a piece lists a cell outside its figure.
    #[error("figure {figure} piece {piece}: cell {cell:?} is not in the figure")]
    OutsideFigure {
        /// Figure index.
        figure: usize,
        /// Piece index.
        piece: usize,
        /// The cell.
        cell: Cell,
    },
    /// Occurs when cells of a figure are in no piece.
    #[error("figure {figure}: {count} cell(s) not covered, e.g. {example:?}")]
    Uncovered {
        /// Figure index.
        figure: usize,
        /// How many.
        count: usize,
        /// One of them.
        example: Cell,
    },
    /// Occurs when a piece is not connected.
    #[error("figure {figure} piece {piece} is not connected ({components} components)")]
    Disconnected {
        /// Figure index.
        figure: usize,
        /// Piece index.
        piece: usize,
        /// Its number of components.
        components: usize,
    },
    /// Occurs when piece `i` of a figure is not congruent to piece `i` of figure 0.
    #[error("piece {piece} of figure {figure} is not congruent to piece {piece} of figure 0")]
    NotCongruent {
        /// Figure index.
        figure: usize,
        /// Piece index.
        piece: usize,
    },
}

/// Checks that `d` is a valid dissection of `figures`; returns the number of
/// pieces, or every violation found.
pub fn verify(d: &Dissection, figures: &[Figure]) -> Result<usize, Vec<Violation>> {
    let mut v = Vec::new();
    let lattice = figures.first().map_or(d.lattice(), |f| f.lattice());
    if d.lattice() != lattice {
        return Err(vec![Violation::LatticeMismatch {
            found: d.lattice(),
            expected: lattice,
        }]);
    }
    if d.pieces().len() != figures.len() {
        return Err(vec![Violation::FigureCount {
            found: d.pieces().len(),
            expected: figures.len(),
        }]);
    }
    let counts: Vec<usize> = d.pieces().iter().map(|p| p.len()).collect();
    if counts.iter().any(|c| *c != counts[0]) {
        return Err(vec![Violation::PieceCount(counts)]);
    }
    // No figure at all counts as no pieces (and must not index `counts`).
    if counts.first().is_none_or(|c| *c == 0) {
        return Err(vec![Violation::NoPieces]);
    }
    let l = lattice.lattice();
    for (f, (fig, pieces)) in figures.iter().zip(d.pieces()).enumerate() {
        let mut seen: HashSet<Cell> = HashSet::new();
        for (i, piece) in pieces.iter().enumerate() {
            if piece.is_empty() {
                v.push(Violation::EmptyPiece {
                    figure: f,
                    piece: i,
                });
                continue;
            }
            for &c in piece {
                if !seen.insert(c) {
                    v.push(Violation::Overlap { figure: f, cell: c });
                } else if !fig.contains(c) {
                    v.push(Violation::OutsideFigure {
                        figure: f,
                        piece: i,
                        cell: c,
                    });
                }
            }
            let comps = count_components(piece, |c| l.neighbors(c));
            if comps > 1 {
                v.push(Violation::Disconnected {
                    figure: f,
                    piece: i,
                    components: comps,
                });
            }
        }
        let missing: Vec<Cell> = fig
            .cells()
            .iter()
            .filter(|c| !seen.contains(*c))
            .copied()
            .collect();
        if let Some(&example) = missing.first() {
            v.push(Violation::Uncovered {
                figure: f,
                count: missing.len(),
                example,
            });
        }
    }
    let mirror = d.mirror() && l.supports_mirror();
    let mats = match lattice {
        LatticeKind::Tri3 | LatticeKind::Hex => own_hexagonal_symmetries(mirror),
        _ => own_symmetries(l.dim(), mirror),
    };
    let modulus = l.modulus();
    for i in 0..counts[0] {
        let base: Vec<Point> = d.pieces()[0][i].iter().map(|c| l.to_point(*c)).collect();
        if base.is_empty() {
            continue;
        }
        let forms: HashSet<Vec<Point>> = mats
            .iter()
            .map(|m| canonical(base.iter().map(|p| mul(m, *p)).collect(), modulus))
            .collect();
        for f in 1..d.pieces().len() {
            let other: Vec<Point> = d.pieces()[f][i].iter().map(|c| l.to_point(*c)).collect();
            if other.is_empty() {
                continue;
            }
            if !forms.contains(&canonical(other, modulus)) {
                v.push(Violation::NotCongruent {
                    figure: f,
                    piece: i,
                });
            }
        }
    }
    if v.is_empty() {
        Ok(counts[0])
    } else {
        Err(v)
    }
}

fn count_components(cells: &[Cell], neighbors: impl Fn(Cell) -> Vec<Cell>) -> usize {
    let set: HashSet<Cell> = cells.iter().copied().collect();
    let mut seen: HashSet<Cell> = HashSet::new();
    let mut n = 0;
    for &c in &set {
        if !seen.insert(c) {
            continue;
        }
        n += 1;
        let mut stack = vec![c];
        while let Some(u) = stack.pop() {
            for w in neighbors(u) {
                if set.contains(&w) && seen.insert(w) {
                    stack.push(w);
                }
            }
        }
    }
    n
}

/// Signed permutation matrices of the given dimension: in 2D the 4
/// rotations (and 4 reflections with `mirror`), in 3D the 24 rotations.
fn own_symmetries(dim: usize, mirror: bool) -> Vec<[[i32; 3]; 3]> {
    let mut out = Vec::new();
    // Its own list, not the lattice's `AXIS_PERMUTATIONS`: the checker
    // shares nothing with the symmetries it checks.
    let perms: Vec<[usize; 3]> = if dim == 2 {
        vec![[0, 1, 2], [1, 0, 2]]
    } else {
        vec![
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ]
    };
    let mut seen = BTreeSet::new();
    for p in perms {
        for s in 0..(1 << dim) {
            let mut m = [[0; 3]; 3];
            for r in 0..3 {
                let sign = if r < dim && s >> r & 1 == 1 { -1 } else { 1 };
                m[r][p[r]] = sign;
            }
            let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            if (det == 1 || mirror) && seen.insert(m) {
                out.push(m);
            }
        }
    }
    out
}

/// The 12 symmetries of the triangular lattice in the skew basis
/// `a = (1, 0)`, `b = (1/2, √3/2)` that `tri3` and `hex` points use: the
/// powers of the 60° turn `a ↦ b, b ↦ b − a`, and with `mirror` each of them
/// after the swap of `a` and `b`.
fn own_hexagonal_symmetries(mirror: bool) -> Vec<[[i32; 3]; 3]> {
    let turn = [[0, -1, 0], [1, 1, 0], [0, 0, 1]];
    let swap = [[0, 1, 0], [1, 0, 0], [0, 0, 1]];
    let times = |a: &[[i32; 3]; 3], b: &[[i32; 3]; 3]| {
        let mut m = [[0; 3]; 3];
        for r in 0..3 {
            for c in 0..3 {
                m[r][c] = (0..3).map(|k| a[r][k] * b[k][c]).sum();
            }
        }
        m
    };
    let mut rotations = vec![[[1, 0, 0], [0, 1, 0], [0, 0, 1]]];
    for k in 1..6 {
        let next = times(&turn, &rotations[k - 1]);
        rotations.push(next);
    }
    let mut out = rotations.clone();
    if mirror {
        out.extend(rotations.iter().map(|r| times(r, &swap)));
    }
    out
}

fn mul(m: &[[i32; 3]; 3], p: Point) -> Point {
    let mut out = [0; 3];
    for r in 0..3 {
        out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2];
    }
    Point::from(out)
}

/// The point set sorted and translated by a multiple of `modulus` so that its
/// smallest point lies in `[0, modulus)^3`.
fn canonical(mut pts: Vec<Point>, modulus: i32) -> Vec<Point> {
    pts.sort();
    let first = pts[0];
    let off = Point::from(first.coords().map(|c| modulus * c.div_euclid(modulus)));
    let mut out: Vec<Point> = pts.iter().map(|p| *p - off).collect();
    out.sort();
    out
}

/// Cells that are not of the lattice, as the violations they make (such a
/// cell lies in no figure).
fn bad_cells(lattice: LatticeKind, pieces: &[Vec<Vec<Cell>>]) -> Vec<Violation> {
    let l = lattice.lattice();
    let mut v = Vec::new();
    for (figure, fp) in pieces.iter().enumerate() {
        for (piece, cells) in fp.iter().enumerate() {
            for &cell in cells.iter().filter(|c| !l.is_cell(**c)) {
                v.push(Violation::OutsideFigure {
                    figure,
                    piece,
                    cell,
                });
            }
        }
    }
    v
}

/// Convenience for callers holding cells per piece: whether the labelling
/// `pieces[f][i]` covers and matches, as [`verify`].
pub fn verify_pieces(
    lattice: LatticeKind,
    mirror: bool,
    figures: &[Figure],
    pieces: &[Vec<Vec<Cell>>],
) -> Result<usize, Vec<Violation>> {
    match Dissection::unnamed(lattice, mirror, pieces.to_vec()) {
        Ok(d) => verify(&d, figures),
        // A cell that is not of the lattice lies in no figure of it.
        Err(_) => Err(bad_cells(lattice, pieces)),
    }
}
