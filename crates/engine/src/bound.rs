//! `bound`: the exact search's lower bound on the number of pieces, under
//! the engine's time limit and stop flag (the operation behind `dissect
//! bound` and Python's `dissect.bound`).
//!
//! The search runs on a thread of its own; the monitor ends the operation
//! within a poll of the deadline or the stop flag, waits a moment for the
//! search to return, and otherwise answers with the best bound its events
//! announced (parts of the search, such as the cheap bounds on huge
//! figures, look at the flag only now and then).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{channel, Receiver};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use dissect_core::Figure;
use dissect_exact::{search, ExactEvent, ExactOptions, ExactOutcome, Limit, Mode};

use crate::limits::TimeLimit;
use crate::monitor::{monitor, Watch};
use crate::report::{End, LowerBound};
use crate::run::{proof, EngineError, EngineEvent, EngineObserver, Forward};
use crate::verified::Verified;

/// The largest SAT encoding a bound builds (estimated bytes; the search's
/// default is 512 MiB): 1.5 GiB, so that a bound with its encoding, the
/// solver's learnt clauses and the rest of the process stays under 2 GiB
/// (the shift chain keeps 3D pairs of 1,000 voxels well inside it).
const BOUND_MAX_BYTES: u64 = 1536 << 20;

/// How long a stopped bound waits for the search to return.
const BOUND_GRACE: Duration = Duration::from_millis(300);

/// The settings of a bound.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundConfig {
    /// Whether 2D pieces may be turned over.
    pub mirror: bool,
    /// Try to refute no more than this many pieces.
    pub max_pieces: Option<usize>,
    /// How long the bound may take.
    pub time_limit: TimeLimit,
    /// Record every refutation's formula and DRAT proof (sent as
    /// [`ExactEvent::Certified`]).
    pub certify: bool,
    /// With `certify`: where the cubes' DRAT proofs are written as the
    /// solvers go (see `dissect_exact::ExactOptions::cube_proofs`).
    pub cube_proofs: Option<dissect_exact::ProofSink>,
    /// Threads for cube-and-conquer on each SAT question (1: one solver;
    /// see `dissect_exact::ExactOptions::cube_threads`).
    pub threads: usize,
}

impl Default for BoundConfig {
    fn default() -> BoundConfig {
        BoundConfig {
            mirror: true,
            max_pieces: None,
            time_limit: TimeLimit::NONE,
            certify: false,
            cube_proofs: None,
            threads: 1,
        }
    }
}

/// What a bound proved.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct BoundReport {
    /// The best lower bound proved.
    pub lower_bound: LowerBound,
    /// A verified dissection the search found (then the bound is optimal).
    pub found: Option<Verified>,
    /// Why it ended: [`End::Finished`] (the search ended by itself),
    /// [`End::TimeLimit`] or [`End::Interrupted`].
    pub end: End,
    /// The encoding that was too large, if that ended the search: its
    /// piece count and estimated bytes, and the cap.
    pub too_large: Option<(usize, u64, u64)>,
    /// The cells of the largest figure when it is over the exact search's
    /// size (`dissect_exact::bound::SAT_MAX_CELLS`): no SAT search
    /// ran, the bound is the cheap one.
    pub too_many_cells: Option<usize>,
    /// Seconds from the start.
    pub seconds: f64,
}

impl BoundConfig {
    /// Whether pieces may be turned over in this bound of `figures`
    /// (`mirror`, where their lattice allows it).
    pub(crate) fn mirror_for(&self, figures: &[Figure]) -> bool {
        self.mirror
            && figures
                .first()
                .is_none_or(|f| f.lattice().lattice().supports_mirror())
    }
}

impl BoundReport {
    /// A report of `lower_bound` and nothing else yet (finished, no
    /// dissection, no limit met).
    pub(crate) fn new(lower_bound: LowerBound) -> BoundReport {
        BoundReport {
            lower_bound,
            found: None,
            end: End::Finished,
            too_large: None,
            too_many_cells: None,
            seconds: 0.0,
        }
    }

    /// Whether the bound was cut short (time limit, stop, or an encoding
    /// too large).
    pub fn stopped(&self) -> bool {
        self.end != End::Finished || self.too_large.is_some()
    }
}

