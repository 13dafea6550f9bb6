//! The exact search's limits: a deterministic conflict budget, the size
//! guard that refuses encodings too large for memory, and stops (deadline
//! and stop flag) honoured within a second in every phase.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use dissect_core::io::parse_figure;
use dissect_core::{Figure, LatticeKind};
use dissect_exact::{
    dimacs, dimacs_within, search, ExactError, ExactOptions, ExactOutcome, Limit, Mode,
};

fn rect(w: usize, h: usize) -> String {
    format!("{}\n", "#".repeat(w)).repeat(h)
}

fn square(texts: &[String]) -> Vec<Figure> {
    texts
        .iter()
        .map(|t| parse_figure(t, LatticeKind::Square).expect("test figure parses"))
        .collect()
}

/// The two figures of a square instance of the repository's `instances/`.
fn instance(name: &str) -> Vec<Figure> {
    let read = |file| {
        std::fs::read_to_string(dissect_testkit::repo::instance_file(name, file)).expect("instance")
    };
    square(&[read("a.txt"), read("b.txt")])
}

fn run(figs: &[Figure], options: &ExactOptions, stop: &AtomicBool) -> ExactOutcome {
    let upper = AtomicUsize::new(usize::MAX);
    search(figs, options, stop, &upper, &()).expect("search runs")
}

#[test]
fn the_conflict_budget_ends_the_search_the_same_way_every_time() {
    let figs = instance("sierpinski9-to-square8");
    let options = ExactOptions {
        conflict_budget: Some(1500),
        ..ExactOptions::default()
    };
    let stop = AtomicBool::new(false);
    let first = run(&figs, &options, &stop);
    assert!(first.stopped);
    assert_eq!(first.limit, Some(Limit::ConflictBudget));
    assert!(first.conflicts <= 1500, "{} conflicts", first.conflicts);
    assert!(first.conflicts > 0);
    let again = run(&figs, &options, &stop);
    assert_eq!(again.lower_bound.value, first.lower_bound.value);
    assert_eq!(again.conflicts, first.conflicts);
    assert_eq!(again.limit, first.limit);
}

#[test]
fn restricted_passes_can_count_conflicts_instead_of_time() {
    let figs = instance("squares-3-4-split-to-5");
    let options = ExactOptions {
        mode: Mode::Minimum,
        restricted_conflicts: Some(200),
        restricted_time: Duration::ZERO,
        ..ExactOptions::default()
    };
    let stop = AtomicBool::new(false);
    let outcome = run(&figs, &options, &stop);
    assert!(outcome.optimal());
    let found = outcome.found.expect("the full pass finds one");
    assert_eq!(found[0].len(), 4);
}

#[test]
fn an_encoding_over_the_cap_is_refused_not_built() {
    let figs = instance("sierpinski9-to-square8");
    let options = ExactOptions {
        max_encoding_bytes: 100_000,
        ..ExactOptions::default()
    };
    let stop = AtomicBool::new(false);
    let outcome = run(&figs, &options, &stop);
    assert!(outcome.stopped);
    assert!(outcome.found.is_none());
    match outcome.limit {
        Some(Limit::TooLarge { pieces, bytes }) => {
            assert_eq!(pieces, outcome.lower_bound.value);
            assert!(bytes > 100_000);
        }
        other => panic!("expected TooLarge, got {other:?}"),
    }
    // A bar 3 wide against a 15×17 rectangle needs at least 5 pieces, and
    // its 5-piece encoding has millions of clauses: refused under a 50 MiB
    // cap before any is built.
    let figs = square(&[rect(85, 3), rect(15, 17)]);
    let capped = ExactOptions {
        max_encoding_bytes: 50 << 20,
        ..ExactOptions::default()
    };
    let outcome = run(&figs, &capped, &stop);
    assert_eq!(outcome.lower_bound.value, 5);
    assert!(matches!(
        outcome.limit,
        Some(Limit::TooLarge { pieces: 5, .. })
    ));
    assert_eq!(outcome.conflicts, 0);
}

