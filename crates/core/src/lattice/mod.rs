//! Lattices: what a cell is, which cells are its neighbours, and how the
//! lattice's point symmetries act on it.
//!
//! Every lattice embeds its cells as integer *points* (`to_point`) on which
//! the point symmetries act as signed permutation matrices about the origin,
//! and whose translations are the multiples of [`Lattice::modulus`] in the
//! first [`Lattice::dim`] coordinates. The solver works on points only, so it
//! is written once for every lattice.

mod cubic;
mod square;
mod tri4;

pub use cubic::Cubic;
pub use square::Square;
pub use tri4::Tri4;

use std::fmt;
use std::str::FromStr;

/// A cell in a figure's own coordinates.
///
/// * `square`: `[x, y, 0]`
/// * `tri4`: `[x, y, t]` with `t` in `0..4` (top, right, bottom, left)
/// * `cubic`: `[x, y, z]`
pub type Cell = [i32; 3];

/// A cell embedded as an integer point, on which symmetries act.
pub type Point = [i32; 3];

/// A point symmetry: a signed permutation matrix acting on points.
///
/// # Validity
/// Every row and every column has exactly one non-zero entry, which is ±1.
/// So the matrix is orthogonal and its inverse is its transpose.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Symmetry {
    m: [[i32; 3]; 3],
}

impl Symmetry {
    /// The identity.
    pub const IDENTITY: Symmetry = Symmetry {
        m: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    };

    /// A symmetry from its matrix, or `None` when it is not a signed
    /// permutation matrix.
    pub fn new(m: [[i32; 3]; 3]) -> Option<Symmetry> {
        for (i, row) in m.iter().enumerate() {
            let row_ok =
                row.iter().filter(|v| **v != 0).count() == 1 && row.iter().all(|v| v.abs() <= 1);
            let col_ok = (0..3).filter(|&r| m[r][i] != 0).count() == 1;
            if !row_ok || !col_ok {
                return None;
            }
        }
        Some(Symmetry { m })
    }

    /// The matrix.
    pub fn matrix(&self) -> [[i32; 3]; 3] {
        self.m
    }

    /// `self · p`.
    #[inline]
    pub fn apply(&self, p: Point) -> Point {
        let m = &self.m;
        [
            m[0][0] * p[0] + m[0][1] * p[1] + m[0][2] * p[2],
            m[1][0] * p[0] + m[1][1] * p[1] + m[1][2] * p[2],
            m[2][0] * p[0] + m[2][1] * p[1] + m[2][2] * p[2],
        ]
    }

    /// `self · v` for a wide vector (sums of points).
    #[inline]
    pub fn apply_wide(&self, p: [i64; 3]) -> [i64; 3] {
        let m = &self.m;
        let mut out = [0i64; 3];
        for (r, o) in out.iter_mut().enumerate() {
            *o = m[r][0] as i64 * p[0] + m[r][1] as i64 * p[1] + m[r][2] as i64 * p[2];
        }
        out
    }

    /// The composition `self ∘ other` (apply `other` first).
    pub fn compose(&self, other: &Symmetry) -> Symmetry {
        let mut m = [[0; 3]; 3];
        for (r, row) in m.iter_mut().enumerate() {
            for (c, v) in row.iter_mut().enumerate() {
                *v = (0..3).map(|k| self.m[r][k] * other.m[k][c]).sum();
            }
        }
        Symmetry { m }
    }

    /// The inverse (the transpose, since the matrix is orthogonal).
    pub fn inverse(&self) -> Symmetry {
        let mut m = [[0; 3]; 3];
        for (r, row) in m.iter_mut().enumerate() {
            for (c, v) in row.iter_mut().enumerate() {
                *v = self.m[c][r];
            }
        }
        Symmetry { m }
    }

    /// The determinant: +1 for rotations, -1 for reflections.
    pub fn determinant(&self) -> i32 {
        let m = &self.m;
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }
}

