//! The data of the motion player (`assets/player.js`): for every figure the
//! pieces' outlines (2D) or cubes (3D) in lattice units, the rigid motion in
//! the plane or in space that carries each piece from figure 0 to that
//! figure, and an assembly order (3D: the reverse of the disassembly plan
//! of `dissect_puzzle::disassembly` when the figure comes apart, so no
//! piece is placed where a hand could not put it; the figure's `level`
//! beside it). The player only interpolates these
//! motions; it derives no geometry of its own.
//!
//! The motions come from `dissect_core::motion` (a symmetry and a
//! translation of the lattice's points); here they are turned into maps of
//! the drawing's coordinates `x ↦ M·x + t` by fitting them to the centres of
//! the cells they move (exact, since a lattice's points are an affine image
//! of the cell centres).

use dissect_core::motion::{assembly_order, motions};
use dissect_core::transform::Transform;
use dissect_core::{Cell, Lattice, LatticeKind};
use dissect_puzzle::disassembly::{disassemble, Disassembly, Limits, Plan};
use serde_json::{json, Value};

use crate::scene::cell_centre;
use crate::{RenderError, Scene};

/// A rigid map of the drawing's coordinates: `x ↦ matrix · x + shift`
/// (2 or 3 coordinates).
#[derive(Clone, Debug, PartialEq)]
pub struct RigidMap {
    /// Row-major, `dim × dim`, orthogonal.
    pub matrix: Vec<Vec<f64>>,
    /// The translation.
    pub shift: Vec<f64>,
}

impl RigidMap {
    /// The image of `x`.
    pub fn apply(&self, x: &[f64]) -> Vec<f64> {
        self.matrix
            .iter()
            .zip(&self.shift)
            .map(|(row, s)| row.iter().zip(x).map(|(a, b)| a * b).sum::<f64>() + s)
            .collect()
    }
}

/// The centre of a cell in the drawing's coordinates (lattice units; 2D in
/// image orientation, 3D `[x, y, z]` with z the layer).
pub fn centre(lattice: LatticeKind, cell: Cell) -> Vec<f64> {
    if lattice.lattice().dim() == 3 {
        cell.iter().map(|v| *v as f64 + 0.5).collect()
    } else {
        cell_centre(lattice, cell).to_vec()
    }
}

/// The rigid map of the drawing that the lattice motion `t` induces on the
/// cells `cells` (and around them), fitted by least squares to the centres
/// of those cells and of their neighbours and their images.
pub fn rigid_map(lattice: LatticeKind, t: &Transform, cells: &[Cell]) -> RigidMap {
    let l: &dyn Lattice = lattice.lattice();
    let dim = l.dim();
    let mut pairs: Vec<(Vec<f64>, Vec<f64>)> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for c in cells {
        for d in std::iter::once(*c).chain(l.neighbors(*c)) {
            if !seen.insert(d) {
                continue;
            }
            if let Some(image) = l.from_point(t.apply(l.to_point(d))) {
                pairs.push((centre(lattice, d), centre(lattice, image)));
            }
        }
    }
    let n = pairs.len().max(1) as f64;
    let mean = |k: usize| -> Vec<f64> {
        (0..dim)
            .map(|j| {
                pairs
                    .iter()
                    .map(|p| if k == 0 { p.0[j] } else { p.1[j] })
                    .sum::<f64>()
                    / n
            })
            .collect()
    };
    let (mx, my) = (mean(0), mean(1));
    // M = (Σ y xᵀ)(Σ x xᵀ)⁻¹ on centred points.
    let mut xx = vec![vec![0.0; dim]; dim];
    let mut yx = vec![vec![0.0; dim]; dim];
    for (x, y) in &pairs {
        for r in 0..dim {
            for c in 0..dim {
                xx[r][c] += (x[r] - mx[r]) * (x[c] - mx[c]);
                yx[r][c] += (y[r] - my[r]) * (x[c] - mx[c]);
            }
        }
    }
    let inv = invert(&xx).unwrap_or_else(|| identity(dim));
    let mut m = vec![vec![0.0; dim]; dim];
    for r in 0..dim {
        for c in 0..dim {
            m[r][c] = clean((0..dim).map(|k| yx[r][k] * inv[k][c]).sum());
        }
    }
    let shift = (0..dim)
        .map(|r| clean(my[r] - (0..dim).map(|c| m[r][c] * mx[c]).sum::<f64>()))
        .collect();
    RigidMap { matrix: m, shift }
}

fn identity(dim: usize) -> Vec<Vec<f64>> {
    (0..dim)
        .map(|r| (0..dim).map(|c| if r == c { 1.0 } else { 0.0 }).collect())
        .collect()
}

