//! The one watcher of every long operation of the engine: it polls the
//! caller's stop flag, the deadline and the work's own progress, and says
//! why the work must end. The run, its polish, the bound and the assembly
//! count all end through it, so that each stops within one poll (a few
//! milliseconds) of a time limit or a stop.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::report::End;

/// How often the monitor looks.
pub(crate) const POLL: Duration = Duration::from_millis(5);

/// Why a monitored phase ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Watch<T> {
    /// `stop` was raised ([`End::Interrupted`]) or the deadline passed
    /// ([`End::TimeLimit`]).
    Stopped(End),
    /// The work's own step said so.
    Ended(T),
}

/// Calls `step` every [`POLL`] until it returns `Some`, `stop` is raised
/// or `deadline` passes (checked first, so that a stop wins over a step
/// that would go on).
pub(crate) fn monitor<T>(
    stop: &AtomicBool,
    deadline: Option<Instant>,
    mut step: impl FnMut() -> Option<T>,
) -> Watch<T> {
    loop {
        if let Some(end) = stopped(stop, deadline) {
            return Watch::Stopped(end);
        }
        if let Some(t) = step() {
            return Watch::Ended(t);
        }
        let mut wait = POLL;
        if let Some(d) = deadline {
            wait = wait.min(d.saturating_duration_since(Instant::now()));
        }
        std::thread::sleep(wait);
    }
}

/// Whether an operation must end now: `stop` raised, or `deadline` past.
pub(crate) fn stopped(stop: &AtomicBool, deadline: Option<Instant>) -> Option<End> {
    if stop.load(Ordering::SeqCst) {
        return Some(End::Interrupted);
    }
    if deadline.is_some_and(|d| Instant::now() >= d) {
        return Some(End::TimeLimit);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_monitor_ends_on_stop_deadline_or_step() {
        let stop = AtomicBool::new(false);
        let mut n = 0;
        let w = monitor(&stop, None, || {
            n += 1;
            (n == 3).then_some(n)
        });
        assert_eq!(w, Watch::Ended(3));
        let t = Instant::now();
        let w: Watch<()> = monitor(&stop, Some(t + Duration::from_millis(20)), || None);
        assert_eq!(w, Watch::Stopped(End::TimeLimit));
        assert!(t.elapsed() < Duration::from_millis(500));
        stop.store(true, Ordering::SeqCst);
        let w: Watch<()> = monitor(&stop, None, || Some(()));
        assert_eq!(w, Watch::Stopped(End::Interrupted));
    }
}
