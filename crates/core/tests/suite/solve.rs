//! Small end-to-end solves on every lattice, with two and three figures.
//! Every dissection is checked by `verify::verify`, and one of them by the
//! independent checkers as well (`tools/check_solution.py`, and the external
//! `verify.py` when present).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::solver::{solve, Event, Found, Observer, Options, Outcome, SolveError};
use dissect_core::verify::verify;
use dissect_core::Dissection;
use dissect_core::{Figure, LatticeKind};

use super::util::{fig, Cubic, Square, Tri4};

/// Small settings: each solve here takes a fraction of a second.
fn small(seed: u64, threads: usize) -> Options {
    Options {
        seed,
        threads,
        explorations: 32,
        keep: 8,
        iterations: 20,
        batch: 8,
        ..Options::default()
    }
}

fn run(figures: &[Figure], options: &Options) -> Outcome {
    let start = Instant::now();
    let outcome = solve(figures, options, &AtomicBool::new(false), &()).expect("solvable input");
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "a small solve took {:?}",
        start.elapsed()
    );
    outcome
}

fn dissection_of(
    lattice: LatticeKind,
    mirror: bool,
    found: &Found,
    names: Vec<String>,
) -> Dissection {
    Dissection::new(lattice, mirror, names, found.pieces.clone()).expect("cells of the lattice")
}

/// Solves the figures and checks the answer: verified, at most `max_pieces`
/// pieces, consistent areas, and (when known) at least `min_pieces`.
fn check(
    lattice: LatticeKind,
    mirror: bool,
    compact: &[&str],
    min_pieces: usize,
    max_pieces: usize,
) -> Found {
    let figures: Vec<Figure> = compact.iter().map(|s| fig(lattice, s)).collect();
    let options = Options {
        mirror,
        ..small(7, 1)
    };
    let outcome = run(&figures, &options);
    let found = outcome
        .found
        .unwrap_or_else(|| panic!("no dissection of {compact:?} on {lattice}"));
    let names = (0..compact.len()).map(|i| format!("f{i}.txt")).collect();
    let d = dissection_of(lattice, mirror && lattice != Cubic, &found, names);
    assert_eq!(
        verify(&d, &figures),
        Ok(found.piece_count()),
        "{compact:?} on {lattice}: {found:?}"
    );
    let n = found.piece_count();
    assert!(
        (min_pieces..=max_pieces).contains(&n),
        "{compact:?} on {lattice}: {n} pieces, expected {min_pieces}..={max_pieces}"
    );
    assert_eq!(outcome.last_pieces, found.level + 1);
    assert!(!outcome.stopped);
    let areas = found.areas();
    assert_eq!(areas.iter().sum::<usize>(), figures[0].len());
    let mean = areas.iter().sum::<usize>() as f64 / n as f64;
    let variance = areas
        .iter()
        .map(|a| (*a as f64 - mean).powi(2))
        .sum::<f64>()
        / n as f64;
    assert!((found.variance - variance).abs() < 1e-9, "{found:?}");
    for pieces in &found.pieces {
        for p in pieces {
            assert!(
                p.windows(2).all(|w| w[0] < w[1]),
                "pieces are sorted: {p:?}"
            );
        }
    }
    found
}

#[test]
fn square_two_figures() {
    check(Square, true, &["###|###", "######"], 2, 2);
    check(Square, true, &["####|####", "##|##|##|##"], 1, 1);
    check(Square, true, &["###|###|###", "#####|####"], 2, 3);
    check(Square, false, &["###.|.###", "####|##"], 2, 3);
    check(Square, true, &["###|#.#|###", "####|####"], 2, 4);
}

#[test]
fn square_three_figures() {
    check(Square, true, &["###|###", "######", "####|##"], 2, 3);
    check(
        Square,
        true,
        &["###|#.#|###", "####|####", "########"],
        2,
        5,
    );
}

