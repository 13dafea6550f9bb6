//! `solve`, `bound`, `verify` and the solution JSON writer.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

use dissect_core::io::parse_solution;
use dissect_core::solver::{self, Batch, Executor, Exploration};
use dissect_core::Dissection;
use dissect_core::{Figure, LatticeKind};
use dissect_engine::{
    BoundConfig, ConstraintError, End, EngineError, EngineEvent, EngineObserver, Improvement,
    OptionsError, Report, RunConfig, RunOptions, Scores, Strategy,
};
use dissect_puzzle::Motions;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

use crate::errors::{error, Kind};
use crate::figure::{cells_to_py, PyFigure};
use crate::run::{watched, watched_polling};

/// The options `solve` takes as keywords: `dissect solve`'s flags
/// (`no_mirror` is `mirror=False`, `no_prove` is `prove=False`).
const OPTION_NAMES: [&str; 16] = [
    "mirror",
    "max_pieces",
    "area_weight",
    "explorations",
    "keep",
    "iterations",
    "split_penalty",
    "split_tries",
    "full_level",
    "extra_rounds",
    "patience",
    "rounds",
    "prove",
    "paper",
    "exact",
    "repair",
];

/// The names of the options `solve` accepts besides seed, time_limit and
/// threads: the solver's and the puzzle's ([`crate::puzzle::NAMES`]).
#[pyfunction]
pub(crate) fn option_names() -> Vec<&'static str> {
    OPTION_NAMES
        .iter()
        .chain(&crate::puzzle::NAMES)
        .copied()
        .collect()
}

