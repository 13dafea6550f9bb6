//! What one studio server accepts: the caps that keep a request from taking
//! the machine.

/// Limits on requests and solves.
///
/// # Validity
/// Every field is at least 1 (`max_time_limit` is positive); [`Limits::new`]
/// clamps zeroes up so the server always accepts something.
#[derive(Clone, Debug, PartialEq)]
pub struct Limits {
    max_cells: usize,
    max_extent: i32,
    max_figures: usize,
    max_concurrent_solves: usize,
    max_time_limit: f64,
    threads: usize,
    max_concurrent_pictures: usize,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            max_cells: 2_500,
            max_extent: 128,
            max_figures: 8,
            max_concurrent_solves: 2,
            max_time_limit: 600.0,
            threads: 0,
            max_concurrent_pictures: 2,
        }
    }
}

impl Limits {
    /// Limits with the given caps.
    ///
    /// * `max_cells`: cells per figure;
    /// * `max_extent`: the largest coordinate (and smallest, negated) a cell may have;
    /// * `max_figures`: figures per request;
    /// * `max_concurrent_solves`: solves running at once (more get HTTP 429);
    /// * `max_time_limit`: seconds; every solve stops by then;
    /// * `threads`: worker threads per solve (0: one per core).
    pub fn new(
        max_cells: usize,
        max_extent: i32,
        max_figures: usize,
        max_concurrent_solves: usize,
        max_time_limit: f64,
        threads: usize,
    ) -> Limits {
        Limits {
            max_cells: max_cells.max(1),
            max_extent: max_extent.max(1),
            max_figures: max_figures.max(2),
            max_concurrent_solves: max_concurrent_solves.max(1),
            max_time_limit: if max_time_limit.is_finite() && max_time_limit > 0.0 {
                max_time_limit
            } else {
                Limits::default().max_time_limit
            },
            threads,
            max_concurrent_pictures: Limits::default().max_concurrent_pictures,
        }
    }

    /// The same limits with at most `n` (at least 1) pictures made at once
    /// (rasterizations and picture downloads; more get HTTP 429).
    pub fn with_max_concurrent_pictures(mut self, n: usize) -> Limits {
        self.max_concurrent_pictures = n.max(1);
        self
    }

    /// Pictures made at once.
    pub fn max_concurrent_pictures(&self) -> usize {
        self.max_concurrent_pictures
    }

    /// Cells per figure.
    pub fn max_cells(&self) -> usize {
        self.max_cells
    }

    /// The largest absolute coordinate of a cell.
    pub fn max_extent(&self) -> i32 {
        self.max_extent
    }

    /// Figures per request.
    pub fn max_figures(&self) -> usize {
        self.max_figures
    }

    /// Solves running at once.
    pub fn max_concurrent_solves(&self) -> usize {
        self.max_concurrent_solves
    }

    /// The longest time limit, in seconds (also the default).
    pub fn max_time_limit(&self) -> f64 {
        self.max_time_limit
    }

    /// Worker threads per solve (0: one per core).
    pub fn threads(&self) -> usize {
        self.threads
    }
}
