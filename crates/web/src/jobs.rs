//! Solve jobs: each runs the engine (`dissect_engine::run`: the anytime
//! search and the exact search side by side, its own time limit) on a
//! blocking thread with its own stop flag; its progress is published as a
//! [`Snapshot`] that the server-sent event stream and the status route read.
//! Once the run returns, the assemblies of each solution are counted in
//! every figure ([`crate::puzzle::count_assemblies`]: `counting` in the
//! snapshot) before the result is published.
//!
//! A job may instead enumerate every minimum dissection ("all solutions",
//! [`crate::enumerate`]): [`Request::enumerate`] set, its count so far in
//! [`Snapshot::enumeration`], its result [`crate::enumerate::result_json`].

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use dissect_core::solver::Event;
use dissect_core::{Figure, LatticeKind};
use dissect_engine::ExactEvent;
use dissect_engine::{
    EngineEvent, EngineObserver, EnumerateConfig, EnumerateEvent, EnumerateObserver, Report,
    RunOptions,
};
use serde::Serialize;
use serde_json::{json, Value};
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
    /// Whether Stop was asked by a client.
    pub stop_requested: bool,
    /// Whether the run has ended and the assemblies of its solutions are
    /// being counted (Stop cuts the counts short).
    pub counting: bool,
    /// The fewest pieces found so far.
    pub best_pieces: Option<usize>,
    /// The best lower bound proved so far.
    pub lower_bound: Option<usize>,
    /// Whether the best so far meets the lower bound.
    pub optimal: bool,
    /// Every improvement so far: `{pieces, seconds, by}`.
    pub history: Vec<Value>,
    /// The result once done: see [`result_json`].
    pub result: Option<Value>,
    /// The error once failed.
    pub error: Option<String>,
    /// An enumeration's count so far (`None` for a solve).
    pub enumeration: Option<crate::enumerate::Progress>,
}

/// One solve.
pub struct Job {
    id: u64,
    stop: AtomicBool,
    /// Stops the assembly counts (a Stop while counting, or the shutdown).
    halt: AtomicBool,
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
        self.tx.send_modify(|s| {
            s.stop_requested = true;
            if s.counting {
                self.halt.store(true, Ordering::SeqCst);
            }
        });
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

    /// Ends the job (a solve or an enumeration) with its outcome: the
    /// result or the error, the optimal mark and the time it took.
    fn finish(&self, state: State, result: Option<Value>, error: Option<String>) {
        let elapsed = self.started.elapsed().as_secs_f64();
        self.tx.send_modify(|s| {
            if let Some(r) = &result {
                s.optimal = r["optimal"] == Value::Bool(true);
            }
            s.state = state;
            s.counting = false;
            s.result = result;
            s.error = error;
            s.elapsed = elapsed;
        });
    }
}

impl EngineObserver for Job {
    fn on_event(&self, event: &EngineEvent<'_>) {
        let finite = |v: f64| v.is_finite().then_some(v);
        self.tx.send_modify(|s| {
            match event {
                EngineEvent::Search(Event::LevelStarted {
                    level,
                    pieces,
                    explorations,
                }) => {
                    s.level = *level;
                    s.pieces = *pieces;
                    s.done = 0;
                    s.total = *explorations;
                    s.best_score = None;
                }
                EngineEvent::Search(Event::Exploration {
                    level,
                    done,
                    total,
                    best_score,
                    best_mismatch,
                }) => {
                    s.level = *level;
                    s.done = s.done.max(*done);
                    s.total = *total;
                    s.explorations += 1;
                    s.best_score = finite(*best_score);
                    s.best_mismatch = Some(*best_mismatch);
                }
                EngineEvent::Search(Event::LevelFinished {
                    level,
                    pieces,
                    best_mismatch,
                    ..
                }) => {
                    s.level = *level;
                    s.pieces = *pieces;
                    s.best_mismatch = Some(*best_mismatch);
                }
                EngineEvent::Improved(i) => {
                    s.best_pieces = Some(i.pieces);
                    s.history.push(json!({
                        "pieces": i.pieces,
                        "seconds": (i.seconds * 1000.0).round() / 1000.0,
                        "by": i.source.name(),
                    }));
                }
                EngineEvent::LowerBound(b) => s.lower_bound = Some(b.value),
                _ => {}
            }
            s.optimal = matches!((s.best_pieces, s.lower_bound), (Some(p), Some(b)) if p <= b);
            s.elapsed = self.started.elapsed().as_secs_f64();
        });
    }
}

