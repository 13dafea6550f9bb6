//! Lattices: what a cell is, which cells are its neighbours, and how the
//! lattice's point symmetries act on it.
//!
//! Every lattice embeds its cells as integer *points* (`to_point`) on which
//! the point symmetries act as signed permutation matrices about the origin,
//! and whose translations are the multiples of [`Lattice::modulus`] in the
//! first [`Lattice::dim`] coordinates. The solver works on points only, so it
//! is written once for every lattice.

mod cubic;
mod hex;
mod square;
mod tri3;
mod tri4;

pub use cubic::Cubic;
pub use hex::Hex;
pub use square::Square;
pub use tri3::Tri3;
pub use tri4::Tri4;

use std::fmt;
use std::str::FromStr;

/// The six permutations of three axes (`[0, 1, 2]` first): the axis
/// orders of the cubic lattice's rotations and of the guillotine cuts.
pub(crate) const AXIS_PERMUTATIONS: [[usize; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

/// The largest coordinate a cell may have in a file (so that lattice points,
/// up to 6 times larger, stay far from overflow).
pub const MAX_COORDINATE: i64 = 1 << 24;

/// A cell in a figure's own coordinates.
///
/// * `square`: `[x, y, 0]`
/// * `tri4`: `[x, y, t]` with `t` in `0..4` (top, right, bottom, left)
/// * `cubic`: `[x, y, z]`
/// * `tri3`: `[x, y, 0]`, pointing up when `x + y` is even
/// * `hex`: `[x, y, 0]`, odd rows shifted half a cell to the right
///
/// A plain array, unlike [`Point`]: a cell is what files, the studio and
/// Python write (through [`LatticeKind::cell_from_coords`] and
/// [`LatticeKind::cell_coords`]), and nothing computes with it but the
/// lattice that owns it; the geometry works on points, whose type a cell
/// does not convert to except through [`Lattice::to_point`].
pub type Cell = [i32; 3];

/// A cell embedded as an integer point, on which symmetries act; also a
/// translation between points (a difference of two points). A distinct
/// type from [`Cell`]: on `tri4`, `tri3` and `hex` a cell's point is not
/// its coordinates ([`Lattice::to_point`], [`Lattice::from_point`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Point([i32; 3]);

impl Point {
    /// The origin, also the zero translation.
    pub const ORIGIN: Point = Point([0, 0, 0]);

    /// The point `(x, y, z)`.
    pub const fn new(x: i32, y: i32, z: i32) -> Point {
        Point([x, y, z])
    }

    /// The coordinates.
    pub const fn coords(self) -> [i32; 3] {
        self.0
    }
}

impl From<[i32; 3]> for Point {
    fn from(c: [i32; 3]) -> Point {
        Point(c)
    }
}

impl From<Point> for [i32; 3] {
    fn from(p: Point) -> [i32; 3] {
        p.0
    }
}

impl std::ops::Index<usize> for Point {
    type Output = i32;
    #[inline]
    fn index(&self, i: usize) -> &i32 {
        &self.0[i]
    }
}

/// `Point ± Point`, also on references (as the integers do).
macro_rules! point_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl std::ops::$trait for Point {
            type Output = Point;
            #[inline]
            fn $method(self, o: Point) -> Point {
                Point([self.0[0] $op o.0[0], self.0[1] $op o.0[1], self.0[2] $op o.0[2]])
            }
        }
        impl std::ops::$trait<&Point> for Point {
            type Output = Point;
            #[inline]
            fn $method(self, o: &Point) -> Point {
                std::ops::$trait::$method(self, *o)
            }
        }
        impl std::ops::$trait<Point> for &Point {
            type Output = Point;
            #[inline]
            fn $method(self, o: Point) -> Point {
                std::ops::$trait::$method(*self, o)
            }
        }
        impl std::ops::$trait<&Point> for &Point {
            type Output = Point;
            #[inline]
            fn $method(self, o: &Point) -> Point {
                std::ops::$trait::$method(*self, *o)
            }
        }
    };
}

point_op!(Add, add, +);
point_op!(Sub, sub, -);

impl std::ops::Neg for Point {
    type Output = Point;
    #[inline]
    fn neg(self) -> Point {
        Point([-self.0[0], -self.0[1], -self.0[2]])
    }
}

