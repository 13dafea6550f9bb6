//! "Is there a dissection into at most K pieces?" as CNF.
//!
//! Variables:
//! * `cell[f][i][c]`: cell `c` of shape `f` belongs to piece `i`;
//! * `motion[f][i][m]` (shapes `f ≥ 1`): piece `i` of the reference shape 0
//!   goes into shape `f` by motion `m`.
//!
//! Clauses:
//! * every cell of every shape is in exactly one piece;
//! * every piece has a motion into every other shape (at least one; when
//!   two are true both carry the piece onto its copy, since the copies
//!   exactly cover a shape of the same area);
//! * `cell[0][i][a] ∧ motion[f][i][m] → cell[f][i][m(a)]` (false when `m(a)`
//!   lies outside shape `f`), and the same backwards through `m⁻¹`;
//! * symmetry breaking: the cells of an incompatible clique of shape 0 go to
//!   pieces `0, 1, ...`; the other pieces are ordered by their first cell; the
//!   first piece's motion into shape `f` is taken up to the symmetries of
//!   shape `f`;
//! * incompatible cells (see `incompatible_clique`) never share a piece;
//! * local connectivity: in a piece of two or more cells every cell has a
//!   neighbour in the piece (a counter over shape 0 tells whether the piece
//!   has two cells).
//!
//! Pieces may still be split into larger parts, so this is a relaxation:
//! UNSAT proves that no K-piece dissection exists; a model is a real
//! dissection once its pieces are connected (`connectivity_cut` adds clauses
//! until they are).

use crate::incompatible_clique::Incompatibility;
use crate::instance::Instance;
use crate::motion::{coset_representatives, motions_into, self_symmetries, Motion, MotionSet};
use crate::sat_backend::Sat;

/// The variables of one encoding.
///
/// # Validity
/// `cell[f][i]` has one variable per cell of shape `f`; `motion[0]` is
/// empty; every `motion[f][i]` (f ≥ 1) is non-empty.
pub(crate) struct Encoding {
    pub k: usize,
    /// `anchors[i]`: a cell of shape 0 fixed to piece `i`, when there is one.
    pub anchors: Vec<usize>,
    pub cell: Vec<Vec<Vec<i32>>>,
    /// The direct encoding's motion variables (empty per piece with
    /// [`MotionEncoding::Shifts`]).
    pub motion: Vec<Vec<Vec<(i32, Motion)>>>,
    /// The shift variables of [`MotionEncoding::Shifts`].
    pub shift_vars: usize,
    /// The literals of one at-least-one clause of the formula, to split it
    /// into cubes (`cube_and_conquer`): piece 0's motions into shape 1
    /// (direct encoding) when it has two or more, else "this cell of shape
    /// 0 is in some piece" for a cell that no piece is anchored at.
    pub cube: Vec<i32>,
}

/// How the motion of each piece into each other figure is encoded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MotionEncoding {
    /// [`MotionEncoding::Direct`] while its estimate is small or not much
    /// larger than the shift chain's, else [`MotionEncoding::Shifts`];
    /// always `Direct` under constraints (they are stated on motion
    /// variables).
    #[default]
    Auto,
    /// One variable per motion (symmetry and translation), tied to every
    /// cell: the strongest propagation, about `cells²` clauses per piece.
    Direct,
    /// A symmetry and one shift per axis, the piece moved one axis at a
    /// time through level variables: about `cells × width` clauses per
    /// piece and symmetry.
    Shifts,
}

/// Counts of what was encoded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EncodingSize {
    /// Variables.
    pub vars: usize,
    /// Clauses.
    pub clauses: usize,
    /// Motion variables.
    pub motions: usize,
}

/// Bytes the SAT solver spends per clause of the encoding (the clause, its
/// two watches, a share of learnt clauses), roughly: for the size guard.
const BYTES_PER_CLAUSE: u64 = 64;
/// Bytes per variable (assignment, level, reason, activity, heap, watch
/// lists), roughly.
const BYTES_PER_VAR: u64 = 96;
/// Bytes per clause of a recorded DIMACS text.
const BYTES_PER_RECORDED_CLAUSE: u64 = 24;

