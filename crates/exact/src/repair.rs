//! Exact local repair of a near miss (a large neighbourhood search).
//!
//! A candidate labels every cell of every figure with one of `k` pieces, and
//! the labels nearly match: a few cells disagree, a piece may be split. The
//! repair keeps every label far from the trouble and lets SAT relabel the
//! rest:
//!
//! 1. For each piece, its best motion from the pivot figure (figure 0) into
//!    each other figure: the one under which most of its cells land on cells
//!    of the same label.
//! 2. Trouble: a cell whose partner under its piece's best motion is missing
//!    or labelled otherwise, and every cell of a piece's smaller components.
//! 3. Free: the cells within BFS distance `r` of trouble, closed under the
//!    best motions (a free cell's partners are free too); all other cells
//!    keep their label as a constant.
//! 4. SAT over the free cells only: one variable per free cell and piece it
//!    can reach (a piece that has fixed cells in a figure can only take free
//!    cells of the free components it touches), the motions of each piece
//!    that carry its fixed cells onto cells it may hold, image clauses both
//!    ways, local connectivity, and lazy connectivity cuts until every piece
//!    is connected.
//! 5. UNSAT: grow `r` and retry, until the free region would exceed its cap
//!    or the conflict budget is spent.
//!
//! Work is counted in SAT conflicts, never in time, so the same input gives
//! the same answer on every machine unless the stop flag or the deadline
//! ends it first. Every dissection returned has passed
//! `dissect_core::verify`.

use rustc_hash::FxHashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use dissect_core::lattice::Point;
use dissect_core::transform::Transform;
use dissect_core::{Cell, Figure};

use crate::connectivity_cut::components;
use crate::instance::Instance;
use crate::sat_backend::Sat;
use crate::ExactError;

/// Settings of [`repair`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RepairOptions {
    /// Whether 2D pieces may be turned over (ignored on `cubic`).
    pub mirror: bool,
    /// SAT conflicts the repair may spend in all, counting each solve
    /// after a connectivity cut as one more (its deterministic measure of
    /// work).
    pub budget: u64,
    /// The most cells (over all figures) the repair may free.
    pub max_free_cells: usize,
    /// Give up at this instant (the answer then depends on the machine).
    pub deadline: Option<Instant>,
    /// The most motions tried for one piece into one figure.
    pub max_motions: usize,
}

impl Default for RepairOptions {
    fn default() -> RepairOptions {
        RepairOptions {
            mirror: true,
            budget: 5_000,
            max_free_cells: 800,
            deadline: None,
            max_motions: 48,
        }
    }
}

/// What one [`repair_report`] did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RepairReport {
    /// The verified dissection (`pieces[f][i]`, input order), if any.
    pub found: Option<Vec<Vec<Vec<Cell>>>>,
    /// Trouble cells found in the candidate (all figures).
    pub trouble: usize,
    /// Free cells in the last neighbourhood tried (all figures).
    pub free: usize,
    /// Neighbourhoods tried.
    pub rounds: usize,
    /// SAT conflicts spent.
    pub conflicts: u64,
    /// Connectivity cuts added.
    pub cuts: usize,
    /// Whether the stop flag or the deadline ended it.
    pub stopped: bool,
}

/// Repairs the near-miss candidate `pieces[f][i]` (the cells of label `i`
/// in figure `f`; every figure partitioned into the same number `k` of
/// labels) into a verified dissection of at most `k` connected pieces that
/// keeps the candidate's labels away from its mismatches, or `None` when no
/// neighbourhood within the limits of `options` holds one (or on `stop`).
///
/// # Errors
/// [`ExactError::Figures`] for figures that are no dissection problem,
/// [`ExactError::Candidate`] for a candidate that does not partition them.
pub fn repair(
    figures: &[Figure],
    pieces: &[Vec<Vec<Cell>>],
    options: &RepairOptions,
    stop: &AtomicBool,
) -> Result<Option<Vec<Vec<Vec<Cell>>>>, ExactError> {
    Ok(repair_report(figures, pieces, options, stop)?.found)
}