/// A point symmetry: an integer matrix of finite order and determinant ±1
/// acting on points (a signed permutation matrix on `square`, `tri4` and
/// `cubic`; on `tri3` and `hex`, whose points use a skew basis, the 60°
/// rotation is `[[0, -1], [1, 1]]`).
///
/// # Validity
/// The entries are integers, the determinant is ±1 (so the inverse is an
/// integer matrix too) and some power up to the 12th is the identity (so it
/// is a rotation or reflection in a suitable metric, never a shear); every
/// entry lies in `-2..=2`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Symmetry {
    m: [[i32; 3]; 3],
}

type Matrix = [[i32; 3]; 3];

fn mat_mul(a: &Matrix, b: &Matrix) -> Matrix {
    let mut m = [[0; 3]; 3];
    for (r, row) in m.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            *v = (0..3).map(|k| a[r][k] * b[k][c]).sum();
        }
    }
    m
}

fn mat_det(m: &Matrix) -> i64 {
    let m = m.map(|r| r.map(i64::from));
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

impl Symmetry {
    /// The identity.
    pub const IDENTITY: Symmetry = Symmetry {
        m: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    };

    /// A symmetry from its matrix, or `None` when its determinant is not ±1
    /// or it has no finite order (a shear, a scaling).
    pub fn new(m: [[i32; 3]; 3]) -> Option<Symmetry> {
        // Entries of a finite-order unimodular 3×3 matrix are small; this
        // also keeps the products below from overflowing.
        if m.iter().flatten().any(|v| v.abs() > 2) || mat_det(&m).abs() != 1 {
            return None;
        }
        // Finite orders of integer 3×3 matrices are 1, 2, 3, 4 and 6.
        let mut p = m;
        for _ in 1..12 {
            if p == Self::IDENTITY.m {
                return Some(Symmetry { m });
            }
            p = mat_mul(&p, &m);
            if p.iter().flatten().any(|v| v.abs() > 64) {
                return None;
            }
        }
        (p == Self::IDENTITY.m).then_some(Symmetry { m })
    }

    /// The matrix.
    pub fn matrix(&self) -> [[i32; 3]; 3] {
        self.m
    }

    /// `self · p`.
    #[inline]
    pub fn apply(&self, p: Point) -> Point {
        let m = &self.m;
        Point([
            m[0][0] * p[0] + m[0][1] * p[1] + m[0][2] * p[2],
            m[1][0] * p[0] + m[1][1] * p[1] + m[1][2] * p[2],
            m[2][0] * p[0] + m[2][1] * p[1] + m[2][2] * p[2],
        ])
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
        Symmetry {
            m: mat_mul(&self.m, &other.m),
        }
    }

    /// The inverse: the adjugate times the determinant (which is ±1).
    pub fn inverse(&self) -> Symmetry {
        let a = &self.m;
        let det = self.determinant();
        let mut m = [[0; 3]; 3];
        for (r, row) in m.iter_mut().enumerate() {
            for (c, v) in row.iter_mut().enumerate() {
                // inverse[r][c] = cofactor[c][r] / det
                let (r1, r2) = ((c + 1) % 3, (c + 2) % 3);
                let (c1, c2) = ((r + 1) % 3, (r + 2) % 3);
                *v = (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]) * det;
            }
        }
        Symmetry { m }
    }

    /// The largest sum of absolute values along a row: how far a point can
    /// move away from the origin, coordinate-wise, relative to its largest
    /// coordinate (1 for signed permutations, 2 for the skew 60° rotation).
    pub fn spread(&self) -> i32 {
        self.m
            .iter()
            .map(|r| r.iter().map(|v| v.abs()).sum::<i32>())
            .max()
            .unwrap_or(1)
    }

    /// The determinant: +1 for rotations, -1 for reflections.
    pub fn determinant(&self) -> i32 {
        mat_det(&self.m) as i32
    }
}

/// The 12 symmetries of the triangular lattice in the skew basis
/// `a = (1, 0)`, `b = (1/2, √3/2)` (6 rotations by multiples of 60°, the
/// identity first, then the 6 reflections with `mirror`): `R` turns `a` into
/// `b` and `b` into `b − a`, `M` swaps `a` and `b`. The third coordinate is
/// left alone.
pub(crate) fn hexagonal_symmetries(mirror: bool) -> Vec<Symmetry> {
    let r = Symmetry::new([[0, -1, 0], [1, 1, 0], [0, 0, 1]]).expect("the 60° rotation");
    let flip = Symmetry::new([[0, 1, 0], [1, 0, 0], [0, 0, 1]]).expect("the a/b swap");
    let mut rots = vec![Symmetry::IDENTITY];
    for _ in 0..5 {
        let last = *rots.last().expect("non-empty");
        rots.push(r.compose(&last));
    }
    let mut out = rots.clone();
    if mirror {
        out.extend(rots.iter().map(|g| g.compose(&flip)));
    }
    out
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
    /// Equilateral triangles in rows, alternately pointing up and down;
    /// 3 edge-neighbours, 12 point symmetries.
    Tri3,
    /// Regular pointy-top hexagons in rows, odd rows shifted half a cell
    /// right; 6 neighbours, 12 point symmetries.
    Hex,
}

