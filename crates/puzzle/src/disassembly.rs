//! Disassembly: can the pieces of a figure be taken apart by straight
//! moves, and how? The analysis of BurrTools.
//!
//! A *move* translates a group of pieces of one *part* together along one
//! lattice axis, any number of unit steps, each step free of the part's
//! other pieces. A move is a *removal* when the group's sweep along that
//! direction never meets the rest of the part: the group goes away to
//! infinity and becomes a part of its own, taken apart by later moves. A
//! figure is apart when every part holds one piece. Its *level* is the
//! 1-based index of the first removal: how many moves it takes before the
//! first piece (or group) comes free.
//!
//! The search is breadth first over the positions reachable from the
//! assembled figure, so the first removal found has the lowest level. The
//! groups tried in a direction `d` are the closures of the *blocking graph*:
//! `p` blocks `q` when `q` moved one step along `d` meets `p`, and the
//! smallest group that can move along `d` and holds `q` is everything `q`
//! reaches by blocking (a group that holds the part's *anchor*, its
//! largest piece, moves as its complement in the opposite direction, so
//! the anchor never moves and every position is one state). When a removal
//! splits a part, both halves are taken apart recursively from their
//! positions at that moment; when one of them cannot be, the search goes on
//! to the next removal. A part is *locked* only when every position it can
//! reach has been tried. Positions are bounded: a group that would leave
//! the rest's extent along its axis is removed instead, so every piece's
//! offset stays within the part's total size, and the number of states is
//! capped ([`Limits::max_states`]).
//!
//! Lattice-generic: pieces are sets of [`Point`]s, and the unit moves are
//! the lattice's translations ([`Lattice::modulus`] along each of the
//! [`Lattice::dim`] axes). A flat (2D) figure is a puzzle laid on a table:
//! every piece lifts off it ([`flat_plan`], level 1).

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use dissect_core::lattice::{Lattice, Point};
use dissect_core::Cell;

/// The default cap on the positions explored for one figure (all parts
/// together): a few hundred MiB at most.
pub const MAX_STATES: usize = 500_000;

/// The most pieces one figure may have (groups are bit sets).
pub const MAX_PIECES: usize = 64;

/// One move of a plan.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Move {
    /// The pieces moved together (indices of the dissection, ascending).
    pub pieces: Vec<usize>,
    /// The translation in lattice steps along one axis (`[dx, dy, dz]`, one
    /// coordinate non-zero). For a removal, how far the group goes until it
    /// has left the rest of its part's extent along that axis.
    pub by: [i32; 3],
    /// Whether the group is taken away to infinity along `by` (it becomes
    /// a part of its own).
    pub removed: bool,
}

/// A plan that takes a figure apart.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// The 1-based index of the first removal (0 for a single piece).
    pub level: usize,
    /// The moves, in order.
    pub moves: Vec<Move>,
}

/// Why a search ended without a decision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Undecided {
    /// The stop flag was raised or the deadline passed.
    Stopped,
    /// More than [`Limits::max_states`] positions would have been explored.
    TooManyStates,
}

/// The outcome of a disassembly search.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Disassembly {
    /// The figure comes apart by this plan (the lowest level there is).
    Apart(Plan),
    /// Every reachable position was tried: these pieces (indices of the
    /// dissection, ascending) hold together, so the figure cannot be taken
    /// apart by straight moves.
    Locked(Vec<usize>),
    /// The search ended before deciding.
    Undecided(Undecided),
}

impl Disassembly {
    /// The level when the figure comes apart.
    pub fn level(&self) -> Option<usize> {
        match self {
            Disassembly::Apart(p) => Some(p.level),
            _ => None,
        }
    }
}

/// Occurs when the pieces given cannot be a figure's pieces.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum DisassemblyError {
    /// Occurs when a piece has no cell.
    #[error("piece {piece} has no cell")]
    EmptyPiece {
        /// The piece (0-based).
        piece: usize,
    },
    /// Occurs when two pieces share a cell.
    #[error("pieces {a} and {b} overlap")]
    Overlap {
        /// One piece (0-based).
        a: usize,
        /// The other.
        b: usize,
    },
    /// Occurs when a figure has more than [`MAX_PIECES`] pieces.
    #[error("{found} pieces is more than the {MAX_PIECES} a disassembly search takes")]
    TooManyPieces {
        /// The number of pieces.
        found: usize,
    },
}

