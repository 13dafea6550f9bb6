//! Lazy connectivity: clauses that forbid a split piece seen in a model.
//!
//! If a piece holds cells `c` and `d` of a shape, it also holds a cell of
//! every set separating `c` from `d` in that shape. For a split piece with
//! components `C` and `D`, the cells next to `C` (outside it) separate `C`
//! from `D`, so `¬x[j][c] ∨ ¬x[j][d] ∨ ⋁_{e ∈ ∂C} x[j][e]` holds for every
//! connected dissection and every piece `j`, and the model violates it.

use crate::instance::Shape;

/// A cut: `a` and `b` in one piece imply one of `separator` in it too.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Cut {
    pub shape: usize,
    pub a: usize,
    pub b: usize,
    pub separator: Vec<usize>,
}

/// Components of a set of cells (indices) of a shape.
pub(crate) fn components(shape: &Shape, cells: &[usize]) -> Vec<Vec<usize>> {
    let mut inside = vec![false; shape.len()];
    for &c in cells {
        inside[c] = true;
    }
    let mut seen = vec![false; shape.len()];
    let mut out = Vec::new();
    for &s in cells {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        let mut comp = vec![s];
        let mut i = 0;
        while i < comp.len() {
            let u = comp[i];
            i += 1;
            for &v in &shape.adj[u] {
                if inside[v] && !seen[v] {
                    seen[v] = true;
                    comp.push(v);
                }
            }
        }
        comp.sort_unstable();
        out.push(comp);
    }
    out
}

/// The cuts violated by the split pieces of `pieces` (`pieces[f][i]`: cell
/// indices of shape `f`), at most `per_piece` for each split piece.
pub(crate) fn cuts(shapes: &[Shape], pieces: &[Vec<Vec<usize>>], per_piece: usize) -> Vec<Cut> {
    let mut out = Vec::new();
    for (f, (shape, fp)) in shapes.iter().zip(pieces).enumerate() {
        for piece in fp {
            let comps = components(shape, piece);
            if comps.len() < 2 {
                continue;
            }
            let mut added = 0;
            'pairs: for (ci, c) in comps.iter().enumerate() {
                let mut in_c = vec![false; shape.len()];
                for &x in c {
                    in_c[x] = true;
                }
                let mut sep: Vec<usize> = c
                    .iter()
                    .flat_map(|&x| shape.adj[x].iter().copied())
                    .filter(|&y| !in_c[y])
                    .collect();
                sep.sort_unstable();
                sep.dedup();
                for (di, d) in comps.iter().enumerate() {
                    if di == ci {
                        continue;
                    }
                    out.push(Cut {
                        shape: f,
                        a: c[0],
                        b: d[0],
                        separator: sep.clone(),
                    });
                    added += 1;
                    if added >= per_piece {
                        break 'pairs;
                    }
                }
            }
        }
    }
    out
}