impl LatticeKind {
    /// All lattices.
    pub const ALL: [LatticeKind; 5] = [
        LatticeKind::Square,
        LatticeKind::Tri4,
        LatticeKind::Cubic,
        LatticeKind::Tri3,
        LatticeKind::Hex,
    ];

    /// The name used in files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            LatticeKind::Square => "square",
            LatticeKind::Tri4 => "tri4",
            LatticeKind::Cubic => "cubic",
            LatticeKind::Tri3 => "tri3",
            LatticeKind::Hex => "hex",
        }
    }

    /// How many coordinates a cell has in files: 2 (`[x, y]`) on `square`,
    /// `tri3` and `hex`, 3 on `tri4` (`[x, y, t]`) and `cubic` (`[x, y, z]`).
    pub fn cell_arity(self) -> usize {
        match self {
            LatticeKind::Square | LatticeKind::Tri3 | LatticeKind::Hex => 2,
            LatticeKind::Tri4 | LatticeKind::Cubic => 3,
        }
    }

    /// How a cell is written in solution files (for error messages).
    pub fn cell_form(self) -> &'static str {
        match self {
            LatticeKind::Square | LatticeKind::Tri3 | LatticeKind::Hex => "[x, y]",
            LatticeKind::Tri4 => "[x, y, t] with t in 0..=3",
            LatticeKind::Cubic => "[x, y, z]",
        }
    }

    /// The cell written as `coords` in a file: [`LatticeKind::cell_arity`]
    /// numbers, each at most [`MAX_COORDINATE`] in size, that make a valid
    /// cell of this lattice; `None` otherwise. The one rule for reading
    /// cells, used by the solution reader, the CLI and the studio.
    pub fn cell_from_coords(self, coords: &[i64]) -> Option<Cell> {
        let want = self.cell_arity();
        if coords.len() != want || coords.iter().any(|v| v.abs() > MAX_COORDINATE) {
            return None;
        }
        let cell = [
            coords[0] as i32,
            coords[1] as i32,
            if want == 3 { coords[2] as i32 } else { 0 },
        ];
        self.lattice().is_cell(cell).then_some(cell)
    }

    /// [`LatticeKind::cell_from_coords`], also taking a 2D lattice's cell
    /// written with a third coordinate of 0 (`[x, y, 0]`, as arrays of
    /// three columns give it): the rule of the studio's API and of Python's
    /// `Figure.from_cells`.
    pub fn cell_from_coords_padded(self, coords: &[i64]) -> Option<Cell> {
        match coords {
            [x, y, 0] if self.cell_arity() == 2 => self.cell_from_coords(&[*x, *y]),
            _ => self.cell_from_coords(coords),
        }
    }

    /// The coordinates a cell is written with in files (the inverse of
    /// [`LatticeKind::cell_from_coords`]).
    pub fn cell_coords(self, cell: Cell) -> Vec<i64> {
        cell[..self.cell_arity()]
            .iter()
            .map(|v| *v as i64)
            .collect()
    }

    /// Whether a figure file has one `#`/`.` character per cell (`square`,
    /// `tri3`, `hex`), as opposed to hex digits (`tri4`) or layers (`cubic`).
    pub fn plain_text(self) -> bool {
        self.cell_arity() == 2
    }

    /// The lattice's geometry.
    pub fn lattice(self) -> &'static dyn Lattice {
        match self {
            LatticeKind::Square => &Square,
            LatticeKind::Tri4 => &Tri4,
            LatticeKind::Cubic => &Cubic,
            LatticeKind::Tri3 => &Tri3,
            LatticeKind::Hex => &Hex,
        }
    }
}

