//! The cubic lattice: unit cubes `[x, y, z]`, 6 face-neighbours, the 24
//! proper rotations and never a mirror image.

use super::{Cell, Lattice, LatticeKind, Point, Symmetry, AXIS_PERMUTATIONS};

/// The cubic (voxel) lattice.
#[derive(Clone, Copy, Debug, Default)]
pub struct Cubic;

impl Lattice for Cubic {
    fn kind(&self) -> LatticeKind {
        LatticeKind::Cubic
    }
    fn dim(&self) -> usize {
        3
    }
    fn modulus(&self) -> i32 {
        1
    }
    fn is_cell(&self, _cell: Cell) -> bool {
        true
    }
    fn to_point(&self, cell: Cell) -> Point {
        Point::from(cell)
    }
    fn from_point(&self, p: Point) -> Option<Cell> {
        Some(p.coords())
    }
    fn neighbors(&self, [x, y, z]: Cell) -> Vec<Cell> {
        vec![
            [x + 1, y, z],
            [x - 1, y, z],
            [x, y + 1, z],
            [x, y - 1, z],
            [x, y, z + 1],
            [x, y, z - 1],
        ]
    }
    fn is_grid(&self) -> bool {
        true
    }
    fn supports_mirror(&self) -> bool {
        false
    }
    /// The 24 rotations (`mirror` is ignored: a solid cannot be turned inside out).
    fn symmetries(&self, _mirror: bool) -> Vec<Symmetry> {
        let mut out = Vec::with_capacity(24);
        for perm in AXIS_PERMUTATIONS {
            for signs in 0..8 {
                let mut m = [[0; 3]; 3];
                for r in 0..3 {
                    m[r][perm[r]] = if signs >> r & 1 == 1 { -1 } else { 1 };
                }
                let s = Symmetry::new(m).expect("signed permutation");
                if s.determinant() == 1 {
                    out.push(s);
                }
            }
        }
        out
    }
    fn cells_in_box(&self, lo: [i32; 3], hi: [i32; 3]) -> Vec<Cell> {
        let mut out = Vec::new();
        for z in lo[2]..=hi[2] {
            for y in lo[1]..=hi[1] {
                for x in lo[0]..=hi[0] {
                    out.push([x, y, z]);
                }
            }
        }
        out
    }
    fn block(&self, cell: Cell) -> [i32; 3] {
        cell
    }
    fn coarse_phases(&self, factor: i32) -> usize {
        (factor.max(0) as usize).pow(3)
    }
    fn coarse_cell(&self, cell: Cell, factor: i32, phase: usize) -> Option<Cell> {
        super::grid_coarse_cell(cell, factor, phase, 3)
    }
}
