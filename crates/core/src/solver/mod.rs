//! The search of Zhou and Wang: levels of random explorations, each refined
//! by copy-paste and label switching, keeping the best candidates per level.
//!
//! Architecture invariant: all randomness comes from [`Options::seed`].
//! Exploration `i` of level `ℓ` draws from its own stream derived from
//! `(seed, ℓ, i)`, explorations run in batches of a fixed size, and results
//! are combined in index order, so the result does not depend on the number
//! of threads (unless the run is stopped early).

pub(crate) mod candidate;
pub(crate) mod coarse;
pub(crate) mod distance;
mod explore;
pub(crate) mod flood_fill;
pub(crate) mod greedy;
pub(crate) mod levels;
pub(crate) mod matching;
mod options;
pub(crate) mod piece;
pub(crate) mod refine;
pub(crate) mod shape;

use std::collections::VecDeque;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind};
use crate::solver::distance::Geometry;
use candidate::{Candidate, Problem, Score};
use shape::Shape;

pub use explore::{Batch, Executor, Exploration, ExplorationError, Explorer};
pub use options::Options;

/// The most worker threads a search may ask for.
pub const MAX_THREADS: usize = 1024;

/// Progress reports, sent while the search runs.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Event {
    /// A level starts; it looks for dissections into `pieces` pieces.
    LevelStarted {
        /// The level `ℓ` (0 checks whether the figures are congruent).
        level: usize,
        /// `ℓ + 1`.
        pieces: usize,
        /// Explorations planned.
        explorations: usize,
    },
    /// An exploration finished.
    Exploration {
        /// The level.
        level: usize,
        /// Explorations finished at this level.
        done: usize,
        /// Explorations planned.
        total: usize,
        /// Best objective so far at this level.
        best_score: f64,
        /// Best matching cost `E_M` so far at this level.
        best_mismatch: u64,
    },
    /// A level ended.
    LevelFinished {
        /// The level.
        level: usize,
        /// Its piece count.
        pieces: usize,
        /// Explorations run.
        explorations: usize,
        /// Best `E_M` at the level.
        best_mismatch: u64,
        /// Whether a valid dissection was found.
        found: bool,
    },
    /// A round of the anytime search starts: the level schedule again, with
    /// new random streams, looking for at most `max_pieces` pieces.
    RoundStarted {
        /// The round (0 is the paper's schedule).
        round: usize,
        /// The most pieces it looks for (one fewer than the best so far).
        max_pieces: usize,
    },
    /// A valid dissection with fewer pieces than any before was found.
    Improved {
        /// Its piece count.
        pieces: usize,
        /// The level it was found at.
        level: usize,
        /// The round.
        round: usize,
        /// How it was found.
        via: Via,
    },
}

/// How an improvement was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Via {
    /// The constructive dissection.
    Greedy,
    /// An exploration of the level search.
    Search,
    /// A near miss of the level search, finished by the repairer.
    Repair,
    /// A dissection of the figures at half resolution, lifted and refined.
    Coarse,
}

impl Via {
    /// A short name: `greedy`, `search`, `repair`, `coarse`.
    pub fn name(self) -> &'static str {
        match self {
            Via::Greedy => "greedy",
            Via::Search => "search",
            Via::Repair => "repair",
            Via::Coarse => "coarse",
        }
    }
}

/// Receives [`Event`]s (from worker threads), and may judge the search's
/// candidates ([`Observer::judge`]).
pub trait Observer: Sync {
    /// Called for every event.
    fn on_event(&self, event: &Event);

    /// Whether [`Observer::judge`] is to be called. `false` (the default):
    /// the search never builds its candidates' cells for it and behaves
    /// exactly as without a judge.
    fn judges(&self) -> bool {
        false
    }

    /// Judges a candidate: every result of a level's explorations (in
    /// index order, on the search's own thread), every constructive and
    /// repaired dissection. `pieces[f][i]` are the cells of piece `i` in
    /// figure `f` (labels aligned to figure 0), `valid` the solver's
    /// verdict. Every valid dissection the search finds passes through
    /// here, so an observer can collect them; one it does not accept is
    /// treated as invalid (never an answer).
    fn judge(&self, pieces: &[Vec<Vec<Cell>>], valid: bool) -> Judgement {
        let _ = (pieces, valid);
        Judgement::default()
    }
}

/// What [`Observer::judge`] says about a candidate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Judgement {
    /// Whether a valid dissection may be an answer (`false`: the search
    /// treats it as invalid).
    pub accept: bool,
    /// Added to the candidate's objective: a penalty steers which
    /// candidates a level keeps as parents of the next.
    pub penalty: f64,
}

impl Default for Judgement {
    fn default() -> Judgement {
        Judgement {
            accept: true,
            penalty: 0.0,
        }
    }
}

impl Observer for () {
    fn on_event(&self, _event: &Event) {}
}

/// A valid dissection found by the solver.
#[derive(Clone, Debug, PartialEq)]
pub struct Found {
    /// `pieces[f][i]`: the cells of piece `i` in figure `f` (sorted).
    pub pieces: Vec<Vec<Vec<Cell>>>,
    /// The level it was found at.
    pub level: usize,
    /// Variance of the piece areas.
    pub variance: f64,
}

impl Found {
    /// The number of pieces.
    pub fn piece_count(&self) -> usize {
        self.pieces.first().map_or(0, |p| p.len())
    }

    /// The area of each piece.
    pub fn areas(&self) -> Vec<usize> {
        self.pieces
            .first()
            .map_or(Vec::new(), |p| p.iter().map(|c| c.len()).collect())
    }
}

