//! Disassembly plans on lettered voxel figures: each plan is replayed by
//! the independent checker of `dissect-testkit` (no code shared with the
//! search), and "cannot" is checked against an exhaustive search of our own
//! here (every subset of pieces as a group, every slide).

use std::collections::{HashMap, HashSet};
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::{Cell, LatticeKind};
use dissect_puzzle::disassembly::{
    disassemble, Disassembly, DisassemblyError, Limits, Plan, Undecided,
};
use dissect_testkit::disassembly::{replay, voxel_pieces, PlanMove, Voxel};

fn cubic() -> &'static dyn dissect_core::Lattice {
    LatticeKind::Cubic.lattice()
}

fn plan_of(pieces: &[Vec<Cell>]) -> Disassembly {
    disassemble(cubic(), pieces, Limits::default()).unwrap()
}

/// The plan's moves as the checker reads them, replayed: the level it finds.
fn replayed(pieces: &[Vec<Cell>], plan: &Plan) -> usize {
    let moves: Vec<PlanMove> = plan
        .moves
        .iter()
        .map(|m| PlanMove {
            pieces: m.pieces.clone(),
            by: m.by,
            removed: m.removed,
        })
        .collect();
    let level = replay(pieces, &moves).unwrap_or_else(|e| panic!("{e}\n{plan:?}"));
    assert_eq!(level, plan.level, "{plan:?}");
    level
}

fn apart(pieces: &[Vec<Cell>]) -> Plan {
    match plan_of(pieces) {
        Disassembly::Apart(plan) => {
            replayed(pieces, &plan);
            plan
        }
        other => panic!("not apart: {other:?}"),
    }
}

/// A Soma cube (the seven Soma pieces, A the V tricube).
const SOMA: &str = "
AFB
FFB
GGC

AFB
AGC
EGC

DDB
EDD
EEC
";

#[test]
fn a_soma_cube_comes_apart_in_well_under_a_second() {
    let pieces = voxel_pieces(SOMA);
    assert_eq!(pieces.len(), 7);
    let t = Instant::now();
    let plan = apart(&pieces);
    let took = t.elapsed();
    assert_eq!(plan.level, 1, "a Soma cube has a piece that lifts off");
    assert!(plan.moves.iter().filter(|m| m.removed).count() >= 6);
    // Generous for a loaded test machine; about a millisecond alone.
    assert!(took < Duration::from_secs(5), "{took:?}");
}

/// Ring A lies in the layer z = 1 around its hole (1, 2, 1); ring B stands
/// in the plane x = 1, passes through A's hole and closes around A's side
/// cell (1, 3, 1).
const LINKED_RINGS: &str = "
...
...
.B.
.B.
.B.

...
AAA
ABA
AAA
.B.

...
...
.B.
.B.
.B.
";

#[test]
fn two_linked_rings_cannot_be_taken_apart() {
    let pieces = voxel_pieces(LINKED_RINGS);
    assert_eq!((pieces[0].len(), pieces[1].len()), (8, 8));
    assert_eq!(plan_of(&pieces), Disassembly::Locked(vec![0, 1]));
    assert_eq!(exhaustive(&pieces), None, "the exhaustive search agrees");
}

#[test]
fn a_loose_piece_comes_off_and_the_rings_stay_locked() {
    let mut pieces = voxel_pieces(LINKED_RINGS);
    pieces.push(vec![[2, 4, 1], [2, 4, 2]]);
    assert_eq!(plan_of(&pieces), Disassembly::Locked(vec![0, 1]));
}

/// A block with a closed channel along x (y = 1, z = 1..=2) holding the L
/// piece B, and a window in its side y = 2 at x = 3..=4: B must slide 2
/// along x before it can leave along y.
fn slider() -> Vec<Vec<Cell>> {
    let b: Vec<Cell> = vec![[1, 1, 1], [2, 1, 1], [1, 1, 2]];
    let free: HashSet<Cell> = [[3, 1, 1], [4, 1, 1], [2, 1, 2], [3, 1, 2], [4, 1, 2]]
        .into_iter()
        .chain([[3, 2, 1], [4, 2, 1], [3, 2, 2], [4, 2, 2]])
        .collect();
    let mut a = Vec::new();
    for x in 0..6 {
        for y in 0..3 {
            for z in 0..4 {
                let c = [x, y, z];
                if !b.contains(&c) && !free.contains(&c) {
                    a.push(c);
                }
            }
        }
    }
    vec![a, b]
}

