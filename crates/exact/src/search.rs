//! The exact search: cheap bounds first, then "at most K pieces?" by SAT for
//! K = the bound, the bound + 1, ... until a dissection is found, the caller's
//! upper bound is met, or the time runs out.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use dissect_core::{Cell, Figure};

use crate::bound::{cheap, cheap_with, Bound, Cheap, Reason};
use crate::certificate::Certificate;
use crate::connectivity_cut::cuts;
use crate::incompatible_clique::Incompatibility;
use crate::instance::Instance;
use crate::motion::MotionSet;
use crate::placement_encoding::{encode, estimate, EncodingSize, MotionEncoding};
use crate::reachability_encoding::{add_connectivity, connectivity_size};
use crate::sat_backend::Sat;
use crate::ExactError;

/// What the search is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Raise the lower bound; a dissection is reported only when the SAT
    /// search meets one on the way.
    LowerBound,
    /// Find a minimum dissection: before the full model for each K, try
    /// translations only, then rotations only (these find dissections fast
    /// but prove nothing).
    Minimum,
}

/// Settings of [`search`].
#[derive(Clone, Debug, PartialEq)]
pub struct ExactOptions {
    /// Whether 2D pieces may be turned over (ignored on `cubic`).
    pub mirror: bool,
    /// What to search for.
    pub mode: Mode,
    /// Give up (reporting what is proved) at this instant.
    pub deadline: Option<Instant>,
    /// Try no more than this many pieces.
    pub max_pieces: Option<usize>,
    /// Time for each restricted-motion pass in [`Mode::Minimum`].
    pub restricted_time: Duration,
    /// Connectivity cuts added per split piece and model.
    pub cuts_per_piece: usize,
    /// On the first model with a split piece, add the full connectivity
    /// encoding (reachability from each piece's root) instead of cuts
    /// (when it fits in `max_encoding_bytes`; else cuts).
    pub eager_connectivity: bool,
    /// The most SAT conflicts the whole search may spend (`None`: no
    /// limit): a measure of work that is the same on every machine, so with
    /// it and no deadline the outcome never depends on timing. Spent, the
    /// search ends as inconclusive ([`Limit::ConflictBudget`]).
    pub conflict_budget: Option<u64>,
    /// Conflicts for each restricted-motion pass of [`Mode::Minimum`]; when
    /// set it replaces `restricted_time`, so the passes end the same way on
    /// every machine.
    pub restricted_conflicts: Option<u64>,
    /// Refuse an encoding estimated to need more memory than this many
    /// bytes: the search ends as inconclusive ([`Limit::TooLarge`]) instead
    /// of exhausting the machine.
    pub max_encoding_bytes: u64,
    /// The designer's constraints every dissection found must honour
    /// (`None`: none). Lower bounds are then bounds under the constraints.
    pub constraints: Option<dissect_puzzle::Constraints>,
    /// Record every refuted formula and its DRAT proof and report them as
    /// [`ExactEvent::Certified`]; the cheap bound `L` (when at least 2) is
    /// then also refuted by SAT at `L - 1` pieces, so that it has a
    /// certificate when the encoding refutes it.
    pub certify: bool,
    /// With [`ExactOptions::certify`] and cube-and-conquer: where each
    /// cube's DRAT proof is written as the solver goes (`None`: every
    /// proof is kept in memory and sent in its certificate).
    pub cube_proofs: Option<crate::ProofSink>,
    /// How motions are encoded ([`MotionEncoding::Auto`]: the direct
    /// encoding unless the shift chain is much smaller; always direct
    /// under constraints).
    pub motion_encoding: MotionEncoding,
    /// Figures of more cells get no SAT model, only the cheap bounds
    /// ([`Limit::Cells`]); at most [`SAT_MAX_CELLS`](crate::bound::SAT_MAX_CELLS)
    /// is used. The default is
    /// [`FULL_GRAPH_MAX_CELLS`](crate::bound::FULL_GRAPH_MAX_CELLS), the
    /// largest figures with incompatibility graphs (the engine's solve
    /// keeps it, beside its heuristic); `dissect bound` asks for
    /// `SAT_MAX_CELLS`.
    pub sat_max_cells: usize,
    /// Threads for cube-and-conquer on the full model (1: none): "at most
    /// K pieces" is split into one cube per literal of one of its
    /// at-least-one clauses (`Encoding::cube`), the cubes solved in
    /// parallel; UNSAT once every cube is. Each cube may spend what is
    /// left of [`ExactOptions::conflict_budget`] (so a pass may spend up to
    /// that many per cube). Not used under constraints.
    pub cube_threads: usize,
    /// Break the symmetries of the reference figure too: the first piece's
    /// motion into the second figure is taken as one per orbit under the
    /// reference figure's symmetries that fix the anchored cells and the
    /// second figure's symmetries (direct encoding; docs/FORMAT.md
    /// "Certificates" for why that is sound). Never under constraints.
    pub source_symmetries: bool,
}

/// The default of [`ExactOptions::max_encoding_bytes`]: 512 MiB.
pub const DEFAULT_MAX_ENCODING_BYTES: u64 = 512 << 20;