impl fmt::Display for LatticeKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Occurs when a lattice name is not one of `square`, `tri4`, `cubic`,
/// `tri3`, `hex`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown lattice {0:?} (expected square, tri4, cubic, tri3 or hex)")]
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

    /// Whether the cells are exactly the integer points (a cell is its own
    /// point, translations are by any integer) and every symmetry is a
    /// signed permutation of the axes, so that a box of cells is a box of
    /// points and a symmetry maps it onto a box (`square` and `cubic`).
    fn is_grid(&self) -> bool {
        false
    }

    /// Every cell whose block `[x, y, z]` lies in the box `lo..=hi`
    /// (for 2D lattices the third coordinate of the box is ignored). The
    /// default is a 2D lattice with one cell `[x, y, 0]` per block
    /// (`square`, `tri3`, `hex`); `tri4` and `cubic` have their own.
    fn cells_in_box(&self, lo: [i32; 3], hi: [i32; 3]) -> Vec<Cell> {
        plane_blocks(lo, hi)
    }

    /// The block (`[x, y, 0]` in 2D) a cell lies in. The default is a 2D
    /// lattice's (`square`, `tri4`, `tri3`, `hex`); `cubic` has its own.
    fn block(&self, cell: Cell) -> [i32; 3] {
        [cell[0], cell[1], 0]
    }

    /// A lattice translation, as a point offset, that moves `cells` so that
    /// their smallest block coordinates are as near 0 as the lattice allows
    /// and never negative (exactly 0 on `square`, `tri4`, `cubic` and `hex`;
    /// on `tri3`, where a translation must keep `x + y` even, `x` may start
    /// at 1). [`Point::ORIGIN`] for no cells.
    fn shift_to_origin(&self, cells: &[Cell]) -> Point {
        let Some(first) = cells.first() else {
            return Point::ORIGIN;
        };
        let mut min = self.block(*first);
        for c in cells {
            let b = self.block(*c);
            for d in 0..3 {
                min[d] = min[d].min(b[d]);
            }
        }
        let m = self.modulus();
        Point([-m * min[0], -m * min[1], -m * min[2]])
    }

    /// The number of ways ([`Lattice::coarse_cell`]'s `phase`) to lay the
    /// lattice enlarged `factor` times over this one; 0 where the lattice
    /// has no coarsening.
    fn coarse_phases(&self, factor: i32) -> usize {
        let _ = factor;
        0
    }

    /// The cell of the lattice enlarged `factor` times (shifted by `phase`,
    /// below [`Lattice::coarse_phases`]) that holds `cell`: the inverse of
    /// enlarging a figure `factor` times. `None` where the lattice has no
    /// coarsening or `phase` is out of range.
    fn coarse_cell(&self, cell: Cell, factor: i32, phase: usize) -> Option<Cell> {
        let _ = (cell, factor, phase);
        None
    }
}

/// The coarse cell of `cell` on a grid of `factor`-blocks along the first
/// `dims` coordinates, shifted by the `phase`-th offset in `0..factor` per
/// coordinate (for the square and cubic lattices, whose cells are points).
pub(crate) fn grid_coarse_cell(cell: Cell, factor: i32, phase: usize, dims: usize) -> Option<Cell> {
    if factor < 1 || phase >= (factor as usize).pow(dims as u32) {
        return None;
    }
    let mut out = [0; 3];
    let mut p = phase;
    for d in 0..dims {
        let shift = (p % factor as usize) as i32;
        p /= factor as usize;
        out[d] = (cell[d] + shift).div_euclid(factor);
    }
    Some(out)
}

/// The blocks `[x, y, 0]` of the plane box `lo..=hi` (row by row; the third
/// coordinate of the box is ignored): the cells of `square`, `tri3` and
/// `hex` in a box, and the squares `tri4` splits.
pub(crate) fn plane_blocks(lo: [i32; 3], hi: [i32; 3]) -> Vec<Cell> {
    let mut out = Vec::new();
    for y in lo[1]..=hi[1] {
        for x in lo[0]..=hi[0] {
            out.push([x, y, 0]);
        }
    }
    out
}

/// The cells moved by the point offset `shift` (a lattice translation).
///
/// # Panics
/// When `shift` is not a translation of the lattice.
pub fn translate_cells(l: &dyn Lattice, cells: &[Cell], shift: Point) -> Vec<Cell> {
    cells
        .iter()
        .map(|c| {
            let p = l.to_point(*c);
            l.from_point(p + shift)
                .expect("a lattice translation maps cells to cells")
        })
        .collect()
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