#[test]
fn a_piece_that_must_slide_first_gives_level_2() {
    let pieces = slider();
    assert!(
        removable_groups(&pieces).is_empty(),
        "nothing comes free at once"
    );
    let plan = apart(&pieces);
    assert_eq!(plan.level, 2);
    assert_eq!(plan.moves[0].pieces, vec![1]);
    assert_eq!(plan.moves[0].by, [2, 0, 0]);
    assert!(!plan.moves[0].removed);
    assert!(plan.moves[1].removed);
    assert_eq!(exhaustive(&pieces), Some(2));
}

/// Two pairs, each hooked along x: A sits in B's U (z = 1), and the rings
/// C (x = 0 and 2) and D (x = 1 and 3) interleave like fingers around the
/// slab A + B, which keeps both from moving across it. No piece can move
/// alone; the slab slides out of the rings as one group.
const TWO_PAIRS: &str = "
CCCD
CDCD
CDCD
CDCD

CDCD
BAAB
BBBB
CDCD

CDCD
CDDD
CDCD
CDCD
";

#[test]
fn a_case_that_needs_a_group_move() {
    let pieces = voxel_pieces(TWO_PAIRS);
    assert_eq!(pieces.len(), 4);
    assert_eq!(
        exhaustive_single(&pieces),
        None,
        "no plan moves one piece at a time"
    );
    assert_eq!(exhaustive(&pieces), Some(1));
    let plan = apart(&pieces);
    assert_eq!(plan.level, 1);
    let first = &plan.moves[0];
    assert!(first.removed);
    assert_eq!(first.pieces, vec![0, 1], "{plan:?}");
    assert_eq!(plan.moves.len(), 3);
}

/// Every subset of pieces (not all) that can go to infinity along an axis
/// from where the figure has them, found by brute force.
fn removable_groups(pieces: &[Vec<Cell>]) -> Vec<(u32, usize)> {
    let at = vec![[0; 3]; pieces.len()];
    let all: Vec<usize> = (0..pieces.len()).collect();
    let mut out = Vec::new();
    for mask in 1..(1u32 << pieces.len()) - 1 {
        for d in 0..6 {
            if slides(pieces, &all, &at, mask, d).1 {
                out.push((mask, d));
            }
        }
    }
    out
}

const DIRS: [[i32; 3]; 6] = [
    [1, 0, 0],
    [-1, 0, 0],
    [0, 1, 0],
    [0, -1, 0],
    [0, 0, 1],
    [0, 0, -1],
];

/// How far the group `mask` (bits over `ids`) slides along `DIRS[d]` (the
/// free lengths below the point where it is past the rest), and whether it
/// goes to infinity.
fn slides(
    pieces: &[Vec<Cell>],
    ids: &[usize],
    at: &[Voxel],
    mask: u32,
    d: usize,
) -> (Vec<i32>, bool) {
    let dir = DIRS[d];
    let cubes = |i: usize| -> Vec<Voxel> {
        pieces[ids[i]]
            .iter()
            .map(|c| [0, 1, 2].map(|k| c[k] + at[i][k]))
            .collect()
    };
    let rest: HashSet<Voxel> = (0..ids.len())
        .filter(|i| mask >> i & 1 == 0)
        .flat_map(cubes)
        .collect();
    let group: Vec<Voxel> = (0..ids.len())
        .filter(|i| mask >> i & 1 == 1)
        .flat_map(cubes)
        .collect();
    let mut lengths = Vec::new();
    for k in 1..64 {
        let moved: Vec<Voxel> = group
            .iter()
            .map(|v| [0, 1, 2].map(|a| v[a] + k * dir[a]))
            .collect();
        if moved.iter().any(|v| rest.contains(v)) {
            return (lengths, false);
        }
        // Past the rest: no cube of the rest lies ahead of any moved cube.
        let ahead = moved.iter().any(|v| {
            rest.iter().any(|r| {
                (0..3).all(|a| dir[a] != 0 || r[a] == v[a])
                    && (0..3).any(|a| dir[a] != 0 && (r[a] - v[a]) * dir[a] > 0)
            })
        });
        if !ahead {
            return (lengths, true);
        }
        lengths.push(k);
    }
    (lengths, false)
}