/// Why a search ended before it could prove or find more.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Limit {
    /// [`ExactOptions::conflict_budget`] was spent.
    ConflictBudget,
    /// A figure has more than [`ExactOptions::sat_max_cells`] cells: no SAT
    /// model is built, only the cheap bounds hold.
    Cells {
        /// The cells of the largest figure.
        cells: usize,
    },
    /// The encoding for `pieces` pieces was estimated at `bytes`, over
    /// [`ExactOptions::max_encoding_bytes`].
    TooLarge {
        /// K.
        pieces: usize,
        /// The estimate.
        bytes: u64,
    },
}

impl Default for ExactOptions {
    fn default() -> ExactOptions {
        ExactOptions {
            mirror: true,
            mode: Mode::LowerBound,
            deadline: None,
            max_pieces: None,
            restricted_time: Duration::from_secs(10),
            cuts_per_piece: 4,
            eager_connectivity: true,
            conflict_budget: None,
            restricted_conflicts: None,
            max_encoding_bytes: DEFAULT_MAX_ENCODING_BYTES,
            constraints: None,
            certify: false,
            cube_proofs: None,
            motion_encoding: MotionEncoding::Auto,
            sat_max_cells: crate::bound::FULL_GRAPH_MAX_CELLS,
            cube_threads: 1,
            source_symmetries: true,
        }
    }
}

/// Progress of the exact search.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ExactEvent {
    /// The bound from components and incompatible cells (first, when it
    /// is above 1, the bound of components and congruence alone).
    CheapBound(Bound),
    /// A SAT model for `pieces` pieces was built.
    Encoded {
        /// K.
        pieces: usize,
        /// Which motions it allows.
        motions: MotionSet,
        /// Its size.
        size: EncodingSize,
    },
    /// A model had split pieces; connectivity cuts were added.
    Cuts {
        /// K.
        pieces: usize,
        /// Cuts added now.
        added: usize,
        /// Cuts added for this K in all.
        total: usize,
    },
    /// A model had split pieces; the full connectivity encoding was added.
    ConnectivityEncoded {
        /// K.
        pieces: usize,
    },
    /// The encoding for `pieces` pieces would be too large: the search ends
    /// there (see [`Limit::TooLarge`]).
    TooLarge {
        /// K.
        pieces: usize,
        /// Its estimated size.
        size: EncodingSize,
        /// Its estimated memory.
        bytes: u64,
    },
    /// No dissection into `bound.value - 1` pieces: the bound rose.
    Refuted(Bound),
    /// A restricted pass ended without a dissection (this proves nothing).
    Inconclusive {
        /// K.
        pieces: usize,
        /// The pass.
        motions: MotionSet,
        /// Whether it ran out of time (else it was unsatisfiable).
        timed_out: bool,
    },
    /// A refutation's certificate (with [`ExactOptions::certify`]): sent
    /// just before the [`ExactEvent::Refuted`] it proves, or alone for the
    /// cheap bound's `L - 1`.
    Certified(Certificate),
    /// Cube-and-conquer ([`ExactOptions::cube_threads`]): a cube was
    /// settled (refuted, or not: a model, a stop or the deadline).
    Cube {
        /// K.
        pieces: usize,
        /// The cube (from 0).
        index: usize,
        /// The number of cubes.
        of: usize,
        /// Whether it was refuted.
        refuted: bool,
        /// Seconds it took.
        seconds: f64,
    },
    /// Cube-and-conquer with [`ExactOptions::cube_proofs`]: the proof
    /// writers already held cube `index` refuted for this very base
    /// formula and cover (an earlier run's, [`CubeProofWriters::begin`](crate::CubeProofWriters::begin)),
    /// so it is not solved again.
    CubeKept {
        /// K.
        pieces: usize,
        /// The cube (from 0).
        index: usize,
        /// The number of cubes.
        of: usize,
    },
    /// A verified dissection into `pieces` pieces.
    Found {
        /// Its piece count.
        pieces: usize,
        /// Seconds since the search started.
        seconds: f64,
    },
}

/// Receives [`ExactEvent`]s.
pub trait ExactObserver: Sync {
    /// Called for every event.
    fn on_event(&self, event: &ExactEvent);
}

impl ExactObserver for () {
    fn on_event(&self, _event: &ExactEvent) {}
}

/// What the exact search proved and found.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactOutcome {
    /// The best lower bound proved.
    pub lower_bound: Bound,
    /// A verified dissection (`pieces[f][i]`, input order), if one was found.
    pub found: Option<Vec<Vec<Vec<Cell>>>>,
    /// Whether the search ended before it could finish (stop flag, deadline,
    /// the caller's upper bound or a [`Limit`]).
    pub stopped: bool,
    /// The limit that ended it, if one did.
    pub limit: Option<Limit>,
    /// SAT conflicts spent.
    pub conflicts: u64,
}

impl ExactOutcome {
    /// Whether the dissection found is proved minimum.
    pub fn optimal(&self) -> bool {
        self.found
            .as_ref()
            .is_some_and(|p| p.first().map_or(0, |f| f.len()) <= self.lower_bound.value)
    }
}

