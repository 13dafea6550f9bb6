//! Connectivity as clauses: every cell of a piece is reached from the
//! piece's root within `D` steps through cells of the piece.
//!
//! `r[i][c][d]`: cell `c` of shape 0 is in piece `i` and is reached from the
//! root in at most `d` steps. `r[i][c][0]` only at the root; `r[i][c][d]`
//! needs `c` in the piece and `r[i][c][d-1]` or `r[i][n][d-1]` for a
//! neighbour `n`; every cell of the piece has `r[i][c][D]`. With `D` the
//! largest possible piece size this is exactly "piece `i` is connected".
//! The root is the piece's anchor cell when it has one (a cell of an
//! incompatible clique fixed to it), else its first cell.
//! Congruent copies of a connected piece are connected, so shape 0 is
//! enough.

use crate::instance::Shape;
use crate::sat_backend::Sat;

/// The (variables, clauses) [`add_connectivity`] adds for `k` pieces of a
/// shape of `n` cells with `edges` ordered neighbour pairs, from above.
pub(crate) fn connectivity_size(n: usize, k: usize, edges: usize) -> (u64, u64) {
    let depth = (n + 1).saturating_sub(k).max(1) as u64;
    let (n, k, e) = (n as u64, k as u64, edges as u64);
    let vars = k.saturating_mul(n.saturating_mul(depth + 3));
    let clauses = k.saturating_mul(
        n.saturating_mul(depth + 4)
            .saturating_add(e.saturating_mul(depth)),
    );
    (vars, clauses)
}

/// Adds "every piece is connected in `shape`" for the pieces whose cell
/// variables are `cell[i][c]`; `anchors[i]` is piece `i`'s root if known.
/// `false` when `interrupted` cut it short (the solver then holds part of
/// it, which is still implied by connectivity).
pub(crate) fn add_connectivity(
    sat: &mut Sat<'_>,
    shape: &Shape,
    cell: &[Vec<i32>],
    anchors: &[usize],
    interrupted: &dyn Fn() -> bool,
) -> bool {
    let n = shape.len();
    let k = cell.len();
    let depth = (n + 1).saturating_sub(k).max(1);
    for (i, x) in cell.iter().enumerate() {
        // Level 0: the root.
        let mut level: Vec<Option<i32>> = vec![None; n];
        if let Some(&root) = anchors.get(i) {
            let v = sat.var();
            sat.add(&[-v, x[root]]);
            level[root] = Some(v);
        } else {
            // prefix[c]: the piece has a cell among 0..=c.
            let mut before: Option<i32> = None;
            for c in 0..n {
                let v = sat.var();
                sat.add(&[-v, x[c]]);
                if let Some(b) = before {
                    sat.add(&[-v, -b]);
                }
                level[c] = Some(v);
                let p = sat.var();
                sat.add(&[-x[c], p]);
                if let Some(b) = before {
                    sat.add(&[-b, p]);
                }
                before = Some(p);
            }
        }
        for _ in 0..depth {
            if interrupted() {
                return false;
            }
            let mut next: Vec<Option<i32>> = vec![None; n];
            for c in 0..n {
                let mut support: Vec<i32> = Vec::new();
                if let Some(v) = level[c] {
                    support.push(v);
                }
                support.extend(shape.adj[c].iter().filter_map(|&m| level[m]));
                if support.is_empty() {
                    continue;
                }
                let v = sat.var();
                sat.add(&[-v, x[c]]);
                let mut clause = vec![-v];
                clause.extend(support);
                sat.add(&clause);
                next[c] = Some(v);
            }
            level = next;
        }
        for c in 0..n {
            match level[c] {
                Some(v) => sat.add(&[-x[c], v]),
                None => sat.add(&[-x[c]]),
            }
        }
    }
    true
}
