//! Guillotine cuts: a dissection into boxes of two figures that are each
//! a union of a few boxes (sums of cubes, cuboids, L-prisms, steps),
//! found by a beam search.
//!
//! Each figure is covered by disjoint boxes ([`cover`]): one is the
//! *source*, the other the *target*. A step takes the target box that
//! comes first in an [`Order`] and fills one of its corners with a piece cut
//! from a corner of a source box, turned by a symmetry; the piece is as
//! large as both boxes allow along every axis. What is left of either box
//! is cut into at most three boxes by guillotine cuts, in any order of the
//! axes. Boxes placed with the same motion that touch in the source are
//! one piece, so a piece may be an L-prism or a slab bent round an edge
//! (the shell that a large cube leaves in a larger one is filled by such
//! slabs). The beam keeps the states with the fewest pieces plus boxes
//! left, until both sides are used up; on the wider rungs of [`RUNGS`] it
//! keeps instead the states whose greedy completion has the fewest pieces
//! (the pilot method: the score alone cannot see that a cut which leaves
//! one box more now saves pieces later). Every rung runs once per order of
//! [`ORDERS`]: which order does best depends on the figure.
//!
//! Only on lattices whose cells are the integer points and whose
//! symmetries are signed permutations ([`Lattice::is_grid`]); written once
//! for both of them (`square`, `cubic`).
//!
//! [`Lattice::is_grid`]: crate::lattice::Lattice::is_grid

use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use crate::lattice::{Cell, Symmetry, AXIS_PERMUTATIONS};

/// Figures covered by more boxes than this are not searched (the beam's
/// branching and its greedy completions grow with the boxes, and the
/// pieces would be many). Sums of cubes, cuboids with a cavity and joined
/// cubes take 1-8 boxes; a rasterized disc (23) or a Sierpinski carpet
/// (18) is better served by the other steps, and the pilot rungs would
/// take seconds on them.
pub(crate) const MAX_BOXES: usize = 12;

/// One search of the ladder: the beam's width and its fan (`0`: the beam
/// keeps the children of the lowest score; `f`: the `f * width` children
/// of the lowest score are each completed greedily, and the beam keeps
/// those whose completion has the fewest pieces).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Rung {
    pub(crate) width: usize,
    pub(crate) fan: usize,
}

/// The rungs, in the order the run climbs them: each one a full search,
/// about twice to four times the work of the one before (on 7³+14³+17³ =
/// 20³, the completions one at a time: 0.2 and 0.7 s for the plain beams,
/// then about 0.5, 2, 3, 13, 26 and 54 s; about half that on two
/// threads).
pub(crate) const RUNGS: [Rung; 8] = [
    Rung { width: 32, fan: 0 },
    Rung { width: 128, fan: 0 },
    Rung { width: 8, fan: 8 },
    Rung { width: 16, fan: 16 },
    Rung { width: 32, fan: 16 },
    Rung { width: 64, fan: 32 },
    Rung {
        width: 128,
        fan: 32,
    },
    Rung {
        width: 256,
        fan: 32,
    },
];

/// Which target box a step fills (and so the order in which the target is
/// used up). The answers differ a good deal from one order to another and
/// no order is best on every figure, so each rung runs them all
/// ([`ORDERS`]); ties go to the lowest corner in `(z, y, x)` order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Order {
    /// The lowest corner in `(z, y, x)` order.
    Low,
    /// The box whose shortest side is the shortest.
    Thin,
    /// The lowest corner in `(x, y, z)` order.
    LowX,
    /// The box whose shortest side is the longest.
    Thick,
}

/// The orders each rung runs, in turn.
pub(crate) const ORDERS: [Order; 4] = [Order::Low, Order::Thin, Order::LowX, Order::Thick];

impl Order {
    /// The key whose least value among the target boxes is filled next.
    fn key(self, b: &Cuboid) -> [i32; 4] {
        let [x, y, z] = b.lo;
        let short = b.size[0].min(b.size[1]).min(b.size[2]);
        match self {
            Order::Low => [z, y, x, 0],
            Order::Thin => [short, z, y, x],
            Order::LowX => [x, y, z, 0],
            Order::Thick => [-short, z, y, x],
        }
    }
}

/// A box of cells: `lo` its lowest corner, `size` its extent per axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
struct Cuboid {
    lo: [i32; 3],
    size: [i32; 3],
}

