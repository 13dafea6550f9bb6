//! The engine's contracts: options checked once with typed errors, every
//! answer verified, improvements that only lower the piece count, the
//! optimal mark where the bound meets the answer, a near miss repaired
//! exactly, and the same answer for any thread count without a time limit.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use dissect_core::io::parse_figure;
use dissect_core::solver::Repair;
use dissect_core::verify::verify_pieces;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_engine::{
    run, End, EngineEvent, EngineObserver, ExactRepair, OptionsError, RunConfig, RunOptions,
    Source, Strategy, TimeLimit, MAX_THREADS,
};
use dissect_exact::RepairOptions;

fn square(rows: &[&str]) -> Figure {
    parse_figure(&(rows.join("\n") + "\n"), LatticeKind::Square).expect("test figure")
}

fn small() -> RunConfig {
    RunConfig {
        explorations: 24,
        keep: 6,
        iterations: 20,
        ..RunConfig::default()
    }
}

#[test]
fn every_option_rule_is_checked_once_with_a_typed_error() {
    let bad: Vec<(RunConfig, &str)> = vec![
        (
            RunConfig {
                explorations: 0,
                ..small()
            },
            "--explorations",
        ),
        (
            RunConfig {
                explorations: 1_000_001,
                ..small()
            },
            "--explorations",
        ),
        (RunConfig { keep: 0, ..small() }, "--keep"),
        (
            RunConfig {
                threads: 100_000,
                ..small()
            },
            "--threads",
        ),
        (
            RunConfig {
                max_pieces: Some(0),
                ..small()
            },
            "--max-pieces",
        ),
        (
            RunConfig {
                area_weight: -0.5,
                ..small()
            },
            "--area-weight",
        ),
        (
            RunConfig {
                area_weight: f64::NAN,
                ..small()
            },
            "--area-weight",
        ),
        (
            RunConfig {
                split_penalty: f64::INFINITY,
                ..small()
            },
            "--split-penalty",
        ),
    ];
    for (config, name) in bad {
        let e: OptionsError = RunOptions::new(config.clone()).expect_err(name);
        assert!(e.to_string().starts_with(name), "{name}: {e}");
    }
    // NaN and negative limits are refused (one rule: TimeLimit); an
    // infinite limit is no limit; the defaults are valid.
    for bad in [-1.0, f64::NAN] {
        let e = TimeLimit::new(bad).expect_err("refused");
        assert!(e.to_string().starts_with("--time-limit"), "{e}");
    }
    let o = RunOptions::new(RunConfig {
        time_limit: TimeLimit::new(f64::INFINITY).unwrap(),
        ..small()
    })
    .unwrap();
    assert_eq!(o.time_limit(), None);
    let e = RunOptions::new(RunConfig {
        threads: MAX_THREADS + 1,
        ..small()
    })
    .expect_err("too many threads");
    assert!(e.to_string().starts_with("--threads"), "{e}");
    RunOptions::new(RunConfig::default()).expect("defaults are valid");
}

/// Records the engine's improvements and bounds.
#[derive(Default)]
struct Seen {
    improvements: Mutex<Vec<usize>>,
    bounds: Mutex<Vec<usize>>,
}

impl EngineObserver for Seen {
    fn on_event(&self, event: &EngineEvent<'_>) {
        match event {
            EngineEvent::Improved(i) => self.improvements.lock().unwrap().push(i.pieces),
            EngineEvent::LowerBound(b) => self.bounds.lock().unwrap().push(b.value),
            _ => {}
        }
    }
}

#[test]
fn a_run_reports_a_verified_answer_its_history_and_the_optimal_mark() {
    // A 3×3 and a 4×4 square into a 5×5 square: 4 pieces, proved optimal.
    let figures = [
        square(&[
            "###.....", "###.....", "###.####", "....####", "....####", "....####",
        ]),
        square(&["#####", "#####", "#####", "#####", "#####"]),
    ];
    let names = vec!["a".to_string(), "b".to_string()];
    let seen = Seen::default();
    let options = RunOptions::new(small()).unwrap();
    let report = run(&figures, &names, &options, &AtomicBool::new(false), &seen).unwrap();
    let best = report.best.as_ref().expect("a dissection");
    assert_eq!(
        verify_pieces(LatticeKind::Square, true, &figures, best.pieces()),
        Ok(best.piece_count())
    );
    assert_eq!(best.piece_count(), 4);
    assert!(report.optimal);
    assert_eq!(report.lower_bound.value, 4);
    assert_eq!(report.end, End::Optimal);
    let counts: Vec<usize> = report.history.iter().map(|h| h.pieces).collect();
    assert_eq!(counts, *seen.improvements.lock().unwrap());
    assert!(counts.windows(2).all(|w| w[1] < w[0]), "{counts:?}");
    assert_eq!(counts.last(), Some(&4));
    assert!(report.time_to_first <= report.time_to_best);
    let json: serde_json::Value =
        serde_json::from_str(&report.solution_json().expect("json")).unwrap();
    assert_eq!(json["optimal"], true);
    assert_eq!(json["lower_bound"], 4);
    assert_eq!(json["history"].as_array().unwrap().len(), counts.len());
}