impl EncodingSize {
    /// The memory the SAT solver needs for it, estimated (recording the
    /// clauses as text adds `recorded` bytes per clause).
    pub fn bytes(&self, recorded: bool) -> u64 {
        let per_clause = BYTES_PER_CLAUSE
            + if recorded {
                BYTES_PER_RECORDED_CLAUSE
            } else {
                0
            };
        (self.vars as u64)
            .saturating_mul(BYTES_PER_VAR)
            .saturating_add((self.clauses as u64).saturating_mul(per_clause))
    }
}

/// An upper estimate of the motions of `set` from shape 0 into shape `to`:
/// the exact count when that is cheap, else the number of shifts within
/// the bounding boxes.
fn motion_count(inst: &Instance, to: usize, set: MotionSet) -> usize {
    let syms = (0..inst.syms.len())
        .filter(|&g| set.admits(g, inst.syms[g].determinant()))
        .count();
    let (a, b) = (&inst.shapes[0], &inst.shapes[to]);
    if (a.len() as u64) * (b.len() as u64) * (syms as u64) <= 4_000_000 {
        return motions_into(inst, to, set, &|| false).map_or(0, |m| m.len());
    }
    let extent = |s: &crate::instance::Shape, d: usize| {
        let lo = s.points.iter().map(|p| p[d]).min().unwrap_or(0);
        let hi = s.points.iter().map(|p| p[d]).max().unwrap_or(0);
        (hi - lo) as usize
    };
    // Symmetries may swap axes: use the largest extent on every axis.
    let big = |s: &crate::instance::Shape| (0..inst.dim).map(|d| extent(s, d)).max().unwrap_or(0);
    let side = big(a) + big(b) + 1;
    let per_axis = side.div_ceil(inst.modulus.max(1) as usize).max(1);
    syms.saturating_mul(per_axis.saturating_pow(inst.dim as u32))
}

/// The size of [`encode`]'s output for `k` pieces, estimated from above
/// without building it (so a hopeless encoding is refused before it takes
/// the memory).
///
/// The first `min(k, max(clique, 1))` pieces are anchored (a cell of
/// theirs is fixed), so their motions are at most one per symmetry and
/// target cell.
pub(crate) fn estimate(
    inst: &Instance,
    k: usize,
    (set, style): (MotionSet, MotionEncoding),
    clique_cells: &[usize],
    incompat: &[Incompatibility],
    interrupted: &dyn Fn() -> bool,
) -> EncodingSize {
    let clique = clique_cells.len();
    if style == MotionEncoding::Auto {
        return estimate(
            inst,
            k,
            (
                set,
                choose(inst, k, set, clique_cells, incompat, interrupted),
            ),
            clique_cells,
            incompat,
            interrupted,
        );
    }
    let anchored = clique.max(1).min(k) as u64;
    let syms = (0..inst.syms.len())
        .filter(|&g| set.admits(g, inst.syms[g].determinant()))
        .count() as u64;
    let figures = inst.shapes.len();
    let n = inst.shapes[0].len();
    let k64 = k as u64;
    let n64 = n as u64;
    let f64_ = figures as u64;
    let mut vars = f64_ * k64 * n64 + 2 * k64 * n64;
    let mut clauses =
        f64_ * n64 * (1 + k64 * k64.saturating_sub(1) / 2) + 4 * k64 * n64 + k64 * f64_ * n64;
    // Incompatible pairs (both orders are counted by `apart` rows).
    let pairs: u64 = incompat.iter().map(|g| g.edges() / 2).sum();
    clauses = clauses.saturating_add(pairs.saturating_mul(k64));
    let mut motions = 0u64;
    if style == MotionEncoding::Shifts {
        let admitted: Vec<usize> = (0..inst.syms.len())
            .filter(|&g| set.admits(g, inst.syms[g].determinant()))
            .collect();
        let q = clique.min(k);
        let anchors = if q > 0 { &clique_cells[..q] } else { &[0][..] };
        // Interrupted: as large as can be (the caller asks the flag).
        let (v, c) = crate::shift_encoding::shifts_size(inst, k, &admitted, anchors, interrupted)
            .unwrap_or((u64::MAX, u64::MAX));
        return EncodingSize {
            vars: vars.saturating_add(v).min(usize::MAX as u64) as usize,
            clauses: clauses.saturating_add(c).min(usize::MAX as u64) as usize,
            motions: v.min(usize::MAX as u64) as usize,
        };
    }
    for f in 1..figures {
        let all = motion_count(inst, f, set) as u64;
        let one_anchored = all.min(syms * inst.shapes[f].len() as u64);
        let m = all * (k64 - anchored) + one_anchored * anchored;
        motions = motions.saturating_add(m);
        let per = (n + inst.shapes[f].len()) as u64;
        clauses = clauses.saturating_add(m.saturating_mul(per + 1));
    }
    vars = vars.saturating_add(motions);
    EncodingSize {
        vars: vars.min(usize::MAX as u64) as usize,
        clauses: clauses.min(usize::MAX as u64) as usize,
        motions: motions.min(usize::MAX as u64) as usize,
    }
}