/// An exhaustive search written apart from the library's: every subset of
/// a part as a group, every free slide; `Some(level)` of the fewest moves
/// before a removal that leaves halves which come apart too, `None` when
/// no plan exists.
fn exhaustive(pieces: &[Vec<Cell>]) -> Option<usize> {
    let ids: Vec<usize> = (0..pieces.len()).collect();
    let mut memo = HashMap::new();
    part_level(pieces, &ids, &vec![[0; 3]; ids.len()], &mut memo, false)
}

/// [`exhaustive`] with moves of one piece only (or, the same motion, of
/// all the other pieces of its part).
fn exhaustive_single(pieces: &[Vec<Cell>]) -> Option<usize> {
    let ids: Vec<usize> = (0..pieces.len()).collect();
    let mut memo = HashMap::new();
    part_level(pieces, &ids, &vec![[0; 3]; ids.len()], &mut memo, true)
}

type Memo = HashMap<(Vec<usize>, Vec<Voxel>), Option<usize>>;

fn part_level(
    pieces: &[Vec<Cell>],
    ids: &[usize],
    start: &[Voxel],
    memo: &mut Memo,
    single: bool,
) -> Option<usize> {
    if ids.len() < 2 {
        return Some(0);
    }
    let norm = |at: &[Voxel]| -> Vec<Voxel> {
        at.iter()
            .map(|p| [0, 1, 2].map(|k| p[k] - at[0][k]))
            .collect()
    };
    let key = (ids.to_vec(), norm(start));
    if let Some(v) = memo.get(&key) {
        return *v;
    }
    let mut seen: HashSet<Vec<Voxel>> = HashSet::from([norm(start)]);
    let mut layer = vec![start.to_vec()];
    let mut depth = 0;
    let mut result = None;
    'bfs: while !layer.is_empty() && depth < 200 {
        let mut next = Vec::new();
        for at in &layer {
            for mask in 1..(1u32 << ids.len()) - 1 {
                let size = mask.count_ones() as usize;
                if single && size != 1 && size != ids.len() - 1 {
                    continue;
                }
                for (d, dir) in DIRS.iter().enumerate() {
                    let (lengths, gone) = slides(pieces, ids, at, mask, d);
                    if gone {
                        let half = |inside: bool| -> (Vec<usize>, Vec<Voxel>) {
                            (0..ids.len())
                                .filter(|i| (mask >> i & 1 == 1) == inside)
                                .map(|i| (ids[i], at[i]))
                                .unzip()
                        };
                        let (a, a_at) = half(true);
                        let (b, b_at) = half(false);
                        if part_level(pieces, &a, &a_at, memo, single).is_some()
                            && part_level(pieces, &b, &b_at, memo, single).is_some()
                        {
                            result = Some(depth + 1);
                            break 'bfs;
                        }
                    }
                    for k in lengths {
                        let moved: Vec<Voxel> = (0..ids.len())
                            .map(|i| {
                                if mask >> i & 1 == 1 {
                                    [0, 1, 2].map(|a| at[i][a] + k * dir[a])
                                } else {
                                    at[i]
                                }
                            })
                            .collect();
                        if seen.insert(norm(&moved)) {
                            next.push(moved);
                        }
                    }
                }
            }
        }
        layer = next;
        depth += 1;
    }
    memo.insert(key, result);
    result
}

/// A small deterministic random stream (xorshift).
struct Rng(u64);
impl Rng {
    fn next(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n as u64) as usize
    }
}

/// The box `0..x × 0..y × 0..z` cut into `k` connected pieces grown from
/// random seeds.
fn random_box(size: [i32; 3], k: usize, rng: &mut Rng) -> Vec<Vec<Cell>> {
    let cells: Vec<Cell> = cubic().cells_in_box([0, 0, 0], size.map(|v| v - 1));
    let set: HashSet<Cell> = cells.iter().copied().collect();
    loop {
        let mut owner: HashMap<Cell, usize> = HashMap::new();
        let mut pieces: Vec<Vec<Cell>> = Vec::new();
        for i in 0..k {
            let c = cells[rng.next(cells.len())];
            if owner.insert(c, i).is_some() {
                break;
            }
            pieces.push(vec![c]);
        }
        if pieces.len() < k {
            continue;
        }
        let mut stuck = 0;
        while owner.len() < cells.len() && stuck < 1000 {
            let i = rng.next(k);
            let frontier: Vec<Cell> = pieces[i]
                .iter()
                .flat_map(|c| cubic().neighbors(*c))
                .filter(|n| set.contains(n) && !owner.contains_key(n))
                .collect();
            if frontier.is_empty() {
                stuck += 1;
                continue;
            }
            let n = frontier[rng.next(frontier.len())];
            owner.insert(n, i);
            pieces[i].push(n);
        }
        if owner.len() == cells.len() {
            return pieces;
        }
    }
}