/// When a search must stop.
#[derive(Clone, Copy, Debug)]
pub struct Limits<'a> {
    /// Raised from elsewhere to stop the search.
    pub stop: Option<&'a AtomicBool>,
    /// The search stops at this instant.
    pub deadline: Option<Instant>,
    /// The most positions explored (all parts together).
    pub max_states: usize,
}

impl Default for Limits<'_> {
    fn default() -> Self {
        Limits {
            stop: None,
            deadline: None,
            max_states: MAX_STATES,
        }
    }
}

/// The plan of a flat figure: every piece but the last lifts off it, one
/// after the other (`by` is one step out of the plane, `[0, 0, 1]`), so its
/// level is 1 (0 for a single piece).
pub fn flat_plan(pieces: usize) -> Plan {
    let moves: Vec<Move> = (0..pieces.saturating_sub(1))
        .map(|i| Move {
            pieces: vec![i],
            by: [0, 0, 1],
            removed: true,
        })
        .collect();
    Plan {
        level: usize::from(!moves.is_empty()),
        moves,
    }
}

/// Searches a plan that takes apart the figure made of `pieces` (the cells
/// of each piece where the figure has them). On a flat lattice
/// ([`Lattice::dim`] below 3) every piece lifts off: [`flat_plan`].
pub fn disassemble(
    lattice: &dyn Lattice,
    pieces: &[Vec<Cell>],
    limits: Limits<'_>,
) -> Result<Disassembly, DisassemblyError> {
    if let Some(piece) = pieces.iter().position(|p| p.is_empty()) {
        return Err(DisassemblyError::EmptyPiece { piece });
    }
    if pieces.len() > MAX_PIECES {
        return Err(DisassemblyError::TooManyPieces {
            found: pieces.len(),
        });
    }
    let mut owner: HashMap<Point, usize> = HashMap::new();
    for (i, p) in pieces.iter().enumerate() {
        for c in p {
            if let Some(&a) = owner.get(&lattice.to_point(*c)) {
                if a != i {
                    return Err(DisassemblyError::Overlap { a, b: i });
                }
            }
            owner.insert(lattice.to_point(*c), i);
        }
    }
    if lattice.dim() < 3 {
        return Ok(Disassembly::Apart(flat_plan(pieces.len())));
    }
    let shapes: Vec<Shape> = pieces
        .iter()
        .map(|p| Shape::new(p.iter().map(|c| lattice.to_point(*c)).collect()))
        .collect();
    let mut search = Search {
        shapes,
        axes: lattice.dim(),
        step: lattice.modulus(),
        limits,
        states: 0,
        memo: HashMap::new(),
    };
    let ids: Vec<usize> = (0..pieces.len()).collect();
    let start = vec![Point::ORIGIN; pieces.len()];
    Ok(match search.part(&ids, &start) {
        Ok(Part::Apart(plan)) => Disassembly::Apart(plan),
        Ok(Part::Locked(locked)) => Disassembly::Locked(locked),
        Err(why) => Disassembly::Undecided(why),
    })
}

/// A piece's points, with its bounding box and a dense membership grid.
struct Shape {
    points: Vec<Point>,
    lo: Point,
    hi: Point,
    size: [i64; 3],
    grid: Vec<bool>,
}

