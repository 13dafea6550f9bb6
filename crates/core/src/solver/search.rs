//! One search's fixed context ([`Search`]) and its steps: level 0, one
//! level of explorations in batches, what a level settles (a valid result,
//! else a near miss finished by the repairer).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

use crate::figure::Figure;
use crate::lattice::Cell;
use crate::solver::candidate::{Candidate, Problem, Score};
use crate::solver::explore::{self, Batch, Executor, Exploration, ExplorationError};
use crate::solver::{
    lookahead, problem_of, Event, Found, Observer, Options, Repair, SolveError, Via, MAX_THREADS,
};

/// What one level of explorations produced.
pub(crate) struct Level {
    /// Every exploration's result, in index order.
    pub(crate) results: Vec<(Candidate, Score)>,
    /// Whether a stop cut the level short.
    pub(crate) stopped: bool,
}

impl Level {
    pub(crate) fn best_mismatch(&self) -> u64 {
        self.results
            .iter()
            .map(|(_, s)| s.mismatch)
            .min()
            .unwrap_or(u64::MAX)
    }

    /// The valid result of least area variance (then objective, then index).
    pub(crate) fn best_valid(&self) -> Option<&(Candidate, Score)> {
        self.results.iter().filter(|(_, s)| s.valid).min_by(|a, b| {
            a.1.variance
                .total_cmp(&b.1.variance)
                .then(a.1.value.total_cmp(&b.1.value))
        })
    }