/// What a search produced.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// The best valid dissection, if one was found.
    pub found: Option<Found>,
    /// The best matching cost `E_M` at the last level searched.
    pub best_mismatch: Option<u64>,
    /// The piece count of the last level searched.
    pub last_pieces: usize,
    /// Whether the search was stopped (time limit, Ctrl-C) before it ended.
    pub stopped: bool,
    /// Explorations run in all.
    pub explorations: usize,
    /// Rounds of the level schedule run (the paper's schedule is one).
    pub rounds: usize,
}

/// Occurs when figures cannot be dissected together.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum SolveError {
    /// Occurs with fewer than two figures.
    #[error("need at least two figures, got {0}")]
    TooFewFigures(usize),
    /// Occurs when figures are on different lattices.
    #[error("figures are on different lattices: {0} and {1}")]
    MixedLattices(LatticeKind, LatticeKind),
    /// Occurs when areas differ; lists every figure's cell count.
    #[error("figures have different areas: {0:?} cells")]
    UnequalAreas(Vec<usize>),
    /// Occurs when a figure is too large for the solver's 16-bit labels.
    #[error("figure has {0} cells; at most 65000 are supported")]
    TooLarge(usize),
    /// Occurs when the thread pool cannot be built.
    #[error("cannot start worker threads: {0}")]
    Threads(String),
    /// Occurs when an [`Executor`] fails or returns explorations that do
    /// not fit the problem.
    #[error(transparent)]
    Executor(#[from] ExplorationError),
}

/// Checks that figures can be dissected together.
pub fn check_figures(figures: &[Figure]) -> Result<(), SolveError> {
    if figures.len() < 2 {
        return Err(SolveError::TooFewFigures(figures.len()));
    }
    let l = figures[0].lattice();
    if let Some(f) = figures.iter().find(|f| f.lattice() != l) {
        return Err(SolveError::MixedLattices(l, f.lattice()));
    }
    let areas: Vec<usize> = figures.iter().map(|f| f.len()).collect();
    if areas.iter().any(|a| *a != areas[0]) {
        return Err(SolveError::UnequalAreas(areas));
    }
    if areas[0] > 65_000 {
        return Err(SolveError::TooLarge(areas[0]));
    }
    Ok(())
}

