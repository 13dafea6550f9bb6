//! Figures: finite, non-empty sets of cells of one lattice.

use std::collections::BTreeSet;

use rustc_hash::FxHashMap;

use crate::lattice::{Cell, LatticeKind};

/// A figure: a non-empty set of cells on one lattice.
///
/// # Validity
/// `cells` is sorted, free of duplicates, non-empty, and every cell is a
/// valid cell of `lattice`. The constructor enforces this.
#[derive(Clone, PartialEq, Eq)]
pub struct Figure {
    lattice: LatticeKind,
    cells: Vec<Cell>,
}

/// Occurs when cells do not make a valid figure.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum FigureError {
    /// Occurs when a figure has no cell.
    #[error("empty figure")]
    Empty,
    /// Occurs when a cell is not of the lattice's form (e.g. `t` outside `0..4` on `tri4`).
    #[error("{cell:?} is not a cell of the {lattice} lattice")]
    BadCell {
        /// The offending cell.
        cell: Cell,
        /// The lattice.
        lattice: LatticeKind,
    },
}

/// What `dissect info` reports about a figure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FigureStats {
    /// The number of cells (the figure's area or volume).
    pub cells: usize,
    /// The number of connected components.
    pub components: usize,
    /// The number of holes (bounded components of the complement; cavities in 3D).
    pub holes: usize,
    /// The smallest block coordinates `[x, y, z]`.
    pub min: [i32; 3],
    /// The largest block coordinates `[x, y, z]`.
    pub max: [i32; 3],
}

impl Figure {
    /// A figure from its cells (any order; duplicates are merged).
    pub fn new(
        lattice: LatticeKind,
        cells: impl IntoIterator<Item = Cell>,
    ) -> Result<Figure, FigureError> {
        let l = lattice.lattice();
        let set: BTreeSet<Cell> = cells.into_iter().collect();
        if let Some(&cell) = set.iter().find(|c| !l.is_cell(**c)) {
            return Err(FigureError::BadCell { cell, lattice });
        }
        if set.is_empty() {
            return Err(FigureError::Empty);
        }
        Ok(Figure {
            lattice,
            cells: set.into_iter().collect(),
        })
    }

    /// The lattice.
    pub fn lattice(&self) -> LatticeKind {
        self.lattice
    }

    /// The cells, sorted.
    pub fn cells(&self) -> &[Cell] {
        &self.cells
    }

    /// The number of cells.
    pub fn len(&self) -> usize {
        self.cells.len()
    }

    /// Always false: figures are non-empty.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The figure moved by a lattice translation so that its blocks start at
    /// `[0, 0, 0]`, or as near as the lattice allows (on `tri3`, `x` may
    /// start at 1, since a translation keeps `x + y` even): the placement
    /// the figure text format writes.
    pub fn to_origin(&self) -> Figure {
        let l = self.lattice.lattice();
        let shift = l.shift_to_origin(&self.cells);
        let cells = crate::lattice::translate_cells(l, &self.cells, shift);
        Figure::new(self.lattice, cells).expect("a translated figure is a figure")
    }

    /// Whether `cell` belongs to the figure.
    pub fn contains(&self, cell: Cell) -> bool {
        self.cells.binary_search(&cell).is_ok()
    }

    /// The connected components, each sorted.
    pub fn components(&self) -> Vec<Vec<Cell>> {
        components_of(self.lattice, &self.cells)
    }

    /// The bounding box in blocks ([`Lattice::block`](crate::lattice::Lattice::block)):
    /// the smallest and the largest block coordinates.
    pub fn bounds(&self) -> ([i32; 3], [i32; 3]) {
        let l = self.lattice.lattice();
        let mut min = [i32::MAX; 3];
        let mut max = [i32::MIN; 3];
        for &c in &self.cells {
            let b = l.block(c);
            for i in 0..3 {
                min[i] = min[i].min(b[i]);
                max[i] = max[i].max(b[i]);
            }
        }
        (min, max)
    }

