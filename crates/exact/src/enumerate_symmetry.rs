//! Symmetry breaking for [`crate::enumerate`]: lex-leader constraints that
//! keep one member of each class of models the enumeration would otherwise
//! visit many times.
//!
//! * **The first figure's symmetries** (the classes `enumerate` counts):
//!   for every adjacent pair of cells `e` of the first figure, `same[e]`
//!   holds when both are in one piece. The pieces of a dissection are
//!   connected, so this vector determines the cut; a symmetry σ of the
//!   figure permutes its positions. Asking `same ≤lex same∘σ` for every σ
//!   (false < true) keeps exactly the lex-least cut of each class, so the
//!   SAT solver finds each class once and proves completeness over a
//!   search space shrunk by up to the group's order; the other members are
//!   the representative's images (counted and verified by the caller).
//! * **Each component of another figure** (the three squares of Loyd's
//!   6², 3², 2²): a symmetry of one component moves what lies in it and
//!   leaves the rest, and maps an assembly of the same labelled pieces onto
//!   another (the pieces lying in the component are moved by an allowed
//!   motion). Asking the component's one-hot labels (`cell[f][i][c]`,
//!   cell-major) to be lex-least under its symmetries keeps one assembly
//!   of each such class; the cut of the first figure is untouched, so no
//!   dissection is lost. This is done only where the encoding did not
//!   already take the first piece's motion up to the whole figure's
//!   symmetries (a figure with no symmetry, as Loyd's target), since the
//!   two reductions together could remove every assembly of a cut.
//!
//! Symmetries of different components act on disjoint cells (a direct
//! product), so each component's lex-least form can be had independently
//! and together with the first figure's.

use std::collections::HashMap;

use dissect_core::transform::Transform;
use dissect_core::Cell;
use dissect_puzzle::Motions;

use crate::instance::Instance;
use crate::motion::{self_symmetries, MotionSet};
use crate::placement_encoding::Encoding;
use crate::sat_backend::Sat;

/// Asks `x ≤lex y` (false < true, position 0 most significant); positions
/// holding the same literal are skipped. `eq` is true while the prefix so
/// far is equal (it may be set true spuriously; that only adds
/// constraints, and a lex-leader assignment with `eq` set exactly satisfies
/// every clause).
pub(crate) fn lex_leq(sat: &mut Sat<'_>, x: &[i32], y: &[i32]) {
    let pairs: Vec<(i32, i32)> = x
        .iter()
        .zip(y)
        .filter(|(a, b)| a != b)
        .map(|(&a, &b)| (a, b))
        .collect();
    let mut eq: Option<i32> = None; // None: true (the empty prefix)
    for (j, &(a, b)) in pairs.iter().enumerate() {
        let guard = |clause: &[i32]| {
            let mut c = clause.to_vec();
            if let Some(e) = eq {
                c.push(-e);
            }
            c
        };
        // While equal so far: a → b.
        let c = guard(&[-a, b]);
        sat.add(&c);
        if j + 1 == pairs.len() {
            break;
        }
        // Equal so far and a = b → equal so far at the next position.
        let next = sat.var();
        let c = guard(&[-a, -b, next]);
        sat.add(&c);
        let c = guard(&[a, b, next]);
        sat.add(&c);
        eq = Some(next);
    }
}

/// The permutation of `cells` (by index in `index`) that `t` induces, or
/// `None` when a cell leaves the set (never for a symmetry of it).
fn permutation(
    motions: &Motions,
    t: &Transform,
    cells: &[Cell],
    index: &HashMap<Cell, usize>,
) -> Option<Vec<usize>> {
    cells
        .iter()
        .map(|&c| motions.move_cell(t, c).and_then(|d| index.get(&d).copied()))
        .collect()
}