impl Shape {
    fn new(points: Vec<Point>) -> Shape {
        let mut lo = points[0].coords();
        let mut hi = lo;
        for p in &points {
            for d in 0..3 {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        let size = [0, 1, 2].map(|d| i64::from(hi[d] - lo[d]) + 1);
        let mut shape = Shape {
            grid: vec![false; (size[0] * size[1] * size[2]) as usize],
            points,
            lo: Point::from(lo),
            hi: Point::from(hi),
            size,
        };
        for i in 0..shape.points.len() {
            let at = shape.index(shape.points[i]).expect("inside its own box");
            shape.grid[at] = true;
        }
        shape
    }

    fn index(&self, p: Point) -> Option<usize> {
        let r = p - self.lo;
        let mut at = 0i64;
        for d in (0..3).rev() {
            let v = i64::from(r[d]);
            if v < 0 || v >= self.size[d] {
                return None;
            }
            at = at * self.size[d] + v;
        }
        Some(at as usize)
    }

    /// Whether this shape moved by `at` meets `other` moved by `other_at`.
    fn meets(&self, at: Point, other: &Shape, other_at: Point) -> bool {
        let shift = at - other_at;
        let (lo, hi) = (self.lo + shift, self.hi + shift);
        if (0..3).any(|d| lo[d] > other.hi[d] || hi[d] < other.lo[d]) {
            return false;
        }
        self.points
            .iter()
            .any(|p| other.index(*p + shift).is_some_and(|i| other.grid[i]))
    }
}

/// The outcome for one part.
#[derive(Clone)]
enum Part {
    Apart(Plan),
    Locked(Vec<usize>),
}

/// A position reached by the breadth-first search of one part.
struct Node {
    /// Offsets of the part's pieces from where the figure has them.
    at: Box<[Point]>,
    parent: usize,
    /// The move that led here: group (bits of the part's pieces), translation.
    by: Option<(u64, Point)>,
}

/// The search of one figure: its pieces, the limits, and the parts
/// already decided (by pieces and relative offsets).
struct Search<'a> {
    shapes: Vec<Shape>,
    axes: usize,
    step: i32,
    limits: Limits<'a>,
    states: usize,
    memo: HashMap<(Vec<usize>, Vec<Point>), Part>,
}

/// A group that can leave its part: found at `node`, moving `group` by
/// `by` (a translation).
struct Removal {
    node: usize,
    group: u64,
    by: Point,
}

impl Search<'_> {
    fn stopped(&self) -> bool {
        self.limits.stop.is_some_and(|s| s.load(Ordering::Relaxed))
            || self.limits.deadline.is_some_and(|d| Instant::now() >= d)
    }

    /// The unit translations: `± step` along each axis.
    fn directions(&self) -> Vec<Point> {
        (0..self.axes)
            .flat_map(|a| {
                let mut v = [0; 3];
                v[a] = self.step;
                [Point::from(v), -Point::from(v)]
            })
            .collect()
    }

    /// Takes apart the part made of the pieces `ids` at offsets `start`.
    fn part(&mut self, ids: &[usize], start: &[Point]) -> Result<Part, Undecided> {
        if ids.len() < 2 {
            return Ok(Part::Apart(Plan {
                level: 0,
                moves: Vec::new(),
            }));
        }
        let key = (ids.to_vec(), start.iter().map(|p| *p - start[0]).collect());
        if let Some(known) = self.memo.get(&key) {
            return Ok(known.clone());
        }
        let result = self.search_part(ids, start)?;
        self.memo.insert(key, result.clone());
        Ok(result)
    }

    /// The breadth-first search of one part.
    fn search_part(&mut self, ids: &[usize], start: &[Point]) -> Result<Part, Undecided> {
        let n = ids.len();
        let all: u64 = if n == 64 { u64::MAX } else { (1 << n) - 1 };
        // The anchor, the largest piece (the first of them), never moves.
        let anchor = (0..n)
            .max_by_key(|&i| (self.shapes[ids[i]].points.len(), std::cmp::Reverse(i)))
            .unwrap_or(0);
        let mut nodes = vec![Node {
            at: start.into(),
            parent: 0,
            by: None,
        }];
        let mut seen: HashSet<Box<[Point]>> = HashSet::from([start.into()]);
        let mut locked: Option<Vec<usize>> = None;
        let mut next = 0;
        while next < nodes.len() {
            if next % 64 == 0 && self.stopped() {
                return Err(Undecided::Stopped);
            }
            let at = nodes[next].at.clone();
            let mut moves = self.moves(ids, &at, all, anchor);
            // Removals first, of the smallest groups first (a plan that takes
            // single pieces off where it can); the order is deterministic.
            moves.sort_by_key(|&(group, _, removed)| (!removed, group.count_ones()));
            for (group, by, removed) in moves {
                if removed {
                    let removal = Removal {
                        node: next,
                        group,
                        by,
                    };
                    match self.split(ids, &nodes, &removal)? {
                        Part::Apart(plan) => return Ok(Part::Apart(plan)),
                        Part::Locked(l) => _ = locked.get_or_insert(l),
                    }
                    continue;
                }
                let moved: Box<[Point]> = (0..n)
                    .map(|i| {
                        if group >> i & 1 == 1 {
                            at[i] + by
                        } else {
                            at[i]
                        }
                    })
                    .collect();
                if seen.insert(moved.clone()) {
                    self.states += 1;
                    if self.states > self.limits.max_states {
                        return Err(Undecided::TooManyStates);
                    }
                    nodes.push(Node {
                        at: moved,
                        parent: next,
                        by: Some((group, by)),
                    });
                }
            }
            next += 1;
        }
        // Every position reached is locked too (the same reachable set).
        let locked = locked.unwrap_or_else(|| ids.to_vec());
        for node in &nodes {
            let key = (
                ids.to_vec(),
                node.at.iter().map(|p| *p - node.at[0]).collect(),
            );
            self.memo.insert(key, Part::Locked(locked.clone()));
        }
        Ok(Part::Locked(locked))
    }

