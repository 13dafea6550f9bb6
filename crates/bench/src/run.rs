//! One timed solver run: `dissect_core::solver::solve` in-process with a
//! stop flag raised by a timer thread at the time limit, the result checked
//! by the independent verifier.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Condvar, Mutex};
use std::time::{Duration, Instant};

use dissect_core::io::Dissection;
use dissect_core::solver::{solve, Event, Found, Observer, Options};
use dissect_core::verify::verify;
use dissect_core::Figure;

/// What one seed produced.
#[derive(Clone, Debug, PartialEq)]
pub struct SeedRun {
    /// The seed.
    pub seed: u64,
    /// The piece count of the dissection found (`None`: none found).
    pub pieces: Option<usize>,
    /// From the start of `solve` to the end of the first level that held a
    /// valid dissection.
    pub first_valid: Option<Duration>,
    /// From the start of `solve` to its return.
    pub total: Duration,
    /// CPU time of the process (every thread) during the run, where the
    /// platform tells it: on a shared machine it shows how much of the wall
    /// time the run really had.
    pub cpu: Option<Duration>,
    /// Area variance of the reported dissection.
    pub variance: Option<f64>,
    /// Whether the time limit stopped the search.
    pub stopped: bool,
    /// Explorations run.
    pub explorations: usize,
    /// The piece count of the last level searched and its best `E_M`.
    pub last_level: (usize, Option<u64>),
    /// `Err` when the solver's dissection failed verification (a bug) or
    /// the solver refused the figures: the message.
    pub error: Option<String>,
    /// The dissection (verified), to save.
    pub found: Option<Found>,
}

impl SeedRun {
    /// Whether the run failed verification or could not run.
    pub fn is_error(&self) -> bool {
        self.error.is_some()
    }
}

/// Records when the first level with a valid dissection finished.
struct FirstValid {
    start: Instant,
    at: Mutex<Option<Duration>>,
}

impl Observer for FirstValid {
    fn on_event(&self, event: &Event) {
        if let Event::LevelFinished { found: true, .. } = event {
            let mut at = self.at.lock().expect("observer lock");
            if at.is_none() {
                *at = Some(self.start.elapsed());
            }
        }
    }
}

/// Runs the solver once on `figures` with `options` (its `seed` is used),
/// stopping it after `time_limit`, and verifies what it returns.
pub fn run_seed(figures: &[Figure], options: &Options, time_limit: Option<Duration>) -> SeedRun {
    let stop = AtomicBool::new(false);
    let cpu_start = crate::cpu::process_cpu_time();
    let finished = (Mutex::new(false), Condvar::new());
    let start = Instant::now();
    let observer = FirstValid {
        start,
        at: Mutex::new(None),
    };
    let outcome = std::thread::scope(|scope| {
        if let Some(limit) = time_limit {
            let (finished, stop) = (&finished, &stop);
            scope.spawn(move || {
                let (lock, cv) = finished;
                let deadline = start + limit;
                let mut done = lock.lock().expect("timer lock");
                while !*done {
                    let now = Instant::now();
                    if now >= deadline {
                        stop.store(true, Ordering::SeqCst);
                        return;
                    }
                    done = cv.wait_timeout(done, deadline - now).expect("timer lock").0;
                }
            });
        }
        let outcome = solve(figures, options, &stop, &observer);
        let (lock, cv) = &finished;
        *lock.lock().expect("timer lock") = true;
        cv.notify_all();
        outcome
    });
    let total = start.elapsed();
    let cpu = crate::cpu::process_cpu_time()
        .zip(cpu_start)
        .map(|(end, start)| end.saturating_sub(start));
    let first_valid = *observer.at.lock().expect("observer lock");
    let mut run = SeedRun {
        seed: options.seed,
        pieces: None,
        first_valid: None,
        total,
        cpu,
        variance: None,
        stopped: false,
        explorations: 0,
        last_level: (0, None),
        error: None,
        found: None,
    };
    let outcome = match outcome {
        Ok(o) => o,
        Err(e) => {
            run.error = Some(format!("the solver refused the figures: {e}"));
            return run;
        }
    };
    run.stopped = outcome.stopped;
    run.explorations = outcome.explorations;
    run.last_level = (outcome.last_pieces, outcome.best_mismatch);
    if let Some(found) = outcome.found {
        let d = Dissection {
            lattice: figures[0].lattice(),
            mirror: options.mirror,
            names: Vec::new(),
            pieces: found.pieces.clone(),
        };
        match verify(&d, figures) {
            Ok(n) => {
                run.pieces = Some(n);
                run.variance = Some(found.variance);
                // A level that found a dissection but was stopped before
                // the observer saw it cannot happen; fall back to the total.
                run.first_valid = Some(first_valid.unwrap_or(total));
                run.found = Some(found);
            }
            Err(violations) => {
                let list: Vec<String> = violations.iter().map(|v| v.to_string()).collect();
                run.error = Some(format!(
                    "BUG: the solver's {}-piece dissection failed verification: {}",
                    found.piece_count(),
                    list.join("; ")
                ));
            }
        }
    }
    run
}
