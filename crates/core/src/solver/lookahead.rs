//! Ordered look-ahead: work items (a level's explorations) run on a pool's
//! threads, each thread starting the next index the moment it is free, at
//! most `window` indices beyond the first one the caller has not taken;
//! the caller takes the results strictly in index order.
//!
//! There is no barrier: a thread never waits for other threads' items,
//! only for the window (the caller deciding the items before it). What
//! the caller decides from the results in index order cannot depend on
//! the number of threads; items run past the point where the caller stops
//! are dropped (at most one per thread still running, plus what the
//! window held).

use std::collections::BTreeMap;
use std::sync::{Condvar, Mutex, MutexGuard};

/// The shared state of one [`ordered`] run.
struct State<T> {
    /// The next index a thread starts.
    next: usize,
    /// Results not yet taken, by index.
    done: BTreeMap<usize, T>,
    /// The first index the caller has not taken.
    taken: usize,
    /// Indices up to here (exclusive) may run.
    end: usize,
    /// The caller is done: threads start nothing more.
    cancel: bool,
    /// What a work item panicked with: nothing more starts, the caller
    /// stops waiting, and [`ordered`] passes the panic on.
    panic: Option<Box<dyn std::any::Any + Send>>,
}

/// The caller's side of [`ordered`]: takes results in index order.
pub(crate) struct Taker<'s, T> {
    state: &'s Mutex<State<T>>,
    /// Signalled when an index may start (the window moved, the end grew,
    /// the run was cancelled).
    work: &'s Condvar,
    /// Signalled when a result is done.
    ready: &'s Condvar,
}

impl<T> Taker<'_, T> {
    fn lock(&self) -> MutexGuard<'_, State<T>> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The next `n` results in index order, waiting for each; fewer only
    /// past the end (or after a work item panicked).
    pub(crate) fn take(&mut self, n: usize) -> Vec<T> {
        let mut out = Vec::with_capacity(n);
        let mut state = self.lock();
        while out.len() < n && state.taken < state.end && state.panic.is_none() {
            let i = state.taken;
            match state.done.remove(&i) {
                Some(r) => {
                    out.push(r);
                    state.taken += 1;
                    self.work.notify_all();
                }
                None => {
                    state = self.ready.wait(state).unwrap_or_else(|e| e.into_inner());
                }
            }
        }
        out
    }

    /// Lets indices up to `end` (exclusive) run too.
    pub(crate) fn extend_to(&mut self, end: usize) {
        let mut state = self.lock();
        if end > state.end {
            state.end = end;
            self.work.notify_all();
        }
    }
}

