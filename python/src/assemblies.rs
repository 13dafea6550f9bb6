//! `Dissection.assemblies`: in how many ways the pieces tile each figure,
//! counted by the engine
//! ([`Verified::assemblies`](dissect_engine::Verified::assemblies), the
//! count of `dissect assemblies`), without the GIL and stopped by Ctrl-C.

use std::sync::atomic::AtomicBool;
use std::time::Duration;

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::errors::{error, Kind};
use crate::figure::PyFigure;
use crate::run::watched;
use crate::solve::verified_from_py;

/// Counts the tilings of each figure by the dissection's pieces; a dict
/// per figure (`figure`, `tilings`, `up_to_symmetry`,
/// `figure_symmetries`, `complete`, `seconds`). `time_limit` (seconds,
/// None: none) applies to each figure's count; a count cut short by it or
/// by Ctrl-C says `complete: False` and its numbers are lower bounds.
#[pyfunction]
#[pyo3(signature = (figures, lattice, mirror, names, pieces, time_limit = None))]
pub(crate) fn assemblies<'py>(
    py: Python<'py>,
    figures: Vec<PyRef<'py, PyFigure>>,
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Vec<i64>>>>,
    time_limit: Option<f64>,
) -> PyResult<Bound<'py, PyList>> {
    // The engine's one rule for a time limit (NaN, negative: refused;
    // infinite or none: no limit).
    let time = crate::run::time_limit(time_limit)
        .map_err(|m| error(py, Kind::Option, m))?
        .duration()
        .unwrap_or(Duration::MAX);
    let figs: Vec<_> = figures.iter().map(|f| f.figure.clone()).collect();
    let verified = verified_from_py(py, &figs, lattice, mirror, names.clone(), &pieces)?;
    let stop = AtomicBool::new(false);
    let run = watched(py, &stop, None, || {
        verified.assemblies(&figs, time, Some(&stop))
    })?;
    let counts = run
        .value
        .map_err(|e| error(py, Kind::InvalidSolution, e.to_string()))?;
    let out = PyList::empty(py);
    for (name, c) in names.iter().zip(&counts) {
        let row = PyDict::new(py);
        row.set_item("figure", name)?;
        row.set_item("tilings", c.tilings)?;
        row.set_item("up_to_symmetry", c.up_to_symmetry)?;
        row.set_item("figure_symmetries", c.figure_symmetries)?;
        row.set_item("complete", c.complete)?;
        row.set_item("seconds", c.elapsed.as_secs_f64())?;
        out.append(row)?;
    }
    Ok(out)
}
