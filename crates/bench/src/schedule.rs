//! Replays recorded exploration times on a simulated machine of `T`
//! threads, to tell what a thread count buys without having its cores: the
//! makespan of each level and the fraction of worker time spent waiting.
//!
//! Explorations start in index order on the first free thread (what a
//! work-stealing pool does with equal priorities). With batch barriers, a
//! batch starts when the whole batch before it has finished; without them a
//! thread takes the next exploration as soon as it is free.

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

/// The greedy schedule of `durations` (in index order) on `threads`
/// threads, all free at time `start`; the time the last one ends.
fn list_schedule(durations: &[f64], threads: usize, start: f64) -> f64 {
    let mut free = vec![start; threads.max(1)];
    let mut end = start;
    for &d in durations {
        let (i, t) = free
            .iter()
            .copied()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))
            .expect("at least one thread");
        free[i] = t + d;
        end = end.max(free[i]);
    }
    end
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
    levels.iter().fold(
        Replay {
            threads: threads.max(1),
            makespan: 0.0,
            work: 0.0,
        },
        |acc, l| {
            let r = replay(l, batch, threads);
            Replay {
                threads: acc.threads,
                makespan: acc.makespan + r.makespan,
                work: acc.work + r.work,
            }
        },
    )
}
