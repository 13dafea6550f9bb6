//! The interlocking search of `--min-level` (and `--assemblable`): a local
//! search that turns a valid dissection the assembly rules refuse into one
//! they accept.
//!
//! The heuristic cuts pieces by matching areas and never aims at
//! interlocking, so its dissections come apart at level 1. This search
//! starts from them and moves to neighbouring dissections that stay valid
//! in every figure by construction: it takes two or three touching pieces,
//! and the union of their cells in each figure is a small dissection
//! problem of its own; every dissection of it into as many pieces
//! ([`dissect_exact::enumerate`], issue 29's enumeration) put back in place
//! of those pieces is a valid dissection of the whole (the other pieces
//! are untouched, and each new piece is congruent in every figure). Among
//! them it keeps the one closest to interlocking by
//! [`interlock_distance`](dissect_puzzle::disassembly::interlock_distance) (summed over
//! the figures: the groups that would come free at once); a candidate with
//! none is judged by the constraints in full (the disassembly search). When
//! a piece count stays stuck, a piece is split in two (the same cut in
//! every figure, through the piece's motion), so the search may spend one
//! or two more pieces than it started with. It ends at the deadline, the
//! stop flag or its work budget, and every dissection it returns has
//! passed the verifier and the constraints.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use dissect_core::{Cell, Figure, LatticeKind};
use dissect_exact::EnumerateOptions;
use dissect_puzzle::disassembly::interlock_distance;
use dissect_puzzle::{Constraints, Motions};

/// A dissection: `pieces[f][i]`, the cells of piece `i` in figure `f`.
pub(crate) type Pieces = Vec<Vec<Vec<Cell>>>;

/// The longest one enumeration of a neighbourhood may take.
const NEIGHBOURHOOD_TIME: Duration = Duration::from_millis(800);

/// The most alternatives of one neighbourhood scored.
const MAX_ALTERNATIVES: usize = 256;

/// Steps without a better score before a piece is split.
const STUCK_STEPS: usize = 12;

/// The most pieces the search may add to the dissection it starts from.
pub(crate) const MAX_EXTRA_PIECES: usize = 2;

/// The most cells of a neighbourhood (the union of the pieces cut again,
/// in one figure): larger ones are not enumerated.
const MAX_NEIGHBOURHOOD_CELLS: usize = 96;

/// What the search works with.
pub(crate) struct Interlock<'a> {
    /// The figures (in the order the run searches them).
    pub(crate) figures: &'a [Figure],
    /// Whether pieces may be turned over.
    pub(crate) mirror: bool,
    /// The constraints every answer honours.
    pub(crate) constraints: &'a Constraints,
    /// The lattice's motions.
    pub(crate) motions: &'a Motions,
    /// Raised to stop.
    pub(crate) stop: &'a AtomicBool,
    /// The search ends at this instant.
    pub(crate) deadline: Option<Instant>,
    /// The most steps (neighbourhoods tried) in all: the work rule of a
    /// run without a time limit.
    pub(crate) steps: usize,
    /// The seed of its choices.
    pub(crate) seed: u64,
}

/// A small deterministic generator (splitmix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

