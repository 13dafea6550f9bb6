//! Solve jobs: each runs the core solver on a blocking thread with its own
//! stop flag; its progress is published as a [`Snapshot`] that the
//! server-sent event stream and the status route read.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use dissect_core::io::Dissection;
use dissect_core::solver::{solve, Event, Observer, Options, Outcome};
use dissect_core::{Figure, LatticeKind};
use serde::Serialize;
use serde_json::{json, Map, Value};
use tokio::sync::{watch, OwnedSemaphorePermit, Semaphore};

use crate::error::ApiError;

/// Finished jobs kept for their results; older ones are forgotten.
const KEEP_FINISHED: usize = 32;

/// Where a job is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum State {
    /// The solver is working.
    Running,
    /// The solver returned (with or without a dissection).
    Done,
    /// The solver failed (its error is in [`Snapshot::error`]).
    Failed,
}

/// What a client sees of a job at one moment.
#[derive(Clone, Debug, Serialize)]
pub struct Snapshot {
    /// The job's id.
    pub id: u64,
    /// Running, done or failed.
    pub state: State,
    /// The level being explored (k pieces = level + 1).
    pub level: usize,
    /// Pieces at this level.
    pub pieces: usize,
    /// Explorations done at this level.
    pub done: usize,
    /// Explorations planned at this level.
    pub total: usize,
    /// Explorations done over all levels.
    pub explorations: usize,
    /// The best objective value seen at this level.
    pub best_score: Option<f64>,
    /// The best matching score E_M seen at this level (0 = a dissection).
    pub best_mismatch: Option<u64>,
    /// Seconds since the start (at the time of the snapshot).
    pub elapsed: f64,
    /// Whether Stop was asked (by a client or the time limit).
    pub stop_requested: bool,
    /// The result once done: see [`result_json`].
    pub result: Option<Value>,
    /// The error once failed.
    pub error: Option<String>,
}

/// One solve.
pub struct Job {
    id: u64,
    stop: AtomicBool,
    started: Instant,
    tx: watch::Sender<Snapshot>,
}

impl Job {
    /// The id.
    pub fn id(&self) -> u64 {
        self.id
    }

    /// Asks the solver to stop; it returns the best dissection found so far.
    pub fn stop(&self) {
        self.stop.store(true, Ordering::SeqCst);
        self.tx.send_modify(|s| s.stop_requested = true);
    }

    /// The current snapshot, with `elapsed` brought up to date while running.
    pub fn snapshot(&self) -> Snapshot {
        let mut s = self.tx.borrow().clone();
        if s.state == State::Running {
            s.elapsed = self.started.elapsed().as_secs_f64();
        }
        s
    }

    /// A receiver of changes.
    pub fn subscribe(&self) -> watch::Receiver<Snapshot> {
        self.tx.subscribe()
    }

    fn finished(&self) -> bool {
        self.tx.borrow().state != State::Running
    }
}

impl Observer for Job {
    fn on_event(&self, event: &Event) {
        let finite = |v: f64| v.is_finite().then_some(v);
        self.tx.send_modify(|s| {
            match event {
                Event::LevelStarted {
                    level,
                    pieces,
                    explorations,
                } => {
                    s.level = *level;
                    s.pieces = *pieces;
                    s.done = 0;
                    s.total = *explorations;
                    s.best_score = None;
                }
                Event::Exploration {
                    level,
                    done,
                    total,
                    best_score,
                    best_mismatch,
                } => {
                    s.level = *level;
                    s.done = s.done.max(*done);
                    s.total = *total;
                    s.explorations += 1;
                    s.best_score = finite(*best_score);
                    s.best_mismatch = Some(*best_mismatch);
                }
                Event::LevelFinished {
                    level,
                    pieces,
                    best_mismatch,
                    ..
                } => {
                    s.level = *level;
                    s.pieces = *pieces;
                    s.best_mismatch = Some(*best_mismatch);
                }
                _ => {}
            }
            s.elapsed = self.started.elapsed().as_secs_f64();
        });
    }
}

/// What a solve needs.
pub struct Request {
    /// The lattice.
    pub lattice: LatticeKind,
    /// The figures (equal areas, checked by the caller).
    pub figures: Vec<Figure>,
    /// Their names.
    pub names: Vec<String>,
    /// Solver options (mirror, seed, area weight, threads, ...).
    pub options: Options,
    /// Seconds until the solve is stopped.
    pub time_limit: f64,
}

/// All jobs of a server.
pub struct Jobs {
    jobs: Mutex<HashMap<u64, Arc<Job>>>,
    next: AtomicU64,
    slots: Arc<Semaphore>,
    max: usize,
}