/// The lex-leader constraints on the first figure's cut under
/// `symmetries` (its symmetries, the identity among them).
fn break_first_figure(
    sat: &mut Sat<'_>,
    inst: &Instance,
    enc: &Encoding,
    motions: &Motions,
    symmetries: &[Transform],
) {
    let shape = &inst.shapes[0];
    let index: HashMap<Cell, usize> = shape
        .cells
        .iter()
        .enumerate()
        .map(|(i, c)| (*c, i))
        .collect();
    let mut edges: Vec<(usize, usize)> = Vec::new();
    for (a, adj) in shape.adj.iter().enumerate() {
        edges.extend(adj.iter().filter(|&&b| a < b).map(|&b| (a, b)));
    }
    let edge_index: HashMap<(usize, usize), usize> =
        edges.iter().enumerate().map(|(i, e)| (*e, i)).collect();
    let perms: Vec<Vec<usize>> = symmetries
        .iter()
        .filter_map(|t| permutation(motions, t, &shape.cells, &index))
        .filter(|p| p.iter().enumerate().any(|(i, &j)| i != j))
        .collect();
    if perms.is_empty() {
        return;
    }
    let cell = &enc.cell[0];
    // same[e] ↔ some piece holds both ends.
    let same: Vec<i32> = edges
        .iter()
        .map(|&(a, b)| {
            let s = sat.var();
            for piece in cell {
                sat.add(&[-piece[a], -piece[b], s]);
                sat.add(&[-s, -piece[a], piece[b]]);
                sat.add(&[-s, -piece[b], piece[a]]);
            }
            s
        })
        .collect();
    for p in &perms {
        let image: Option<Vec<i32>> = edges
            .iter()
            .map(|&(a, b)| {
                let (x, y) = (p[a].min(p[b]), p[a].max(p[b]));
                edge_index.get(&(x, y)).map(|&e| same[e])
            })
            .collect();
        if let Some(image) = image {
            lex_leq(sat, &same, &image);
        }
    }
}

/// The lex-leader constraints on the labels of each component of shape
/// `f` under the component's symmetries.
fn break_components(
    sat: &mut Sat<'_>,
    inst: &Instance,
    enc: &Encoding,
    motions: &Motions,
    f: usize,
) {
    let shape = &inst.shapes[f];
    let index: HashMap<Cell, usize> = shape
        .cells
        .iter()
        .enumerate()
        .map(|(i, c)| (*c, i))
        .collect();
    for comp in 0..shape.components {
        let members: Vec<usize> = (0..shape.len())
            .filter(|&c| shape.component[c] == comp)
            .collect();
        if members.len() < 2 {
            continue;
        }
        let cells: Vec<Cell> = members.iter().map(|&c| shape.cells[c]).collect();
        let labels = |order: &[usize]| -> Vec<i32> {
            order
                .iter()
                .flat_map(|&c| enc.cell[f].iter().map(move |piece| piece[c]))
                .collect()
        };
        let own = labels(&members);
        for t in motions.symmetries_of(&cells) {
            let Some(p) = permutation(motions, &t, &cells, &index) else {
                continue;
            };
            if p == members {
                continue;
            }
            lex_leq(sat, &own, &labels(&p));
        }
    }
}

/// Adds both kinds of lex-leader constraints (see the module's doc) for
/// an enumeration whose first figure has `symmetries`.
pub(crate) fn break_symmetries(
    sat: &mut Sat<'_>,
    inst: &Instance,
    enc: &Encoding,
    motions: &Motions,
    symmetries: &[Transform],
) {
    break_first_figure(sat, inst, enc, motions, symmetries);
    for f in 1..inst.shapes.len() {
        // The encoding took piece 0's motion into f up to f's symmetries
        // when it has any (see `placement_encoding::motions_of_shape`).
        let whole = self_symmetries(inst, f)
            .into_iter()
            .filter(|&h| MotionSet::All.admits(h, inst.syms[h].determinant()))
            .filter(|&h| inst.target_symmetries || h == 0)
            .count();
        if whole <= 1 {
            break_components(sat, inst, enc, motions, f);
        }
    }
}
