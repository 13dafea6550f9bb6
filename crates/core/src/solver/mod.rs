//! The search of Zhou and Wang: levels of random explorations, each refined
//! by copy-paste and label switching, keeping the best candidates per level.
//!
//! Architecture invariant: all randomness comes from [`Options::seed`].
//! Exploration `i` of level `ℓ` draws from its own stream derived from
//! `(seed, ℓ, i)`, explorations run in batches of a fixed size, and results
//! are combined in index order, so the result does not depend on the number
//! of threads (unless the run is stopped early).

pub(crate) mod candidate;
mod explore;
pub(crate) mod flood_fill;
pub(crate) mod levels;
pub(crate) mod refine;
pub(crate) mod shape;

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::distance::Geometry;
use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind};
use candidate::{Candidate, Problem, Score};
use shape::Shape;

pub use explore::{Batch, Executor, Exploration, ExplorationError, Explorer};

/// The most worker threads a search may ask for.
pub const MAX_THREADS: usize = 1024;

/// Solver settings. `Default` gives the paper's constants.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Whether 2D pieces may be turned over (ignored on `cubic`).
    pub mirror: bool,
    /// The seed every random choice derives from.
    pub seed: u64,
    /// Worker threads (0: one per core).
    pub threads: usize,
    /// Give up after levels with this many pieces.
    pub max_pieces: Option<usize>,
    /// `λ` at level 1 (the paper's 0.5); 0 turns the area term off.
    pub area_weight: f64,
    /// Explorations per level, `N` (paper: 400).
    pub explorations: usize,
    /// Candidates kept per level, `Nb` (paper: 30).
    pub keep: usize,
    /// Refinement iterations per exploration, `R` (paper: 100).
    pub iterations: usize,
    /// Added to the objective per disconnected piece.
    pub split_penalty: f64,
    /// Level-1 runs tried when splitting the worst pair; the best is used.
    pub split_tries: usize,
    /// Explorations per batch: a level stops after the first batch that
    /// holds a valid dissection (the same batches for any thread count).
    pub batch: usize,
    /// Run every exploration of the final level even after a valid one is
    /// found (to pick the least area variance among more solutions).
    pub full_levels: bool,
    /// Extra rounds of `explorations` a level gets when its best candidate
    /// is a near miss (see [`Options::near_miss`]); 0 is the paper's schedule.
    pub extra_rounds: usize,
    /// Stop refining an exploration whose conflicting cells have not
    /// improved for this many iterations (0: the paper's loop, which stops
    /// only when nothing changes).
    pub patience: usize,
}

impl Options {
    /// The largest matching cost `E_M` that counts as a near miss: one
    /// misplaced cell (cost 2) per figure pair per 150 cells.
    pub fn near_miss(&self, figures: usize, cells: usize) -> u64 {
        (2 * (figures.max(2) - 1) * cells.div_ceil(150).max(1)) as u64
    }
}

impl Default for Options {
    fn default() -> Options {
        Options {
            mirror: true,
            seed: 1,
            threads: 0,
            max_pieces: None,
            area_weight: 0.5,
            explorations: 400,
            keep: 30,
            iterations: 100,
            split_penalty: 1000.0,
            split_tries: 4,
            batch: 16,
            full_levels: false,
            extra_rounds: 1,
            patience: 20,
        }
    }
}

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
}

