//! `run_with`: a run whose explorations go through a foreign executor (as
//! `dissect.ray` sends them to Ray workers) gives the same answer as `run`.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use dissect_core::io::parse_figure;
use dissect_core::solver::{Batch, Executor, Exploration, Explorer};
use dissect_core::{Figure, LatticeKind};
use dissect_engine::{explorer, run, run_with, RunConfig, RunOptions};

/// Runs every exploration on an `Explorer` of its own, through bytes.
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
                self.explorer
                    .explore(
                        batch.round,
                        batch.level,
                        batch.descent,
                        i,
                        &parents,
                        &AtomicBool::new(false),
                    )
                    .map(|e| Exploration::from_bytes(&e.to_bytes()).expect("round trip"))
                    .map_err(|e| e.to_string())
            })
            .collect()
    }
}

fn fig(text: &str) -> Figure {
    parse_figure(text, LatticeKind::Square).expect("a figure")
}

#[test]
fn a_foreign_executor_gives_the_same_answer_as_run() {
    let figures = [
        fig("###.####\n###.####\n###.####\n....####\n"),
        fig("#####\n#####\n#####\n#####\n#####\n"),
    ];
    let names = ["a".to_string(), "b".to_string()];
    for config in [
        RunConfig {
            explorations: 40,
            ..RunConfig::default()
        },
        RunConfig {
            explorations: 40,
            seed: 2,
            prove: false,
            ..RunConfig::default()
        },
    ] {
        let options = RunOptions::new(config).expect("valid options");
        let stop = AtomicBool::new(false);
        let local = run(&figures, &names, &options, &stop, &()).expect("a run");
        let remote = Remote {
            explorer: explorer(&figures, &options).expect("solvable"),
            batches: AtomicUsize::new(0),
        };
        let spread =
            run_with(&figures, &names, &options, &stop, &(), Some(&remote)).expect("a run");
        assert!(remote.batches.load(Ordering::Relaxed) > 0);
        let (l, s) = (local.best.expect("found"), spread.best.expect("found"));
        assert_eq!(s.pieces(), l.pieces());
        let steps = |r: &[dissect_engine::Improvement]| -> Vec<usize> {
            r.iter().map(|i| i.pieces).collect()
        };
        assert_eq!(steps(&spread.history), steps(&local.history));
    }
}