/// Direct encodings estimated at most this many bytes are always taken.
const DIRECT_ALWAYS_BYTES: u64 = 64 << 20;

/// The motion encoding [`MotionEncoding::Auto`] stands for: the direct one
/// when it is estimated at most [`DIRECT_ALWAYS_BYTES`] or at most twice
/// the shift chain's size, else the shift chain.
pub(crate) fn choose(
    inst: &Instance,
    k: usize,
    set: MotionSet,
    clique: &[usize],
    incompat: &[Incompatibility],
    interrupted: &dyn Fn() -> bool,
) -> MotionEncoding {
    let direct = estimate(
        inst,
        k,
        (set, MotionEncoding::Direct),
        clique,
        incompat,
        interrupted,
    )
    .bytes(false);
    if direct <= DIRECT_ALWAYS_BYTES {
        return MotionEncoding::Direct;
    }
    let shifts = estimate(
        inst,
        k,
        (set, MotionEncoding::Shifts),
        clique,
        incompat,
        interrupted,
    )
    .bytes(false);
    if direct <= shifts.saturating_mul(2) {
        MotionEncoding::Direct
    } else {
        MotionEncoding::Shifts
    }
}

/// Encodes "at most `k` pieces" with motions from `set` into `sat`.
///
/// `clique` lists cells of shape 0 that are pairwise incompatible (at most
/// `k` of them are used); `incompat[f]` is shape `f`'s incompatibility graph.
/// `None` when `interrupted` says so (it is asked for every piece and
/// motion).
pub(crate) fn encode(
    inst: &Instance,
    sat: &mut Sat<'_>,
    k: usize,
    (set, style): (MotionSet, MotionEncoding),
    clique: &[usize],
    incompat: &[Incompatibility],
    interrupted: &dyn Fn() -> bool,
) -> Option<Encoding> {
    let style = match style {
        MotionEncoding::Auto => choose(inst, k, set, clique, incompat, interrupted),
        s => s,
    };
    let cell: Vec<Vec<Vec<i32>>> = inst
        .shapes
        .iter()
        .map(|s| {
            (0..k)
                .map(|_| (0..s.len()).map(|_| sat.var()).collect())
                .collect()
        })
        .collect();
    one_piece_per_cell(sat, &cell, k, interrupted)?;
    let mut anchor = order_pieces(inst, sat, &cell, k, clique);
    no_cell_cut_off(inst, sat, &cell, k, interrupted)?;
    incompatible_apart(inst, sat, &cell, incompat, interrupted)?;
    let mut motion: Vec<Vec<Vec<(i32, Motion)>>> = vec![Vec::new()];
    let mut shift_vars = 0;
    for f in 1..inst.shapes.len() {
        if style == MotionEncoding::Shifts {
            shift_vars += shifts_of_shape(inst, sat, &cell, (f, set), &anchor, interrupted)?;
            motion.push(vec![Vec::new(); k]);
            continue;
        }
        motion.push(motions_of_shape(
            inst,
            sat,
            &cell,
            (f, set),
            &anchor,
            interrupted,
        )?);
    }
    anchor.truncate(k);
    let cube = cube_clause(&cell, &motion, &anchor);
    Some(Encoding {
        k,
        anchors: anchor,
        cell,
        motion,
        shift_vars,
        cube,
    })
}