/// The figures of a call: the core's figures and their names (a figure's
/// own name, or `figure-N`), after the checks `dissect solve` makes.
pub(crate) fn problem(
    py: Python<'_>,
    figures: &[PyRef<'_, PyFigure>],
) -> PyResult<(Vec<Figure>, Vec<String>)> {
    let names: Vec<String> = figures
        .iter()
        .enumerate()
        .map(|(i, f)| {
            f.name
                .clone()
                .unwrap_or_else(|| format!("figure-{}", i + 1))
        })
        .collect();
    let figs: Vec<Figure> = figures.iter().map(|f| f.figure.clone()).collect();
    if figs.len() < 2 {
        return Err(error(
            py,
            Kind::Problem,
            format!("need at least two figures, got {}", figs.len()),
        ));
    }
    if let Some((i, f)) = figs
        .iter()
        .enumerate()
        .find(|(_, f)| f.lattice() != figs[0].lattice())
    {
        return Err(error(
            py,
            Kind::Problem,
            format!(
                "figures are on different lattices: {} is {}, {} is {}",
                names[0],
                figs[0].lattice(),
                names[i],
                f.lattice()
            ),
        ));
    }
    if figs.iter().any(|f| f.len() != figs[0].len()) {
        let counts: Vec<String> = names
            .iter()
            .zip(&figs)
            .map(|(n, f)| format!("{n} has {} cells", f.len()))
            .collect();
        return Err(error(
            py,
            Kind::Problem,
            format!("figures have different areas: {}", counts.join(", ")),
        ));
    }
    solver::check_figures(&figs).map_err(|e| error(py, Kind::Problem, e.to_string()))?;
    Ok((figs, names))
}

/// An engine message in Python's words: `--split-tries` becomes `split_tries`.
pub(crate) fn python_words(message: &str) -> String {
    message
        .split(' ')
        .map(|w| match w.strip_prefix("--") {
            Some(flag) => flag.replace('-', "_"),
            None => w.to_string(),
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The run settings of a call, checked by the engine as `dissect solve`'s
/// flags are (`figures`: the problem's, for keep regions). Constraints
/// that cannot hold raise `NoDissectionFound`, as `dissect solve` exits 1.
pub(crate) fn run_options(
    py: Python<'_>,
    seed: u64,
    threads: usize,
    time_limit: Option<f64>,
    kwargs: Option<&Bound<'_, PyDict>>,
    figures: &[Figure],
) -> PyResult<RunOptions> {
    let bad = |m: String| error(py, Kind::Option, m);
    let mut c = RunConfig {
        seed,
        threads: crate::run::threads(threads).map_err(bad)?,
        time_limit: crate::run::time_limit(time_limit).map_err(bad)?,
        ..RunConfig::default()
    };
    let (mut paper, mut exact) = (false, false);
    if let Some(kwargs) = kwargs {
        for (key, value) in kwargs.iter() {
            let key: String = key.extract()?;
            let int = |v: &Bound<'_, PyAny>| -> PyResult<usize> {
                if v.is_instance_of::<pyo3::types::PyBool>() {
                    return Err(bad(format!("{key} must be a whole number >= 0, got {v}")));
                }
                v.extract::<usize>()
                    .map_err(|_| bad(format!("{key} must be a whole number >= 0, got {v}")))
            };
            let float = |v: &Bound<'_, PyAny>| -> PyResult<f64> {
                v.extract::<f64>()
                    .map_err(|_| bad(format!("{key} must be a number, got {v}")))
            };
            let boolean = |v: &Bound<'_, PyAny>| -> PyResult<bool> {
                if !v.is_instance_of::<pyo3::types::PyBool>() {
                    return Err(bad(format!("{key} must be True or False, got {v}")));
                }
                v.extract::<bool>()
            };
            match key.as_str() {
                _ if crate::puzzle::apply(py, &mut c, &key, &value, figures)? => {}
                "mirror" => c.mirror = boolean(&value)?,
                "max_pieces" => {
                    c.max_pieces = if value.is_none() {
                        None
                    } else {
                        Some(int(&value)?)
                    }
                }
                "area_weight" => c.area_weight = float(&value)?,
                "explorations" => c.explorations = int(&value)?,
                "keep" => c.keep = int(&value)?,
                "iterations" => c.iterations = int(&value)?,
                "split_penalty" => c.split_penalty = float(&value)?,
                "split_tries" => c.split_tries = int(&value)?,
                "full_level" => c.full_level = boolean(&value)?,
                "extra_rounds" => c.extra_rounds = int(&value)?,
                "patience" => c.patience = int(&value)?,
                "rounds" => c.idle_rounds = int(&value)?,
                "prove" => c.prove = boolean(&value)?,
                "repair" => c.repair = boolean(&value)?,
                "paper" => paper = boolean(&value)?,
                "exact" => exact = boolean(&value)?,
                _ => {
                    return Err(bad(format!(
                        "unknown option {key:?}; solve takes seed, time_limit, threads and {}",
                        option_names().join(", ")
                    )))
                }
            }
        }
    }
    c.strategy = match (paper, exact) {
        (true, true) => return Err(bad("paper and exact cannot be used together".into())),
        (true, false) => Strategy::Paper,
        (false, true) => Strategy::Exact,
        (false, false) => Strategy::Anytime,
    };
    match RunOptions::new(c) {
        Ok(o) => Ok(o),
        Err(OptionsError::Constraints(e)) if e.is_impossible() => Err(impossible(py, &e)),
        Err(e) => Err(bad(python_words(&e.to_string()))),
    }
}

/// `NoDissectionFound` for constraints that cannot hold (`dissect solve`'s
/// words).
fn impossible(py: Python<'_>, e: &ConstraintError) -> PyErr {
    error(
        py,
        Kind::NotFound,
        format!(
            "no dissection found: the constraints cannot all hold: {}",
            python_words(&e.to_string())
        ),
    )
}

/// [`dissect_engine::check`]: the figures make a problem and the options'
/// constraints fit them, before anything runs.
pub(crate) fn check(py: Python<'_>, figures: &[Figure], options: &RunOptions) -> PyResult<()> {
    match dissect_engine::check(figures, options) {
        Ok(()) => Ok(()),
        Err(EngineError::Constraints(e)) if e.is_impossible() => Err(impossible(py, &e)),
        Err(EngineError::Constraints(e)) => {
            Err(error(py, Kind::Option, python_words(&e.to_string())))
        }
        Err(e) => Err(error(py, Kind::Problem, e.to_string())),
    }
}

/// Runs batches of explorations through a Python callable
/// `executor(round, level, descent, start, end, parents) -> list[bytes]` (parents and
/// results as `Exploration` bytes): how `dissect.ray` spreads a search.
struct PyExecutor {
    call: Py<PyAny>,
    /// The callable's exception, raised again when the search has ended.
    error: Mutex<Option<PyErr>>,
}

impl Executor for PyExecutor {
    fn run(&self, batch: &Batch<'_>) -> Result<Vec<Exploration>, String> {
        Python::attach(|py| {
            let parents: Vec<Bound<'_, PyBytes>> = batch
                .parents
                .iter()
                .map(|p| PyBytes::new(py, &p.to_bytes()))
                .collect();
            let args = (
                batch.round,
                batch.level,
                batch.descent,
                batch.indices.start,
                batch.indices.end,
                parents,
            );
            let got = self
                .call
                .call1(py, args)
                .and_then(|r| r.extract::<Vec<Vec<u8>>>(py));
            match got {
                Ok(list) => list
                    .iter()
                    .map(|b| Exploration::from_bytes(b).map_err(|e| e.to_string()))
                    .collect(),
                Err(e) => {
                    let message = e.to_string();
                    *self.error.lock().unwrap_or_else(|p| p.into_inner()) = Some(e);
                    Err(message)
                }
            }
        })
    }
}

/// Runs single explorations of one problem: the worker half of
/// `dissect.ray.solve` (`Explorer(figures, seed, **options).explore(...)`).
#[pyclass(module = "dissect._dissect", name = "Explorer", frozen)]
pub(crate) struct PyExplorer {
    explorer: solver::Explorer,
}

#[pymethods]
impl PyExplorer {
    #[new]
    #[pyo3(signature = (figures, seed = 1, **options))]
    fn new(
        py: Python<'_>,
        figures: Vec<PyRef<'_, PyFigure>>,
        seed: u64,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyExplorer> {
        let (figs, _) = problem(py, &figures)?;
        let opts = run_options(py, seed, 1, None, options, &figs)?;
        // The problem the run searches (its order of the figures).
        let explorer = dissect_engine::explorer(&figs, &opts)
            .map_err(|e| error(py, Kind::Problem, e.to_string()))?;
        Ok(PyExplorer { explorer })
    }

    /// The explorations `indices` of `level` in `round` (of the descent
    /// when `descent`) from `parents` (bytes), as bytes, in order; without
    /// the GIL.
    #[allow(clippy::too_many_arguments)] // a batch's whole identity
    fn explore<'py>(
        &self,
        py: Python<'py>,
        round: usize,
        level: usize,
        descent: bool,
        indices: Vec<usize>,
        parents: Vec<Vec<u8>>,
    ) -> PyResult<Vec<Bound<'py, PyBytes>>> {
        let parents = parents
            .iter()
            .map(|b| Exploration::from_bytes(b))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| error(py, Kind::Problem, e.to_string()))?;
        let stop = AtomicBool::new(false);
        let out = py.detach(|| {
            indices
                .iter()
                .map(|&i| {
                    self.explorer
                        .explore(round, level, descent, i, &parents, &stop)
                        .map(|e| e.to_bytes())
                })
                .collect::<Result<Vec<_>, _>>()
        });
        let out = out.map_err(|e| error(py, Kind::Problem, e.to_string()))?;
        Ok(out.iter().map(|b| PyBytes::new(py, b)).collect())
    }
}

