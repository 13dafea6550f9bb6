//! One timed run through the engine (`dissect_engine::run`: its time limit,
//! its searches, its verified answer), with process CPU time beside wall
//! time.

use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::solver::{Found, Options};
use dissect_core::Figure;
use dissect_engine::{EngineObserver, RunConfig, RunOptions, Strategy, TimeLimit};

use crate::schedule::{Recorder, Recording};

/// What one seed produced.
#[derive(Clone, Debug, PartialEq)]
pub struct SeedRun {
    /// The seed.
    pub seed: u64,
    /// The piece count of the dissection found (`None`: none found).
    pub pieces: Option<usize>,
    /// From the start of the run to its first valid dissection.
    pub first_valid: Option<Duration>,
    /// From the start of the run to the first dissection with the final
    /// piece count.
    pub time_to_best: Option<Duration>,
    /// From the start of the run to its return.
    pub total: Duration,
    /// CPU time of the process (every thread) during the run, where the
    /// platform tells it: on a shared machine it shows how much of the wall
    /// time the run really had.
    pub cpu: Option<Duration>,
    /// Area variance of the reported dissection.
    pub variance: Option<f64>,
    /// Whether the time limit stopped the search.
    pub stopped: bool,
    /// The best lower bound proved.
    pub lower_bound: Option<usize>,
    /// Whether the dissection meets the lower bound.
    pub optimal: bool,
    /// Explorations run.
    pub explorations: usize,
    /// The piece count of the last level searched and its best `E_M`.
    pub last_level: (usize, Option<u64>),
    /// `Err` when the run failed (a dissection the verifier rejects: a bug;
    /// or figures the solver refuses): the message.
    pub error: Option<String>,
    /// The dissection (verified), to save.
    pub found: Option<Found>,
    /// The peak resident set size of the process during the run, in bytes
    /// (see [`crate::cpu::peak_rss`]; the whole process's, so it includes
    /// what the harness itself holds), where the platform tells it.
    pub peak_rss: Option<u64>,
    /// Every exploration's time, level by level, when the mode records
    /// them.
    pub recording: Option<Recording>,
}

impl SeedRun {
    /// Whether the run failed verification or could not run.
    pub fn is_error(&self) -> bool {
        self.error.is_some()
    }
}

/// How a run searches: the engine's strategy and whether the exact search
/// runs beside the heuristic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mode {
    /// The strategy.
    pub strategy: Strategy,
    /// Whether the exact lower-bound search runs beside.
    pub prove: bool,
    /// Whether every exploration's time is recorded (see
    /// [`crate::schedule::Recorder`]: exact on one solver thread).
    pub record: bool,
}

impl Default for Mode {
    /// `dissect solve` with no flag: anytime, proving.
    fn default() -> Mode {
        Mode {
            strategy: Strategy::Anytime,
            prove: true,
            record: false,
        }
    }
}

/// Runs the engine once on `figures` with `options` (its `seed` is used)
/// in the default mode, stopping at `time_limit`.
pub fn run_seed(figures: &[Figure], options: &Options, time_limit: Option<Duration>) -> SeedRun {
    run_mode(figures, options, Mode::default(), time_limit)
}

/// Runs the engine once in `mode`.
pub fn run_mode(
    figures: &[Figure],
    options: &Options,
    mode: Mode,
    time_limit: Option<Duration>,
) -> SeedRun {
    let mut run = SeedRun {
        seed: options.seed,
        pieces: None,
        first_valid: None,
        time_to_best: None,
        total: Duration::ZERO,
        cpu: None,
        variance: None,
        stopped: false,
        lower_bound: None,
        optimal: false,
        explorations: 0,
        last_level: (0, None),
        error: None,
        found: None,
        peak_rss: None,
        recording: None,
    };
    let config = RunConfig {
        strategy: mode.strategy,
        prove: mode.prove,
        mirror: options.mirror,
        seed: options.seed,
        threads: options.threads,
        time_limit: time_limit.map_or(TimeLimit::NONE, TimeLimit::from_duration),
        max_pieces: options.max_pieces,
        area_weight: options.area_weight,
        explorations: options.explorations,
        keep: options.keep,
        iterations: options.iterations,
        split_penalty: options.split_penalty,
        split_tries: options.split_tries,
        full_level: options.full_levels,
        extra_rounds: options.extra_rounds,
        patience: options.patience,
        ..RunConfig::default()
    };
    let run_options = match RunOptions::new(config) {
        Ok(o) => o,
        Err(e) => {
            run.error = Some(format!("bad settings: {e}"));
            return run;
        }
    };
    let rss_reset = crate::cpu::reset_peak_rss();
    let cpu_start = crate::cpu::process_cpu_time();
    let start = Instant::now();
    let recorder = mode.record.then(Recorder::new);
    let observer: &dyn EngineObserver = match &recorder {
        Some(r) => r,
        None => &(),
    };
    let report = dissect_engine::run(
        figures,
        &[],
        &run_options,
        &AtomicBool::new(false),
        observer,
    );
    run.total = start.elapsed();
    run.peak_rss = crate::cpu::peak_rss().filter(|_| rss_reset);
    run.recording = recorder.map(Recorder::finish);
    run.cpu = crate::cpu::process_cpu_time()
        .zip(cpu_start)
        .map(|(end, start)| end.saturating_sub(start));
    let report = match report {
        Ok(r) => r,
        Err(e) => {
            run.error = Some(format!("the engine refused the run: {e}"));
            return run;
        }
    };
    run.stopped = report.end.stopped();
    run.explorations = report.explorations;
    run.last_level = (report.last_pieces, report.best_mismatch);
    run.lower_bound = Some(report.lower_bound.value);
    run.optimal = report.optimal;
    run.first_valid = report.time_to_first.map(Duration::from_secs_f64);
    run.time_to_best = report.time_to_best.map(Duration::from_secs_f64);
    if let Some(best) = &report.best {
        run.pieces = Some(best.piece_count());
        run.variance = Some(best.variance());
        run.found = Some(Found {
            pieces: best.pieces().to_vec(),
            level: report.level.unwrap_or(best.piece_count().saturating_sub(1)),
            variance: best.variance(),
        });
        // A dissection found but no history (cannot happen): the total.
        run.first_valid = run.first_valid.or(Some(run.total));
    }
    run
}