pub(crate) enum Pass {
    Unsat {
        cuts: usize,
        seconds: f64,
        certificate: Option<Box<Certificate>>,
    },
    Found(Vec<Vec<Vec<usize>>>),
    /// Stopped, past the deadline or out of conflicts.
    Unknown,
    /// The encoding would need this many bytes.
    TooLarge(u64),
}

struct Context<'a> {
    inst: &'a Instance,
    clique: &'a [usize],
    incompat: &'a [Incompatibility],
    stop: &'a AtomicBool,
    upper: &'a AtomicUsize,
    observer: &'a dyn ExactObserver,
    cuts_per_piece: usize,
    eager_connectivity: bool,
    max_bytes: u64,
    constraints: Option<&'a dissect_puzzle::Constraints>,
    certify: bool,
    cube_proofs: Option<&'a crate::ProofSink>,
    motion_encoding: MotionEncoding,
    cube_threads: usize,
    /// Conflicts spent so far.
    spent: std::cell::Cell<u64>,
}

impl Context<'_> {
    /// One SAT model for `k` pieces with `set` motions, with connectivity
    /// cuts until a model is connected, the model is UNSAT, time is up or
    /// `conflicts` are spent.
    /// The restricted passes of `k` pieces (translations, then rotations:
    /// quick to find a dissection, proving nothing when they find none);
    /// the first dissection found.
    fn restricted_passes(
        &self,
        k: usize,
        restricted: &[MotionSet],
        options: &ExactOptions,
        left: &dyn Fn() -> Option<u64>,
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Vec<Vec<Vec<usize>>>> {
        for &set in restricted {
            let (deadline, conflicts) = match options.restricted_conflicts {
                Some(c) => (options.deadline, Some(left().map_or(c, |l| l.min(c)))),
                None => {
                    let budget = Instant::now().checked_add(options.restricted_time);
                    let d = match (options.deadline, budget) {
                        (Some(d), Some(b)) => Some(d.min(b)),
                        (d, b) => d.or(b),
                    };
                    (d, left())
                }
            };
            let timed_out = match self.pass(k, set, deadline, conflicts) {
                Pass::Found(p) => return Some(p),
                Pass::Unsat { .. } => false,
                Pass::Unknown | Pass::TooLarge(_) => true,
            };
            self.observer.on_event(&ExactEvent::Inconclusive {
                pieces: k,
                motions: set,
                timed_out,
            });
            if interrupted() || self.upper.load(Ordering::SeqCst) <= k {
                break;
            }
        }
        None
    }

    /// With certificates, the cheap bound `bound` (at least 2) refuted by
    /// SAT at `bound - 1` pieces, its certificate sent as
    /// [`ExactEvent::Certified`]; nothing when the encoding does not refute
    /// it in time (the cheap bound still holds, uncertified). When the
    /// encoding is too large and the bound is an incompatible clique's, the
    /// certificate holds the clique's clauses only ([`Certificate::clique_only`]).
    fn certify_cheap(
        &self,
        bound: usize,
        deadline: Option<Instant>,
        left: &dyn Fn() -> Option<u64>,
    ) {
        if bound < 2 {
            return;
        }
        let certificate = match self.pass(bound - 1, MotionSet::All, deadline, left()) {
            Pass::Unsat { certificate, .. } => certificate,
            // The full encoding would not fit: the clique's clauses alone.
            Pass::TooLarge(_) if self.clique.len() >= bound => {
                crate::certificate::clique(bound - 1, self.clique.len(), self.stop)
            }
            _ => None,
        };
        if let Some(c) = certificate {
            self.observer.on_event(&ExactEvent::Certified(*c));
        }
    }

    fn pass(
        &self,
        k: usize,
        set: MotionSet,
        deadline: Option<Instant>,
        conflicts: Option<u64>,
    ) -> Pass {
        let start = Instant::now();
        let interrupted =
            || self.stop.load(Ordering::Relaxed) || deadline.is_some_and(|d| Instant::now() >= d);
        let style = match self.motion_encoding {
            _ if self.constraints.is_some() => MotionEncoding::Direct,
            MotionEncoding::Auto => crate::placement_encoding::choose(
                self.inst,
                k,
                set,
                self.clique,
                self.incompat,
                &interrupted,
            ),
            s => s,
        };
        let estimate = estimate(
            self.inst,
            k,
            (set, style),
            self.clique,
            self.incompat,
            &interrupted,
        );
        if interrupted() {
            return Pass::Unknown;
        }
        let bytes = estimate.bytes(self.certify);
        if bytes > self.max_bytes {
            self.observer.on_event(&ExactEvent::TooLarge {
                pieces: k,
                size: estimate,
                bytes,
            });
            return Pass::TooLarge(bytes);
        }
        let mut sat = Sat::new(self.stop, Some((self.upper, k)));
        if self.certify && set == MotionSet::All {
            sat.record();
            sat.record_proof();
        }
        sat.set_conflict_limit(conflicts);
        let spend = |sat: &Sat<'_>| self.spent.set(self.spent.get() + sat.conflicts());
        let Some(enc) = encode(
            self.inst,
            &mut sat,
            k,
            (set, style),
            self.clique,
            self.incompat,
            &interrupted,
        ) else {
            return Pass::Unknown;
        };
        if let Some(c) = self.constraints {
            crate::constraint_encoding::add(self.inst, &mut sat, &enc, c);
        }
        self.observer.on_event(&ExactEvent::Encoded {
            pieces: k,
            motions: set,
            size: EncodingSize {
                vars: sat.vars(),
                clauses: sat.clauses(),
                motions: enc.motions(),
            },
        });
        let shape0 = &self.inst.shapes[0];
        let (cv, cc) = connectivity_size(shape0.len(), k, shape0.adj.iter().map(Vec::len).sum());
        let connectivity_fits = bytes.saturating_add(
            EncodingSize {
                vars: cv.min(usize::MAX as u64) as usize,
                clauses: cc.min(usize::MAX as u64) as usize,
                motions: 0,
            }
            .bytes(false),
        ) <= self.max_bytes;
        let cutting = Cutting {
            inst: self.inst,
            cuts_per_piece: self.cuts_per_piece,
            observer: self.observer,
            eager: self.eager_connectivity && connectivity_fits,
        };
        if set == MotionSet::All && self.cube_threads > 1 && self.constraints.is_none() {
            let cubes = crate::cube_and_conquer::Cubes {
                cutting: &cutting,
                clique: self.clique,
                incompat: self.incompat,
                stop: self.stop,
                upper: self.upper,
                style,
                certify: self.certify,
                sink: self.cube_proofs,
                threads: self.cube_threads,
            };
            let cover = crate::cube_and_conquer::add_groups(
                &mut sat,
                &enc.cube,
                self.cube_threads * crate::cube_and_conquer::CUBES_PER_THREAD,
            );
            let base = sat.dimacs().map(|(text, _)| text);
            let base_clauses = sat.clauses();
            drop(sat);
            let (pass, conflicts) = cubes.pass(
                k,
                &cover,
                (base, base_clauses),
                (deadline, conflicts),
                start,
            );
            self.spent.set(self.spent.get() + conflicts);
            return pass;
        }
        let answer = cutting.solve(&mut sat, &enc, k, deadline, &interrupted);
        spend(&sat);
        match answer {
            Connected::Unknown => Pass::Unknown,
            Connected::Found(p) => Pass::Found(p),
            Connected::Unsat { cuts, connected } => Pass::Unsat {
                cuts,
                seconds: start.elapsed().as_secs_f64(),
                certificate: crate::certificate::of_sat(&sat, k, cuts, connected),
            },
        }
    }
}