/// The random stream of exploration `index` at `level` of round `round`
/// (round 0 is the paper's schedule and keeps its streams).
fn stream(seed: u64, round: usize, level: usize, index: usize) -> ChaCha8Rng {
    fn splitmix(mut z: u64) -> u64 {
        z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    let mut key = splitmix(seed) ^ ((level as u64) << 40) ^ index as u64;
    if round > 0 {
        key = splitmix(key ^ splitmix(round as u64).rotate_left(17));
    }
    ChaCha8Rng::seed_from_u64(splitmix(key))
}

/// What one level of explorations produced.
pub(crate) struct Level {
    /// Every exploration's result, in index order.
    pub(crate) results: Vec<(Candidate, Score)>,
    /// Whether a stop cut the level short.
    pub(crate) stopped: bool,
}

impl Level {
    fn best_mismatch(&self) -> u64 {
        self.results
            .iter()
            .map(|(_, s)| s.mismatch)
            .min()
            .unwrap_or(u64::MAX)
    }

    /// The valid result of least area variance (then objective, then index).
    fn best_valid(&self) -> Option<&(Candidate, Score)> {
        self.results.iter().filter(|(_, s)| s.valid).min_by(|a, b| {
            a.1.variance
                .total_cmp(&b.1.variance)
                .then(a.1.value.total_cmp(&b.1.value))
        })
    }

    /// The `keep` best results by objective (stable: ties keep index order).
    fn kept(self, keep: usize) -> Vec<(Candidate, Score)> {
        let results = self.results;
        let mut order: Vec<usize> = (0..results.len()).collect();
        order.sort_by(|&a, &b| {
            results[a]
                .1
                .value
                .total_cmp(&results[b].1.value)
                .then(a.cmp(&b))
        });
        order.truncate(keep.max(1));
        let mut slots: Vec<Option<(Candidate, Score)>> = results.into_iter().map(Some).collect();
        order
            .into_iter()
            .map(|i| slots[i].take().expect("each index once"))
            .collect()
    }
}

/// Where the explorations of a level start from.
#[derive(Clone, Copy)]
enum From<'p> {
    /// The paper's level: two clusters at level 1, else one more piece for
    /// a random one of the kept candidates of the level below.
    Below(&'p [(Candidate, Score)]),
    /// As `Below`, with a quarter of the explorations and no extra rounds:
    /// the climb from a candidate lifted from the coarse figures.
    Lifted(&'p [(Candidate, Score)]),
    /// The descent: one piece fewer than this dissection (merge), with
    /// exploration indices from the given one (a new attempt at the same
    /// step draws new streams).
    Above(&'p Candidate, usize),
}

/// Stream levels of the descent are kept apart from the ladder's.
pub(crate) const DESCENT: usize = 1 << 20;

/// Explorations run ahead per worker thread (in whole batches, see
/// [`Search::level`]); at most `MAX_AHEAD` batches.
const AHEAD_PER_THREAD: usize = 4;
const MAX_AHEAD: usize = 8;

/// Levels climbed at full resolution from a lifted coarse candidate.
const CLIMB: usize = 2;

/// Attempts (fresh streams) at one descent step while it ends near misses.
const DESCENT_ATTEMPTS: usize = 4;

/// The solver form of `figures` under `options`.
fn problem_of(figures: &[Figure], options: &Options) -> Result<Problem, SolveError> {
    check_figures(figures)?;
    let lattice = figures[0].lattice().lattice();
    let mirror = options.mirror && lattice.supports_mirror();
    Ok(Problem::new(
        figures.iter().map(Shape::of_figure).collect(),
        Geometry {
            syms: lattice.symmetries(mirror),
            dim: lattice.dim(),
            modulus: lattice.modulus(),
        },
    ))
}

/// One search's fixed context.
pub(crate) struct Search<'a> {
    figures: &'a [Figure],
    problem: Problem,
    options: &'a Options,
    stop: &'a AtomicBool,
    observer: &'a dyn Observer,
    pool: rayon::ThreadPool,
    /// Runs the batches instead of `pool` when set.
    executor: Option<&'a dyn Executor>,
}

impl<'a> Search<'a> {
    pub(crate) fn new(
        figures: &'a [Figure],
        options: &'a Options,
        stop: &'a AtomicBool,
        observer: &'a dyn Observer,
        executor: Option<&'a dyn Executor>,
    ) -> Result<Search<'a>, SolveError> {
        let problem = problem_of(figures, options)?;
        if options.threads > MAX_THREADS {
            return Err(SolveError::Threads(format!(
                "{} threads asked for; at most {MAX_THREADS}",
                options.threads
            )));
        }
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(options.threads)
            .build()
            .map_err(|e| SolveError::Threads(e.to_string()))?;
        Ok(Search {
            figures,
            problem,
            options,
            stop,
            observer,
            pool,
            executor,
        })
    }

    fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }

    /// Lets the observer judge a candidate ([`Observer::judge`]): its
    /// penalty is added to the objective, and a valid candidate it does not
    /// accept becomes invalid.
    fn judge(&self, cand: &Candidate, score: &mut Score) {
        if !self.observer.judges() {
            return;
        }
        let j = self
            .observer
            .judge(&cand.cells_by_label(self.figures), score.valid);
        if j.penalty.is_finite() {
            score.value += j.penalty;
        }
        score.valid &= j.accept;
    }

    fn found(&self, cand: &Candidate, score: &Score, level: usize) -> Found {
        Found {
            pieces: cand.cells_by_label(self.figures),
            level,
            variance: score.variance,
        }
    }

    /// Level 0: the figures themselves, one piece each.
    fn level_zero(&self) -> (Candidate, Score) {
        self.observer.on_event(&Event::LevelStarted {
            level: 0,
            pieces: 1,
            explorations: 1,
        });
        let mut whole = Candidate {
            labels: self
                .problem
                .shapes
                .iter()
                .map(|s| vec![0u16; s.len()])
                .collect(),
            k: 1,
        };
        let mut s0 = whole.evaluate(&self.problem, 0.0, self.options.split_penalty);
        self.judge(&whole, &mut s0);
        self.observer.on_event(&Event::LevelFinished {
            level: 0,
            pieces: 1,
            explorations: 1,
            best_mismatch: s0.mismatch,
            found: s0.valid,
        });
        (whole, s0)
    }

    /// The explorations of `level` in `round`, from `parents` (the kept
    /// candidates of the level below; unused at level 1), in batches, with
    /// the near-miss extra rounds.
    fn level(&self, round: usize, level: usize, from: From<'_>) -> Result<Level, SolveError> {
        let options = self.options;
        let pieces = level + 1;
        // The descent is a local step from a dissection: a quarter of a
        // level's explorations, no extra rounds.
        let (n, extra_rounds, first) = match from {
            From::Below(_) => (options.explorations.max(1), options.extra_rounds, 0),
            From::Lifted(_) => (options.explorations.div_ceil(4).max(1), 0, 0),
            From::Above(_, first) => (options.explorations.div_ceil(4).max(1), 0, first),
        };
        self.observer.on_event(&Event::LevelStarted {
            level,
            pieces,
            explorations: n,
        });
        let done = AtomicUsize::new(0);
        let total = AtomicUsize::new(n);
        let best_seen = Mutex::new((f64::INFINITY, u64::MAX));
        let note = |result: &(Candidate, Score)| {
            let d = done.fetch_add(1, Ordering::Relaxed) + 1;
            let (bs, bm) = {
                let mut g = best_seen.lock().unwrap_or_else(|e| e.into_inner());
                g.0 = g.0.min(result.1.value);
                g.1 = g.1.min(result.1.mismatch);
                *g
            };
            self.observer.on_event(&Event::Exploration {
                level,
                done: d,
                total: total.load(Ordering::Relaxed),
                best_score: bs,
                best_mismatch: bm,
            });
        };
        let run_one = |i: usize| -> (Candidate, Score) {
            let result = match from {
                From::Below(parents) | From::Lifted(parents) => explore::explore_one(
                    &self.problem,
                    options,
                    round,
                    level,
                    i,
                    false,
                    parents.len(),
                    |p| &parents[p].0,
                    self.stop,
                ),
                From::Above(parent, _) => explore::explore_one(
                    &self.problem,
                    options,
                    round,
                    level,
                    i,
                    true,
                    1,
                    |_| parent,
                    self.stop,
                ),
            };
            note(&result);
            result
        };
        // What an executor gets as parents (made once per level, only for one).
        let (parents, descent): (Vec<Exploration>, bool) = match (self.executor, from) {
            (None, _) => (Vec::new(), false),
            (Some(_), From::Below(parents) | From::Lifted(parents)) => (
                parents
                    .iter()
                    .map(|(candidate, score)| Exploration {
                        candidate: candidate.clone(),
                        score: *score,
                    })
                    .collect(),
                false,
            ),
            // The descent's parent is a dissection; explorations read only
            // a parent's labels, never its score.
            (Some(_), From::Above(parent, _)) => (
                vec![Exploration {
                    candidate: parent.clone(),
                    score: Score {
                        value: 0.0,
                        mismatch: 0,
                        split: 0,
                        valid: true,
                        variance: 0.0,
                    },
                }],
                true,
            ),
        };
        let mut results: Vec<(Candidate, Score)> = Vec::with_capacity(n);
        let batch = options.batch.max(1);
        let near_miss = options.near_miss(self.figures.len(), self.figures[0].len());
        let mut start = first;
        let mut planned = first + n;
        let mut stopped = false;
        // Explorations run ahead of the batch being decided, up to `ahead`
        // batches at once (the pool's path; an executor gets one batch at a
        // time), so that many threads meet at a barrier once per window
        // rather than once per batch. Results are still taken batch by
        // batch in index order and those past the batch that decides the
        // level are dropped: the answer does not depend on the threads.
        let ahead = (AHEAD_PER_THREAD * self.pool.current_num_threads())
            .div_ceil(batch)
            .clamp(1, MAX_AHEAD);
        let mut pending: VecDeque<(Candidate, Score)> = VecDeque::new();
        while start < planned {
            let end = (start + batch).min(planned);
            let chunk: Vec<(Candidate, Score)> = match self.executor {
                None => {
                    if pending.len() < end - start {
                        let from = start + pending.len();
                        let to = (start + batch * ahead).min(planned);
                        let more: Vec<(Candidate, Score)> = self
                            .pool
                            .install(|| (from..to).into_par_iter().map(run_one).collect());
                        pending.extend(more);
                    }
                    pending.drain(..end - start).collect()
                }
                Some(ex) => {
                    let batch = Batch {
                        round,
                        level,
                        descent,
                        indices: start..end,
                        parents: &parents,
                    };
                    let got = ex.run(&batch).map_err(ExplorationError::Executor)?;
                    if got.len() != end - start {
                        return Err(ExplorationError::Count {
                            got: got.len(),
                            want: end - start,
                        }
                        .into());
                    }
                    let mut chunk = Vec::with_capacity(got.len());
                    for e in got {
                        e.check(&self.problem)?;
                        let result = (e.candidate, e.score);
                        note(&result);
                        chunk.push(result);
                    }
                    chunk
                }
            };
            let mut chunk = chunk;
            for (cand, score) in &mut chunk {
                self.judge(cand, score);
            }
            results.extend(chunk);
            start = end;
            if self.stopped() {
                stopped = true;
                break;
            }
            if !options.full_levels && results.iter().any(|(_, s)| s.valid) {
                break;
            }
            // A level that ends a near miss gets more rounds of explorations
            // (new streams, same parents) before the next level is tried.
            let best_mismatch = results
                .iter()
                .map(|(_, s)| s.mismatch)
                .min()
                .unwrap_or(u64::MAX);
            if start == planned
                && planned - first < n.saturating_mul(1 + extra_rounds)
                && best_mismatch <= near_miss
            {
                planned += n;
                total.store(planned - first, Ordering::Relaxed);
                self.observer.on_event(&Event::LevelStarted {
                    level,
                    pieces,
                    explorations: planned - first,
                });
            }
        }
        let level_result = Level { results, stopped };
        self.observer.on_event(&Event::LevelFinished {
            level,
            pieces,
            explorations: level_result.results.len(),
            best_mismatch: level_result.best_mismatch(),
            found: level_result.results.iter().any(|(_, s)| s.valid),
        });
        Ok(level_result)
    }

    /// Hands the near misses of a level (smallest `E_M` first, at most
    /// `tries`) to the repairer; the first valid repair with at most
    /// `pieces` pieces wins.
    pub(crate) fn repair(
        &self,
        repairer: &dyn Repair,
        level: &Level,
        pieces: usize,
        tries: usize,
    ) -> Option<(Candidate, Score)> {
        let limit = 4 * self
            .options
            .near_miss(self.figures.len(), self.figures[0].len());
        let mut order: Vec<usize> = (0..level.results.len())
            .filter(|&i| {
                let s = &level.results[i].1;
                !s.valid && s.mismatch <= limit
            })
            .collect();
        order.sort_by_key(|&i| (level.results[i].1.mismatch, level.results[i].1.split, i));
        let mut seen: Vec<&Vec<Vec<u16>>> = Vec::new();
        for i in order {
            if seen.len() >= tries || self.stopped() {
                break;
            }
            let cand = &level.results[i].0;
            if seen.contains(&&cand.labels) {
                continue;
            }
            seen.push(&cand.labels);
            let cells = cand.cells_by_label(self.figures);
            let Some(fixed) = repairer.repair(&cells, self.stop) else {
                continue;
            };
            if let Some(c) = self.candidate_of(&fixed) {
                if c.0.k <= pieces {
                    return Some(c);
                }
            }
        }
        None
    }

    /// What a level settles: its valid result of least area variance, else
    /// (when the level ran to its end) one of its near misses finished by
    /// the repairer.
    fn settle(
        &self,
        level: &Level,
        pieces: usize,
        repairer: Option<&dyn Repair>,
        tries: usize,
    ) -> Option<(Candidate, Score, Via)> {
        if let Some((c, s)) = level.best_valid() {
            return Some((c.clone(), *s, Via::Search));
        }
        if level.stopped {
            return None;
        }
        let (c, s) = self.repair(repairer?, level, pieces, tries)?;
        Some((c, s, Via::Repair))
    }

    /// A candidate from cells per piece per figure, when they cover every
    /// figure exactly and the solver's own score calls it valid.
    fn candidate_of(&self, pieces: &[Vec<Vec<Cell>>]) -> Option<(Candidate, Score)> {
        if pieces.len() != self.figures.len() {
            return None;
        }
        let k = pieces[0].len();
        if k == 0 || k >= u16::MAX as usize {
            return None;
        }
        let mut labels = Vec::with_capacity(pieces.len());
        for (fig, fp) in self.figures.iter().zip(pieces) {
            if fp.len() != k {
                return None;
            }
            let cells = fig.cells();
            let mut l = vec![u16::MAX; cells.len()];
            for (i, piece) in fp.iter().enumerate() {
                for c in piece {
                    let j = cells.binary_search(c).ok()?;
                    if l[j] != u16::MAX {
                        return None;
                    }
                    l[j] = i as u16;
                }
            }
            if l.contains(&u16::MAX) {
                return None;
            }
            labels.push(l);
        }
        let mut cand = Candidate { labels, k };
        let mut score = cand.evaluate(&self.problem, 0.0, self.options.split_penalty);
        self.judge(&cand, &mut score);
        score.valid.then_some((cand, score))
    }
}

