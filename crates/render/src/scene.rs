//! The scene: what every exporter draws or builds. It holds, for every
//! figure of a dissection, the cells of every piece, and for 2D lattices the
//! merged outline of every piece and of the whole figure; pieces have a
//! label and a colour that are the same in every figure and every format.

use std::collections::{HashMap, HashSet, VecDeque};

use dissect_core::io::{parse_figure, parse_solution};
use dissect_core::Dissection;
use dissect_core::{Cell, LatticeKind};

use crate::colour::{piece_colour, Rgb};
use crate::outline::Outline;
use crate::RenderError;

/// A dissection ready to be drawn.
///
/// # Validity
/// At least one figure; every figure has the same number (at least one) of
/// non-empty pieces; for 2D lattices `outlines[f][i]` is the outline of
/// `pieces[f][i]` and `figure_outlines[f]` that of the whole figure. A scene
/// built by [`Scene::from_solution`] or [`Scene::verified`] is also a valid
/// dissection (checked by `dissect_core::verify`).
#[derive(Clone, Debug)]
pub struct Scene {
    lattice: LatticeKind,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Cell>>>,
    outlines: Vec<Vec<Outline>>,
    figure_outlines: Vec<Outline>,
    /// `ids[i]`: the number of piece `i` in the whole dissection (its label
    /// and colour); `0..n` except in a [`Scene::subset`].
    ids: Vec<usize>,
}

impl Scene {
    /// A scene of a dissection (not checked against any figure).
    pub fn new(d: &Dissection) -> Result<Scene, RenderError> {
        if d.pieces().is_empty() {
            return Err(RenderError::Mismatch("the solution has no figure".into()));
        }
        let n = d.pieces()[0].len();
        if n == 0 {
            return Err(RenderError::Mismatch("the solution has no piece".into()));
        }
        for (f, fp) in d.pieces().iter().enumerate() {
            if fp.len() != n {
                return Err(RenderError::Mismatch(format!(
                    "figure {} has {} pieces, figure 1 has {n}",
                    f + 1,
                    fp.len()
                )));
            }
            if let Some(i) = fp.iter().position(|p| p.is_empty()) {
                return Err(RenderError::Mismatch(format!(
                    "figure {} piece {} is empty",
                    f + 1,
                    i + 1
                )));
            }
        }
        let two_d = d.lattice() != LatticeKind::Cubic;
        let outlines = if two_d {
            d.pieces()
                .iter()
                .map(|fp| {
                    fp.iter()
                        .map(|p| Outline::of_cells(d.lattice(), p))
                        .collect()
                })
                .collect()
        } else {
            Vec::new()
        };
        let figure_outlines = if two_d {
            d.pieces()
                .iter()
                .map(|fp| Outline::of_cells(d.lattice(), &fp.concat()))
                .collect()
        } else {
            Vec::new()
        };
        let names = (0..d.pieces().len())
            .map(|f| {
                d.names()
                    .get(f)
                    .filter(|s| !s.is_empty())
                    .cloned()
                    .unwrap_or_else(|| format!("figure {}", f + 1))
            })
            .collect();
        Ok(Scene {
            lattice: d.lattice(),
            names,
            pieces: d.pieces().to_vec(),
            outlines,
            figure_outlines,
            ids: (0..n).collect(),
        })
    }