/// Receives [`Event`]s (from worker threads).
pub trait Observer: Sync {
    /// Called for every event.
    fn on_event(&self, event: &Event);
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

/// The random stream of exploration `index` at `level`.
fn stream(seed: u64, level: usize, index: usize) -> ChaCha8Rng {
    fn splitmix(mut z: u64) -> u64 {
        z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    ChaCha8Rng::seed_from_u64(splitmix(
        splitmix(seed) ^ ((level as u64) << 40) ^ index as u64,
    ))
}

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

/// Finds a dissection of `figures` into as few connected pieces as it can.
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
    let to_found = |cand: &Candidate, score: &Score, level: usize| -> Found {
        let pieces = cand.cells_by_label(figures);
        Found {
            pieces,
            level,
            variance: score.variance,
        }
    };

    // Level 0: are the figures already congruent?
    observer.on_event(&Event::LevelStarted {
        level: 0,
        pieces: 1,
        explorations: 1,
    });
    let mut whole = Candidate {
        labels: problem.shapes.iter().map(|s| vec![0u16; s.len()]).collect(),
        k: 1,
    };
    let s0 = whole.evaluate(&problem, 0.0, options.split_penalty);
    observer.on_event(&Event::LevelFinished {
        level: 0,
        pieces: 1,
        explorations: 1,
        best_mismatch: s0.mismatch,
        found: s0.valid,
    });
    if s0.valid {
        return Ok(Outcome {
            found: Some(to_found(&whole, &s0, 0)),
            best_mismatch: Some(0),
            last_pieces: 1,
            stopped: false,
            explorations: 1,
        });
    }

    let cells = figures[0].len();
    let max_pieces = options.max_pieces.unwrap_or(cells).min(cells);
    let mut best: Vec<(Candidate, Score)> = Vec::new();
    let mut total_explorations = 0;
    let mut outcome = Outcome {
        found: None,
        best_mismatch: Some(s0.mismatch),
        last_pieces: 1,
        stopped: false,
        explorations: 1,
    };
    for level in 1.. {
        let pieces = level + 1;
        if pieces > max_pieces || stop.load(Ordering::Relaxed) {
            break;
        }
        let n = options.explorations.max(1);
        observer.on_event(&Event::LevelStarted {
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
                let mut g = best_seen.lock().expect("progress lock");
                g.0 = g.0.min(result.1.value);
                g.1 = g.1.min(result.1.mismatch);
                *g
            };
            observer.on_event(&Event::Exploration {
                level,
                done: d,
                total: total.load(Ordering::Relaxed),
                best_score: bs,
                best_mismatch: bm,
            });
        };
        let run_one = |i: usize| -> (Candidate, Score) {
            let result = explore::explore_one(
                &problem,
                options,
                0,
                level,
                i,
                best.len(),
                |p| &best[p].0,
                stop,
            );
            note(&result);
            result
        };
        // What a foreign executor gets as parents (made once per level).
        let parents: Vec<Exploration> = match executor {
            Some(_) => best
                .iter()
                .map(|(candidate, score)| Exploration {
                    candidate: candidate.clone(),
                    score: *score,
                })
                .collect(),
            None => Vec::new(),
        };
        let mut results: Vec<(Candidate, Score)> = Vec::with_capacity(n);
        let batch = options.batch.max(1);
        let near_miss = options.near_miss(figures.len(), cells);
        let mut start = 0;
        let mut planned = n;
        while start < planned {
            let end = (start + batch).min(planned);
            let chunk: Vec<(Candidate, Score)> = match executor {
                None => pool.install(|| (start..end).into_par_iter().map(run_one).collect()),
                Some(ex) => {
                    let batch = Batch {
                        round: 0,
                        level,
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
                        e.check(&problem)?;
                        let result = (e.candidate, e.score);
                        note(&result);
                        chunk.push(result);
                    }
                    chunk
                }
            };
            results.extend(chunk);
            start = end;
            if stop.load(Ordering::Relaxed) {
                outcome.stopped = true;
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
                && planned < n * (1 + options.extra_rounds)
                && best_mismatch <= near_miss
            {
                planned += n;
                total.store(planned, Ordering::Relaxed);
                observer.on_event(&Event::LevelStarted {
                    level,
                    pieces,
                    explorations: planned,
                });
            }
        }
        total_explorations += results.len();
        let found = results.iter().any(|(_, s)| s.valid);
        let best_mismatch = results
            .iter()
            .map(|(_, s)| s.mismatch)
            .min()
            .unwrap_or(u64::MAX);
        observer.on_event(&Event::LevelFinished {
            level,
            pieces,
            explorations: results.len(),
            best_mismatch,
            found,
        });
        outcome.last_pieces = pieces;
        outcome.best_mismatch = Some(best_mismatch);
        outcome.explorations = total_explorations + 1;
        if found {
            let (cand, score) = results
                .iter()
                .filter(|(_, s)| s.valid)
                .min_by(|a, b| {
                    a.1.variance
                        .total_cmp(&b.1.variance)
                        .then(a.1.value.total_cmp(&b.1.value))
                })
                .expect("a valid result");
            outcome.found = Some(to_found(cand, score, level));
            return Ok(outcome);
        }
        if outcome.stopped || results.is_empty() {
            break;
        }
        // Keep the Nb best (stable: ties keep exploration order).
        let mut order: Vec<usize> = (0..results.len()).collect();
        order.sort_by(|&a, &b| {
            results[a]
                .1
                .value
                .total_cmp(&results[b].1.value)
                .then(a.cmp(&b))
        });
        order.truncate(options.keep.max(1));
        let mut slots: Vec<Option<(Candidate, Score)>> = results.into_iter().map(Some).collect();
        best = order
            .into_iter()
            .map(|i| slots[i].take().expect("each index once"))
            .collect();
    }
    outcome.stopped |= stop.load(Ordering::Relaxed);
    Ok(outcome)
}