/// [`repair`], with what it did.
///
/// # Errors
/// As [`repair`].
pub fn repair_report(
    figures: &[Figure],
    pieces: &[Vec<Vec<Cell>>],
    options: &RepairOptions,
    stop: &AtomicBool,
) -> Result<RepairReport, ExactError> {
    dissect_core::solver::check_figures(figures)?;
    let inst = Instance::new(figures, options.mirror, 0);
    let label = labels(&inst, pieces)?;
    let k = pieces[0].len();
    let mut report = RepairReport {
        found: None,
        trouble: 0,
        free: 0,
        rounds: 0,
        conflicts: 0,
        cuts: 0,
        stopped: false,
    };
    let interrupted =
        || stop.load(Ordering::Relaxed) || options.deadline.is_some_and(|d| Instant::now() >= d);
    let Some(cand) = Candidate::new(&inst, label, k, &interrupted) else {
        report.stopped = true;
        return Ok(report);
    };
    report.trouble = cand.trouble.iter().flatten().filter(|t| **t).count();
    if report.trouble == 0 {
        // Already a dissection (every piece matches and is connected).
        let found = to_cells(&inst, &cand.label, k);
        if dissect_core::verify::verify_pieces(inst.lattice, inst.mirror, figures, &found).is_ok() {
            report.found = Some(found);
        }
        return Ok(report);
    }
    let mut radius = 1;
    let mut last_free = 0;
    loop {
        if interrupted() {
            report.stopped = true;
            return Ok(report);
        }
        let free = cand.free_within(radius);
        let count: usize = free.iter().flatten().filter(|x| **x).count();
        if count > options.max_free_cells || count == last_free {
            return Ok(report);
        }
        last_free = count;
        report.free = count;
        report.rounds += 1;
        let left = options.budget.saturating_sub(report.conflicts);
        if left == 0 {
            return Ok(report);
        }
        let mut sat = Sat::new(stop, None);
        let outcome = Round::new(&cand, free, options, &mut sat, &interrupted).map(|mut round| {
            let o = round.solve(&mut sat, left, options.deadline);
            report.cuts += round.cuts;
            o
        });
        report.conflicts += sat.conflicts();
        match outcome {
            None | Some(Outcome::Unknown) => {
                report.stopped = interrupted();
                return Ok(report);
            }
            Some(Outcome::Unsat) => {}
            Some(Outcome::Found(label)) => {
                let found = to_cells(&inst, &label, k);
                dissect_core::verify::verify_pieces(inst.lattice, inst.mirror, figures, &found)
                    .map_err(|v| ExactError::InvalidModel(v[0].to_string()))?;
                report.found = Some(found);
                return Ok(report);
            }
        }
        radius += (radius / 2).max(1);
    }
}

/// The label of every cell of every shape, checking that `pieces` partitions
/// each figure into the same number of labels.
fn labels(inst: &Instance, pieces: &[Vec<Vec<Cell>>]) -> Result<Vec<Vec<usize>>, ExactError> {
    let bad = |m: String| Err(ExactError::Candidate(m));
    if pieces.len() != inst.shapes.len() {
        return bad(format!(
            "{} figures in the candidate, {} given",
            pieces.len(),
            inst.shapes.len()
        ));
    }
    let k = pieces[0].len();
    if k == 0 {
        return bad("no labels".to_string());
    }
    let l = inst.lattice.lattice();
    let mut out = Vec::with_capacity(pieces.len());
    for (f, (fp, shape)) in pieces.iter().zip(&inst.shapes).enumerate() {
        if fp.len() != k {
            return bad(format!(
                "figure {f} has {} labels, figure 0 has {k}",
                fp.len()
            ));
        }
        let mut label = vec![usize::MAX; shape.len()];
        for (i, cells) in fp.iter().enumerate() {
            for c in cells {
                match shape.index.get(&l.to_point(*c)) {
                    None => return bad(format!("figure {f}: cell {c:?} is not in the figure")),
                    Some(&x) if label[x] != usize::MAX => {
                        return bad(format!("figure {f}: cell {c:?} has two labels"))
                    }
                    Some(&x) => label[x] = i,
                }
            }
        }
        if let Some(x) = label.iter().position(|v| *v == usize::MAX) {
            return bad(format!(
                "figure {f}: cell {:?} has no label",
                shape.cells[x]
            ));
        }
        out.push(label);
    }
    Ok(out)
}