/// The literals of [`Encoding::cube`]: each is a clause of the formula
/// (`motions_of_shape`'s at-least-one motion, `one_piece_per_cell`'s
/// at-least-one piece).
fn cube_clause(
    cell: &[Vec<Vec<i32>>],
    motion: &[Vec<Vec<(i32, Motion)>>],
    anchor: &[usize],
) -> Vec<i32> {
    if let Some(first) = motion.get(1).and_then(|m| m.first()) {
        if first.len() >= 2 {
            return first.iter().map(|(v, _)| *v).collect();
        }
    }
    let n = cell[0].first().map_or(0, Vec::len);
    // The middle cell, or the next one no piece is anchored at.
    let c = (0..n)
        .map(|i| (n / 2 + i) % n.max(1))
        .find(|c| !anchor.contains(c))
        .unwrap_or(0);
    cell[0].iter().map(|piece| piece[c]).collect()
}

/// Exactly one piece per cell (`cell[f][i][c]`: cell `c` of shape `f` is
/// in piece `i`). `None` when interrupted.
fn one_piece_per_cell(
    sat: &mut Sat<'_>,
    cell: &[Vec<Vec<i32>>],
    k: usize,
    interrupted: &dyn Fn() -> bool,
) -> Option<()> {
    for per_piece in cell {
        if interrupted() {
            return None;
        }
        for c in 0..per_piece[0].len() {
            if c.is_multiple_of(1024) && interrupted() {
                return None;
            }
            let lits: Vec<i32> = per_piece.iter().map(|p| p[c]).collect();
            sat.add(&lits);
            for i in 0..k {
                for j in i + 1..k {
                    sat.add(&[-lits[i], -lits[j]]);
                }
            }
        }
    }
    Some(())
}

/// Symmetry breaking on piece order: the clique's cells in pieces
/// `0..q`, the later pieces ordered by their first cell. Returns the
/// anchors (the cell of shape 0 each first piece holds).
fn order_pieces(
    inst: &Instance,
    sat: &mut Sat<'_>,
    cell: &[Vec<Vec<i32>>],
    k: usize,
    clique: &[usize],
) -> Vec<usize> {
    let n = inst.shapes[0].len();
    let q = clique.len().min(k);
    let anchor: Vec<usize> = if q > 0 { clique[..q].to_vec() } else { vec![0] };
    for (i, &c) in clique.iter().take(q).enumerate() {
        sat.add(&[cell[0][i][c]]);
    }
    if q == 0 {
        // Piece 0 holds cell 0; later pieces are ordered by their first cell.
        sat.add(&[cell[0][0][0]]);
    }
    let ordered_from = if q == 0 { 0 } else { q };
    for i in ordered_from..k.saturating_sub(1) {
        // u[a]: piece i has a cell among 0..=a.
        let u: Vec<i32> = (0..n).map(|_| sat.var()).collect();
        sat.add(&[-u[0], cell[0][i][0]]);
        for a in 1..n {
            sat.add(&[-u[a], u[a - 1], cell[0][i][a]]);
        }
        sat.add(&[-cell[0][i + 1][0]]);
        for a in 1..n {
            sat.add(&[-cell[0][i + 1][a], u[a - 1]]);
        }
    }
    anchor
}

