//! The data of the motion player (`assets/player.js`): for every figure the
//! pieces' outlines (2D) or cubes (3D) in lattice units, the rigid motion in
//! the plane or in space that carries each piece from figure 0 to that
//! figure, and an assembly order (3D: the reverse of the disassembly plan
//! of `dissect_puzzle::disassembly` when the figure comes apart, so no
//! piece is placed where a hand could not put it; the figure's `level`
//! beside it, or the pieces that lock). A 3D figure that comes apart also
//! carries its plan's moves as the player plays them (`plan`: the pieces
//! of each move and their displacement, removals set down clear of
//! everything, [`played_moves`]): the player takes the first figure apart
//! by them, carries the pieces over, and puts the next figure together by
//! its plan in reverse. The player only interpolates these
//! motions; it derives no geometry of its own.
//!
//! The motions come from `dissect_core::motion` (a symmetry and a
//! translation of the lattice's points); here they are turned into maps of
//! the drawing's coordinates `x ↦ M·x + t` by fitting them to the centres of
//! the cells they move (exact, since a lattice's points are an affine image
//! of the cell centres).

use dissect_core::lattice::Point;
use dissect_core::motion::{assembly_order, motions};
use dissect_core::transform::Transform;
use dissect_core::{Cell, Lattice, LatticeKind};
use dissect_puzzle::disassembly::{disassemble, Disassembly, Limits, Plan};
use serde_json::{json, Value};
use std::collections::HashSet;

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

/// What the player knows of how one figure is taken apart and put
/// together.
#[derive(Clone, Debug, PartialEq)]
pub struct FigurePlan {
    /// An order in which a person can put the pieces together (3D: the
    /// reverse of the order in which the plan leaves each piece on its
    /// own).
    pub order: Vec<usize>,
    /// The disassembly level (`None`: no plan).
    pub level: Option<usize>,
    /// 3D figures that come apart: the plan's moves as the player plays
    /// them ([`played_moves`]); `None` otherwise.
    pub moves: Option<Vec<PlayedMove>>,
    /// The pieces that hold together when the figure cannot be taken apart
    /// by straight moves (`None`: it can, or it was not decided).
    pub locked: Option<Vec<usize>>,
}

/// The plan of one figure for the player. 3D: the disassembly plan of
/// `dissect_puzzle::disassembly` (at most [`PLAN_STATES`] positions), its
/// moves played by [`played_moves`] and its reverse as the assembly order;
/// a figure that does not come apart (or is not decided) gets
/// [`assembly_order`], no level and no moves. Flat figures:
/// [`assembly_order`], level 1, no moves (the pieces lift off).
pub fn figure_plan(lattice: LatticeKind, pieces: &[Vec<Cell>]) -> FigurePlan {
    let l = lattice.lattice();
    let limits = Limits {
        max_states: PLAN_STATES,
        ..Limits::default()
    };
    let stacked = || assembly_order(l, pieces);
    match disassemble(l, pieces, limits) {
        Ok(Disassembly::Apart(plan)) if l.dim() == 3 => FigurePlan {
            order: reverse_of_plan(&plan, pieces.len()),
            level: Some(plan.level),
            moves: Some(played_moves(lattice, pieces, &plan)),
            locked: None,
        },
        Ok(Disassembly::Apart(plan)) => FigurePlan {
            order: stacked(),
            level: Some(plan.level),
            moves: None,
            locked: None,
        },
        Ok(Disassembly::Locked(locked)) => FigurePlan {
            order: stacked(),
            level: None,
            moves: None,
            locked: Some(locked),
        },
        _ => FigurePlan {
            order: stacked(),
            level: None,
            moves: None,
            locked: None,
        },
    }
}

/// One move of a figure's disassembly as the player plays it.
#[derive(Clone, Debug, PartialEq)]
pub struct PlayedMove {
    /// The pieces that move together (indices of the dissection).
    pub pieces: Vec<usize>,
    /// Their displacement in the drawing's coordinates.
    pub by: Vec<f64>,
    /// Whether the plan takes the group out of its part here.
    pub removed: bool,
}

