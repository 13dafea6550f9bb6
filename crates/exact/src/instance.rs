//! The figures of one problem as integer points, with index maps and
//! adjacency, in the order the exact search uses (the reference figure
//! first).

use std::collections::HashMap;

use rustc_hash::FxHashMap;

use dissect_core::lattice::{Point, Symmetry};
use dissect_core::{Cell, Figure, LatticeKind};

/// One figure as points.
///
/// # Validity
/// `cells`, `points` and `adj` have one entry per cell, in the figure's
/// sorted cell order; `index` maps each point back to its position.
pub(crate) struct Shape {
    pub cells: Vec<Cell>,
    pub points: Vec<Point>,
    pub index: FxHashMap<Point, usize>,
    /// Neighbours inside the figure.
    pub adj: Vec<Vec<usize>>,
    /// The component id of each cell.
    pub component: Vec<usize>,
    pub components: usize,
}

impl Shape {
    fn new(lattice: LatticeKind, figure: &Figure) -> Shape {
        let l = lattice.lattice();
        let cells = figure.cells().to_vec();
        let points: Vec<Point> = cells.iter().map(|c| l.to_point(*c)).collect();
        let cell_index: HashMap<Cell, usize> =
            cells.iter().enumerate().map(|(i, c)| (*c, i)).collect();
        let index = points.iter().enumerate().map(|(i, p)| (*p, i)).collect();
        let adj: Vec<Vec<usize>> = cells
            .iter()
            .map(|c| {
                l.neighbors(*c)
                    .into_iter()
                    .filter_map(|n| cell_index.get(&n).copied())
                    .collect()
            })
            .collect();
        let mut component = vec![usize::MAX; cells.len()];
        let mut components = 0;
        for s in 0..cells.len() {
            if component[s] != usize::MAX {
                continue;
            }
            component[s] = components;
            let mut stack = vec![s];
            while let Some(u) = stack.pop() {
                for &v in &adj[u] {
                    if component[v] == usize::MAX {
                        component[v] = components;
                        stack.push(v);
                    }
                }
            }
            components += 1;
        }
        Shape {
            cells,
            points,
            index,
            adj,
            component,
            components,
        }
    }

    pub fn len(&self) -> usize {
        self.cells.len()
    }
}

/// The problem: shapes, the allowed symmetries and the translation lattice.
///
/// # Validity
/// At least two shapes of equal size on one lattice; `order[k]` is the input
/// position of shape `k`.
pub(crate) struct Instance {
    pub lattice: LatticeKind,
    pub mirror: bool,
    pub syms: Vec<Symmetry>,
    pub dim: usize,
    pub modulus: i32,
    pub shapes: Vec<Shape>,
    pub order: Vec<usize>,
    /// Whether the search may take the first piece's motion into a target
    /// up to the target's symmetries (false under constraints those
    /// symmetries would break).
    pub target_symmetries: bool,
    /// Whether the search may also take the first piece's motion into
    /// shape 1 up to the symmetries of shape 0 that fix its anchor and the
    /// anchored cells (`placement_encoding::orbit_representatives`); off
    /// unless the search asks (the enumeration does not).
    pub source_symmetries: bool,
}

impl Instance {
    /// The instance with `reference` moved to the front.
    pub fn new(figures: &[Figure], mirror: bool, reference: usize) -> Instance {
        let lattice = figures[0].lattice();
        let l = lattice.lattice();
        let mirror = mirror && l.supports_mirror();
        let mut order: Vec<usize> = (0..figures.len()).collect();
        order.remove(reference);
        order.insert(0, reference);
        Instance {
            lattice,
            mirror,
            syms: l.symmetries(mirror),
            dim: l.dim(),
            modulus: l.modulus(),
            shapes: order
                .iter()
                .map(|&i| Shape::new(lattice, &figures[i]))
                .collect(),
            order,
            target_symmetries: true,
            source_symmetries: false,
        }
    }

    /// Whether `t` is a lattice translation.
    pub fn is_translation(&self, t: Point) -> bool {
        (0..3).all(|k| {
            if k < self.dim {
                t[k].rem_euclid(self.modulus) == 0
            } else {
                t[k] == 0
            }
        })
    }

    /// The residue of a point modulo the translations.
    pub fn residue(&self, p: Point) -> Point {
        let mut r = p.coords();
        for v in r.iter_mut().take(self.dim) {
            *v = v.rem_euclid(self.modulus);
        }
        Point::from(r)
    }

    /// Pieces given per shape (`pieces[k]` for shape `k`) back in input order.
    pub fn to_input_order<T: Clone>(&self, per_shape: &[T]) -> Vec<T> {
        let mut out: Vec<Option<T>> = vec![None; per_shape.len()];
        for (k, &i) in self.order.iter().enumerate() {
            out[i] = Some(per_shape[k].clone());
        }
        out.into_iter().map(|v| v.expect("a permutation")).collect()
    }
}