    /// Cell count, components, holes and bounding box.
    pub fn stats(&self) -> FigureStats {
        let (min, max) = self.bounds();
        FigureStats {
            cells: self.cells.len(),
            components: self.components().len(),
            holes: self.holes(min, max),
            min,
            max,
        }
    }

    /// Bounded components of the complement inside the bounding box grown by one.
    fn holes(&self, min: [i32; 3], max: [i32; 3]) -> usize {
        let l = self.lattice.lattice();
        let three_d = l.dim() == 3;
        let lo = [min[0] - 1, min[1] - 1, if three_d { min[2] - 1 } else { 0 }];
        let hi = [max[0] + 1, max[1] + 1, if three_d { max[2] + 1 } else { 0 }];
        let mut boxed = l.cells_in_box(lo, hi);
        boxed.sort_unstable();
        // Both lists are sorted: the empty cells are a merge away.
        let mut inside = self.cells.iter().peekable();
        let empty: Vec<Cell> = boxed
            .into_iter()
            .filter(|c| {
                while inside.next_if(|f| *f < c).is_some() {}
                inside.peek() != Some(&c)
            })
            .collect();
        let on_border = |c: &Cell| {
            let b = l.block(*c);
            (0..l.dim()).any(|i| b[i] == lo[i] || b[i] == hi[i])
        };
        components_of(self.lattice, &empty)
            .iter()
            .filter(|comp| !comp.iter().any(on_border))
            .count()
    }
}

impl std::fmt::Debug for Figure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "Figure({}, {} cells)", self.lattice, self.cells.len())?;
        f.write_str(&crate::io::format_figure(self))
    }
}

/// Connected components of a set of cells under the lattice's adjacency.
pub fn components_of(lattice: LatticeKind, cells: &[Cell]) -> Vec<Vec<Cell>> {
    let l = lattice.lattice();
    if cells.windows(2).all(|w| w[0] < w[1]) {
        // Sorted (a figure's cells): a neighbour lies near its cell in the
        // list, so a galloping search from the cell finds it without a
        // hash table (4M cells of `tri4` in about a second).
        components_with(l, cells, |i, n| find_near(cells, i, n))
    } else {
        let index: FxHashMap<Cell, usize> =
            cells.iter().enumerate().map(|(i, c)| (*c, i)).collect();
        components_with(l, cells, |_, n| index.get(n).copied())
    }
}

/// The index of `target` in the sorted `cells`, searched outwards from `from`.
fn find_near(cells: &[Cell], from: usize, target: &Cell) -> Option<usize> {
    let (lo, hi) = if *target > cells[from] {
        let mut step = 1;
        let mut lo = from;
        while from + step < cells.len() && cells[from + step] < *target {
            lo = from + step;
            step *= 2;
        }
        (lo, (from + step).min(cells.len() - 1))
    } else {
        let mut step = 1;
        let mut hi = from;
        while step <= from && cells[from - step] > *target {
            hi = from - step;
            step *= 2;
        }
        (from.saturating_sub(step), hi)
    };
    cells[lo..=hi].binary_search(target).ok().map(|i| lo + i)
}

fn components_with(
    l: &dyn crate::lattice::Lattice,
    cells: &[Cell],
    find: impl Fn(usize, &Cell) -> Option<usize>,
) -> Vec<Vec<Cell>> {
    let mut seen = vec![false; cells.len()];
    let mut out = Vec::new();
    for start in 0..cells.len() {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut stack = vec![start];
        let mut comp = Vec::new();
        while let Some(i) = stack.pop() {
            comp.push(cells[i]);
            for n in l.neighbors(cells[i]) {
                if let Some(j) = find(i, &n) {
                    if !seen[j] {
                        seen[j] = true;
                        stack.push(j);
                    }
                }
            }
        }
        comp.sort_unstable();
        out.push(comp);
    }
    out
}