/// The lattices `dissect` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum LatticeKind {
    /// Unit squares, 4 edge-neighbours, 8 point symmetries.
    Square,
    /// Unit squares split by both diagonals into 4 right triangles.
    Tri4,
    /// Unit cubes, 6 face-neighbours, 24 proper rotations.
    Cubic,
}

impl LatticeKind {
    /// All lattices.
    pub const ALL: [LatticeKind; 3] = [LatticeKind::Square, LatticeKind::Tri4, LatticeKind::Cubic];

    /// The name used in files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            LatticeKind::Square => "square",
            LatticeKind::Tri4 => "tri4",
            LatticeKind::Cubic => "cubic",
        }
    }

    /// The lattice's geometry.
    pub fn lattice(self) -> &'static dyn Lattice {
        match self {
            LatticeKind::Square => &Square,
            LatticeKind::Tri4 => &Tri4,
            LatticeKind::Cubic => &Cubic,
        }
    }
}

impl fmt::Display for LatticeKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Occurs when a lattice name is not one of `square`, `tri4`, `cubic`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown lattice {0:?} (expected square, tri4 or cubic)")]
pub struct UnknownLattice(pub String);

impl FromStr for LatticeKind {
    type Err = UnknownLattice;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        LatticeKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| UnknownLattice(s.to_string()))
    }
}

/// The geometry of a lattice.
pub trait Lattice: Send + Sync {
    /// Which lattice this is.
    fn kind(&self) -> LatticeKind;

    /// The number of point coordinates that translations move (2 or 3).
    fn dim(&self) -> usize;

    /// Translations are the multiples of this in each moved coordinate.
    fn modulus(&self) -> i32;

    /// Whether a cell has a valid form for this lattice.
    fn is_cell(&self, cell: Cell) -> bool;

    /// The integer point of a cell.
    fn to_point(&self, cell: Cell) -> Point;

    /// The cell whose point is `p`, if any.
    #[allow(clippy::wrong_self_convention)] // a lattice method, not a constructor
    fn from_point(&self, p: Point) -> Option<Cell>;

    /// The edge- (or face-) neighbours of a cell, whether in a figure or not.
    fn neighbors(&self, cell: Cell) -> Vec<Cell>;

    /// Whether mirror images (2D flips) may be used at all.
    fn supports_mirror(&self) -> bool;

    /// The allowed point symmetries; the identity comes first.
    fn symmetries(&self, mirror: bool) -> Vec<Symmetry>;

    /// Every cell whose block `[x, y, z]` lies in the box `lo..=hi`
    /// (for 2D lattices the third coordinate of the box is ignored).
    fn cells_in_box(&self, lo: [i32; 3], hi: [i32; 3]) -> Vec<Cell>;

    /// The block (`[x, y, 0]` in 2D) a cell lies in.
    fn block(&self, cell: Cell) -> [i32; 3];
}

/// The 8 symmetries of the square grid acting on the x/y plane (rotations
/// first, then reflections); the z coordinate is left alone.
pub(crate) fn planar_symmetries(mirror: bool) -> Vec<Symmetry> {
    let rots = [
        [[1, 0], [0, 1]],
        [[0, -1], [1, 0]],
        [[-1, 0], [0, -1]],
        [[0, 1], [-1, 0]],
    ];
    let flips = [
        [[-1, 0], [0, 1]],
        [[0, 1], [1, 0]],
        [[1, 0], [0, -1]],
        [[0, -1], [-1, 0]],
    ];
    let lift = |m: [[i32; 2]; 2]| {
        Symmetry::new([[m[0][0], m[0][1], 0], [m[1][0], m[1][1], 0], [0, 0, 1]])
            .expect("planar symmetry is a signed permutation")
    };
    let mut out: Vec<Symmetry> = rots.into_iter().map(lift).collect();
    if mirror {
        out.extend(flips.into_iter().map(lift));
    }
    out
}