impl Cuboid {
    /// Whether the two (disjoint) boxes share a face.
    fn touches(&self, o: &Cuboid) -> bool {
        let mut faces = 0;
        for k in 0..3 {
            let lo = self.lo[k].max(o.lo[k]);
            let hi = (self.lo[k] + self.size[k]).min(o.lo[k] + o.size[k]);
            if hi < lo {
                return false;
            }
            if hi == lo {
                faces += 1;
            }
        }
        faces == 1
    }

    fn cells(&self) -> impl Iterator<Item = Cell> + '_ {
        let [x0, y0, z0] = self.lo;
        let [dx, dy, dz] = self.size;
        (z0..z0 + dz).flat_map(move |z| {
            (y0..y0 + dy).flat_map(move |y| (x0..x0 + dx).map(move |x| [x, y, z]))
        })
    }

    /// The box at corner `corner` (bit `k` set: the high end of axis `k`)
    /// with these sizes.
    fn corner(&self, size: [i32; 3], corner: usize) -> Cuboid {
        let mut lo = self.lo;
        for k in 0..3 {
            if corner >> k & 1 == 1 {
                lo[k] += self.size[k] - size[k];
            }
        }
        Cuboid { lo, size }
    }

    /// What is left of the box once `piece` (one of its corner boxes) is
    /// taken, cut first across axis `order[0]`, then `order[1]`, then
    /// `order[2]`: at most three boxes.
    fn rest(&self, piece: &Cuboid, order: [usize; 3]) -> Vec<Cuboid> {
        let mut out = Vec::with_capacity(3);
        let mut cur = *self;
        for ax in order {
            if piece.size[ax] == cur.size[ax] {
                continue;
            }
            let mut r = cur;
            if piece.lo[ax] == cur.lo[ax] {
                r.lo[ax] = cur.lo[ax] + piece.size[ax];
            }
            r.size[ax] = cur.size[ax] - piece.size[ax];
            out.push(r);
            cur.lo[ax] = piece.lo[ax];
            cur.size[ax] = piece.size[ax];
        }
        out
    }
}

/// A symmetry as a signed permutation: target axis `k` takes source axis
/// `axis[k]`, times `sign[k]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Turn {
    axis: [usize; 3],
    sign: [i32; 3],
}

impl Turn {
    fn of(s: &Symmetry) -> Option<Turn> {
        let m = s.matrix();
        let mut axis = [0; 3];
        let mut sign = [0; 3];
        for k in 0..3 {
            let nz: Vec<usize> = (0..3).filter(|&a| m[k][a] != 0).collect();
            if nz.len() != 1 || m[k][nz[0]].abs() != 1 {
                return None;
            }
            axis[k] = nz[0];
            sign[k] = m[k][nz[0]];
        }
        Some(Turn { axis, sign })
    }
}

/// A motion: the turn (an index into the turns) and the shift after it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Motion {
    turn: usize,
    shift: [i32; 3],
}

fn apply(turns: &[Turn], m: Motion, c: Cell) -> Cell {
    let t = turns[m.turn];
    let mut out = [0; 3];
    for k in 0..3 {
        out[k] = t.sign[k] * c[t.axis[k]] + m.shift[k];
    }
    out
}

/// A box of the source laid with a motion, in piece `group`.
#[derive(Clone, Copy, Debug)]
struct Placed {
    piece: Cuboid,
    motion: Motion,
    group: usize,
}

#[derive(Clone, Debug, Default)]
struct State {
    src: Vec<Cuboid>,
    dst: Vec<Cuboid>,
    placed: Vec<Placed>,
    pieces: usize,
}

