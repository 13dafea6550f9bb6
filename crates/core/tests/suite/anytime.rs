//! The anytime search: a valid dissection at once for any accepted input,
//! improvements that only ever lower the piece count, a work rule that
//! makes the answer independent of the thread count, and the repair hook.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use dissect_core::solver::{
    solve_anytime, Anytime, Event, Observer, Options, Outcome, Repair, Via,
};
use dissect_core::verify::verify_pieces;
use dissect_core::{Figure, LatticeKind};

use super::util::{fig, Cubic, Square, Tri4};

fn small(seed: u64, threads: usize) -> Options {
    Options {
        seed,
        threads,
        explorations: 24,
        keep: 8,
        iterations: 20,
        batch: 8,
        ..Options::default()
    }
}

/// Records every improvement.
#[derive(Default)]
struct Improvements(Mutex<Vec<(usize, Via)>>);

impl Observer for Improvements {
    fn on_event(&self, event: &Event) {
        if let Event::Improved { pieces, via, .. } = event {
            self.0.lock().unwrap().push((*pieces, *via));
        }
    }
}

fn anytime(
    figures: &[Figure],
    options: &Options,
    settings: &Anytime,
    repair: Option<&dyn Repair>,
) -> (Outcome, Vec<(usize, Via)>) {
    let seen = Improvements::default();
    let outcome = solve_anytime(
        figures,
        options,
        settings,
        &AtomicBool::new(false),
        &seen,
        repair,
    )
    .expect("solvable input");
    let list = seen.0.into_inner().unwrap();
    (outcome, list)
}

fn verified(lattice: LatticeKind, figures: &[Figure], outcome: &Outcome) -> usize {
    let found = outcome.found.as_ref().expect("a dissection");
    verify_pieces(lattice, true, figures, &found.pieces)
        .unwrap_or_else(|v| panic!("invalid dissection: {}", v[0]))
}

/// Four figures of 27 cubes (a 3×3×3 cube, a 9×3 slab, a step and a
/// 3×3×3 cube with one cube moved on top): the constructive step alone (no rounds)
/// already dissects them.
#[test]
fn four_cubic_figures_of_27_get_a_dissection_without_any_round() {
    let figures = [
        fig(Cubic, "###|###|###/###|###|###/###|###|###"),
        fig(Cubic, "#########|#########|#########"),
        fig(Cubic, "######|######|######/###...|###...|###..."),
        fig(Cubic, "###|###|###/###|###|###/###|###|##./#..|...|..."),
    ];
    assert!(figures.iter().all(|f| f.len() == 27), "27 cubes each");
    let settings = Anytime {
        idle_rounds: Some(0),
        ..Anytime::default()
    };
    let (outcome, improvements) = anytime(&figures, &small(1, 1), &settings, None);
    let n = verified(LatticeKind::Cubic, &figures, &outcome);
    assert_eq!(outcome.rounds, 0, "no round ran");
    assert_eq!(improvements.last().map(|i| i.0), Some(n));
    assert!(improvements.iter().all(|i| i.1 == Via::Greedy));
}

/// A voxelized blob of 200 cubes into a 10×5×4 box (the repository's
/// `blob200-to-box10x5x4`): under 300 cells, but its greedy's 18 pieces are
/// out of the level search's reach, so the run takes the large figures'
/// constructive steps (tidy choices, pilots, regrouping) before any round,
/// and they cut the count by a third.
#[test]
fn a_mid_size_mesh_beyond_the_ladder_gets_the_large_figures_steps() {
    let read = |text: &str| dissect_core::io::parse_figure(text, Cubic).expect("instance figure");
    let figures = [
        read(include_str!(
            "../../../../instances/blob200-to-box10x5x4/a.txt"
        )),
        read(include_str!(
            "../../../../instances/blob200-to-box10x5x4/b.txt"
        )),
    ];
    assert!(figures.iter().all(|f| f.len() == 200));
    let settings = Anytime {
        idle_rounds: Some(0),
        ..Anytime::default()
    };
    let (outcome, improvements) = anytime(&figures, &small(1, 2), &settings, None);
    let n = verified(LatticeKind::Cubic, &figures, &outcome);
    let greedy = improvements
        .iter()
        .filter(|i| i.1 == Via::Greedy)
        .map(|i| i.0)
        .max()
        .expect("the greedy's count");
    assert!(greedy >= 15, "the greedy alone: {greedy} pieces");
    assert!(n <= 12, "{n} pieces: {improvements:?}");
}

