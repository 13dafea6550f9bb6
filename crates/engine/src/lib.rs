//! The engine of `dissect`: one run, the same for every front end (CLI, web
//! studio, bench, Python).
//!
//! * [`TimeLimit`]: how long any operation may run, parsed once by one
//!   rule for every front end; [`check_threads`]: the thread count's rule.
//! * [`RunOptions`]: every solver setting, validated once
//!   ([`RunOptions::new`] from a plain [`RunConfig`], [`OptionsError`]).
//! * [`run`]: the time limit and the stop flag (the only deadline of the
//!   workspace), the anytime heuristic ([`dissect_core::solver::solve_anytime`])
//!   and the exact lower-bound search ([`dissect_exact::search()`]) side by
//!   side with shared bounds, ending as soon as the best dissection meets
//!   the lower bound (`optimal`), the repair of near misses, and the
//!   [`Report`].
//! * [`bound()`]: the exact search's lower bound alone ([`BoundConfig`],
//!   [`BoundReport`]), under the same time limit and stop flag.
//! * [`assemblies()`]: the ways a dissection's pieces tile figures
//!   ([`AssemblyEvent`], [`CountError`]), under the same time limit and
//!   stop flag.
//! * [`Verified`]: a dissection that passed [`dissect_core::verify`]; the
//!   only kind of dissection a [`Report`] holds; [`Verified::assemblies`]
//!   counts the ways its pieces tile each figure.
//! * [`disassemble()`]: whether each figure of a dissection can be taken
//!   apart by straight moves (the plan, its level), within a time limit
//!   and a stop flag.
//! * [`enumerate()`]: every dissection with K pieces (the minimum, proved,
//!   unless K is given), each [`Verified`], in classes up to the first
//!   figure's symmetries, with the time limit and the stop flag.
//! * [`EngineObserver`]: live events (level progress, improvements, bounds).
//! * Puzzle runs ([`RunConfig::solutions`], [`RunConfig::rank`],
//!   [`RunConfig::constraints`]): every candidate of the heuristic is judged
//!   against the designer's constraints (a distance to them steers which
//!   candidates a level keeps; a dissection that breaks them is never an
//!   answer), the exact side encodes them as clauses, every valid
//!   dissection is collected ([`dissect_puzzle::Collection`]: distinct up to
//!   the lattice's motions, the fewest pieces), and the report carries them
//!   ranked ([`Report::solutions`]), each verified and checked.
//!
//! Architecture invariant: like the core, this crate does no I/O and never
//! prints.

mod assemblies;
mod bound;
mod disassemble;
mod enumerate;
mod external;
mod interlock;
mod limits;
mod monitor;
mod options;
mod repair;
mod report;
mod run;
mod verified;

pub use assemblies::{assemblies, AssemblyEvent, CountError};
pub use bound::{bound, BoundConfig, BoundReport};
pub use disassemble::disassemble;
pub use dissect_exact::{EnumerateEvent, EnumerateObserver, ExactEvent};
pub use dissect_puzzle::assemblies::{AssemblyError, Count};
pub use dissect_puzzle::disassembly::{Disassembly, DisassemblyError, Plan as DisassemblyPlan};
pub use dissect_puzzle::{constraints::ConstraintError, Constraints, KeepRegions, Rank, Scores};
pub use enumerate::{enumerate, EnumerateConfig, EnumeratedClass, EnumerationReport};
pub use external::{bound_external, ExternalAnswer, ExternalSolver};
pub use limits::{check_threads, LimitError, TimeLimit, MAX_THREADS};
pub use options::{
    OptionsError, RunConfig, RunOptions, Strategy, MAX_EXPLORATIONS, MAX_SOLUTIONS,
    PLATEAU_IDLE_ROUNDS,
};
pub use repair::ExactRepair;
pub use report::{End, Improvement, LowerBound, Ranking, Report, Solution, Source};
pub use run::{
    check, explorer, run, run_with, EngineError, EngineEvent, EngineObserver, Phase, SLIVER_CELLS,
};
pub use verified::Verified;
