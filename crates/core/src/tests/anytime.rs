//! The constructive dissection and the repair hook of the anytime search.

use std::sync::atomic::AtomicBool;
use std::sync::Mutex;

use crate::lattice::{Cell, LatticeKind, Point};
use crate::solver::candidate::{Candidate, Score};
use crate::solver::greedy::{greedy, Choice, GreedyStyle};
use crate::solver::{Level, Options, Repair, Search};
use crate::tests::util::{candidate, cells_by_label, verified};

/// Every style of the constructive dissection is valid, on every lattice,
/// with two and three figures, whatever the pivot, with the first motion
/// displaced by one lattice translation or not.
#[test]
fn the_constructive_dissection_is_always_valid() {
    use LatticeKind::*;
    let cases: &[(LatticeKind, &[&str])] = &[
        (Square, &["AAAA|AAAA|AAAA|AAAA", "AAAAAAAA|AAAAAAAA"]),
        (Square, &["AAA.|AAAA|AAAA|.AAA", "AAAAAAA|AAAAAAA"]),
        (
            Square,
            &["AAAAAA|AAAAAA", "AAAA|AAAA|AAAA", "AAA|AAA|AAA|AAA"],
        ),
        (Tri4, &["AAAA AAAA|AAAA AAAA", "AAAA AAAA AAAA AAAA"]),
        (Tri4, &["AA.. AAAA|AAAA A..A", "AAAA AAAA AA.. ..AA"]),
        (Cubic, &["AA|AA/AA|AA", "AAAA|AAAA"]),
        (
            Cubic,
            &[
                "AAA|AAA|AAA/AAA|AAA|AAA/AAA|AAA|AAA",
                "AAAAAAAAA|AAAAAAAAA|AAAAAAAAA",
            ],
        ),
    ];
    for (lattice, figures) in cases {
        let (figs, problem, _) = candidate(*lattice, true, figures);
        for pivot in 0..figs.len() {
            for divisor in [1, 2] {
                for choice in [
                    Choice::Overlap,
                    Choice::Connected,
                    Choice::Tidy { slack: 4 },
                    Choice::Tidy { slack: 1 },
                ] {
                    let step = lattice.lattice().modulus();
                    for start in [Point::ORIGIN, Point::from([step, 0, 0])] {
                        let style = GreedyStyle {
                            pivot,
                            divisor,
                            choice,
                            start,
                        };
                        let cand = greedy(&problem, style);
                        assert!(
                            verified(*lattice, true, &figs, &cand),
                            "{lattice} {figures:?} {style:?}: {:?}",
                            cells_by_label(&figs, &cand)
                        );
                    }
                }
            }
        }
    }
}

/// Congruent figures come out as one piece; a square and a bar of the same
/// cells as few pieces (the common part first).
#[test]
fn the_constructive_dissection_keeps_common_parts_whole() {
    let (figs, problem, _) = candidate(LatticeKind::Square, true, &["AAA|AAA", "AA|AA|AA"]);
    let cand = greedy(
        &problem,
        GreedyStyle {
            pivot: 0,
            divisor: 1,
            choice: Choice::Overlap,
            start: Point::ORIGIN,
        },
    );
    assert_eq!(cand.k, 1);
    assert!(verified(LatticeKind::Square, true, &figs, &cand));
    let (figs, problem, _) = candidate(
        LatticeKind::Square,
        true,
        &["AAAA|AAAA|AAAA|AAAA", "AAAAAAAA|AAAAAAAA"],
    );
    let cand = greedy(
        &problem,
        GreedyStyle {
            pivot: 0,
            divisor: 1,
            choice: Choice::Overlap,
            start: Point::ORIGIN,
        },
    );
    assert_eq!(cand.k, 2, "two 4×2 halves");
    assert!(verified(LatticeKind::Square, true, &figs, &cand));
}