    /// A scene of a dissection that is checked by `dissect_core::verify`
    /// against the figures its own pieces make: pieces disjoint, connected
    /// and congruent across figures. So nothing that is not a dissection is
    /// ever drawn, even without the figure files.
    pub fn verified(d: &Dissection) -> Result<Scene, RenderError> {
        // The shape first (figures, pieces, counts), with its own messages.
        let scene = Scene::new(d)?;
        let figs = d
            .pieces()
            .iter()
            .map(|fp| {
                dissect_core::Figure::new(d.lattice(), fp.iter().flatten().copied())
                    .map_err(|e| RenderError::Invalid(e.to_string()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if let Err(v) = dissect_core::verify::verify(d, &figs) {
            return Err(RenderError::Invalid(v[0].to_string()));
        }
        Ok(scene)
    }

    /// A scene from a solution JSON text, which must be a valid dissection:
    /// of the figure texts when they are given (in the solution's order),
    /// else of the figures its own pieces make (see [`Scene::verified`]).
    pub fn from_solution(solution: &str, figures: &[&str]) -> Result<Scene, RenderError> {
        let (_, d) = parse_solution(solution)?;
        if figures.is_empty() {
            return Scene::verified(&d);
        }
        if figures.len() != d.pieces().len() {
            return Err(RenderError::Mismatch(format!(
                "the solution has {} figures, {} were given",
                d.pieces().len(),
                figures.len()
            )));
        }
        let figs = figures
            .iter()
            .enumerate()
            .map(|(index, t)| {
                parse_figure(t, d.lattice()).map_err(|error| RenderError::Figure { index, error })
            })
            .collect::<Result<Vec<_>, _>>()?;
        if let Err(v) = dissect_core::verify::verify(&d, &figs) {
            return Err(RenderError::Invalid(v[0].to_string()));
        }
        Scene::new(&d)
    }

    /// The lattice.
    pub fn lattice(&self) -> LatticeKind {
        self.lattice
    }

    /// The number of figures.
    pub fn figure_count(&self) -> usize {
        self.pieces.len()
    }

    /// The number of pieces (the same in every figure).
    pub fn piece_count(&self) -> usize {
        self.pieces[0].len()
    }

    /// The name of figure `f`.
    pub fn name(&self, f: usize) -> &str {
        &self.names[f]
    }

    /// The cells of piece `i` in figure `f`.
    pub fn cells(&self, f: usize, i: usize) -> &[Cell] {
        &self.pieces[f][i]
    }

    /// The merged outline of piece `i` in figure `f` (2D lattices; empty for `cubic`).
    pub fn outline(&self, f: usize, i: usize) -> Outline {
        self.outlines
            .get(f)
            .and_then(|o| o.get(i))
            .cloned()
            .unwrap_or_default()
    }

    /// The merged outline of figure `f` (2D lattices; empty for `cubic`).
    pub fn figure_outline(&self, f: usize) -> Outline {
        self.figure_outlines.get(f).cloned().unwrap_or_default()
    }

    /// The label of piece `i` (`A`, `B`, ...).
    pub fn label(&self, i: usize) -> String {
        dissect_core::ascii::piece_letter(self.ids[i]).to_string()
    }

    /// The colour of piece `i`.
    pub fn colour(&self, i: usize) -> Rgb {
        piece_colour(self.ids[i])
    }

    /// Figure `f` with only the pieces `pieces` (numbers of this scene, in
    /// the order given; at least one), which keep their labels and colours:
    /// a step of the figure's assembly.
    pub fn subset(&self, f: usize, pieces: &[usize]) -> Scene {
        let cells: Vec<Vec<Cell>> = pieces.iter().map(|&i| self.pieces[f][i].clone()).collect();
        let two_d = !self.outlines.is_empty();
        Scene {
            lattice: self.lattice,
            names: vec![self.names[f].clone()],
            outlines: if two_d {
                vec![pieces
                    .iter()
                    .map(|&i| self.outlines[f][i].clone())
                    .collect()]
            } else {
                Vec::new()
            },
            figure_outlines: if two_d {
                vec![Outline::of_cells(self.lattice, &cells.concat())]
            } else {
                Vec::new()
            },
            pieces: vec![cells],
            ids: pieces.iter().map(|&i| self.ids[i]).collect(),
        }
    }

    /// The number of cells of piece `i`.
    pub fn area(&self, i: usize) -> usize {
        self.pieces[0][i].len()
    }

    /// Where to write a 2D piece's label, in lattice units: the centre of
    /// its cell deepest inside the piece.
    pub fn label_point(&self, f: usize, i: usize) -> [f64; 2] {
        let cells = &self.pieces[f][i];
        let c = deepest_cell(self.lattice, cells);
        cell_centre(self.lattice, c)
    }
}

/// The centre of a 2D cell in lattice units (centroid for triangles), in the
/// plane of [`Outline`]'s points.
pub fn cell_centre(lattice: LatticeKind, [x, y, t]: Cell) -> [f64; 2] {
    let h = 3f64.sqrt() / 2.0;
    match lattice {
        LatticeKind::Tri3 => {
            let up = (x + y).rem_euclid(2) == 0;
            let dy = if up { 2.0 / 3.0 } else { 1.0 / 3.0 };
            return [(x as f64 + 1.0) / 2.0, (y as f64 + dy) * h];
        }
        LatticeKind::Hex => {
            return [x as f64 + y.rem_euclid(2) as f64 / 2.0, y as f64 * h];
        }
        _ => {}
    }
    let (x, y) = (x as f64, y as f64);
    if lattice == LatticeKind::Tri4 {
        let off = [
            [0.5, 1.0 / 6.0],
            [5.0 / 6.0, 0.5],
            [0.5, 5.0 / 6.0],
            [1.0 / 6.0, 0.5],
        ];
        let o = off[t.clamp(0, 3) as usize];
        [x + o[0], y + o[1]]
    } else {
        [x + 0.5, y + 0.5]
    }
}

/// The cell farthest (in adjacency steps) from the cells outside the set;
/// ties go to the smallest cell, so the choice is reproducible.
pub fn deepest_cell(lattice: LatticeKind, cells: &[Cell]) -> Cell {
    let l = lattice.lattice();
    let set: HashSet<Cell> = cells.iter().copied().collect();
    let mut dist: HashMap<Cell, u32> = HashMap::new();
    let mut queue = VecDeque::new();
    for &c in cells {
        if l.neighbors(c).iter().any(|n| !set.contains(n)) {
            dist.insert(c, 0);
            queue.push_back(c);
        }
    }
    while let Some(c) = queue.pop_front() {
        let d = dist[&c];
        for n in l.neighbors(c) {
            if set.contains(&n) && !dist.contains_key(&n) {
                dist.insert(n, d + 1);
                queue.push_back(n);
            }
        }
    }
    // Among the deepest cells, the one nearest the piece's centre.
    let n = cells.len() as f64;
    let centre = cells.iter().fold([0.0, 0.0, 0.0], |m, c| {
        let p = cell_centre(lattice, *c);
        [m[0] + p[0] / n, m[1] + p[1] / n, m[2] + c[2] as f64 / n]
    });
    let depth = |c: &Cell| dist.get(c).copied().unwrap_or(0);
    let deepest = cells.iter().map(depth).max().unwrap_or(0);
    let mut sorted: Vec<Cell> = cells
        .iter()
        .copied()
        .filter(|c| depth(c) == deepest)
        .collect();
    sorted.sort();
    let far = |c: &Cell| {
        let p = cell_centre(lattice, *c);
        let dz = if lattice == LatticeKind::Cubic {
            c[2] as f64 - centre[2]
        } else {
            0.0
        };
        (p[0] - centre[0]).powi(2) + (p[1] - centre[1]).powi(2) + dz * dz
    };
    *sorted
        .iter()
        .min_by(|a, b| far(a).total_cmp(&far(b)))
        .expect("a piece has cells")
}
