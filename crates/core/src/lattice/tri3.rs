//! The `tri3` lattice: equilateral triangles `[x, y, 0]` in rows, the
//! `x`-th triangle of row `y` pointing up when `x + y` is even.
//!
//! Points use the skew basis `a = (1, 0)`, `b = (1/2, √3/2)` of the
//! triangular lattice: a triangle's point is the sum of its three vertices
//! (three times its centroid), each vertex `i·a + j·b` counted as `(i, j)`.
//! Up triangles have points `≡ (2, 2)` and down triangles `≡ (1, 1)` modulo
//! 3; translations are lattice vectors, three times over, so the modulus is 3
//! and a translation never turns an up triangle into a down one. In this
//! basis the 60° rotation about a vertex is an integer matrix (see
//! [`hexagonal_symmetries`]). The same embedding as `shared/tools/verify.py`.

use super::{hexagonal_symmetries, Cell, Lattice, LatticeKind, Point, Symmetry};

/// The equilateral-triangle lattice.
#[derive(Clone, Copy, Debug, Default)]
pub struct Tri3;

/// Whether triangle `(x, y)` points up.
pub(crate) fn points_up(x: i32, y: i32) -> bool {
    (x + y).rem_euclid(2) == 0
}

impl Lattice for Tri3 {
    fn kind(&self) -> LatticeKind {
        LatticeKind::Tri3
    }
    fn dim(&self) -> usize {
        2
    }
    fn modulus(&self) -> i32 {
        3
    }
    fn is_cell(&self, cell: Cell) -> bool {
        cell[2] == 0
    }
    fn to_point(&self, [x, y, _]: Cell) -> Point {
        if points_up(x, y) {
            Point::new(3 * (x - y) / 2 - 1, 3 * y + 2, 0)
        } else {
            Point::new(3 * (x - y - 1) / 2 + 1, 3 * y + 1, 0)
        }
    }
    fn from_point(&self, p: Point) -> Option<Cell> {
        let [i, j, k] = p.coords();
        if k != 0 {
            return None;
        }
        match (i.rem_euclid(3), j.rem_euclid(3)) {
            (2, 2) => {
                let y = (j - 2) / 3;
                Some([2 * ((i + 1) / 3) + y, y, 0])
            }
            (1, 1) => {
                let y = (j - 1) / 3;
                Some([2 * ((i - 1) / 3) + y + 1, y, 0])
            }
            _ => None,
        }
    }
    fn neighbors(&self, [x, y, _]: Cell) -> Vec<Cell> {
        let across = if points_up(x, y) { y + 1 } else { y - 1 };
        vec![[x - 1, y, 0], [x + 1, y, 0], [x, across, 0]]
    }
    fn supports_mirror(&self) -> bool {
        true
    }
    fn symmetries(&self, mirror: bool) -> Vec<Symmetry> {
        hexagonal_symmetries(mirror)
    }
    /// Moves the top row to `y = 0` and the leftmost triangle to `x = 0`, or
    /// to `x = 1` when `x + y` must stay even.
    fn shift_to_origin(&self, cells: &[Cell]) -> Point {
        let Some(&first) = cells.first() else {
            return Point::ORIGIN;
        };
        let min_x = cells.iter().map(|c| c[0]).min().unwrap_or(0);
        let min_y = cells.iter().map(|c| c[1]).min().unwrap_or(0);
        let dy = -min_y;
        let mut dx = -min_x;
        if (dx + dy).rem_euclid(2) == 1 {
            dx += 1;
        }
        let from = self.to_point(first);
        let to = self.to_point([first[0] + dx, first[1] + dy, 0]);
        Point::new(to[0] - from[0], to[1] - from[1], 0)
    }
}