/// A displaced start moves the first piece off the largest common part:
/// two congruent figures are one piece undisplaced, and with the first
/// motion shifted by one cell the first piece is smaller and the cut takes
/// more pieces, still a valid dissection. A displacement that keeps no
/// cell is ignored.
#[test]
fn a_displaced_start_moves_the_first_piece() {
    let (figs, problem, _) = candidate(LatticeKind::Square, true, &["AAA|AAA", "AA|AA|AA"]);
    let style = |start| GreedyStyle {
        pivot: 0,
        divisor: 1,
        choice: Choice::Overlap,
        start,
    };
    let plain = greedy(&problem, style(Point::ORIGIN));
    assert_eq!(plain.k, 1);
    let first = |cand: &Candidate| cand.labels[0].iter().filter(|&&l| l == 0).count();
    for d in [[1, 0, 0], [0, 1, 0], [-1, 0, 0]] {
        let shifted = greedy(&problem, style(Point::from(d)));
        assert!(verified(LatticeKind::Square, true, &figs, &shifted));
        assert!(
            first(&shifted) < 6,
            "{d:?}: {:?}",
            cells_by_label(&figs, &shifted)
        );
        assert!(shifted.k > 1);
    }
    let nowhere = greedy(&problem, style(Point::from([100, 0, 0])));
    assert_eq!(
        nowhere.labels, plain.labels,
        "a displacement off the figure is ignored"
    );
}

/// Displaced starts move along the two axes on which the figures reach
/// farthest, the longest first, by four lattice translations: the length
/// of a 20×10×10 box, a tower's height, the first axis on ties.
#[test]
fn displaced_starts_move_along_the_longest_axes() {
    use crate::figure::Figure;
    use crate::solver::anytime::displacements;
    let boxed = |x: i32, y: i32, z: i32| {
        let mut cells = Vec::new();
        for i in 0..x {
            for j in 0..y {
                for k in 0..z {
                    cells.push([i, j, k]);
                }
            }
        }
        Figure::new(LatticeKind::Cubic, cells).expect("a box")
    };
    let d = |figs: &[Figure]| -> Vec<[i32; 3]> {
        displacements(figs)
            .into_iter()
            .map(<[i32; 3]>::from)
            .collect()
    };
    let (x, y, z) = ([4, 0, 0], [0, 4, 0], [0, 0, 4]);
    assert_eq!(d(&[boxed(20, 10, 10), boxed(10, 20, 10)]), [x, y]);
    assert_eq!(d(&[boxed(20, 8, 10), boxed(10, 8, 20)]), [x, z]);
    assert_eq!(d(&[boxed(5, 4, 10), boxed(10, 4, 5)]), [x, z]);
    assert_eq!(d(&[boxed(3, 4, 12), boxed(6, 6, 4)]), [z, x]);
    assert_eq!(d(&[boxed(2, 6, 2), boxed(4, 3, 2)]), [y, x]);
    assert_eq!(d(&[boxed(4, 4, 4)]), [x, y]);
    assert!(d(&[]).is_empty());
}

/// The connected choice takes the motion whose common part has the largest
/// component among its candidates, and the overlap choice's motion is one
/// of them: its largest component is never smaller, on 2D and 3D figures.
#[test]
fn the_connected_choice_keeps_the_largest_component() {
    use crate::solver::greedy::{common_part_by, components, FREE};
    let cases: &[(LatticeKind, &[&str])] = &[
        (
            LatticeKind::Square,
            &["AAAA.|A..AA|AAAAA|..A..", "AAAAAAA|AAAAAA"],
        ),
        (
            LatticeKind::Square,
            &["A.A.A|AAAAA|A.A.A", "AAAAA|AAAAA|A...."],
        ),
        (
            LatticeKind::Cubic,
            &["AAA|A.A|AAA/A..|...|..A", "AAAAA|AAAAA"],
        ),
    ];
    for (lattice, figures) in cases {
        let (_, problem, _) = candidate(*lattice, true, figures);
        let labels: Vec<Vec<u16>> = problem.shapes.iter().map(|s| vec![FREE; s.len()]).collect();
        let largest = |choice| {
            let (common, _) = common_part_by(&problem, 0, &labels, choice);
            let comps = components(&problem.shapes[0], &common);
            comps.iter().map(Vec::len).max().unwrap_or(0)
        };
        let (overlap, connected) = (largest(Choice::Overlap), largest(Choice::Connected));
        assert!(connected >= overlap, "{figures:?}: {connected} < {overlap}");
    }
}

