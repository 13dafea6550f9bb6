//! Replays recorded exploration times on a simulated machine of `T`
//! threads, to tell what a thread count buys without having its cores: the
//! makespan of each level and the fraction of worker time spent waiting.
//! [`Recorder`] records the times from a run's events.
//!
//! Explorations start in index order on the first free thread (what a
//! work-stealing pool does with equal priorities). With batch barriers, a
//! batch starts when the whole batch before it has finished; without them a
//! thread takes the next exploration as soon as it is free; the solver's
//! schedule is the latter within a sliding window ([`window`],
//! [`replay_window`]).

use std::collections::HashMap;
use std::sync::Mutex;
use std::thread::ThreadId;
use std::time::Instant;

use dissect_core::solver::Event;
use dissect_engine::{EngineEvent, EngineObserver};

/// The simulated thread counts of a replay.
pub const REPLAY_THREADS: [usize; 5] = [1, 2, 4, 8, 16];

/// How many explorations the solver's pool runs ahead of the first one it
/// has not yet decided on `threads` threads: 4 per thread, at least one
/// batch, at most 8 batches (the constants of `dissect_core`'s level
/// search, repeated here). There is no barrier: a thread starts the next
/// exploration as soon as it is free, unless that one is this far ahead.
pub fn window(batch: usize, threads: usize) -> usize {
    let batch = batch.max(1);
    (4 * threads.max(1)).clamp(batch, 8 * batch)
}

/// One level's schedule on `threads` threads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Replay {
    /// Simulated threads.
    pub threads: usize,
    /// Seconds from the level's start to its last exploration's end.
    pub makespan: f64,
    /// Seconds of exploration work in all.
    pub work: f64,
}

impl Replay {
    /// The fraction of worker time spent waiting: `1 − work / (threads ·
    /// makespan)` (0 when nothing ran).
    pub fn waiting(&self) -> f64 {
        let capacity = self.threads as f64 * self.makespan;
        if capacity <= 0.0 {
            0.0
        } else {
            (1.0 - self.work / capacity).max(0.0)
        }
    }
}

/// The thread that is free first (the lowest index among equals) and
/// when; `free` is never empty.
fn earliest(free: &[f64]) -> (usize, f64) {
    free.iter()
        .copied()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))
        .unwrap_or((0, 0.0))
}

/// The greedy schedule of `durations` (in index order) on `threads`
/// threads, all free at time `start`; the time the last one ends.
fn list_schedule(durations: &[f64], threads: usize, start: f64) -> f64 {
    let mut free = vec![start; threads.max(1)];
    let mut end = start;
    for &d in durations {
        let (i, t) = earliest(&free);
        free[i] = t + d;
        end = end.max(free[i]);
    }
    end
}

/// The schedule of `durations` (in index order) on `threads` threads with
/// no barrier but a sliding window: exploration `i` starts on the first
/// free thread once every exploration up to `i − window` has ended (the
/// solver takes results in index order and runs at most `window` beyond
/// the first one it has not taken). The time the last one ends.
fn window_schedule(durations: &[f64], window: usize, threads: usize) -> f64 {
    let window = window.max(1);
    let mut free = vec![0.0f64; threads.max(1)];
    // prefix[i]: when explorations 0..=i have all ended.
    let mut prefix: Vec<f64> = Vec::with_capacity(durations.len());
    for (i, &d) in durations.iter().enumerate() {
        let gate = if i >= window { prefix[i - window] } else { 0.0 };
        let (k, t) = earliest(&free);
        let end = t.max(gate) + d;
        free[k] = end;
        prefix.push(prefix.last().copied().unwrap_or(0.0).max(end));
    }
    prefix.last().copied().unwrap_or(0.0)
}

/// A level run the solver's way: no barriers, at most `window`
/// explorations ahead of the first one not yet decided.
pub fn replay_window(durations: &[f64], window: usize, threads: usize) -> Replay {
    Replay {
        threads: threads.max(1),
        makespan: window_schedule(durations, window, threads),
        work: durations.iter().sum(),
    }
}

/// [`replay_window`] of several levels one after the other.
pub fn replay_levels_window(levels: &[Vec<f64>], window: usize, threads: usize) -> Replay {
    in_sequence(levels, threads, |l| replay_window(l, window, threads))
}

/// Levels one after the other, each replayed by `one`: the summed
/// makespans and work.
fn in_sequence(levels: &[Vec<f64>], threads: usize, one: impl Fn(&[f64]) -> Replay) -> Replay {
    levels.iter().fold(
        Replay {
            threads: threads.max(1),
            makespan: 0.0,
            work: 0.0,
        },
        |acc, l| {
            let r = one(l);
            Replay {
                threads: acc.threads,
                makespan: acc.makespan + r.makespan,
                work: acc.work + r.work,
            }
        },
    )
}

/// A level whose explorations took `durations` seconds, run in batches of
/// `batch` with a barrier after each (`batch` 0: no barriers).
pub fn replay(durations: &[f64], batch: usize, threads: usize) -> Replay {
    let work = durations.iter().sum();
    let makespan = if batch == 0 {
        list_schedule(durations, threads, 0.0)
    } else {
        durations
            .chunks(batch)
            .fold(0.0, |t, chunk| list_schedule(chunk, threads, t))
    };
    Replay {
        threads: threads.max(1),
        makespan,
        work,
    }
}

