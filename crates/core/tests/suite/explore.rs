//! Explorations run by a foreign executor (`solve_with`): the same answer as
//! `solve` when every exploration travels through bytes and is run by an
//! `Explorer` of its own, and clear errors when an executor misbehaves.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use dissect_core::solver::{
    solve, solve_anytime, solve_anytime_with, solve_with, Anytime, Batch, Executor, Exploration,
    ExplorationError, Explorer, Options, SolveError,
};
use dissect_core::Figure;

use super::util::{fig, Cubic, Square, Tri4};

fn small(seed: u64) -> Options {
    Options {
        seed,
        threads: 2,
        explorations: 24,
        keep: 6,
        iterations: 20,
        batch: 8,
        ..Options::default()
    }
}

/// Like a remote worker: an explorer built from the figures and options,
/// parents and results as bytes.
struct Remote {
    explorer: Explorer,
    batches: AtomicUsize,
}

impl Executor for Remote {
    fn run(&self, batch: &Batch<'_>) -> Result<Vec<Exploration>, String> {
        self.batches.fetch_add(1, Ordering::Relaxed);
        let parents: Vec<Exploration> = batch
            .parents
            .iter()
            .map(|p| Exploration::from_bytes(&p.to_bytes()).map_err(|e| e.to_string()))
            .collect::<Result<_, _>>()?;
        batch
            .indices
            .clone()
            .map(|i| {
                let e = self
                    .explorer
                    .explore(
                        batch.round,
                        batch.level,
                        batch.descent,
                        i,
                        &parents,
                        &AtomicBool::new(false),
                    )
                    .map_err(|e| e.to_string())?;
                Exploration::from_bytes(&e.to_bytes()).map_err(|e| e.to_string())
            })
            .collect()
    }
}

fn same_as_local(figures: &[Figure], options: &Options) {
    let stop = AtomicBool::new(false);
    let local = solve(figures, options, &stop, &()).expect("solvable");
    let remote = Remote {
        explorer: Explorer::new(figures, options).expect("solvable"),
        batches: AtomicUsize::new(0),
    };
    let spread = solve_with(figures, options, &stop, &(), Some(&remote)).expect("solvable");
    assert!(remote.batches.load(Ordering::Relaxed) > 0);
    assert!(local.found.is_some());
    assert_eq!(spread, local);
    // The anytime schedule too: rounds, the descent, the ladder.
    let anytime = Anytime::default();
    let local = solve_anytime(figures, options, &anytime, &stop, &(), None).expect("solvable");
    let spread = solve_anytime_with(figures, options, &anytime, &stop, &(), None, Some(&remote))
        .expect("solvable");
    assert!(local.found.is_some());
    assert_eq!(spread, local);
}

#[test]
fn a_foreign_executor_gives_the_local_answer_on_every_lattice() {
    same_as_local(
        &[fig(Square, "###|###|###|###"), fig(Square, "######|######")],
        &small(3),
    );
    same_as_local(
        &[
            fig(Square, "###.####|###.####|###.####|....####"),
            fig(Square, "#####|#####|#####|#####|#####"),
        ],
        &small(1),
    );
    same_as_local(&[fig(Tri4, "FF|FF"), fig(Tri4, "FFFF")], &small(2));
    same_as_local(
        &[fig(Cubic, "##|##/##|##"), fig(Cubic, "####|####")],
        &small(4),
    );
}

#[test]
fn explorations_round_trip_and_bad_bytes_are_errors() {
    let figures = [fig(Square, "###|###"), fig(Square, "######")];
    let explorer = Explorer::new(&figures, &small(1)).expect("solvable");
    let e = explorer
        .explore(0, 1, false, 0, &[], &AtomicBool::new(false))
        .expect("level 1 needs no parent");
    let bytes = e.to_bytes();
    assert_eq!(Exploration::from_bytes(&bytes), Ok(e.clone()));
    assert_eq!(e.pieces(), 2);
    assert!(matches!(
        Exploration::from_bytes(&bytes[..bytes.len() - 1]),
        Err(ExplorationError::Bytes(_))
    ));
    assert!(matches!(
        Exploration::from_bytes(b"nope"),
        Err(ExplorationError::Bytes(_))
    ));
    let mut longer = bytes.clone();
    longer.push(0);
    assert!(matches!(
        Exploration::from_bytes(&longer),
        Err(ExplorationError::Bytes(_))
    ));
    // Another problem's exploration does not fit.
    let other =
        Explorer::new(&[fig(Square, "##|##"), fig(Square, "####")], &small(1)).expect("solvable");
    assert!(matches!(
        other.explore(0, 2, false, 0, &[e], &AtomicBool::new(false)),
        Err(ExplorationError::Mismatch(_))
    ));
}

struct Short;

impl Executor for Short {
    fn run(&self, _batch: &Batch<'_>) -> Result<Vec<Exploration>, String> {
        Ok(Vec::new())
    }
}

struct Failing;

impl Executor for Failing {
    fn run(&self, _batch: &Batch<'_>) -> Result<Vec<Exploration>, String> {
        Err("the cluster went away".into())
    }
}

#[test]
fn a_misbehaving_executor_is_an_error() {
    let figures = [fig(Square, "###|###"), fig(Square, "######")];
    let stop = AtomicBool::new(false);
    let e = solve_with(&figures, &small(1), &stop, &(), Some(&Short)).unwrap_err();
    assert!(matches!(
        e,
        SolveError::Executor(ExplorationError::Count { got: 0, want: 8 })
    ));
    let e = solve_with(&figures, &small(1), &stop, &(), Some(&Failing)).unwrap_err();
    assert!(e.to_string().contains("the cluster went away"), "{e}");
}
