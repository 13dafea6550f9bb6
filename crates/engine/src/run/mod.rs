//! One run: the heuristic and the exact search side by side, the deadline,
//! the stop flag, and the report. Its phases, each a module: the shared
//! state and its observers (`shared`), the search of both sides under the
//! monitor (`sides`), the polish (`polish`), the answer (`answer`:
//! verification, ranking, report).

mod answer;
mod interlock;
mod order;
mod polish;
mod shared;
mod sides;

use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::solver::{Event, Executor, Explorer, Repair, SolveError};
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_exact::{ExactError, ExactEvent, ExactOptions, Mode, RepairOptions};
use dissect_puzzle::constraints::ConstraintError;
use dissect_puzzle::Motions;

use crate::options::{RunConfig, RunOptions, Strategy};
use crate::report::{Improvement, LowerBound, Report};
pub(crate) use shared::{proof, Forward};
use shared::{Judge, Shared};

/// The SAT search (beside the heuristic, and in the polish) works only on
/// figures of at most this many cells: its encoding grows with cells ×
/// placements. Larger figures get the exact side's cheap bounds only
/// (components, incompatible corners), which hold at every size.
pub const PROVE_MAX_CELLS: usize = dissect_exact::bound::FULL_GRAPH_MAX_CELLS;

/// SAT conflicts the exact side may spend in a run without a time limit.
pub const EXACT_BUDGET: u64 = 100_000;

/// The largest SAT encoding the exact side may build (bytes).
const EXACT_MAX_BYTES: u64 = 256 << 20;

/// How long a stopped run waits for the exact side to return.
const EXACT_GRACE: Duration = Duration::from_millis(300);

/// With a time limit, the share of it at its end that goes to the polish
/// when the answer has a sliver.
pub const POLISH_SHARE: f64 = 0.15;

/// With a time limit and the assembly rules, the share of it at its end
/// that goes to the interlocking search when no answer honours them yet.
pub const INTERLOCK_SHARE: f64 = 0.6;

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

/// How long past a time limit the counts of `--rank unique` may go on in
/// all (the run ends within a second of its limit).
pub const COUNT_GRACE: Duration = Duration::from_millis(500);

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
    /// A phase of the run started (or, for the exact repair, the sectors
    /// and the regrouping, was called once more).
    Phase(Phase),
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

/// A phase of a run, as [`EngineEvent::Phase`] names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Phase {
    /// The exact repair of one of the heuristic's near misses.
    Repair,
    /// The exact dissection of one sector (small figures) of a large one.
    Sectors,
    /// The exact search that cuts a few pieces of the best answer again.
    Regroup,
    /// The polish of an answer with a sliver.
    Polish,
    /// The ranking of several solutions (their assemblies counted with
    /// `--rank unique`).
    Ranking,
    /// The interlocking search (`--min-level`, `--assemblable`: no
    /// dissection found honoured the assembly rules).
    Interlock,
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
    /// Another SAT solver (named first) could not run or answered
    /// something that is no answer (`bound --solver`).
    #[error("{0}: {1}")]
    External(String, String),
}

/// Runs `options` on `figures` (named `names` in the answer, input order).
///
/// The search sees the figures in an order their shapes decide (the most
/// self-symmetries first, `order.rs`), so the piece count a run reaches does
/// not depend on the order they are given in; the answer is in input order.
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
///
/// The phases: the `Plan` (what runs, fixed before the start), the
/// `Shared` state, the search of both sides under the monitor
/// (`sides::search`), the polish (`polish::polish`) and the answer
/// (verification, ranking, the report: `answer::answer`).
pub fn run_with(
    figures: &[Figure],
    names: &[String],
    options: &RunOptions,
    stop: &AtomicBool,
    observer: &dyn EngineObserver,
    executor: Option<&dyn Executor>,
) -> Result<Report, EngineError> {
    check(figures, options)?;
    let lattice = figures[0].lattice().lattice();
    let mirror = options.config().mirror && lattice.supports_mirror();
    let order = order::canonical_order(figures, mirror);
    let names: Vec<String> = (0..figures.len()).map(|i| figure_name(names, i)).collect();
    if order.iter().enumerate().all(|(i, &f)| i == f) {
        return run_in_order(figures, &names, options, stop, observer, executor);
    }
    let mut new_of_old = vec![0; order.len()];
    for (i, &f) in order.iter().enumerate() {
        new_of_old[f] = i;
    }
    let report = run_in_order(
        &order
            .iter()
            .map(|&f| figures[f].clone())
            .collect::<Vec<_>>(),
        &order.iter().map(|&f| names[f].clone()).collect::<Vec<_>>(),
        &options.renumbered(&new_of_old),
        stop,
        observer,
        executor,
    )?;
    let mut report = order::restore(report, &order);
    if let Some(ranking) = &mut report.ranking {
        // The constraints as given (their figure numbers in input order).
        ranking.constraints = options.config().constraints.to_json(figures[0].lattice());
    }
    Ok(report)
}

/// The explorer for an executor of [`run_with`] on these figures and
/// options: it explores the problem the run searches (the figures in the
/// order the search sees them, `order.rs`), so the executor's explorations
/// fit the run whatever order the figures are given in.
pub fn explorer(figures: &[Figure], options: &RunOptions) -> Result<Explorer, EngineError> {
    check(figures, options)?;
    let lattice = figures[0].lattice().lattice();
    let mirror = options.config().mirror && lattice.supports_mirror();
    let seen: Vec<Figure> = order::canonical_order(figures, mirror)
        .into_iter()
        .map(|f| figures[f].clone())
        .collect();
    Ok(Explorer::new(&seen, &options.solver_options())?)
}