/// Records the piece count of every level that starts.
#[derive(Default)]
struct Levels(Mutex<Vec<usize>>);

impl Observer for Levels {
    fn on_event(&self, event: &Event) {
        if let Event::LevelStarted { pieces, .. } = event {
            self.0.lock().unwrap().push(*pieces);
        }
    }
}

/// The same mid-size voxel figures in rounds: the ladder from two pieces
/// up is not run (on voxels its levels take tens of seconds), only the
/// descent from the best count, and the answer stays valid.
#[test]
fn a_mid_size_mesh_beyond_the_ladder_only_descends() {
    let read = |text: &str| dissect_core::io::parse_figure(text, Cubic).expect("instance figure");
    let figures = [
        read(include_str!(
            "../../../../instances/blob200-to-box10x5x4/a.txt"
        )),
        read(include_str!(
            "../../../../instances/blob200-to-box10x5x4/b.txt"
        )),
    ];
    let settings = Anytime {
        idle_rounds: Some(1),
        max_rounds: Some(2),
        ..Anytime::default()
    };
    let levels = Levels::default();
    let outcome = solve_anytime(
        &figures,
        &small(1, 2),
        &settings,
        &AtomicBool::new(false),
        &levels,
        None,
    )
    .expect("solvable input");
    let n = verified(LatticeKind::Cubic, &figures, &outcome);
    let levels = levels.0.into_inner().unwrap();
    assert!(
        outcome.rounds >= 1,
        "at least one round ran: {}",
        outcome.rounds
    );
    // Level 0 (one piece: are the figures congruent?) always runs; the
    // descent's levels are one piece under a count of 10 or more.
    assert!(
        levels.iter().all(|&p| p == 1 || p + 1 >= n),
        "levels of {levels:?} pieces, answer {n}"
    );
    assert!(levels.iter().any(|&p| p > 1), "the descent ran: {levels:?}");
}

/// On every lattice, with two and three figures: each improvement has fewer
/// pieces than the one before, and the answer is the last one.
#[test]
fn improvements_only_ever_lower_the_piece_count() {
    let cases: Vec<(LatticeKind, Vec<Figure>)> = vec![
        (
            Square,
            vec![
                fig(Square, "###.|####|####|.###"),
                fig(Square, "####|####|####|##.."),
            ],
        ),
        (
            Square,
            vec![
                fig(Square, "######|######"),
                fig(Square, "####|####|####"),
                fig(Square, "###|###|###|###"),
            ],
        ),
        (Tri4, vec![fig(Tri4, "FF|FF"), fig(Tri4, "FFFF")]),
        (
            Cubic,
            vec![fig(Cubic, "##|##/##|##"), fig(Cubic, "####|####")],
        ),
    ];
    for (lattice, figures) in cases {
        let (outcome, improvements) = anytime(&figures, &small(3, 2), &Anytime::default(), None);
        let n = verified(lattice, &figures, &outcome);
        assert!(!improvements.is_empty(), "{lattice}: no improvement event");
        for w in improvements.windows(2) {
            assert!(
                w[1].0 < w[0].0,
                "{lattice}: {improvements:?} not decreasing"
            );
        }
        assert_eq!(improvements.last().unwrap().0, n, "{lattice}");
    }
}

