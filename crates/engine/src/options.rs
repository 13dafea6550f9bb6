//! Run options: what a front end asks for ([`RunConfig`], plain fields) and
//! the same checked once ([`RunOptions`]); every rule on solver settings
//! lives here.

use std::time::Duration;

use dissect_core::solver::{Anytime, Options};
use dissect_puzzle::constraints::ConstraintError;
use dissect_puzzle::{Constraints, Rank};

use crate::limits::{check_threads, LimitError, TimeLimit};

/// The most explorations per level (bounds the memory a level holds).
pub const MAX_EXPLORATIONS: usize = 1_000_000;
/// The most candidates kept, refinement iterations, split tries and idle
/// rounds.
const MAX_COUNT: usize = 1_000_000;
/// Near misses repaired per level when several solutions are asked for.
const PLATEAU_REPAIR_TRIES: usize = 8;
/// Without a time limit, a run asked for several solutions ends after at
/// least this many rounds in a row without fewer pieces or a new solution.
pub const PLATEAU_IDLE_ROUNDS: usize = 8;
/// The most solutions a run may be asked for (`--solutions`).
pub const MAX_SOLUTIONS: usize = 1000;

/// Which searches a run uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Strategy {
    /// A dissection at once (constructive), then rounds of the level search
    /// for fewer pieces, near misses repaired; with the exact search beside
    /// it when proving.
    Anytime,
    /// Exactly the paper's schedule: levels of 2, 3, ... pieces, ending at
    /// the first level with a valid dissection (with the exact search beside
    /// it when proving).
    Paper,
    /// The SAT search alone, for a minimum dissection.
    Exact,
}

/// The settings of a run as a front end gives them; [`RunOptions::new`]
/// checks them. `Default` is `dissect solve` with no flag.
#[derive(Clone, Debug, PartialEq)]
pub struct RunConfig {
    /// Which searches run.
    pub strategy: Strategy,
    /// Run the exact lower-bound search beside the heuristic.
    pub prove: bool,
    /// Finish near misses by the exact local repair.
    pub repair: bool,
    /// Whether 2D pieces may be turned over.
    pub mirror: bool,
    /// The seed.
    pub seed: u64,
    /// Heuristic worker threads (0: one per core).
    pub threads: usize,
    /// How long the run may last ([`TimeLimit::NONE`]: it ends by its work
    /// rule).
    pub time_limit: TimeLimit,
    /// Never report more pieces than this.
    pub max_pieces: Option<usize>,
    /// `λ` at level 1.
    pub area_weight: f64,
    /// Explorations per level, `N`.
    pub explorations: usize,
    /// Candidates kept per level, `Nb`.
    pub keep: usize,
    /// Refinement iterations, `R`.
    pub iterations: usize,
    /// Objective penalty per disconnected piece.
    pub split_penalty: f64,
    /// Level-1 runs tried when splitting a pair.
    pub split_tries: usize,
    /// Run the whole final level.
    pub full_level: bool,
    /// Extra rounds for a level ending a near miss.
    pub extra_rounds: usize,
    /// Refinement patience (0: the paper's loop).
    pub patience: usize,
    /// Without a time limit, end after this many rounds in a row without
    /// fewer pieces.
    pub idle_rounds: usize,
    /// How many different dissections with the fewest pieces to report
    /// (`--solutions`; 1: the best only). With more than one the heuristic
    /// keeps searching at the fewest piece count (see
    /// [`dissect_core::solver::Anytime::plateau`]).
    pub solutions: usize,
    /// How the solutions are ranked (`--rank`).
    pub rank: Rank,
    /// The designer's constraints every answer honours (`--keep N:FILE`,
    /// `--min-piece`, `--max-piece`, `--checkerboard`, `--symmetry-weight`).
    pub constraints: Constraints,
}

impl Default for RunConfig {
    fn default() -> RunConfig {
        let o = Options::default();
        RunConfig {
            strategy: Strategy::Anytime,
            prove: true,
            repair: true,
            mirror: o.mirror,
            seed: o.seed,
            threads: o.threads,
            time_limit: TimeLimit::NONE,
            max_pieces: None,
            area_weight: o.area_weight,
            explorations: o.explorations,
            keep: o.keep,
            iterations: o.iterations,
            split_penalty: o.split_penalty,
            split_tries: o.split_tries,
            full_level: o.full_levels,
            extra_rounds: o.extra_rounds,
            patience: o.patience,
            idle_rounds: Anytime::default().idle_rounds.unwrap_or(2),
            solutions: 1,
            rank: Rank::default(),
            constraints: Constraints::none(),
        }
    }
}