/// How a solve with connectivity ended.
pub(crate) enum Connected {
    /// Unsatisfiable with `cuts` connectivity cuts (`connected`: with the
    /// connectivity encoding).
    Unsat { cuts: usize, connected: bool },
    /// A model with connected pieces (cell indices per shape and piece).
    Found(Vec<Vec<Vec<usize>>>),
    /// Stopped, past the deadline or out of conflicts.
    Unknown,
}

/// Solves an encoding until its model has connected pieces, adding the
/// connectivity encoding (or cuts) at each split model.
pub(crate) struct Cutting<'a> {
    pub inst: &'a Instance,
    pub cuts_per_piece: usize,
    pub observer: &'a dyn ExactObserver,
    /// Add the full connectivity encoding at the first split model (else
    /// cuts only).
    pub eager: bool,
}

impl Cutting<'_> {
    /// Solves `sat` (holding `enc` for `k` pieces) with connectivity cuts
    /// until a model is connected, it is UNSAT, or it is interrupted.
    pub(crate) fn solve(
        &self,
        sat: &mut Sat<'_>,
        enc: &crate::placement_encoding::Encoding,
        k: usize,
        deadline: Option<Instant>,
        interrupted: &dyn Fn() -> bool,
    ) -> Connected {
        let mut total = 0;
        let mut connected_encoding = !self.eager;
        loop {
            match sat.solve(deadline) {
                None => return Connected::Unknown,
                Some(false) => {
                    return Connected::Unsat {
                        cuts: total,
                        connected: connected_encoding,
                    }
                }
                Some(true) => {
                    let pieces = enc.decode(sat);
                    let found = cuts(&self.inst.shapes, &pieces, self.cuts_per_piece);
                    if found.is_empty() {
                        return Connected::Found(pieces);
                    }
                    if !connected_encoding {
                        if !add_connectivity(
                            sat,
                            &self.inst.shapes[0],
                            &enc.cell[0],
                            &enc.anchors,
                            interrupted,
                        ) {
                            return Connected::Unknown;
                        }
                        connected_encoding = true;
                        self.observer
                            .on_event(&ExactEvent::ConnectivityEncoded { pieces: k });
                        continue;
                    }
                    if interrupted() {
                        return Connected::Unknown;
                    }
                    for cut in &found {
                        for piece in &enc.cell[cut.shape] {
                            let mut clause = vec![-piece[cut.a], -piece[cut.b]];
                            clause.extend(cut.separator.iter().map(|&e| piece[e]));
                            sat.add(&clause);
                        }
                    }
                    total += found.len();
                    self.observer.on_event(&ExactEvent::Cuts {
                        pieces: k,
                        added: found.len(),
                        total,
                    });
                }
            }
        }
    }
}