/// Queues a run's improvements (from the engine's threads) for the
/// `progress=` callable, which the calling thread calls with the GIL.
#[derive(Default)]
struct Improvements(Mutex<Vec<Improvement>>);

impl EngineObserver for Improvements {
    fn on_event(&self, event: &EngineEvent<'_>) {
        if let EngineEvent::Improved(i) = event {
            self.0.lock().unwrap_or_else(|e| e.into_inner()).push(*i);
        }
    }
}

impl Improvements {
    /// Calls `progress(pieces, seconds, source)` for every queued
    /// improvement, in order.
    fn deliver(&self, progress: &Bound<'_, PyAny>) -> PyResult<()> {
        let events = std::mem::take(&mut *self.0.lock().unwrap_or_else(|e| e.into_inner()));
        for i in events {
            progress.call1((i.pieces, i.seconds, i.source.name()))?;
        }
        Ok(())
    }
}

/// Finds a dissection (see `dissect.solve`) by `dissect_engine::run`, the
/// run `dissect solve` makes; returns a dict the Python half turns into a
/// `Dissection`. With `executor` (see [`PyExecutor`]) the heuristic's
/// explorations run wherever it sends them; `progress(pieces, seconds,
/// source)` is called on this thread for every improvement, soon after it
/// happens (an exception it raises stops the run and is raised).
#[pyfunction]
#[pyo3(signature = (figures, seed = 1, time_limit = None, threads = 0, executor = None, progress = None, **options))]
#[allow(clippy::too_many_arguments)] // Python keywords
pub(crate) fn solve<'py>(
    py: Python<'py>,
    figures: Vec<PyRef<'py, PyFigure>>,
    seed: u64,
    time_limit: Option<f64>,
    threads: usize,
    executor: Option<Py<PyAny>>,
    progress: Option<Bound<'py, PyAny>>,
    options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (figs, names) = problem(py, &figures)?;
    let run_options = run_options(py, seed, threads, time_limit, options, &figs)?;
    check(py, &figs, &run_options)?;
    if let Some(p) = &progress {
        if !p.is_callable() {
            return Err(error(
                py,
                Kind::Option,
                format!(
                    "progress must be a callable (pieces, seconds, source), got {}",
                    p.get_type().name()?
                ),
            ));
        }
    }
    let executor = executor.map(|call| PyExecutor {
        call,
        error: Mutex::new(None),
    });
    let stop = AtomicBool::new(false);
    let queue = Improvements::default();
    let mut callback_error = None;
    let mut poll = |_: Python<'_>| -> PyResult<()> {
        if let (Some(p), None) = (&progress, &callback_error) {
            if let Err(e) = queue.deliver(p) {
                stop.store(true, Ordering::SeqCst);
                callback_error = Some(e);
            }
        }
        Ok(())
    };
    // The engine keeps the time limit; the watcher turns Ctrl-C into `stop`
    // and hands the queued improvements to `progress`.
    let run = watched_polling(py, &stop, None, &mut poll, || {
        let ex = executor.as_ref().map(|e| e as &dyn Executor);
        dissect_engine::run_with(&figs, &names, &run_options, &stop, &queue, ex)
    })?;
    if let Some(e) = callback_error {
        return Err(e);
    }
    if let Some(e) = executor.and_then(|e| e.error.into_inner().unwrap_or_else(|p| p.into_inner()))
    {
        return Err(e);
    }
    let report = match run.value {
        Ok(r) => r,
        Err(e @ EngineError::Figures(_)) => return Err(error(py, Kind::Problem, e.to_string())),
        Err(EngineError::Constraints(e)) if e.is_impossible() => return Err(impossible(py, &e)),
        Err(e) => return Err(pyo3::exceptions::PyRuntimeError::new_err(e.to_string())),
    };
    if report.best.is_none() {
        if let Some(e) = run.interrupted {
            return Err(e);
        }
        return Err(not_found(py, &report, &run_options));
    }
    let out = report_to_py(py, &report, &names, &run_options)?;
    out.set_item(
        "interrupted",
        report.end == End::Interrupted || run.interrupted.is_some(),
    )?;
    Ok(out)
}