/// The tidy choice's first cut gives up at most `1 / slack` of the
/// connected choice's largest component and leaves no more remainder
/// components in the more broken figure (the connected choice's motion is
/// one of its candidates); its greedy and pilot are valid. Voxel figures
/// with a hole and a notch, both figures as the pivot.
#[test]
fn the_tidy_choice_leaves_no_more_remainder_parts() {
    use crate::solver::greedy::{common_part_by, components, pilot_until, Lookahead, FREE};
    let cases: &[&[&str]] = &[
        &["AAA|A.A|AAA/A..|...|..A", "AAAAA|AAAAA"],
        &["AAAA|A..A|AAAA/AA.A|AAAA|AAAA", "AAAAAAA|AAAAAAA|AAAAAAA"],
        &["AAAAA|A...A|AAAAA/AA...|.....|...AA", "AAAAAAAA|AAAAAAAA"],
    ];
    // Cases where the tidy cut leaves strictly fewer remainder components
    // than the connected one (the choice must make a difference somewhere).
    let mut tidier = 0;
    for figures in cases {
        let (figs, problem, _) = candidate(LatticeKind::Cubic, true, figures);
        let labels: Vec<Vec<u16>> = problem.shapes.iter().map(|s| vec![FREE; s.len()]).collect();
        // The largest component of the first cut and the components each
        // figure has left after it (divisor 1: the largest components cut).
        let cut = |choice| {
            let (common, motions) = common_part_by(&problem, 0, &labels, choice);
            let comps = components(&problem.shapes[0], &common);
            let largest = comps.iter().map(Vec::len).max().unwrap_or(0);
            let mut left = labels.clone();
            for comp in comps.iter().filter(|c| c.len() == largest) {
                for &c in comp {
                    left[0][c as usize] = 0;
                    let (s, t) = motions[1].expect("the other figure moves");
                    let p = problem.geo.syms[s].apply(problem.shapes[0].point(c)) + t;
                    let j = problem.shapes[1].lookup(p).expect("inside");
                    left[1][j as usize] = 0;
                }
            }
            let parts = (0..2).map(|f| {
                let free: Vec<u32> = (0..left[f].len() as u32)
                    .filter(|&c| left[f][c as usize] == FREE)
                    .collect();
                components(&problem.shapes[f], &free).len()
            });
            (largest, parts.max().unwrap_or(0))
        };
        let (connected, connected_parts) = cut(Choice::Connected);
        for slack in [1, 2, 4] {
            let choice = Choice::Tidy { slack };
            let (tidy, tidy_parts) = cut(choice);
            assert!(
                tidy >= connected - connected / slack,
                "{figures:?} slack {slack}: {tidy} of {connected}"
            );
            assert!(
                tidy_parts <= connected_parts,
                "{figures:?} slack {slack}: {tidy_parts} > {connected_parts}"
            );
            tidier += usize::from(tidy_parts < connected_parts);
            for pivot in 0..2 {
                let style = GreedyStyle {
                    pivot,
                    divisor: 1,
                    choice,
                    start: Point::ORIGIN,
                };
                let plain = greedy(&problem, style);
                assert!(verified(LatticeKind::Cubic, true, &figs, &plain));
                let (pilot, _) = pilot_until(
                    &problem,
                    style,
                    Lookahead {
                        width: 4,
                        depth: 4,
                        beam: 1,
                    },
                    &AtomicBool::new(false),
                )
                .unwrap();
                assert!(verified(LatticeKind::Cubic, true, &figs, &pilot));
                assert!(pilot.k <= plain.k, "{figures:?} {style:?}");
            }
        }
    }
    assert!(tidier > 0, "the tidy choice never cut differently");
}