/// The 3×3 and 4×4 squares into a 5×5 square: the constructive dissection
/// is already optimal (4 pieces) but has pieces of 2 cells; the polish
/// finds 4 pieces without a sliver, and the answer is still optimal.
#[test]
fn an_optimal_answer_with_slivers_is_polished_at_the_same_count() {
    let figures = [
        square(&["####..###", "####..###", "####..###", "####....."]),
        square(&["#####", "#####", "#####", "#####", "#####"]),
    ];
    let names = vec!["a".to_string(), "b".to_string()];
    let options = RunOptions::new(RunConfig::default()).unwrap();
    let report = run(&figures, &names, &options, &AtomicBool::new(false), &()).unwrap();
    let best = report.best.as_ref().expect("a dissection");
    assert_eq!(
        verify_pieces(LatticeKind::Square, true, &figures, best.pieces()),
        Ok(4)
    );
    assert!(report.optimal);
    let sizes: Vec<usize> = best.pieces()[0].iter().map(Vec::len).collect();
    assert!(
        sizes.iter().all(|&n| n >= dissect_engine::SLIVER_CELLS),
        "no sliver: {sizes:?}"
    );
}

#[test]
fn without_a_time_limit_the_answer_is_the_same_for_1_and_2_threads() {
    let figures = [
        square(&[
            "########", "#......#", "#.####.#", "#.#..#.#", "#.#..#.#", "#.####.#", "#......#",
            "########",
        ]),
        square(&["########", "########", "########", "########", "########"]),
    ];
    assert_eq!(figures[0].len(), figures[1].len());
    for prove in [false, true] {
        let answers: Vec<_> = [1, 2]
            .into_iter()
            .map(|threads| {
                let options = RunOptions::new(RunConfig {
                    seed: 3,
                    threads,
                    prove,
                    ..small()
                })
                .unwrap();
                let r = run(&figures, &[], &options, &AtomicBool::new(false), &()).unwrap();
                assert!(!r.end.stopped());
                r.best.expect("a dissection").pieces().to_vec()
            })
            .collect();
        assert_eq!(answers[0], answers[1], "prove {prove}");
    }
}

#[test]
fn the_order_of_the_figures_does_not_change_the_answer() {
    let figures = [
        square(&["####", "####", "####", "####"]),
        square(&["########", "########"]),
        square(&["#.....", "######", "######", "##....", "#....."]),
    ];
    let names = ["square", "bar", "comb"];
    let options = RunOptions::new(RunConfig { seed: 5, ..small() }).unwrap();
    let mut answers = Vec::new();
    for order in [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ] {
        let figs: Vec<Figure> = order.iter().map(|&i| figures[i].clone()).collect();
        let named: Vec<String> = order.iter().map(|&i| names[i].to_string()).collect();
        let r = run(&figs, &named, &options, &AtomicBool::new(false), &()).unwrap();
        let best = r.best.expect("a dissection");
        assert!(verify_pieces(LatticeKind::Square, true, &figs, best.pieces()).is_ok());
        assert_eq!(best.dissection().names(), named.as_slice(), "input order");
        // Figure i of the instance, wherever it was given.
        let mut by_figure = vec![Vec::new(); 3];
        for (place, &i) in order.iter().enumerate() {
            by_figure[i] = best.pieces()[place].clone();
        }
        answers.push((best.piece_count(), by_figure));
    }
    for a in &answers[1..] {
        assert_eq!(a, &answers[0], "the same dissection in every order");
    }
}

#[test]
fn a_raised_stop_still_returns_a_verified_answer_or_none() {
    let figures = [
        square(&["#########", "#########", "#########", "#########"]),
        square(&["######", "######", "######", "######", "######", "######"]),
    ];
    let stop = AtomicBool::new(true);
    let options = RunOptions::new(small()).unwrap();
    let r = run(&figures, &[], &options, &stop, &()).unwrap();
    assert_eq!(r.end, End::Interrupted);
    if let Some(best) = &r.best {
        assert!(verify_pieces(LatticeKind::Square, true, &figures, best.pieces()).is_ok());
    }
    // Raised by the first improvement: that one is kept.
    struct StopAtFirst(AtomicBool);
    impl EngineObserver for StopAtFirst {
        fn on_event(&self, event: &EngineEvent<'_>) {
            if matches!(event, EngineEvent::Improved(_)) {
                self.0.store(true, Ordering::SeqCst);
            }
        }
    }
    let obs = StopAtFirst(AtomicBool::new(false));
    let r = run(&figures, &[], &options, &obs.0, &obs).unwrap();
    let best = r.best.expect("the first improvement is kept");
    assert!(verify_pieces(LatticeKind::Square, true, &figures, best.pieces()).is_ok());
}