/// The candidate with its best motions and trouble cells.
struct Candidate<'a> {
    inst: &'a Instance,
    k: usize,
    /// `label[f][c]`.
    label: Vec<Vec<usize>>,
    /// `best[f][i]` (f ≥ 1): piece `i`'s best motion from shape 0 into `f`,
    /// with its inverse.
    best: Vec<Vec<Option<(Transform, Transform)>>>,
    /// `trouble[f][c]`.
    trouble: Vec<Vec<bool>>,
}

impl<'a> Candidate<'a> {
    /// `None` when interrupted.
    fn new(
        inst: &'a Instance,
        label: Vec<Vec<usize>>,
        k: usize,
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Candidate<'a>> {
        let shapes = &inst.shapes;
        let members: Vec<Vec<Vec<usize>>> = label
            .iter()
            .map(|l| {
                let mut m = vec![Vec::new(); k];
                for (c, &i) in l.iter().enumerate() {
                    m[i].push(c);
                }
                m
            })
            .collect();
        let mut best = vec![vec![None; k]];
        for f in 1..shapes.len() {
            let mut per_piece = Vec::with_capacity(k);
            for (from, to) in members[0].iter().zip(&members[f]) {
                if interrupted() {
                    return None;
                }
                let t = best_motion(inst, from, f, to);
                per_piece.push(t.map(|t| (t, t.inverse())));
            }
            best.push(per_piece);
        }
        let mut cand = Candidate {
            inst,
            k,
            label,
            best,
            trouble: shapes.iter().map(|s| vec![false; s.len()]).collect(),
        };
        for f in 0..shapes.len() {
            for c in 0..shapes[f].len() {
                cand.trouble[f][c] = !cand.consistent(f, c);
            }
            // Every component of a piece but its largest.
            for cells in &members[f] {
                let comps = components(&shapes[f], cells);
                let main = largest(&comps);
                for (ci, comp) in comps.iter().enumerate() {
                    if ci != main {
                        for &c in comp {
                            cand.trouble[f][c] = true;
                        }
                    }
                }
            }
        }
        Some(cand)
    }

    /// The partner in shape `to` of cell `c` of shape 0 under its piece's
    /// best motion, when it lies in `to` with the same label.
    fn image(&self, c: usize, to: usize) -> Option<usize> {
        let i = self.label[0][c];
        let (t, _) = self.best[to][i]?;
        let b = *self.inst.shapes[to]
            .index
            .get(&t.apply(self.inst.shapes[0].points[c]))?;
        (self.label[to][b] == i).then_some(b)
    }

    /// The partner in shape 0 of cell `c` of shape `f ≥ 1`, likewise.
    fn preimage(&self, f: usize, c: usize) -> Option<usize> {
        let i = self.label[f][c];
        let (_, u) = self.best[f][i]?;
        let a = *self.inst.shapes[0]
            .index
            .get(&u.apply(self.inst.shapes[f].points[c]))?;
        (self.label[0][a] == i).then_some(a)
    }

    fn consistent(&self, f: usize, c: usize) -> bool {
        if f == 0 {
            (1..self.inst.shapes.len()).all(|g| self.image(c, g).is_some())
        } else {
            self.preimage(f, c).is_some()
        }
    }

    /// The cells within BFS distance `radius` of trouble, closed under the
    /// best motions.
    fn free_within(&self, radius: usize) -> Vec<Vec<bool>> {
        let shapes = &self.inst.shapes;
        let mut free: Vec<Vec<bool>> = shapes
            .iter()
            .zip(&self.trouble)
            .map(|(s, t)| {
                let mut dist = vec![usize::MAX; s.len()];
                let mut queue: Vec<usize> = (0..s.len()).filter(|&c| t[c]).collect();
                for &c in &queue {
                    dist[c] = 0;
                }
                let mut head = 0;
                while head < queue.len() {
                    let u = queue[head];
                    head += 1;
                    if dist[u] >= radius {
                        continue;
                    }
                    for &v in &s.adj[u] {
                        if dist[v] == usize::MAX {
                            dist[v] = dist[u] + 1;
                            queue.push(v);
                        }
                    }
                }
                dist.iter().map(|d| *d <= radius).collect()
            })
            .collect();
        for f in 1..shapes.len() {
            for b in 0..shapes[f].len() {
                if free[f][b] {
                    if let Some(a) = self.preimage(f, b) {
                        free[0][a] = true;
                    }
                }
            }
        }
        for a in 0..shapes[0].len() {
            if free[0][a] {
                for (f, fr) in free.iter_mut().enumerate().skip(1) {
                    if let Some(b) = self.image(a, f) {
                        fr[b] = true;
                    }
                }
            }
        }
        free
    }
}