/// Finds a dissection of `figures` into as few connected pieces as it can,
/// by the paper's schedule: levels of 2, 3, ... pieces, stopping at the
/// first level that holds a valid dissection.
///
/// Raising `stop` ends the search soon after; the best valid dissection found
/// so far is returned.
pub fn solve(
    figures: &[Figure],
    options: &Options,
    stop: &AtomicBool,
    observer: &dyn Observer,
) -> Result<Outcome, SolveError> {
    solve_with(figures, options, stop, observer, None)
}

/// [`solve`], with the explorations run by `executor` (`None`: the
/// solver's thread pool). An executor that returns what
/// [`Explorer::explore`] returns gives the same answer as [`solve`].
pub fn solve_with(
    figures: &[Figure],
    options: &Options,
    stop: &AtomicBool,
    observer: &dyn Observer,
    executor: Option<&dyn Executor>,
) -> Result<Outcome, SolveError> {
    let search = Search::new(figures, options, stop, observer, executor)?;
    let (whole, s0) = search.level_zero();
    if s0.valid {
        observer.on_event(&Event::Improved {
            pieces: 1,
            level: 0,
            round: 0,
            via: Via::Search,
        });
        return Ok(Outcome {
            found: Some(search.found(&whole, &s0, 0)),
            best_mismatch: Some(0),
            last_pieces: 1,
            stopped: false,
            explorations: 1,
            rounds: 0,
        });
    }
    let cells = figures[0].len();
    let max_pieces = options.max_pieces.unwrap_or(cells).min(cells);
    let mut parents: Vec<(Candidate, Score)> = Vec::new();
    let mut outcome = Outcome {
        found: None,
        best_mismatch: Some(s0.mismatch),
        last_pieces: 1,
        stopped: false,
        explorations: 1,
        rounds: 1,
    };
    for level in 1.. {
        let pieces = level + 1;
        if pieces > max_pieces || search.stopped() {
            break;
        }
        let result = search.level(0, level, From::Below(&parents))?;
        outcome.explorations += result.results.len();
        outcome.last_pieces = pieces;
        outcome.best_mismatch = Some(result.best_mismatch());
        outcome.stopped |= result.stopped;
        if let Some((cand, score)) = result.best_valid() {
            let found = search.found(cand, score, level);
            observer.on_event(&Event::Improved {
                pieces: found.piece_count(),
                level,
                round: 0,
                via: Via::Search,
            });
            outcome.found = Some(found);
            return Ok(outcome);
        }
        if result.stopped || result.results.is_empty() {
            break;
        }
        parents = result.kept(options.keep);
    }
    outcome.stopped |= search.stopped();
    Ok(outcome)
}

