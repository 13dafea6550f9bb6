//! A figure in the solver's form: cells numbered `0..n`, their points, an
//! adjacency list and a dense point grid for `O(1)` point lookup.

use crate::figure::Figure;
use crate::lattice::Point;

const NONE: u32 = u32::MAX;

/// Dense lookup from points to cell numbers over the points' bounding box.
#[derive(Clone, Debug)]
struct Grid {
    lo: Point,
    size: [i32; 3],
    slots: Vec<u32>,
}

impl Grid {
    fn build(points: &[Point]) -> Grid {
        let mut lo = [i32::MAX; 3];
        let mut hi = [i32::MIN; 3];
        for p in points {
            for d in 0..3 {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        let size = [hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1];
        let mut slots = vec![NONE; size.iter().map(|s| *s as usize).product()];
        for (i, p) in points.iter().enumerate() {
            let idx = ((p[2] - lo[2]) * size[1] + (p[1] - lo[1])) * size[0] + (p[0] - lo[0]);
            slots[idx as usize] = i as u32;
        }
        Grid { lo, size, slots }
    }

    #[inline]
    fn get(&self, p: Point) -> Option<u32> {
        let x = p[0].wrapping_sub(self.lo[0]);
        let y = p[1].wrapping_sub(self.lo[1]);
        let z = p[2].wrapping_sub(self.lo[2]);
        if (x as u32) >= self.size[0] as u32
            || (y as u32) >= self.size[1] as u32
            || (z as u32) >= self.size[2] as u32
        {
            return None;
        }
        let v = self.slots[((z * self.size[1] + y) * self.size[0] + x) as usize];
        (v != NONE).then_some(v)
    }
}

/// A figure with numbered cells.
///
/// # Validity
/// `points` are distinct; `nbr_start` has `n + 1` entries and
/// `nbrs[nbr_start[i]..nbr_start[i+1]]` are the numbers of the neighbours of
/// cell `i` inside the shape.
#[derive(Clone, Debug)]
pub(crate) struct Shape {
    points: Vec<Point>,
    nbr_start: Vec<u32>,
    nbrs: Vec<u32>,
    grid: Grid,
}

impl Shape {
    /// The shape of a figure; cell `i` is `figure.cells()[i]`.
    pub(crate) fn of_figure(figure: &Figure) -> Shape {
        let l = figure.lattice().lattice();
        let points: Vec<Point> = figure.cells().iter().map(|c| l.to_point(*c)).collect();
        let grid = Grid::build(&points);
        let mut nbr_start = Vec::with_capacity(points.len() + 1);
        let mut nbrs = Vec::new();
        nbr_start.push(0);
        for c in figure.cells() {
            for n in l.neighbors(*c) {
                if let Some(j) = grid.get(l.to_point(n)) {
                    nbrs.push(j);
                }
            }
            nbr_start.push(nbrs.len() as u32);
        }
        Shape {
            points,
            nbr_start,
            nbrs,
            grid,
        }
    }

    /// The sub-shape made of `cells` (new cell `i` is old cell `cells[i]`).
    pub(crate) fn subset(&self, cells: &[u32]) -> Shape {
        let points: Vec<Point> = cells.iter().map(|&c| self.points[c as usize]).collect();
        let grid = Grid::build(&points);
        let mut nbr_start = Vec::with_capacity(points.len() + 1);
        let mut nbrs = Vec::new();
        nbr_start.push(0);
        for &c in cells {
            for &n in self.neighbors(c) {
                if let Some(j) = grid.get(self.points[n as usize]) {
                    nbrs.push(j);
                }
            }
            nbr_start.push(nbrs.len() as u32);
        }
        Shape {
            points,
            nbr_start,
            nbrs,
            grid,
        }
    }

    /// The number of cells.
    pub(crate) fn len(&self) -> usize {
        self.points.len()
    }

    /// The point of cell `i`.
    #[inline]
    pub(crate) fn point(&self, i: u32) -> Point {
        self.points[i as usize]
    }

    /// The neighbours of cell `i` inside the shape.
    #[inline]
    pub(crate) fn neighbors(&self, i: u32) -> &[u32] {
        &self.nbrs[self.nbr_start[i as usize] as usize..self.nbr_start[i as usize + 1] as usize]
    }

    /// The cell at point `p`, if any.
    #[inline]
    pub(crate) fn lookup(&self, p: Point) -> Option<u32> {
        self.grid.get(p)
    }
}
