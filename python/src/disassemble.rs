//! `Dissection.disassemble`: a plan of straight moves that takes each
//! figure apart, by the engine
//! ([`Verified::disassemble`](dissect_engine::Verified::disassemble), the
//! search of `dissect disassemble`), without the GIL and stopped by Ctrl-C.

use std::sync::atomic::AtomicBool;

use dissect_engine::Disassembly;
use dissect_puzzle::disassembly::{outcome_line, plan_json};
use pyo3::prelude::*;

use crate::errors::{error, Kind};
use crate::figure::PyFigure;
use crate::run::watched;
use crate::solve::verified_from_py;

/// Takes every figure of the dissection apart; returns the plan file's text
/// (`dissection-disassembly/1`, what `dissect disassemble -o` writes) and
/// the result line of each figure (what it prints). `time_limit` (seconds,
/// None: none) bounds all figures together; figures not decided by then or
/// by Ctrl-C say so.
#[pyfunction]
#[pyo3(signature = (figures, lattice, mirror, names, pieces, time_limit = None))]
pub(crate) fn disassemble<'py>(
    py: Python<'py>,
    figures: Vec<PyRef<'py, PyFigure>>,
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Vec<i64>>>>,
    time_limit: Option<f64>,
) -> PyResult<(String, Vec<String>)> {
    let time = crate::run::time_limit(time_limit).map_err(|m| error(py, Kind::Option, m))?;
    let figs: Vec<_> = figures.iter().map(|f| f.figure.clone()).collect();
    let verified = verified_from_py(py, &figs, lattice, mirror, names.clone(), &pieces)?;
    let stop = AtomicBool::new(false);
    let run = watched(py, &stop, None, || verified.disassemble(time, Some(&stop)))?;
    let outcomes = run
        .value
        .map_err(|e| error(py, Kind::InvalidSolution, e.to_string()))?;
    let lines = names
        .iter()
        .zip(&outcomes)
        .map(|(n, o)| outcome_line(n, o))
        .collect();
    let named: Vec<(&str, &Disassembly)> =
        names.iter().map(String::as_str).zip(&outcomes).collect();
    Ok((plan_json(verified.dissection().lattice(), &named), lines))
}