/// No cell of a piece with two or more cells is cut off from the rest:
/// `big[i]` holds when piece i has two cells (counted in shape 0), and
/// then every cell of the piece has a neighbour in it, in every shape.
/// `None` when interrupted.
fn no_cell_cut_off(
    inst: &Instance,
    sat: &mut Sat<'_>,
    cell: &[Vec<Vec<i32>>],
    k: usize,
    interrupted: &dyn Fn() -> bool,
) -> Option<()> {
    let shapes = &inst.shapes;
    #[allow(clippy::needless_range_loop)] // piece i of every shape
    for i in 0..k {
        if interrupted() {
            return None;
        }
        let big = sat.var();
        let mut seen_before: Option<i32> = None;
        for &x in &cell[0][i] {
            if let Some(s) = seen_before {
                sat.add(&[-x, -s, big]);
                let next = sat.var();
                sat.add(&[-s, next]);
                sat.add(&[-x, next]);
                seen_before = Some(next);
            } else {
                seen_before = Some(x);
            }
        }
        for (f, shape) in shapes.iter().enumerate() {
            for (c, adj) in shape.adj.iter().enumerate() {
                let mut clause = vec![-cell[f][i][c], -big];
                clause.extend(adj.iter().map(|&d| cell[f][i][d]));
                sat.add(&clause);
            }
        }
    }
    Some(())
}

/// Incompatible cells never share a piece. `None` when interrupted.
fn incompatible_apart(
    inst: &Instance,
    sat: &mut Sat<'_>,
    cell: &[Vec<Vec<i32>>],
    incompat: &[Incompatibility],
    interrupted: &dyn Fn() -> bool,
) -> Option<()> {
    let shapes = &inst.shapes;
    for (f, g) in incompat.iter().enumerate() {
        if g.edges() == 0 {
            continue;
        }
        for a in 0..shapes[f].len() {
            if a.is_multiple_of(64) && interrupted() {
                return None;
            }
            for b in a + 1..shapes[f].len() {
                if g.apart(a, b) {
                    for piece in &cell[f] {
                        sat.add(&[-piece[a], -piece[b]]);
                    }
                }
            }
        }
    }
    Some(())
}

/// The symmetries piece `i` may take into shape `f`: those of `set`, and
/// for the first piece only one per coset of shape `f`'s symmetries (see
/// [`motions_of_shape`]).
fn piece_symmetries(inst: &Instance, f: usize, set: MotionSet) -> (Vec<usize>, Vec<bool>) {
    let group: Vec<usize> = self_symmetries(inst, f)
        .into_iter()
        .filter(|&h| set.admits(h, inst.syms[h].determinant()))
        .filter(|&h| inst.target_symmetries || h == 0)
        .collect();
    let reps = coset_representatives(inst, &group);
    let admitted = (0..inst.syms.len())
        .filter(|&g| set.admits(g, inst.syms[g].determinant()))
        .collect();
    (admitted, reps)
}

/// [`motions_of_shape`] as shift chains ([`MotionEncoding::Shifts`]):
/// the same symmetries per piece, the anchored pieces' shifts limited by
/// their anchor. Returns the shift variables; `None` when interrupted.
fn shifts_of_shape(
    inst: &Instance,
    sat: &mut Sat<'_>,
    cell: &[Vec<Vec<i32>>],
    (f, set): (usize, MotionSet),
    anchor: &[usize],
    interrupted: &dyn Fn() -> bool,
) -> Option<usize> {
    let (admitted, reps) = piece_symmetries(inst, f, set);
    let mut count = 0;
    for (i, (from, into)) in cell[0].iter().zip(&cell[f]).enumerate() {
        let syms: Vec<usize> = admitted
            .iter()
            .copied()
            .filter(|&g| i != 0 || reps[g])
            .collect();
        count += crate::shift_encoding::motions_by_shifts(
            inst,
            sat,
            (f, &syms),
            (from, into),
            anchor.get(i).copied(),
            interrupted,
        )?;
    }
    Some(count)
}