#[test]
fn tri4_two_figures() {
    // The big right triangle and the 2x1 rectangle.
    check(Tri4, true, &["#9|9", "##"], 2, 3);
    // A diamond and a big triangle: two half squares each.
    check(Tri4, true, &["6C|39", "#9|9"], 2, 2);
    check(Tri4, false, &["6#9", "##"], 2, 2);
}

#[test]
fn tri4_three_figures() {
    check(Tri4, true, &["6#9", "##", "#9|9"], 2, 4);
}

#[test]
fn cubic_two_figures() {
    check(Cubic, false, &["##|##/##|##", "####|####"], 2, 2);
    check(Cubic, false, &["###|###", "##|##/#|#"], 2, 3);
}

#[test]
fn cubic_three_figures() {
    check(
        Cubic,
        false,
        &["##|##/##|##", "####|####", "########"],
        2,
        4,
    );
}

#[test]
fn other_settings() {
    // No area term, every exploration of the last level, mirror off.
    let figures = [fig(Square, "###|#.#|###"), fig(Square, "####|####")];
    let options = Options {
        area_weight: 0.0,
        full_levels: true,
        mirror: false,
        ..small(5, 2)
    };
    let outcome = run(&figures, &options);
    let found = outcome.found.expect("a dissection");
    let d = dissection_of(Square, false, &found, vec!["a".into(), "b".into()]);
    assert_eq!(verify(&d, &figures), Ok(found.piece_count()));
}

#[test]
fn congruent_figures_are_one_piece() {
    let found = check(Square, false, &["##.|.##", ".#|##|#."], 1, 1);
    assert_eq!(found.level, 0);
    check(Cubic, false, &["##", "#/#"], 1, 1);
}

#[test]
fn same_seed_same_result_whatever_the_threads() {
    let cases: [(LatticeKind, &[&str]); 3] = [
        (Square, &["###|#.#|###", "####|####"]),
        (Tri4, &["6#9", "##", "#9|9"]),
        (Cubic, &["###|###", "##|##/#|#"]),
    ];
    for (lattice, compact) in cases {
        let figures: Vec<Figure> = compact.iter().map(|s| fig(lattice, s)).collect();
        let one = run(&figures, &small(11, 1));
        let two = run(&figures, &small(11, 2));
        // Eight threads run four batches ahead of the one being decided.
        let eight = run(&figures, &small(11, 8));
        assert_eq!(one.found, two.found, "{compact:?} on {lattice}");
        assert_eq!(
            one.found, eight.found,
            "{compact:?} on {lattice}, 8 threads"
        );
        assert_eq!(one.best_mismatch, two.best_mismatch);
        assert_eq!(one.best_mismatch, eight.best_mismatch);
        assert_eq!(one.explorations, two.explorations);
        assert_eq!(one.explorations, eight.explorations);
        assert!(one.found.is_some());
    }
}

#[test]
fn explorations_are_reported() {
    struct Count(std::sync::Mutex<Vec<Event>>);
    impl Observer for Count {
        fn on_event(&self, event: &Event) {
            self.0.lock().unwrap().push(event.clone());
        }
    }
    let figures = [fig(Square, "###|###"), fig(Square, "######")];
    let seen = Count(Default::default());
    let outcome = solve(&figures, &small(3, 1), &AtomicBool::new(false), &seen).unwrap();
    let events = seen.0.into_inner().unwrap();
    let explorations = events
        .iter()
        .filter(|e| matches!(e, Event::Exploration { .. }))
        .count();
    // Level 0 counts one; the pool may also have run (and dropped) a few
    // explorations past the batch that decided a level, at most its
    // window (one batch on one thread) per level.
    let levels = events
        .iter()
        .filter(|e| matches!(e, Event::LevelFinished { .. }))
        .count();
    assert!(
        explorations + 1 >= outcome.explorations
            && explorations < outcome.explorations + levels * small(3, 1).batch,
        "{explorations} reported, {} counted, {levels} levels",
        outcome.explorations
    );
    assert!(matches!(
        events.first(),
        Some(Event::LevelStarted {
            level: 0,
            pieces: 1,
            ..
        })
    ));
    // The level that found it is the last level event; the improvement it
    // made is the last event.
    assert!(matches!(
        events
            .iter()
            .rev()
            .find(|e| matches!(e, Event::LevelFinished { .. })),
        Some(Event::LevelFinished { found: true, .. })
    ));
    assert!(matches!(events.last(), Some(Event::Improved { .. })));
}