/// The pilot method, and a beam of pilots, gives a valid dissection with no
/// more pieces than the greedy of the same style (its first trial finishes
/// that greedy).
#[test]
fn the_pilot_is_valid_and_never_worse_than_its_greedy() {
    use crate::solver::greedy::{pilot_until, Lookahead};
    let cases: &[(LatticeKind, &[&str])] = &[
        (
            LatticeKind::Square,
            &["AAA.|AAAA|AAAA|.AAA", "AAAAAAA|AAAAAAA"],
        ),
        (
            LatticeKind::Cubic,
            &["AAA|A.A|AAA/A..|...|..A", "AAAAA|AAAAA"],
        ),
    ];
    for (lattice, figures) in cases {
        let (figs, problem, _) = candidate(*lattice, true, figures);
        for divisor in [1, 2] {
            let style = GreedyStyle {
                pivot: 0,
                divisor,
                choice: Choice::Connected,
                start: Point::ORIGIN,
            };
            let plain = greedy(&problem, style);
            // The pilot method (beam 1) and beams that keep more states,
            // looking ahead at a few steps or past the last one (the
            // meshes' depth).
            for (beam, depth) in [(1, 4), (2, 4), (4, 4), (4, 16)] {
                let look = Lookahead {
                    width: 3,
                    depth,
                    beam,
                };
                let (pilot, _) =
                    pilot_until(&problem, style, look, &AtomicBool::new(false)).unwrap();
                assert!(
                    verified(*lattice, true, &figs, &pilot),
                    "{figures:?} {style:?} beam {beam} depth {depth}"
                );
                assert!(
                    pilot.k <= plain.k,
                    "{figures:?} beam {beam} depth {depth}: {} > {}",
                    pilot.k,
                    plain.k
                );
            }
            // As wide as the motions a step ranks: nothing was left out,
            // and the pilot says so.
            let (_, truncated) = pilot_until(
                &problem,
                style,
                Lookahead {
                    width: 100_000,
                    depth: 4,
                    beam: 1,
                },
                &AtomicBool::new(false),
            )
            .unwrap();
            assert!(!truncated, "{figures:?} {style:?}");
            // One motion per step leaves others out: a wider pilot has
            // something to add.
            let (_, truncated) = pilot_until(
                &problem,
                style,
                Lookahead {
                    width: 1,
                    depth: 4,
                    beam: 1,
                },
                &AtomicBool::new(false),
            )
            .unwrap();
            assert!(truncated, "{figures:?} {style:?}");
        }
    }
    let (_, problem, _) = candidate(LatticeKind::Square, true, &["AA|AA", "AAAA"]);
    let style = GreedyStyle {
        pivot: 0,
        divisor: 1,
        choice: Choice::Connected,
        start: Point::ORIGIN,
    };
    assert!(pilot_until(
        &problem,
        style,
        Lookahead {
            width: 2,
            depth: 2,
            beam: 1
        },
        &AtomicBool::new(true)
    )
    .is_none());
}

/// Checks what the repairer is handed and returns a fixed answer.
struct Oracle {
    answer: Vec<Vec<Vec<Cell>>>,
    handed: Mutex<Vec<Vec<Vec<Vec<Cell>>>>>,
}

impl Repair for Oracle {
    fn repair(&self, pieces: &[Vec<Vec<Cell>>], _stop: &AtomicBool) -> Option<Vec<Vec<Vec<Cell>>>> {
        self.handed.lock().unwrap().push(pieces.to_vec());
        Some(self.answer.clone())
    }
}

fn search_of<'a>(
    figures: &'a [crate::Figure],
    options: &'a Options,
    stop: &'a AtomicBool,
) -> Search<'a> {
    Search::new(figures, options, stop, &(), None).expect("valid figures")
}