/// Rounds away the noise of the fit (entries are exact up to ~1e-12).
fn clean(v: f64) -> f64 {
    let r = (v * 1e9).round() / 1e9;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

/// Gauss-Jordan inverse of a small matrix; `None` when singular.
fn invert(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let mut m: Vec<Vec<f64>> = a.to_vec();
    let mut inv = identity(n);
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[pivot][col].abs() < 1e-9 {
            return None;
        }
        m.swap(col, pivot);
        inv.swap(col, pivot);
        let p = m[col][col];
        for c in 0..n {
            m[col][c] /= p;
            inv[col][c] /= p;
        }
        for r in 0..n {
            if r != col {
                let f = m[r][col];
                for c in 0..n {
                    m[r][c] -= f * m[col][c];
                    inv[r][c] -= f * inv[col][c];
                }
            }
        }
    }
    Some(inv)
}

/// The positions a disassembly may explore for the player's order (a count
/// of work: the same order on every machine).
pub const PLAN_STATES: usize = 20_000;

/// An order in which a person can put the pieces of one figure together,
/// and the figure's disassembly level. 3D: the reverse of the order in which
/// the disassembly plan leaves each piece on its own; a figure that does
/// not come apart (or is not decided within [`PLAN_STATES`]) gets
/// [`assembly_order`] and no level. Flat figures: [`assembly_order`],
/// level 1.
pub fn assembly_plan_order(
    lattice: &dyn Lattice,
    pieces: &[Vec<Cell>],
) -> (Vec<usize>, Option<usize>) {
    let limits = Limits {
        max_states: PLAN_STATES,
        ..Limits::default()
    };
    match disassemble(lattice, pieces, limits) {
        Ok(Disassembly::Apart(plan)) if lattice.dim() == 3 => {
            (reverse_of_plan(&plan, pieces.len()), Some(plan.level))
        }
        Ok(Disassembly::Apart(plan)) => (assembly_order(lattice, pieces), Some(plan.level)),
        _ => (assembly_order(lattice, pieces), None),
    }
}

/// The pieces in the reverse of the order the plan leaves them alone in a
/// part of their own.
fn reverse_of_plan(plan: &Plan, n: usize) -> Vec<usize> {
    let mut part = vec![0usize; n];
    let mut parts = 1;
    let mut alone: Vec<usize> = Vec::with_capacity(n);
    for m in plan.moves.iter().filter(|m| m.removed) {
        let Some(&first) = m.pieces.first() else {
            continue;
        };
        let old = part[first];
        for &i in &m.pieces {
            part[i] = parts;
        }
        for p in [parts, old] {
            let members: Vec<usize> = (0..n).filter(|&i| part[i] == p).collect();
            if let [i] = members[..] {
                if !alone.contains(&i) {
                    alone.push(i);
                }
            }
        }
        parts += 1;
    }
    alone.extend((0..n).filter(|i| !alone.contains(i)).collect::<Vec<_>>());
    alone.reverse();
    alone
}