/// The index of the largest component (the first among equals).
fn largest(comps: &[Vec<usize>]) -> usize {
    let mut best = 0;
    for (i, c) in comps.iter().enumerate() {
        if c.len() > comps[best].len() {
            best = i;
        }
    }
    best
}

/// The motion of shape 0 into shape `f` under which most cells of `from`
/// land on cells of `to` (ties: the first symmetry, then the smallest
/// shift); `None` when either is empty.
fn best_motion(inst: &Instance, from: &[usize], f: usize, to: &[usize]) -> Option<Transform> {
    if from.is_empty() || to.is_empty() {
        return None;
    }
    let p0 = &inst.shapes[0].points;
    let pf = &inst.shapes[f].points;
    // (count, sym, shift): the best so far.
    let mut best: Option<(u32, usize, Point)> = None;
    let mut offer = |count: u32, sym: usize, t: Point| {
        let better = match best {
            None => true,
            Some((bc, bs, bt)) => count > bc || (count == bc && (sym, t) < (bs, bt)),
        };
        if better {
            best = Some((count, sym, t));
        }
    };
    for (gi, g) in inst.syms.iter().enumerate() {
        let img: Vec<Point> = from.iter().map(|&a| g.apply(p0[a])).collect();
        let mut lo = [i32::MAX; 3];
        let mut hi = [i32::MIN; 3];
        for &b in to {
            for d in 0..3 {
                lo[d] = lo[d].min(pf[b][d]);
                hi[d] = hi[d].max(pf[b][d]);
            }
        }
        let mut ilo = [i32::MAX; 3];
        let mut ihi = [i32::MIN; 3];
        for p in &img {
            for d in 0..3 {
                ilo[d] = ilo[d].min(p[d]);
                ihi[d] = ihi[d].max(p[d]);
            }
        }
        // Shifts range over [lo - ihi, hi - ilo] on each axis.
        let base = [lo[0] - ihi[0], lo[1] - ihi[1], lo[2] - ihi[2]];
        let ext: Vec<usize> = (0..3)
            .map(|d| (hi[d] - ilo[d] - base[d] + 1) as usize)
            .collect();
        let size = ext[0].saturating_mul(ext[1]).saturating_mul(ext[2]);
        if size <= 1 << 22 {
            let mut votes = vec![0u32; size];
            for p in &img {
                for &b in to {
                    let q = pf[b];
                    let x = [
                        (q[0] - p[0] - base[0]) as usize,
                        (q[1] - p[1] - base[1]) as usize,
                        (q[2] - p[2] - base[2]) as usize,
                    ];
                    votes[(x[0] * ext[1] + x[1]) * ext[2] + x[2]] += 1;
                }
            }
            for (idx, &v) in votes.iter().enumerate() {
                if v == 0 {
                    continue;
                }
                let t = Point::new(
                    base[0] + (idx / (ext[1] * ext[2])) as i32,
                    base[1] + (idx / ext[2] % ext[1]) as i32,
                    base[2] + (idx % ext[2]) as i32,
                );
                if inst.is_translation(t) {
                    offer(v, gi, t);
                }
            }
        } else {
            let mut votes: FxHashMap<Point, u32> = FxHashMap::default();
            for p in &img {
                for &b in to {
                    let q = pf[b];
                    let t = q - p;
                    if inst.is_translation(t) {
                        *votes.entry(t).or_default() += 1;
                    }
                }
            }
            for (t, v) in votes {
                offer(v, gi, t);
            }
        }
    }
    best.map(|(_, sym, t)| Transform::new(inst.syms[sym], t))
}

/// A literal that may be a constant.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Lit {
    True,
    False,
    Var(i32),
}

impl Lit {
    fn not(self) -> Lit {
        match self {
            Lit::True => Lit::False,
            Lit::False => Lit::True,
            Lit::Var(v) => Lit::Var(-v),
        }
    }
}

/// Adds the clause (constants folded); `false` when it is empty, that is
/// unsatisfiable.
fn add(sat: &mut Sat<'_>, lits: &[Lit]) -> bool {
    let mut clause = Vec::with_capacity(lits.len());
    for l in lits {
        match *l {
            Lit::True => return true,
            Lit::False => {}
            Lit::Var(v) => clause.push(v),
        }
    }
    if clause.is_empty() {
        return false;
    }
    sat.add(&clause);
    true
}