#[test]
fn dimacs_refuses_huge_piece_counts_quickly() {
    let figs = square(&[rect(85, 3), rect(15, 17)]);
    let start = Instant::now();
    let err = dimacs(&figs, true, 1_000_000).unwrap_err();
    assert!(start.elapsed() < Duration::from_secs(1));
    match &err {
        ExactError::TooLarge { pieces, bytes, cap } => {
            assert_eq!(*pieces, 1_000_000);
            assert!(bytes > cap);
        }
        other => panic!("expected TooLarge, got {other:?}"),
    }
    assert!(err.to_string().contains("1000000 pieces"), "{err}");
    let small = square(&[rect(3, 2), rect(6, 1)]);
    assert!(matches!(
        dimacs_within(&small, true, 2, 1000),
        Err(ExactError::TooLarge { .. })
    ));
    // A piece count above the number of cells is the number of cells.
    let d = dimacs(&small, true, 1_000_000).expect("small enough");
    assert_eq!(d, dimacs(&small, true, 6).unwrap());
}

/// Runs the search with a deadline `limit` from now, or with the stop flag
/// raised after `limit`, and returns how long it took.
fn time_to_stop(figs: &[Figure], limit: Duration, by_flag: bool) -> (Duration, ExactOutcome) {
    let stop = AtomicBool::new(false);
    let start = Instant::now();
    let options = ExactOptions {
        deadline: (!by_flag).then(|| start + limit),
        ..ExactOptions::default()
    };
    let outcome = std::thread::scope(|s| {
        let h = s.spawn(|| run(figs, &options, &stop));
        if by_flag {
            while !h.is_finished() && start.elapsed() < limit {
                std::thread::sleep(Duration::from_millis(5));
            }
            stop.store(true, Ordering::SeqCst);
        }
        h.join().expect("search thread")
    });
    (start.elapsed(), outcome)
}

#[test]
fn a_deadline_stops_the_cheap_bounds_on_big_figures() {
    // 9,000 cells: the incompatibility graphs alone would take minutes.
    let figs = square(&[rect(100, 90), rect(60, 150)]);
    let (took, outcome) = time_to_stop(&figs, Duration::from_secs(1), false);
    assert!(took < Duration::from_millis(2500), "took {took:?}");
    // Over the SAT search's size only the cheap bounds run: stopped by the
    // deadline, or ended by themselves before it.
    assert!(
        outcome.stopped || matches!(outcome.limit, Some(dissect_exact::Limit::Cells { .. })),
        "{outcome:?}"
    );
    assert_eq!(
        outcome.lower_bound.value, 2,
        "not congruent is still proved"
    );
}

#[test]
fn the_stop_flag_ends_the_cheap_bounds_on_big_figures() {
    let figs = square(&[rect(100, 90), rect(60, 150)]);
    let (took, outcome) = time_to_stop(&figs, Duration::from_millis(500), true);
    assert!(took < Duration::from_millis(2000), "took {took:?}");
    assert!(
        outcome.stopped || matches!(outcome.limit, Some(dissect_exact::Limit::Cells { .. })),
        "{outcome:?}"
    );
}

#[test]
fn a_deadline_stops_the_solver_and_the_connectivity_encoding() {
    // The 4-piece question on the Sierpinski carpet runs for long in the
    // solver (with connectivity added after its first split model).
    let figs = instance("sierpinski9-to-square8");
    for secs in [1, 2] {
        let limit = Duration::from_secs(secs);
        let (took, outcome) = time_to_stop(&figs, limit, false);
        assert!(took < limit + Duration::from_millis(1500), "took {took:?}");
        assert!(outcome.stopped && outcome.found.is_none());
    }
    let (took, outcome) = time_to_stop(&figs, Duration::from_millis(1500), true);
    assert!(took < Duration::from_millis(3000), "took {took:?}");
    assert!(outcome.stopped);
}