/// The moves of `plan` (a plan of the figure made of `pieces`) as the
/// player shows them, in the plan's order and groups. A move that is not a
/// removal goes exactly as far as the plan says. A removal, which the plan
/// sends to infinity, goes one step further than the plan's `by` (a gap
/// after its part) and on until the group, and the group one step further
/// still, meets no other piece of the figure: removed groups are set down
/// clear of everything, and the figure ends apart with no two pieces
/// overlapping.
pub fn played_moves(lattice: LatticeKind, pieces: &[Vec<Cell>], plan: &Plan) -> Vec<PlayedMove> {
    let l = lattice.lattice();
    let m = l.modulus();
    let mut at: Vec<Vec<Point>> = pieces
        .iter()
        .map(|p| p.iter().map(|c| l.to_point(*c)).collect())
        .collect();
    let mut out = Vec::with_capacity(plan.moves.len());
    for mv in &plan.moves {
        let axis = (0..3).find(|&a| mv.by[a] != 0).unwrap_or(0);
        let sign = mv.by[axis].signum();
        let unit = |k: i32| {
            let mut v = [0i32; 3];
            v[axis] = sign * k * m;
            Point::from(v)
        };
        let mut steps = mv.by[axis].abs();
        if mv.removed {
            let others: HashSet<Point> = (0..at.len())
                .filter(|i| !mv.pieces.contains(i))
                .flat_map(|i| at[i].iter().copied())
                .collect();
            let clear = |k: i32| {
                mv.pieces.iter().flat_map(|&i| &at[i]).all(|p| {
                    !others.contains(&(*p + unit(k))) && !others.contains(&(*p + unit(k + 1)))
                })
            };
            steps += 1;
            while !clear(steps) {
                steps += 1;
            }
        }
        let shift = unit(steps);
        for &i in &mv.pieces {
            for p in &mut at[i] {
                *p = *p + shift;
            }
        }
        let dim = l.dim();
        let by = mv
            .pieces
            .first()
            .and_then(|&i| pieces[i].first())
            .and_then(|&c| {
                let moved = l.from_point(l.to_point(c) + shift)?;
                let (a, b) = (centre(lattice, c), centre(lattice, moved));
                Some((0..dim).map(|j| clean(b[j] - a[j])).collect())
            })
            .unwrap_or_else(|| vec![0.0; dim]);
        out.push(PlayedMove {
            pieces: mv.pieces.clone(),
            by,
            removed: mv.removed,
        });
    }
    out
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
            let plan = figure_plan(lattice, &pieces[f]);
            let moves = plan.moves.as_ref().map(|moves| {
                moves
                    .iter()
                    .map(|m| json!({"pieces": m.pieces, "by": m.by, "removed": m.removed}))
                    .collect::<Vec<_>>()
            });
            json!({
                "name": scene.name(f),
                "min": lo,
                "max": hi,
                "order": plan.order,
                "level": plan.level,
                "locked": plan.locked,
                "plan": moves,
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
        let plan = figure_plan(LatticeKind::Cubic, &channel_block());
        let (order, level) = (plan.order, plan.level);
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
        let plan = figure_plan(LatticeKind::Cubic, &[ring_a, ring_b]);
        assert_eq!((plan.order.len(), plan.level), (2, None));
        assert_eq!((plan.moves, plan.locked), (None, Some(vec![0, 1])));
    }

    /// The block with a closed channel of `the_3d_order_is_the_plan_reversed`
    /// (B slides 2 along x, then leaves along y) and a loose cube on top.
    fn channel_block() -> Vec<Vec<Cell>> {
        let l = LatticeKind::Cubic.lattice();
        let b: Vec<Cell> = vec![[1, 1, 1], [2, 1, 1], [1, 1, 2]];
        let free = [[3, 1, 1], [4, 1, 1], [2, 1, 2], [3, 1, 2], [4, 1, 2]];
        let window = [[3, 2, 1], [4, 2, 1], [3, 2, 2], [4, 2, 2]];
        let a: Vec<Cell> = l
            .cells_in_box([0, 0, 0], [5, 2, 3])
            .into_iter()
            .filter(|c| !b.contains(c) && !free.contains(c) && !window.contains(c))
            .collect();
        vec![a, b, vec![[0, 0, 4]]]
    }

    /// Plays the player's moves on the cells (an integer grid: the drawing's
    /// unit is one cube) and checks each: along one axis by whole cubes;
    /// every unit step free of the other pieces of its part (a removal's
    /// sweep free of them for good) and, before a removal, of every piece;
    /// after every move no two pieces overlap; at the end every part holds
    /// one piece. Returns each piece's final offset.
    fn replay(pieces: &[Vec<Cell>], moves: &[PlayedMove]) -> Vec<[i32; 3]> {
        let n = pieces.len();
        let mut off = vec![[0i32; 3]; n];
        let mut part: Vec<usize> = vec![0; n];
        let cells = |i: usize, off: &[[i32; 3]], extra: [i32; 3]| -> HashSet<[i32; 3]> {
            pieces[i]
                .iter()
                .map(|c| [0, 1, 2].map(|j| c[j] + off[i][j] + extra[j]))
                .collect()
        };
        for (k, m) in moves.iter().enumerate() {
            let by: Vec<i32> = m.by.iter().map(|v| v.round() as i32).collect();
            assert!(m
                .by
                .iter()
                .zip(&by)
                .all(|(a, b)| (a - *b as f64).abs() < 1e-9));
            let axes: Vec<usize> = (0..3).filter(|&j| by[j] != 0).collect();
            assert_eq!(axes.len(), 1, "move {k}: {m:?}");
            let (axis, len) = (axes[0], by[axes[0]]);
            let owner = part[m.pieces[0]];
            assert!(m.pieces.iter().all(|&i| part[i] == owner), "move {k}");
            let same: Vec<usize> = (0..n)
                .filter(|i| part[*i] == owner && !m.pieces.contains(i))
                .collect();
            let reach = if m.removed { len.abs() + 40 } else { len.abs() };
            for step in 1..=reach {
                let mut d = [0; 3];
                d[axis] = step * len.signum();
                for &i in &m.pieces {
                    let moved = cells(i, &off, d);
                    for &o in &same {
                        assert!(
                            moved.is_disjoint(&cells(o, &off, [0; 3])),
                            "move {k} step {step}"
                        );
                    }
                }
            }
            for &i in &m.pieces {
                off[i][axis] += len;
            }
            if m.removed {
                let fresh = part.iter().max().unwrap_or(&0) + 1;
                for &i in &m.pieces {
                    part[i] = fresh;
                }
            }
            for i in 0..n {
                for j in i + 1..n {
                    let (a, b) = (cells(i, &off, [0; 3]), cells(j, &off, [0; 3]));
                    assert!(
                        a.is_disjoint(&b),
                        "after move {k}: pieces {i} and {j} overlap"
                    );
                }
            }
        }
        let mut parts = part.clone();
        parts.sort_unstable();
        parts.dedup();
        assert_eq!(parts.len(), n, "every part holds one piece at the end");
        off
    }

    #[test]
    fn the_player_plays_the_plan_in_its_order_and_groups() {
        let pieces = channel_block();
        let plan = figure_plan(LatticeKind::Cubic, &pieces);
        let moves = plan.moves.expect("the block comes apart");
        let limits = Limits::default();
        let Ok(Disassembly::Apart(want)) =
            disassemble(LatticeKind::Cubic.lattice(), &pieces, limits)
        else {
            panic!("the block comes apart");
        };
        // The same moves, groups and order as the plan; slides exactly as
        // long, removals at least as long.
        assert_eq!(moves.len(), want.moves.len());
        for (got, m) in moves.iter().zip(&want.moves) {
            assert_eq!((&got.pieces, got.removed), (&m.pieces, m.removed));
            for j in 0..3 {
                let (g, w) = (got.by[j], f64::from(m.by[j]));
                if m.removed {
                    assert!(g * w >= w * w && (w != 0.0 || g == 0.0), "{got:?} vs {m:?}");
                } else {
                    assert_eq!(g, w);
                }
            }
        }
        assert_eq!(plan.level, Some(want.level));
        replay(&pieces, &moves);
    }

    /// Golden data: the player's plan of a small figure (a 2x1x2 slab, an
    /// L lying on it, a cube in the L's corner) as `data` writes it.
    #[test]
    fn the_plan_in_the_player_data_is_golden() {
        let pieces: Vec<Vec<Cell>> = vec![
            vec![[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]],
            vec![[0, 0, 1], [1, 0, 1], [0, 1, 1]],
            vec![[1, 1, 1]],
        ];
        let plan = figure_plan(LatticeKind::Cubic, &pieces);
        let moves = plan.moves.clone().expect("apart");
        let json: Vec<Value> = moves
            .iter()
            .map(|m| json!({"pieces": m.pieces, "by": m.by, "removed": m.removed}))
            .collect();
        assert_eq!(serde_json::to_string(&json).unwrap(), GOLDEN_PLAN);
        assert_eq!(plan.level, Some(1));
        replay(&pieces, &moves);
    }

    /// The cube leaves first along +x (the plan's one step, one more as a
    /// gap), then the L along -x, clear of the cube set down.
    const GOLDEN_PLAN: &str = concat!(
        r#"[{"by":[2.0,0.0,0.0],"pieces":[2],"removed":true},"#,
        r#"{"by":[-3.0,0.0,0.0],"pieces":[1],"removed":true}]"#
    );

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
