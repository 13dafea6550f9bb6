//! One run: the heuristic and the exact search side by side, the deadline,
//! the stop flag, and the report.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{channel, Sender};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use dissect_core::solver::{
    solve_anytime_with, solve_with, Event, Executor, Judgement, Observer, Outcome, Repair,
    SolveError, Via,
};
use dissect_core::{Cell, Figure};
use dissect_exact::{
    search, Bound, ExactError, ExactEvent, ExactObserver, ExactOptions, ExactOutcome, Mode, Reason,
    RepairOptions,
};
use dissect_puzzle::constraints::ConstraintError;
use dissect_puzzle::{Added, Collection, Constraints, Motions};

use crate::options::{RunOptions, Strategy};
use crate::report::{End, Improvement, LowerBound, Ranking, Report, Solution, Source};
use crate::verified::Verified;

/// The exact search runs beside the heuristic only on figures of at most
/// this many cells: its encoding grows with cells × placements, and larger
/// figures would spend memory and a core on a formula it cannot solve.
pub const PROVE_MAX_CELLS: usize = 600;

/// SAT conflicts the exact side may spend in a run without a time limit.
pub const EXACT_BUDGET: u64 = 100_000;

/// The largest SAT encoding the exact side may build (bytes).
const EXACT_MAX_BYTES: u64 = 256 << 20;

/// How long a stopped run waits for the exact side to return.
const EXACT_GRACE: Duration = Duration::from_millis(300);

/// With a time limit, the share of it at its end that goes to the polish
/// when the answer has a sliver.
pub const POLISH_SHARE: f64 = 0.15;

/// No polish within a time limit shorter than this share leaves.
const POLISH_LEAST: Duration = Duration::from_millis(500);

/// SAT conflicts one repair of a near miss may spend (deterministic work).
pub const REPAIR_BUDGET: u64 = 4_000;

/// Added to a candidate's objective per unit of its distance to the keep
/// regions and size bounds ([`Constraints::distance`]): a split region or
/// a cell out of bounds weighs as much as four mismatched cells in each of
/// two figures, so the candidates a level keeps lean towards the
/// constraints.
pub const CONSTRAINT_PENALTY: f64 = 8.0;

/// The most dissections a puzzle run keeps at its fewest piece count.
const MAX_COLLECTED: usize = 4096;

/// How long `--rank unique` may count the assemblies of one figure.
pub const COUNT_TIME: Duration = Duration::from_secs(5);