#[test]
fn random_boxes_agree_with_the_exhaustive_search() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let (mut apart_count, mut locked_count) = (0, 0);
    for round in 0..120 {
        let size = [[3, 3, 2], [4, 2, 2], [3, 3, 3]][round % 3];
        let pieces = random_box(size, 3 + round % 2, &mut rng);
        let truth = exhaustive(&pieces);
        match plan_of(&pieces) {
            Disassembly::Apart(plan) => {
                let level = replayed(&pieces, &plan);
                let best = truth.expect("the exhaustive search finds a plan too");
                assert!(level >= best, "{pieces:?}");
                apart_count += 1;
            }
            Disassembly::Locked(_) => {
                assert_eq!(truth, None, "{pieces:?}");
                locked_count += 1;
            }
            other => panic!("{other:?}"),
        }
    }
    eprintln!("apart {apart_count} locked {locked_count}");
    assert!(
        apart_count > 0 && locked_count > 0,
        "{apart_count} {locked_count}"
    );
}

#[test]
fn flat_figures_lift_off_piece_by_piece() {
    let square = LatticeKind::Square.lattice();
    let pieces = vec![vec![[0, 0, 0]], vec![[1, 0, 0]], vec![[2, 0, 0]]];
    let Disassembly::Apart(plan) = disassemble(square, &pieces, Limits::default()).unwrap() else {
        panic!("flat pieces lift off");
    };
    assert_eq!(plan.level, 1);
    assert_eq!(plan.moves.len(), 2);
    assert!(plan.moves.iter().all(|m| m.removed && m.by == [0, 0, 1]));
}

#[test]
fn bad_pieces_are_typed_errors() {
    let e = disassemble(cubic(), &[vec![[0, 0, 0]], vec![]], Limits::default());
    assert_eq!(e, Err(DisassemblyError::EmptyPiece { piece: 1 }));
    let e = disassemble(
        cubic(),
        &[vec![[0, 0, 0]], vec![[0, 0, 0]]],
        Limits::default(),
    );
    assert_eq!(e, Err(DisassemblyError::Overlap { a: 0, b: 1 }));
    let many: Vec<Vec<Cell>> = (0..65).map(|x| vec![[x, 0, 0]]).collect();
    assert!(matches!(
        disassemble(cubic(), &many, Limits::default()),
        Err(DisassemblyError::TooManyPieces { found: 65 })
    ));
    assert_eq!(
        plan_of(&[vec![[0, 0, 0]]]),
        Disassembly::Apart(Plan {
            level: 0,
            moves: vec![]
        })
    );
}

#[test]
fn a_stop_or_a_state_cap_leaves_it_undecided() {
    let pieces = voxel_pieces(LINKED_RINGS);
    let stop = AtomicBool::new(true);
    let limits = Limits {
        stop: Some(&stop),
        ..Limits::default()
    };
    assert_eq!(
        disassemble(cubic(), &pieces, limits).unwrap(),
        Disassembly::Undecided(Undecided::Stopped)
    );
    let limits = Limits {
        deadline: Some(Instant::now()),
        ..Limits::default()
    };
    assert_eq!(
        disassemble(cubic(), &pieces, limits).unwrap(),
        Disassembly::Undecided(Undecided::Stopped)
    );
    let limits = Limits {
        max_states: 1,
        ..Limits::default()
    };
    assert_eq!(
        disassemble(cubic(), &slider(), limits).unwrap(),
        Disassembly::Undecided(Undecided::TooManyStates)
    );
}