    /// The `keep` best results by objective (stable: ties keep index order).
    pub(crate) fn kept(self, keep: usize) -> Vec<(Candidate, Score)> {
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
pub(crate) enum From<'p> {
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

/// Explorations a level runs ahead of the first one not yet decided, per
/// worker thread (see [`Search::level`]): at least one batch, at most
/// `MAX_AHEAD` batches.
const AHEAD_PER_THREAD: usize = 4;
const MAX_AHEAD: usize = 8;

/// Where a level's exploration results come from.
enum Feed<'t, 's> {
    /// The solver's pool, in index order.
    Pool(&'t mut lookahead::Taker<'s, (Candidate, Score)>),
    /// An executor, one batch at a time.
    Executor(&'t dyn Executor),
}

/// One search's fixed context.
pub(crate) struct Search<'a> {
    pub(crate) figures: &'a [Figure],
    pub(crate) problem: Problem,
    pub(crate) options: &'a Options,
    pub(crate) stop: &'a AtomicBool,
    pub(crate) observer: &'a dyn Observer,
    pool: rayon::ThreadPool,
    /// Runs the batches instead of `pool` when set.
    executor: Option<&'a dyn Executor>,
    /// Valid dissections the observer's judge called fresh so far.
    fresh: AtomicUsize,
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
            fresh: AtomicUsize::new(0),
        })
    }

    /// Valid dissections the judge has called fresh so far.
    pub(crate) fn fresh(&self) -> usize {
        self.fresh.load(Ordering::Relaxed)
    }

    pub(crate) fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }

    /// Lets the observer judge a candidate ([`Observer::judge`]): its
    /// penalty is added to the objective, and a valid candidate it does not
    /// accept becomes invalid.
    pub(crate) fn judge(&self, cand: &Candidate, score: &mut Score) {
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
        if score.valid && j.fresh {
            self.fresh.fetch_add(1, Ordering::Relaxed);
        }
    }

    pub(crate) fn found(&self, cand: &Candidate, score: &Score, level: usize) -> Found {
        Found {
            pieces: cand.cells_by_label(self.figures),
            level,
            variance: score.variance,
        }
    }

    /// Level 0: the figures themselves, one piece each.
    pub(crate) fn level_zero(&self) -> (Candidate, Score) {
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
    /// the near-miss extra rounds (the steps: [`LevelRun`]).
    pub(crate) fn level(
        &self,
        round: usize,
        level: usize,
        from: From<'_>,
    ) -> Result<Level, SolveError> {
        let run = LevelRun::new(self, round, level, from);
        self.observer.on_event(&Event::LevelStarted {
            level,
            pieces: level + 1,
            explorations: run.n,
        });
        // The pool's threads run explorations without barriers, each taking
        // the next index as soon as it is free, at most `window` beyond the
        // first one not yet decided; an executor gets one batch at a time.
        let level_result = match self.executor {
            None => {
                let batch = self.options.batch.max(1);
                let window = (AHEAD_PER_THREAD * self.pool.current_num_threads())
                    .clamp(batch, MAX_AHEAD * batch);
                lookahead::ordered(
                    &self.pool,
                    run.first,
                    run.first + run.n,
                    window,
                    |i| run.run_one(i),
                    |t| run.decide(Feed::Pool(t)),
                )?
            }
            Some(ex) => run.decide(Feed::Executor(ex))?,
        };
        self.observer.on_event(&Event::LevelFinished {
            level,
            pieces: level + 1,
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
    pub(crate) fn settle(
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
    pub(crate) fn candidate_of(&self, pieces: &[Vec<Vec<Cell>>]) -> Option<(Candidate, Score)> {
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

/// One level of explorations while it runs: what it explores and its
/// progress so far. Its steps: [`LevelRun::run_one`] (one exploration, on
/// a pool thread), [`LevelRun::note`] (its progress event) and
/// [`LevelRun::decide`] (the batches in index order, the near-miss extra
/// rounds).
struct LevelRun<'l, 'a> {
    search: &'l Search<'a>,
    round: usize,
    level: usize,
    from: From<'l>,
    /// Explorations per round of the level.
    n: usize,
    /// Extra rounds allowed for a near miss.
    extra_rounds: usize,
    /// The first exploration index.
    first: usize,
    /// Explorations done, and planned (for the progress events).
    done: AtomicUsize,
    total: AtomicUsize,
    /// The best objective and matching cost seen so far.
    best_seen: Mutex<(f64, u64)>,
    /// What an executor gets as parents (made once per level, only for
    /// one), and whether the level is the descent.
    parents: Vec<Exploration>,
    descent: bool,
}

impl<'l, 'a> LevelRun<'l, 'a> {
    fn new(search: &'l Search<'a>, round: usize, level: usize, from: From<'l>) -> Self {
        let options = search.options;
        // The descent is a local step from a dissection: a quarter of a
        // level's explorations, no extra rounds.
        let (n, extra_rounds, first) = match from {
            From::Below(_) => (options.explorations.max(1), options.extra_rounds, 0),
            From::Lifted(_) => (options.explorations.div_ceil(4).max(1), 0, 0),
            From::Above(_, first) => (options.explorations.div_ceil(4).max(1), 0, first),
        };
        let (parents, descent) = match search.executor {
            None => (Vec::new(), false),
            Some(_) => executor_parents(from),
        };
        LevelRun {
            search,
            round,
            level,
            from,
            n,
            extra_rounds,
            first,
            done: AtomicUsize::new(0),
            total: AtomicUsize::new(n),
            best_seen: Mutex::new((f64::INFINITY, u64::MAX)),
            parents,
            descent,
        }
    }

    /// Notes one exploration's result: the level's progress event.
    fn note(&self, result: &(Candidate, Score)) {
        let d = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        let (bs, bm) = {
            let mut g = self.best_seen.lock().unwrap_or_else(|e| e.into_inner());
            g.0 = g.0.min(result.1.value);
            g.1 = g.1.min(result.1.mismatch);
            *g
        };
        // Explorations run ahead of the deciding batch count too, up to the
        // level's total.
        let total = self.total.load(Ordering::Relaxed);
        self.search.observer.on_event(&Event::Exploration {
            level: self.level,
            done: d.min(total),
            total,
            best_score: bs,
            best_mismatch: bm,
        });
    }

    /// Exploration `i` of the level (on the solver's pool).
    fn run_one(&self, i: usize) -> (Candidate, Score) {
        let s = self.search;
        let result = match self.from {
            From::Below(parents) | From::Lifted(parents) => explore::explore_one(
                &s.problem,
                s.options,
                self.round,
                self.level,
                i,
                false,
                parents.len(),
                |p| &parents[p].0,
                s.stop,
            ),
            From::Above(parent, _) => explore::explore_one(
                &s.problem,
                s.options,
                self.round,
                self.level,
                i,
                true,
                1,
                |_| parent,
                s.stop,
            ),
        };
        self.note(&result);
        result
    }

    /// Explorations `start..end` from `feed`: the pool's, or an executor's
    /// batch (checked, and noted as the pool's are).
    fn take(
        &self,
        feed: &mut Feed<'_, '_>,
        start: usize,
        end: usize,
    ) -> Result<Vec<(Candidate, Score)>, SolveError> {
        let ex = match feed {
            Feed::Pool(taker) => return Ok(taker.take(end - start)),
            Feed::Executor(ex) => ex,
        };
        let batch = Batch {
            round: self.round,
            level: self.level,
            descent: self.descent,
            indices: start..end,
            parents: &self.parents,
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
            e.check(&self.search.problem)?;
            let result = (e.candidate, e.score);
            self.note(&result);
            chunk.push(result);
        }
        Ok(chunk)
    }

    /// Results are decided batch by batch in index order, whoever runs
    /// them; those past the batch that decides the level are dropped, so
    /// the answer does not depend on the threads.
    fn decide(&self, mut feed: Feed<'_, '_>) -> Result<Level, SolveError> {
        let s = self.search;
        let options = s.options;
        let batch = options.batch.max(1);
        let near_miss = options.near_miss(s.figures.len(), s.figures[0].len());
        let mut results: Vec<(Candidate, Score)> = Vec::with_capacity(self.n);
        let mut start = self.first;
        let mut planned = self.first + self.n;
        let mut stopped = false;
        while start < planned {
            let end = (start + batch).min(planned);
            let mut chunk = self.take(&mut feed, start, end)?;
            for (cand, score) in &mut chunk {
                s.judge(cand, score);
            }
            results.extend(chunk);
            start = end;
            if s.stopped() {
                stopped = true;
                break;
            }
            if !options.full_levels && results.iter().any(|(_, s)| s.valid) {
                break;
            }
            let best_mismatch = results
                .iter()
                .map(|(_, s)| s.mismatch)
                .min()
                .unwrap_or(u64::MAX);
            if start == planned && self.more_rounds(planned, best_mismatch, near_miss) {
                planned += self.n;
                if let Feed::Pool(taker) = &mut feed {
                    taker.extend_to(planned);
                }
                self.total.store(planned - self.first, Ordering::Relaxed);
                s.observer.on_event(&Event::LevelStarted {
                    level: self.level,
                    pieces: self.level + 1,
                    explorations: planned - self.first,
                });
            }
        }
        Ok(Level { results, stopped })
    }

    /// Whether a level that planned explorations up to `planned` and ends
    /// a near miss (`best_mismatch` at most `near_miss`) gets another
    /// round of explorations (new streams, same parents) before the next
    /// level is tried.
    fn more_rounds(&self, planned: usize, best_mismatch: u64, near_miss: u64) -> bool {
        planned - self.first < self.n.saturating_mul(1 + self.extra_rounds)
            && best_mismatch <= near_miss
    }
}

/// What an executor gets as the parents of a level from `from`, and
/// whether the level is the descent.
fn executor_parents(from: From<'_>) -> (Vec<Exploration>, bool) {
    match from {
        From::Below(parents) | From::Lifted(parents) => (
            parents
                .iter()
                .map(|(candidate, score)| Exploration {
                    candidate: candidate.clone(),
                    score: *score,
                })
                .collect(),
            false,
        ),
        // The descent's parent is a dissection; explorations read only a
        // parent's labels, never its score.
        From::Above(parent, _) => (
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
    }
}