/// Steps of the plateau walk per round ([`Anytime::plateau`]).
const WALK_STEPS: usize = 3;
/// Repaired moves per step of the plateau walk.
const WALK_REPAIRS: usize = 4;

/// Hands a ball of radius 1 or 2 around a random cell of the first figure
/// that touches another piece to that piece; whether it found one.
fn shift_ball<R: rand::Rng>(problem: &Problem, cand: &mut Candidate, rng: &mut R) -> bool {
    use rand::RngExt;
    let shape = &problem.shapes[0];
    let labels = &mut cand.labels[0];
    for _ in 0..32 {
        let start = rng.random_range(0..shape.len()) as u32;
        let own = labels[start as usize];
        let others: Vec<u16> = shape
            .neighbors(start)
            .iter()
            .map(|&n| labels[n as usize])
            .filter(|&l| l != own)
            .collect();
        if others.is_empty() {
            continue;
        }
        let to = others[rng.random_range(0..others.len())];
        let radius = rng.random_range(1..=2);
        let mut ball = vec![start];
        let mut seen = vec![false; shape.len()];
        seen[start as usize] = true;
        let mut frontier = vec![start];
        for _ in 0..radius {
            let mut next = Vec::new();
            for &c in &frontier {
                for &n in shape.neighbors(c) {
                    if !seen[n as usize] {
                        seen[n as usize] = true;
                        next.push(n);
                    }
                }
            }
            ball.extend(&next);
            frontier = next;
        }
        for c in ball {
            labels[c as usize] = to;
        }
        return true;
    }
    false
}

/// Valid dissections one piece above the best that the plateau descends
/// from, per round.
const PLATEAU_DESCENTS: usize = 4;

/// The level one piece above the incumbent from `parents` (a ladder's
/// last kept candidates), then the descent from a few of its valid
/// results, their near misses repaired; every result is seen by the judge.
/// Returns whether it found fewer pieces than the incumbent.
#[allow(clippy::too_many_arguments)]
fn plateau_descents<F>(
    search: &Search<'_>,
    best: &mut Option<(Candidate, Score)>,
    outcome: &mut Outcome,
    round: usize,
    parents: &[(Candidate, Score)],
    repairer: Option<&dyn Repair>,
    anytime: &Anytime,
    improve: &F,
) -> Result<bool, SolveError>
where
    F: Fn(
        &mut Option<(Candidate, Score)>,
        &mut Outcome,
        Candidate,
        Score,
        usize,
        usize,
        Via,
    ) -> bool,
{
    let Some(k) = best.as_ref().map(|(b, _)| b.k) else {
        return Ok(false);
    };
    if parents.is_empty() || k < 2 {
        return Ok(false);
    }
    let up = search.level(round, k, From::Below(parents))?;
    outcome.explorations += up.results.len();
    let mut seen: Vec<Vec<u16>> = Vec::new();
    let mut improved = false;
    for (cand, _) in up.results.iter().filter(|(_, s)| s.valid) {
        if seen.len() >= PLATEAU_DESCENTS || search.stopped() {
            break;
        }
        let key = partition(cand);
        if seen.contains(&key) {
            continue;
        }
        seen.push(key);
        let level = cand.k.saturating_sub(2);
        if level == 0 {
            break;
        }
        let down = search.level(round, level, From::Above(cand, 0))?;
        outcome.explorations += down.results.len();
        if let Some((c, s, via)) = search.settle(&down, level + 1, repairer, anytime.repair_tries) {
            improved |= improve(best, outcome, c, s, level, round, via);
        }
    }
    Ok(improved)
}