impl Interlock<'_> {
    fn lattice(&self) -> LatticeKind {
        self.figures[0].lattice()
    }

    fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed) || self.deadline.is_some_and(|d| Instant::now() >= d)
    }

    /// How far `pieces` is from what the constraints ask: with a least
    /// level of 2 or more, the groups that come free at once (0: every
    /// figure holds together at the start); else the figures that break
    /// the assembly rules.
    fn score(&self, pieces: &Pieces) -> usize {
        if self.constraints.min_level().is_some_and(|m| m >= 2) {
            let l = self.lattice().lattice();
            let d: usize = pieces.iter().map(|fig| interlock_distance(l, fig)).sum();
            // Nothing comes free at once, yet it is refused (locked, or
            // a level too low): next to an answer, but not one.
            if d == 0 && !self.accepted(pieces) {
                return 1;
            }
            d
        } else {
            self.constraints.check(self.motions, pieces).len()
        }
    }

    /// Whether `pieces` is an answer: verified and honouring every
    /// constraint.
    fn accepted(&self, pieces: &Pieces) -> bool {
        dissect_core::verify::verify_pieces(self.lattice(), self.mirror, self.figures, pieces)
            .is_ok()
            && self.constraints.check(self.motions, pieces).is_empty()
    }

    /// Searches from each of `starts` (valid dissections, the fewest
    /// pieces first) in turn, sharing the work budget; the first answer.
    pub(crate) fn run(&self, starts: &[Pieces]) -> Option<Pieces> {
        let mut rng = Rng(self.seed ^ 0x1e7e_c0c5);
        let per_start = (self.steps / starts.len().max(1)).max(1);
        for start in starts {
            if self.stopped() {
                return None;
            }
            if let Some(found) = self.from(start.clone(), per_start, &mut rng) {
                return Some(found);
            }
        }
        None
    }

    /// The local search from one dissection, for at most `steps` steps.
    fn from(&self, mut current: Pieces, steps: usize, rng: &mut Rng) -> Option<Pieces> {
        let k0 = current.first().map_or(0, Vec::len);
        let mut score = self.score(&current);
        let mut stuck = 0;
        for _ in 0..steps {
            if self.stopped() {
                return None;
            }
            if score == 0 && self.accepted(&current) {
                return Some(current);
            }
            let group = self.group(&current, rng);
            let mut best: Option<(usize, Pieces)> = None;
            for alt in self.alternatives(&current, &group, rng) {
                let s = self.score(&alt);
                if s == 0 && self.accepted(&alt) {
                    return Some(alt);
                }
                if best.as_ref().is_none_or(|(b, _)| s < *b) {
                    best = Some((s, alt));
                }
            }
            match best {
                Some((s, alt)) if s <= score => {
                    stuck = if s < score { 0 } else { stuck + 1 };
                    score = s;
                    current = alt;
                }
                _ => stuck += 1,
            }
            if stuck >= STUCK_STEPS && current[0].len() < k0 + MAX_EXTRA_PIECES {
                if let Some(split) = self.split(&current, rng) {
                    current = split;
                    score = self.score(&current);
                }
                stuck = 0;
            }
        }
        None
    }

    /// Two touching pieces of the first figure (three, one time in three,
    /// when there are three), chosen at random.
    fn group(&self, pieces: &Pieces, rng: &mut Rng) -> Vec<usize> {
        let first = &pieces[0];
        let touching = touching(self.lattice(), first);
        let a = rng.below(first.len());
        let mut group = vec![a];
        let want = if first.len() >= 3 && rng.below(3) == 0 {
            3
        } else {
            2
        };
        while group.len() < want {
            let near: Vec<usize> = group
                .iter()
                .flat_map(|g| touching[*g].iter().copied())
                .filter(|p| !group.contains(p))
                .collect();
            if near.is_empty() {
                break;
            }
            group.push(near[rng.below(near.len())]);
        }
        group.sort_unstable();
        group
    }

    /// Every dissection of the union of `group`'s pieces (in each figure)
    /// into as many pieces, put in place of them (at most
    /// [`MAX_ALTERNATIVES`], in a random order), the current one left out.
    fn alternatives(&self, pieces: &Pieces, group: &[usize], rng: &mut Rng) -> Vec<Pieces> {
        if group.len() < 2 {
            return Vec::new();
        }
        let lattice = self.lattice();
        let mut subs = Vec::new();
        for fig in pieces {
            let cells: Vec<Cell> = group.iter().flat_map(|g| fig[*g].clone()).collect();
            if cells.len() > MAX_NEIGHBOURHOOD_CELLS {
                return Vec::new();
            }
            match Figure::new(lattice, cells) {
                Ok(f) => subs.push(f),
                Err(_) => return Vec::new(),
            }
        }
        let until = Instant::now() + NEIGHBOURHOOD_TIME;
        let deadline = Some(self.deadline.map_or(until, |d| d.min(until)));
        let options = EnumerateOptions {
            mirror: self.mirror,
            pieces: Some(group.len()),
            deadline,
            ..EnumerateOptions::default()
        };
        let Ok(found) = dissect_exact::enumerate(&subs, &options, self.stop, &()) else {
            return Vec::new();
        };
        let mut out: Vec<Pieces> = found
            .dissections
            .into_iter()
            .map(|sub| {
                let mut next = pieces.clone();
                for (f, fig) in sub.into_iter().enumerate() {
                    for (j, mut cells) in fig.into_iter().enumerate() {
                        cells.sort_unstable();
                        next[f][group[j]] = cells;
                    }
                }
                next
            })
            .filter(|next| !same_cut(&next[0], &pieces[0]))
            .collect();
        for i in (1..out.len()).rev() {
            out.swap(i, rng.below(i + 1));
        }
        out.truncate(MAX_ALTERNATIVES);
        out
    }

    /// The dissection with one piece (the largest of the first figure)
    /// cut in two connected halves, the same cut in every figure (carried
    /// by the piece's motion), or `None` when no cut was found.
    fn split(&self, pieces: &Pieces, rng: &mut Rng) -> Option<Pieces> {
        let lattice = self.lattice();
        let first = &pieces[0];
        let i = (0..first.len()).max_by_key(|i| (first[*i].len(), usize::MAX - i))?;
        let piece = &first[i];
        if piece.len() < 2 {
            return None;
        }
        let motions: Vec<_> = pieces
            .iter()
            .map(|fig| self.motions.motion_between(piece, &fig[i], |_| true))
            .collect::<Option<Vec<_>>>()?;
        for _ in 0..8 {
            let half = grow_half(lattice, piece, piece[rng.below(piece.len())]);
            let rest: Vec<Cell> = piece
                .iter()
                .copied()
                .filter(|c| !half.contains(c))
                .collect();
            if dissect_core::figure::components_of(lattice, &rest).len() != 1 {
                continue;
            }
            let mut next = pieces.clone();
            for (f, m) in motions.iter().enumerate() {
                let moved = |cells: &[Cell]| -> Option<Vec<Cell>> {
                    let mut v: Vec<Cell> = cells
                        .iter()
                        .map(|c| self.motions.move_cell(m, *c))
                        .collect::<Option<Vec<Cell>>>()?;
                    v.sort_unstable();
                    Some(v)
                };
                next[f][i] = moved(&half)?;
                next[f].push(moved(&rest)?);
            }
            let ok = dissect_core::verify::verify_pieces(lattice, self.mirror, self.figures, &next);
            if ok.is_ok() {
                return Some(next);
            }
        }
        None
    }
}