/// A near miss (one cell of the 2×3 rectangle in the wrong piece) goes to
/// the repairer as cells per piece per figure; a valid answer with as many
/// pieces comes back as a valid candidate, an invalid one is refused.
#[test]
fn a_near_miss_goes_to_the_repairer_and_a_valid_answer_comes_back() {
    // 2×3 rectangle vs 1×6 bar: two 1×3 bars. The candidate's rectangle has
    // one cell of B in A's row.
    let (figs, problem, mut near) = candidate(LatticeKind::Square, true, &["AAB|BBB", "AAABBB"]);
    let score = near.evaluate(&problem, 0.0, 1000.0);
    assert!(!score.valid && score.mismatch > 0, "{score:?}");
    let (_, _, fixed) = candidate(LatticeKind::Square, true, &["AAA|BBB", "AAABBB"]);
    let answer = cells_by_label(&figs, &fixed);
    let oracle = Oracle {
        answer: answer.clone(),
        handed: Mutex::new(Vec::new()),
    };
    let options = Options::default();
    let stop = AtomicBool::new(false);
    let search = search_of(&figs, &options, &stop);
    let level = Level {
        results: vec![(near.clone(), score)],
        stopped: false,
    };
    let (cand, s): (Candidate, Score) = search.repair(&oracle, &level, 2, 2).expect("repaired");
    assert!(s.valid);
    assert!(verified(LatticeKind::Square, true, &figs, &cand));
    let handed = oracle.handed.lock().unwrap();
    assert_eq!(handed.len(), 1);
    assert_eq!(
        handed[0],
        cells_by_label(&figs, &near),
        "the candidate's cells"
    );
    drop(handed);

    // More pieces than allowed, or cells that do not tile: refused.
    assert!(
        search.repair(&oracle, &level, 1, 2).is_none(),
        "3 > 1 piece cap"
    );
    let mut broken = answer.clone();
    broken[1][0].pop();
    let liar = Oracle {
        answer: broken,
        handed: Mutex::new(Vec::new()),
    };
    assert!(search.repair(&liar, &level, 2, 2).is_none(), "not a tiling");
}

/// The tail rebuild keeps the `keep` largest pieces of the dissection it
/// starts from exactly (cells and labels), cuts the rest again into a
/// valid dissection on every lattice and with three figures, gives the
/// same answer for the same stream, and its random draws make a
/// difference somewhere.
#[test]
fn the_tail_rebuild_keeps_the_largest_pieces_and_stays_valid() {
    use crate::solver::greedy::rebuild_until;
    use crate::tests::util::rng;
    use LatticeKind::*;
    let cases: &[(LatticeKind, &[&str])] = &[
        (Square, &["AAA.|AAAA|AAAA|.AAA", "AAAAAAA|AAAAAAA"]),
        (
            Square,
            &["AAAAAA|AAAAAA", "AAAA|AAAA|AAAA", "AAA|AAA|AAA|AAA"],
        ),
        (Tri4, &["AA.. AAAA|AAAA A..A", "AAAA AAAA AA.. ..AA"]),
        (
            Cubic,
            &[
                "AAA|A.A|AAA/AAA|AAA|AAA/A..|...|..A",
                "AAAAAAAAAA|AAAAAAAAA.",
            ],
        ),
    ];
    let never = AtomicBool::new(false);
    let mut differs = 0;
    for (lattice, figures) in cases {
        let (figs, problem, _) = candidate(*lattice, true, figures);
        for pivot in 0..figs.len() {
            let style = GreedyStyle {
                pivot,
                divisor: 2,
                choice: Choice::Connected,
                start: Point::ORIGIN,
            };
            let base = greedy(&problem, style);
            // The base's pieces by size in the pivot, largest first.
            let mut size = vec![0usize; base.k];
            for &l in &base.labels[pivot] {
                size[l as usize] += 1;
            }
            let mut order: Vec<usize> = (0..base.k).collect();
            order.sort_by_key(|&l| (std::cmp::Reverse(size[l]), l));
            for keep in 0..=base.k {
                for seed in 0..4 {
                    let again = |seed| {
                        rebuild_until(&problem, style, (&base, keep), (&mut rng(seed), 3), &never)
                            .expect("never stopped")
                    };
                    let rebuilt = again(seed);
                    assert!(
                        verified(*lattice, true, &figs, &rebuilt),
                        "{lattice} {figures:?} keep {keep} seed {seed}: {:?}",
                        cells_by_label(&figs, &rebuilt)
                    );
                    assert_eq!(rebuilt, again(seed), "the same stream, the same answer");
                    for (f, labels) in base.labels.iter().enumerate() {
                        for (c, &l) in labels.iter().enumerate() {
                            if let Some(new) =
                                order.iter().take(keep).position(|&o| o == l as usize)
                            {
                                assert_eq!(
                                    rebuilt.labels[f][c] as usize, new,
                                    "kept piece {l} moved"
                                );
                            } else {
                                assert!(rebuilt.labels[f][c] as usize >= keep.min(base.k));
                            }
                        }
                    }
                    differs += usize::from(rebuilt.k != base.k || rebuilt.labels != base.labels);
                }
            }
        }
    }
    assert!(
        differs > 0,
        "the rebuilds never left the greedy's own dissection"
    );
}

