//! The `hex` lattice: regular pointy-top hexagons `[x, y, 0]` in rows, odd
//! rows shifted half a cell to the right ("odd-r" offset coordinates).
//!
//! A hexagon's point is its centre in axial coordinates `(q, r)`, the skew
//! basis `a = (1, 0)`, `b = (1/2, √3/2)` of the centres (`q = x − ⌊y/2⌋`,
//! `r = y`). Every integer point is a centre, so the modulus is 1, and the
//! 60° rotation is an integer matrix (see [`hexagonal_symmetries`]). The
//! same embedding as `shared/tools/verify.py`.

use super::{hexagonal_symmetries, Cell, Lattice, LatticeKind, Point, Symmetry};

/// The six axial neighbour directions.
const DIRS: [[i32; 2]; 6] = [[1, 0], [-1, 0], [0, 1], [0, -1], [1, -1], [-1, 1]];

/// The hexagon lattice.
#[derive(Clone, Copy, Debug, Default)]
pub struct Hex;

fn axial(x: i32, y: i32) -> [i32; 2] {
    [x - y.div_euclid(2), y]
}

fn offset(q: i32, r: i32) -> Cell {
    [q + r.div_euclid(2), r, 0]
}

impl Lattice for Hex {
    fn kind(&self) -> LatticeKind {
        LatticeKind::Hex
    }
    fn dim(&self) -> usize {
        2
    }
    fn modulus(&self) -> i32 {
        1
    }
    fn is_cell(&self, cell: Cell) -> bool {
        cell[2] == 0
    }
    fn to_point(&self, [x, y, _]: Cell) -> Point {
        let [q, r] = axial(x, y);
        Point::new(q, r, 0)
    }
    fn from_point(&self, p: Point) -> Option<Cell> {
        let [q, r, k] = p.coords();
        (k == 0).then(|| offset(q, r))
    }
    fn neighbors(&self, [x, y, _]: Cell) -> Vec<Cell> {
        let [q, r] = axial(x, y);
        DIRS.iter().map(|[dq, dr]| offset(q + dq, r + dr)).collect()
    }
    fn supports_mirror(&self) -> bool {
        true
    }
    fn symmetries(&self, mirror: bool) -> Vec<Symmetry> {
        hexagonal_symmetries(mirror)
    }
    /// Moves the top row to `y = 0` (which shifts the rows' `x` by their
    /// parity when `y` moves by an odd number), then the leftmost hexagon to
    /// `x = 0`.
    fn shift_to_origin(&self, cells: &[Cell]) -> Point {
        if cells.is_empty() {
            return Point::ORIGIN;
        }
        let dr = -cells.iter().map(|c| c[1]).min().unwrap_or(0);
        let min_x = cells
            .iter()
            .map(|&[x, y, _]| {
                let [q, r] = axial(x, y);
                offset(q, r + dr)[0]
            })
            .min()
            .unwrap_or(0);
        Point::new(-min_x, dr, 0)
    }
}