/// `NoDissectionFound` for a run that ended without a dissection, saying
/// why and how close it came (`dissect solve`'s words).
fn not_found(py: Python<'_>, report: &Report, options: &RunOptions) -> PyErr {
    let why = match report.end {
        End::TimeLimit => format!(
            "the time limit of {} s was reached",
            options.config().time_limit.seconds().unwrap_or_default()
        ),
        _ => match options.config().max_pieces {
            Some(k) => format!("max_pieces={k} was reached"),
            None => "every piece count was tried".to_string(),
        },
    };
    error(
        py,
        Kind::NotFound,
        format!(
            "no dissection found: {why} after {:.1} s; the best candidate ({} pieces) had matching score E_M = {}; lower bound: {} ({})",
            report.seconds,
            report.last_pieces.max(1),
            report.best_mismatch.map_or("n/a".to_string(), |m| m.to_string()),
            report.lower_bound.value,
            report.lower_bound.reason,
        ),
    )
}

/// A run's report with a dissection as the dict `dissect.Dissection` reads.
fn report_to_py<'py>(
    py: Python<'py>,
    report: &Report,
    names: &[String],
    options: &RunOptions,
) -> PyResult<Bound<'py, PyDict>> {
    let best = report.best.as_ref().expect("a dissection was found");
    let lattice = best.dissection().lattice();
    let out = PyDict::new(py);
    out.set_item("lattice", lattice.name())?;
    out.set_item("mirror", best.dissection().mirror())?;
    out.set_item("names", names.to_vec())?;
    out.set_item("pieces", pieces_to_py(py, lattice, best.pieces())?)?;
    out.set_item("level", report.level)?;
    out.set_item("area_variance", best.variance())?;
    out.set_item("explorations", report.explorations)?;
    out.set_item("rounds", report.rounds)?;
    out.set_item("stopped", report.end.stopped())?;
    out.set_item(
        "end",
        match report.end {
            End::Optimal => "optimal",
            End::Finished => "finished",
            End::TimeLimit => "time_limit",
            End::Interrupted => "interrupted",
            _ => "other",
        },
    )?;
    out.set_item("seconds", report.seconds)?;
    out.set_item("seed", report.seed)?;
    out.set_item("lower_bound", report.lower_bound.value)?;
    out.set_item("lower_bound_reason", report.lower_bound.reason.clone())?;
    out.set_item("lower_bound_proof", report.lower_bound.proof.clone())?;
    out.set_item("optimal", report.optimal)?;
    out.set_item("found_by", report.source.map(|s| s.name()))?;
    out.set_item("time_to_first", report.time_to_first)?;
    out.set_item("time_to_best", report.time_to_best)?;
    let rows = PyList::empty(py);
    for h in &report.history {
        let row = PyDict::new(py);
        row.set_item("pieces", h.pieces)?;
        row.set_item("seconds", h.seconds)?;
        row.set_item("by", h.source.name())?;
        rows.append(row)?;
    }
    out.set_item("history", rows)?;
    out.set_item("solution_json", report.solution_json())?;
    // The different dissections, best first; a run that did not collect
    // them has its best alone, scored as the engine scores them.
    let solutions = PyList::empty(py);
    if report.solutions.is_empty() {
        let motions = Motions::new(lattice, best.dissection().mirror());
        let weight = options.config().constraints.symmetry_weight();
        let scores = Scores::weighted(&motions, &best.pieces()[0], weight);
        out.set_item("scores", scores_to_py(py, &scores)?)?;
    }
    for (i, s) in report.solutions.iter().enumerate() {
        let row = PyDict::new(py);
        row.set_item("pieces", pieces_to_py(py, lattice, s.dissection.pieces())?)?;
        row.set_item("area_variance", s.dissection.variance())?;
        row.set_item("scores", scores_to_py(py, &s.scores)?)?;
        row.set_item("found_by", s.source.name())?;
        row.set_item(
            "optimal",
            s.dissection.piece_count() <= report.lower_bound.value,
        )?;
        row.set_item("solution_json", report.solution_json_at(i))?;
        if i == 0 {
            out.set_item("scores", scores_to_py(py, &s.scores)?)?;
        }
        solutions.append(row)?;
    }
    out.set_item("solutions", solutions)?;
    out.set_item(
        "rank",
        report
            .ranking
            .as_ref()
            .map_or(options.config().rank.name(), |r| r.rank.name()),
    )?;
    Ok(out)
}