/// Proves lower bounds and (in [`Mode::Minimum`], or when met on the way)
/// finds dissections.
///
/// `upper` is the best known piece count (`usize::MAX` for none), shared
/// with whoever else is searching: the search stops once its lower bound
/// meets it, and lowers it when it finds a dissection. Raising `stop` ends
/// the search soon after, with what is proved so far.
pub fn search(
    figures: &[Figure],
    options: &ExactOptions,
    stop: &AtomicBool,
    upper: &AtomicUsize,
    observer: &dyn ExactObserver,
) -> Result<ExactOutcome, ExactError> {
    let start = Instant::now();
    let out_of_time = || options.deadline.is_some_and(|d| Instant::now() >= d);
    let interrupted = || stop.load(Ordering::Relaxed) || out_of_time();
    // The bound of components and congruence is announced at once, so
    // that a caller that stops waiting for the slower bounds has it.
    let early = |b: &Bound| {
        if b.value > 1 {
            observer.on_event(&ExactEvent::CheapBound(b.clone()));
        }
    };
    let mut cheap = cheap_with(figures, options.mirror, &interrupted, &early)?;
    observer.on_event(&ExactEvent::CheapBound(cheap.bound.clone()));
    let mut outcome = ExactOutcome {
        lower_bound: cheap.bound.clone(),
        found: None,
        stopped: false,
        limit: None,
        conflicts: 0,
    };
    let cells = figures.iter().map(Figure::len).max().unwrap_or(0);
    let sat_max = options.sat_max_cells.min(crate::bound::SAT_MAX_CELLS);
    if cells > sat_max && !interrupted() {
        outcome.limit = Some(Limit::Cells { cells });
        return Ok(outcome);
    }
    let Some((mut inst, clique, incompat)) = model_inputs(figures, options.mirror, &mut cheap)
    else {
        if cells > sat_max && !interrupted() {
            outcome.limit = Some(Limit::Cells { cells });
        } else {
            outcome.stopped = true;
        }
        return Ok(outcome);
    };
    if let Some(c) = &options.constraints {
        inst.target_symmetries = !crate::constraint_encoding::needs_all_target_motions(c);
    }
    inst.source_symmetries = options.source_symmetries && options.constraints.is_none();
    let ctx = Context {
        inst: &inst,
        clique: &clique,
        incompat: &incompat,
        stop,
        upper,
        observer,
        cuts_per_piece: options.cuts_per_piece.max(1),
        eager_connectivity: options.eager_connectivity,
        max_bytes: options.max_encoding_bytes,
        constraints: options.constraints.as_ref(),
        certify: options.certify,
        cube_proofs: options.cube_proofs.as_ref(),
        motion_encoding: options.motion_encoding,
        cube_threads: options.cube_threads,
        spent: std::cell::Cell::new(0),
    };
    let left = || {
        options
            .conflict_budget
            .map(|b| b.saturating_sub(ctx.spent.get()))
    };
    if options.certify {
        ctx.certify_cheap(outcome.lower_bound.value, options.deadline, &left);
    }
    let cells = inst.shapes[0].len();
    let max = options.max_pieces.unwrap_or(cells).min(cells);
    let mut k = outcome.lower_bound.value;
    let restricted: Vec<MotionSet> = match options.mode {
        Mode::LowerBound => Vec::new(),
        Mode::Minimum if inst.dim == 3 || !inst.mirror => vec![MotionSet::Translations],
        Mode::Minimum => vec![MotionSet::Translations, MotionSet::Rotations],
    };
    'levels: while k <= max {
        if upper.load(Ordering::SeqCst) <= k {
            break;
        }
        if interrupted() {
            outcome.stopped = true;
            break;
        }
        if left() == Some(0) {
            outcome.stopped = true;
            outcome.limit = Some(Limit::ConflictBudget);
            break;
        }
        let found = ctx.restricted_passes(k, &restricted, options, &left, &interrupted);
        let found = match found {
            Some(p) => Some(p),
            None => match ctx.pass(k, MotionSet::All, options.deadline, left()) {
                Pass::Found(p) => Some(p),
                Pass::Unsat {
                    cuts,
                    seconds,
                    certificate,
                } => {
                    if let Some(c) = certificate {
                        observer.on_event(&ExactEvent::Certified(*c));
                    }
                    outcome.lower_bound = Bound {
                        value: k + 1,
                        reason: Reason::Sat {
                            refuted: k,
                            seconds,
                            cuts,
                        },
                    };
                    observer.on_event(&ExactEvent::Refuted(outcome.lower_bound.clone()));
                    k += 1;
                    continue 'levels;
                }
                Pass::Unknown => {
                    outcome.stopped = upper.load(Ordering::SeqCst) > k;
                    if outcome.stopped && left() == Some(0) {
                        outcome.limit = Some(Limit::ConflictBudget);
                    }
                    break;
                }
                Pass::TooLarge(bytes) => {
                    outcome.stopped = true;
                    outcome.limit = Some(Limit::TooLarge { pieces: k, bytes });
                    break;
                }
            },
        };
        if let Some(p) = found {
            let pieces = to_cells(&inst, &p);
            dissect_core::verify::verify_pieces(inst.lattice, inst.mirror, figures, &pieces)
                .map_err(|v| ExactError::InvalidModel(v[0].to_string()))?;
            let count = pieces[0].len();
            upper.fetch_min(count, Ordering::SeqCst);
            observer.on_event(&ExactEvent::Found {
                pieces: count,
                seconds: start.elapsed().as_secs_f64(),
            });
            outcome.found = Some(pieces);
            break;
        }
    }
    outcome.conflicts = ctx.spent.get();
    Ok(outcome)
}