/// Several levels one after the other (a barrier between levels in every
/// schedule: a level needs the one below): the summed makespans and work.
pub fn replay_levels(levels: &[Vec<f64>], batch: usize, threads: usize) -> Replay {
    in_sequence(levels, threads, |l| replay(l, batch, threads))
}

/// What a recorded exploration time measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clock {
    /// CPU time of the thread that ran the exploration (from
    /// `/proc/thread-self/schedstat`): what it costs on a core of its own,
    /// however loaded the machine was.
    ThreadCpu,
    /// Wall time since the run's previous event (where the thread CPU time
    /// is unknown): exact only on one solver thread of an idle machine.
    Wall,
}

impl std::fmt::Display for Clock {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Clock::ThreadCpu => "thread CPU time",
            Clock::Wall => "wall time",
        })
    }
}

/// The explorations of one level, in the order they ended.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordedLevel {
    /// The level (pieces − 1).
    pub level: usize,
    /// Seconds of each exploration.
    pub seconds: Vec<f64>,
}

/// The exploration times of a run, level by level in the order the levels
/// ran (a level searched again in a later round appears again).
#[derive(Clone, Debug, PartialEq)]
pub struct Recording {
    /// What the seconds measure.
    pub clock: Clock,
    /// The levels.
    pub levels: Vec<RecordedLevel>,
}

impl Recording {
    /// Each level's exploration times, for [`replay_levels`].
    pub fn durations(&self) -> Vec<Vec<f64>> {
        self.levels.iter().map(|l| l.seconds.clone()).collect()
    }

    /// Explorations recorded.
    pub fn explorations(&self) -> usize {
        self.levels.iter().map(|l| l.seconds.len()).sum()
    }

    /// Seconds of exploration work in all.
    pub fn work(&self) -> f64 {
        self.levels.iter().flat_map(|l| &l.seconds).sum()
    }
}

/// An [`EngineObserver`] that records how long every exploration of a run
/// took, level by level.
///
/// An exploration's time is read when it ends (its `Exploration` event, sent
/// from the thread that ran it): the thread's CPU time since its previous
/// exploration ended (or since the thread started). On one solver thread the
/// explorations of a batch run back to back in index order, so these are
/// the explorations' own times, plus the little the thread spends between
/// batches; on several threads the first exploration of a batch on each
/// thread would also count the thread's idle spinning, so record on one.
pub struct Recorder {
    clock: Clock,
    state: Mutex<State>,
}

struct State {
    origin: Instant,
    /// Wall seconds (from `origin`) of the previous event.
    last_wall: f64,
    /// CPU seconds of each thread at its previous exploration's end.
    last_cpu: HashMap<ThreadId, f64>,
    current: Vec<f64>,
    current_level: usize,
    levels: Vec<RecordedLevel>,
}

impl Default for Recorder {
    fn default() -> Recorder {
        Recorder::new()
    }
}

impl Recorder {
    /// A recorder on thread CPU time where the platform tells it, else on
    /// wall time.
    pub fn new() -> Recorder {
        let clock = if crate::cpu::thread_cpu_time().is_some() {
            Clock::ThreadCpu
        } else {
            Clock::Wall
        };
        Recorder {
            clock,
            state: Mutex::new(State {
                origin: Instant::now(),
                last_wall: 0.0,
                last_cpu: HashMap::new(),
                current: Vec::new(),
                current_level: 0,
                levels: Vec::new(),
            }),
        }
    }

    /// What was recorded (a level the run left without its
    /// `LevelFinished` event is kept too).
    pub fn finish(self) -> Recording {
        let mut s = self.state.into_inner().unwrap_or_else(|e| e.into_inner());
        if !s.current.is_empty() {
            let level = s.current_level;
            let seconds = std::mem::take(&mut s.current);
            s.levels.push(RecordedLevel { level, seconds });
        }
        Recording {
            clock: self.clock,
            levels: s.levels,
        }
    }
}

impl EngineObserver for Recorder {
    fn on_event(&self, event: &EngineEvent<'_>) {
        // Read before the lock: the clock of this thread, not of a waiter.
        let cpu = match (self.clock, event) {
            (Clock::ThreadCpu, EngineEvent::Search(Event::Exploration { .. })) => {
                crate::cpu::thread_cpu_time().map(|d| d.as_secs_f64())
            }
            _ => None,
        };
        let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let wall = s.origin.elapsed().as_secs_f64();
        let since_last = wall - s.last_wall;
        s.last_wall = wall;
        match event {
            EngineEvent::Search(Event::Exploration { level, .. }) => {
                let seconds = match cpu {
                    Some(now) => {
                        let before = s
                            .last_cpu
                            .insert(std::thread::current().id(), now)
                            .unwrap_or(0.0);
                        (now - before).max(0.0)
                    }
                    None => since_last,
                };
                if *level != s.current_level && !s.current.is_empty() {
                    // A level whose end was not reported (cannot happen).
                    let (l, seconds) = (s.current_level, std::mem::take(&mut s.current));
                    s.levels.push(RecordedLevel { level: l, seconds });
                }
                s.current_level = *level;
                s.current.push(seconds);
            }
            EngineEvent::Search(Event::LevelFinished {
                level,
                explorations,
                ..
            }) if !s.current.is_empty() => {
                // The level's own explorations: on one thread the first
                // ones to end; those the pool ran past the deciding batch
                // (and dropped) are not the level's.
                let mut seconds = std::mem::take(&mut s.current);
                seconds.truncate(*explorations);
                s.levels.push(RecordedLevel {
                    level: *level,
                    seconds,
                });
            }
            _ => {}
        }
    }
}