/// The symmetries of shape `f` admitted by `set` as maps of its cells:
/// `(symmetry index, the image of each cell)`.
fn cell_maps(inst: &Instance, f: usize, set: MotionSet) -> Vec<(usize, Vec<usize>)> {
    let s = &inst.shapes[f];
    let min = *s.points.iter().min().expect("non-empty");
    self_symmetries(inst, f)
        .into_iter()
        .filter(|&h| set.admits(h, inst.syms[h].determinant()))
        .map(|h| {
            let g = &inst.syms[h];
            let low = s
                .points
                .iter()
                .map(|p| g.apply(*p))
                .min()
                .expect("non-empty");
            let t = min - low;
            let map = s
                .points
                .iter()
                .map(|p| s.index[&(g.apply(*p) + t)])
                .collect();
            (h, map)
        })
        .collect()
}

/// Which motions of `all` (into shape 1) the first piece keeps when the
/// symmetries of both shapes are broken: one per orbit.
///
/// Soundness: let `σ` be a symmetry of shape 0 that fixes the first
/// anchor `c0` and maps the anchored cells onto themselves, and `τ` one of
/// shape 1. A dissection with piece motions `m_i` into shape 1 gives
/// another one: pieces `σ(P_i)`, motions `τ ∘ m_i ∘ σ⁻¹` into shape 1 (and
/// `m_i ∘ σ⁻¹` into the others); the piece at `c0` is still the first, the
/// other anchored pieces are renumbered after their anchors, the free
/// pieces after their first cells. The first piece's motion `m` becomes
/// `τ ∘ m ∘ σ⁻¹`: symmetry `lin(τ) g lin(σ)⁻¹`, anchor image `τ(m(c0))`
/// (as `σ(c0) = c0`). So some dissection, if any, has the first piece at
/// the least `(symmetry, anchor image)` of its orbit; only those motions
/// are kept (with no such `σ` but the identity this is the coset
/// reduction of [`piece_symmetries`], which it replaces for shape 1).
/// Held by `tests/exact.rs` `source_symmetry_breaking_matches_brute_force`.
fn orbit_representatives(
    inst: &Instance,
    set: MotionSet,
    anchor: &[usize],
    all: &[Motion],
) -> Vec<bool> {
    let c0 = anchor.first().copied().unwrap_or(0);
    let mut anchored: Vec<usize> = anchor.to_vec();
    anchored.sort_unstable();
    let sources: Vec<(usize, Vec<usize>)> = cell_maps(inst, 0, set)
        .into_iter()
        .filter(|(_, map)| {
            let mut img: Vec<usize> = anchored.iter().map(|&a| map[a]).collect();
            img.sort_unstable();
            map[c0] == c0 && img == anchored
        })
        .collect();
    let targets: Vec<(usize, Vec<usize>)> = cell_maps(inst, 1, set)
        .into_iter()
        .filter(|(h, _)| inst.target_symmetries || *h == 0)
        .collect();
    let shape1 = &inst.shapes[1];
    let p0 = inst.shapes[0].points[c0];
    let key = |m: &Motion| shape1.index.get(&m.transform.apply(p0)).copied();
    let index = |s: dissect_core::lattice::Symmetry| inst.syms.iter().position(|x| *x == s);
    all.iter()
        .map(|m| {
            let Some(b) = key(m) else {
                // Not a motion the anchored piece can take.
                return true;
            };
            sources.iter().all(|(hs, _)| {
                let inv = inst.syms[*hs].inverse();
                targets.iter().all(|(ht, tmap)| {
                    let g = inst.syms[*ht].compose(&inst.syms[m.sym]).compose(&inv);
                    index(g).is_none_or(|g| (g, tmap[b]) >= (m.sym, b))
                })
            })
        })
        .collect()
}