impl EnumerateObserver for Job {
    fn on_event(&self, event: &EnumerateEvent) {
        self.tx.send_modify(|s| {
            let e = s.enumeration.get_or_insert_with(Default::default);
            match event {
                EnumerateEvent::Search(ExactEvent::Refuted(b)) => {
                    s.lower_bound = Some(b.value);
                    e.pieces = b.value;
                    s.pieces = b.value;
                }
                EnumerateEvent::Minimum { pieces, seconds } => {
                    e.pieces = *pieces;
                    e.minimum = true;
                    s.pieces = *pieces;
                    s.best_pieces = Some(*pieces);
                    s.lower_bound = Some(*pieces);
                    s.optimal = true;
                    s.history.push(json!({
                        "pieces": pieces,
                        "seconds": (seconds * 1000.0).round() / 1000.0,
                        "by": "enumerate",
                    }));
                }
                EnumerateEvent::Encoded { pieces, .. } => {
                    e.pieces = *pieces;
                    s.pieces = *pieces;
                }
                EnumerateEvent::Found { count, classes, .. } => {
                    e.dissections = *count;
                    e.classes = *classes;
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
    /// The run's options (checked by the engine), time limit included.
    pub options: RunOptions,
    /// Enumerate every dissection with the fewest pieces instead of
    /// solving ("all solutions"); `options` is then not used.
    pub enumerate: Option<EnumerateConfig>,
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
            job.halt.store(true, Ordering::SeqCst);
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
            counting: false,
            best_pieces: None,
            lower_bound: None,
            optimal: false,
            history: Vec::new(),
            result: None,
            error: None,
            enumeration: request.enumerate.as_ref().map(|_| Default::default()),
        });
        let job = Arc::new(Job {
            id,
            stop: AtomicBool::new(false),
            halt: AtomicBool::new(false),
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
        if request.enumerate.is_some() {
            spawn_enumeration(Arc::clone(&job), request, permit);
        } else {
            spawn(Arc::clone(&job), request, permit);
        }
        Ok(job)
    }
}

fn spawn(job: Arc<Job>, request: Request, permit: OwnedSemaphorePermit) {
    // The time limit is the engine's (in the run options).
    let worker = Arc::clone(&job);
    let handle = tokio::task::spawn_blocking(move || {
        let report = dissect_engine::run(
            &request.figures,
            &request.names,
            &request.options,
            &worker.stop,
            &*worker,
        );
        let counts = match &report {
            Ok(r) => {
                worker.tx.send_modify(|s| s.counting = true);
                if worker.stop.load(Ordering::SeqCst) {
                    // Stopped just before the counts began: they stop too.
                    worker.halt.store(true, Ordering::SeqCst);
                }
                crate::puzzle::count_assemblies(r, &request.figures, &worker.halt)
            }
            Err(_) => Vec::new(),
        };
        (report.map(|r| (r, counts)), request)
    });
    tokio::spawn(async move {
        let (state, result, error) = match handle.await {
            Ok((Ok((report, counts)), request)) => match result_json(&request, &report, &counts) {
                Ok(v) => (State::Done, Some(v), None),
                Err(e) => (State::Failed, None, Some(e)),
            },
            Ok((Err(e), _)) => (State::Failed, None, Some(e.to_string())),
            Err(e) => (
                State::Failed,
                None,
                Some(format!("the solver crashed: {e}")),
            ),
        };
        drop(permit);
        job.finish(state, result, error);
    });
}

/// Runs an enumeration job ([`Request::enumerate`]): its result is
/// [`crate::enumerate::result_json`].
fn spawn_enumeration(job: Arc<Job>, request: Request, permit: OwnedSemaphorePermit) {
    let worker = Arc::clone(&job);
    let handle = tokio::task::spawn_blocking(move || {
        let config = request.enumerate.clone().unwrap_or_default();
        dissect_engine::enumerate(
            &request.figures,
            &request.names,
            &config,
            &worker.stop,
            &*worker,
        )
    });
    tokio::spawn(async move {
        let (state, result, error) = match handle.await {
            Ok(Ok(report)) => (
                State::Done,
                Some(crate::enumerate::result_json(&report)),
                None,
            ),
            Ok(Err(e)) => (State::Failed, None, Some(e.to_string())),
            Err(e) => (
                State::Failed,
                None,
                Some(format!("the enumeration crashed: {e}")),
            ),
        };
        drop(permit);
        job.finish(state, result, error);
    });
}

/// The result of a finished solve:
///
/// ```json
/// {"found": true, "stopped": false, "pieces": 4, "areas": [..], "area_variance": 1.5,
///  "level": 3, "explorations": 812, "best_mismatch": 0, "seconds": 0.4,
///  "lower_bound": 4, "lower_bound_reason": "...", "optimal": true,
///  "found_by": "search", "time_to_first": 0.01, "time_to_best": 0.3,
///  "history": [{"pieces": 5, "seconds": 0.01, "by": "greedy"}, ...],
///  "solution": { dissection-solution/1 ... }, "solution_text": "...",
///  "solutions": [{"position": 1, "scores": {..}, "rank": {..}, "assemblies": [..],
///                 "unique": true, "solution": {..}, "solution_text": "..."}, ...],
///  "ranking": {"by": "variance", "asked": 3, "found": 3, "constraints": {..}}}
/// ```
///
/// `solution` (the best, the first of `solutions`) is present only when a
/// dissection was found; the engine verified every one (it holds only
/// `Verified` dissections). `solutions` lists every solution of a run that
/// collected them ([`dissect_engine::Report::solutions`]: several asked
/// for, a ranking or constraints), else the one answer, each with its
/// assembly count per figure (`counts`, see [`crate::puzzle::solutions_json`]);
/// `ranking` is present for a run that collected them.
pub fn result_json(
    request: &Request,
    report: &Report,
    counts: &[Vec<dissect_engine::Count>],
) -> Result<Value, String> {
    let seconds = (report.seconds * 1000.0).round() / 1000.0;
    let stopped = report.end.stopped();
    let mut extra = report.extra();
    let ranking = crate::puzzle::ranking_json(report);
    if report.best.is_none() {
        let mut v = json!({
            "found": false,
            "stopped": stopped,
            "last_pieces": report.last_pieces,
            "best_mismatch": report.best_mismatch,
            "explorations": report.explorations,
            "lower_bound": report.lower_bound.value,
            "seconds": seconds,
        });
        if let Some(r) = ranking {
            v["ranking"] = r;
        }
        return Ok(v);
    }
    let _ = request;
    let solutions = crate::puzzle::solutions_json(report, counts)?;
    // The best is the first solution: its file (with its scores, rank and
    // constraints when the run collected solutions).
    let text = report
        .solution_json()
        .ok_or("a found dissection has no file")?;
    let file: Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
    extra.insert("found".into(), Value::Bool(true));
    extra.insert("stopped".into(), Value::Bool(stopped));
    extra.insert("best_mismatch".into(), json!(0));
    extra.insert("level".into(), json!(report.level));
    extra.insert("solution_text".into(), json!(text));
    extra.insert("solution".into(), file);
    extra.insert("solutions".into(), Value::Array(solutions));
    if let Some(r) = ranking {
        extra.insert("ranking".into(), r);
    }
    Ok(Value::Object(extra))
}