/// A dissection's scores (`dissect_engine::Scores`) as a dict.
fn scores_to_py<'py>(py: Python<'py>, s: &Scores) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("pieces", s.pieces)?;
    d.set_item("variance", s.variance)?;
    d.set_item("smallest", s.smallest)?;
    d.set_item("shapes", s.shapes)?;
    d.set_item("symmetry", s.symmetry)?;
    d.set_item("objective", s.objective)?;
    d.set_item("assemblies", s.assemblies)?;
    Ok(d)
}

/// `pieces[f][i]` as nested Python lists of cell tuples.
pub(crate) fn pieces_to_py<'py>(
    py: Python<'py>,
    lattice: LatticeKind,
    pieces: &[Vec<Vec<dissect_core::Cell>>],
) -> PyResult<Bound<'py, PyList>> {
    let figs = PyList::empty(py);
    for fig in pieces {
        let list = PyList::empty(py);
        for piece in fig {
            list.append(cells_to_py(py, lattice, piece)?)?;
        }
        figs.append(list)?;
    }
    Ok(figs)
}

/// Proves a lower bound (see `dissect.bound`); returns a dict.
#[pyfunction]
#[pyo3(signature = (figures, time_limit = None, max_pieces = None, mirror = true, solver = None, certificate = None))]
pub(crate) fn bound<'py>(
    py: Python<'py>,
    figures: Vec<PyRef<'py, PyFigure>>,
    time_limit: Option<f64>,
    max_pieces: Option<usize>,
    mirror: bool,
    solver: Option<String>,
    certificate: Option<std::path::PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    let (figs, names) = problem(py, &figures)?;
    let lattice = figs[0].lattice();
    let mirror = mirror && lattice.lattice().supports_mirror();
    let process = match &solver {
        Some(command) => Some(
            dissect_solver_process::SolverProcess::new(command, certificate.as_deref())
                .map_err(|e| error(py, Kind::Option, format!("solver: {e}")))?,
        ),
        None => None,
    };
    // The built-in solver's certificates (another solver's are its files).
    let writer = match (&process, &certificate) {
        (None, Some(dir)) => Some(
            dissect_certificate::Writer::new(dir, &names, lattice.name(), mirror)
                .map_err(|e| crate::proof::certificate_error(py, e))?,
        ),
        _ => None,
    };
    let config = BoundConfig {
        mirror,
        max_pieces,
        time_limit: crate::run::time_limit(time_limit).map_err(|m| error(py, Kind::Option, m))?,
        certify: writer.is_some(),
        cube_proofs: writer.as_ref().map(|w| w.cube_proofs()),
        threads: 1,
    };
    // The engine keeps the time limit; the watcher raises `stop` on Ctrl-C.
    let stop = AtomicBool::new(false);
    let run = watched(py, &stop, None, || match (&process, &writer) {
        (Some(p), _) => dissect_engine::bound_external(
            &figs,
            &names,
            (&config, dissect_exact::DEFAULT_MAX_ENCODING_BYTES),
            p,
            &stop,
            &(),
        ),
        (None, Some(w)) => {
            dissect_engine::bound(&figs, &names, &config, &stop, &crate::proof::Certifying(w))
        }
        (None, None) => dissect_engine::bound(&figs, &names, &config, &stop, &()),
    })?;
    let report = run
        .value
        .map_err(|e| error(py, Kind::Problem, e.to_string()))?;
    let out = PyDict::new(py);
    out.set_item("value", report.lower_bound.value)?;
    out.set_item("reason", report.lower_bound.reason.clone())?;
    out.set_item(
        "stopped",
        report.stopped() || run.interrupted.is_some() || stop.load(Ordering::SeqCst),
    )?;
    out.set_item("interrupted", run.interrupted.is_some())?;
    out.set_item("lattice", lattice.name())?;
    out.set_item("mirror", mirror)?;
    out.set_item("names", names)?;
    match &report.found {
        Some(v) => out.set_item("pieces", pieces_to_py(py, lattice, v.pieces())?)?,
        None => out.set_item("pieces", py.None())?,
    }
    let refuted = match (&process, &writer) {
        (Some(p), _) => p
            .finish()
            .map_err(|e| error(py, Kind::Option, format!("solver: {e}")))?,
        (None, Some(w)) => {
            w.finish()
                .map_err(|e| crate::proof::certificate_error(py, e))?
                .certified
        }
        (None, None) => Vec::new(),
    };
    out.set_item(
        "certificates",
        if certificate.is_some() {
            refuted
        } else {
            Vec::new()
        },
    )?;
    Ok(out)
}