/// The instance (reference shape: the one holding the cheap bound's
/// clique, when it has two or more cells), that clique and the
/// incompatibility graph of every shape (taken from `cheap`); `None` when
/// the cheap bounds were interrupted before the graphs were built.
fn model_inputs(
    figures: &[Figure],
    mirror: bool,
    cheap: &mut Cheap,
) -> Option<(Instance, Vec<usize>, Vec<Incompatibility>)> {
    model_inputs_from(figures, mirror, cheap, false)
}

/// [`model_inputs`]; with `first` the reference shape is always input
/// figure 0 (the clique is used only when it lies there).
pub(crate) fn model_inputs_from(
    figures: &[Figure],
    mirror: bool,
    cheap: &mut Cheap,
    first: bool,
) -> Option<(Instance, Vec<usize>, Vec<Incompatibility>)> {
    let reference = if first {
        0
    } else if cheap.clique.len() >= 2 {
        cheap.clique_figure
    } else {
        0
    };
    let clique: Vec<usize> = if reference == cheap.clique_figure {
        cheap.clique.clone()
    } else {
        Vec::new()
    };
    let inst = Instance::new(figures, mirror, reference);
    let mut graphs: Vec<Option<Incompatibility>> =
        cheap.graphs.take()?.into_iter().map(Some).collect();
    let incompat: Vec<Incompatibility> = inst
        .order
        .iter()
        .map(|&i| graphs[i].take().expect("a permutation"))
        .collect();
    Some((inst, clique, incompat))
}

/// A CNF in DIMACS form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dimacs {
    /// The text: a `p cnf VARS CLAUSES` header, then one clause a line.
    pub text: String,
    /// Variables.
    pub vars: usize,
    /// Clauses.
    pub clauses: usize,
}

/// The CNF that [`search`] solves for "at most `k` pieces" with all
/// motions, as DIMACS: the relaxation without connectivity (the cuts and the
/// connectivity encoding are added lazily only after a model), so UNSAT
/// proves that no `k`-piece dissection exists. For other SAT solvers and
/// for measuring them; it solves nothing.
pub fn dimacs(figures: &[Figure], mirror: bool, k: usize) -> Result<Dimacs, ExactError> {
    dimacs_within(figures, mirror, k, DEFAULT_MAX_ENCODING_BYTES)
}

/// [`dimacs`], refusing ([`ExactError::TooLarge`]) a CNF estimated to need
/// more than `max_bytes` of memory (the solver's and the text's) before
/// building it. `k` above the number of cells is taken as that number.
pub fn dimacs_within(
    figures: &[Figure],
    mirror: bool,
    k: usize,
    max_bytes: u64,
) -> Result<Dimacs, ExactError> {
    dimacs_of(figures, mirror, k, max_bytes, false)
}

/// [`dimacs`] with the full connectivity encoding (every piece reached
/// from its root, as the search adds it after a model with a split piece):
/// the formula whose UNSAT settles "at most `k` connected pieces" in one
/// solve, for other SAT solvers. Refused like [`dimacs_within`] past
/// `max_bytes`, the connectivity encoding counted.
pub fn dimacs_connected(
    figures: &[Figure],
    mirror: bool,
    k: usize,
    max_bytes: u64,
) -> Result<Dimacs, ExactError> {
    dimacs_of(figures, mirror, k, max_bytes, true)
}

fn dimacs_of(
    figures: &[Figure],
    mirror: bool,
    k: usize,
    max_bytes: u64,
    connected: bool,
) -> Result<Dimacs, ExactError> {
    let stop = AtomicBool::new(false);
    let (_, sat, _) = formula(figures, mirror, k, (max_bytes, connected, true), &stop)?;
    let (text, clauses) = sat.dimacs().expect("recording");
    Ok(Dimacs {
        text,
        vars: sat.vars(),
        clauses,
    })
}

/// The dissection that a model of the formula of [`dimacs_connected`]
/// (or [`dimacs`]) for `k` pieces stands for, from any SAT solver: `model`
/// holds the literals it sets true (the numbers of its `v` lines; a
/// variable it does not list is false). The formula is built again (the
/// encoding is deterministic), the pieces are read from its cell
/// variables and verified. `pieces[f][i]` in input order.
pub fn decode_model(
    figures: &[Figure],
    mirror: bool,
    k: usize,
    model: &[i32],
) -> Result<Vec<Vec<Vec<Cell>>>, ExactError> {
    decode_model_within(figures, mirror, k, model, DEFAULT_MAX_ENCODING_BYTES)
}

