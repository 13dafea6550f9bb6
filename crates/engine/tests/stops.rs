//! A stop honoured within a second in every phase of a run (issue 27): the
//! stop is raised by the observer when the phase starts
//! ([`EngineEvent::Phase`]), so the phase is running when it comes on any
//! machine, fast or slow; the run must return within [`LATE`] of it with
//! the best answer found so far, verified.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use dissect_core::io::parse_figure;
use dissect_core::verify::verify_pieces;
use dissect_core::{Figure, LatticeKind};
use dissect_engine::{
    run, End, EngineEvent, EngineObserver, Phase, Rank, Report, RunConfig, RunOptions, TimeLimit,
};

/// The bound: a phase stops within one second (measured: 2-33 ms
/// after the stop on a loaded 2-core machine).
const LATE: Duration = Duration::from_secs(1);

fn square(rows: &[&str]) -> Figure {
    parse_figure(&(rows.join("\n") + "\n"), LatticeKind::Square).expect("test figure")
}

/// A `w`×`h` rectangle.
fn rect(w: usize, h: usize) -> Figure {
    let row = "#".repeat(w);
    square(&vec![row.as_str(); h])
}

/// The two figures of an instance.
fn instance(name: &str) -> [Figure; 2] {
    ["a.txt", "b.txt"].map(|f| {
        let path = dissect_testkit::repo::instance_file(name, f);
        let text = std::fs::read_to_string(path).expect("the instance");
        parse_figure(&text, LatticeKind::Square).expect("a figure")
    })
}

/// The 3×3 and 4×4 squares and the 5×5 square: the constructive answer
/// (4 pieces, optimal) has pieces of 2 cells, so it is polished.
fn squares_3_4_5() -> [Figure; 2] {
    [
        square(&["####..###", "####..###", "####..###", "####....."]),
        square(&["#####", "#####", "#####", "#####", "#####"]),
    ]
}

/// Raises the stop at the first event that `when` picks, and keeps the
/// fewest pieces improved before it.
struct StopAt<F: Fn(&EngineEvent<'_>) -> bool + Sync> {
    when: F,
    stop: AtomicBool,
    raised: Mutex<Option<Instant>>,
    best: Mutex<Option<usize>>,
}

impl<F: Fn(&EngineEvent<'_>) -> bool + Sync> EngineObserver for StopAt<F> {
    fn on_event(&self, event: &EngineEvent<'_>) {
        if let EngineEvent::Improved(i) = event {
            let mut best = self.best.lock().unwrap();
            if self.raised.lock().unwrap().is_none() {
                *best = Some(best.map_or(i.pieces, |b| b.min(i.pieces)));
            }
        }
        if (self.when)(event) {
            let mut raised = self.raised.lock().unwrap();
            if raised.is_none() {
                *raised = Some(Instant::now());
                self.stop.store(true, Ordering::SeqCst);
            }
        }
    }
}

/// Runs with `config` on `figures`, stopped at the first event `when`
/// picks: the report, after checking that the stop came (the phase ran),
/// the run returned within [`LATE`] of it, and its answers
/// are verified, the best no worse than the best improvement before the
/// stop.
fn stopped(
    what: &str,
    figures: &[Figure],
    config: RunConfig,
    when: impl Fn(&EngineEvent<'_>) -> bool + Sync,
) -> Report {
    let options = RunOptions::new(config).unwrap();
    let observer = StopAt {
        when,
        stop: AtomicBool::new(false),
        raised: Mutex::new(None),
        best: Mutex::new(None),
    };
    let names = vec!["a".to_string(), "b".to_string()];
    let report = run(figures, &names, &options, &observer.stop, &observer).expect("a run");
    let returned = Instant::now();
    let raised = observer.raised.lock().unwrap().expect("the phase ran");
    let late = returned - raised;
    eprintln!("{what}: returned {late:?} after the stop");
    assert!(
        late < LATE,
        "{what}: the run returned {late:?} after the stop"
    );
    let best = report.best.as_ref().expect("the best so far");
    let lattice = figures[0].lattice();
    let n = verify_pieces(lattice, true, figures, best.pieces()).expect("verified");
    if let Some(before) = *observer.best.lock().unwrap() {
        assert!(
            n <= before,
            "{what}: {n} pieces, {before} found before the stop"
        );
    }
    for s in &report.solutions {
        verify_pieces(lattice, true, figures, s.dissection.pieces()).expect("verified");
    }
    report
}

fn phase(p: Phase) -> impl Fn(&EngineEvent<'_>) -> bool + Sync {
    move |e| matches!(e, EngineEvent::Phase(q) if *q == p)
}

#[test]
fn a_stop_in_the_exact_repair_ends_the_run_within_a_second() {
    let figures = instance("sierpinski9-to-square8");
    let report = stopped(
        "repair",
        &figures,
        RunConfig {
            threads: 2,
            ..RunConfig::default()
        },
        phase(Phase::Repair),
    );
    assert_eq!(report.end, End::Interrupted);
}

#[test]
fn a_stop_in_the_sectors_ends_the_run_within_a_second() {
    let figures = instance("disc21-to-square37");
    let report = stopped(
        "sectors",
        &figures,
        RunConfig {
            threads: 2,
            ..RunConfig::default()
        },
        phase(Phase::Sectors),
    );
    assert_eq!(report.end, End::Interrupted);
}

#[test]
fn a_stop_in_the_polish_ends_the_run_within_a_second() {
    // Without the proof, only the limit ends the search, and its last
    // 2.4 s go to the polish: the stop comes at the polish's start.
    let report = stopped(
        "polish",
        &squares_3_4_5(),
        RunConfig {
            prove: false,
            threads: 2,
            time_limit: TimeLimit::new(16.0).unwrap(),
            ..RunConfig::default()
        },
        phase(Phase::Polish),
    );
    // The search ended at its limit; the polish was cut short.
    assert_eq!(report.end, End::TimeLimit);
}

#[test]
fn a_stop_while_collecting_several_solutions_ends_the_run_within_a_second() {
    let figures = [rect(48, 48), rect(128, 18)];
    let report = stopped(
        "several solutions",
        &figures,
        RunConfig {
            threads: 2,
            solutions: 5,
            ..RunConfig::default()
        },
        |e| matches!(e, EngineEvent::Collected { .. }),
    );
    assert_eq!(report.end, End::Interrupted);
    assert!(!report.solutions.is_empty());
}

#[test]
fn a_stop_while_ranking_several_solutions_ends_the_run_within_a_second() {
    // The disc's pieces tile the figures in many ways: a count of their
    // assemblies may take its 5 s, for each of the solutions collected.
    let report = stopped(
        "ranking",
        &instance("disc21-to-square37"),
        RunConfig {
            threads: 2,
            solutions: 5,
            rank: Rank::Unique,
            time_limit: TimeLimit::new(3.0).unwrap(),
            ..RunConfig::default()
        },
        phase(Phase::Ranking),
    );
    assert!(!report.solutions.is_empty());
}