#[test]
fn stop_and_limits() {
    let figures = [fig(Square, "###|#.#|###"), fig(Square, "####|####")];
    // A raised stop flag ends the search before level 1.
    let outcome = solve(&figures, &small(1, 1), &AtomicBool::new(true), &()).unwrap();
    assert!(outcome.stopped);
    assert_eq!(outcome.found, None);
    // One piece is not enough.
    let capped = Options {
        max_pieces: Some(1),
        ..small(1, 1)
    };
    let outcome = solve(&figures, &capped, &AtomicBool::new(false), &()).unwrap();
    assert_eq!(outcome.found, None);
    assert!(!outcome.stopped);
    assert_eq!(outcome.last_pieces, 1);
    assert!(outcome.best_mismatch.unwrap() > 0);
}

#[test]
fn bad_input_is_an_error() {
    let o = small(1, 1);
    let stop = AtomicBool::new(false);
    let sq = fig(Square, "##");
    assert_eq!(
        solve(std::slice::from_ref(&sq), &o, &stop, &()),
        Err(SolveError::TooFewFigures(1))
    );
    assert_eq!(
        solve(&[sq.clone(), fig(Square, "###")], &o, &stop, &()),
        Err(SolveError::UnequalAreas(vec![2, 3]))
    );
    assert_eq!(
        solve(&[sq.clone(), fig(Cubic, "##")], &o, &stop, &()),
        Err(SolveError::MixedLattices(Square, Cubic))
    );
    let big = |w: i32| Figure::new(Square, (0..w).flat_map(|x| (0..5).map(move |y| [x, y, 0])));
    let (a, b) = (big(13_001).unwrap(), big(13_001).unwrap());
    assert_eq!(
        solve(&[a, b], &o, &stop, &()),
        Err(SolveError::TooLarge(65_005))
    );
}

/// Solutions of every kind pass the independent checkers:
/// `tools/check_solution.py` always, the external `verify.py` when present.
#[test]
fn solutions_pass_the_independent_checkers() {
    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("core-solve-python");
    std::fs::create_dir_all(&work).unwrap();
    let cases: [(LatticeKind, bool, &[&str]); 4] = [
        (Square, false, &["###|#.#|###", "####|####"]),
        (Square, true, &["###|###", "######", "####|##"]),
        (Tri4, true, &["6#9", "##", "#9|9"]),
        (Cubic, false, &["##|##/##|##", "####|####", "########"]),
    ];
    for (n, (lattice, mirror, compact)) in cases.into_iter().enumerate() {
        let found = check(lattice, mirror, compact, 1, 8);
        let mut paths = Vec::new();
        let mut names = Vec::new();
        for (i, c) in compact.iter().enumerate() {
            let name = format!("case{n}-f{i}.txt");
            let p = work.join(&name);
            std::fs::write(&p, super::util::text(c)).unwrap();
            paths.push(p);
            names.push(name);
        }
        let d = dissection_of(lattice, mirror && lattice != Cubic, &found, names);
        let sol = work.join(format!("case{n}-solution.json"));
        std::fs::write(&sol, d.to_file(serde_json::Map::new()).to_json()).unwrap();
        let pieces = dissect_testkit::repo::assert_checked(&work, lattice.name(), &sol, &paths);
        assert_eq!(pieces, found.piece_count(), "case {n}");
    }
}