/// [`decode_model`] of a formula built by [`dimacs_connected`] with the
/// cap `max_bytes` (the same formula must fit again to be decoded).
pub fn decode_model_within(
    figures: &[Figure],
    mirror: bool,
    k: usize,
    model: &[i32],
    cap: u64,
) -> Result<Vec<Vec<Vec<Cell>>>, ExactError> {
    let stop = AtomicBool::new(false);
    let (inst, _, enc) = formula(figures, mirror, k, (cap, false, false), &stop)?;
    let truth: std::collections::HashSet<i32> = model.iter().copied().filter(|&l| l > 0).collect();
    let pieces = to_cells(&inst, &enc.decode_with(&|v| truth.contains(&v)));
    dissect_core::verify::verify_pieces(inst.lattice, inst.mirror, figures, &pieces)
        .map_err(|v| ExactError::Model(v[0].to_string()))?;
    Ok(pieces)
}

/// The encoding of "at most `k` pieces" with all motions (and the
/// connectivity encoding when `connected`), recorded when `record`, as
/// [`dimacs`] and [`decode_model`] share it.
fn formula<'s>(
    figures: &[Figure],
    mirror: bool,
    k: usize,
    (max_bytes, connected, record): (u64, bool, bool),
    stop: &'s AtomicBool,
) -> Result<(Instance, Sat<'s>, crate::placement_encoding::Encoding), ExactError> {
    dissect_core::solver::check_figures(figures)?;
    let asked = k;
    let k = k.clamp(1, figures[0].len());
    // The part of the size that needs no geometry first: cheap, and enough
    // to refuse a huge K at once.
    let n = figures[0].len() as u64;
    let one_of = EncodingSize {
        vars: (figures.len() as u64 * n * k as u64).min(usize::MAX as u64) as usize,
        clauses: (figures.len() as u64)
            .saturating_mul(n)
            .saturating_mul((k as u64).saturating_mul(k as u64 - 1) / 2 + 1)
            .min(usize::MAX as u64) as usize,
        motions: 0,
    };
    let too_large = |size: EncodingSize| {
        let bytes = size.bytes(true);
        (bytes > max_bytes).then_some(ExactError::TooLarge {
            pieces: asked,
            bytes,
            cap: max_bytes,
        })
    };
    if let Some(e) = too_large(one_of) {
        return Err(e);
    }
    let mut cheap = cheap(figures, mirror, &|| false)?;
    let (mut inst, clique, incompat) =
        model_inputs(figures, mirror, &mut cheap).expect("not interrupted");
    inst.source_symmetries = true;
    let all = (MotionSet::All, MotionEncoding::Auto);
    let mut size = estimate(&inst, k, all, &clique, &incompat, &|| false);
    if connected {
        let shape0 = &inst.shapes[0];
        let (v, c) = connectivity_size(shape0.len(), k, shape0.adj.iter().map(Vec::len).sum());
        size.vars = size.vars.saturating_add(v.min(usize::MAX as u64) as usize);
        size.clauses = size
            .clauses
            .saturating_add(c.min(usize::MAX as u64) as usize);
    }
    if let Some(e) = too_large(size) {
        return Err(e);
    }
    let mut sat = Sat::new(stop, None);
    if record {
        sat.record();
    }
    let enc =
        encode(&inst, &mut sat, k, all, &clique, &incompat, &|| false).expect("not interrupted");
    if connected {
        add_connectivity(
            &mut sat,
            &inst.shapes[0],
            &enc.cell[0],
            &enc.anchors,
            &|| false,
        );
    }
    Ok((inst, sat, enc))
}