/// A near miss on ASCII figures: a 2×4 rectangle and a 1×8 bar, cut as
/// two 2×2 squares and two 1×4 bars (same areas, wrong shapes: E_M > 0).
/// The exact repair makes it a dissection with at most two pieces.
#[test]
fn a_near_miss_is_repaired_exactly() {
    let figures = [square(&["####", "####"]), square(&["########"])];
    let cells = |f: &Figure, keep: &dyn Fn(&Cell) -> bool| -> Vec<Cell> {
        f.cells().iter().copied().filter(|c| keep(c)).collect()
    };
    let near = vec![
        vec![
            cells(&figures[0], &|c| c[0] < 2),
            cells(&figures[0], &|c| c[0] >= 2),
        ],
        vec![
            cells(&figures[1], &|c| c[0] < 4),
            cells(&figures[1], &|c| c[0] >= 4),
        ],
    ];
    assert!(verify_pieces(LatticeKind::Square, true, &figures, &near).is_err());
    let repairer = ExactRepair::new(&figures, RepairOptions::default());
    let fixed = repairer
        .repair(&near, &AtomicBool::new(false))
        .expect("repaired");
    let n = verify_pieces(LatticeKind::Square, true, &figures, &fixed).expect("valid");
    assert!(n <= 2, "{n} pieces");
}

#[test]
fn exact_alone_finds_and_proves_a_minimum() {
    let figures = [square(&["###", "###"]), square(&["######"])];
    let options = RunOptions::new(RunConfig {
        strategy: Strategy::Exact,
        ..small()
    })
    .unwrap();
    let r = run(&figures, &[], &options, &AtomicBool::new(false), &()).unwrap();
    assert_eq!(r.source, Some(Source::Sat));
    assert_eq!(r.best.unwrap().piece_count(), 2);
    assert!(r.optimal);
}

/// A sector of a rasterized disc (two strips of its rim) and the corner of
/// a square they fill: the exact dissection of small figures finds the
/// fewest pieces (4), and at that count none of fewer than three cells,
/// though the exact search's own first minimum has such a piece.
#[test]
fn small_figures_are_dissected_exactly_without_slivers() {
    let figures = [
        square(&[
            "...................##",
            "...................##",
            "...................##",
            "...................##",
            "...................##",
            "...................##",
            "...................#.",
            "...................#.",
            "#########............",
            "#######..............",
        ]),
        square(&[
            ".......#", ".......#", "......##", ".....###", "....####", "...#####", "..######",
            "########",
        ]),
    ];
    let options = dissect_exact::ExactOptions {
        mode: dissect_exact::Mode::Minimum,
        ..dissect_exact::ExactOptions::default()
    };
    let upper = std::sync::atomic::AtomicUsize::new(usize::MAX);
    let plain = dissect_exact::search(&figures, &options, &AtomicBool::new(false), &upper, &())
        .unwrap()
        .found
        .expect("a minimum");
    assert_eq!(plain[0].len(), 4);
    assert!(
        plain[0]
            .iter()
            .any(|p| p.len() < dissect_engine::SLIVER_CELLS),
        "the plain minimum has a sliver (else this test shows nothing)"
    );
    let repairer = ExactRepair::new(&figures, RepairOptions::default());
    let cells: Vec<Vec<Cell>> = figures.iter().map(|f| f.cells().to_vec()).collect();
    let pieces = repairer
        .dissect(&cells, 4, &AtomicBool::new(false))
        .expect("a dissection");
    assert_eq!(
        verify_pieces(LatticeKind::Square, true, &figures, &pieces),
        Ok(4)
    );
    let sizes: Vec<usize> = pieces[0].iter().map(Vec::len).collect();
    assert!(
        sizes.iter().all(|&n| n >= dissect_engine::SLIVER_CELLS),
        "{sizes:?}"
    );
}

/// The 3×3 and 4×4 squares into a 5×5 square within a time limit and
/// without the proof, so that only the limit ends the run: the constructive
/// answer (4 pieces, two of 2 cells) cannot be beaten, and the last part of
/// the time goes to the polish, which finds 4 pieces without a sliver.
#[test]
fn a_sliver_answer_is_polished_within_the_time_limit() {
    let figures = [
        square(&["####..###", "####..###", "####..###", "####....."]),
        square(&["#####", "#####", "#####", "#####", "#####"]),
    ];
    let names = vec!["a".to_string(), "b".to_string()];
    let options = RunOptions::new(RunConfig {
        prove: false,
        time_limit: TimeLimit::new(16.0).unwrap(),
        ..RunConfig::default()
    })
    .unwrap();
    let report = run(&figures, &names, &options, &AtomicBool::new(false), &()).unwrap();
    assert_eq!(report.end, End::TimeLimit);
    let best = report.best.as_ref().expect("a dissection");
    assert_eq!(
        verify_pieces(LatticeKind::Square, true, &figures, best.pieces()),
        Ok(4)
    );
    let sizes: Vec<usize> = best.pieces()[0].iter().map(Vec::len).collect();
    assert!(
        sizes.iter().all(|&n| n >= dissect_engine::SLIVER_CELLS),
        "no sliver: {sizes:?}"
    );
}
