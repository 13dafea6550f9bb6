//! The corner/extent bound: two cells of one figure are *incompatible* when
//! no connected piece can hold both, because they lie in different components
//! of their figure or because no motion puts a path of the figure joining
//! them inside another figure. Pairwise incompatible cells need pairwise different
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
    ///
    /// Cells `a` and `b` are compatible with shape `h` when some motion `m`
    /// puts both into `h` and joins them by a path of shape `k` that `m`
    /// keeps inside `h` (a connected piece holding both contains such a
    /// path). For every motion, the components of the cells it keeps inside
    /// are computed once and every pair within one is marked compatible.
    /// `None` when `interrupted` says so (it is asked once per motion).
    pub fn of_shape(
        inst: &Instance,
        k: usize,
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Incompatibility> {
        let s = &inst.shapes[k];
        let n = s.len();
        let words = n.div_ceil(64);
        let mut rows = vec![vec![0u64; words]; n];
        // Different components of the shape itself.
        for (a, (row, ca)) in rows.iter_mut().zip(&s.component).enumerate() {
            if a.is_multiple_of(256) && interrupted() {
                return None;
            }
            for (b, cb) in s.component.iter().enumerate() {
                if ca != cb {
                    row[b / 64] |= 1 << (b % 64);
                }
            }
        }
        let mut inside = vec![false; n];
        let mut seen = vec![false; n];
        let mut stack = Vec::new();
        for (h, target) in inst.shapes.iter().enumerate() {
            if h == k {
                continue;
            }
            let mut together = vec![vec![0u64; words]; n];
            for g in &inst.syms {
                let images: Vec<Point> = s.points.iter().map(|p| g.apply(*p)).collect();
                let mut shifts: HashSet<Point> = HashSet::new();
                for (c, gp) in images.iter().enumerate() {
                    if c.is_multiple_of(256) && interrupted() {
                        return None;
                    }
                    for q in &target.points {
                        let t = q - gp;
                        if inst.is_translation(t) {
                            shifts.insert(t);
                        }
                    }
                }
                let mut shifts: Vec<Point> = shifts.into_iter().collect();
                shifts.sort_unstable();
                for t in shifts {
                    if interrupted() {
                        return None;
                    }
                    for (c, gp) in images.iter().enumerate() {
                        inside[c] = target.index.contains_key(&(gp + t));
                        seen[c] = false;
                    }
                    for start in 0..n {
                        if !inside[start] || seen[start] {
                            continue;
                        }
                        seen[start] = true;
                        stack.clear();
                        stack.push(start);
                        let mut comp = vec![start];
                        while let Some(u) = stack.pop() {
                            for &v in &s.adj[u] {
                                if inside[v] && !seen[v] {
                                    seen[v] = true;
                                    stack.push(v);
                                    comp.push(v);
                                }
                            }
                        }
                        if comp.len() < 2 {
                            continue;
                        }
                        let mut mask = vec![0u64; words];
                        for &c in &comp {
                            mask[c / 64] |= 1 << (c % 64);
                        }
                        for &c in &comp {
                            for (w, m) in together[c].iter_mut().zip(&mask) {
                                *w |= m;
                            }
                        }
                    }
                }
            }
            for (row, tog) in rows.iter_mut().zip(&together) {
                for (w, t) in row.iter_mut().zip(tog) {
                    *w |= !t;
                }
            }
        }
        // Keep the graph irreflexive and within n bits.
        for (a, row) in rows.iter_mut().enumerate() {
            row[a / 64] &= !(1 << (a % 64));
            if !n.is_multiple_of(64) {
                row[words - 1] &= (1u64 << (n % 64)) - 1;
            }
        }
        Some(Incompatibility { n, rows })
    }

    /// The number of ordered pairs of incompatible cells.
    pub fn edges(&self) -> u64 {
        self.rows
            .iter()
            .flatten()
            .map(|w| u64::from(w.count_ones()))
            .sum()
    }

    /// Whether cells `a` and `b` can never share a piece.
    pub fn apart(&self, a: usize, b: usize) -> bool {
        self.rows[a][b / 64] >> (b % 64) & 1 == 1
    }

    /// A large clique (cell indices), found by branch and bound with greedy
    /// colouring; stops after `node_limit` nodes and then returns the best
    /// clique seen, which is still a valid bound. `interrupted` is asked
    /// every 64 nodes and ends the search the same way.
    pub fn clique(&self, node_limit: usize, interrupted: &dyn Fn() -> bool) -> Vec<usize> {
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
            if i.is_multiple_of(64) && interrupted() {
                return vec![order[0]];
            }
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
            interrupted,
        };
        search.expand(&mut Vec::new(), all);
        search.best.into_iter().map(|i| order[i]).collect()
    }
}

struct CliqueSearch<'a> {
    adj: Vec<Vec<u64>>,
    best: Vec<usize>,
    nodes: usize,
    limit: usize,
    interrupted: &'a dyn Fn() -> bool,
}

impl CliqueSearch<'_> {
    fn expand(&mut self, r: &mut Vec<usize>, mut p: Vec<u64>) {
        self.nodes += 1;
        if self.nodes.is_multiple_of(64) && (self.interrupted)() {
            // Unwinds the search: every caller sees the limit passed.
            self.nodes = self.limit.saturating_add(1);
        }
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
