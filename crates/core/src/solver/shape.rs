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
        Grid {
            lo: Point::from(lo),
            size,
            slots,
        }
    }

    /// The slot of point `p` in the box, if inside.
    #[inline]
    fn slot(&self, p: Point) -> Option<usize> {
        let x = p[0].wrapping_sub(self.lo[0]);
        let y = p[1].wrapping_sub(self.lo[1]);
        let z = p[2].wrapping_sub(self.lo[2]);
        if (x as u32) >= self.size[0] as u32
            || (y as u32) >= self.size[1] as u32
            || (z as u32) >= self.size[2] as u32
        {
            return None;
        }
        Some(((z * self.size[1] + y) * self.size[0] + x) as usize)
    }

    #[inline]
    fn get(&self, p: Point) -> Option<u32> {
        let v = self.slots[self.slot(p)?];
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

    /// Every cell's point under every symmetry, as a linear address:
    /// entry `s * len() + c` addresses `syms[s] · point(c)`.
    pub(crate) fn moved(&self, syms: &[crate::lattice::Symmetry], layout: &Layout) -> Vec<i64> {
        syms.iter()
            .flat_map(|g| self.points.iter().map(move |p| layout.linear(g.apply(*p))))
            .collect()
    }

    /// The connected components of the cells marked in `marked`, each
    /// found from one of `starts` (which must include every marked cell);
    /// clears the marks of every cell it reaches.
    pub(crate) fn count_marked(
        &self,
        starts: impl IntoIterator<Item = u32>,
        marked: &mut [bool],
    ) -> usize {
        let mut count = 0;
        let mut stack = Vec::new();
        for c in starts {
            if !marked[c as usize] {
                continue;
            }
            count += 1;
            marked[c as usize] = false;
            stack.push(c);
            while let Some(u) = stack.pop() {
                for &w in self.neighbors(u) {
                    if marked[w as usize] {
                        marked[w as usize] = false;
                        stack.push(w);
                    }
                }
            }
        }
        count
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

    /// The smallest and largest point coordinates.
    pub(crate) fn point_box(&self) -> (Point, Point) {
        let mut lo = [i32::MAX; 3];
        let mut hi = [i32::MIN; 3];
        for p in &self.points {
            for d in 0..3 {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        (Point::from(lo), Point::from(hi))
    }
}

/// A linear addressing of points shared by all shapes of a problem, with
/// every shape's box padded so that any piece of any shape, moved onto a
/// piece of this shape by centroid alignment, lands inside the padded box.
/// The distance's inner loop then costs one add and one load per cell.
#[derive(Clone, Debug)]
pub(crate) struct Layout {
    stride: [i64; 3],
    len: usize,
    /// Per shape: the linear index of its padded box's low corner.
    origin: Vec<i64>,
    /// Per shape: the grid slot of each cell.
    slots: Vec<Vec<usize>>,
}

thread_local! {
    /// Zeroed label grids for reuse, so a grid costs O(cells), not O(box).
    static GRID_POOL: std::cell::RefCell<Vec<Vec<u16>>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// A shape's labels by address (see [`Layout::label_grid`]).
///
/// # Validity
/// Only the slots of the shape's cells are non-zero; they are zeroed again on
/// drop and the buffer goes back to a per-thread pool.
pub(crate) struct LabelGrid<'a> {
    grid: Vec<u16>,
    slots: &'a [usize],
}

impl std::ops::Deref for LabelGrid<'_> {
    type Target = [u16];
    fn deref(&self) -> &[u16] {
        &self.grid
    }
}

impl Drop for LabelGrid<'_> {
    fn drop(&mut self) {
        for &s in self.slots {
            self.grid[s] = 0;
        }
        let grid = std::mem::take(&mut self.grid);
        GRID_POOL.with(|p| p.borrow_mut().push(grid));
    }
}

impl Layout {
    /// The layout for these shapes; translations are multiples of `modulus`
    /// in the first `dim` coordinates, and no symmetry moves a coordinate
    /// by more than `spread` times the largest coordinate of a point (1 for
    /// signed permutations, 2 for the skew 60° rotation of `tri3`/`hex`).
    pub(crate) fn new(shapes: &[Shape], dim: usize, modulus: i32, spread: i32) -> Layout {
        let boxes: Vec<(Point, Point)> = shapes.iter().map(|s| s.point_box()).collect();
        let mut ext = [0i64; 3];
        for (lo, hi) in &boxes {
            for d in 0..3 {
                ext[d] = ext[d].max((hi[d] - lo[d]) as i64);
            }
        }
        // Rotations mix the translated axes, so each of them gets room for
        // the largest extent of any axis (times the spread: a skew rotation
        // adds two coordinates), plus the rounding of the centroid offset;
        // axes that translations never move need none.
        let reach =
            ext[..dim].iter().copied().max().unwrap_or(0) * spread as i64 + modulus as i64 + 2;
        let pad: Vec<i64> = (0..3).map(|d| if d < dim { reach } else { 0 }).collect();
        let mut size = [1i64; 3];
        for (lo, hi) in &boxes {
            for d in 0..3 {
                size[d] = size[d].max((hi[d] - lo[d]) as i64 + 1 + 2 * pad[d]);
            }
        }
        let stride = [1, size[0], size[0] * size[1]];
        let origin: Vec<i64> = boxes
            .iter()
            .map(|(lo, _)| (0..3).map(|d| (lo[d] as i64 - pad[d]) * stride[d]).sum())
            .collect();
        let linear = |p: &Point| (0..3).map(|d| p[d] as i64 * stride[d]).sum::<i64>();
        let slots = shapes
            .iter()
            .zip(&origin)
            .map(|(s, o)| s.points.iter().map(|p| (linear(p) - o) as usize).collect())
            .collect();
        Layout {
            stride,
            len: (size[0] * size[1] * size[2]) as usize,
            origin,
            slots,
        }
    }

    /// The linear address of a point (or of a translation).
    #[inline]
    pub(crate) fn linear(&self, p: Point) -> i64 {
        p[0] as i64 * self.stride[0] + p[1] as i64 * self.stride[1] + p[2] as i64 * self.stride[2]
    }

    /// The linear address of shape `f`'s padded box.
    pub(crate) fn origin(&self, f: usize) -> i64 {
        self.origin[f]
    }

    /// Labels of shape `f` by address: `label + 1` on its cells, 0 elsewhere.
    pub(crate) fn label_grid<'a>(&'a self, f: usize, labels: &[u16]) -> LabelGrid<'a> {
        let mut grid = GRID_POOL.with(|p| p.borrow_mut().pop()).unwrap_or_default();
        grid.resize(self.len, 0);
        let slots = &self.slots[f];
        for (&slot, &l) in slots.iter().zip(labels) {
            grid[slot] = l.wrapping_add(1);
        }
        LabelGrid { grid, slots }
    }
}
