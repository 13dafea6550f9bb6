//! The square lattice: unit squares `[x, y, 0]`, 4 edge-neighbours.

use super::{planar_symmetries, Cell, Lattice, LatticeKind, Point, Symmetry};

/// The square lattice.
#[derive(Clone, Copy, Debug, Default)]
pub struct Square;

impl Lattice for Square {
    fn kind(&self) -> LatticeKind {
        LatticeKind::Square
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
    fn to_point(&self, cell: Cell) -> Point {
        Point::from(cell)
    }
    fn from_point(&self, p: Point) -> Option<Cell> {
        (p[2] == 0).then_some(p.coords())
    }
    fn neighbors(&self, [x, y, _]: Cell) -> Vec<Cell> {
        vec![[x + 1, y, 0], [x - 1, y, 0], [x, y + 1, 0], [x, y - 1, 0]]
    }
    fn is_grid(&self) -> bool {
        true
    }
    fn supports_mirror(&self) -> bool {
        true
    }
    fn symmetries(&self, mirror: bool) -> Vec<Symmetry> {
        planar_symmetries(mirror)
    }
    fn coarse_phases(&self, factor: i32) -> usize {
        (factor.max(0) as usize).pow(2)
    }
    fn coarse_cell(&self, cell: Cell, factor: i32, phase: usize) -> Option<Cell> {
        super::grid_coarse_cell(cell, factor, phase, 2)
    }
}
