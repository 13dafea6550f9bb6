//! The motions of a piece as a symmetry and one shift per axis (the
//! "shift chain"), for encodings where one variable per whole motion would
//! not fit.
//!
//! The direct encoding (`placement_encoding::motions_of_shape`) has one
//! variable per motion `(g, t)` and ties every cell of shape 0 to its image:
//! per piece about `syms × translations × (n + n_f)` clauses, which grows
//! with the square of the cells (the translations grow with the cells too).
//! Here a piece's motion into shape `f` is a symmetry `g` (`sym[g]`) and a
//! shift `δ_d` per axis `d` (one-hot `shift[g][d][j]`), and the piece is
//! moved one axis at a time through level variables:
//!
//! * level 0 is `g` applied to shape 0's cells (the piece's own variables);
//! * level `d + 1` holds the points of level `d` shifted by `δ_d` along axis
//!   `d`, kept only where shape `f` has a cell with the same first `d + 1`
//!   coordinates and the same residues on the others (elsewhere the shift
//!   is forbidden for a piece holding that point);
//! * the last level is shape `f`'s own cell variables of the piece.
//!
//! Between levels, both ways: `L_d[q] ∧ shift[j] → L_{d+1}[q + δ_j e_d]`
//! and `L_{d+1}[q'] ∧ shift[j] → L_d[q' − δ_j e_d]` (a binary clause where
//! the other end does not exist). With one shift per axis chosen, level
//! `d + 1` is exactly level `d` moved, so the piece's cells in shape `f` are
//! exactly `g` and the translation `(δ_0, δ_1, δ_2)` applied to its cells in
//! shape 0: the same constraint as the direct encoding's motion variable.
//! Every motion the direct encoding allows has its shifts here (each axis'
//! shifts are all differences of a coordinate of shape `f` and one of the
//! turned shape 0), so every dissection is a model; the clauses grow with
//! `cells × width` per axis instead of `cells × translations`.
//!
//! Soundness is held by `tests/exact.rs`
//! `shift_encoding_matches_brute_force` (the same brute-force figures as
//! the direct encoding, on every lattice).

use rustc_hash::FxHashMap;

use dissect_core::lattice::Point;

use crate::instance::Instance;
use crate::sat_backend::Sat;

/// The shifts and level points of one symmetry `g` into one shape.
struct Chain {
    /// `deltas[d]`: the shifts along axis `d`, sorted.
    deltas: Vec<Vec<i32>>,
}

/// The point `p` moved by `delta` along `axis`.
fn shifted(p: Point, axis: usize, delta: i32) -> Point {
    let mut c = p.coords();
    c[axis] += delta;
    Point::from(c)
}

/// The key of a point at level `level`: exact coordinates below it,
/// residues from it on.
fn key(inst: &Instance, p: Point, level: usize) -> [i32; 3] {
    let mut c = p.coords();
    for v in c.iter_mut().take(inst.dim).skip(level) {
        *v = v.rem_euclid(inst.modulus.max(1));
    }
    c
}

/// The keys of shape `to` at every level `1..dim` (level `dim` is the
/// shape itself).
fn level_keys(inst: &Instance, to: usize) -> Vec<rustc_hash::FxHashSet<[i32; 3]>> {
    (0..inst.dim)
        .map(|l| {
            inst.shapes[to]
                .points
                .iter()
                .map(|p| key(inst, *p, l))
                .collect()
        })
        .collect()
}

impl Chain {
    /// The shifts of symmetry `g` from shape 0 into shape `to`; with
    /// `anchor`, only those that keep that cell of shape 0 inside `to`'s
    /// extent on every axis.
    fn new(inst: &Instance, to: usize, g: usize, anchor: Option<usize>) -> Chain {
        let sym = &inst.syms[g];
        let m = inst.modulus.max(1);
        let target = &inst.shapes[to];
        let deltas = (0..inst.dim)
            .map(|d| {
                let mut from: Vec<i32> = match anchor {
                    Some(c) => vec![sym.apply(inst.shapes[0].points[c])[d]],
                    None => inst.shapes[0]
                        .points
                        .iter()
                        .map(|p| sym.apply(*p)[d])
                        .collect(),
                };
                from.sort_unstable();
                from.dedup();
                let mut into: Vec<i32> = target.points.iter().map(|p| p[d]).collect();
                into.sort_unstable();
                into.dedup();
                let mut out: Vec<i32> = from
                    .iter()
                    .flat_map(|a| into.iter().map(move |b| b - a))
                    .filter(|t| t.rem_euclid(m) == 0)
                    .collect();
                out.sort_unstable();
                out.dedup();
                out
            })
            .collect();
        Chain { deltas }
    }
}

/// Counts of a chain for the size guard: (variables, clauses).
fn chain_size(
    inst: &Instance,
    (to, g): (usize, usize),
    anchor: Option<usize>,
    keys: &[rustc_hash::FxHashSet<[i32; 3]>],
) -> (u64, u64) {
    let chain = Chain::new(inst, to, g, anchor);
    let sym = &inst.syms[g];
    let mut level: Vec<Point> = inst.shapes[0]
        .points
        .iter()
        .map(|p| sym.apply(*p))
        .collect();
    let (mut vars, mut clauses) = (1u64, 2u64);
    for d in 0..inst.dim {
        let deltas = &chain.deltas[d];
        vars += deltas.len() as u64;
        clauses += 1 + deltas.len() as u64;
        let mut next: rustc_hash::FxHashSet<Point> = rustc_hash::FxHashSet::default();
        for q in &level {
            for &t in deltas {
                let p = shifted(*q, d, t);
                let kept = if d + 1 == inst.dim {
                    inst.shapes[to].index.contains_key(&p)
                } else {
                    keys[d + 1].contains(&key(inst, p, d + 1))
                };
                if kept {
                    next.insert(p);
                }
            }
        }
        let size = if d + 1 == inst.dim {
            inst.shapes[to].len()
        } else {
            vars += next.len() as u64;
            next.len()
        };
        clauses += (level.len() as u64 + size as u64) * deltas.len() as u64;
        level = next.into_iter().collect();
    }
    (vars, clauses)
}