#[test]
fn the_assembly_rules_are_constraints() {
    use dissect_puzzle::constraints::{ConstraintError, Violation};
    use dissect_puzzle::{Constraints, Motions};
    let motions = Motions::new(LatticeKind::Cubic, false);
    let rings = vec![voxel_pieces(LINKED_RINGS)];
    let slider = vec![slider()];
    let assemblable = Constraints::none().with_assembly(true, None);
    assert!(!assemblable.is_empty());
    assert_eq!(
        assemblable.check(&motions, &rings),
        vec![Violation::NotAssemblable { figure: 0 }]
    );
    assert!(assemblable.check(&motions, &slider).is_empty());
    let level2 = Constraints::none().with_assembly(false, Some(2));
    assert!(level2.assemblable(), "a least level implies assemblable");
    assert!(level2.check(&motions, &slider).is_empty());
    let level3 = Constraints::none().with_assembly(false, Some(3));
    assert_eq!(
        level3.check(&motions, &slider),
        vec![Violation::LevelTooLow {
            figure: 0,
            level: 2
        }]
    );
    assert_eq!(level3.to_json(LatticeKind::Cubic)["min_level"], 3);
    // A flat figure always comes apart at level 1: 2 or more is impossible.
    let flat = dissect_core::io::parse_figure("##\n", LatticeKind::Square).unwrap();
    let e = level2.validate(std::slice::from_ref(&flat)).unwrap_err();
    assert_eq!(e, ConstraintError::FlatLevel(2));
    assert!(e.is_impossible());
    assert!(assemblable.validate(&[flat]).is_ok());
    let zero = Constraints::none().with_assembly(false, Some(0));
    assert_eq!(
        zero.validate_settings(),
        Err(ConstraintError::ZeroSize("min-level"))
    );
}

#[test]
fn rank_level_puts_the_most_interlocking_first() {
    use dissect_puzzle::{Motions, Rank, Scores};
    let motions = Motions::new(LatticeKind::Cubic, false);
    let with = |levels: Vec<Option<usize>>| Scores {
        levels: Some(levels),
        ..Scores::of(&motions, &[vec![[0, 0, 0]], vec![[1, 0, 0]]])
    };
    let mut items = vec![
        (with(vec![Some(1), Some(3)]), "1"),
        (with(vec![None, Some(5)]), "locked"),
        (with(vec![Some(2), Some(2)]), "2"),
    ];
    Rank::Level.sort(&mut items);
    let order: Vec<&str> = items.iter().map(|i| i.1).collect();
    assert_eq!(order, vec!["2", "1", "locked"]);
    assert_eq!("level".parse::<Rank>(), Ok(Rank::Level));
}

#[test]
fn a_box_has_no_level_two_and_the_interlock_distance_sees_it() {
    use dissect_puzzle::constraints::ConstraintError;
    use dissect_puzzle::disassembly::{axis_convex, interlock_distance};
    use dissect_puzzle::Constraints;
    let parse = |t: &str| dissect_core::io::parse_figure(t, LatticeKind::Cubic).unwrap();
    let cube = parse("##\n##\n\n##\n##\n");
    let slab = parse("####\n####\n");
    let cavity = parse("###\n###\n###\n\n###\n#.#\n###\n\n###\n###\n###\n");
    let dent = parse("###\n\n#.#\n\n###\n");
    assert!(axis_convex(cubic(), cube.cells()));
    assert!(axis_convex(cubic(), slab.cells()));
    assert!(!axis_convex(cubic(), cavity.cells()));
    assert!(!axis_convex(cubic(), dent.cells()));
    let level2 = Constraints::none().with_assembly(false, Some(2));
    let e = level2.validate(&[cavity.clone(), slab]).unwrap_err();
    assert_eq!(
        e,
        ConstraintError::ConvexLevel {
            figure: 2,
            level: 2
        }
    );
    assert!(e.is_impossible());
    assert!(level2.validate(&[cavity.clone(), cavity]).is_ok());
    // The slider needs a move before its first removal: nothing comes
    // free at once. Linked rings are locked: nothing either. Two halves of
    // a cube come free at once (each in 5 of 6 directions, 1 piece left
    // out each time).
    assert_eq!(interlock_distance(cubic(), &slider()), 0);
    assert_eq!(interlock_distance(cubic(), &voxel_pieces(LINKED_RINGS)), 0);
    let halves = voxel_pieces("AB\nAB\n\nAB\nAB\n");
    assert_eq!(interlock_distance(cubic(), &halves), 10);
    // One piece has nothing to hold.
    assert_eq!(interlock_distance(cubic(), &voxel_pieces("AA\n")), 0);
}