    /// Every move from the position `at` of the part `ids`: (group, translation,
    /// removed). Slides first, then removals, per direction.
    fn moves(
        &self,
        ids: &[usize],
        at: &[Point],
        all: u64,
        anchor: usize,
    ) -> Vec<(u64, Point, bool)> {
        let n = ids.len();
        let mut out = Vec::new();
        let mut tried: HashSet<(u64, Point)> = HashSet::new();
        for d in self.directions() {
            // blocked[q]: the pieces q meets when it moves one step along d.
            let blocked: Vec<u64> = (0..n)
                .map(|q| {
                    (0..n)
                        .filter(|&p| {
                            p != q
                                && self.shapes[ids[q]].meets(at[q] + d, &self.shapes[ids[p]], at[p])
                        })
                        .fold(0u64, |m, p| m | 1 << p)
                })
                .collect();
            for q in 0..n {
                let mut group = 1u64 << q;
                loop {
                    let grown = (0..n)
                        .filter(|&i| group >> i & 1 == 1)
                        .fold(group, |m, i| m | blocked[i]);
                    if grown == group {
                        break;
                    }
                    group = grown;
                }
                if group == all {
                    continue;
                }
                let (group, dir) = if group >> anchor & 1 == 1 {
                    (all & !group, -d)
                } else {
                    (group, d)
                };
                if tried.insert((group, dir)) {
                    self.slide(ids, at, group, dir, &mut out);
                }
            }
        }
        out
    }

    /// The slides of `group` along `dir` (one per free length) and its
    /// removal when its whole sweep is free.
    fn slide(
        &self,
        ids: &[usize],
        at: &[Point],
        group: u64,
        dir: Point,
        out: &mut Vec<(u64, Point, bool)>,
    ) {
        let n = ids.len();
        let axis = (0..3).find(|&a| dir[a] != 0).unwrap_or(0);
        let positive = dir[axis] > 0;
        let (mut g_lo, mut g_hi, mut r_lo, mut r_hi) = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);
        for i in 0..n {
            let s = &self.shapes[ids[i]];
            let (lo, hi) = (s.lo[axis] + at[i][axis], s.hi[axis] + at[i][axis]);
            if group >> i & 1 == 1 {
                (g_lo, g_hi) = (g_lo.min(lo), g_hi.max(hi));
            } else {
                (r_lo, r_hi) = (r_lo.min(lo), r_hi.max(hi));
            }
        }
        let step = dir[axis].abs();
        // Steps until the group lies beyond the rest along the axis.
        let gap = if positive { r_hi - g_lo } else { g_hi - r_lo };
        let clear = (gap.max(-1) / step + 1).max(1);
        let mut by = Point::ORIGIN;
        for k in 1..=clear {
            by = by + dir;
            let meets = (0..n).filter(|&i| group >> i & 1 == 1).any(|i| {
                (0..n)
                    .filter(|&j| group >> j & 1 == 0)
                    .any(|j| self.shapes[ids[i]].meets(at[i] + by, &self.shapes[ids[j]], at[j]))
            });
            if meets {
                return;
            }
            if k == clear {
                out.push((group, by, true));
            } else {
                out.push((group, by, false));
            }
        }
    }

    /// Takes apart both halves left by a removal; the plan of the part when
    /// both come apart, else the pieces of the first that does not.
    fn split(
        &mut self,
        ids: &[usize],
        nodes: &[Node],
        removal: &Removal,
    ) -> Result<Part, Undecided> {
        let at = &nodes[removal.node].at;
        let pick = |inside: bool| -> (Vec<usize>, Vec<Point>) {
            (0..ids.len())
                .filter(|&i| (removal.group >> i & 1 == 1) == inside)
                .map(|i| (ids[i], at[i]))
                .unzip()
        };
        let (gone, gone_at) = pick(true);
        let (kept, kept_at) = pick(false);
        let gone_plan = match self.part(&gone, &gone_at)? {
            Part::Apart(p) => p,
            locked => return Ok(locked),
        };
        let kept_plan = match self.part(&kept, &kept_at)? {
            Part::Apart(p) => p,
            locked => return Ok(locked),
        };
        let mut moves = self.path(ids, nodes, removal.node);
        moves.push(self.make_move(ids, removal.group, removal.by, true));
        let level = moves.len();
        moves.extend(gone_plan.moves);
        moves.extend(kept_plan.moves);
        Ok(Part::Apart(Plan { level, moves }))
    }

    /// The moves from the part's start to `node`.
    fn path(&self, ids: &[usize], nodes: &[Node], mut node: usize) -> Vec<Move> {
        let mut moves = Vec::new();
        while let Some((group, by)) = nodes[node].by {
            moves.push(self.make_move(ids, group, by, false));
            node = nodes[node].parent;
        }
        moves.reverse();
        moves
    }

    fn make_move(&self, ids: &[usize], group: u64, by: Point, removed: bool) -> Move {
        let mut pieces: Vec<usize> = (0..ids.len())
            .filter(|&i| group >> i & 1 == 1)
            .map(|i| ids[i])
            .collect();
        pieces.sort_unstable();
        Move {
            pieces,
            by: [0, 1, 2].map(|a| by[a] / self.step),
            removed,
        }
    }
}

