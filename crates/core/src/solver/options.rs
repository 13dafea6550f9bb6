//! [`Options`]: the solver's settings, the paper's constants by default.

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