/// For each piece, the pieces that touch it (share a face of a cell).
fn touching(lattice: LatticeKind, pieces: &[Vec<Cell>]) -> Vec<Vec<usize>> {
    let owner: HashMap<Cell, usize> = pieces
        .iter()
        .enumerate()
        .flat_map(|(i, p)| p.iter().map(move |c| (*c, i)))
        .collect();
    let l = lattice.lattice();
    pieces
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let mut near: Vec<usize> = p
                .iter()
                .flat_map(|c| l.neighbors(*c))
                .filter_map(|n| owner.get(&n).copied())
                .filter(|o| *o != i)
                .collect();
            near.sort_unstable();
            near.dedup();
            near
        })
        .collect()
}

/// Whether two cuts of a figure are the same partition (pieces in any
/// order, each sorted).
fn same_cut(a: &[Vec<Cell>], b: &[Vec<Cell>]) -> bool {
    let mut a = a.to_vec();
    let mut b = b.to_vec();
    a.sort();
    b.sort();
    a == b
}

/// Half of `piece`'s cells, grown breadth first from `seed` (connected).
fn grow_half(lattice: LatticeKind, piece: &[Cell], seed: Cell) -> Vec<Cell> {
    let l = lattice.lattice();
    let want = piece.len() / 2;
    let inside: std::collections::HashSet<Cell> = piece.iter().copied().collect();
    let mut seen = std::collections::HashSet::from([seed]);
    let mut order = vec![seed];
    let mut at = 0;
    while at < order.len() && order.len() < want {
        for n in l.neighbors(order[at]) {
            if order.len() < want && inside.contains(&n) && seen.insert(n) {
                order.push(n);
            }
        }
        at += 1;
    }
    order.sort_unstable();
    order
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_puzzle::disassembly::{disassemble, Disassembly, Limits};
    use dissect_testkit::disassembly::{replay, PlanMove};

    /// A 4×4×4 cube with a 2×2×2 cavity.
    const CAVITY: &str = "####\n####\n####\n####\n\n####\n#..#\n#..#\n####\n\n####\n#..#\n#..#\n####\n\n####\n####\n####\n####\n";

    #[test]
    fn a_level_one_cut_is_cut_again_until_it_interlocks() {
        let lattice = LatticeKind::Cubic;
        let cube = dissect_core::io::parse_figure(CAVITY, lattice).unwrap();
        let figures = vec![cube.clone(), cube.clone()];
        // Two halves (x < 2, x >= 2), in place in both figures: level 1.
        let halves: Vec<Vec<Cell>> = [true, false]
            .iter()
            .map(|left| {
                cube.cells()
                    .iter()
                    .copied()
                    .filter(|c| (c[0] < 2) == *left)
                    .collect()
            })
            .collect();
        let start = vec![halves.clone(), halves];
        let constraints = Constraints::none().with_assembly(false, Some(2));
        let motions = Motions::new(lattice, false);
        assert!(!constraints.check(&motions, &start).is_empty(), "level 1");
        let stop = AtomicBool::new(false);
        let search = Interlock {
            figures: &figures,
            mirror: false,
            constraints: &constraints,
            motions: &motions,
            stop: &stop,
            // No deadline: a loaded machine takes longer, by steps.
            deadline: None,
            steps: 400,
            seed: 1,
        };
        let found = search.run(&[start]).expect("an interlocking cut");
        dissect_core::verify::verify_pieces(lattice, false, &figures, &found).unwrap();
        assert!(constraints.check(&motions, &found).is_empty());
        assert!(found[0].len() <= 2 + MAX_EXTRA_PIECES);
        // Each figure's plan, replayed by the independent checker.
        for fig in &found {
            let Disassembly::Apart(plan) =
                disassemble(lattice.lattice(), fig, Limits::default()).unwrap()
            else {
                panic!("it comes apart");
            };
            let moves: Vec<PlanMove> = plan
                .moves
                .iter()
                .map(|m| PlanMove {
                    pieces: m.pieces.clone(),
                    by: m.by,
                    removed: m.removed,
                })
                .collect();
            let level = replay(fig, &moves).unwrap();
            assert_eq!(level, plan.level);
            assert!(level >= 2, "level {level}");
        }
        // A raised stop flag ends it at once, with nothing.
        stop.store(true, Ordering::SeqCst);
        let halves = found.clone();
        assert_eq!(search.run(&[halves]), None);
    }
}