/// The motion variables of each piece into shape `f` (from `set`) and
/// the clauses that tie a piece's cells in shape 0 to its cells in shape
/// `f`. `None` when interrupted.
fn motions_of_shape(
    inst: &Instance,
    sat: &mut Sat<'_>,
    cell: &[Vec<Vec<i32>>],
    (f, set): (usize, MotionSet),
    anchor: &[usize],
    interrupted: &dyn Fn() -> bool,
) -> Option<Vec<Vec<(i32, Motion)>>> {
    let shapes = &inst.shapes;
    let all = motions_into(inst, f, set, interrupted)?;
    let (_, reps) = piece_symmetries(inst, f, set);
    let orbits =
        (f == 1 && inst.source_symmetries).then(|| orbit_representatives(inst, set, anchor, &all));
    let target = &shapes[f];
    let mut per_piece = Vec::with_capacity(cell[0].len());
    for (i, (from, into)) in cell[0].iter().zip(&cell[f]).enumerate() {
        let anchor_cell = anchor.get(i).copied();
        let allowed: Vec<Motion> = all
            .iter()
            .enumerate()
            .filter(|(j, m)| match (i, &orbits) {
                (0, Some(keep)) => keep[*j],
                (0, None) => reps[m.sym],
                _ => true,
            })
            .map(|(_, m)| m)
            .filter(|m| match anchor_cell {
                Some(c) => target
                    .index
                    .contains_key(&m.transform.apply(shapes[0].points[c])),
                None => true,
            })
            .copied()
            .collect();
        let vars: Vec<(i32, Motion)> = allowed.into_iter().map(|m| (sat.var(), m)).collect();
        let lits: Vec<i32> = vars.iter().map(|(v, _)| *v).collect();
        sat.add(&lits);
        for &(mv, m) in &vars {
            if interrupted() {
                return None;
            }
            let t = m.transform;
            for (a, p) in shapes[0].points.iter().enumerate() {
                let img = t.apply(*p);
                match target.index.get(&img) {
                    Some(&b) => sat.add(&[-from[a], -mv, into[b]]),
                    None => sat.add(&[-from[a], -mv]),
                }
            }
            let inv = t.inverse();
            for (b, q) in target.points.iter().enumerate() {
                let pre = inv.apply(*q);
                match shapes[0].index.get(&pre) {
                    Some(&a) => sat.add(&[-into[b], -mv, from[a]]),
                    None => sat.add(&[-into[b], -mv]),
                }
            }
        }
        per_piece.push(vars);
    }
    Some(per_piece)
}

impl Encoding {
    /// The pieces of the last model: `pieces[f][i]` are cell indices of
    /// shape `f`; pieces empty in the model are dropped.
    pub fn decode(&self, sat: &Sat<'_>) -> Vec<Vec<Vec<usize>>> {
        self.decode_with(&|v| sat.value(v))
    }

    /// [`Encoding::decode`] of the model whose variables are `value`.
    pub fn decode_with(&self, value: &dyn Fn(i32) -> bool) -> Vec<Vec<Vec<usize>>> {
        let mut pieces: Vec<Vec<Vec<usize>>> = self
            .cell
            .iter()
            .map(|per_piece| {
                per_piece
                    .iter()
                    .map(|vars| (0..vars.len()).filter(|&c| value(vars[c])).collect())
                    .collect()
            })
            .collect();
        let keep: Vec<bool> = (0..self.k).map(|i| !pieces[0][i].is_empty()).collect();
        for p in pieces.iter_mut() {
            let mut i = 0;
            p.retain(|_| {
                i += 1;
                keep[i - 1]
            });
        }
        pieces
    }

    /// The number of motion variables (shift variables with
    /// [`MotionEncoding::Shifts`]).
    pub fn motions(&self) -> usize {
        self.motion.iter().flatten().map(|v| v.len()).sum::<usize>() + self.shift_vars
    }
}
