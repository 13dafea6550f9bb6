//! Sectors: one large common piece, and what is left of the figures cut
//! into small balanced sectors that are dissected exactly.
//!
//! Figures that are mostly alike (a rasterized disc and a square, an
//! octagon and a rectangle) share one large piece: the largest connected
//! part common to every figure under the motions of the greedy's first step.
//! What is left of each figure lies along the boundary in thin strips, and
//! the greedy cuts those strips into cells and slivers. Here the leftover
//! cells of every figure are ordered by their angle around the large piece
//! (in the pivot's frame) and cut at angles where every figure has had the
//! same number of leftover cells so far, into sectors of equal area in every
//! figure. Each sector is a small dissection problem of its own, solved
//! exactly (fewest pieces, and among those none of fewer than three cells
//! when that is possible) by the [`Repair`] hook; the large piece and every
//! sector's pieces together are a dissection of the figures.
//!
//! The angle only decides which sectors are compact; any cut at balanced
//! positions gives sectors of equal area, so the answer is a dissection
//! whatever the lattice (on `cubic` the angle is taken about the `z` axis).

use std::sync::atomic::AtomicBool;

use crate::lattice::{Cell, Point};
use crate::solver::candidate::Problem;
use crate::solver::greedy::{common_part, components, FREE};
use crate::solver::Repair;

/// Sectors hold at least this many leftover cells of each figure (the
/// last one may hold fewer only when it is the only one).
const MIN_SECTOR_CELLS: usize = 24;

/// No sector is solved when one holds more leftover cells of a figure than
/// this: the exact search would not finish.
const MAX_SECTOR_CELLS: usize = 120;

/// The large common piece and the sectors of what is left, as cell indices
/// of each figure's shape.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Plan {
    /// `big[f]`: the large piece's cells in figure `f`.
    pub(crate) big: Vec<Vec<u32>>,
    /// `sectors[s][f]`: the leftover cells of figure `f` in sector `s`
    /// (as many in every figure).
    pub(crate) sectors: Vec<Vec<Vec<u32>>>,
}

/// Cut sets tried per frame: the balanced values whose cuts pass through
/// the widest angular gaps between leftover cells.
const PLANS: usize = 3;

/// Plans with figure `pivot` as the frame (at most [`PLANS`], the most
/// promising first); none when the figures share no piece that leaves
/// something to cut, or every cut set leaves a sector too large to solve
/// exactly.
pub(crate) fn plans(problem: &Problem, pivot: usize) -> Vec<Plan> {
    let Some((big, entries)) = leftover(problem, pivot) else {
        return Vec::new();
    };
    let nf = problem.shapes.len();
    let len = entries.len();
    let mut out = Vec::new();
    for cuts in balanced_cuts(&entries, nf) {
        let mut sectors = Vec::with_capacity(cuts.len());
        for (i, &from) in cuts.iter().enumerate() {
            let to = if i + 1 < cuts.len() {
                cuts[i + 1]
            } else {
                cuts[0] + len
            };
            let mut sector = vec![Vec::new(); nf];
            for e in from..to {
                let (_, f, c) = entries[e % len];
                sector[f].push(c);
            }
            for cells in &mut sector {
                cells.sort_unstable();
            }
            sectors.push(sector);
        }
        // In a canonical order, so that the same sectors found from
        // another frame compare equal.
        sectors.sort();
        if sectors.iter().all(|s| s[0].len() <= MAX_SECTOR_CELLS) {
            out.push(Plan {
                big: big.clone(),
                sectors,
            });
            if out.len() == PLANS {
                break;
            }
        }
    }
    out
}

/// A leftover cell: its angle about the large piece (pivot's frame), its
/// figure and its index there.
type Entry = (f64, usize, u32);

/// The large piece in every figure (`big[f]`) and every figure's leftover
/// cells in order of angle; `None` when the largest common part is the
/// whole figure or less than half of it.
fn leftover(problem: &Problem, pivot: usize) -> Option<(Vec<Vec<u32>>, Vec<Entry>)> {
    let shapes = &problem.shapes;
    let nf = shapes.len();
    let labels: Vec<Vec<u16>> = shapes.iter().map(|s| vec![FREE; s.len()]).collect();
    let (common, motions) = common_part(problem, pivot, &labels);
    let comps = components(&shapes[pivot], &common);
    // The largest component (the first of the largest, for determinism).
    let big_pivot = comps
        .iter()
        .enumerate()
        .max_by_key(|(i, c)| (c.len(), std::cmp::Reverse(*i)))
        .map(|(_, c)| c.clone())?;
    let n = shapes[pivot].len();
    if big_pivot.len() == n || big_pivot.len() < n / 2 {
        return None;
    }
    let mut big: Vec<Vec<u32>> = Vec::with_capacity(nf);
    let mut entries: Vec<Entry> = Vec::new();
    let centre = centroid(big_pivot.iter().map(|&c| shapes[pivot].point(c)));
    for (f, motion) in motions.iter().enumerate() {
        // Into figure f, and back into the pivot's frame.
        let (sym, inv, t) = match *motion {
            None => (None, None, Point::new(0, 0, 0)),
            Some((s, t)) => {
                let sym = problem.geo.syms[s];
                (Some(sym), Some(sym.inverse()), t)
            }
        };
        let mut in_big = vec![false; shapes[f].len()];
        let mut cells = Vec::with_capacity(big_pivot.len());
        for &c in &big_pivot {
            let p = shapes[pivot].point(c);
            let q = sym.map_or(p, |g| g.apply(p) + t);
            let j = shapes[f].lookup(q)?;
            in_big[j as usize] = true;
            cells.push(j);
        }
        cells.sort_unstable();
        big.push(cells);
        for c in (0..shapes[f].len() as u32).filter(|&c| !in_big[c as usize]) {
            let q = shapes[f].point(c);
            let p = inv.map_or(q, |g| g.apply(q - t));
            let angle = (f64::from(p[1]) - centre[1]).atan2(f64::from(p[0]) - centre[0]);
            entries.push((angle, f, c));
        }
    }
    entries.sort_by(|a, b| a.0.total_cmp(&b.0).then((a.1, a.2).cmp(&(b.1, b.2))));
    Some((big, entries))
}