/// Cell indices per shape to sorted cells per figure, in input order.
pub(crate) fn to_cells(inst: &Instance, pieces: &[Vec<Vec<usize>>]) -> Vec<Vec<Vec<Cell>>> {
    let per_shape: Vec<Vec<Vec<Cell>>> = pieces
        .iter()
        .zip(&inst.shapes)
        .map(|(fp, s)| {
            fp.iter()
                .map(|p| {
                    let mut c: Vec<Cell> = p.iter().map(|&i| s.cells[i]).collect();
                    c.sort();
                    c
                })
                .collect()
        })
        .collect();
    inst.to_input_order(&per_shape)
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::io::parse_figure;
    use dissect_core::LatticeKind;

    const DIRECT: (MotionSet, MotionEncoding) = (MotionSet::All, MotionEncoding::Direct);

    /// Parses `d.text`, checks its header against the clauses and solves it
    /// with the crate's own backend.
    fn solve_dimacs(d: &Dimacs) -> bool {
        let mut lines = d.text.lines();
        let header: Vec<&str> = lines.next().expect("header").split_whitespace().collect();
        assert_eq!(header[..2], ["p", "cnf"]);
        assert_eq!(header[2].parse::<usize>().unwrap(), d.vars);
        assert_eq!(header[3].parse::<usize>().unwrap(), d.clauses);
        let stop = AtomicBool::new(false);
        let mut sat = Sat::new(&stop, None);
        for _ in 0..d.vars {
            sat.var();
        }
        let mut clauses = 0;
        for line in lines {
            let lits: Vec<i32> = line
                .split_whitespace()
                .map(|x| x.parse().expect("a literal"))
                .collect();
            assert_eq!(lits.last(), Some(&0), "clause ends with 0");
            let clause = &lits[..lits.len() - 1];
            assert!(clause.iter().all(|l| l.unsigned_abs() as usize <= d.vars));
            sat.add(clause);
            clauses += 1;
        }
        assert_eq!(clauses, d.clauses);
        sat.solve(None).expect("no deadline")
    }

    #[test]
    fn the_estimate_bounds_the_encoding_and_interrupts_end_every_builder() {
        let figs: Vec<Figure> = ["####\n#..#\n####\n", "#####\n#####\n"]
            .iter()
            .map(|t| parse_figure(t, LatticeKind::Square).expect("figure"))
            .collect();
        let mut cheap = cheap(&figs, true, &|| false).expect("valid figures");
        let (inst, clique, incompat) = model_inputs(&figs, true, &mut cheap).expect("graphs");
        let stop = AtomicBool::new(false);
        for k in 1..=5 {
            let est = estimate(&inst, k, DIRECT, &clique, &incompat, &|| false);
            let mut sat = Sat::new(&stop, None);
            encode(&inst, &mut sat, k, DIRECT, &clique, &incompat, &|| false)
                .expect("not interrupted");
            assert!(est.vars >= sat.vars(), "k={k}: {est:?} vs {}", sat.vars());
            assert!(est.clauses >= sat.clauses(), "k={k}: {est:?}");
            assert!(est.clauses <= 4 * sat.clauses(), "k={k}: {est:?}");
        }
        let mut sat = Sat::new(&stop, None);
        assert!(encode(&inst, &mut sat, 3, DIRECT, &clique, &incompat, &|| true).is_none());
        let enc = encode(&inst, &mut sat, 3, DIRECT, &clique, &incompat, &|| false)
            .expect("not interrupted");
        assert!(!add_connectivity(
            &mut sat,
            &inst.shapes[0],
            &enc.cell[0],
            &enc.anchors,
            &|| true
        ));
        assert!(add_connectivity(
            &mut sat,
            &inst.shapes[0],
            &enc.cell[0],
            &enc.anchors,
            &|| false
        ));
        assert!(Incompatibility::of_shape(&inst, 0, &|| true).is_none());
        assert!(crate::motion::motions_into(&inst, 1, MotionSet::All, &|| true).is_none());
        // An interrupted clique search still returns a clique (a bound).
        let c = incompat[0].clique(1_000_000, &|| true);
        assert!(!c.is_empty());
    }

    #[test]
    fn the_shift_estimate_bounds_the_shift_encoding() {
        let figs: Vec<Figure> = ["####\n#..#\n####\n", "#####\n#####\n"]
            .iter()
            .map(|t| parse_figure(t, LatticeKind::Square).expect("figure"))
            .collect();
        let cubes: Vec<Figure> = ["###\n#..\n\n##.\n...", "###\n###"]
            .iter()
            .map(|t| parse_figure(t, LatticeKind::Cubic).expect("figure"))
            .collect();
        let tri: Vec<Figure> = ["FF", "6C\n39"]
            .iter()
            .map(|t| parse_figure(t, LatticeKind::Tri4).expect("figure"))
            .collect();
        let shifts = (MotionSet::All, MotionEncoding::Shifts);
        let stop = AtomicBool::new(false);
        for figs in [&figs, &cubes, &tri] {
            let mut cheap = cheap(figs, true, &|| false).expect("valid figures");
            let (inst, clique, incompat) = model_inputs(figs, true, &mut cheap).expect("graphs");
            for k in 1..=4 {
                let est = estimate(&inst, k, shifts, &clique, &incompat, &|| false);
                let mut sat = Sat::new(&stop, None);
                let enc = encode(&inst, &mut sat, k, shifts, &clique, &incompat, &|| false)
                    .expect("not interrupted");
                assert!(est.vars >= sat.vars(), "k={k}: {est:?} vs {}", sat.vars());
                assert!(est.clauses >= sat.clauses(), "k={k}: {est:?}");
                // Loose for one piece: its motions are taken up to the
                // target's symmetries, which the estimate does not count.
                let slack = if k == 1 { 8 } else { 4 };
                assert!(
                    est.clauses <= slack * sat.clauses(),
                    "k={k}: {est:?} vs {}",
                    sat.clauses()
                );
                assert!(enc.motions() > 0 && enc.motion.iter().flatten().all(Vec::is_empty));
            }
        }
    }

    #[test]
    fn dimacs_header_matches_and_solves_as_expected() {
        let figs: Vec<Figure> = ["###\n###\n", "######\n"]
            .iter()
            .map(|t| parse_figure(t, LatticeKind::Square).expect("figure"))
            .collect();
        let one = dimacs(&figs, true, 1).expect("valid figures");
        assert!(one.vars > 0 && one.clauses > 0);
        assert!(!solve_dimacs(&one), "a 2×3 rectangle is no 1×6 bar");
        let two = dimacs(&figs, true, 2).expect("valid figures");
        assert!(solve_dimacs(&two), "two 1×3 bars");
    }
}