impl Jobs {
    /// A registry running at most `max_concurrent` solves at once.
    pub fn new(max_concurrent: usize) -> Jobs {
        Jobs {
            jobs: Mutex::new(HashMap::new()),
            next: AtomicU64::new(1),
            slots: Arc::new(Semaphore::new(max_concurrent.max(1))),
            max: max_concurrent.max(1),
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<u64, Arc<Job>>> {
        // A panic elsewhere cannot leave the map inconsistent: use it anyway.
        self.jobs.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The job with this id.
    pub fn get(&self, id: u64) -> Option<Arc<Job>> {
        self.lock().get(&id).cloned()
    }

    /// Stops every running job (at shutdown).
    pub fn stop_all(&self) {
        for job in self.lock().values() {
            job.stop();
        }
    }

    /// Starts a solve; fails with [`ApiError::Busy`] when all slots are taken.
    /// Must be called inside a tokio runtime.
    pub fn start(&self, request: Request) -> Result<Arc<Job>, ApiError> {
        let permit = Arc::clone(&self.slots)
            .try_acquire_owned()
            .map_err(|_| ApiError::Busy(self.max))?;
        let id = self.next.fetch_add(1, Ordering::Relaxed);
        let (tx, _) = watch::channel(Snapshot {
            id,
            state: State::Running,
            level: 0,
            pieces: 1,
            done: 0,
            total: 0,
            explorations: 0,
            best_score: None,
            best_mismatch: None,
            elapsed: 0.0,
            stop_requested: false,
            result: None,
            error: None,
        });
        let job = Arc::new(Job {
            id,
            stop: AtomicBool::new(false),
            started: Instant::now(),
            tx,
        });
        {
            let mut jobs = self.lock();
            if jobs.len() >= KEEP_FINISHED {
                let mut old: Vec<u64> = jobs
                    .iter()
                    .filter(|(_, j)| j.finished())
                    .map(|(k, _)| *k)
                    .collect();
                old.sort_unstable();
                let excess = jobs.len() + 1 - KEEP_FINISHED;
                for k in old.into_iter().take(excess) {
                    jobs.remove(&k);
                }
            }
            jobs.insert(id, Arc::clone(&job));
        }
        spawn(Arc::clone(&job), request, permit);
        Ok(job)
    }
}

fn spawn(job: Arc<Job>, request: Request, permit: OwnedSemaphorePermit) {
    // The time limit: a task that raises the stop flag unless the job ends first.
    let limit = Duration::from_secs_f64(request.time_limit);
    let timer_job = Arc::clone(&job);
    let mut rx = job.subscribe();
    tokio::spawn(async move {
        tokio::select! {
            _ = tokio::time::sleep(limit) => timer_job.stop(),
            _ = rx.wait_for(|s| s.state != State::Running) => {}
        }
    });
    let worker = Arc::clone(&job);
    let handle = tokio::task::spawn_blocking(move || {
        let outcome = solve(&request.figures, &request.options, &worker.stop, &*worker);
        let elapsed = worker.started.elapsed().as_secs_f64();
        (outcome, request, elapsed)
    });
    tokio::spawn(async move {
        let (state, result, error) = match handle.await {
            Ok((Ok(outcome), request, elapsed)) => match result_json(&request, &outcome, elapsed) {
                Ok(v) => (State::Done, Some(v), None),
                Err(e) => (State::Failed, None, Some(e)),
            },
            Ok((Err(e), _, _)) => (State::Failed, None, Some(e.to_string())),
            Err(e) => (
                State::Failed,
                None,
                Some(format!("the solver crashed: {e}")),
            ),
        };
        drop(permit);
        let elapsed = job.started.elapsed().as_secs_f64();
        job.tx.send_modify(|s| {
            s.state = state;
            s.result = result;
            s.error = error;
            s.elapsed = elapsed;
        });
    });
}

/// The result of a finished solve:
///
/// ```json
/// {"found": true, "stopped": false, "pieces": 4, "areas": [..], "area_variance": 1.5,
///  "level": 3, "explorations": 812, "best_mismatch": 0, "seconds": 0.4,
///  "solution": { dissection-solution/1 ... }}
/// ```
///
/// `solution` is present only when a dissection was found; it has been
/// checked by the core verifier.
pub fn result_json(request: &Request, outcome: &Outcome, elapsed: f64) -> Result<Value, String> {
    let seconds = (elapsed * 1000.0).round() / 1000.0;
    let Some(found) = &outcome.found else {
        return Ok(json!({
            "found": false,
            "stopped": outcome.stopped,
            "last_pieces": outcome.last_pieces,
            "best_mismatch": outcome.best_mismatch,
            "explorations": outcome.explorations,
            "seconds": seconds,
        }));
    };
    let dissection = Dissection {
        lattice: request.lattice,
        mirror: request.options.mirror && request.lattice.lattice().supports_mirror(),
        names: request.names.clone(),
        pieces: found.pieces.clone(),
    };
    if let Err(v) = dissect_core::verify::verify(&dissection, &request.figures) {
        return Err(format!(
            "the solver's dissection failed verification: {}",
            v[0]
        ));
    }
    let mut extra = Map::new();
    extra.insert("pieces".into(), json!(found.piece_count()));
    extra.insert("areas".into(), json!(found.areas()));
    extra.insert("area_variance".into(), json!(found.variance));
    extra.insert("seed".into(), json!(request.options.seed));
    extra.insert("seconds".into(), json!(seconds));
    extra.insert("level".into(), json!(found.level));
    extra.insert("explorations".into(), json!(outcome.explorations));
    extra.insert("stopped_early".into(), Value::Bool(outcome.stopped));
    let file = dissection.to_file(extra);
    Ok(json!({
        "found": true,
        "stopped": outcome.stopped,
        "pieces": found.piece_count(),
        "areas": found.areas(),
        "area_variance": found.variance,
        "level": found.level,
        "explorations": outcome.explorations,
        "best_mismatch": 0,
        "seconds": seconds,
        "solution_text": file.to_json(),
        "solution": serde_json::to_value(&file).map_err(|e| e.to_string())?,
    }))
}