/// Checks a solution (JSON text, FORMAT.md) against its figures; returns
/// the piece count or raises `InvalidSolution` listing every violation.
#[pyfunction]
pub(crate) fn verify(
    py: Python<'_>,
    figures: Vec<PyRef<'_, PyFigure>>,
    solution: &str,
) -> PyResult<usize> {
    let (_, d) = parse_solution(solution)
        .map_err(|e| error(py, Kind::InvalidSolution, format!("solution: {e}")))?;
    let figs: Vec<Figure> = figures.iter().map(|f| f.figure.clone()).collect();
    let count = py.detach(|| dissect_core::verify::verify(&d, &figs));
    count.map_err(|v| {
        let all: Vec<String> = v.iter().map(|v| v.to_string()).collect();
        error(
            py,
            Kind::InvalidSolution,
            format!("not a valid dissection: {}", all.join("; ")),
        )
    })
}

/// A solution file (FORMAT.md) from its parts and `extra` keys (a JSON
/// object text), written by the core's writer.
#[pyfunction]
#[pyo3(signature = (lattice, mirror, names, pieces, extra = "{}"))]
pub(crate) fn solution_json(
    py: Python<'_>,
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Vec<i64>>>>,
    extra: &str,
) -> PyResult<String> {
    let extra: serde_json::Map<String, serde_json::Value> = serde_json::from_str(extra)
        .map_err(|e| error(py, Kind::Option, format!("extra keys: {e}")))?;
    let d = dissection_from_py(py, lattice, mirror, names, &pieces)?;
    Ok(d.to_file(extra).to_json())
}

