//! The corner/extent bound: two cells of one figure are *incompatible* when
//! no connected piece can hold both, because they lie in different components
//! of their figure or because no motion puts a path of the figure joining
//! them inside another figure. Pairwise incompatible cells need pairwise different
//! pieces, so a clique of the incompatibility graph is a lower bound.

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
                if interrupted() {
                    return None;
                }
                let images: Vec<Point> = s.points.iter().map(|p| g.apply(*p)).collect();
                let overlaps = Overlaps::of(inst, &images, &target.points, interrupted)?;
                for (i, cells) in overlaps.lists().enumerate() {
                    if i % 4096 == 4095 && interrupted() {
                        return None;
                    }
                    if cells.len() < 2 {
                        continue;
                    }
                    for &c in cells {
                        inside[c as usize] = true;
                    }
                    for &start in cells {
                        let start = start as usize;
                        if seen[start] {
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
                    for &c in cells {
                        inside[c as usize] = false;
                        seen[c as usize] = false;
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

    /// The graph on `n` cells where `apart(a, b)` (asked for `a < b`)
    /// says whether `a` and `b` can never share a piece.
    pub fn from_pairs(n: usize, apart: impl Fn(usize, usize) -> bool) -> Incompatibility {
        let words = n.div_ceil(64);
        let mut rows = vec![vec![0u64; words]; n];
        for a in 0..n {
            for b in a + 1..n {
                if apart(a, b) {
                    rows[a][b / 64] |= 1 << (b % 64);
                    rows[b][a / 64] |= 1 << (a % 64);
                }
            }
        }
        Incompatibility { n, rows }
    }

    /// The graph on `n` cells with no pair known apart (for figures too
    /// large for the full graph: the encoding then has no incompatibility
    /// clauses, a weaker relaxation, still sound).
    pub fn none(n: usize) -> Incompatibility {
        Incompatibility {
            n,
            rows: Vec::new(),
        }
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
        self.rows
            .get(a)
            .is_some_and(|r| r[b / 64] >> (b % 64) & 1 == 1)
    }

    /// A large clique (cell indices), found by branch and bound with greedy
    /// colouring; stops after `node_limit` nodes and then returns the best
    /// clique seen, which is still a valid bound. `interrupted` is asked
    /// every 64 nodes and ends the search the same way.
    pub fn clique(&self, node_limit: usize, interrupted: &dyn Fn() -> bool) -> Vec<usize> {
        if self.rows.is_empty() {
            // No pair known apart: any one cell.
            return if self.n > 0 { vec![0] } else { Vec::new() };
        }
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

/// For every lattice translation `t`, the cells `c` whose moved point
/// `images[c] + t` is a point of the target: the pairs grouped by
/// translation (counting sort over the box of translations), so a motion
/// costs one pass over the pairs that land rather than one lookup per cell
/// and translation.
struct Overlaps {
    /// `starts[i]..starts[i + 1]` indexes translation `i`'s cells.
    starts: Vec<u32>,
    cells: Vec<u32>,
}

impl Overlaps {
    /// `None` when `interrupted` says so (asked every 256 cells).
    fn of(
        inst: &Instance,
        images: &[Point],
        target: &[Point],
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Overlaps> {
        let (ilo, ihi) = bounds(images);
        let (tlo, thi) = bounds(target);
        let m = i64::from(inst.modulus);
        let mut lo = [0i64; 3];
        let mut size = [1usize; 3];
        let mut boxed = Some(1usize);
        for d in 0..inst.dim {
            lo[d] = (i64::from(tlo[d]) - i64::from(ihi[d])).div_euclid(m);
            let hi = (i64::from(thi[d]) - i64::from(ilo[d])).div_euclid(m);
            size[d] = usize::try_from(hi - lo[d] + 1).unwrap_or(usize::MAX);
            boxed = boxed.and_then(|b| b.checked_mul(size[d]));
        }
        let pairs = images.len().saturating_mul(target.len());
        match boxed {
            // The box of translations is small next to the pairs: a
            // counting sort over it.
            Some(b) if b <= pairs.saturating_mul(4).saturating_add(4096) => {
                let index = |t: Point| -> Option<usize> {
                    if !inst.is_translation(t) {
                        return None;
                    }
                    let mut i = 0usize;
                    for d in (0..inst.dim).rev() {
                        i = i * size[d] + (i64::from(t[d]) / m - lo[d]) as usize;
                    }
                    Some(i)
                };
                Self::counted(images, target, b, index, interrupted)
            }
            // Figures far apart: the box would be huge (memory), so the
            // pairs are sorted by translation instead.
            _ => Self::sorted(inst, images, target, interrupted),
        }
    }

    /// The pairs grouped by a counting sort over `boxed` translation
    /// indices (`index`).
    fn counted(
        images: &[Point],
        target: &[Point],
        boxed: usize,
        index: impl Fn(Point) -> Option<usize>,
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Overlaps> {
        let mut starts = vec![0u32; boxed + 1];
        for (c, gp) in images.iter().enumerate() {
            if c % 256 == 255 && interrupted() {
                return None;
            }
            for q in target {
                if let Some(i) = index(*q - *gp) {
                    starts[i + 1] += 1;
                }
            }
        }
        for i in 1..starts.len() {
            starts[i] += starts[i - 1];
        }
        let mut next = starts.clone();
        let mut cells = vec![0u32; starts[starts.len() - 1] as usize];
        for (c, gp) in images.iter().enumerate() {
            for q in target {
                if let Some(i) = index(*q - *gp) {
                    cells[next[i] as usize] = c as u32;
                    next[i] += 1;
                }
            }
        }
        Some(Overlaps { starts, cells })
    }

    /// The pairs grouped by sorting them by translation (memory in the
    /// pairs, whatever the figures' spread).
    fn sorted(
        inst: &Instance,
        images: &[Point],
        target: &[Point],
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Overlaps> {
        let mut pairs: Vec<(Point, u32)> = Vec::new();
        for (c, gp) in images.iter().enumerate() {
            if c % 256 == 255 && interrupted() {
                return None;
            }
            for q in target {
                let t = *q - *gp;
                if inst.is_translation(t) {
                    pairs.push((t, c as u32));
                }
            }
        }
        pairs.sort_unstable();
        let mut starts = vec![0u32];
        let mut cells = Vec::with_capacity(pairs.len());
        for (i, &(t, c)) in pairs.iter().enumerate() {
            if i > 0 && pairs[i - 1].0 != t {
                starts.push(cells.len() as u32);
            }
            cells.push(c);
        }
        starts.push(cells.len() as u32);
        Some(Overlaps { starts, cells })
    }

    /// Every translation's cells, in ascending order.
    fn lists(&self) -> impl Iterator<Item = &[u32]> {
        self.starts
            .windows(2)
            .map(|w| &self.cells[w[0] as usize..w[1] as usize])
    }
}

/// The smallest and largest coordinates of `points`.
fn bounds(points: &[Point]) -> ([i32; 3], [i32; 3]) {
    let mut lo = [i32::MAX; 3];
    let mut hi = [i32::MIN; 3];
    for p in points {
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::{Figure, LatticeKind};

    /// Figures whose cells lie far apart would need a huge box of
    /// translations: the pairs are sorted instead, and both ways give the
    /// same graph.
    #[test]
    fn far_apart_cells_give_the_same_graph_without_a_huge_box() {
        let far = 1 << 28;
        let cells = |v: &[[i32; 3]]| Figure::new(LatticeKind::Cubic, v.iter().copied()).unwrap();
        let a = cells(&[[0, 0, 0], [1, 0, 0], [far, far, far], [far, far, far + 1]]);
        let b = cells(&[[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]);
        let inst = Instance::new(&[a, b], true, 0);
        let g = Incompatibility::of_shape(&inst, 0, &|| false).expect("not interrupted");
        // The two far components are apart; each pair inside one is not.
        assert!(g.apart(0, 2) && g.apart(1, 3));
        assert!(!g.apart(0, 1) && !g.apart(2, 3));
        let images: Vec<Point> = inst.shapes[0].points.clone();
        let target = &inst.shapes[1].points;
        let sorted = Overlaps::sorted(&inst, &images, target, &|| false).unwrap();
        let near = &inst.shapes[1].points;
        let counted = Overlaps::of(&inst, near, target, &|| false).unwrap();
        let by_sort = Overlaps::sorted(&inst, near, target, &|| false).unwrap();
        let lists = |o: &Overlaps| -> Vec<Vec<u32>> {
            o.lists()
                .filter(|l| !l.is_empty())
                .map(<[u32]>::to_vec)
                .collect()
        };
        assert_eq!(lists(&counted), lists(&by_sort));
        assert!(!lists(&sorted).is_empty());
    }
}