/// The one-line verdict on a figure, as `dissect disassemble` prints it:
/// `NAME: apart in M moves (level L)`, `NAME: cannot be taken apart by
/// straight moves (pieces A, C locked)` or `NAME: not decided (...)`.
pub fn outcome_line(name: &str, outcome: &Disassembly) -> String {
    match outcome {
        Disassembly::Apart(plan) => format!(
            "{name}: apart in {} move{} (level {})",
            plan.moves.len(),
            if plan.moves.len() == 1 { "" } else { "s" },
            plan.level
        ),
        Disassembly::Locked(pieces) => {
            let letters: Vec<String> = pieces
                .iter()
                .map(|&i| dissect_core::ascii::piece_letter(i).to_string())
                .collect();
            format!(
                "{name}: cannot be taken apart by straight moves (pieces {} locked)",
                letters.join(", ")
            )
        }
        Disassembly::Undecided(Undecided::TooManyStates) => {
            format!("{name}: not decided (more than {MAX_STATES} positions)")
        }
        Disassembly::Undecided(Undecided::Stopped) => format!("{name}: not decided (stopped)"),
    }
}

/// The format name of a plan file.
pub const PLAN_FORMAT: &str = "dissection-disassembly/1";

/// The plan file (`dissection-disassembly/1`) of a dissection's figures:
/// `figures` holds each figure's name and outcome, in the solution's order.
/// A figure that comes apart has its `level` and `moves`; one that does
/// not has `"level": null`, no moves, and `"locked"` (the pieces that hold
/// together) or `"stopped": true` (not decided).
pub fn plan_json(lattice: dissect_core::LatticeKind, figures: &[(&str, &Disassembly)]) -> String {
    let entries: Vec<String> = figures
        .iter()
        .map(|(name, outcome)| figure_json(name, outcome))
        .collect();
    let figures = if entries.is_empty() {
        String::new()
    } else {
        format!("\n{}", entries.join(",\n"))
    };
    format!(
        "{{\n  \"format\": \"{PLAN_FORMAT}\",\n  \"lattice\": \"{}\",\n  \"figures\": [{figures}\n  ]\n}}\n",
        lattice.name()
    )
}

/// One figure's entry of the plan file, on its own lines (a move a line).
fn figure_json(name: &str, outcome: &Disassembly) -> String {
    let list = |v: &[usize]| -> String {
        let items: Vec<String> = v.iter().map(usize::to_string).collect();
        format!("[{}]", items.join(", "))
    };
    let name = serde_json::to_string(name).unwrap_or_else(|_| "\"\"".into());
    match outcome {
        Disassembly::Apart(plan) => {
            let moves: Vec<String> = plan
                .moves
                .iter()
                .map(|m| {
                    format!(
                        "      {{\"pieces\": {}, \"by\": [{}, {}, {}], \"removed\": {}}}",
                        list(&m.pieces),
                        m.by[0],
                        m.by[1],
                        m.by[2],
                        m.removed
                    )
                })
                .collect();
            let moves = if moves.is_empty() {
                String::new()
            } else {
                format!("\n{}\n    ", moves.join(",\n"))
            };
            format!(
                "    {{\"name\": {name}, \"level\": {}, \"moves\": [{moves}]}}",
                plan.level
            )
        }
        Disassembly::Locked(locked) => format!(
            "    {{\"name\": {name}, \"level\": null, \"moves\": [], \"locked\": {}}}",
            list(locked)
        ),
        _ => format!("    {{\"name\": {name}, \"level\": null, \"moves\": [], \"stopped\": true}}"),
    }
}