enum Outcome {
    Found(Vec<Vec<usize>>),
    Unsat,
    Unknown,
}

/// One neighbourhood encoded.
struct Round<'c, 'a> {
    cand: &'c Candidate<'a>,
    free: Vec<Vec<bool>>,
    /// `vars[f][c]`: (piece, variable) for each piece free cell `c` of
    /// shape `f` may join; empty for fixed cells.
    vars: Vec<Vec<Vec<(usize, i32)>>>,
    /// Whether an empty clause came up (the neighbourhood holds nothing).
    unsat: bool,
    /// Connectivity cuts added.
    cuts: usize,
}

impl<'c, 'a> Round<'c, 'a> {
    /// Encodes the neighbourhood `free`; `None` when interrupted.
    fn new(
        cand: &'c Candidate<'a>,
        free: Vec<Vec<bool>>,
        options: &RepairOptions,
        sat: &mut Sat<'_>,
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Round<'c, 'a>> {
        let shapes = &cand.inst.shapes;
        let k = cand.k;
        // has_fixed[f][i]: piece i keeps a cell of shape f.
        let mut has_fixed = vec![vec![false; k]; shapes.len()];
        for f in 0..shapes.len() {
            for c in 0..shapes[f].len() {
                if !free[f][c] {
                    has_fixed[f][cand.label[f][c]] = true;
                }
            }
        }
        // The pieces each free cell may join: those touching its free
        // component, and those with no fixed cell in its shape.
        let mut vars: Vec<Vec<Vec<(usize, i32)>>> = Vec::with_capacity(shapes.len());
        for (f, s) in shapes.iter().enumerate() {
            let mut per_cell = vec![Vec::new(); s.len()];
            let mut seen = vec![false; s.len()];
            for start in 0..s.len() {
                if !free[f][start] || seen[start] {
                    continue;
                }
                seen[start] = true;
                let mut comp = vec![start];
                let mut touch = vec![false; k];
                let mut head = 0;
                while head < comp.len() {
                    let u = comp[head];
                    head += 1;
                    for &v in &s.adj[u] {
                        if !free[f][v] {
                            touch[cand.label[f][v]] = true;
                        } else if !seen[v] {
                            seen[v] = true;
                            comp.push(v);
                        }
                    }
                }
                let allowed: Vec<usize> =
                    (0..k).filter(|&i| touch[i] || !has_fixed[f][i]).collect();
                comp.sort_unstable();
                for c in comp {
                    per_cell[c] = allowed.iter().map(|&i| (i, sat.var())).collect();
                }
            }
            vars.push(per_cell);
        }
        let mut round = Round {
            cand,
            free,
            vars,
            unsat: false,
            cuts: 0,
        };
        // Exactly one piece per free cell.
        for (f, s) in shapes.iter().enumerate() {
            for c in 0..s.len() {
                if !round.free[f][c] {
                    continue;
                }
                let lits: Vec<i32> = round.vars[f][c].iter().map(|(_, v)| *v).collect();
                if lits.is_empty() {
                    round.unsat = true;
                    return Some(round);
                }
                sat.add(&lits);
                for x in 0..lits.len() {
                    for y in x + 1..lits.len() {
                        sat.add(&[-lits[x], -lits[y]]);
                    }
                }
            }
        }
        // Local connectivity for pieces that keep a cell in the shape: a
        // free cell of the piece has a neighbour in it.
        for (f, s) in shapes.iter().enumerate() {
            for c in 0..s.len() {
                for &(i, v) in &round.vars[f][c] {
                    if !has_fixed[f][i] {
                        continue;
                    }
                    let mut clause = vec![Lit::Var(-v)];
                    clause.extend(s.adj[c].iter().map(|&n| round.lit(f, i, n)));
                    round.unsat |= !add(sat, &clause);
                }
            }
        }
        // Motions.
        let floating: Vec<bool> = (0..k)
            .map(|i| (0..shapes.len()).all(|f| !has_fixed[f][i]))
            .collect();
        let mut empty: Vec<Option<i32>> = vec![None; k];
        for i in 0..k {
            if floating[i] {
                let e = sat.var();
                empty[i] = Some(e);
                for per_cell in &round.vars {
                    for (j, v) in per_cell.iter().flatten() {
                        if *j == i {
                            sat.add(&[-e, -v]);
                        }
                    }
                }
            }
        }
        for f in 1..shapes.len() {
            for (i, e) in empty.iter().enumerate() {
                if interrupted() {
                    return None;
                }
                let motions = round.motions(i, f, options.max_motions);
                let mut at_least: Vec<Lit> = e.map(Lit::Var).into_iter().collect();
                for (t, u) in motions {
                    let m = sat.var();
                    at_least.push(Lit::Var(m));
                    round.encode_motion(sat, i, f, m, &t, &u);
                }
                round.unsat |= !add(sat, &at_least);
            }
        }
        Some(round)
    }

    /// Whether cell `c` of shape `f` is in piece `i`.
    fn lit(&self, f: usize, i: usize, c: usize) -> Lit {
        if !self.free[f][c] {
            return if self.cand.label[f][c] == i {
                Lit::True
            } else {
                Lit::False
            };
        }
        match self.vars[f][c].iter().find(|(j, _)| *j == i) {
            Some((_, v)) => Lit::Var(*v),
            None => Lit::False,
        }
    }

    /// Whether cell `c` of shape `f` may be in piece `i`.
    fn may_hold(&self, f: usize, i: usize, c: usize) -> bool {
        self.lit(f, i, c) != Lit::False
    }

    /// The cells of piece `i` in shape `f` that are fixed, those next to
    /// other labels (or the outside) first.
    fn fixed_cells(&self, f: usize, i: usize) -> Vec<usize> {
        let s = &self.cand.inst.shapes[f];
        let label = &self.cand.label[f];
        let mut edge = Vec::new();
        let mut inner = Vec::new();
        let full = s.adj.iter().map(Vec::len).max().unwrap_or(0);
        for c in 0..s.len() {
            if self.free[f][c] || label[c] != i {
                continue;
            }
            if s.adj[c].len() < full || s.adj[c].iter().any(|&n| label[n] != i) {
                edge.push(c);
            } else {
                inner.push(c);
            }
        }
        edge.extend(inner);
        edge
    }

    /// The motions of piece `i` from shape 0 into shape `f` that carry its
    /// fixed cells onto cells it may hold (both ways), with inverses: the
    /// best motion of the candidate first, at most `cap`.
    fn motions(&self, i: usize, f: usize, cap: usize) -> Vec<(Transform, Transform)> {
        let inst = self.cand.inst;
        let (s0, sf) = (&inst.shapes[0], &inst.shapes[f]);
        let fixed0 = self.fixed_cells(0, i);
        let fixedf = self.fixed_cells(f, i);
        let fits = |t: &Transform, u: &Transform| {
            fixed0.iter().all(|&a| {
                sf.index
                    .get(&t.apply(s0.points[a]))
                    .is_some_and(|&b| self.may_hold(f, i, b))
            }) && fixedf.iter().all(|&b| {
                s0.index
                    .get(&u.apply(sf.points[b]))
                    .is_some_and(|&a| self.may_hold(0, i, a))
            })
        };
        let mut out: Vec<(Transform, Transform)> = Vec::new();
        if let Some((t, u)) = self.cand.best[f][i] {
            if fits(&t, &u) {
                out.push((t, u));
            }
        }
        let push = |t: Transform, out: &mut Vec<(Transform, Transform)>| {
            if out.len() >= cap || out.iter().any(|(x, _)| *x == t) {
                return;
            }
            let u = t.inverse();
            if fits(&t, &u) {
                out.push((t, u));
            }
        };
        let holds0: Vec<usize> = (0..s0.len()).filter(|&a| self.may_hold(0, i, a)).collect();
        let holdsf: Vec<usize> = (0..sf.len()).filter(|&b| self.may_hold(f, i, b)).collect();
        let dist2 = |p: Point, q: Point| -> i64 {
            (0..3)
                .map(|d| i64::from(p[d] - q[d]) * i64::from(p[d] - q[d]))
                .sum()
        };
        // Motions that move the anchor least from where the best motion
        // puts it come first (a tiny piece may fit almost anywhere).
        let mut ranked: Vec<(i64, usize, Transform)> = Vec::new();
        if let Some(&a0) = fixed0.first() {
            let home = self.cand.best[f][i].map(|(t, _)| t.apply(s0.points[a0]));
            for g in &inst.syms {
                let ga = g.apply(s0.points[a0]);
                for &b in &holdsf {
                    let q = sf.points[b];
                    let t = q - ga;
                    if inst.is_translation(t) {
                        let key = home.map_or(0, |h| dist2(h, q));
                        ranked.push((key, ranked.len(), Transform::new(*g, t)));
                    }
                }
            }
        } else if let Some(&b0) = fixedf.first() {
            let q = sf.points[b0];
            let home = self.cand.best[f][i].map(|(_, u)| u.apply(q));
            for g in &inst.syms {
                for &a in &holds0 {
                    let ga = g.apply(s0.points[a]);
                    let t = q - ga;
                    if inst.is_translation(t) {
                        let key = home.map_or(0, |h| dist2(h, s0.points[a]));
                        ranked.push((key, ranked.len(), Transform::new(*g, t)));
                    }
                }
            }
        }
        if fixed0.first().or(fixedf.first()).is_some() {
            ranked.sort_unstable_by_key(|&(key, index, _)| (key, index));
            for (_, _, t) in ranked {
                if out.len() >= cap {
                    break;
                }
                push(t, &mut out);
            }
        } else {
            // A piece with no fixed cell here: the motions that carry a cell
            // it may hold onto one, those that keep its first cell nearest
            // to where the best motion puts it first, then those that carry
            // the most.
            let first = self.cand.label[0].iter().position(|&l| l == i);
            let home = first.and_then(|a| {
                self.cand.best[f][i].map(|(t, _)| (s0.points[a], t.apply(s0.points[a])))
            });
            let mut votes: FxHashMap<(usize, Point), u32> = FxHashMap::default();
            for (gi, g) in inst.syms.iter().enumerate() {
                for &a in &holds0 {
                    let ga = g.apply(s0.points[a]);
                    for &b in &holdsf {
                        let q = sf.points[b];
                        let t = q - ga;
                        if inst.is_translation(t) {
                            *votes.entry((gi, t)).or_default() += 1;
                        }
                    }
                }
            }
            let mut ranked: Vec<(i64, std::cmp::Reverse<u32>, usize, Point)> = votes
                .into_iter()
                .map(|((gi, t), v)| {
                    let key = home.map_or(0, |(p, h)| {
                        let gp = inst.syms[gi].apply(p);
                        dist2(gp + t, h)
                    });
                    (key, std::cmp::Reverse(v), gi, t)
                })
                .collect();
            ranked.sort_unstable();
            for (_, _, gi, t) in ranked {
                push(Transform::new(inst.syms[gi], t), &mut out);
                if out.len() >= cap {
                    break;
                }
            }
        }
        out
    }

    /// Clauses of motion variable `m`: piece `i` goes from shape 0 into
    /// shape `f` by `t` (inverse `u`).
    fn encode_motion(
        &self,
        sat: &mut Sat<'_>,
        i: usize,
        f: usize,
        m: i32,
        t: &Transform,
        u: &Transform,
    ) {
        let inst = self.cand.inst;
        let (s0, sf) = (&inst.shapes[0], &inst.shapes[f]);
        for a in 0..s0.len() {
            if !self.free[0][a] {
                continue;
            }
            let (img, fixed) = match sf.index.get(&t.apply(s0.points[a])) {
                Some(&b) => (self.lit(f, i, b), !self.free[f][b]),
                None => (Lit::False, false),
            };
            // a in the piece → its image too; a fixed image in the piece →
            // a too (a free image gets that clause below).
            add(sat, &[self.lit(0, i, a).not(), Lit::Var(-m), img]);
            if fixed {
                add(sat, &[img.not(), Lit::Var(-m), self.lit(0, i, a)]);
            }
        }
        for b in 0..sf.len() {
            if !self.free[f][b] {
                continue;
            }
            let (pre, fixed) = match s0.index.get(&u.apply(sf.points[b])) {
                Some(&a) => (self.lit(0, i, a), !self.free[0][a]),
                None => (Lit::False, false),
            };
            add(sat, &[self.lit(f, i, b).not(), Lit::Var(-m), pre]);
            if fixed {
                add(sat, &[pre.not(), Lit::Var(-m), self.lit(f, i, b)]);
            }
        }
    }

    /// Solves with connectivity cuts until every piece is connected.
    fn solve(&mut self, sat: &mut Sat<'_>, budget: u64, deadline: Option<Instant>) -> Outcome {
        if self.unsat {
            return Outcome::Unsat;
        }
        let shapes = &self.cand.inst.shapes;
        let start = sat.conflicts();
        let mut solves = 0u64;
        loop {
            // Every solve after a cut costs one unit too, so a long chain of
            // cuts without conflicts still ends within the budget.
            let used = sat.conflicts() - start + solves;
            if used >= budget {
                return Outcome::Unknown;
            }
            sat.set_conflict_limit(Some(sat.conflicts() + (budget - used)));
            solves += 1;
            match sat.solve(deadline) {
                None => return Outcome::Unknown,
                Some(false) => return Outcome::Unsat,
                Some(true) => {}
            }
            let label: Vec<Vec<usize>> = (0..shapes.len())
                .map(|f| {
                    (0..shapes[f].len())
                        .map(|c| {
                            if self.free[f][c] {
                                self.vars[f][c]
                                    .iter()
                                    .find(|(_, v)| sat.value(*v))
                                    .map_or(usize::MAX, |(i, _)| *i)
                            } else {
                                self.cand.label[f][c]
                            }
                        })
                        .collect()
                })
                .collect();
            let mut split = false;
            for (f, s) in shapes.iter().enumerate() {
                let mut members = vec![Vec::new(); self.cand.k];
                for (c, &i) in label[f].iter().enumerate() {
                    members[i].push(c);
                }
                for (i, cells) in members.iter().enumerate() {
                    let comps = components(s, cells);
                    if comps.len() < 2 {
                        continue;
                    }
                    split = true;
                    let main = largest(&comps);
                    for (ci, comp) in comps.iter().enumerate().take(6) {
                        if ci == main {
                            continue;
                        }
                        for (c, d) in [(comp, &comps[main]), (&comps[main], comp)] {
                            self.cuts += 1;
                            if !self.cut(sat, f, i, c, d) {
                                return Outcome::Unsat;
                            }
                        }
                    }
                }
            }
            if !split {
                return Outcome::Found(label);
            }
        }
    }

    /// Adds "if piece `i` holds a cell of `c` and one of `d`, it holds a
    /// cell next to `c`" in shape `f`; `false` when that is empty.
    fn cut(&self, sat: &mut Sat<'_>, f: usize, i: usize, c: &[usize], d: &[usize]) -> bool {
        let s = &self.cand.inst.shapes[f];
        // A fixed cell makes the clause shorter.
        let pick = |set: &[usize]| {
            set.iter()
                .copied()
                .find(|&x| !self.free[f][x])
                .unwrap_or(set[0])
        };
        let mut inside = vec![false; s.len()];
        for &x in c {
            inside[x] = true;
        }
        let mut sep: Vec<usize> = c
            .iter()
            .flat_map(|&x| s.adj[x].iter().copied())
            .filter(|&y| !inside[y])
            .collect();
        sep.sort_unstable();
        sep.dedup();
        let mut clause = vec![self.lit(f, i, pick(c)).not(), self.lit(f, i, pick(d)).not()];
        clause.extend(sep.iter().map(|&e| self.lit(f, i, e)));
        add(sat, &clause)
    }
}

/// Labels to sorted cells per piece and figure (input order: shape 0 is
/// figure 0), dropping labels empty everywhere.
fn to_cells(inst: &Instance, label: &[Vec<usize>], k: usize) -> Vec<Vec<Vec<Cell>>> {
    let per_shape: Vec<Vec<Vec<Cell>>> = label
        .iter()
        .zip(&inst.shapes)
        .map(|(l, s)| {
            let mut p = vec![Vec::new(); k];
            for (c, &i) in l.iter().enumerate() {
                p[i].push(s.cells[c]);
            }
            p
        })
        .collect();
    let keep: Vec<bool> = (0..k).map(|i| !per_shape[0][i].is_empty()).collect();
    let per_shape: Vec<Vec<Vec<Cell>>> = per_shape
        .into_iter()
        .map(|p| {
            p.into_iter()
                .zip(&keep)
                .filter(|(_, k)| **k)
                .map(|(mut c, _)| {
                    c.sort();
                    c
                })
                .collect()
        })
        .collect();
    inst.to_input_order(&per_shape)
}