/// An upper estimate of the variables and clauses of [`motions_by_shifts`]
/// for every shape `f ≥ 1` and the symmetries `syms`, for `k` pieces of
/// which the first ones are anchored at `anchors` (cells of shape 0);
/// `None` when `interrupted` says so (asked for every symmetry).
pub(crate) fn shifts_size(
    inst: &Instance,
    k: usize,
    syms: &[usize],
    anchors: &[usize],
    interrupted: &dyn Fn() -> bool,
) -> Option<(u64, u64)> {
    let (mut vars, mut clauses) = (0u64, 0u64);
    let anchored = anchors.len().min(k);
    for to in 1..inst.shapes.len() {
        let keys = level_keys(inst, to);
        for &g in syms {
            if interrupted() {
                return None;
            }
            let (v, c) = chain_size(inst, (to, g), None, &keys);
            let free = (k - anchored) as u64;
            vars = vars.saturating_add(v.saturating_mul(free));
            clauses = clauses.saturating_add(c.saturating_mul(free));
            for &a in &anchors[..anchored] {
                let (v, c) = chain_size(inst, (to, g), Some(a), &keys);
                vars = vars.saturating_add(v);
                clauses = clauses.saturating_add(c);
            }
        }
        clauses = clauses.saturating_add(k as u64);
    }
    Some((vars, clauses))
}

/// Encodes the motions of piece `i` into shape `to` as a shift chain per
/// symmetry in `syms` (see the module). `from`/`into`: the piece's cell
/// variables in shape 0 and in shape `to`. Returns the number of shift
/// variables, or `None` when interrupted.
pub(crate) fn motions_by_shifts(
    inst: &Instance,
    sat: &mut Sat<'_>,
    (to, syms): (usize, &[usize]),
    (from, into): (&[i32], &[i32]),
    anchor: Option<usize>,
    interrupted: &dyn Fn() -> bool,
) -> Option<usize> {
    let keys = level_keys(inst, to);
    let mut chosen = Vec::with_capacity(syms.len());
    let mut count = 0;
    for &g in syms {
        if interrupted() {
            return None;
        }
        let s = sat.var();
        chosen.push(s);
        count += one_chain(inst, sat, (to, g, s), (from, into), anchor, &keys);
    }
    sat.add(&chosen);
    Some(count)
}

/// One symmetry's chain, switched on by `s`; returns its shift variables.
fn one_chain(
    inst: &Instance,
    sat: &mut Sat<'_>,
    (to, g, s): (usize, usize, i32),
    (from, into): (&[i32], &[i32]),
    anchor: Option<usize>,
    keys: &[rustc_hash::FxHashSet<[i32; 3]>],
) -> usize {
    let chain = Chain::new(inst, to, g, anchor);
    let sym = &inst.syms[g];
    let target = &inst.shapes[to];
    let mut level: Vec<(Point, i32)> = inst.shapes[0]
        .points
        .iter()
        .zip(from)
        .map(|(p, &v)| (sym.apply(*p), v))
        .collect();
    let mut count = 0;
    for d in 0..inst.dim {
        let deltas = &chain.deltas[d];
        if deltas.is_empty() {
            sat.add(&[-s]);
            return count;
        }
        let shift: Vec<i32> = deltas.iter().map(|_| sat.var()).collect();
        count += shift.len();
        let mut some = vec![-s];
        some.extend(&shift);
        sat.add(&some);
        for &x in &shift {
            sat.add(&[-x, s]);
        }
        let last = d + 1 == inst.dim;
        let mut next: FxHashMap<Point, i32> = FxHashMap::default();
        let mut order: Vec<(Point, i32)> = Vec::new();
        for &(q, v) in &level {
            for (&t, &x) in deltas.iter().zip(&shift) {
                let p = shifted(q, d, t);
                let w = if last {
                    target.index.get(&p).map(|&b| into[b])
                } else if keys[d + 1].contains(&key(inst, p, d + 1)) {
                    Some(*next.entry(p).or_insert_with(|| {
                        let w = sat.var();
                        order.push((p, w));
                        w
                    }))
                } else {
                    None
                };
                match w {
                    Some(w) => sat.add(&[-v, -x, w]),
                    None => sat.add(&[-v, -x]),
                }
            }
        }
        let here: FxHashMap<Point, i32> = level.iter().copied().collect();
        let upper: Vec<(Point, i32)> = if last {
            target
                .points
                .iter()
                .copied()
                .zip(into.iter().copied())
                .collect()
        } else {
            order
        };
        for &(p, w) in &upper {
            for (&t, &x) in deltas.iter().zip(&shift) {
                match here.get(&shifted(p, d, -t)) {
                    Some(&v) => sat.add(&[-w, -x, v]),
                    None => sat.add(&[-w, -x]),
                }
            }
        }
        level = upper;
    }
    count
}
