//! The designer's constraints ([`dissect_puzzle::Constraints`]) as clauses
//! on top of the placement encoding:
//!
//! * keep-whole regions: every two cells of a region are in the same piece
//!   (`cell[f][i][a] ↔ cell[f][i][b]` for every piece `i`);
//! * piece sizes: a sequential counter over the cells of each piece in
//!   shape 0 (the pieces are congruent in every shape), at most
//!   `--max-piece` true, and at least `--min-piece` unless the piece is
//!   empty;
//! * checkerboard: a motion may carry a cell of a piece only onto a cell of
//!   the same colour (`¬motion ∨ ¬cell` for every cell it would recolour;
//!   one unit clause when it recolours every cell).
//!
//! Keep regions and the checkerboard are not invariant under the target
//! figures' symmetries, so the search that adds these clauses also drops
//! that symmetry breaking ([`needs_all_target_motions`]).

use std::collections::HashMap;

use dissect_core::Cell;
use dissect_puzzle::constraints::colour;
use dissect_puzzle::Constraints;

use crate::instance::Instance;
use crate::placement_encoding::Encoding;
use crate::sat_backend::Sat;

/// Whether the constraints would be broken by moving a target figure's
/// dissection by one of the figure's symmetries.
pub(crate) fn needs_all_target_motions(c: &Constraints) -> bool {
    !c.keep().is_empty() || c.checkerboard()
}

/// Adds the clauses of `c` to the encoding `enc` of `inst`.
pub(crate) fn add(inst: &Instance, sat: &mut Sat<'_>, enc: &Encoding, c: &Constraints) {
    keep_regions(inst, sat, enc, c);
    sizes(sat, enc, c);
    if c.checkerboard() {
        checkerboard(inst, sat, enc);
    }
}

fn keep_regions(inst: &Instance, sat: &mut Sat<'_>, enc: &Encoding, c: &Constraints) {
    for keep in c.keep() {
        let Some(shape) = inst.order.iter().position(|&i| i == keep.figure()) else {
            continue;
        };
        let index: HashMap<Cell, usize> = inst.shapes[shape]
            .cells
            .iter()
            .enumerate()
            .map(|(i, c)| (*c, i))
            .collect();
        for (_, cells) in keep.regions() {
            let idx: Vec<usize> = cells.iter().filter_map(|c| index.get(c).copied()).collect();
            for w in idx.windows(2) {
                for piece in &enc.cell[shape] {
                    let (x, y) = (piece[w[0]], piece[w[1]]);
                    sat.add(&[-x, y]);
                    sat.add(&[x, -y]);
                }
            }
        }
    }
}

fn sizes(sat: &mut Sat<'_>, enc: &Encoding, c: &Constraints) {
    let (min, max) = (c.min_piece(), c.max_piece());
    if min.is_none() && max.is_none() {
        return;
    }
    for piece in &enc.cell[0] {
        let n = piece.len();
        // A bound the piece's cells cannot reach is no constraint (a
        // maximum of `n` or more), and a minimum above `n` leaves the piece
        // empty: the counter never counts past `n`, whatever the bounds
        // (a maximum of `usize::MAX` once asked for that many variables).
        let max = max.filter(|&m| m < n);
        let min = min.filter(|&m| m >= 2);
        if min.is_some_and(|m| m > n) {
            for &x in piece {
                sat.add(&[-x]);
            }
            continue;
        }
        // Count up to the largest threshold needed (at most n).
        let top = max.map_or(0, |m| m + 1).max(min.unwrap_or(0));
        if top == 0 {
            continue;
        }
        // s[c - 1] after cell j: at least c of cells 0..=j are in the piece
        // (both ways, so the counts are exact).
        let mut prev: Vec<i32> = Vec::new();
        for &x in piece {
            let cur: Vec<i32> = (0..top).map(|_| sat.var()).collect();
            for (c, &s) in cur.iter().enumerate() {
                let before = prev.get(c).copied();
                let below = if c == 0 {
                    None
                } else {
                    prev.get(c - 1).copied()
                };
                // before → s; (x ∧ below) → s (below is true for c = 0).
                if let Some(b) = before {
                    sat.add(&[-b, s]);
                }
                match (c, below) {
                    (0, _) => sat.add(&[-x, s]),
                    (_, Some(b)) => sat.add(&[-x, -b, s]),
                    _ => {}
                }
                // s → before ∨ x; s → before ∨ below.
                let mut a = vec![-s, x];
                let mut b = vec![-s];
                if let Some(v) = before {
                    a.push(v);
                    b.push(v);
                }
                sat.add(&a);
                if c > 0 {
                    if let Some(v) = below {
                        b.push(v);
                    }
                    sat.add(&b);
                }
            }
            prev = cur;
        }
        if prev.is_empty() {
            continue;
        }
        if let Some(m) = max {
            sat.add(&[-prev[m]]);
        }
        if let Some(m) = min {
            // Non-empty (at least 1) → at least m.
            sat.add(&[-prev[0], prev[m - 1]]);
        }
    }
}

fn checkerboard(inst: &Instance, sat: &mut Sat<'_>, enc: &Encoding) {
    let from = &inst.shapes[0];
    for (f, per_piece) in enc.motion.iter().enumerate().skip(1) {
        let target = &inst.shapes[f];
        for (i, vars) in per_piece.iter().enumerate() {
            for &(mv, m) in vars {
                let mut recoloured = Vec::new();
                let mut mapped = 0;
                for (a, p) in from.points.iter().enumerate() {
                    if let Some(&b) = target.index.get(&m.transform.apply(*p)) {
                        mapped += 1;
                        if colour(inst.lattice, from.cells[a])
                            != colour(inst.lattice, target.cells[b])
                        {
                            recoloured.push(a);
                        }
                    }
                }
                if !recoloured.is_empty() && recoloured.len() == mapped {
                    sat.add(&[-mv]);
                } else {
                    for a in recoloured {
                        sat.add(&[-mv, -enc.cell[0][i][a]]);
                    }
                }
            }
        }
    }
}