/// How a candidate cuts the first figure: its labels there, renumbered in
/// order of first appearance.
fn partition(c: &Candidate) -> Vec<u16> {
    let mut map = vec![u16::MAX; c.k];
    let mut next = 0u16;
    c.labels[0]
        .iter()
        .map(|&l| {
            let m = &mut map[l as usize];
            if *m == u16::MAX {
                *m = next;
                next += 1;
            }
            *m
        })
        .collect()
}

/// One plateau walk from the incumbent (see [`Anytime::plateau`]): each
/// step goes one piece up (the level search from the current dissection
/// alone) and one piece down again (the descent from a valid result of
/// the step up), and moves to a valid result of the step down: a random
/// walk over dissections with the best count, each seen by the judge.
/// Returns whether it found fewer pieces than the incumbent.
fn plateau_walk<F>(
    search: &Search<'_>,
    best: &mut Option<(Candidate, Score)>,
    outcome: &mut Outcome,
    round: usize,
    repairer: Option<&dyn Repair>,
    improve: &F,
) -> Result<bool, SolveError>
where
    F: Fn(
        &mut Option<(Candidate, Score)>,
        &mut Outcome,
        Candidate,
        Score,
        usize,
        usize,
        Via,
    ) -> bool,
{
    let Some(mut current) = best.clone() else {
        return Ok(false);
    };
    let mut improved = false;
    let mut visited = vec![partition(&current.0)];
    for step in 0..WALK_STEPS {
        if search.stopped() {
            break;
        }
        // Streams of their own: a walk step is no round of the ladder.
        let streams = ((round + 1) << 16) | (step + 1);
        let k = current.0.k;
        // Large-neighbourhood moves: a small ball of the first figure
        // handed to a neighbouring piece, then repaired exactly.
        if let Some(r) = repairer {
            for t in 0..WALK_REPAIRS {
                if search.stopped() {
                    break;
                }
                let mut rng = stream(search.options.seed, streams, DESCENT - 1, t);
                let mut moved = current.0.clone();
                if !shift_ball(&search.problem, &mut moved, &mut rng) {
                    continue;
                }
                let cells = moved.cells_by_label(search.figures);
                let Some(fixed) = r.repair(&cells, search.stop) else {
                    continue;
                };
                let Some(next) = search.candidate_of(&fixed) else {
                    continue;
                };
                if next.0.k < current.0.k {
                    improved |= improve(
                        best,
                        outcome,
                        next.0.clone(),
                        next.1,
                        next.0.k - 1,
                        round,
                        Via::Repair,
                    );
                }
                let key = partition(&next.0);
                if next.0.k <= current.0.k && !visited.contains(&key) {
                    visited.push(key);
                    current = next;
                }
            }
        }
        let up = search.level(streams, k, From::Below(std::slice::from_ref(&current)))?;
        outcome.explorations += up.results.len();
        let ups: Vec<&(Candidate, Score)> = up.results.iter().filter(|(_, s)| s.valid).collect();
        let Some(&upper) = ups.get(step % ups.len().max(1)) else {
            break;
        };
        let level = upper.0.k.saturating_sub(2);
        if level == 0 {
            break;
        }
        let down = search.level(streams, level, From::Above(&upper.0, 0))?;
        outcome.explorations += down.results.len();
        // The first valid result that cuts the first figure unlike any
        // dissection the walk stood on.
        let Some(next) = down
            .results
            .iter()
            .filter(|(_, s)| s.valid)
            .find(|(c, _)| !visited.contains(&partition(c)))
        else {
            continue;
        };
        visited.push(partition(&next.0));
        if next.0.k < k {
            improved |= improve(
                best,
                outcome,
                next.0.clone(),
                next.1,
                level,
                round,
                Via::Search,
            );
        }
        current = next.clone();
    }
    Ok(improved)
}

/// Settings of [`solve_anytime`] beyond [`Options`].
#[derive(Clone, Debug, PartialEq)]
pub struct Anytime {
    /// End after this many rounds in a row that found no fewer pieces
    /// (`None`: only a stop, or having nothing left to try, ends the run).
    pub idle_rounds: Option<usize>,
    /// Near-miss candidates handed to the repairer per level.
    pub repair_tries: usize,
    /// End after this many rounds (`None`: no such cap).
    pub max_rounds: Option<usize>,
    /// Keep searching at the best piece count, not only below it: every
    /// round's ladder runs up to the best count's level, so more valid
    /// dissections with the fewest pieces reach [`Observer::judge`]
    /// (several solutions). `false`: each round looks for fewer pieces only.
    pub plateau: bool,
}

impl Default for Anytime {
    fn default() -> Anytime {
        Anytime {
            idle_rounds: Some(1),
            repair_tries: 2,
            max_rounds: None,
            plateau: false,
        }
    }
}

/// Finishes near misses: given a candidate that is a few cells from a
/// dissection, returns a valid dissection with at most as many pieces, or
/// `None`. (The core cannot depend on the exact search; the engine plugs
/// it in.)
pub trait Repair: Sync {
    /// `pieces[f][i]`: the cells of piece `i` in figure `f` of a candidate
    /// whose pieces nearly match (labels aligned to figure 0). The answer
    /// has the same shape. Raising `stop` should end the repair soon.
    fn repair(&self, pieces: &[Vec<Vec<Cell>>], stop: &AtomicBool) -> Option<Vec<Vec<Vec<Cell>>>>;
}