/// The greedy's best translations by votes: the same as sorting every
/// non-zero vote (most first, the smaller index on ties), on votes with
/// many ties.
#[test]
fn top_votes_are_the_sorted_best() {
    use crate::solver::greedy::top_votes;
    use rand::{RngExt, SeedableRng};
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    for round in 0..200 {
        let n = rng.random_range(0..300);
        let high = 1 + round % 6;
        let votes: Vec<u32> = (0..n).map(|_| rng.random_range(0..=high)).collect();
        let mut all: Vec<(u32, usize)> = votes
            .iter()
            .enumerate()
            .filter(|(_, &v)| v > 0)
            .map(|(i, &v)| (v, i))
            .collect();
        all.sort_by_key(|&(v, i)| (std::cmp::Reverse(v), i));
        for take in [0, 1, 2, 8, 1000] {
            let want: Vec<(u32, usize)> = all.iter().copied().take(take).collect();
            assert_eq!(
                top_votes(&votes, take),
                want,
                "votes {votes:?}, take {take}"
            );
        }
    }
}

/// The lanes of the pilots take turns, the narrowest next pilot first and
/// the lower lane on ties; a lane stops past the widest pilot, past the
/// eager widths once its pilots stop finding fewer pieces, and at once
/// when a pilot took every motion (its next width is unbounded).
#[test]
fn lanes_take_turns_narrowest_first() {
    use crate::solver::anytime::{Schedule, PILOT_EAGER_WIDTH, PILOT_MAX_WIDTH, PILOT_WIDTH};
    assert_eq!(
        (PILOT_WIDTH, PILOT_EAGER_WIDTH, PILOT_MAX_WIDTH),
        (4, 32, 256)
    );
    // Lane 1 finds no fewer pieces from width 16 on; lane 2's 8-wide pilot
    // takes every motion.
    let mut widths = vec![PILOT_WIDTH; 3];
    let mut schedule = Schedule::new(3);
    let mut ran = Vec::new();
    while let Some(i) = schedule.next(&widths) {
        let width = widths[i];
        if schedule.runs(i, width) {
            ran.push((i, width));
            schedule.record(i, !(i == 1 && width >= 16));
            widths[i] = if i == 2 && width == 8 {
                usize::MAX
            } else {
                width * 2
            };
        }
    }
    let expected = [
        (0, 4),
        (1, 4),
        (2, 4),
        (0, 8),
        (1, 8),
        (2, 8),
        (0, 16),
        (1, 16),
        (0, 32),
        (1, 32),
        (0, 64),
        (0, 128),
        (0, 256),
    ];
    assert_eq!(ran, expected);
}