/// Live news of a run.
#[derive(Debug)]
#[non_exhaustive]
pub enum EngineEvent<'a> {
    /// Progress of the level search.
    Search(&'a Event),
    /// Progress of the exact search.
    Exact(&'a ExactEvent),
    /// A dissection with fewer pieces than any before.
    Improved(Improvement),
    /// The lower bound rose.
    LowerBound(&'a LowerBound),
    /// A puzzle run kept a new different dissection with the fewest pieces.
    Collected {
        /// Its piece count (the fewest so far).
        pieces: usize,
        /// How many different ones with that count are kept now.
        count: usize,
        /// Seconds from the start of the run.
        seconds: f64,
    },
}

/// Receives [`EngineEvent`]s (from worker threads).
pub trait EngineObserver: Sync {
    /// Called for every event.
    fn on_event(&self, event: &EngineEvent<'_>);
}

impl EngineObserver for () {
    fn on_event(&self, _event: &EngineEvent<'_>) {}
}

/// Occurs when a run cannot be done.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum EngineError {
    /// The figures are not a dissection problem (fewer than two, mixed
    /// lattices, unequal areas, too large), or threads cannot start.
    #[error(transparent)]
    Figures(#[from] SolveError),
    /// The exact search failed.
    #[error(transparent)]
    Exact(#[from] ExactError),
    /// A search produced a dissection the verifier rejects (a bug).
    #[error("internal error: the {0} dissection failed verification: {1}")]
    Unverified(&'static str, String),
    /// The constraints do not fit the figures (a figure number out of
    /// range, no checkerboard on the lattice) or cannot hold for them
    /// ([`ConstraintError::is_impossible`]).
    #[error(transparent)]
    Constraints(#[from] ConstraintError),
}

/// The judge of a puzzle run: the constraints every answer honours, and
/// the collection of the different valid dissections with the fewest
/// pieces.
struct Judge {
    motions: Motions,
    constraints: Constraints,
    /// Whether the constraints steer the search (keep regions, sizes).
    steer: bool,
    collection: Mutex<Collection>,
    /// Solutions asked for: a new one up to this many is fresh (progress
    /// for the run's work rule).
    wanted: usize,
}

impl Judge {
    /// Offers a valid dissection to the collection (skipped past
    /// `MAX_COLLECTED` at the same count); `Some((pieces, count))` when it
    /// was kept.
    fn collect(&self, pieces: &[Vec<Vec<Cell>>]) -> Option<(usize, usize)> {
        let mut c = self.collection.lock().unwrap_or_else(|e| e.into_inner());
        let n = pieces.first().map_or(0, Vec::len);
        if c.len() < MAX_COLLECTED || c.fewest().is_some_and(|k| n < k) {
            if let Added::New | Added::Fewer = c.add(pieces.to_vec()) {
                return Some((n, c.len()));
            }
        }
        None
    }

    /// The number of different dissections kept.
    fn collected(&self) -> usize {
        self.collection
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .len()
    }
}

/// What both sides share while the run lasts.
struct Shared<'a> {
    start: Instant,
    names: &'a [String],
    observer: &'a dyn EngineObserver,
    /// The best piece count of each side (`usize::MAX`: none yet).
    heuristic_best: AtomicUsize,
    sat_best: AtomicUsize,
    /// The cells of the smallest piece of the heuristic's best.
    heuristic_smallest: AtomicUsize,
    /// The best piece count known to either side, for the exact search.
    upper: Arc<AtomicUsize>,
    lower: Mutex<LowerBound>,
    lower_value: AtomicUsize,
    history: Mutex<Vec<Improvement>>,
    /// Present in a puzzle run ([`RunOptions::collects`]).
    judge: Option<Judge>,
}

impl Shared<'_> {
    fn seconds(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    /// Notes a dissection of `pieces` pieces; an improvement when it has
    /// fewer than any before.
    fn found(&self, pieces: usize, source: Source) {
        let side = match source {
            Source::Sat => &self.sat_best,
            _ => &self.heuristic_best,
        };
        side.fetch_min(pieces, Ordering::SeqCst);
        self.upper.fetch_min(pieces, Ordering::SeqCst);
        let improvement = {
            let mut h = self.history.lock().unwrap_or_else(|e| e.into_inner());
            if h.last().is_some_and(|l| l.pieces <= pieces) {
                return;
            }
            let i = Improvement {
                pieces,
                seconds: self.seconds(),
                source,
            };
            h.push(i);
            i
        };
        self.observer.on_event(&EngineEvent::Improved(improvement));
    }

    /// [`Shared::found`] for the heuristic's dissection, whose smallest
    /// piece has `smallest` cells.
    fn found_by_heuristic(&self, pieces: usize, smallest: usize, source: Source) {
        if pieces <= self.heuristic_best.load(Ordering::SeqCst) {
            self.heuristic_smallest.store(smallest, Ordering::SeqCst);
        }
        self.found(pieces, source);
    }

    fn raise_lower(&self, value: usize, reason: impl FnOnce() -> (String, String)) {
        let bound = {
            let mut l = self.lower.lock().unwrap_or_else(|e| e.into_inner());
            if value <= l.value {
                return;
            }
            let (reason, proof) = reason();
            *l = LowerBound {
                value,
                reason,
                proof,
            };
            self.lower_value.store(value, Ordering::SeqCst);
            l.clone()
        };
        self.observer.on_event(&EngineEvent::LowerBound(&bound));
    }
}

impl Observer for Shared<'_> {
    fn on_event(&self, event: &Event) {
        match event {
            Event::LevelFinished {
                level: 0,
                found: false,
                ..
            } => self.raise_lower(2, || {
                let r = "the figures are not congruent".to_string();
                (r.clone(), r)
            }),
            Event::Improved {
                pieces,
                smallest,
                via,
                ..
            } => self.found_by_heuristic(
                *pieces,
                *smallest,
                match via {
                    Via::Greedy => Source::Greedy,
                    Via::Repair => Source::Repair,
                    Via::Coarse => Source::Coarse,
                    Via::Sectors => Source::Sectors,
                    _ => Source::Search,
                },
            ),
            _ => {}
        }
        self.observer.on_event(&EngineEvent::Search(event));
    }

    fn judges(&self) -> bool {
        self.judge.is_some()
    }

    /// Steers by the distance to the keep regions and size bounds, refuses
    /// a dissection that breaks a constraint, and collects the others.
    fn judge(&self, pieces: &[Vec<Vec<Cell>>], valid: bool) -> Judgement {
        let Some(j) = &self.judge else {
            return Judgement::default();
        };
        let penalty = if j.steer {
            CONSTRAINT_PENALTY * j.constraints.distance(pieces) as f64
        } else {
            0.0
        };
        if !valid {
            return Judgement {
                accept: true,
                penalty,
                fresh: false,
            };
        }
        let accept = j.constraints.check(&j.motions, pieces).is_empty();
        let mut fresh = false;
        if accept {
            if let Some((pieces, count)) = j.collect(pieces) {
                fresh = count <= j.wanted;
                self.observer.on_event(&EngineEvent::Collected {
                    pieces,
                    count,
                    seconds: self.seconds(),
                });
            }
        }
        Judgement {
            accept,
            penalty,
            fresh,
        }
    }
}

/// The exact search's events, sent to the thread that owns the run (the
/// exact search runs on a thread of its own that a stop does not wait for:
/// parts of it, such as the cheap bound, do not look at the stop flag).
struct Forward(Mutex<Sender<ExactEvent>>);

impl ExactObserver for Forward {
    fn on_event(&self, event: &ExactEvent) {
        let _ = self
            .0
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .send(event.clone());
    }
}

impl ExactObserver for Shared<'_> {
    fn on_event(&self, event: &ExactEvent) {
        match event {
            ExactEvent::CheapBound(b) | ExactEvent::Refuted(b) => {
                self.raise_lower(b.value, || (b.describe(self.names), proof(b, self.names)))
            }
            ExactEvent::Found { pieces, .. } => self.found(*pieces, Source::Sat),
            _ => {}
        }
        self.observer.on_event(&EngineEvent::Exact(event));
    }
}

/// Runs `options` on `figures` (named `names` in the answer, input order).
///
/// The run ends when the best dissection meets the lower bound, at the
/// time limit, when `stop` is raised, or when both sides ended by their
/// work rules: the heuristic after [`RunConfig::idle_rounds`](crate::RunConfig)
/// rounds without improvement (or the paper's first valid level), the
/// exact side after `EXACT_BUDGET` SAT conflicts (no time limit) or
/// when its bound meets the best dissection.
/// The answer is the dissection with the fewest pieces; on a tie the
/// heuristic's, so that without a time limit the same seed gives the same
/// answer on any machine and for any thread count.
pub fn run(
    figures: &[Figure],
    names: &[String],
    options: &RunOptions,
    stop: &AtomicBool,
    observer: &dyn EngineObserver,
) -> Result<Report, EngineError> {
    run_with(figures, names, options, stop, observer, None)
}

/// Checks what [`run`] checks before it starts: the figures make a
/// dissection problem and the options' constraints fit them (a figure
/// number in range, a checkerboard on the lattice) and are not impossible
/// on their face ([`ConstraintError::is_impossible`]). A front end calls it
/// to refuse a request at once rather than fail a started run.
pub fn check(figures: &[Figure], options: &RunOptions) -> Result<(), EngineError> {
    dissect_core::solver::check_figures(figures)?;
    options.config().constraints.validate(figures)?;
    Ok(())
}

/// [`run`], with the heuristic's explorations run by `executor` (`None`:
/// the local thread pool; `dissect.ray` sends them to a Ray cluster). An
/// executor that returns what [`dissect_core::solver::Explorer::explore`]
/// returns gives the same answer as [`run`].
pub fn run_with(
    figures: &[Figure],
    names: &[String],
    options: &RunOptions,
    stop: &AtomicBool,
    observer: &dyn EngineObserver,
    executor: Option<&dyn Executor>,
) -> Result<Report, EngineError> {
    check(figures, options)?;
    let config = options.config();
    let constraints = &config.constraints;
    let lattice = figures[0].lattice();
    let mirror = config.mirror && lattice.lattice().supports_mirror();
    let motions = Motions::new(lattice, mirror);
    let names: Vec<String> = (0..figures.len())
        .map(|i| {
            names
                .get(i)
                .cloned()
                .unwrap_or_else(|| format!("figure {i}"))
        })
        .collect();
    let start = Instant::now();
    let deadline = options.time_limit().and_then(|d| start.checked_add(d));
    let shared = Shared {
        start,
        names: &names,
        observer,
        heuristic_best: AtomicUsize::new(usize::MAX),
        sat_best: AtomicUsize::new(usize::MAX),
        heuristic_smallest: AtomicUsize::new(usize::MAX),
        upper: Arc::new(AtomicUsize::new(usize::MAX)),
        lower: Mutex::new(LowerBound {
            value: 1,
            reason: "every dissection has a piece".to_string(),
            proof: "every dissection has a piece".to_string(),
        }),
        lower_value: AtomicUsize::new(1),
        history: Mutex::new(Vec::new()),
        judge: options.collects().then(|| Judge {
            motions: motions.clone(),
            constraints: constraints.clone(),
            steer: !constraints.keep().is_empty()
                || constraints.min_piece().is_some()
                || constraints.max_piece().is_some(),
            collection: Mutex::new(Collection::new(motions.clone(), constraints.clone())),
            wanted: config.solutions,
        }),
    };
    let wanted = config.solutions;
    let strategy = options.strategy();
    let heuristic_on = strategy != Strategy::Exact;
    let exact_on =
        strategy == Strategy::Exact || (config.prove && figures[0].len() <= PROVE_MAX_CELLS);
    let heuristic_stop = AtomicBool::new(false);
    let exact_stop = Arc::new(AtomicBool::new(false));
    let heuristic_done = AtomicBool::new(!heuristic_on);
    let solver_options = options.solver_options();
    let anytime = options.anytime();
    let exact_options = ExactOptions {
        mirror,
        mode: if strategy == Strategy::Exact {
            Mode::Minimum
        } else {
            Mode::LowerBound
        },
        max_pieces: config.max_pieces,
        // Without a time limit the exact side beside the heuristic counts
        // its work (SAT conflicts), so what it proves and finds is the same
        // on every machine; the run waits for it.
        conflict_budget: (deadline.is_none() && strategy != Strategy::Exact)
            .then_some(EXACT_BUDGET),
        max_encoding_bytes: EXACT_MAX_BYTES,
        constraints: (!constraints.is_empty()).then(|| constraints.clone()),
        ..ExactOptions::default()
    };
    let exact_repair = crate::repair::ExactRepair::new(
        figures,
        RepairOptions {
            mirror,
            deadline,
            budget: REPAIR_BUDGET,
            ..RepairOptions::default()
        },
    );
    let repairer: Option<&dyn Repair> = config.repair.then_some(&exact_repair as &dyn Repair);

    if deadline.is_some_and(|d| Instant::now() >= d) {
        // No time at all: stop before anything starts.
        heuristic_stop.store(true, Ordering::SeqCst);
        exact_stop.store(true, Ordering::SeqCst);
    }
    // The exact side: on a thread of its own, with its own copies, its
    // events forwarded to this thread.
    let (events_tx, events) = channel::<ExactEvent>();
    let exact = exact_on.then(|| {
        let figures = figures.to_vec();
        let stop = Arc::clone(&exact_stop);
        let upper = Arc::clone(&shared.upper);
        let forward = Forward(Mutex::new(events_tx));
        let options = exact_options.clone();
        std::thread::spawn(move || search(&figures, &options, &stop, &upper, &forward))
    });
    let exact_done = || exact.as_ref().is_none_or(|t| t.is_finished());
    let drain = || {
        while let Ok(e) = events.try_recv() {
            ExactObserver::on_event(&shared, &e);
        }
    };
    // The polish (below) of an answer with a sliver: figures it can take,
    // and with a time limit the instant from which it takes over.
    let polishable = strategy == Strategy::Anytime
        && shared.judge.is_none()
        && figures[0].len() <= PROVE_MAX_CELLS;
    let polish_from = options
        .time_limit()
        .map(|t| t.mul_f64(POLISH_SHARE))
        .filter(|r| polishable && *r >= POLISH_LEAST)
        .and_then(|r| deadline.map(|d| d - r));
    let mut polish_early = false;
    let mut end = End::Finished;
    let heuristic = std::thread::scope(|s| {
        let heuristic = heuristic_on.then(|| {
            s.spawn(|| {
                let r = match strategy {
                    Strategy::Paper => {
                        solve_with(figures, &solver_options, &heuristic_stop, &shared, executor)
                    }
                    _ => solve_anytime_with(
                        figures,
                        &solver_options,
                        &anytime,
                        &heuristic_stop,
                        &shared,
                        repairer,
                        executor,
                    ),
                };
                heuristic_done.store(true, Ordering::SeqCst);
                r
            })
        });
        loop {
            drain();
            if stop.load(Ordering::SeqCst) {
                end = End::Interrupted;
                break;
            }
            if deadline.is_some_and(|d| Instant::now() >= d) {
                end = End::TimeLimit;
                break;
            }
            // The last part of a time limit goes to the polish when the
            // heuristic's answer (the better one) has a sliver.
            if polish_from.is_some_and(|t| Instant::now() >= t)
                && shared.heuristic_smallest.load(Ordering::SeqCst) < SLIVER_CELLS
                && shared.heuristic_best.load(Ordering::SeqCst)
                    <= shared.sat_best.load(Ordering::SeqCst)
                && !heuristic_done.load(Ordering::SeqCst)
            {
                end = End::TimeLimit;
                polish_early = true;
                break;
            }
            let lower = shared.lower_value.load(Ordering::SeqCst);
            let h = shared.heuristic_best.load(Ordering::SeqCst);
            let x = shared.sat_best.load(Ordering::SeqCst);
            // Without a time limit only the heuristic's answer ends the run
            // early (on a tie it is the answer), so the answer does not
            // depend on how fast the exact side is.
            let best = if deadline.is_some() || !heuristic_on {
                h.min(x)
            } else {
                h
            };
            // A run that does not prove (no exact side) goes on to its own
            // end: the paper's `--full-level` keeps looking.
            // Several solutions: optimal only ends the run once enough
            // different ones are collected.
            let enough = wanted <= 1
                || shared
                    .judge
                    .as_ref()
                    .is_some_and(|j| j.collected() >= wanted);
            if best <= lower && exact_on && enough {
                end = End::Optimal;
                break;
            }
            let h_done = heuristic_done.load(Ordering::SeqCst);
            let x_done = exact_done();
            // Both sides end on their own: the heuristic by its work rule
            // (or the time limit), the exact side by its conflict budget
            // (or the time limit).
            let ended = h_done && x_done;
            if ended {
                break;
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        heuristic_stop.store(true, Ordering::SeqCst);
        exact_stop.store(true, Ordering::SeqCst);
        heuristic.map(|t| t.join().expect("heuristic thread"))
    });
    // The exact side gets a moment to see its stop flag; past that it is
    // left to end on its own (what it would have said is not waited for).
    let grace = Instant::now() + EXACT_GRACE;
    while !exact_done() && Instant::now() < grace {
        std::thread::sleep(Duration::from_millis(2));
    }
    let exact: Option<ExactOutcome> = match exact {
        Some(t) if t.is_finished() => Some(t.join().expect("exact thread")?),
        _ => None,
    };
    drain();
    let mut heuristic: Option<Outcome> = heuristic.transpose()?;
    // Polish: an answer with a sliver (a piece of fewer than SLIVER_CELLS
    // cells) gets one more round of the search at its piece count that
    // accepts only sliver-free dissections, in the time left (with a time
    // limit, its last POLISH_SHARE).
    let sat_count = shared.sat_best.load(Ordering::SeqCst);
    let sliver_count = heuristic
        .as_ref()
        .and_then(|o| o.found.as_ref())
        .filter(|f| f.piece_count() <= sat_count && has_sliver(&f.pieces))
        .map(|f| f.piece_count());
    if let Some(count) = sliver_count.filter(|_| {
        polishable
            && (polish_early || matches!(end, End::Optimal | End::Finished))
            && !stop.load(Ordering::SeqCst)
            && deadline.is_none_or(|d| Instant::now() < d)
    }) {
        let polish_options = dissect_core::solver::Options {
            max_pieces: Some(count),
            ..solver_options.clone()
        };
        // One round after an optimal or finished run; in the last part of
        // a time limit, rounds until it.
        let rounds = (!polish_early).then_some(1);
        let polish_anytime = dissect_core::solver::Anytime {
            idle_rounds: rounds,
            max_rounds: rounds,
            ..anytime.clone()
        };
        let polish_stop = AtomicBool::new(false);
        let polish_done = AtomicBool::new(false);
        let polished = std::thread::scope(|s| {
            let t = s.spawn(|| {
                let r = solve_anytime_with(
                    figures,
                    &polish_options,
                    &polish_anytime,
                    &polish_stop,
                    &NoSlivers(&shared),
                    repairer,
                    executor,
                );
                polish_done.store(true, Ordering::SeqCst);
                r
            });
            while !polish_done.load(Ordering::SeqCst) {
                if stop.load(Ordering::SeqCst) || deadline.is_some_and(|d| Instant::now() >= d) {
                    polish_stop.store(true, Ordering::SeqCst);
                }
                std::thread::sleep(Duration::from_millis(5));
            }
            t.join().expect("polish thread")
        })?;
        if let (Some(h), Some(found)) = (heuristic.as_mut(), polished.found) {
            if found.piece_count() <= count && !has_sliver(&found.pieces) {
                h.found = Some(found);
            }
        }
    }

    let mut best: Option<(Verified, Source, Option<usize>)> = None;
    if let Some(found) = heuristic.as_ref().and_then(|o| o.found.as_ref()) {
        let v = Verified::new(
            lattice,
            mirror,
            names.clone(),
            figures,
            found.pieces.clone(),
        )
        .map_err(|e| EngineError::Unverified("heuristic", e))?;
        let source = shared
            .history
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .iter()
            .rev()
            .find(|i| i.source != Source::Sat && i.pieces == v.piece_count())
            .map_or(Source::Search, |i| i.source);
        best = Some((v, source, Some(found.level)));
    }
    if let Some(pieces) = exact.as_ref().and_then(|o| o.found.clone()) {
        let v = Verified::new(lattice, mirror, names.clone(), figures, pieces)
            .map_err(|e| EngineError::Unverified("SAT", e))?;
        if best
            .as_ref()
            .is_none_or(|(b, _, _)| v.piece_count() < b.piece_count())
        {
            best = Some((v, Source::Sat, None));
        }
    }
    // A puzzle run: the collection, with the answers of both sides, ranked;
    // every one verified and checked against the constraints.
    let mut solutions = Vec::new();
    let mut ranking = None;
    if let Some(judge) = &shared.judge {
        let mut collection = judge
            .collection
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone();
        let heuristic_pieces = heuristic
            .as_ref()
            .and_then(|o| o.found.as_ref())
            .map(|f| f.pieces.clone());
        let sat_pieces = exact.as_ref().and_then(|o| o.found.clone());
        for p in heuristic_pieces.iter().chain(&sat_pieces) {
            collection.add(p.clone());
        }
        let heuristic_source = best
            .as_ref()
            .filter(|b| b.1 != Source::Sat)
            .map_or(Source::Search, |b| b.1);
        for e in collection.ranked(config.rank, wanted, figures, COUNT_TIME) {
            let broken = constraints.check(&motions, &e.pieces);
            if let Some(v) = broken.first() {
                return Err(EngineError::Unverified(
                    "constrained",
                    format!("it breaks a constraint: {v}"),
                ));
            }
            let source = if sat_pieces.as_ref() == Some(&e.pieces) {
                Source::Sat
            } else if heuristic_pieces.as_ref() == Some(&e.pieces) {
                heuristic_source
            } else {
                Source::Search
            };
            let dissection = Verified::new(lattice, mirror, names.clone(), figures, e.pieces)
                .map_err(|err| EngineError::Unverified("collected", err))?;
            solutions.push(Solution {
                dissection,
                scores: e.scores,
                source,
            });
        }
        // The best is the first by the ranking.
        best = solutions.first().map(|s| {
            let level = best
                .as_ref()
                .filter(|b| b.0 == s.dissection)
                .and_then(|b| b.2);
            (s.dissection.clone(), s.source, level)
        });
        ranking = Some(Ranking {
            rank: config.rank,
            asked: wanted,
            constraints: constraints.to_json(lattice),
        });
    }
    let lower_bound = shared
        .lower
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .clone();
    let history = shared
        .history
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .clone();
    let count = best.as_ref().map(|(b, _, _)| b.piece_count());
    let optimal = count.is_some_and(|c| c <= lower_bound.value);
    if optimal && end == End::Finished {
        end = End::Optimal;
    }
    let outcome = heuristic.as_ref();
    Ok(Report {
        seed: config.seed,
        time_to_first: history.first().map(|i| i.seconds),
        time_to_best: count
            .and_then(|c| history.iter().find(|i| i.pieces <= c))
            .map(|i| i.seconds),
        source: best.as_ref().map(|b| b.1),
        level: best.as_ref().and_then(|b| b.2),
        best: best.map(|b| b.0),
        seconds: start.elapsed().as_secs_f64(),
        lower_bound,
        optimal,
        history,
        end,
        explorations: outcome.map_or(0, |o| o.explorations),
        rounds: outcome.map_or(0, |o| o.rounds),
        last_pieces: outcome.map_or(0, |o| o.last_pieces),
        best_mismatch: outcome.and_then(|o| o.best_mismatch),
        solutions,
        ranking,
    })
}

/// Pieces of fewer cells are slivers: a run whose answer has one polishes
/// it (one more round at the same piece count, sliver-free answers only).
pub const SLIVER_CELLS: usize = 3;

/// Whether a dissection (`pieces[f][i]`) has a piece of fewer than
/// [`SLIVER_CELLS`] cells.
fn has_sliver(pieces: &[Vec<Vec<Cell>>]) -> bool {
    pieces
        .first()
        .is_some_and(|p| p.iter().any(|c| c.len() < SLIVER_CELLS))
}

/// The polish's observer: the run's, refusing every dissection with a
/// sliver and steering candidates away from tiny pieces.
struct NoSlivers<'s, 'a>(&'s Shared<'a>);

impl Observer for NoSlivers<'_, '_> {
    fn on_event(&self, event: &Event) {
        Observer::on_event(self.0, event);
    }

    fn judges(&self) -> bool {
        true
    }

    fn judge(&self, pieces: &[Vec<Vec<Cell>>], valid: bool) -> Judgement {
        let missing: usize = pieces.first().map_or(0, |p| {
            p.iter().map(|c| SLIVER_CELLS.saturating_sub(c.len())).sum()
        });
        Judgement {
            accept: !valid || missing == 0,
            penalty: 2.0 * missing as f64,
            fresh: false,
        }
    }
}

/// Why a dissection meeting `b` is optimal, in words.
fn proof(b: &Bound, names: &[String]) -> String {
    match &b.reason {
        Reason::Sat {
            refuted, seconds, ..
        } => format!(
            "no {refuted}-piece dissection exists; proof {}",
            if *seconds < 10.0 {
                format!("{seconds:.1} s")
            } else {
                format!("{seconds:.0} s")
            }
        ),
        _ => b.describe(names),
    }
}