/// Occurs when a run setting is out of range; the message names the
/// setting as the command line spells it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum OptionsError {
    /// A count outside its range.
    #[error("--{name} must be from {min} to {max}, got {value}")]
    Count {
        /// The setting.
        name: &'static str,
        /// Its value.
        value: usize,
        /// The least allowed.
        min: usize,
        /// The most allowed.
        max: usize,
    },
    /// A number that must be finite (and maybe non-negative) is not.
    #[error("--{name} must be a finite number{}, got {value}", if *.non_negative { " >= 0" } else { "" })]
    Number {
        /// The setting.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Whether it must also be >= 0.
        non_negative: bool,
    },
    /// The thread count is out of range ([`crate::check_threads`]).
    #[error(transparent)]
    Limit(#[from] LimitError),
    /// The constraints are malformed or cannot hold
    /// ([`ConstraintError::is_impossible`] tells which).
    #[error(transparent)]
    Constraints(#[from] ConstraintError),
}

/// Checked run settings (built only by [`RunOptions::new`]).
///
/// # Validity
/// Every count is in its range, `area_weight` is finite and >= 0,
/// `split_penalty` is finite, the thread count passes
/// [`check_threads`], the constraints pass [`Constraints::validate_settings`] (what needs the
/// figures is checked by [`crate::run`]).
#[derive(Clone, Debug, PartialEq)]
pub struct RunOptions {
    config: RunConfig,
}

fn count(name: &'static str, value: usize, min: usize, max: usize) -> Result<(), OptionsError> {
    if value < min || value > max {
        return Err(OptionsError::Count {
            name,
            value,
            min,
            max,
        });
    }
    Ok(())
}

impl RunOptions {
    /// Checks `config`.
    pub fn new(config: RunConfig) -> Result<RunOptions, OptionsError> {
        count("explorations", config.explorations, 1, MAX_EXPLORATIONS)?;
        count("keep", config.keep, 1, MAX_COUNT)?;
        count("iterations", config.iterations, 0, MAX_COUNT)?;
        count("split-tries", config.split_tries, 1, MAX_COUNT)?;
        count("extra-rounds", config.extra_rounds, 0, MAX_COUNT)?;
        count("patience", config.patience, 0, MAX_COUNT)?;
        count("rounds", config.idle_rounds, 0, MAX_COUNT)?;
        check_threads(config.threads)?;
        count("solutions", config.solutions, 1, MAX_SOLUTIONS)?;
        config.constraints.validate_settings()?;
        if let Some(k) = config.max_pieces {
            count("max-pieces", k, 1, usize::MAX)?;
        }
        if !(config.area_weight.is_finite() && config.area_weight >= 0.0) {
            return Err(OptionsError::Number {
                name: "area-weight",
                value: config.area_weight,
                non_negative: true,
            });
        }
        if !config.split_penalty.is_finite() {
            return Err(OptionsError::Number {
                name: "split-penalty",
                value: config.split_penalty,
                non_negative: false,
            });
        }
        Ok(RunOptions { config })
    }

    /// The same options for the figures in another order (the keep
    /// regions follow their figure: figure `f` is `new_of_old[f]` now).
    pub(crate) fn renumbered(&self, new_of_old: &[usize]) -> RunOptions {
        let mut config = self.config.clone();
        config.constraints = config.constraints.renumbered(new_of_old);
        RunOptions { config }
    }

    /// The settings as given.
    pub fn config(&self) -> &RunConfig {
        &self.config
    }

    /// The time limit (`None`: the run ends by its work rule).
    pub fn time_limit(&self) -> Option<Duration> {
        self.config.time_limit.duration()
    }

    /// The seed.
    pub fn seed(&self) -> u64 {
        self.config.seed
    }

    /// The strategy.
    pub fn strategy(&self) -> Strategy {
        self.config.strategy
    }

    /// Whether the run collects solutions (several, ranked, or under
    /// constraints or a symmetry weight) rather than reporting the
    /// heuristic's answer as it is.
    pub fn collects(&self) -> bool {
        let c = &self.config;
        c.solutions > 1
            || c.rank != Rank::default()
            || !c.constraints.is_empty()
            || c.constraints.symmetry_weight() != 0.0
    }

    /// The heuristic solver's settings.
    pub fn solver_options(&self) -> Options {
        let c = &self.config;
        Options {
            mirror: c.mirror,
            seed: c.seed,
            threads: c.threads,
            max_pieces: c.max_pieces,
            area_weight: c.area_weight,
            explorations: c.explorations,
            keep: c.keep,
            iterations: c.iterations,
            split_penalty: c.split_penalty,
            split_tries: c.split_tries,
            // Several solutions: a level that holds a valid dissection is
            // run to its end, for more of them.
            full_levels: c.full_level || c.solutions > 1,
            extra_rounds: c.extra_rounds,
            patience: c.patience,
            ..Options::default()
        }
    }

    /// The anytime schedule's settings: without a time limit the run ends
    /// after `idle_rounds` rounds without improvement; with one, only the
    /// limit (or optimality) ends it.
    pub fn anytime(&self) -> Anytime {
        Anytime {
            idle_rounds: match self.time_limit() {
                // Several solutions: a round that found a new one is no
                // idle round, and more idle rounds are allowed.
                None if self.config.solutions > 1 => {
                    Some(self.config.idle_rounds.max(PLATEAU_IDLE_ROUNDS))
                }
                None => Some(self.config.idle_rounds),
                Some(_) => None,
            },
            plateau: self.config.solutions > 1,
            // Several solutions: more near misses repaired per level.
            repair_tries: if self.config.solutions > 1 {
                PLATEAU_REPAIR_TRIES
            } else {
                Anytime::default().repair_tries
            },
            ..Anytime::default()
        }
    }
}
