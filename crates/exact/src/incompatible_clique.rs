//! The corner/extent bound: two cells of one figure are *incompatible* when
//! no connected piece can hold both, because they lie in different components
//! of their figure or because no motion puts both inside one component of
//! another figure. Pairwise incompatible cells need pairwise different
//! pieces, so a clique of the incompatibility graph is a lower bound.

use std::collections::HashSet;

use dissect_core::lattice::Point;

use crate::instance::Instance;

/// The incompatibility graph of one shape, as bit rows.
///
/// # Validity
/// Symmetric and irreflexive; `rows[a]` has `n.div_ceil(64)` words.
pub(crate) struct Incompatibility {
    n: usize,
    rows: Vec<Vec<u64>>,
}

impl Incompatibility {
    /// The graph of shape `k` against every other shape.
    pub fn of_shape(inst: &Instance, k: usize) -> Incompatibility {
        let s = &inst.shapes[k];
        let n = s.len();
        let words = n.div_ceil(64);
        // For each other shape: the (residue of q, q' - q) of pairs inside one component.
        let fits: Vec<HashSet<(Point, Point)>> = inst
            .shapes
            .iter()
            .enumerate()
            .filter(|(h, _)| *h != k)
            .map(|(_, t)| {
                let mut set = HashSet::with_capacity(t.len() * t.len());
                for (i, q) in t.points.iter().enumerate() {
                    let r = inst.residue(*q);
                    for (j, q2) in t.points.iter().enumerate() {
                        if t.component[i] == t.component[j] {
                            set.insert((r, [q2[0] - q[0], q2[1] - q[1], q2[2] - q[2]]));
                        }
                    }
                }
                set
            })
            .collect();
        let mut rows = vec![vec![0u64; words]; n];
        for a in 0..n {
            for b in a + 1..n {
                let apart = s.component[a] != s.component[b] || {
                    let (p, p2) = (s.points[a], s.points[b]);
                    let d = [p2[0] - p[0], p2[1] - p[1], p2[2] - p[2]];
                    fits.iter().any(|set| {
                        !inst
                            .syms
                            .iter()
                            .any(|g| set.contains(&(inst.residue(g.apply(p)), g.apply(d))))
                    })
                };
                if apart {
                    rows[a][b / 64] |= 1 << (b % 64);
                    rows[b][a / 64] |= 1 << (a % 64);
                }
            }
        }
        Incompatibility { n, rows }
    }

    /// Whether cells `a` and `b` can never share a piece.
    pub fn apart(&self, a: usize, b: usize) -> bool {
        self.rows[a][b / 64] >> (b % 64) & 1 == 1
    }

    /// A large clique (cell indices), found by branch and bound with greedy
    /// colouring; stops after `node_limit` nodes and then returns the best
    /// clique seen, which is still a valid bound.
    pub fn clique(&self, node_limit: usize) -> Vec<usize> {
        // Relabel by degree, largest first: colouring bounds get tighter.
        let deg: Vec<usize> = self
            .rows
            .iter()
            .map(|r| r.iter().map(|w| w.count_ones() as usize).sum())
            .collect();
        let mut order: Vec<usize> = (0..self.n).filter(|&v| deg[v] > 0).collect();
        if order.is_empty() {
            return if self.n > 0 { vec![0] } else { Vec::new() };
        }
        order.sort_by_key(|&v| (std::cmp::Reverse(deg[v]), v));
        let m = order.len();
        let w = m.div_ceil(64);
        let mut adj = vec![vec![0u64; w]; m];
        for (i, &u) in order.iter().enumerate() {
            for (j, &v) in order.iter().enumerate() {
                if self.apart(u, v) {
                    adj[i][j / 64] |= 1 << (j % 64);
                }
            }
        }
        let mut all = vec![0u64; w];
        for i in 0..m {
            all[i / 64] |= 1 << (i % 64);
        }
        let mut search = CliqueSearch {
            adj,
            best: Vec::new(),
            nodes: 0,
            limit: node_limit,
        };
        search.expand(&mut Vec::new(), all);
        search.best.into_iter().map(|i| order[i]).collect()
    }
}

struct CliqueSearch {
    adj: Vec<Vec<u64>>,
    best: Vec<usize>,
    nodes: usize,
    limit: usize,
}

impl CliqueSearch {
    fn expand(&mut self, r: &mut Vec<usize>, mut p: Vec<u64>) {
        self.nodes += 1;
        // Greedy colouring of p, in index order.
        let mut order: Vec<(usize, usize)> = Vec::new();
        let mut uncolored = p.clone();
        let mut color = 0;
        while uncolored.iter().any(|w| *w != 0) {
            color += 1;
            let mut q = uncolored.clone();
            while let Some(v) = first(&q) {
                q[v / 64] &= !(1 << (v % 64));
                for (qw, aw) in q.iter_mut().zip(&self.adj[v]) {
                    *qw &= !aw;
                }
                uncolored[v / 64] &= !(1 << (v % 64));
                order.push((v, color));
            }
        }
        for &(v, c) in order.iter().rev() {
            if r.len() + c <= self.best.len() || self.nodes > self.limit {
                return;
            }
            r.push(v);
            let np: Vec<u64> = p.iter().zip(&self.adj[v]).map(|(a, b)| a & b).collect();
            if np.iter().all(|w| *w == 0) {
                if r.len() > self.best.len() {
                    self.best = r.clone();
                }
            } else {
                self.expand(r, np);
            }
            r.pop();
            p[v / 64] &= !(1 << (v % 64));
        }
    }
}

fn first(bits: &[u64]) -> Option<usize> {
    bits.iter()
        .enumerate()
        .find(|(_, w)| **w != 0)
        .map(|(i, w)| i * 64 + w.trailing_zeros() as usize)
}