/// Disjoint boxes covering `cells`: from the first uncovered cell in
/// `(z, y, x)` order, as long along `x`, then `y`, then `z` as the figure
/// allows. `None` when more than `max` boxes are needed.
fn cover(cells: &[Cell], max: usize) -> Option<Vec<Cuboid>> {
    let first = cells.first()?;
    let (mut lo, mut hi) = (*first, *first);
    for c in cells {
        for k in 0..3 {
            lo[k] = lo[k].min(c[k]);
            hi[k] = hi[k].max(c[k]);
        }
    }
    let dims: Vec<usize> = (0..3).map(|k| (hi[k] - lo[k] + 1) as usize).collect();
    let index = |c: [i32; 3]| -> usize {
        let [x, y, z] = [0, 1, 2].map(|k| (c[k] - lo[k]) as usize);
        (z * dims[1] + y) * dims[0] + x
    };
    // 0: not in the figure, 1: in it and uncovered, 2: covered.
    let mut grid = vec![0u8; dims.iter().product()];
    for c in cells {
        grid[index(*c)] = 1;
    }
    let free = |grid: &[u8], b: &Cuboid| b.cells().all(|c| grid[index(c)] == 1);
    let mut sorted = cells.to_vec();
    sorted.sort_by_key(|c| (c[2], c[1], c[0]));
    let mut out = Vec::new();
    for c in sorted {
        if grid[index(c)] != 1 {
            continue;
        }
        let mut b = Cuboid {
            lo: c,
            size: [1, 1, 1],
        };
        for (k, &top) in hi.iter().enumerate() {
            loop {
                let mut slab = b;
                slab.lo[k] += b.size[k];
                slab.size[k] = 1;
                if slab.lo[k] > top || !free(&grid, &slab) {
                    break;
                }
                b.size[k] += 1;
            }
        }
        for cell in b.cells() {
            grid[index(cell)] = 2;
        }
        out.push(b);
        if out.len() > max {
            return None;
        }
    }
    Some(out)
}

/// The distinct ways to cut what is left of `b` once `piece` is taken.
fn rests(b: &Cuboid, piece: &Cuboid) -> Vec<Vec<Cuboid>> {
    let mut out: Vec<Vec<Cuboid>> = Vec::new();
    for order in AXIS_PERMUTATIONS {
        let mut r = b.rest(piece, order);
        r.sort_unstable();
        if !out.contains(&r) {
            out.push(r);
        }
    }
    out
}

/// Corners of a box of `size` that differ for a piece of `piece` (a
/// corner bit along an axis the piece fills is the same corner).
fn corners(size: [i32; 3], piece: [i32; 3]) -> impl Iterator<Item = usize> {
    (0..8).filter(move |c| (0..3).all(|k| c >> k & 1 == 0 || piece[k] < size[k]))
}

/// One step from a state: the child's boxes and the piece laid.
/// The boxes are not kept, only what makes them from the parent's (the
/// children of a step are many, and this keeps them small).
struct Child {
    parent: usize,
    /// The source box cut and what is left of it.
    si: usize,
    src_rest: Rest,
    /// The target box filled and what is left of it.
    ti: usize,
    dst_rest: Rest,
    piece: Cuboid,
    motion: Motion,
    /// The groups of touching boxes with the same motion it joins.
    joins: Vec<usize>,
    score: usize,
}

/// What is left of a box: at most three boxes, kept inline.
#[derive(Clone, Copy)]
struct Rest {
    boxes: [Cuboid; 3],
    len: usize,
}

impl Rest {
    fn of(boxes: &[Cuboid]) -> Rest {
        let mut r = Rest {
            boxes: [Cuboid {
                lo: [0; 3],
                size: [0; 3],
            }; 3],
            len: boxes.len(),
        };
        r.boxes[..boxes.len()].copy_from_slice(boxes);
        r
    }

    fn boxes(&self) -> &[Cuboid] {
        &self.boxes[..self.len]
    }
}

/// `boxes` without box `i`, and `rest` added (in this order: the same
/// boxes in the same order wherever they are made).
fn replaced(boxes: &[Cuboid], i: usize, rest: &[Cuboid]) -> Vec<Cuboid> {
    let mut out = boxes.to_vec();
    out.swap_remove(i);
    out.extend_from_slice(rest);
    out
}

/// A hash of the boxes left on both sides (states with the same boxes
/// left are the same to the rest of the search).
fn key(src: &[Cuboid], dst: &[Cuboid]) -> u64 {
    let mut a = src.to_vec();
    let mut b = dst.to_vec();
    a.sort_unstable();
    b.sort_unstable();
    let mut h = std::collections::hash_map::DefaultHasher::new();
    a.hash(&mut h);
    b.hash(&mut h);
    h.finish()
}

/// The target box a step fills, the first by `order`; `None` when the
/// target is used up.
fn target(st: &State, order: Order) -> Option<usize> {
    (0..st.dst.len()).min_by_key(|&i| order.key(&st.dst[i]))
}