/// Proves a lower bound on the pieces of a dissection of `figures` (named
/// `names`), within `config.time_limit` and until `stop` is raised; the
/// exact search's events go to `observer` as [`EngineEvent::Exact`].
pub fn bound(
    figures: &[Figure],
    names: &[String],
    config: &BoundConfig,
    stop: &AtomicBool,
    observer: &dyn EngineObserver,
) -> Result<BoundReport, EngineError> {
    let start = Instant::now();
    let deadline = config.time_limit.deadline_from(start);
    let mirror = config.mirror_for(figures);
    let options = ExactOptions {
        mirror,
        mode: Mode::LowerBound,
        deadline,
        max_pieces: config.max_pieces,
        certify: config.certify,
        cube_proofs: config.cube_proofs.clone(),
        max_encoding_bytes: BOUND_MAX_BYTES,
        sat_max_cells: dissect_exact::bound::SAT_MAX_CELLS,
        cube_threads: config.threads.max(1),
        ..ExactOptions::default()
    };
    let cap = options.max_encoding_bytes;
    let search_stop = Arc::new(AtomicBool::new(false));
    let (tx, events) = channel::<ExactEvent>();
    let thread = {
        let figures = figures.to_vec();
        let stop = Arc::clone(&search_stop);
        let forward = Forward(Mutex::new(tx));
        std::thread::spawn(move || {
            let upper = AtomicUsize::new(usize::MAX);
            search(&figures, &options, &stop, &upper, &forward)
        })
    };
    let mut best = Best::new(names);
    let watch = monitor(stop, deadline, || {
        best.drain(&events, observer);
        thread.is_finished().then_some(())
    });
    search_stop.store(true, Ordering::SeqCst);
    let grace = Instant::now() + BOUND_GRACE;
    while !thread.is_finished() && Instant::now() < grace {
        std::thread::sleep(Duration::from_millis(2));
    }
    best.drain(&events, observer);
    let outcome: Option<ExactOutcome> = if thread.is_finished() {
        Some(thread.join().expect("bound thread")?)
    } else {
        None
    };
    let end = match watch {
        Watch::Stopped(end) => end,
        Watch::Ended(()) => End::Finished,
    };
    let mut report = BoundReport {
        lower_bound: best.lower,
        found: None,
        end,
        too_large: None,
        too_many_cells: None,
        seconds: 0.0,
    };
    if let Some(o) = outcome {
        if o.lower_bound.value >= report.lower_bound.value {
            report.lower_bound = LowerBound {
                value: o.lower_bound.value,
                reason: o.lower_bound.describe(names),
                proof: proof(&o.lower_bound, names),
            };
        }
        match o.limit {
            Some(Limit::TooLarge { pieces, bytes }) => {
                report.too_large = Some((pieces, bytes, cap))
            }
            Some(Limit::Cells { cells }) => report.too_many_cells = Some(cells),
            _ => {}
        }
        if let Some(pieces) = o.found {
            report.found = Some(verified_sat(figures, names, mirror, pieces)?);
        }
    }
    report.seconds = start.elapsed().as_secs_f64();
    Ok(report)
}

/// The dissection a SAT model stands for (`pieces[f][i]`, input order),
/// verified.
pub(crate) fn verified_sat(
    figures: &[Figure],
    names: &[String],
    mirror: bool,
    pieces: Vec<Vec<Vec<dissect_core::Cell>>>,
) -> Result<Verified, EngineError> {
    Verified::new(
        figures[0].lattice(),
        mirror,
        names.to_vec(),
        figures,
        pieces,
    )
    .map_err(|e| EngineError::Unverified("SAT", e))
}

/// The best bound the search's events announced.
struct Best<'n> {
    names: &'n [String],
    lower: LowerBound,
}

impl<'n> Best<'n> {
    fn new(names: &'n [String]) -> Best<'n> {
        let piece = "every dissection has a piece".to_string();
        Best {
            names,
            lower: LowerBound {
                value: 1,
                reason: piece.clone(),
                proof: piece,
            },
        }
    }

    /// Takes the search's events (on the caller's thread): a bound that
    /// rose is kept, and every event goes to `observer`.
    fn drain(&mut self, events: &Receiver<ExactEvent>, observer: &dyn EngineObserver) {
        while let Ok(e) = events.try_recv() {
            if let ExactEvent::CheapBound(b) | ExactEvent::Refuted(b) = &e {
                if b.value > self.lower.value {
                    self.lower = LowerBound {
                        value: b.value,
                        reason: b.describe(self.names),
                        proof: proof(b, self.names),
                    };
                }
            }
            observer.on_event(&EngineEvent::Exact(&e));
        }
    }
}