/// Sets of cut positions in the circular order of `entries` (a cut before
/// entry `i`) between which every figure has as many entries, the most
/// promising first. Cuts at positions whose running counts (figure 0's
/// less each other figure's) take one value are balanced; for each value
/// its positions are thinned so that each sector holds at least
/// [`MIN_SECTOR_CELLS`] cells of figure 0, and the values are ranked by the
/// mean angular gap their cuts pass through (a cut through a gap parts
/// strips that no piece needs to join), then by more sectors.
fn balanced_cuts(entries: &[Entry], nf: usize) -> Vec<Vec<usize>> {
    let len = entries.len();
    if len == 0 {
        return Vec::new();
    }
    let mut run = vec![0i64; nf];
    let mut keys: Vec<(Vec<i64>, usize)> = Vec::with_capacity(len);
    for (i, &(_, f, _)) in entries.iter().enumerate() {
        keys.push(((1..nf).map(|g| run[0] - run[g]).collect(), i));
        run[f] += 1;
    }
    if (1..nf).any(|g| run[g] != run[0]) {
        return Vec::new();
    }
    // Figure 0's cells before each position, to size the sectors.
    let mut before = vec![0usize; len + 1];
    for (i, &(_, f, _)) in entries.iter().enumerate() {
        before[i + 1] = before[i] + usize::from(f == 0);
    }
    let total = before[len];
    let gap = |i: usize| {
        let prev = if i == 0 {
            entries[len - 1].0 - std::f64::consts::TAU
        } else {
            entries[i - 1].0
        };
        entries[i].0 - prev
    };
    // Positions grouped by value (sorted by value, then position).
    keys.sort();
    let mut candidates: Vec<(f64, usize, Vec<usize>)> = Vec::new();
    let mut i = 0;
    while i < keys.len() {
        let j = i + keys[i..].iter().take_while(|k| k.0 == keys[i].0).count();
        let positions: Vec<usize> = keys[i..j].iter().map(|k| k.1).collect();
        i = j;
        let mut cuts = vec![positions[0]];
        for &p in &positions[1..] {
            let last = *cuts.last().expect("one cut");
            let this = before[p] - before[last];
            let rest = total - before[p] + before[cuts[0]];
            if this >= MIN_SECTOR_CELLS && rest >= MIN_SECTOR_CELLS {
                cuts.push(p);
            }
        }
        let mean_gap = cuts.iter().map(|&c| gap(c)).sum::<f64>() / cuts.len() as f64;
        candidates.push((mean_gap, cuts.len(), cuts));
    }
    candidates.sort_by(|a, b| b.0.total_cmp(&a.0).then(b.1.cmp(&a.1)).then(a.2.cmp(&b.2)));
    candidates.dedup_by(|a, b| a.2 == b.2);
    candidates.into_iter().map(|(_, _, cuts)| cuts).collect()
}

/// The mean of points, as `[x, y]`.
fn centroid(points: impl Iterator<Item = Point>) -> [f64; 2] {
    let (mut x, mut y, mut n) = (0.0f64, 0.0f64, 0.0f64);
    for p in points {
        x += f64::from(p[0]);
        y += f64::from(p[1]);
        n += 1.0;
    }
    [x / n.max(1.0), y / n.max(1.0)]
}

/// The plan's dissection, `pieces[f][i]` (the large piece first), with at
/// most `max_pieces` pieces in all, when the repairer dissects every
/// sector within what is left of that; `None` when one fails or a stop is
/// raised.
pub(crate) fn dissect(
    figures: &[crate::figure::Figure],
    plan: &Plan,
    max_pieces: usize,
    repairer: &dyn Repair,
    stop: &AtomicBool,
) -> Option<Vec<Vec<Vec<Cell>>>> {
    let nf = figures.len();
    let cell = |f: usize, c: u32| figures[f].cells()[c as usize];
    let mut pieces: Vec<Vec<Vec<Cell>>> = (0..nf)
        .map(|f| vec![plan.big[f].iter().map(|&c| cell(f, c)).collect()])
        .collect();
    for (i, sector) in plan.sectors.iter().enumerate() {
        if stop.load(std::sync::atomic::Ordering::Relaxed) {
            return None;
        }
        // Every sector after this one needs a piece at least.
        let later = plan.sectors.len() - i - 1;
        let cap = max_pieces.checked_sub(pieces[0].len() + later)?;
        if cap == 0 {
            return None;
        }
        let cells: Vec<Vec<Cell>> = (0..nf)
            .map(|f| sector[f].iter().map(|&c| cell(f, c)).collect())
            .collect();
        let found = repairer.dissect(&cells, cap, stop)?;
        if found.len() != nf || found[0].len() > cap {
            return None;
        }
        for (f, fp) in found.into_iter().enumerate() {
            pieces[f].extend(fp);
        }
    }
    Some(pieces)
}