/// The anytime search: a valid dissection first (the constructive greedy
/// dissection, never fails), then rounds of the paper's level schedule with
/// fresh random streams, each looking for fewer pieces than the best so
/// far; near misses go to `repair`. Every improvement is reported as
/// [`Event::Improved`]; the answer never has more pieces than an earlier
/// one.
///
/// Without a stop the run ends after [`Anytime::idle_rounds`] rounds
/// without improvement, or when two pieces are reached (one is impossible:
/// the figures are not congruent), so it is the same for any thread count.
pub fn solve_anytime(
    figures: &[Figure],
    options: &Options,
    anytime: &Anytime,
    stop: &AtomicBool,
    observer: &dyn Observer,
    repair: Option<&dyn Repair>,
) -> Result<Outcome, SolveError> {
    solve_anytime_with(figures, options, anytime, stop, observer, repair, None)
}

/// [`solve_anytime`], with the explorations run by `executor` (`None`: the
/// solver's thread pool); the same answer when it returns what
/// [`Explorer::explore`] returns.
pub fn solve_anytime_with(
    figures: &[Figure],
    options: &Options,
    anytime: &Anytime,
    stop: &AtomicBool,
    observer: &dyn Observer,
    repair: Option<&dyn Repair>,
    executor: Option<&dyn Executor>,
) -> Result<Outcome, SolveError> {
    let search = Search::new(figures, options, stop, observer, executor)?;
    let (whole, s0) = search.level_zero();
    if s0.valid {
        let found = search.found(&whole, &s0, 0);
        observer.on_event(&Event::Improved {
            pieces: 1,
            level: 0,
            round: 0,
            via: Via::Search,
        });
        return Ok(Outcome {
            found: Some(found),
            best_mismatch: Some(0),
            last_pieces: 1,
            stopped: false,
            explorations: 1,
            rounds: 0,
        });
    }
    let cells = figures[0].len();
    let max_pieces = options.max_pieces.unwrap_or(cells).min(cells);
    let mut outcome = Outcome {
        found: None,
        best_mismatch: Some(s0.mismatch),
        last_pieces: 1,
        stopped: false,
        explorations: 1,
        rounds: 0,
    };
    // The incumbent: the best dissection so far (within the cap).
    let mut best: Option<(Candidate, Score)> = None;
    let improve = |best: &mut Option<(Candidate, Score)>,
                   outcome: &mut Outcome,
                   cand: Candidate,
                   score: Score,
                   level: usize,
                   round: usize,
                   via: Via|
     -> bool {
        let found = search.found(&cand, &score, level);
        let pieces = found.piece_count();
        if pieces > max_pieces || best.as_ref().is_some_and(|(b, _)| pieces >= b.k) {
            return false;
        }
        // Labels that vanished are dropped, so `k` is the piece count.
        let cand = search.candidate_of(&found.pieces).map_or(cand, |(c, _)| c);
        observer.on_event(&Event::Improved {
            pieces,
            level,
            round,
            via,
        });
        outcome.found = Some(found);
        *best = Some((cand, score));
        true
    };
    // The constructive dissection: every figure as the pivot, two ways of
    // keeping components; each one with fewer pieces is an improvement.
    'styles: for divisor in [2, 1] {
        for pivot in 0..figures.len() {
            if search.stopped() {
                break 'styles;
            }
            let mut cand = greedy::greedy(&search.problem, greedy::GreedyStyle { pivot, divisor });
            let mut score = cand.evaluate(&search.problem, 0.0, options.split_penalty);
            debug_assert!(score.valid, "the greedy dissection is valid");
            search.judge(&cand, &mut score);
            if score.valid {
                let level = cand.k - 1;
                improve(&mut best, &mut outcome, cand, score, level, 0, Via::Greedy);
            }
        }
    }
    // Large figures: the level search costs about the same per level at
    // any resolution, so it runs on the figures at half resolution (halved
    // again while they are large); the coarse dissection is lifted, refined
    // at full resolution and, when it is a near miss, repaired. The ladder
    // at full resolution is then not run: the coarse search is the ladder.
    let large = cells >= coarse::MIN_CELLS && coarse::downsample(figures, coarse::FACTOR).is_some();
    if large && !search.stopped() {
        let best_pieces = best.as_ref().map_or(max_pieces, |(b, _)| b.k - 1);
        let inner_options = Options {
            max_pieces: Some(best_pieces.min(max_pieces)),
            ..options.clone()
        };
        let inner = Anytime {
            idle_rounds: Some(1),
            max_rounds: Some(1),
            ..anytime.clone()
        };
        let lifted = coarse::from_coarse(
            figures,
            &search.problem,
            options,
            options.seed,
            stop,
            |coarse_figures| {
                solve_anytime_with(
                    coarse_figures,
                    &inner_options,
                    &inner,
                    stop,
                    &(),
                    repair,
                    None,
                )
                .ok()?
                .found
            },
        );
        if let Some((cand, mut score)) = lifted {
            search.judge(&cand, &mut score);
            let level = cand.k.saturating_sub(1);
            let mut done = false;
            if score.valid {
                done = improve(
                    &mut best,
                    &mut outcome,
                    cand.clone(),
                    score,
                    level,
                    0,
                    Via::Coarse,
                );
            } else if let Some(r) = repair {
                let near = Level {
                    results: vec![(cand.clone(), score)],
                    stopped: false,
                };
                if let Some((c, s)) = search.repair(r, &near, level + 1, 1) {
                    done = improve(&mut best, &mut outcome, c, s, level, 0, Via::Coarse);
                }
            }
            // Not yet a dissection but close (a repairable distance): climb
            // the paper's levels from it (one more piece per level, at most
            // CLIMB levels) while that stays below the best. A lift far
            // from any dissection (curved boundaries the coarse cells cut
            // differently) is left to the descent.
            let close = score.mismatch <= 4 * options.near_miss(figures.len(), cells);
            let mut parents = vec![(cand, score)];
            let top = if close { level + CLIMB } else { level };
            let mut level = level + 1;
            while !done && !search.stopped() && level <= top {
                let pieces = level + 1;
                if best.as_ref().is_some_and(|(b, _)| pieces >= b.k) || pieces > max_pieces {
                    break;
                }
                let result = search.level(0, level, From::Lifted(&parents))?;
                outcome.explorations += result.results.len();
                if let Some((c, s, _)) =
                    search.settle(&result, pieces, repair, anytime.repair_tries)
                {
                    improve(&mut best, &mut outcome, c, s, level, 0, Via::Coarse);
                    break;
                }
                if result.stopped || result.results.is_empty() {
                    break;
                }
                parents = result.kept(options.keep);
                level += 1;
            }
        }
    }
    let near_miss = options.near_miss(figures.len(), cells);
    // The plateau (several solutions) searches at the best count too.
    let below = usize::from(!anytime.plateau);
    // The descent: one piece fewer than the incumbent, by merging two of
    // its pieces and refining (a near miss goes to the repairer, and earns
    // new attempts with fresh streams), for as long as that works.
    let descend = |best: &mut Option<(Candidate, Score)>,
                   outcome: &mut Outcome,
                   round: usize|
     -> Result<bool, SolveError> {
        let mut improved = false;
        let mut attempt = 0;
        let n = options.explorations.div_ceil(4).max(1);
        while let Some((parent, _)) = best.clone() {
            let pieces = parent.k - 1;
            if pieces < 2 || search.stopped() {
                break;
            }
            let level = pieces - 1;
            let result = search.level(round, level, From::Above(&parent, attempt * n))?;
            outcome.explorations += result.results.len();
            match search.settle(&result, pieces, repair, anytime.repair_tries) {
                Some((c, s, via)) => {
                    if !improve(best, outcome, c, s, level, round, via) {
                        break;
                    }
                    improved = true;
                    attempt = 0;
                }
                None => {
                    attempt += 1;
                    if result.stopped
                        || attempt >= DESCENT_ATTEMPTS
                        || result.best_mismatch() > near_miss
                    {
                        break;
                    }
                }
            }
        }
        Ok(improved)
    };
    // The ladder: the paper's levels from two pieces up, with this round's
    // streams, below the best so far.
    let ladder = |best: &mut Option<(Candidate, Score)>,
                  outcome: &mut Outcome,
                  round: usize|
     -> Result<bool, SolveError> {
        let target = best
            .as_ref()
            .map_or(usize::MAX, |(b, _)| b.k)
            .saturating_sub(below)
            .min(max_pieces);
        let mut parents: Vec<(Candidate, Score)> = Vec::new();
        let mut ladder_ended = false;
        for level in 1..target {
            if search.stopped() {
                break;
            }
            let pieces = level + 1;
            let result = search.level(round, level, From::Below(&parents))?;
            outcome.explorations += result.results.len();
            outcome.last_pieces = outcome.last_pieces.max(pieces);
            outcome.best_mismatch = Some(result.best_mismatch());
            if let Some((c, s, via)) = search.settle(&result, pieces, repair, anytime.repair_tries)
            {
                return Ok(improve(best, outcome, c, s, level, round, via));
            }
            if result.stopped || result.results.is_empty() {
                break;
            }
            parents = result.kept(options.keep);
            ladder_ended = level + 1 == target;
        }
        // The plateau: a ladder that found nothing up to the best count
        // goes one level further and descends from there, into other
        // dissections with the best count.
        if anytime.plateau && ladder_ended && !search.stopped() {
            return plateau_descents(
                &search, best, outcome, round, &parents, repair, anytime, &improve,
            );
        }
        Ok(false)
    };
    let mut idle = 0;
    // On large figures the coarse step was round 0.
    let first_round = usize::from(large);
    if large {
        outcome.rounds = 1;
    }
    for round in first_round.. {
        let best_pieces = best.as_ref().map_or(usize::MAX, |(b, _)| b.k);
        // Look for fewer pieces than the best so far (and no more than the
        // cap); two pieces is the least there can be.
        let target = best_pieces.saturating_sub(below).min(max_pieces);
        if target < 2 || search.stopped() {
            break;
        }
        if anytime.idle_rounds.is_some_and(|n| idle >= n)
            || anytime.max_rounds.is_some_and(|n| round >= n)
        {
            break;
        }
        observer.on_event(&Event::RoundStarted {
            round,
            max_pieces: target,
        });
        outcome.rounds = round + 1;
        // Round 0 of a small figure runs the paper's ladder first (its
        // schedule reaches the fewest pieces there), then the descent from
        // what it found; later rounds descend first. Large figures only
        // descend (their ladder ran on the coarse figures).
        let improved = if large {
            descend(&mut best, &mut outcome, round)?
        } else if round == 0 {
            let a = ladder(&mut best, &mut outcome, round)?;
            descend(&mut best, &mut outcome, round)? | a
        } else {
            let a = descend(&mut best, &mut outcome, round)?;
            ladder(&mut best, &mut outcome, round)? | a
        };
        // The plateau walk: from the incumbent one piece up and down again,
        // and exact repairs of small moves: other dissections with the best
        // count (each seen by the judge), or fewer pieces.
        let improved = if anytime.plateau && !search.stopped() {
            plateau_walk(&search, &mut best, &mut outcome, round, repair, &improve)? | improved
        } else {
            improved
        };
        if improved {
            idle = 0;
        } else {
            idle += 1;
        }
    }
    outcome.stopped |= search.stopped();
    Ok(outcome)
}