/// A dissection from its parts as Python holds them (`pieces[f][i]`: the
/// cells of piece `i` in figure `f`, as coordinate lists); not verified.
pub(crate) fn dissection_from_py(
    py: Python<'_>,
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: &[Vec<Vec<Vec<i64>>>],
) -> PyResult<Dissection> {
    let kind = crate::figure::lattice(py, lattice)?;
    let pieces = pieces
        .iter()
        .map(|fig| {
            fig.iter()
                .map(|piece| {
                    piece
                        .iter()
                        .map(|c| crate::figure::cell_from_coords(py, kind, c))
                        .collect::<PyResult<Vec<_>>>()
                })
                .collect::<PyResult<Vec<_>>>()
        })
        .collect::<PyResult<Vec<_>>>()?;
    Dissection::new(kind, mirror, names, pieces)
        .map_err(|e| error(py, Kind::InvalidSolution, e.to_string()))
}

/// A dissection given from Python, checked against `figures`: the
/// engine's [`Verified`], or `InvalidSolution` naming what is wrong.
pub(crate) fn verified_from_py(
    py: Python<'_>,
    figures: &[Figure],
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: &[Vec<Vec<Vec<i64>>>],
) -> PyResult<dissect_engine::Verified> {
    let d = dissection_from_py(py, lattice, mirror, names.clone(), pieces)?;
    dissect_engine::Verified::new(d.lattice(), d.mirror(), names, figures, d.pieces().to_vec())
        .map_err(|e| {
            error(
                py,
                Kind::InvalidSolution,
                format!("not a valid dissection: {e}"),
            )
        })
}
