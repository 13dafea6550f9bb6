//! The `tri4` lattice: every unit square split by both diagonals into four
//! right triangles `[x, y, t]`, `t` = 0 top, 1 right, 2 bottom, 3 left.
//!
//! A triangle's point is its centroid times 6, `6·(x, y) + R[t]` with
//! `R = (3,1), (5,3), (3,5), (1,3)`; translations are whole squares, so the
//! modulus is 6. The 8 symmetries of the square grid map these points onto
//! each other.

use super::{planar_symmetries, Cell, Lattice, LatticeKind, Point, Symmetry};

/// Triangle centroids times 6, relative to `6·(x, y)`.
const RESIDUE: [[i32; 2]; 4] = [[3, 1], [5, 3], [3, 5], [1, 3]];

/// The right-triangle lattice.
#[derive(Clone, Copy, Debug, Default)]
pub struct Tri4;

impl Lattice for Tri4 {
    fn kind(&self) -> LatticeKind {
        LatticeKind::Tri4
    }
    fn dim(&self) -> usize {
        2
    }
    fn modulus(&self) -> i32 {
        6
    }
    fn is_cell(&self, cell: Cell) -> bool {
        (0..4).contains(&cell[2])
    }
    fn to_point(&self, [x, y, t]: Cell) -> Point {
        let r = RESIDUE[t as usize];
        Point::new(6 * x + r[0], 6 * y + r[1], 0)
    }
    fn from_point(&self, p: Point) -> Option<Cell> {
        if p[2] != 0 {
            return None;
        }
        let r = [p[0].rem_euclid(6), p[1].rem_euclid(6)];
        let t = RESIDUE.iter().position(|q| *q == r)?;
        Some([p[0].div_euclid(6), p[1].div_euclid(6), t as i32])
    }
    fn neighbors(&self, [x, y, t]: Cell) -> Vec<Cell> {
        let across = match t {
            0 => [x, y - 1, 2],
            1 => [x + 1, y, 3],
            2 => [x, y + 1, 0],
            _ => [x - 1, y, 1],
        };
        vec![[x, y, (t + 1) % 4], [x, y, (t + 3) % 4], across]
    }
    fn supports_mirror(&self) -> bool {
        true
    }
    fn symmetries(&self, mirror: bool) -> Vec<Symmetry> {
        planar_symmetries(mirror)
    }
    fn cells_in_box(&self, lo: [i32; 3], hi: [i32; 3]) -> Vec<Cell> {
        super::plane_blocks(lo, hi)
            .into_iter()
            .flat_map(|[x, y, _]| (0..4).map(move |t| [x, y, t]))
            .collect()
    }
}