/// Without a stop the run ends by its work rule, and the same seed gives
/// the same dissection on 1 and 2 threads.
#[test]
fn same_seed_same_answer_on_1_and_2_threads() {
    // A 5×5 square and a 4×4 beside a 3×3 (touching at a corner cell).
    let figures = [
        fig(Square, "#####|#####|#####|#####|#####"),
        fig(Square, "####...|####...|####...|#######|....###|....###"),
    ];
    assert_eq!(figures[0].len(), figures[1].len());
    for seed in [2, 9] {
        let one = anytime(&figures, &small(seed, 1), &Anytime::default(), None);
        let two = anytime(&figures, &small(seed, 2), &Anytime::default(), None);
        verified(LatticeKind::Square, &figures, &one.0);
        assert_eq!(one.0.found, two.0.found, "seed {seed}");
        assert_eq!(one.1, two.1, "seed {seed}: improvements differ");
    }
}

/// A stop at any moment still leaves the best dissection found so far (or
/// none, when stopped before the first).
#[test]
fn a_stop_at_any_moment_keeps_a_valid_dissection() {
    let figures = [
        fig(Square, "#########|#########|#########|#########"),
        fig(Square, "######|######|######|######|######|######"),
    ];
    /// Raises the stop flag at the `n`th event.
    struct StopAt {
        n: usize,
        seen: Mutex<usize>,
        stop: AtomicBool,
    }
    impl Observer for StopAt {
        fn on_event(&self, _event: &Event) {
            let mut s = self.seen.lock().unwrap();
            *s += 1;
            if *s >= self.n {
                self.stop.store(true, Ordering::SeqCst);
            }
        }
    }
    for n in [1, 2, 3, 5, 20, 100] {
        let obs = StopAt {
            n,
            seen: Mutex::new(0),
            stop: AtomicBool::new(false),
        };
        let outcome = solve_anytime(
            &figures,
            &small(5, 2),
            &Anytime::default(),
            &obs.stop,
            &obs,
            None,
        )
        .expect("solvable");
        if outcome.found.is_some() {
            verified(LatticeKind::Square, &figures, &outcome);
        } else {
            assert!(outcome.stopped, "stopped at event {n} with no answer");
        }
    }
}

/// A rectangle of `w`×`h` cells in the compact form (`|` between rows).
fn rect(w: usize, h: usize) -> String {
    vec!["#".repeat(w); h].join("|")
}

/// Large figures (here 576 cells, above the coarse threshold) are solved at
/// half resolution first: the lifted, refined dissection improves on the
/// constructive one (the pilots of every width included), and the answer
/// is a verified dissection.
#[test]
fn large_figures_are_solved_coarse_to_fine() {
    let figures = [fig(Square, &rect(36, 16)), fig(Square, &rect(24, 24))];
    let settings = Anytime {
        idle_rounds: Some(0),
        ..Anytime::default()
    };
    let (outcome, improvements) = anytime(&figures, &small(1, 2), &settings, None);
    let n = verified(LatticeKind::Square, &figures, &outcome);
    assert!(
        improvements.iter().any(|i| i.1 == Via::Coarse),
        "an improvement from the coarse figures: {improvements:?}"
    );
    assert!(
        improvements.windows(2).all(|w| w[1].0 < w[0].0),
        "improvements only lower the count: {improvements:?}"
    );
    assert!(n <= 3, "{n} pieces for a staircase pair");
}

/// A judge that refuses every dissection with a piece of fewer than
/// `least` cells, and records the valid dissections it saw.
struct Judge {
    least: usize,
    valid: Mutex<Vec<Vec<Vec<Vec<dissect_core::Cell>>>>>,
}

impl Observer for Judge {
    fn on_event(&self, _event: &Event) {}
    fn judges(&self) -> bool {
        true
    }
    fn judge(
        &self,
        pieces: &[Vec<Vec<dissect_core::Cell>>],
        valid: bool,
    ) -> dissect_core::solver::Judgement {
        let accept = pieces[0].iter().all(|p| p.len() >= self.least);
        if valid {
            self.valid.lock().unwrap().push(pieces.to_vec());
        }
        dissect_core::solver::Judgement {
            accept,
            penalty: if accept { 0.0 } else { 10.0 },
            fresh: false,
        }
    }
}