/// How far the assembled figure made of `pieces` is from interlocking. For
/// each piece and each of the lattice's `2 × dim` unit directions `d`, the
/// piece's *sweep closure*: the piece and, closed under the rule, every
/// piece that has a cell anywhere ahead (along `d`) of a cell of the
/// closure; it is the smallest group holding the piece that can go away to
/// infinity along `d` at once. The distance is the sum, over those pairs,
/// of the pieces outside the closure. So 0 means that no group comes free
/// by one move (the level is at least 2, or the figure is locked), and a
/// lower distance is a figure closer to that: the interlocking search
/// steers by it. A flat figure has nothing to hold its pieces: every
/// closure counts as the piece alone, `2 × dim × n × (n - 1)` (0 for a
/// single piece).
pub fn interlock_distance(lattice: &dyn Lattice, pieces: &[Vec<Cell>]) -> usize {
    let n = pieces.len();
    if lattice.dim() < 3 || n < 2 {
        return 2 * lattice.dim() * n * n.saturating_sub(1);
    }
    let mut owner: HashMap<Point, usize> = HashMap::new();
    let (mut lo, mut hi) = ([i32::MAX; 3], [i32::MIN; 3]);
    for (i, p) in pieces.iter().enumerate() {
        for c in p {
            let q = lattice.to_point(*c);
            for d in 0..3 {
                lo[d] = lo[d].min(q[d]);
                hi[d] = hi[d].max(q[d]);
            }
            owner.insert(q, i);
        }
    }
    let inside = |q: Point| (0..3).all(|d| q[d] >= lo[d] && q[d] <= hi[d]);
    let step = lattice.modulus();
    let mut free = 0;
    for axis in 0..lattice.dim() {
        for sign in [1, -1] {
            let mut v = [0; 3];
            v[axis] = sign * step;
            let dir = Point::from(v);
            // ahead[q]: the pieces with a cell ahead of a cell of q.
            let mut ahead: Vec<Vec<bool>> = vec![vec![false; n]; n];
            for (q, p) in pieces.iter().enumerate() {
                for c in p {
                    let mut at = lattice.to_point(*c) + dir;
                    while inside(at) {
                        if let Some(&o) = owner.get(&at) {
                            ahead[q][o] = true;
                        }
                        at = at + dir;
                    }
                }
            }
            for q in 0..n {
                let mut seen = vec![false; n];
                seen[q] = true;
                let mut todo = vec![q];
                while let Some(a) = todo.pop() {
                    for (b, &is_ahead) in ahead[a].iter().enumerate() {
                        if is_ahead && !seen[b] {
                            seen[b] = true;
                            todo.push(b);
                        }
                    }
                }
                free += seen.iter().filter(|s| !**s).count();
            }
        }
    }
    free
}

/// Whether every line along one of the lattice's axes meets `cells` in one
/// run of consecutive cells at most (a box, a cube, a slab, any shape
/// without a dent, a tunnel or a cavity along the axes). No figure of this
/// kind has a level of 2 or more: a group that can move one step along `d`
/// has, on every line along `d`, only cells whose next cell is its own or
/// outside the figure, so on each line it holds the end of the run, nothing
/// of the rest lies ahead of it, and the move can go on to infinity: the
/// first move is a removal.
pub fn axis_convex(lattice: &dyn Lattice, cells: &[Cell]) -> bool {
    let step = lattice.modulus();
    let points: Vec<Point> = cells.iter().map(|c| lattice.to_point(*c)).collect();
    (0..lattice.dim()).all(|axis| {
        // The line of a point: its other coordinates and its residue along
        // the axis; the runs: its positions along the axis, in steps.
        let mut lines: HashMap<([i32; 3], i32), Vec<i32>> = HashMap::new();
        for p in &points {
            let mut key = p.coords();
            let at = key[axis];
            key[axis] = 0;
            lines
                .entry((key, at.rem_euclid(step)))
                .or_default()
                .push(at.div_euclid(step));
        }
        lines.values_mut().all(|v| {
            v.sort_unstable();
            v.windows(2).all(|w| w[1] - w[0] <= 1)
        })
    })
}
