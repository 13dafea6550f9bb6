//! The search of Zhou and Wang: levels of random explorations, each refined
//! by copy-paste and label switching, keeping the best candidates per level.
//!
//! Architecture invariant: all randomness comes from [`Options::seed`].
//! Exploration `i` of level `ℓ` draws from its own stream derived from
//! `(seed, ℓ, i)`, explorations run in batches of a fixed size, and results
//! are combined in index order, so the result does not depend on the number
//! of threads (unless the run is stopped early).
//!
//! This file holds the vocabulary (events, observer, outcome, errors); the
//! steps live in files named after them: `search` (one level), `paper`
//! (the paper's schedule), `anytime` (the anytime rounds), `plateau`
//! (several solutions), `incumbent` (keep-best).

pub(crate) mod anytime;
pub(crate) mod candidate;
pub(crate) mod coarse;
pub(crate) mod distance;
mod explore;
pub(crate) mod flood_fill;
pub(crate) mod greedy;
pub(crate) mod guillotine;
mod incumbent;
pub(crate) mod levels;
mod lookahead;
pub(crate) mod matching;
mod options;
mod paper;
pub(crate) mod piece;
mod plateau;
pub(crate) mod refine;
pub(crate) mod regroup;
mod search;
pub(crate) mod sectors;
pub(crate) mod shape;

use std::sync::atomic::AtomicBool;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind};
use crate::solver::distance::Geometry;
use candidate::Problem;
use shape::Shape;

pub use anytime::{solve_anytime, solve_anytime_with, Anytime};
pub use explore::{Batch, Executor, Exploration, ExplorationError, Explorer};
pub use options::Options;
pub use paper::{solve, solve_with};
#[cfg(test)]
pub(crate) use search::{Level, Search};

/// The most worker threads a search may ask for (every front end checks
/// it through `dissect_engine::check_threads`).
pub const MAX_THREADS: usize = 256;

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
    /// An exploration finished, on the thread that ran it. Explorations
    /// the pool ran ahead of the batch that decided the level (dropped, so
    /// not counted in [`Outcome::explorations`]) are reported too: this is
    /// the work done, `done` capped at `total`.
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
        /// The cells of its smallest piece.
        smallest: usize,
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
    /// One large common piece, the rest dissected exactly sector by sector.
    Sectors,
    /// A few touching pieces of the best dissection cut again, exactly,
    /// with fewer pieces.
    Regroup,
    /// The tail of a dissection cut again by a randomized greedy, its
    /// largest pieces kept.
    Rebuild,
    /// Figures of a few boxes cut into boxes by guillotine cuts.
    Boxes,
}

impl Via {
    /// A short name: `greedy`, `search`, `repair`, `coarse`, `sectors`,
    /// `regroup`, `rebuild`, `boxes`.
    pub fn name(self) -> &'static str {
        match self {
            Via::Greedy => "greedy",
            Via::Search => "search",
            Via::Repair => "repair",
            Via::Coarse => "coarse",
            Via::Sectors => "sectors",
            Via::Regroup => "regroup",
            Via::Rebuild => "rebuild",
            Via::Boxes => "boxes",
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
    /// A valid dissection the observer had not seen and wanted (several
    /// solutions): with [`Anytime::plateau`] a round that meets one
    /// counts as progress, not as an idle round.
    pub fresh: bool,
}

impl Default for Judgement {
    fn default() -> Judgement {
        Judgement {
            accept: true,
            penalty: 0.0,
            fresh: false,
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

    /// The cells of the smallest piece (0 for none).
    pub fn smallest(&self) -> usize {
        self.pieces
            .first()
            .and_then(|p| p.iter().map(Vec::len).min())
            .unwrap_or(0)
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

/// Stream levels of the descent are kept apart from the ladder's.
pub(crate) const DESCENT: usize = 1 << 20;

/// Stream level of the tail rebuilds ([`anytime`]).
pub(crate) const REBUILD: usize = 1 << 21;

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

/// Finishes near misses: given a candidate that is a few cells from a
/// dissection, returns a valid dissection with at most as many pieces, or
/// `None`. (The core cannot depend on the exact search; the engine plugs
/// it in.)
pub trait Repair: Sync {
    /// `pieces[f][i]`: the cells of piece `i` in figure `f` of a candidate
    /// whose pieces nearly match (labels aligned to figure 0). The answer
    /// has the same shape. Raising `stop` should end the repair soon.
    fn repair(&self, pieces: &[Vec<Vec<Cell>>], stop: &AtomicBool) -> Option<Vec<Vec<Vec<Cell>>>>;

    /// An exact dissection of small figures (`figures[f]`: the cells of
    /// figure `f`, equal in number; they need not be connected) with at
    /// most `max_pieces` pieces, as few as the hook can find, and among
    /// those none of fewer than three cells when that is possible:
    /// `pieces[f][i]`, or `None` when it finds none within its budget. Used
    /// for the sectors of large figures (one large common piece aside). The
    /// default finds none.
    fn dissect(
        &self,
        figures: &[Vec<Cell>],
        max_pieces: usize,
        stop: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        let _ = (figures, max_pieces, stop);
        None
    }

    /// [`Repair::dissect`] for the groups of pieces of a dissection that
    /// the anytime search's regrouping hands over: their
    /// unions, to be cut with at most `max_pieces` pieces. The default is
    /// [`Repair::dissect`]; an implementation may give it a budget of its
    /// own.
    fn regroup(
        &self,
        figures: &[Vec<Cell>],
        max_pieces: usize,
        stop: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        self.dissect(figures, max_pieces, stop)
    }
}
