//! Running a search without the GIL while the calling thread watches for
//! Ctrl-C.
//!
//! The search runs on a scoped worker thread. The calling thread waits for
//! it with the GIL released, waking every 50 ms to run Python's signal
//! handlers (`check_signals`): a `KeyboardInterrupt` (or any other exception
//! a handler raises) raises the search's stop flag, and the search ends soon
//! after with the best it found. The exception is handed back so that the
//! caller decides whether to re-raise it (nothing found) or to return the
//! best result.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Condvar, Mutex};
use std::time::{Duration, Instant};

use dissect_engine::TimeLimit;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// What a watched run produced.
pub(crate) struct Watched<T> {
    /// The work's result.
    pub(crate) value: T,
    /// The exception a signal handler raised (Ctrl-C), if any.
    pub(crate) interrupted: Option<PyErr>,
}

/// How often the watcher runs the signal handlers.
const POLL: Duration = Duration::from_millis(50);

/// Runs `work` on a worker thread without the GIL; raises `stop` on Ctrl-C
/// or when `deadline` passes.
pub(crate) fn watched<T: Send>(
    py: Python<'_>,
    stop: &AtomicBool,
    deadline: Option<Instant>,
    work: impl FnOnce() -> T + Send,
) -> PyResult<Watched<T>> {
    watched_polling(py, stop, deadline, &mut |_| Ok(()), work)
}

/// [`watched`], calling `poll` with the GIL on the calling thread at every
/// wake (every 50 ms) and once more after the work ended: how events the
/// work queued reach Python callbacks (`progress=`). An exception `poll`
/// raises stops the work and is handed back like Ctrl-C's.
pub(crate) fn watched_polling<T: Send>(
    py: Python<'_>,
    stop: &AtomicBool,
    deadline: Option<Instant>,
    poll: &mut dyn FnMut(Python<'_>) -> PyResult<()>,
    work: impl FnOnce() -> T + Send,
) -> PyResult<Watched<T>> {
    let done = (Mutex::new(false), Condvar::new());
    let mut interrupted = None;
    let mut poll_now = |interrupted: &mut Option<PyErr>| {
        if interrupted.is_none() {
            if let Err(e) = poll(py) {
                stop.store(true, Ordering::SeqCst);
                *interrupted = Some(e);
            }
        }
    };
    let value = std::thread::scope(|s| {
        let worker = s.spawn(|| {
            let value = work();
            let (lock, cv) = &done;
            *lock.lock().unwrap_or_else(|e| e.into_inner()) = true;
            cv.notify_all();
            value
        });
        loop {
            let finished = py.detach(|| {
                let (lock, cv) = &done;
                let guard = lock.lock().unwrap_or_else(|e| e.into_inner());
                let mut wait = POLL;
                if let Some(d) = deadline {
                    wait = wait.min(d.saturating_duration_since(Instant::now()));
                }
                let (guard, _) = cv
                    .wait_timeout_while(guard, wait, |finished| !*finished)
                    .unwrap_or_else(|e| e.into_inner());
                *guard
            });
            poll_now(&mut interrupted);
            if finished {
                break;
            }
            if deadline.is_some_and(|d| Instant::now() >= d) {
                stop.store(true, Ordering::SeqCst);
            }
            if interrupted.is_none() {
                if let Err(e) = py.check_signals() {
                    stop.store(true, Ordering::SeqCst);
                    interrupted = Some(e);
                }
            }
        }
        worker.join()
    });
    let value = value.map_err(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        PyRuntimeError::new_err(format!("internal error: the search panicked: {what}"))
    })?;
    Ok(Watched { value, interrupted })
}

/// `time_limit=` by the engine's [`TimeLimit`] rule; the error in Python's
/// words (`time_limit must be ...`).
pub(crate) fn time_limit(seconds: Option<f64>) -> Result<TimeLimit, String> {
    TimeLimit::from_option(seconds).map_err(|e| e.to_string().replace("--time-limit", "time_limit"))
}

/// `threads=` by the engine's rule ([`dissect_engine::check_threads`]).
pub(crate) fn threads(threads: usize) -> Result<usize, String> {
    dissect_engine::check_threads(threads).map_err(|_| {
        format!(
            "threads={threads} is too many (at most {}; 0 means one per core)",
            dissect_engine::MAX_THREADS
        )
    })
}