/// What a step may do: the turns, their distinct axis permutations (turns
/// with the same axes give the same boxes; only the motion, and so what
/// the piece joins, differs) and the order the target boxes are filled in.
struct Moves<'a> {
    turns: &'a [Turn],
    perms: Vec<[usize; 3]>,
    order: Order,
}

impl Moves<'_> {
    fn new(turns: &[Turn], order: Order) -> Moves<'_> {
        let mut perms: Vec<[usize; 3]> = turns.iter().map(|t| t.axis).collect();
        perms.sort_unstable();
        perms.dedup();
        Moves {
            turns,
            perms,
            order,
        }
    }
}

/// The sizes of the largest piece that source box `s` and target box `t`
/// both hold when target axis `k` takes source axis `axis[k]`: in the
/// source's axes, then in the target's.
fn piece_sizes(s: &Cuboid, t: &Cuboid, axis: &[usize; 3]) -> ([i32; 3], [i32; 3]) {
    let mut pdt = [0; 3];
    let mut pds = [0; 3];
    for k in 0..3 {
        pdt[k] = t.size[k].min(s.size[axis[k]]);
        pds[axis[k]] = pdt[k];
    }
    (pds, pdt)
}

/// Every step from state `st` (index `parent` in the beam), into `out`
/// (keyed by the boxes left, the best score kept).
fn expand(
    st: &State,
    parent: usize,
    moves: &Moves<'_>,
    out: &mut Vec<Child>,
    seen: &mut HashMap<u64, usize>,
) {
    let Some(ti) = target(st, moves.order) else {
        return;
    };
    let t = st.dst[ti];
    for (si, s) in st.src.iter().enumerate() {
        for axis in &moves.perms {
            let (pds, pdt) = piece_sizes(s, &t, axis);
            for cs in corners(s.size, pds) {
                let ps = s.corner(pds, cs);
                let src_rests = rests(s, &ps);
                for ct in corners(t.size, pdt) {
                    let pt = t.corner(pdt, ct);
                    let (motion, joins) = best_motion(st, moves.turns, *axis, &ps, &pt);
                    let pieces = st.pieces + 1 - joins.len();
                    for rt in rests(&t, &pt) {
                        for rs in &src_rests {
                            let src = replaced(&st.src, si, rs);
                            let dst = replaced(&st.dst, ti, &rt);
                            let score = pieces + src.len() + dst.len();
                            let k = key(&src, &dst);
                            let child = Child {
                                parent,
                                si,
                                src_rest: Rest::of(rs),
                                ti,
                                dst_rest: Rest::of(&rt),
                                piece: ps,
                                motion,
                                joins: joins.clone(),
                                score,
                            };
                            match seen.get(&k) {
                                Some(&i) if out[i].score <= score => {}
                                Some(&i) => out[i] = child,
                                None => {
                                    seen.insert(k, out.len());
                                    out.push(child);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
}

/// The motion that lays `ps` (source) on `pt` (target) with these axes,
/// among the turns, that joins the most pieces already laid (the first
/// such turn), and the groups it joins.
fn best_motion(
    st: &State,
    turns: &[Turn],
    axis: [usize; 3],
    ps: &Cuboid,
    pt: &Cuboid,
) -> (Motion, Vec<usize>) {
    let mut best: Option<(Motion, Vec<usize>)> = None;
    for (ti, turn) in turns.iter().enumerate() {
        if turn.axis != axis {
            continue;
        }
        let shift: [i32; 3] = std::array::from_fn(|k| {
            let a = turn.axis[k];
            if turn.sign[k] > 0 {
                pt.lo[k] - ps.lo[a]
            } else {
                pt.lo[k] + pt.size[k] - 1 + ps.lo[a]
            }
        });
        let motion = Motion { turn: ti, shift };
        let mut joins: Vec<usize> = st
            .placed
            .iter()
            .filter(|p| p.motion == motion && p.piece.touches(ps))
            .map(|p| p.group)
            .collect();
        joins.sort_unstable();
        joins.dedup();
        if best.as_ref().is_none_or(|(_, j)| joins.len() > j.len()) {
            best = Some((motion, joins));
        }
    }
    best.expect("the axes come from a turn")
}

/// The state a child stands for.
fn grow(parent: &State, c: Child) -> State {
    let mut placed = parent.placed.clone();
    let group = match c.joins.first() {
        Some(&g) => {
            for p in &mut placed {
                if c.joins.contains(&p.group) {
                    p.group = g;
                }
            }
            g
        }
        None => placed.len(),
    };
    placed.push(Placed {
        piece: c.piece,
        motion: c.motion,
        group,
    });
    State {
        src: replaced(&parent.src, c.si, c.src_rest.boxes()),
        dst: replaced(&parent.dst, c.ti, c.dst_rest.boxes()),
        placed,
        pieces: parent.pieces + 1 - c.joins.len(),
    }
}

/// The greedy completion of `st`: each step the child of the fewest
/// pieces plus boxes left (the first on ties), its rests cut in the first
/// order of the axes. `None` when stopped.
fn rollout(mut st: State, moves: &Moves<'_>, stop: &AtomicBool) -> Option<State> {
    while !(st.src.is_empty() && st.dst.is_empty()) {
        if stop.load(Ordering::Relaxed) {
            return None;
        }
        let c = greedy_step(&st, moves)?;
        st = grow(&st, c);
    }
    Some(st)
}

/// The best child of `st` by score, the rests cut in the first order.
fn greedy_step(st: &State, moves: &Moves<'_>) -> Option<Child> {
    let ti = target(st, moves.order)?;
    let t = st.dst[ti];
    let mut best: Option<Child> = None;
    for (si, s) in st.src.iter().enumerate() {
        for axis in &moves.perms {
            let (pds, pdt) = piece_sizes(s, &t, axis);
            let ns = (0..3).filter(|&k| pds[k] < s.size[k]).count();
            let nt = (0..3).filter(|&k| pdt[k] < t.size[k]).count();
            for cs in corners(s.size, pds) {
                let ps = s.corner(pds, cs);
                for ct in corners(t.size, pdt) {
                    let pt = t.corner(pdt, ct);
                    let (motion, joins) = best_motion(st, moves.turns, *axis, &ps, &pt);
                    let pieces = st.pieces + 1 - joins.len();
                    let score = pieces + st.src.len() - 1 + ns + st.dst.len() - 1 + nt;
                    if best.as_ref().is_some_and(|b| b.score <= score) {
                        continue;
                    }
                    best = Some(Child {
                        parent: 0,
                        si,
                        src_rest: Rest::of(&s.rest(&ps, AXIS_PERMUTATIONS[0])),
                        ti,
                        dst_rest: Rest::of(&t.rest(&pt, AXIS_PERMUTATIONS[0])),
                        piece: ps,
                        motion,
                        joins,
                        score,
                    });
                }
            }
        }
    }
    best
}

/// The beam search of `rung` from `src` to `dst`: the finished state with
/// the fewest pieces, `None` when stopped.
fn beam(
    src: Vec<Cuboid>,
    dst: Vec<Cuboid>,
    moves: &Moves<'_>,
    rung: Rung,
    stop: &AtomicBool,
) -> Option<State> {
    let Rung { width, fan } = rung;
    let mut beam = vec![State {
        src,
        dst,
        ..State::default()
    }];
    let mut best: Option<State> = None;
    while !beam.is_empty() {
        if stop.load(Ordering::Relaxed) {
            return None;
        }
        let mut children = Vec::new();
        let mut seen = HashMap::new();
        for (i, st) in beam.iter().enumerate() {
            expand(st, i, moves, &mut children, &mut seen);
        }
        // Stable: ties keep the order they were made in, so the search is
        // the same on every run.
        children.sort_by_key(|c| c.score);
        children.truncate(width * fan.max(1));
        let mut grown: Vec<State> = children
            .into_iter()
            .map(|c| grow(&beam[c.parent], c))
            .collect();
        if fan > 0 {
            // Each completion on its own: collected in order, the same
            // on any number of threads.
            let done: Vec<State> = grown
                .par_iter()
                .map(|st| rollout(st.clone(), moves, stop))
                .collect::<Option<_>>()?;
            let mut scored: Vec<(usize, State)> = Vec::with_capacity(grown.len());
            for (st, done) in grown.into_iter().zip(done) {
                let pieces = done.pieces;
                if best.as_ref().is_none_or(|b| pieces < b.pieces) {
                    best = Some(done);
                }
                scored.push((pieces, st));
            }
            // Stable: ties keep the order of the scores.
            scored.sort_by_key(|(n, _)| *n);
            scored.truncate(width);
            grown = scored.into_iter().map(|(_, s)| s).collect();
        }
        let mut next = Vec::with_capacity(grown.len());
        for st in grown {
            if st.src.is_empty() && st.dst.is_empty() {
                if best.as_ref().is_none_or(|b| st.pieces < b.pieces) {
                    best = Some(st);
                }
            } else if best.as_ref().is_none_or(|b| st.pieces < b.pieces) {
                next.push(st);
            }
        }
        beam = next;
    }
    best
}

/// Two figures covered by boxes, ready for the beam: the first is the
/// source of one search and the target of the other.
pub(crate) struct Boxes {
    turns: Vec<Turn>,
    boxes: [Vec<Cuboid>; 2],
}

impl Boxes {
    /// The boxes of two figures (`cells[0]`, `cells[1]`, cells equal to
    /// points) under the symmetries `syms`; `None` when a figure needs
    /// more than [`MAX_BOXES`] boxes or a symmetry is not a signed
    /// permutation.
    pub(crate) fn new(cells: [&[Cell]; 2], syms: &[Symmetry]) -> Option<Boxes> {
        let turns: Vec<Turn> = syms.iter().map(Turn::of).collect::<Option<_>>()?;
        let boxes = [cover(cells[0], MAX_BOXES)?, cover(cells[1], MAX_BOXES)?];
        Some(Boxes { turns, boxes })
    }

    /// A dissection into boxes and pieces made of touching boxes, by the
    /// search of `rung` filling the target's boxes in `order`, with each
    /// figure as the source in turn (the fewer pieces kept; the first on
    /// ties): the pieces' cells per figure, `None` when stopped.
    pub(crate) fn dissect(
        &self,
        rung: Rung,
        order: Order,
        stop: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        let moves = Moves::new(&self.turns, order);
        let mut best: Option<(usize, State)> = None;
        for from in 0..2 {
            let st = beam(
                self.boxes[from].clone(),
                self.boxes[1 - from].clone(),
                &moves,
                rung,
                stop,
            )?;
            if best.as_ref().is_none_or(|(_, b)| st.pieces < b.pieces) {
                best = Some((from, st));
            }
        }
        let (from, st) = best?;
        Some(pieces_of(&st, from, &self.turns))
    }
}

/// The pieces of a finished state, per figure (`from`: the source's
/// index), in the order their first box was laid.
fn pieces_of(st: &State, from: usize, turns: &[Turn]) -> Vec<Vec<Vec<Cell>>> {
    let mut order: Vec<usize> = Vec::new();
    for p in &st.placed {
        if !order.contains(&p.group) {
            order.push(p.group);
        }
    }
    let mut out = vec![vec![Vec::new(); order.len()]; 2];
    for p in &st.placed {
        let i = order.iter().position(|&g| g == p.group).expect("listed");
        for c in p.piece.cells() {
            out[from][i].push(c);
            out[1 - from][i].push(apply(turns, p.motion, c));
        }
    }
    for fig in &mut out {
        for piece in fig.iter_mut() {
            piece.sort_unstable();
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube_cells(lo: [i32; 3], side: i32) -> Vec<Cell> {
        Cuboid {
            lo,
            size: [side; 3],
        }
        .cells()
        .collect()
    }

    #[test]
    fn cover_finds_one_box_per_cube() {
        let mut cells = cube_cells([0, 0, 0], 3);
        cells.extend(cube_cells([4, 0, 0], 2));
        let boxes = cover(&cells, MAX_BOXES).expect("two boxes");
        assert_eq!(boxes.len(), 2);
        assert!(cover(&cells, 1).is_none());
    }

    #[test]
    fn rest_cuts_a_corner_off_in_three() {
        let b = Cuboid {
            lo: [0, 0, 0],
            size: [4, 3, 2],
        };
        let p = b.corner([1, 1, 1], 0b111);
        let r = b.rest(&p, [0, 1, 2]);
        assert_eq!(r.len(), 3);
        let volume: i32 = r.iter().map(|c| c.size.iter().product::<i32>()).sum();
        assert_eq!(volume, 23);
    }
}