#[test]
fn a_deadline_stops_a_large_encoding() {
    // 255 cells each: the 2-piece encoding has over a million clauses; a
    // larger cap lets a bigger one start, and the deadline still ends it.
    let mut notched = rect(16, 15);
    notched.push_str(&"#".repeat(15));
    notched.push_str(".\n");
    let figs = square(&[notched, rect(15, 17)]);
    for ms in [300, 700, 1000] {
        let stop = AtomicBool::new(false);
        let start = Instant::now();
        let options = ExactOptions {
            deadline: Some(start + Duration::from_millis(ms)),
            max_encoding_bytes: 4 << 30,
            ..ExactOptions::default()
        };
        let outcome = run(&figs, &options, &stop);
        let took = start.elapsed();
        assert!(
            took < Duration::from_millis(ms + 1000),
            "deadline {ms} ms, took {took:?}"
        );
        if outcome.found.is_none() {
            assert!(outcome.stopped);
        }
    }
}

/// Records the encodings the search builds.
struct Encodings(std::sync::Mutex<Vec<(usize, dissect_exact::EncodingSize)>>);

impl dissect_exact::ExactObserver for Encodings {
    fn on_event(&self, event: &dissect_exact::ExactEvent) {
        if let dissect_exact::ExactEvent::Encoded { pieces, size, .. } = event {
            self.0.lock().expect("lock").push((*pieces, *size));
        }
    }
}

#[test]
fn figures_over_the_full_graph_size_get_a_sat_model_by_shifts() {
    // 676 cells each (over FULL_GRAPH_MAX_CELLS): no incompatibility graph,
    // a SAT model all the same; one variable per motion would take about
    // 1 GB here, the shift chain a few dozen MB. Two 13×26 halves.
    let figs = square(&[rect(26, 26), rect(13, 52)]);
    assert!(figs[0].len() > dissect_exact::bound::FULL_GRAPH_MAX_CELLS);
    let options = ExactOptions {
        mode: Mode::Minimum,
        sat_max_cells: dissect_exact::bound::SAT_MAX_CELLS,
        ..ExactOptions::default()
    };
    let stop = AtomicBool::new(false);
    let upper = AtomicUsize::new(usize::MAX);
    let default = search(&figs, &ExactOptions::default(), &stop, &upper, &()).expect("runs");
    assert!(
        matches!(
            default.limit,
            Some(dissect_exact::Limit::Cells { cells: 676 })
        ),
        "by default figures over the full graph's size get no SAT model: {default:?}"
    );
    let seen = Encodings(std::sync::Mutex::new(Vec::new()));
    let outcome = search(&figs, &options, &stop, &upper, &seen).expect("search runs");
    let found = outcome.found.clone().expect("two halves");
    let count = dissect_core::verify::verify_pieces(LatticeKind::Square, true, &figs, &found)
        .expect("a valid dissection");
    assert_eq!(count, 2);
    assert!(outcome.optimal(), "{:?}", outcome.lower_bound);
    let seen = seen.0.lock().expect("lock");
    assert!(!seen.is_empty());
    for (k, size) in seen.iter() {
        let bytes = size.bytes(false);
        assert!(bytes < 256 << 20, "k={k}: {size:?}, {bytes} bytes");
    }
}

#[test]
fn a_deadline_stops_the_shift_estimate_and_encoding_of_large_figures() {
    // 1,800 cells each, SAT models allowed up to 2,000 cells: the shift
    // chain's estimate and encoding take seconds; deadlines inside them end
    // the search within a second or so.
    let figs = square(&[rect(60, 30), rect(45, 40)]);
    for ms in [200, 1000, 2500] {
        let stop = AtomicBool::new(false);
        let start = Instant::now();
        let options = ExactOptions {
            deadline: Some(start + Duration::from_millis(ms)),
            sat_max_cells: dissect_exact::bound::SAT_MAX_CELLS,
            max_encoding_bytes: 4 << 30,
            ..ExactOptions::default()
        };
        let outcome = run(&figs, &options, &stop);
        let took = start.elapsed();
        assert!(
            took < Duration::from_millis(ms + 1200),
            "deadline {ms} ms, took {took:?}"
        );
        assert!(outcome.stopped || outcome.found.is_some(), "{outcome:?}");
    }
}