/// The name of figure `i`: the one given, else "figure i".
fn figure_name(names: &[String], i: usize) -> String {
    names
        .get(i)
        .cloned()
        .unwrap_or_else(|| format!("figure {i}"))
}

/// [`run_with`] on the figures in the order the search sees them
/// (`order::canonical_order`), named.
fn run_in_order(
    figures: &[Figure],
    names: &[String],
    options: &RunOptions,
    stop: &AtomicBool,
    observer: &dyn EngineObserver,
    executor: Option<&dyn Executor>,
) -> Result<Report, EngineError> {
    let plan = Plan::new(figures, names, options);
    let judge = options
        .collects()
        .then(|| Judge::new(&plan.motions, &plan.config().constraints, plan.wanted()));
    let shared = Shared::new(plan.start, &plan.names, observer, judge);
    let exact_repair = crate::repair::ExactRepair::new(
        figures,
        RepairOptions {
            mirror: plan.mirror,
            deadline: plan.deadline,
            budget: REPAIR_BUDGET,
            ..RepairOptions::default()
        },
    )
    .with_observer(observer);
    let repairer = plan.config().repair.then_some(&exact_repair as &dyn Repair);
    let mut sides = sides::search(&plan, &shared, stop, repairer, executor)?;
    polish::polish(&plan, &shared, stop, &mut sides, repairer, executor)?;
    interlock::interlock(&plan, &shared, stop, &mut sides);
    answer::answer(&plan, &shared, stop, sides)
}

/// What a run does, fixed before it starts.
pub(super) struct Plan<'r> {
    figures: &'r [Figure],
    options: &'r RunOptions,
    lattice: LatticeKind,
    /// Whether pieces may be turned over (asked for, and the lattice can).
    mirror: bool,
    motions: Motions,
    /// A name for each figure (input order).
    names: Vec<String>,
    start: Instant,
    deadline: Option<Instant>,
    heuristic_on: bool,
    exact_on: bool,
    /// Whether an answer with a sliver may be polished.
    polishable: bool,
    /// With a time limit, the instant from which the polish takes over.
    polish_from: Option<Instant>,
    /// With a time limit and the assembly rules, the instant from which
    /// the interlocking search takes over when no answer honours them.
    interlock_from: Option<Instant>,
}

impl<'r> Plan<'r> {
    fn new(figures: &'r [Figure], names: &[String], options: &'r RunOptions) -> Plan<'r> {
        let config = options.config();
        let lattice = figures[0].lattice();
        let mirror = config.mirror && lattice.lattice().supports_mirror();
        let names = (0..figures.len()).map(|i| figure_name(names, i)).collect();
        let start = Instant::now();
        let deadline = options.time_limit().and_then(|d| start.checked_add(d));
        let strategy = options.strategy();
        let polishable = strategy == Strategy::Anytime
            && !options.collects()
            && figures[0].len() <= PROVE_MAX_CELLS;
        // The last POLISH_SHARE of a time limit, if it is long enough.
        let polish_from = options
            .time_limit()
            .map(|t| t.mul_f64(POLISH_SHARE))
            .filter(|r| polishable && *r >= POLISH_LEAST)
            .and_then(|r| deadline.map(|d| d - r));
        let interlock_from = options
            .time_limit()
            .filter(|_| config.constraints.assemblable() && options.collects())
            .map(|t| t.mul_f64(INTERLOCK_SHARE))
            .and_then(|r| deadline.map(|d| d - r));
        Plan {
            figures,
            options,
            lattice,
            mirror,
            motions: Motions::new(lattice, mirror),
            names,
            start,
            deadline,
            heuristic_on: strategy != Strategy::Exact,
            // On figures over the exact crate's size the exact side gives
            // the cheap bounds (corners, components) and no SAT search.
            exact_on: strategy == Strategy::Exact || config.prove,
            polishable,
            polish_from,
            interlock_from,
        }
    }

    fn config(&self) -> &RunConfig {
        self.options.config()
    }

    fn strategy(&self) -> Strategy {
        self.options.strategy()
    }

    /// How many solutions are asked for.
    fn wanted(&self) -> usize {
        self.config().solutions
    }

    /// The exact side's settings.
    fn exact_options(&self) -> ExactOptions {
        let config = self.config();
        let strategy = self.strategy();
        ExactOptions {
            mirror: self.mirror,
            mode: if strategy == Strategy::Exact {
                Mode::Minimum
            } else {
                Mode::LowerBound
            },
            max_pieces: config.max_pieces,
            // Without a time limit the exact side beside the heuristic
            // counts its work (SAT conflicts), so what it proves and finds
            // is the same on every machine; the run waits for it.
            conflict_budget: (self.deadline.is_none() && strategy != Strategy::Exact)
                .then_some(EXACT_BUDGET),
            max_encoding_bytes: EXACT_MAX_BYTES,
            constraints: (!config.constraints.is_empty()).then(|| config.constraints.clone()),
            certify: config.certify,
            ..ExactOptions::default()
        }
    }
}

/// Pieces of fewer cells are slivers: a run whose answer has one polishes
/// it (one more round at the same piece count, sliver-free answers only).
pub const SLIVER_CELLS: usize = 3;

/// Whether a dissection (`pieces[f][i]`) has a piece of fewer than
/// [`SLIVER_CELLS`] cells.
pub(super) fn has_sliver(pieces: &[Vec<Vec<Cell>>]) -> bool {
    pieces
        .first()
        .is_some_and(|p| p.iter().any(|c| c.len() < SLIVER_CELLS))
}