/// A dissection the judge refuses is never the answer; with the plateau
/// the search offers more valid dissections than without it.
#[test]
fn the_judge_refuses_answers_and_the_plateau_offers_more() {
    let figures = [fig(Square, "####|####"), fig(Square, "########")];
    let run = |least: usize, plateau: bool| {
        let judge = Judge {
            least,
            valid: Mutex::new(Vec::new()),
        };
        let settings = Anytime {
            idle_rounds: Some(2),
            plateau,
            ..Anytime::default()
        };
        let outcome = solve_anytime(
            &figures,
            &small(1, 2),
            &settings,
            &AtomicBool::new(false),
            &judge,
            None,
        )
        .expect("solvable input");
        (outcome, judge.valid.into_inner().unwrap())
    };
    let (free, _) = run(1, false);
    let n = verified(Square, &figures, &free);
    assert_eq!(n, 2, "two 1×4 bars");
    // Pieces of at least 5 cells: none (8 = 4 + 4 is the only 2-piece cut,
    // and one piece is not a dissection): no answer at all.
    let (none, seen) = run(5, false);
    assert!(none.found.is_none());
    assert!(
        !seen.is_empty(),
        "the judge saw the valid dissections it refused"
    );
    let (_, plain) = run(1, false);
    let (_, plateau) = run(1, true);
    assert!(
        plateau.len() > plain.len(),
        "{} vs {}",
        plateau.len(),
        plain.len()
    );
}

/// A judge that calls each dissection it has not seen before fresh, up to
/// `wanted` of them, and counts the rounds.
struct Fresh {
    wanted: usize,
    seen: Mutex<Vec<Vec<Vec<Vec<dissect_core::Cell>>>>>,
    rounds: Mutex<usize>,
}

impl Observer for Fresh {
    fn on_event(&self, event: &Event) {
        if matches!(event, Event::RoundStarted { .. }) {
            *self.rounds.lock().unwrap() += 1;
        }
    }
    fn judges(&self) -> bool {
        true
    }
    fn judge(
        &self,
        pieces: &[Vec<Vec<dissect_core::Cell>>],
        valid: bool,
    ) -> dissect_core::solver::Judgement {
        let mut seen = self.seen.lock().unwrap();
        let fresh = valid && seen.len() < self.wanted && !seen.iter().any(|p| p == pieces);
        if fresh {
            seen.push(pieces.to_vec());
        }
        dissect_core::solver::Judgement {
            fresh,
            ..Default::default()
        }
    }
}

/// With the plateau, a round that meets dissections the judge calls fresh
/// is no idle round: the run goes on while they come, and still ends on
/// its own (the same way for 1 and 2 threads).
#[test]
fn fresh_dissections_keep_a_plateau_run_going() {
    let figures = [fig(Square, "####|####"), fig(Square, "########")];
    let run = |wanted: usize, threads: usize| {
        let judge = Fresh {
            wanted,
            seen: Mutex::new(Vec::new()),
            rounds: Mutex::new(0),
        };
        let settings = Anytime {
            idle_rounds: Some(1),
            plateau: true,
            ..Anytime::default()
        };
        let out = solve_anytime(
            &figures,
            &small(5, threads),
            &settings,
            &AtomicBool::new(false),
            &judge,
            None,
        )
        .unwrap();
        let found = out.found.expect("a dissection");
        assert!(verify_pieces(Square, true, &figures, &found.pieces).is_ok());
        let rounds = *judge.rounds.lock().unwrap();
        (rounds, judge.seen.into_inner().unwrap().len(), found.pieces)
    };
    let (without, _, _) = run(0, 1);
    let (with, seen, answer) = run(1000, 1);
    assert!(seen > 1, "{seen} fresh dissections");
    assert!(
        with > without,
        "{with} rounds with fresh ones, {without} without"
    );
    assert_eq!(run(1000, 2), (with, seen, answer));
}
