//! `enumerate`: every dissection with K pieces (`dissect enumerate`), by
//! `dissect_engine::enumerate`, with the GIL released while it runs and
//! Ctrl-C turned into its stop flag.

use std::sync::atomic::{AtomicBool, Ordering};

use dissect_engine::{EnumerateConfig, Rank};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::{json, Map};

use crate::errors::{error, Kind};
use crate::figure::PyFigure;
use crate::run::{time_limit as checked_limit, watched};
use crate::solve::{pieces_to_py, problem};

/// Counts every dissection with `pieces` pieces (the minimum, proved
/// first, when `None`); returns a dict (see `dissect.enumerate`).
#[pyfunction]
#[pyo3(signature = (figures, pieces = None, time_limit = None, mirror = true, unique = false, rank = None))]
pub(crate) fn enumerate<'py>(
    py: Python<'py>,
    figures: Vec<PyRef<'py, PyFigure>>,
    pieces: Option<usize>,
    time_limit: Option<f64>,
    mirror: bool,
    unique: bool,
    rank: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let (figs, names) = problem(py, &figures)?;
    let lattice = figs[0].lattice();
    let mirror = mirror && lattice.lattice().supports_mirror();
    let time_limit = checked_limit(time_limit).map_err(|m| error(py, Kind::Option, m))?;
    let limit = time_limit.deadline();
    if pieces == Some(0) {
        return Err(error(py, Kind::Option, "pieces must be at least 1, got 0"));
    }
    let rank = match rank {
        None => None,
        Some(r) => Some(
            r.parse::<Rank>()
                .map_err(|e| error(py, Kind::Option, e.to_string()))?,
        ),
    };
    let config = EnumerateConfig {
        mirror,
        pieces,
        time_limit,
        rank,
        unique,
    };
    let stop = AtomicBool::new(false);
    let run = watched(py, &stop, limit, || {
        dissect_engine::enumerate(&figs, &names, &config, &stop, &())
    })?;
    let report = run
        .value
        .map_err(|e| error(py, Kind::Problem, e.to_string()))?;
    let out = PyDict::new(py);
    out.set_item("pieces", report.pieces)?;
    out.set_item("minimum", report.minimum)?;
    out.set_item("lower_bound", report.lower_bound.value)?;
    out.set_item("complete", report.complete)?;
    out.set_item("interrupted", run.interrupted.is_some())?;
    out.set_item(
        "stopped",
        !report.complete || stop.load(Ordering::SeqCst) || run.interrupted.is_some(),
    )?;
    out.set_item("count", report.dissections.len())?;
    out.set_item("seconds", report.seconds)?;
    out.set_item("lattice", lattice.name())?;
    out.set_item("mirror", mirror)?;
    out.set_item("names", names)?;
    let all = PyList::empty(py);
    for d in &report.dissections {
        all.append(pieces_to_py(py, lattice, d.pieces())?)?;
    }
    out.set_item("dissections", all)?;
    let classes = PyList::empty(py);
    for (i, class) in report.classes.iter().enumerate() {
        let c = PyDict::new(py);
        c.set_item(
            "pieces",
            pieces_to_py(py, lattice, class.dissection.pieces())?,
        )?;
        c.set_item("size", class.size)?;
        let mut extra = Map::new();
        extra.insert("pieces".into(), json!(class.dissection.piece_count()));
        extra.insert("areas".into(), json!(class.dissection.areas()));
        extra.insert(
            "enumeration".into(),
            json!({
                "class": i + 1,
                "classes": report.classes.len(),
                "dissections_in_class": class.size,
                "dissections": report.dissections.len(),
                "complete": report.complete,
                "minimum": report.minimum,
            }),
        );
        c.set_item(
            "solution_json",
            class.dissection.dissection().to_file(extra).to_json(),
        )?;
        classes.append(c)?;
    }
    out.set_item("classes", classes)?;
    Ok(out)
}