/// The player's data of a scene as a JSON value (format
/// `dissect-animation/1`; see `assets/player.js`).
pub fn data(scene: &Scene) -> Result<Value, RenderError> {
    let lattice = scene.lattice();
    let l = lattice.lattice();
    let dim = l.dim();
    let figures = scene.figure_count();
    let n = scene.piece_count();
    let pieces: Vec<Vec<Vec<Cell>>> = (0..figures)
        .map(|f| (0..n).map(|i| scene.cells(f, i).to_vec()).collect())
        .collect();
    let moves = motions(l, &pieces).map_err(|e| RenderError::Invalid(e.to_string()))?;
    let piece_info: Vec<Value> = (0..n)
        .map(|i| {
            json!({
                "label": scene.label(i),
                "colour": scene.colour(i).to_string(),
                "area": scene.area(i),
            })
        })
        .collect();
    let figure_info: Vec<Value> = (0..figures)
        .map(|f| {
            let mut lo = vec![f64::INFINITY; dim];
            let mut hi = vec![f64::NEG_INFINITY; dim];
            let ps: Vec<Value> = (0..n)
                .map(|i| {
                    let cells = scene.cells(f, i);
                    let map = rigid_map(lattice, &moves[f][i], scene.cells(0, i));
                    let centres: Vec<Vec<f64>> =
                        cells.iter().map(|c| centre(lattice, *c)).collect();
                    let mid: Vec<f64> = (0..dim)
                        .map(|j| centres.iter().map(|c| c[j]).sum::<f64>() / cells.len() as f64)
                        .collect();
                    let mut v = json!({
                        "centre": mid,
                        "matrix": map.matrix,
                        "shift": map.shift,
                    });
                    if dim == 3 {
                        for c in cells {
                            for j in 0..3 {
                                lo[j] = lo[j].min(c[j] as f64);
                                hi[j] = hi[j].max(c[j] as f64 + 1.0);
                            }
                        }
                        v["cubes"] = json!(cells.iter().map(|c| c.to_vec()).collect::<Vec<_>>());
                    } else {
                        let outline = scene.outline(f, i);
                        let rings: Vec<Vec<[f64; 2]>> =
                            outline.loops().iter().map(|lp| lp.points_f64()).collect();
                        for p in rings.iter().flatten() {
                            for j in 0..2 {
                                lo[j] = lo[j].min(p[j]);
                                hi[j] = hi[j].max(p[j]);
                            }
                        }
                        v["rings"] = json!(rings);
                        v["label_at"] = json!(scene.label_point(f, i));
                    }
                    v
                })
                .collect();
            let (order, level) = assembly_plan_order(l, &pieces[f]);
            json!({
                "name": scene.name(f),
                "min": lo,
                "max": hi,
                "order": order,
                "level": level,
                "pieces": ps,
            })
        })
        .collect();
    Ok(json!({
        "format": "dissect-animation/1",
        "lattice": lattice.name(),
        "dim": dim,
        "pieces": piece_info,
        "figures": figure_info,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::motion::piece_motion;

    fn maps_cells(lattice: LatticeKind, a: &[Cell], b: &[Cell]) {
        let t = piece_motion(lattice.lattice(), a, b).expect("congruent");
        let m = rigid_map(lattice, &t, a);
        let mut got: Vec<Vec<i64>> = a
            .iter()
            .map(|c| {
                m.apply(&centre(lattice, *c))
                    .iter()
                    .map(|v| (v * 6.0).round() as i64)
                    .collect()
            })
            .collect();
        let mut want: Vec<Vec<i64>> = b
            .iter()
            .map(|c| {
                centre(lattice, *c)
                    .iter()
                    .map(|v| (v * 6.0).round() as i64)
                    .collect()
            })
            .collect();
        got.sort();
        want.sort();
        assert_eq!(got, want, "{lattice}");
        // Orthogonal: M Mᵀ = I.
        let dim = m.matrix.len();
        for r in 0..dim {
            for c in 0..dim {
                let v: f64 = (0..dim).map(|k| m.matrix[r][k] * m.matrix[c][k]).sum();
                assert!((v - if r == c { 1.0 } else { 0.0 }).abs() < 1e-9);
            }
        }
    }

    /// A block with a closed channel and a window (B slides 2 along x, then
    /// leaves along y): the block goes first, then B.
    #[test]
    fn the_3d_order_is_the_plan_reversed() {
        let l = LatticeKind::Cubic.lattice();
        let b: Vec<Cell> = vec![[1, 1, 1], [2, 1, 1], [1, 1, 2]];
        let free = [[3, 1, 1], [4, 1, 1], [2, 1, 2], [3, 1, 2], [4, 1, 2]];
        let window = [[3, 2, 1], [4, 2, 1], [3, 2, 2], [4, 2, 2]];
        let a: Vec<Cell> = l
            .cells_in_box([0, 0, 0], [5, 2, 3])
            .into_iter()
            .filter(|c| !b.contains(c) && !free.contains(c) && !window.contains(c))
            .collect();
        // A loose cube on top of the block's far end, taken off first.
        let c: Vec<Cell> = vec![[0, 0, 4]];
        let (order, level) = assembly_plan_order(l, &[a, b, c]);
        assert_eq!(level, Some(1));
        assert_eq!(order.len(), 3);
        let at = |i: usize| order.iter().position(|&p| p == i).unwrap();
        assert!(at(0) < at(1), "{order:?}");
        // Two linked rings: no plan, the stacking order and no level.
        let ring_a: Vec<Cell> = [
            [0, 1],
            [1, 1],
            [2, 1],
            [0, 2],
            [2, 2],
            [0, 3],
            [1, 3],
            [2, 3],
        ]
        .map(|[x, y]| [x, y, 1])
        .to_vec();
        let ring_b: Vec<Cell> = [
            [2, 0],
            [3, 0],
            [4, 0],
            [2, 1],
            [4, 1],
            [2, 2],
            [3, 2],
            [4, 2],
        ]
        .map(|[y, z]| [1, y, z])
        .to_vec();
        let (order, level) = assembly_plan_order(l, &[ring_a, ring_b]);
        assert_eq!((order.len(), level), (2, None));
    }

    #[test]
    fn the_drawing_map_moves_every_cell_centre_onto_its_partner() {
        maps_cells(
            LatticeKind::Square,
            &[[0, 0, 0], [0, 1, 0], [0, 2, 0], [1, 2, 0]],
            &[[4, 4, 0], [5, 4, 0], [6, 4, 0], [4, 5, 0]],
        );
        // A flip: an S into a Z.
        maps_cells(
            LatticeKind::Square,
            &[[1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0]],
            &[[0, 0, 0], [1, 0, 0], [1, 1, 0], [2, 1, 0]],
        );
        // A single triangle turned a quarter.
        maps_cells(LatticeKind::Tri4, &[[0, 0, 0]], &[[3, 1, 1]]);
        maps_cells(
            LatticeKind::Cubic,
            &[[0, 0, 0], [1, 0, 0], [0, 0, 1]],
            &[[5, 5, 5], [5, 6, 5], [5, 5, 6]],
        );
    }
}