/// Runs `work(i)` for the indices from `first` on (below the end, at
/// first `end`, see [`Taker::extend_to`]) on the threads of `pool`, at most
/// `window` (≥ 1) indices beyond the first one not yet taken, while `take`
/// takes the results on the calling thread; when `take` returns, nothing
/// more starts, the items still running are awaited and dropped, and its
/// value is returned.
///
/// The calling thread must not be one of `pool`'s threads.
pub(crate) fn ordered<T, W, C, R>(
    pool: &rayon::ThreadPool,
    first: usize,
    end: usize,
    window: usize,
    work: W,
    take: C,
) -> R
where
    T: Send,
    W: Fn(usize) -> T + Sync,
    C: FnOnce(&mut Taker<'_, T>) -> R,
{
    let window = window.max(1);
    let state = Mutex::new(State {
        next: first,
        done: BTreeMap::new(),
        taken: first,
        end,
        cancel: false,
        panic: None,
    });
    let (work_cv, ready) = (Condvar::new(), Condvar::new());
    let lock = || state.lock().unwrap_or_else(|e| e.into_inner());
    let worker = || loop {
        let i = {
            let mut s = lock();
            loop {
                if s.cancel {
                    return;
                }
                if s.next < s.end && s.next < s.taken + window {
                    s.next += 1;
                    break s.next - 1;
                }
                s = work_cv.wait(s).unwrap_or_else(|e| e.into_inner());
            }
        };
        // A panic ends the run instead of leaving the caller waiting for
        // this index forever.
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(i)));
        let mut s = lock();
        match r {
            Ok(r) if !s.cancel => {
                s.done.insert(i, r);
            }
            Ok(_) => {}
            Err(payload) => {
                s.cancel = true;
                s.panic.get_or_insert(payload);
                work_cv.notify_all();
            }
        }
        ready.notify_all();
    };
    let result = pool.in_place_scope(|scope| {
        for _ in 0..pool.current_num_threads() {
            scope.spawn(|_| worker());
        }
        let mut taker = Taker {
            state: &state,
            work: &work_cv,
            ready: &ready,
        };
        // Cancel on the way out, also when `take` panics (the scope then
        // waits for the threads before it passes the panic on).
        struct Cancel<'a, T>(&'a Mutex<State<T>>, &'a Condvar);
        impl<T> Drop for Cancel<'_, T> {
            fn drop(&mut self) {
                self.0.lock().unwrap_or_else(|e| e.into_inner()).cancel = true;
                self.1.notify_all();
            }
        }
        let _cancel = Cancel(&state, &work_cv);
        take(&mut taker)
    });
    if let Some(payload) = state.into_inner().unwrap_or_else(|e| e.into_inner()).panic {
        std::panic::resume_unwind(payload);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
    }

    #[test]
    fn results_come_in_index_order_whatever_the_threads() {
        for threads in [1, 2, 5] {
            let p = pool(threads);
            // Later indices finish first: the order is still the index's.
            let got = ordered(
                &p,
                3,
                40,
                8,
                |i| {
                    std::thread::sleep(std::time::Duration::from_micros((50 - i as u64) * 20));
                    i * i
                },
                |t| {
                    let mut v = t.take(10);
                    v.extend(t.take(27));
                    v
                },
            );
            assert_eq!(
                got,
                (3..40).map(|i| i * i).collect::<Vec<_>>(),
                "{threads} threads"
            );
        }
    }

    #[test]
    fn nothing_runs_past_the_window_or_the_end_and_the_end_can_grow() {
        let p = pool(4);
        let highest = AtomicUsize::new(0);
        let got = ordered(
            &p,
            0,
            5,
            3,
            |i| {
                highest.fetch_max(i, Ordering::SeqCst);
                i
            },
            |t| {
                let a = t.take(2);
                // Taken 2: indices 2, 3, 4 may have run, no more.
                std::thread::sleep(std::time::Duration::from_millis(20));
                assert!(highest.load(Ordering::SeqCst) <= 4);
                let b = t.take(10); // stops at the end, 5
                t.extend_to(7);
                let c = t.take(10);
                (a, b, c)
            },
        );
        assert_eq!(got, (vec![0, 1], vec![2, 3, 4], vec![5, 6]));
        assert!(highest.load(Ordering::SeqCst) <= 6);
    }

    #[test]
    fn a_panicking_item_ends_the_run_with_its_panic_not_a_hang() {
        let p = pool(2);
        let got = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            ordered(
                &p,
                0,
                100,
                8,
                |i| {
                    assert!(i != 5, "item 5 fails");
                    i
                },
                |t| {
                    let mut all = Vec::new();
                    for _ in 0..10 {
                        all.extend(t.take(10));
                    }
                    all
                },
            )
        }));
        let payload = got.expect_err("the panic is passed on");
        let message = payload
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| payload.downcast_ref::<&str>().map(|m| m.to_string()))
            .unwrap_or_default();
        assert!(message.contains("item 5 fails"), "{message}");
    }

    #[test]
    fn stopping_early_drops_the_rest_and_returns() {
        let p = pool(2);
        let started = AtomicUsize::new(0);
        let got = ordered(
            &p,
            0,
            1_000_000,
            4,
            |i| {
                started.fetch_add(1, Ordering::SeqCst);
                i
            },
            |t| t.take(3),
        );
        assert_eq!(got, vec![0, 1, 2]);
        // The window bounds what ran: 3 taken + at most 4 ahead.
        assert!(started.load(Ordering::SeqCst) <= 7);
    }
}
